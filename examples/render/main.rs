//! A small path tracer over speclab's renderer API: a box of ColorChecker
//! walls and spheres with an RGB-textured back wall, lit by one or two
//! lights in the ceiling, with colour carried three ways (`--wavelengths`):
//! hero wavelengths (K = 4, from a chosen pdf and strata), a rule of M
//! wavelengths fitted to the scene's lights, or RGB triples. It renders
//! twice, with colour and grey (the same paths, one number per surface),
//! and prints the time per path vertex of each: the difference is the
//! colour's share. `--exact` integrates each of the same paths exactly over
//! wavelength and compares pixel by pixel; `--survey` does so for every way
//! and prints the render-level speed against accuracy.
//!
//! ```text
//! cargo run --release --example render
//! cargo run --release --example render -- --light f11 --wavelengths fitted --m 10 --exact
//! cargo run --release --example render -- --light F11 --light A --survey --csv docs/render.csv
//! ```

mod args;
mod exact;
mod output;
mod paint;
#[cfg(feature = "study")]
mod survey;
mod tracer;

use std::marker::PhantomData;
use std::process::ExitCode;
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use args::{Args, Mode};
use exact::{ExactScene, PathRecord};
use paint::{Fitted, Grey, Hero, Rgb};
use speclab::color::RgbAlbedo;
use speclab::color::upsample::RgbSpace;
use speclab::data::Patch;
use speclab::sampling::binned::BinnedPdf;
use speclab::sampling::pdf::WavelengthPdf;
use speclab::sampling::{reference, rule::Rule, strata::Strata};
use speclab::spectrum::{Cie1931, DenseObserver, DenseSpectrum, Spectrum};
use speclab::{LinearSrgb, TabulatedSpectrum, Xyz};
use tracer::{Material, Paint, Rng, Scene};

/// The walls (floor, ceiling, back, left, right, front), the spheres, and
/// `lights` squares in the ceiling.
fn scene(lights: usize) -> Scene {
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
        lights: if lights > 1 { vec![[0.3, 0.7], [0.7, 0.7]] } else { vec![[0.5, 0.7]] },
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

/// An image of mean XYZ per pixel (and, if asked, the exact image of the
/// same paths), the vertices its paths met, and how long it took.
pub struct Render {
    pub xyz: Vec<Xyz>,
    pub exact: Option<Vec<Xyz>>,
    pub vertices: u64,
    pub seconds: f64,
}

/// Renders `spp` paths per pixel on `threads` threads; with `exact`, each
/// path's exact colour too (not timed apart: time the render without it).
pub fn render<P: Paint>(
    scene: &Scene,
    paint: &P,
    a: &Args,
    (spp, threads): (usize, usize),
    pass: u64,
    exact: Option<&ExactScene>,
) -> Render {
    let mut pixels = vec![(Xyz::ZERO, Xyz::ZERO); a.width * a.height];
    let rows = Mutex::new(pixels.chunks_mut(a.width).enumerate());
    let vertices = AtomicU64::new(0);
    let start = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                let mut count = 0;
                while let Some((y, row)) = rows.lock().map(|mut r| r.next()).ok().flatten() {
                    for (x, pixel) in row.iter_mut().enumerate() {
                        let mut rng = Rng(seed(pass, y * a.width + x));
                        let shift = rng.next();
                        let (mut sum, mut truth) = (Xyz::ZERO, Xyz::ZERO);
                        for i in 0..spp {
                            let u = if a.sampling.strata == Strata::Kronecker { shift } else { rng.next() };
                            let path = paint.path(a.sampling.strata.point(i, spp, 4, u));
                            let at = (
                                (x as f64 + rng.next()) / a.width as f64,
                                (y as f64 + rng.next()) / a.height as f64,
                            );
                            let (value, n) = match exact {
                                None => tracer::trace(scene, paint, &path, at, &mut rng, &mut ()),
                                Some(e) => {
                                    let mut record = PathRecord::new();
                                    let traced =
                                        tracer::trace(scene, paint, &path, at, &mut rng, &mut record);
                                    truth += e.xyz(&record);
                                    traced
                                }
                            };
                            sum += value;
                            count += u64::from(n);
                        }
                        *pixel = (sum / spp as f64, truth / spp as f64);
                    }
                }
                vertices.fetch_add(count, Ordering::Relaxed);
            });
        }
    });
    let seconds = start.elapsed().as_secs_f64();
    let (xyz, truth): (Vec<Xyz>, Vec<Xyz>) = pixels.into_iter().unzip();
    Render { xyz, exact: exact.map(|_| truth), vertices: vertices.into_inner(), seconds }
}

