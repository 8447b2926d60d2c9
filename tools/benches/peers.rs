//! speclab's per-sample path beside two kernels of the kind renderers write
//! (see `peers/kernels.rs`), and the rest of the speed targets, in one run,
//! on the same spectra (F11 × H4). Prints the table the README quotes:
//! medians over interleaved rounds, and ratios to the hand-tuned kernel
//! taken within each run, the median of three runs.
//!
//! ```text
//! cargo bench -p speclab-tools --bench peers
//! ```

#[path = "peers/harness.rs"]
mod harness;
#[path = "peers/kernels.rs"]
mod kernels;

use std::hint::black_box;

use harness::{Case, measure, median};
use kernels::{Pcg32, Tables, XorShift32};
use rayon::prelude::*;
use rayon::{ThreadPool, ThreadPoolBuilder};
use speclab::sampling::{PreparedLight, reference, rule::Rule};
use speclab::spectrum::DenseSpectrum;
use speclab::{BoxAverage, Center, RegularSpectrum, Spectrum, TabulatedSpectrum, Xyz, data};

/// Hero samples per batch.
const N: usize = 1024;
/// Spectra per batch conversion (a 256 × 256 texture).
const SPECTRA: usize = 65_536;

/// One row of the table: what, target, and how to read the measurement.
struct Row {
    what: &'static str,
    target: &'static str,
    unit: Unit,
}

#[derive(Clone, Copy)]
enum Unit {
    /// ns per unit, with its ratio to the hand-tuned kernel.
    Ratio,
    /// ns per unit, with its ratio to speclab's f32 dense row (row 2).
    Dense,
    /// ns per call.
    Nanos,
    /// millions of spectra per second, and the ratio to row `.0`.
    Throughput(Option<usize>),
}

