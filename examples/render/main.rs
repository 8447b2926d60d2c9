//! A small spectral path tracer over speclab's renderer API (no `study`):
//! a box of ColorChecker walls and spheres with an RGB-textured back wall,
//! hero wavelengths (K = 4) from a chosen pdf and strata, Russian roulette
//! on the throughput's luminance, both cores, a PNG through
//! `color::display`. It renders twice, spectral and grey (the same paths
//! with one number per surface), and prints the time per path vertex of
//! each: the difference is speclab's share.
//!
//! ```text
//! cargo run --release --example render
//! cargo run --release --example render -- --light f11 --pdf light --spp 64 --reference 1024
//! cargo run --release --example render -- --light-file examples/build-data/data/led.csv --spectra dense
//! ```

mod output;
mod paint;
mod tracer;

use std::marker::PhantomData;
use std::path::PathBuf;
use std::process::ExitCode;
use std::str::FromStr;
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use output::{reference_error, report, write_png};
use paint::{Grey, Spectral};
use speclab::color::upsample::RgbSpace;
use speclab::data::{Light, Patch, lights};
use speclab::sampling::binned::BinnedPdf;
use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
use speclab::sampling::{reference, strata::Strata};
use speclab::spectrum::{Cie1931, DenseObserver, DenseSpectrum, Float, RgbAlbedo, Spectrum};
use speclab::{LinearSrgb, Role, TabulatedSpectrum, Xyz, io::Load};
use tracer::{Material, Paint, Rng, Scene};

const USAGE: &str = "\
usage: render [--width W] [--height H] [--spp N] [--light NAME | --light-file PATH]
              [--pdf uniform|visible|light|balanced] [--strata none|jitter|kronecker]
              [--bins B | --exact-pdf] [--spectra exact|dense] [--precision f64|f32]
              [--reference N] [--threads T] [--out PATH]
  --width, --height  image size in pixels (default 256 × 256)
  --spp N            paths per pixel (default 32)
  --light NAME       a built-in light (listed by --help; default D65), or D and a
                     temperature for CIE daylight; --light-file reads any light
  --pdf P            how hero wavelengths are drawn (default uniform)
  --strata S         how a pixel's primary numbers are spread (default jitter)
  --bins B           sample visible and light pdfs from a histogram of B bins
                     (BinnedPdf, default 256); --exact-pdf samples the
                     density itself (inverting its CDF per wavelength)
  --spectra S        exact tabulated spectra (default) or dense 1 nm tables
  --precision P      the per-sample values' precision, f64 (default) or f32
  --reference N      also render N paths per pixel and print the RMS ΔE*ab
  --threads T        worker threads (default 2)
  --out PATH         the PNG to write (default render.png)";

/// The wavelength pdfs a renderer picks from.
#[derive(Clone, Copy, Debug)]
enum PdfChoice {
    Uniform,
    Visible,
    Light,
    Balanced,
}

impl FromStr for PdfChoice {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "uniform" => Ok(PdfChoice::Uniform),
            "visible" => Ok(PdfChoice::Visible),
            "light" => Ok(PdfChoice::Light),
            "balanced" => Ok(PdfChoice::Balanced),
            _ => Err(format!("expected a pdf (uniform, visible, light or balanced), found {s:?}")),
        }
    }
}

struct Args {
    width: usize,
    height: usize,
    spp: usize,
    light: TabulatedSpectrum,
    light_name: String,
    pdf: PdfChoice,
    strata: Strata,
    dense: bool,
    single: bool,
    /// Bins of the histogram pdf, or `None` for the exact density.
    bins: Option<usize>,
    reference: Option<usize>,
    threads: usize,
    out: PathBuf,
}

fn positive(what: &str, v: &str) -> Result<usize, String> {
    v.parse::<usize>()
        .ok()
        .filter(|&n| n > 0)
        .ok_or_else(|| format!("expected a positive {what}, found {v:?}"))
}

