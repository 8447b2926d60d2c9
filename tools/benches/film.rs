//! What a spectral film costs per sample, beside what converting the same
//! sample to XYZ costs: the same 1024 hero samples (K = 4, f32 and f64,
//! weighed by the CIE 1931 observer, with F11 × H4 at their wavelengths),
//! converted with `to_xyz` and added to their pixel's XYZ, or splatted
//! into a 64 × 64 film of 16 buckets (pbrt-v4's default count) or 351
//! (1 nm at every whole nanometre of 380–730 nm): 16 samples per pixel in
//! turn (a tracer's order), and a new pixel each sample (every splat a
//! cache miss). A splat's `Result` is read with `is_ok()`, as a renderer
//! reads it: returned whole, criterion would copy and drop an 88-byte
//! value each iteration and time that too.
//!
//! ```text
//! cargo bench -p speclab-tools --bench film
//! ```

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use speclab::film::{Buckets, Kind, SpectralFilm};
use speclab::sampling::pdf::Uniform;
use speclab::spectrum::{DenseObserver, DenseSpectrum, Float, SampledSpectrum, WavelengthRange};
use speclab::{HeroSample, Xyz, data};

/// 1024 samples and their values `F11 × H4` over dense tables.
fn samples<T: Float>() -> Vec<(HeroSample<4, T>, SampledSpectrum<4, T>)> {
    let (light, surface) = (DenseSpectrum::new(&data::lights::F11), DenseSpectrum::new(&data::patches::H4));
    (0..1024)
        .map(|i| {
            let u = T::from_f64((i as f64 * 0.618_033_988_749_895).fract());
            let h = HeroSample::<4, T>::from_pdf_with(u, &Uniform::ASSIGNMENT, &DenseObserver::CIE_1931)
                .expect("the CIE observer covers 380–730 nm");
            (h, light.sample(&h) * surface.sample(&h))
        })
        .collect()
}

fn film(c: &mut Criterion) {
    let mut group = c.benchmark_group("a hero sample: splat or convert");
    for m in [16, 351] {
        let buckets = Buckets::new(WavelengthRange::new(379.5, 730.5).expect("a range"), m).expect("buckets");
        bench::<f32>(&mut group, buckets, "f32");
        bench::<f64>(&mut group, buckets, "f64");
    }
    group.finish();
}

fn bench<T: Float>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    buckets: Buckets,
    precision: &str,
) {
    let all = samples::<T>();
    let mut film = SpectralFilm::new((64, 64), buckets, Kind::Emissive).expect("a film");
    let mut xyz = vec![Xyz::ZERO; 64 * 64];
    // A tracer's order: 16 samples in a pixel, then the next pixel.
    let at = |i: usize| ((i >> 4) & 63, (i >> 10) & 63);
    let mut i = 0;
    let m = buckets.count();
    group.bench_function(format!("to_xyz, added to the pixel, {precision} (beside M = {m})"), |b| {
        b.iter(|| {
            i = (i + 1) & 0xF_FFFF;
            let (h, v) = &all[i & 1023];
            let (x, y) = at(i);
            xyz[y * 64 + x] += black_box(h).to_xyz(black_box(*v));
        })
    });
    group.bench_function(format!("splat into 64 × 64 × {m}, {precision}"), |b| {
        b.iter(|| {
            i = (i + 1) & 0xF_FFFF;
            let (h, v) = &all[i & 1023];
            film.splat(at(i), black_box(h), black_box(*v)).is_ok()
        })
    });
    group.bench_function(format!("splat into 64 × 64 × {m}, not inlined, {precision}"), |b| {
        b.iter(|| {
            i = (i + 1) & 0xF_FFFF;
            let (h, v) = &all[i & 1023];
            splat_once(&mut film, at(i), black_box(h), black_box(*v))
        })
    });
    group.bench_function(format!("splat into 64 × 64 × {m}, a new pixel each sample, {precision}"), |b| {
        b.iter(|| {
            i = (i + 1) & 0xF_FFFF;
            let (h, v) = &all[i & 1023];
            film.splat((i & 63, (i >> 6) & 63), black_box(h), black_box(*v)).is_ok()
        })
    });
    black_box(xyz);
}

/// One splat, as a call (what a renderer's own splat function does).
#[inline(never)]
fn splat_once<T: Float>(
    film: &mut SpectralFilm,
    at: (usize, usize),
    h: &HeroSample<4, T>,
    v: SampledSpectrum<4, T>,
) -> bool {
    film.splat(at, h, v).is_ok()
}

criterion_group!(benches, film);
criterion_main!(benches);
