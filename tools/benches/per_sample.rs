//! Speed of the per-sample path, side by side in one run:
//! one random wavelength, one hero sample (K = 4), a 16-bucket product and
//! conversion (centre and box), a fitted rule of 10, the exact reference,
//! the operations a path tracer does on a sample, drawing hero samples from
//! each pdf, evaluating each kind of spectrum, preparing bucketed spectra,
//! and fitting rules.
//!
//! And one light three ways (built in, scaled, loaded from its file): the
//! same path at the same speed.
//!
//! ```text
//! cargo bench -p speclab-tools --bench per_sample
//! ```

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use speclab::sampling::Domain;
use speclab::sampling::reference;
use speclab::spectrum::{DenseObserver, DenseSpectrum};
use speclab::{BoxAverage, Center, HeroSample, RegularSpectrum, SampledSpectrum, data};

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
    let (light, surface) = (&data::lights::F11, &data::patches::H4);
    let mut group = c.benchmark_group("light×surface→XYZ");
    let mut next_u = sequence();
    group.bench_function("random K=1, one sample", |b| {
        b.iter(|| {
            let h = HeroSample::<1>::exact(black_box(next_u()));
            h.to_xyz(light.sample(&h) * surface.sample(&h))
        })
    });
    group.bench_function("hero K=4, one sample", |b| {
        b.iter(|| {
            let h = HeroSample::<4>::exact(black_box(next_u()));
            h.to_xyz(light.sample(&h) * surface.sample(&h))
        })
    });
    let (dl, ds) = (DenseSpectrum::new(light), DenseSpectrum::new(surface));
    group.bench_function("hero K=4 f32 over dense tables, one sample", |b| {
        b.iter(|| {
            let h = HeroSample::<4, f32>::new(black_box(next_u()) as f32);
            h.to_xyz(dl.sample(&h) * ds.sample(&h))
        })
    });
    let (lc, sc) =
        (RegularSpectrum::<16, Center>::center(light), RegularSpectrum::<16, Center>::center(surface));
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
    let (lc32, sc32) = (
        RegularSpectrum::<16, Center, f32>::center(light),
        RegularSpectrum::<16, Center, f32>::center(surface),
    );
    group.bench_function("regular M=16 centre f32, multiply + to_xyz", |b| {
        b.iter(|| (black_box(lc32) * black_box(sc32)).to_xyz())
    });
    let rule = speclab::sampling::rule::Rule::fit(&[light], 10).expect("a rule");
    let at = rule.wavelengths::<10, f64>().expect("M = 10");
    let (lf, sf) = (light.sample(&at), surface.sample(&at));
    group.bench_function("fitted M=10, multiply + to_xyz", |b| {
        b.iter(|| at.to_xyz(black_box(lf) * black_box(sf)))
    });
    let at32 = rule.wavelengths::<10, f32>().expect("M = 10");
    let (lf32, sf32) = (light.sample(&at32), surface.sample(&at32));
    group.bench_function("fitted M=10 f32, multiply + to_xyz", |b| {
        b.iter(|| at32.to_xyz(black_box(lf32) * black_box(sf32)))
    });
    group.bench_function("exact reference", |b| {
        b.iter(|| reference::xyz(black_box(light), black_box(surface)))
    });
    group.finish();
    path_tracer_ops(c);
    drawing(c);
    evaluating(c);
    preparing(c);
}

/// Drawing one hero sample (K = 4) from each wavelength pdf, statically
/// dispatched, and the binned light pdf through `&dyn`.
fn drawing(c: &mut Criterion) {
    use speclab::sampling::binned::BinnedPdf;
    use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
    let light = LightPdf::light(&data::lights::F11).expect("bright");
    let (binned_light, binned_visible) = (
        BinnedPdf::new(&light, 256).expect("bins"),
        BinnedPdf::new(&Visible::ASSIGNMENT, 256).expect("bins"),
    );
    let mut group = c.benchmark_group("drawing a hero sample, K=4");
    let mut next_u = sequence();
    group.bench_function("HeroSample::new (uniform, dense observer)", |b| {
        b.iter(|| HeroSample::<4>::new(black_box(next_u())))
    });
    group.bench_function("HeroSample::exact (uniform, exact observer)", |b| {
        b.iter(|| HeroSample::<4>::exact(black_box(next_u())))
    });
    // Each density with the observer, checked once (a Domain).
    let dense = DenseObserver::ASSIGNMENT;
    let within = "within the observer";
    let dynamic: &dyn WavelengthPdf = &binned_light;
    let domains: [(&str, Domain<&dyn WavelengthPdf>); 6] = [
        ("Uniform", Domain::new(&Uniform::ASSIGNMENT as &dyn WavelengthPdf, dense).expect(within)),
        ("Visible", Domain::new(&Visible::ASSIGNMENT as &dyn WavelengthPdf, dense).expect(within)),
        ("BinnedPdf of Visible", Domain::new(&binned_visible as &dyn WavelengthPdf, dense).expect(within)),
        ("LightPdf F11 (exact)", Domain::new(&light as &dyn WavelengthPdf, dense).expect(within)),
        ("BinnedPdf of LightPdf F11", Domain::new(&binned_light as &dyn WavelengthPdf, dense).expect(within)),
        ("BinnedPdf F11 via &dyn", Domain::new(black_box(dynamic), dense).expect(within)),
    ];
    for (name, domain) in &domains {
        group.bench_function(format!("Domain::hero {name}"), |b| {
            b.iter(|| domain.hero::<4, f64>(black_box(next_u())))
        });
    }
    group.finish();
}