fn parse_args() -> Result<Args, Box<dyn std::error::Error>> {
    use lexopt::prelude::*;
    let mut a = Args {
        width: 256,
        height: 256,
        spp: 32,
        light: Light::D65.spectrum().clone(),
        light_name: "D65".into(),
        pdf: PdfChoice::Uniform,
        strata: Strata::Jittered,
        dense: false,
        single: false,
        bins: Some(256),
        reference: None,
        threads: 2,
        out: PathBuf::from("render.png"),
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("width") => a.width = parser.value()?.parse_with(|v| positive("width", v))?,
            Long("height") => a.height = parser.value()?.parse_with(|v| positive("height", v))?,
            Long("spp") => a.spp = parser.value()?.parse_with(|v| positive("path count", v))?,
            Long("light") => {
                let name = parser.value()?.string()?;
                (a.light, a.light_name) = (lights::named(&name)?.into_owned(), name.to_uppercase());
            }
            Long("light-file") => {
                let path: PathBuf = parser.value()?.into();
                a.light = Load::new(Role::Light).file(&path)?;
                a.light_name = path.display().to_string();
            }
            Long("pdf") => a.pdf = parser.value()?.parse()?,
            Long("strata") => a.strata = parser.value()?.parse()?,
            Long("spectra") => {
                a.dense = match parser.value()?.string()?.as_str() {
                    "exact" => false,
                    "dense" => true,
                    other => return Err(format!("expected exact or dense spectra, found {other:?}").into()),
                }
            }
            Long("precision") => {
                a.single = match parser.value()?.string()?.as_str() {
                    "f64" => false,
                    "f32" => true,
                    other => return Err(format!("expected f64 or f32, found {other:?}").into()),
                }
            }
            Long("bins") => a.bins = Some(parser.value()?.parse_with(|v| positive("bin count", v))?),
            Long("exact-pdf") => a.bins = None,
            Long("reference") => {
                a.reference = Some(parser.value()?.parse_with(|v| positive("path count", v))?)
            }
            Long("threads") => a.threads = parser.value()?.parse_with(|v| positive("thread count", v))?,
            Long("out") => a.out = parser.value()?.into(),
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected().into()),
        }
    }
    if a.width.saturating_mul(a.height) > 1 << 24 {
        return Err("expected at most 16 M pixels".into());
    }
    Ok(a)
}

/// The walls (floor, ceiling, back, left, right, front) and the spheres.
fn scene() -> Scene {
    let patch = |p: Patch| Material::Patch(Patch::ALL.iter().position(|&q| q == p).unwrap_or(0));
    Scene {
        walls: [
            patch(Patch::E2),
            patch(Patch::A1),
            Material::Texture,
            patch(Patch::G4),
            patch(Patch::F4),
            patch(Patch::A1),
        ],
        spheres: [([0.3, 0.15, 0.8], 0.15, patch(Patch::H4)), ([0.7, 0.12, 0.68], 0.12, patch(Patch::J4))],
    }
}

/// The back wall's 8 × 8 texels: a hue circle across, lightness down.
fn texture_colours() -> Vec<LinearSrgb> {
    let hue = |h: f64| [0.0, 2.0, 4.0].map(|o: f64| ((h * 6.0 + o) % 6.0 - 3.0).abs().clamp(1.0, 2.0) - 1.0);
    (0..64)
        .map(|t| {
            let (column, row) = (t / 8, t % 8);
            let lightness = 0.15 + 0.8 * (7 - row) as f64 / 7.0;
            LinearSrgb::from(hue(column as f64 / 8.0).map(|c| lightness * (0.25 + 0.75 * c)))
        })
        .collect()
}

/// A pixel's seed, spread by SplitMix64's finaliser.
fn seed(pass: u64, pixel: usize) -> u64 {
    let mut z = pass.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (pixel as u64).wrapping_add(0xD1B5_4A32_D192_ED03);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z ^ (z >> 31)) | 1
}

/// An image of mean XYZ per pixel, and the vertices its paths met.
struct Render {
    xyz: Vec<Xyz>,
    vertices: u64,
    seconds: f64,
}

fn render<P: Paint>(scene: &Scene, paint: &P, a: &Args, spp: usize, pass: u64) -> Render {
    let mut xyz = vec![Xyz::ZERO; a.width * a.height];
    let rows = Mutex::new(xyz.chunks_mut(a.width).enumerate());
    let vertices = AtomicU64::new(0);
    let start = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..a.threads {
            s.spawn(|| {
                let mut count = 0;
                while let Some((y, row)) = rows.lock().map(|mut r| r.next()).ok().flatten() {
                    for (x, pixel) in row.iter_mut().enumerate() {
                        let mut rng = Rng(seed(pass, y * a.width + x));
                        let shift = rng.next();
                        let mut sum = Xyz::ZERO;
                        for i in 0..spp {
                            let u = if a.strata == Strata::Kronecker { shift } else { rng.next() };
                            let path = paint.path(a.strata.point(i, spp, 4, u));
                            let at = (
                                (x as f64 + rng.next()) / a.width as f64,
                                (y as f64 + rng.next()) / a.height as f64,
                            );
                            let (value, n) = tracer::trace(scene, paint, &path, at, &mut rng);
                            sum += value;
                            count += u64::from(n);
                        }
                        *pixel = sum / spp as f64;
                    }
                }
                vertices.fetch_add(count, Ordering::Relaxed);
            });
        }
    });
    Render { xyz, vertices: vertices.into_inner(), seconds: start.elapsed().as_secs_f64() }
}