fn main() {
    let (light, surface) = (&data::lights::F11, &data::patches::H4);
    let tables = Tables::new(light, surface);
    let prepared = PreparedLight::for_grid(light, surface.lambda(), surface.interpolation()).expect("grid");
    let reflectances = mixtures(SPECTRA);
    let (dl, ds) = (DenseSpectrum::new(light), DenseSpectrum::new(surface));
    let materials: [Box<dyn Spectrum + Send + Sync>; 2] = [Box::new(dl.clone()), Box::new(ds.clone())];
    let [bl, bs] = materials;
    let albedo = speclab::color::RgbAlbedo::new(speclab::LinearRgb::new(0.2, 0.5, 0.1)).expect("in gamut");
    let list = [
        kernels::Material::Table(dl.clone()),
        kernels::Material::Table(ds.clone()),
        kernels::Material::Rgb(albedo),
    ];
    let (el, es) = (black_box(&list[0]), black_box(&list[1]));
    let er = black_box(&list[2]);
    let dyn_albedo: Box<dyn Spectrum + Send + Sync> = Box::new(albedo);
    // A texture's colours: 64 albedos spread through the cube (golden-ratio steps).
    let texels: Vec<speclab::color::LinearRgb> = (0..64)
        .map(|i| {
            let v = (f64::from(i) * 0.618_033_988_7).fract();
            speclab::color::LinearRgb::new(v, (v * 3.7).fract(), (v * 7.3).fract())
        })
        .collect();
    // And 4,096 random ones: a texture whose lookups leave the caches.
    let mut rng = XorShift32(0x2545_F491);
    let random_texels: Vec<speclab::color::LinearRgb> = (0..4096)
        .map(|_| speclab::color::LinearRgb::from([0; 3].map(|_| f64::from(rng.next() >> 8) / 16_777_216.0)))
        .collect();
    let srgb = speclab::color::RgbSpace::srgb();
    let converted: Vec<speclab::color::RgbAlbedo> =
        texels.iter().map(|&rgb| srgb.albedo(rgb).expect("texels are albedos")).collect();
    let small: Vec<speclab::color::RgbTexel> = converted.iter().map(|&a| a.into()).collect();
    let (lc, sc) =
        (RegularSpectrum::<16, Center>::center(light), RegularSpectrum::<16, Center>::center(surface));
    let (lb, sb) = (
        RegularSpectrum::<16, BoxAverage>::box_average(light),
        RegularSpectrum::<16, BoxAverage>::box_average(surface),
    );
    let (lc32, sc32) = (
        RegularSpectrum::<16, Center, f32>::center(light),
        RegularSpectrum::<16, Center, f32>::center(surface),
    );
    let (lb32, sb32) = (
        RegularSpectrum::<16, BoxAverage, f32>::box_average(light),
        RegularSpectrum::<16, BoxAverage, f32>::box_average(surface),
    );
    let rule = Rule::fit(&[light], 10).expect("a rule");
    let at = rule.wavelengths::<10, f32>().expect("M = 10");
    let (lf, sf) = (light.sample(&at), surface.sample(&at));
    let at64 = rule.wavelengths::<10, f64>().expect("M = 10");
    let (lf64, sf64) = (light.sample(&at64), surface.sample(&at64));
    let rows = [
        Row { what: "hand-tuned kernel, per wavelength", target: "", unit: Unit::Ratio },
        Row { what: "pbrt-style kernel, per wavelength", target: "", unit: Unit::Ratio },
        Row {
            what: "f32 hero K = 4 over dense tables (the README's loop), per wavelength",
            target: "≤ 1.3×",
            unit: Unit::Ratio,
        },
        Row {
            what: "the same, materials as an enum of kinds, per wavelength",
            target: "≤ 1.3×",
            unit: Unit::Ratio,
        },
        Row {
            what: "the same, materials as Box<dyn Spectrum>, per wavelength",
            target: "",
            unit: Unit::Ratio,
        },
        Row { what: "f64 hero K = 4 over dense tables, per wavelength", target: "", unit: Unit::Ratio },
        Row {
            what: "f32 hero K = 4, the surface an RGB albedo already looked up, per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row {
            what: "the same, the albedo in the enum of kinds, per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row {
            what: "the same, the albedo as Box<dyn Spectrum>, per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row {
            what: "f32 hero K = 4, a texel: space.albedo(rgb) at each hit, then the sample, per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row {
            what: "the same, 4,096 random texels (the table leaves the caches), per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row {
            what: "the same texture converted once (an RgbAlbedo per texel), read and sampled, per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row {
            what: "the same, each texel in 12 bytes (an RgbTexel, decoded at the hit), per wavelength",
            target: "",
            unit: Unit::Dense,
        },
        Row { what: "exact hero K = 4 (f64), per wavelength", target: "≤ 5×", unit: Unit::Ratio },
        Row { what: "exact hero K = 4 (f32), per wavelength", target: "", unit: Unit::Ratio },
        Row { what: "one random wavelength (exact, f64)", target: "≤ 6×", unit: Unit::Ratio },
        Row {
            what: "RegularSpectrum<16> centre (f64), multiply + to_xyz",
            target: "≤ 3 ns",
            unit: Unit::Nanos,
        },
        Row {
            what: "RegularSpectrum<16> box (f64), multiply + to_xyz", target: "≤ 3 ns", unit: Unit::Nanos
        },
        Row {
            what: "RegularSpectrum<16> centre (f32), multiply + to_xyz",
            target: "≤ 3 ns",
            unit: Unit::Nanos,
        },
        Row {
            what: "RegularSpectrum<16> box (f32), multiply + to_xyz", target: "≤ 3 ns", unit: Unit::Nanos
        },
        Row { what: "fitted rule M = 10 (f32), multiply + to_xyz", target: "≤ 2.5 ns", unit: Unit::Nanos },
        Row { what: "fitted rule M = 10 (f64), multiply + to_xyz", target: "", unit: Unit::Nanos },
        Row { what: "bucketing one spectrum, M = 16, centre", target: "≤ 40 ns", unit: Unit::Nanos },
        Row { what: "bucketing one spectrum, M = 16, box", target: "≤ 150 ns", unit: Unit::Nanos },
        Row {
            what: "exact reference, one pair, the light prepared", target: "≤ 1000 ns", unit: Unit::Nanos
        },
        Row {
            what: "exact reference, one pair, from nothing (reference::xyz)",
            target: "",
            unit: Unit::Nanos,
        },
        Row {
            what: "batch, 36-sample reflectances, 1 thread",
            target: "≥ 40 M/s",
            unit: Unit::Throughput(None),
        },
        Row { what: "batch, 2 threads", target: "≥ 1.6× 1 thread", unit: Unit::Throughput(Some(24)) },
        Row {
            what: "reading the same reflectances alone (a sum), 1 thread",
            target: "",
            unit: Unit::Throughput(None),
        },
    ];
    let pools = [1, 2].map(|n| ThreadPoolBuilder::new().num_threads(n).build().expect("a thread pool"));
    let mut runs = Vec::new();
    for run in 0..3 {
        let seed = XorShift32(0x9E37_79B9);
        let (mut r1, mut r2, mut r3, mut r4, mut r5) =
            (seed, seed, Pcg32::new(7), seed, XorShift32(0x1234_5678));
        let (mut r6, mut r7, mut r8, mut r9) = (seed, seed, seed, seed);
        let (mut r10, mut r11, mut r12, mut r13, mut r14, mut r15, mut r16) =
            (seed, seed, seed, seed, seed, seed, seed);
        let (mut out, mut out2) = (vec![Xyz::ZERO; SPECTRA], vec![Xyz::ZERO; SPECTRA]);
        let mut cases = [
            Case::new("hand-tuned", || (black_box(kernels::hand_tuned_hero(&tables, N, &mut r1)), 4 * N).1),
            Case::new("pbrt-style", || (black_box(kernels::pbrt_hero(&tables, N, &mut r3)), 4 * N).1),
            Case::new("dense f32", || {
                (black_box(kernels::speclab_dense_hero::<f32, _, _>(&dl, &ds, N, &mut r6)), 4 * N).1
            }),
            Case::new("dense f32 enum", || {
                (black_box(kernels::speclab_dense_hero::<f32, _, _>(el, es, N, &mut r9)), 4 * N).1
            }),
            Case::new("dense f32 dyn", || {
                (black_box(kernels::speclab_dense_hero::<f32, _, _>(&bl, &bs, N, &mut r8)), 4 * N).1
            }),
            Case::new("dense f64", || {
                (black_box(kernels::speclab_dense_hero::<f64, _, _>(&dl, &ds, N, &mut r7)), 4 * N).1
            }),
            Case::new("albedo f32", || {
                (black_box(kernels::speclab_dense_hero::<f32, _, _>(&dl, &albedo, N, &mut r10)), 4 * N).1
            }),
            Case::new("albedo f32 enum", || {
                (black_box(kernels::speclab_dense_hero::<f32, _, _>(el, er, N, &mut r11)), 4 * N).1
            }),
            Case::new("albedo f32 dyn", || {
                (black_box(kernels::speclab_dense_hero::<f32, _, _>(&bl, &dyn_albedo, N, &mut r12)), 4 * N).1
            }),
            Case::new("texel f32", || {
                (black_box(kernels::speclab_texel_hero(srgb, &dl, &texels, N, &mut r13)), 4 * N).1
            }),
            Case::new("texel f32 random", || {
                (black_box(kernels::speclab_texel_hero(srgb, &dl, &random_texels, N, &mut r15)), 4 * N).1
            }),
            Case::new("texel f32 converted", || {
                (black_box(kernels::speclab_converted_texel_hero(&dl, &converted, N, &mut r14)), 4 * N).1
            }),
            Case::new("texel f32 12 bytes", || {
                (black_box(kernels::speclab_texel_12_hero(&dl, &small, N, &mut r16)), 4 * N).1
            }),
            Case::new("exact f64", || {
                (black_box(kernels::speclab_hero::<4, f64>(light, surface, N, &mut r2)), 4 * N).1
            }),
            Case::new("exact f32", || {
                (black_box(kernels::speclab_hero::<4, f32>(light, surface, N, &mut r4)), 4 * N).1
            }),
            Case::new("random", || {
                (black_box(kernels::speclab_hero::<1, f64>(light, surface, N, &mut r5)), N).1
            }),
            Case::new("centre", || calls(|| (*black_box(&lc) * *black_box(&sc)).to_xyz())),
            Case::new("box", || calls(|| (*black_box(&lb) * *black_box(&sb)).to_xyz())),
            Case::new("centre f32", || calls(|| (*black_box(&lc32) * *black_box(&sc32)).to_xyz())),
            Case::new("box f32", || calls(|| (*black_box(&lb32) * *black_box(&sb32)).to_xyz())),
            Case::new("fitted", || calls(|| black_box(&at).to_xyz(*black_box(&lf) * *black_box(&sf)))),
            Case::new("fitted f64", || {
                calls(|| black_box(&at64).to_xyz(*black_box(&lf64) * *black_box(&sf64)))
            }),
            Case::new("bucket centre", || calls(|| RegularSpectrum::<16, Center>::center(black_box(light)))),
            Case::new("bucket box", || {
                calls(|| RegularSpectrum::<16, BoxAverage>::box_average(black_box(light)))
            }),
            Case::new("prepared", || calls(|| black_box(&prepared).xyz(black_box(surface)))),
            Case::new("reference", || calls(|| reference::xyz(black_box(light), black_box(surface)))),
            Case::new("batch 1", || batch(&prepared, &reflectances, &mut out, &pools[0])),
            Case::new("batch 2", || batch(&prepared, &reflectances, &mut out2, &pools[1])),
            Case::new("read", || {
                black_box(read(black_box(&reflectances)));
                SPECTRA
            }),
        ];
        let ns = measure(&mut cases, 15, 20.0);
        eprintln!(
            "run {run}: {}",
            cases.iter().zip(&ns).map(|(c, t)| format!("{} {t:.2}", c.name)).collect::<Vec<_>>().join(", ")
        );
        runs.push(ns);
    }
    print_table(&rows, &runs);
    print_sizes(light, surface);
}