/// A spectrum at a hero sample's 4 wavelengths, by kind of spectrum; making
/// an RGB albedo.
fn evaluating(c: &mut Criterion) {
    use speclab::LinearRgb;
    use speclab::color::RgbAlbedo;
    use speclab::color::rgb_table::RgbTable;
    let h = HeroSample::<4>::new(0.3);
    let patch = &data::patches::H4;
    let dense = DenseSpectrum::new(patch);
    let rgb = LinearRgb::from([0.6, 0.3, 0.1]);
    let albedo = RgbAlbedo::new(rgb).expect("an albedo");
    let table = RgbTable::SRGB;
    let mut group = c.benchmark_group("a spectrum at 4 wavelengths");
    group.bench_function("TabulatedSpectrum (exact cubic)", |b| {
        b.iter(|| black_box(&h).sample(black_box(patch)))
    });
    group.bench_function("DenseSpectrum (1 nm, nearest)", |b| {
        b.iter(|| black_box(&h).sample(black_box(&dense)))
    });
    group.bench_function("RgbAlbedo (sigmoid)", |b| b.iter(|| black_box(&h).sample(black_box(&albedo))));
    group.bench_function("RgbAlbedo::new (Gauss-Newton fit)", |b| b.iter(|| RgbAlbedo::new(black_box(rgb))));
    group.bench_function("RgbTable::albedo (lookup)", |b| b.iter(|| table.albedo(black_box(rgb))));
    group.finish();
}

/// Each operation a path tracer adds to the per-sample path, on K = 4.
fn path_tracer_ops(c: &mut Criterion) {
    let mut group = c.benchmark_group("path tracer ops, K=4");
    let h = HeroSample::<4>::new(0.3);
    let (le, albedo) = (data::lights::F11.sample(&h), data::patches::H4.sample(&h));
    group.bench_function("HeroSample::from_wavelengths", |b| {
        b.iter(|| {
            HeroSample::from_wavelengths_with(
                black_box(*h.lambda()),
                black_box(h.pdf()),
                &DenseObserver::ASSIGNMENT,
            )
        })
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
    // y and to_xyz over 64 samples in a loop, per sample: one call between
    // black boxes measures the round trip through memory, not the sum.
    let many: Vec<_> = (0..64).map(|i| HeroSample::<4>::new((f64::from(i) + 0.5) / 64.0)).collect();
    let les: Vec<_> = many.iter().map(|h| data::lights::F11.sample(h)).collect();
    group.throughput(criterion::Throughput::Elements(64));
    group.bench_function("y (luminance alone), per sample of 64", |b| {
        b.iter(|| black_box(&many).iter().zip(black_box(&les)).map(|(h, le)| h.y(*le)).sum::<f64>())
    });
    group.bench_function("to_xyz, per sample of 64", |b| {
        b.iter(|| {
            black_box(&many).iter().zip(black_box(&les)).map(|(h, le)| h.to_xyz(*le)).sum::<speclab::Xyz>()
        })
    });
    group.finish();
}

fn preparing(c: &mut Criterion) {
    let light = &data::lights::F11;
    let mut prep = c.benchmark_group("preparing a spectrum (once per spectrum)");
    prep.bench_function("centre buckets M=16", |b| {
        b.iter(|| RegularSpectrum::<16, Center>::center(black_box(light)))
    });
    prep.bench_function("box buckets M=16", |b| {
        b.iter(|| RegularSpectrum::<16, BoxAverage>::box_average(black_box(light)))
    });
    prep.finish();
    let mut fit = c.benchmark_group("fitting a rule (once per scene's lights)");
    fit.sample_size(10);
    for m in [8, 16] {
        fit.bench_function(format!("Rule::fit F11, M={m}"), |b| {
            b.iter(|| speclab::sampling::rule::Rule::fit(&[black_box(light)], m))
        });
    }
    let three: [&dyn speclab::Spectrum; 3] = [&data::lights::A, &data::lights::D65, light];
    fit.bench_function("Rule::fit A + D65 + F11, M=16", |b| {
        b.iter(|| speclab::sampling::rule::Rule::fit(black_box(&three), 16))
    });
    fit.finish();
}

criterion_group!(benches, per_sample);
/// One light three ways: built in, scaled by 1 (a new value, computed from
/// the built-in one) and loaded from its file. Each keeps its own reference
/// weights after the first call and builds its own pdf table.
fn same_light_three_ways(c: &mut Criterion) {
    use speclab::io::Load;
    use speclab::sampling::pdf::LightPdf;
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../data/illuminant_f11.txt");
    let scaled = data::lights::F11.scaled(1.0).expect("finite");
    let loaded = Load::new(speclab::Role::Light).file(path).expect("valid data");
    let mut group = c.benchmark_group("F11 three ways");
    for (name, light) in [("built-in", &data::lights::F11), ("scaled", &scaled), ("loaded", &loaded)] {
        group.bench_function(format!("reference::xyz {name}"), |b| {
            b.iter(|| reference::xyz(black_box(light), black_box(&data::patches::H4)))
        });
        group.bench_function(format!("LightPdf::light {name}"), |b| {
            b.iter(|| LightPdf::light(black_box(light)))
        });
        let pdf = LightPdf::light(light).expect("bright");
        let domain = Domain::new(&pdf, DenseObserver::ASSIGNMENT).expect("within the observer");
        let mut next_u = sequence();
        group.bench_function(format!("hero K=4 from the light pdf {name}"), |b| {
            b.iter(|| {
                let h = domain.hero::<4, f64>(black_box(next_u()));
                h.to_xyz(light.sample(&h) * data::patches::H4.sample(&h))
            })
        });
    }
    group.finish();
}

criterion_group!(three_ways, same_light_three_ways);
criterion_main!(benches, three_ways);
