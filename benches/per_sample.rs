//! Speed of the per-sample path, side by side in one run:
//! one random wavelength, one hero sample (K = 4), a 16-bucket product and
//! conversion (centre and box), the exact reference, the operations a path
//! tracer does on a sample, and preparing bucketed spectra.
//!
//! ```text
//! cargo bench --bench per_sample
//! ```

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use speclab::sampling::reference;
use speclab::{BoxAverage, Centre, HeroSample, RegularSpectrum, SampledSpectrum, data};

/// A fixed low-discrepancy sequence of u, so every run draws the same.
fn sequence() -> impl FnMut() -> f64 {
    let us: Vec<f64> = (0..1024).map(|i| (i as f64 * 0.618_033_988_749_895).fract()).collect();
    let mut i = 0;
    move || {
        i = (i + 1) & 1023;
        us[i]
    }
}

fn per_sample(c: &mut Criterion) {
    let (light, surface) = (&data::F11, &data::H4);
    let mut group = c.benchmark_group("light×surface→XYZ");
    let mut next_u = sequence();
    group.bench_function("random K=1, one sample", |b| {
        b.iter(|| {
            let h = HeroSample::<1>::new(black_box(next_u()));
            h.to_xyz(light.sample(&h) * surface.sample(&h))
        })
    });
    group.bench_function("hero K=4, one sample", |b| {
        b.iter(|| {
            let h = HeroSample::<4>::new(black_box(next_u()));
            h.to_xyz(light.sample(&h) * surface.sample(&h))
        })
    });
    let (lc, sc) =
        (RegularSpectrum::<16, Centre>::centre(light), RegularSpectrum::<16, Centre>::centre(surface));
    group.bench_function("regular M=16 centre, multiply + to_xyz", |b| {
        b.iter(|| (black_box(lc) * black_box(sc)).to_xyz())
    });
    let (lb, sb) = (
        RegularSpectrum::<16, BoxAverage>::box_average(light),
        RegularSpectrum::<16, BoxAverage>::box_average(surface),
    );
    group.bench_function("regular M=16 box, multiply + to_xyz", |b| {
        b.iter(|| (black_box(lb) * black_box(sb)).to_xyz())
    });
    group.bench_function("exact reference", |b| {
        b.iter(|| reference::xyz(black_box(light), black_box(surface)))
    });
    group.finish();
    path_tracer_ops(c);
    preparing(c);
}

/// Each operation a path tracer adds to the per-sample path, on K = 4.
fn path_tracer_ops(c: &mut Criterion) {
    let mut group = c.benchmark_group("path tracer ops, K=4");
    let h = HeroSample::<4>::new(0.3);
    let (le, albedo) = (data::F11.sample(&h), data::H4.sample(&h));
    group.bench_function("HeroSample::with_pdf", |b| {
        b.iter(|| HeroSample::with_pdf(black_box(*h.lambda()), black_box(h.pdf())))
    });
    group.bench_function("terminate_secondary", |b| {
        b.iter(|| {
            let mut t = black_box(h);
            t.terminate_secondary();
            t
        })
    });
    group.bench_function("bounce: L += beta * Le; beta *= albedo", |b| {
        b.iter(|| {
            let (mut l, mut beta) =
                (black_box(SampledSpectrum::<4>::zero()), black_box(SampledSpectrum::splat(1.0)));
            l += beta * black_box(le);
            beta *= black_box(albedo);
            (l, beta)
        })
    });
    group.bench_function("safe_div by the pdf", |b| {
        b.iter(|| black_box(le).safe_div(black_box(SampledSpectrum::new(h.pdf()))))
    });
    group.bench_function("average + max_value + is_black", |b| {
        b.iter(|| {
            let v = black_box(le);
            (v.average(), v.max_value(), v.is_black())
        })
    });
    group.bench_function("y (luminance alone)", |b| b.iter(|| black_box(h).y(black_box(le))));
    group.bench_function("to_xyz", |b| b.iter(|| black_box(h).to_xyz(black_box(le))));
    group.finish();
}

fn preparing(c: &mut Criterion) {
    let light = &data::F11;
    let mut prep = c.benchmark_group("preparing a spectrum (once per spectrum)");
    prep.bench_function("centre buckets M=16", |b| {
        b.iter(|| RegularSpectrum::<16, Centre>::centre(black_box(light)))
    });
    prep.bench_function("box buckets M=16", |b| {
        b.iter(|| RegularSpectrum::<16, BoxAverage>::box_average(black_box(light)))
    });
    prep.finish();
}

criterion_group!(benches, per_sample);
criterion_main!(benches);