/// Calls `f` [`CALLS`] times (so that the harness's indirect call is spread
/// over many); returns the number of calls.
#[inline(always)]
fn calls<T>(mut f: impl FnMut() -> T) -> usize {
    for _ in 0..CALLS {
        black_box(f());
    }
    CALLS
}

/// Calls per batch of the single-call cases.
const CALLS: usize = 64;

/// Converts `r` into `out` on the threads of `pool` (one share each);
/// returns spectra converted.
fn batch(
    prepared: &PreparedLight<&TabulatedSpectrum>,
    r: &[f64],
    out: &mut [Xyz],
    pool: &ThreadPool,
) -> usize {
    let threads = pool.current_num_threads();
    if threads == 1 {
        prepared.batch(r, out).expect("valid reflectances");
        return out.len();
    }
    let per = out.len().div_ceil(threads);
    pool.install(|| {
        r.par_chunks(per * 36)
            .zip(out.par_chunks_mut(per))
            .for_each(|(r, out)| prepared.batch(r, out).expect("valid reflectances"));
    });
    black_box(&out);
    out.len()
}

/// The sum of `r` in eight independent lanes: reading it as fast as the
/// memory gives it (the floor under the batch).
fn read(r: &[f64]) -> f64 {
    let mut acc = [0.0f64; 8];
    for c in r.as_chunks::<8>().0 {
        for l in 0..8 {
            acc[l] += c[l];
        }
    }
    acc.iter().sum()
}

