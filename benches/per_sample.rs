//! Speed of the per-sample path, side by side in one run:
//! one random wavelength, one hero sample (K = 4), a 16-bucket product and
//! conversion (centre and box), and the exact reference.
//!
//! ```text
//! cargo bench --bench per_sample
//! ```

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use speclab::{BoxAverage, Centre, HeroSample, RegularSpectrum, data, reference};

fn per_sample(c: &mut Criterion) {
    let (light, surface) = (&data::F11, &data::H4);
    let mut group = c.benchmark_group("light×surface→XYZ");
    // A fixed low-discrepancy sequence of u, so every run draws the same.
    let us: Vec<f64> = (0..1024).map(|i| (i as f64 * 0.618_033_988_749_895).fract()).collect();
    let mut i = 0;
    let mut next_u = move || {
        i = (i + 1) & 1023;
        us[i]
    };
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