/// The scene's spectra and what every way of painting needs.
pub struct Setup {
    pub scene: Scene,
    pub lights: Vec<TabulatedSpectrum>,
    pub patches: Vec<TabulatedSpectrum>,
    pub colours: Vec<LinearSrgb>,
    pub texture: Vec<RgbAlbedo>,
    pub grey: Grey,
    pub white: Xyz,
}

impl Setup {
    fn new(a: &Args) -> Result<Self, speclab::Error> {
        let lights: Vec<TabulatedSpectrum> = a.lights.iter().map(|(_, l)| l.clone()).collect();
        let colours = texture_colours();
        let texture = colours.iter().map(|&c| RgbAlbedo::new(c)).collect::<Result<Vec<_>, _>>()?;
        let patches: Vec<TabulatedSpectrum> = Patch::ALL.iter().map(|p| p.spectrum().clone()).collect();
        let white: Xyz = lights.iter().map(reference::white).sum();
        let space = RgbSpace::srgb();
        let under_all =
            |s: &TabulatedSpectrum| lights.iter().map(|l| reference::xyz(l, s).y).sum::<f64>() / white.y;
        let grey = Grey {
            patches: patches.iter().map(under_all).collect(),
            texture: colours.iter().map(|&c| space.xyz(c).y / space.white().y).collect(),
            white,
        };
        Ok(Setup { scene: scene(lights.len()), lights, patches, colours, texture, grey, white })
    }

    /// The exact image's spectra.
    pub fn exact(&self) -> ExactScene {
        ExactScene::new(&self.lights, &self.patches, &self.texture)
    }
}

fn main() -> ExitCode {
    let a = match args::parse() {
        Ok(a) => a,
        Err(e) => return fail(format!("{e}\n(render --help lists the options)")),
    };
    let setup = match Setup::new(&a) {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    if a.survey {
        #[cfg(feature = "study")]
        return match survey::run(&a, &setup) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => fail(e),
        };
        #[cfg(not(feature = "study"))]
        return fail("--survey needs speclab's study feature (on by default)");
    }
    let image = match paint_and_run(&a, &setup) {
        Ok(image) => image,
        Err(e) => return fail(e),
    };
    match output::write_png(&a.out, a.width, a.height, &image.xyz, setup.white) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(e),
    }
}

/// Builds the paint `--wavelengths` asks for and runs it.
fn paint_and_run(a: &Args, setup: &Setup) -> Result<Render, speclab::Error> {
    match a.mode {
        Mode::Rgb => Ok(run(a, setup, &Rgb::new(&setup.lights, &setup.patches, &setup.colours))),
        Mode::Fitted => fitted(a, setup, a.m, Run(a, setup)),
        Mode::Hero => {
            let pdf = wavelength_pdf(a, setup)?;
            let dense = |s: &TabulatedSpectrum| DenseSpectrum::<f64>::new(s);
            let dense32 = |s: &TabulatedSpectrum| DenseSpectrum::<f32>::new(s);
            let (l, p) = (&setup.lights, &setup.patches);
            Ok(match (a.dense, a.single) {
                (false, false) => {
                    run(a, setup, &hero::<_, _, f64>(l.clone(), p.clone(), Cie1931, setup, &*pdf))
                }
                (false, true) => {
                    run(a, setup, &hero::<_, _, f32>(l.clone(), p.clone(), Cie1931, setup, &*pdf))
                }
                (true, false) => {
                    let (l, p) = (l.iter().map(dense).collect(), p.iter().map(dense).collect());
                    run(a, setup, &hero::<_, _, f64>(l, p, DenseObserver::<f64>::new(), setup, &*pdf))
                }
                (true, true) => {
                    let (l, p) = (l.iter().map(dense32).collect(), p.iter().map(dense32).collect());
                    run(a, setup, &hero::<_, _, f32>(l, p, DenseObserver::<f32>::new(), setup, &*pdf))
                }
            })
        }
    }
}