/// `count` reflectances on the patches' grid: random convex mixtures of the
/// six patches (smooth, in [0, 1], like a texture's).
fn mixtures(count: usize) -> Vec<f64> {
    let patches = data::Patch::ALL.map(|p| p.spectrum().values());
    let mut rng = XorShift32(0x2545_F491);
    let mut out = Vec::with_capacity(count * 36);
    for _ in 0..count {
        let w: [f64; 6] = std::array::from_fn(|_| f64::from(rng.next() >> 8));
        let total: f64 = w.iter().sum();
        out.extend((0..36).map(|i| patches.iter().zip(&w).map(|(p, w)| p[i] * w / total).sum::<f64>()));
    }
    out
}

fn print_table(rows: &[Row], runs: &[Vec<f64>]) {
    let col = |i: usize| median(runs.iter().map(|r| r[i]).collect());
    let ratio = |i: usize, to: usize| median(runs.iter().map(|r| r[i] / r[to]).collect());
    println!("\nspeclab speed, median of 3 runs (F11 × H4; one core unless stated; ratios within each run)");
    println!(
        "last column: the time per wavelength, call or spectrum over the hand-tuned kernel's per wavelength"
    );
    println!("| path | target | measured | ÷ hand-tuned |\n|---|---|---|---|");
    for (i, row) in rows.iter().enumerate() {
        let measured = match row.unit {
            Unit::Ratio => format!("{:.2} ns, {:.2}× hand-tuned", col(i), ratio(i, 0)),
            Unit::Dense => format!("{:.2} ns, {:.2}× dense f32", col(i), ratio(i, 2)),
            Unit::Nanos => format!("{:.1} ns", col(i)),
            Unit::Throughput(None) => format!("{:.1} M spectra/s", 1e3 / col(i)),
            Unit::Throughput(Some(one)) => {
                format!("{:.1} M spectra/s, {:.2}× 1 thread", 1e3 / col(i), ratio(one, i))
            }
        };
        println!("| {} | {} | {measured} | {:.1}× |", row.what, row.target, ratio(i, 0));
    }
}

/// The static tables the hot paths read, in bytes.
fn print_sizes(light: &TabulatedSpectrum, surface: &TabulatedSpectrum) {
    let spectrum = |s: &TabulatedSpectrum| s.lambda().len() * 8 + (s.lambda().len() - 1) * 32;
    // Four vectors [x, y, z, 1] of four f64 per 5 nm segment, and the knots.
    let observer = 80 * 128 + 81 * 8;
    let weights = 36 * 24 + 35 * 96 + 35 * 64 + 36 * 8;
    println!(
        "\nhot tables: observer coefficients {observer} B; F11 {} B; H4 {} B; one light's reference weights {weights} B",
        spectrum(light),
        spectrum(surface)
    );
    println!("dense f32 tables: 352 × 4 B per spectrum, observer 352 × 16 B");
}