/// Renders spectrally with `light`, `patches` and `observer`, three times per mode
/// (spectral, grey, spectral, grey, …) keeping each mode's fastest run.
fn spectral_and_grey<S: Spectrum + Sync, O: speclab::spectrum::Observer + Sync, T: Float>(
    a: &Args,
    spectral: &Spectral<'_, S, O, T>,
    grey: &Grey,
) -> (Render, Render) {
    let scene = scene();
    let (mut best_s, mut best_g): (Option<Render>, Option<Render>) = (None, None);
    for _ in 0..3 {
        let s = render(&scene, spectral, a, a.spp, 1);
        let g = render(&scene, grey, a, a.spp, 1);
        if best_s.as_ref().is_none_or(|b| s.seconds < b.seconds) {
            best_s = Some(s);
        }
        if best_g.as_ref().is_none_or(|b| g.seconds < b.seconds) {
            best_g = Some(g);
        }
    }
    (best_s.expect("two runs"), best_g.expect("two runs"))
}

fn main() -> ExitCode {
    let a = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("render: {e}\n(render --help lists the options)");
            return ExitCode::from(2);
        }
    };
    let space = RgbSpace::srgb();
    let colours = texture_colours();
    let texture: Vec<RgbAlbedo> = match colours.iter().map(|&c| RgbAlbedo::new(c)).collect() {
        Ok(t) => t,
        Err(e) => return fail(e),
    };
    let pdf = match wavelength_pdf(&a) {
        Ok(pdf) => pdf,
        Err(e) => return fail(e),
    };
    let white = reference::white(&a.light);
    let grey = Grey {
        patches: Patch::ALL.iter().map(|p| reference::xyz(&a.light, p.spectrum()).y / white.y).collect(),
        texture: colours.iter().map(|&c| space.xyz(c).y / space.white().y).collect(),
        white,
    };
    let image = match (a.dense, a.single) {
        (false, false) => run::<_, _, f64>(&a, a.light.clone(), patches(), Cie1931, &texture, &*pdf, &grey),
        (false, true) => run::<_, _, f32>(&a, a.light.clone(), patches(), Cie1931, &texture, &*pdf, &grey),
        (true, false) => {
            let dense = |s: &TabulatedSpectrum| DenseSpectrum::<f64>::new(s);
            let observer = DenseObserver::<f64>::new();
            run::<_, _, f64>(
                &a,
                dense(&a.light),
                patches().map(|p| dense(&p)),
                observer,
                &texture,
                &*pdf,
                &grey,
            )
        }
        (true, true) => {
            let dense = |s: &TabulatedSpectrum| DenseSpectrum::<f32>::new(s);
            let observer = DenseObserver::<f32>::new();
            run::<_, _, f32>(
                &a,
                dense(&a.light),
                patches().map(|p| dense(&p)),
                observer,
                &texture,
                &*pdf,
                &grey,
            )
        }
    };
    match write_png(&a, &image.xyz, white) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(e),
    }
}

/// The built-in patches.
fn patches() -> impl Iterator<Item = TabulatedSpectrum> {
    Patch::ALL.iter().map(|p| p.spectrum().clone())
}

/// Renders spectrally (and grey, for the timing) with these spectra,
/// observer and precision; reports; returns the spectral image.
fn run<S: Spectrum + Sync, O: speclab::spectrum::Observer + Sync, T: Float>(
    a: &Args,
    light: S,
    patches: impl Iterator<Item = S>,
    observer: O,
    texture: &[RgbAlbedo],
    pdf: &(dyn WavelengthPdf + Sync),
    grey: &Grey,
) -> Render {
    let spectral =
        Spectral { light, patches: patches.collect(), texture, observer, pdf, precision: PhantomData::<T> };
    let (s, g) = spectral_and_grey(a, &spectral, grey);
    report(a, &s, &g);
    reference_error(a, &spectral, s)
}

/// The chosen density, as a histogram of `--bins` bins unless
/// `--exact-pdf` (uniform needs neither).
fn wavelength_pdf(a: &Args) -> Result<Box<dyn WavelengthPdf + Sync>, speclab::Error> {
    let exact: Box<dyn WavelengthPdf + Sync> = match a.pdf {
        PdfChoice::Uniform => return Ok(Box::new(Uniform)),
        PdfChoice::Visible => Box::new(Visible),
        PdfChoice::Light => Box::new(LightPdf::light(&a.light)?),
        PdfChoice::Balanced => Box::new(LightPdf::balanced(&a.light)?),
    };
    Ok(match a.bins {
        Some(bins) => Box::new(BinnedPdf::new(&*exact, bins)?),
        None => exact,
    })
}

/// The built-in lights, for the help text.
fn names_help() -> String {
    format!("built-in lights (any case): {}", lights::NAMES.join(", "))
}

fn fail(e: impl std::fmt::Display) -> ExitCode {
    eprintln!("render: {e}");
    ExitCode::from(2)
}