/// The hero paint over these spectra.
pub fn hero<'a, S, O, T>(
    lights: Vec<S>,
    patches: Vec<S>,
    observer: O,
    setup: &'a Setup,
    pdf: &'a (dyn WavelengthPdf + Sync),
) -> Hero<'a, S, O, T> {
    Hero { lights, patches, texture: &setup.texture, observer, pdf, precision: PhantomData }
}

/// Something done with a paint, whatever its type (a visitor: each way of
/// painting is its own type, monomorphised).
pub trait WithPaint {
    type Out;
    fn go<P: Paint>(self, paint: &P) -> Self::Out;
}

/// Runs a paint as `render` does ([`run`]).
struct Run<'a>(&'a Args, &'a Setup);

impl WithPaint for Run<'_> {
    type Out = Render;
    fn go<P: Paint>(self, paint: &P) -> Render {
        run(self.0, self.1, paint)
    }
}

/// The rules of `m` wavelengths fitted to the scene's lights (shared
/// wavelengths, each light its own weights), as a paint of the smallest
/// compiled width that holds them (4, 8, 12, 16, 24, 32 or 64 lanes; the
/// rest weigh nothing), in `--precision`, handed to `with`.
pub fn fitted<W: WithPaint>(a: &Args, setup: &Setup, m: usize, with: W) -> Result<W::Out, speclab::Error> {
    let lights: Vec<&dyn Spectrum> = setup.lights.iter().map(|l| l as &dyn Spectrum).collect();
    let rules = Rule::fit_each(&lights, m)?;
    let (l, p, t) = (&setup.lights, &setup.patches, &setup.texture);
    macro_rules! lanes {
        ($($cap:literal)*) => {
            $(if m <= $cap {
                return Ok(if a.single {
                    with.go(&Fitted::<$cap, f32>::new(&rules, l, p, t)?)
                } else {
                    with.go(&Fitted::<$cap, f64>::new(&rules, l, p, t)?)
                });
            })*
        };
    }
    lanes!(4 8 12 16 24 32 64);
    Err(speclab::Error::Count { what: "a fitted wavelength count", found: m, min: 1, max: 64 })
}

/// Renders with `paint` and grey alternately, three times each (the
/// fastest of each kept), reports the time per vertex and the colour's
/// overhead, and, if asked, compares with the exact image and a reference.
pub fn run<P: Paint>(a: &Args, setup: &Setup, paint: &P) -> Render {
    let (mut best, mut best_grey): (Option<Render>, Option<Render>) = (None, None);
    for _ in 0..3 {
        let s = render(&setup.scene, paint, a, (a.spp, a.threads), 1, None);
        let g = render(&setup.scene, &setup.grey, a, (a.spp, a.threads), 1, None);
        if best.as_ref().is_none_or(|b| s.seconds < b.seconds) {
            best = Some(s);
        }
        if best_grey.as_ref().is_none_or(|b| g.seconds < b.seconds) {
            best_grey = Some(g);
        }
    }
    let (image, grey) = (best.expect("three runs"), best_grey.expect("three runs"));
    output::report(a, &image, &grey);
    if a.exact {
        let start = Instant::now();
        let exact = setup.exact();
        let prepared = start.elapsed().as_secs_f64();
        let with_exact = render(&setup.scene, paint, a, (a.spp, a.threads), 1, Some(&exact));
        output::exact_report(a, setup, &with_exact, image.seconds, prepared);
    }
    output::reference_error(a, setup, paint, &image);
    image
}

/// The chosen density, as a histogram of `--bins` bins unless
/// `--exact-pdf` (uniform needs neither); following all the lights.
pub fn wavelength_pdf(a: &Args, setup: &Setup) -> Result<Box<dyn WavelengthPdf + Sync>, speclab::Error> {
    let mut scene = speclab::spectrum::Mixture::new();
    for l in &setup.lights {
        scene = scene.with(1.0, l)?;
    }
    let exact = a.sampling.pdf.for_light(&scene)?;
    Ok(match (a.bins, a.sampling.pdf) {
        (_, speclab::sampling::choice::PdfKind::Uniform) | (None, _) => Box::new(exact),
        (Some(bins), _) => Box::new(BinnedPdf::new(&exact, bins)?),
    })
}

fn fail(e: impl std::fmt::Display) -> ExitCode {
    eprintln!("render: {e}");
    ExitCode::from(2)
}
