//! A small path tracer over the core's renderer API, and what it measures:
//! a box of ColorChecker walls and spheres with an RGB-textured back wall,
//! lit by one or two lights in the ceiling, colour carried four ways
//! ([`crate::carry`]: hero wavelengths, a fitted rule, RGB
//! triples; and [`ways::Prefilter`], spectrally prefiltered triples), each
//! against the exact image of its own paths.
//!
//! - [`tracer`]: the scene's geometry and the one tracer, generic over the
//!   way colour is carried;
//! - [`exact`]: each recorded path integrated exactly over wavelength;
//! - [`ways`]: the scene's albedos as one list, and grey (the timing
//!   baseline);
//! - [`run`]: the way [`Options`] asks for, timed against grey, and
//!   compared with the exact image or a reference render;
//! - [`survey`]: every way on the standard scenes, as rows.
//!
//! Pixels are independent: each is seeded by its place, so an image does
//! not depend on the number of threads (rayon), only its time does.
//!
//! ```
//! use speclab_study::evaluate::Named;
//! use speclab_study::render::{self, Options, Setup, Way};
//! let setup = Setup::new(&[Named::from(speclab::data::Light::F11)])?;
//! let options = Options { width: 8, height: 8, spp: 2, way: Way::Fitted, ..Options::default() };
//! let (image, de00) = render::run::against_exact(&options, &setup)?;
//! assert_eq!(image.xyz.len(), 64);
//! assert!(de00[0] < 1.0, "mean ΔE00 {}", de00[0]); // a rule of 10 under F11
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

pub mod exact;
pub mod film;
pub mod run;
pub mod survey;
pub mod tracer;
pub mod ways;

use std::time::Instant;

use crate::carry::Carry;
use crate::sampling::choice::Sampling;
use crate::sampling::seed::mix;
use crate::sampling::strata::Strata;
use rayon::prelude::*;
use speclab::color::RgbAlbedo;
use speclab::color::RgbSpace;
use speclab::data::Patch;
use speclab::named_choices;
use speclab::sampling::reference;
use speclab::{LinearRgb, TabulatedSpectrum, Xyz};

use crate::evaluate::Named;
use exact::{ExactScene, PathRecord};
use tracer::{Material, Rng, Scene};
use ways::Grey;

/// How colour is carried along the paths.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Way {
    /// Hero wavelengths (K = 4) from [`Options::sampling`].
    #[default]
    Hero,
    /// A rule of [`Options::m`] wavelengths fitted to the scene's lights.
    Fitted,
    /// Linear sRGB triples.
    Rgb,
    /// Spectral prefiltering in sharpened RGB ([`ways::Prefilter`]).
    Prefilter,
}

named_choices!(Way, "a way to carry colour": Hero => "hero", Fitted => "fitted", Rgb => "rgb", Prefilter => "prefilter");

/// What to render, and how.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Image width, pixels.
    pub width: usize,
    /// Image height, pixels.
    pub height: usize,
    /// Paths per pixel.
    pub spp: usize,
    /// How colour is carried.
    pub way: Way,
    /// The fitted rule's wavelengths.
    pub m: usize,
    /// How hero wavelengths are drawn, and how a pixel's primary numbers
    /// are spread.
    pub sampling: Sampling,
    /// Hero over dense 1 nm tables instead of the exact tabulated spectra.
    pub dense: bool,
    /// With `dense`: every surface (the patches and the texels) an RGB
    /// colour in this built-in space (by name), looked up in the space's
    /// table at each hit, as a renderer's textures are.
    pub rgb_space: Option<&'static str>,
    /// With `rgb_space`: each surface's colour converted to its albedo
    /// once, when the scene is built (Mitsuba 3's `bitmap` textures),
    /// instead of at each hit (pbrt-v4's image textures).
    pub rgb_converted: bool,
    /// Per-sample values in `f32` instead of `f64`.
    pub single: bool,
    /// Bins of the histogram pdf, or `None` for the exact density.
    pub bins: Option<usize>,
    /// Worker threads.
    pub threads: usize,
}

impl Default for Options {
    /// 256 × 256, 32 paths per pixel, hero (uniform, jittered) over exact
    /// spectra in f64, M = 10, 256 bins, two threads.
    fn default() -> Self {
        Options {
            width: 256,
            height: 256,
            spp: 32,
            way: Way::Hero,
            m: 10,
            sampling: Sampling { strata: Strata::Jittered, ..Sampling::DEFAULT },
            dense: false,
            rgb_space: None,
            rgb_converted: false,
            single: false,
            bins: Some(256),
            threads: 2,
        }
    }
}

/// The scene's geometry and spectra, and what every way of carrying
/// colour needs.
#[derive(Clone, Debug)]
pub struct Setup {
    /// The geometry.
    pub scene: Scene,
    /// The lights, named.
    pub lights: Vec<Named>,
    /// The six patches.
    pub patches: Vec<TabulatedSpectrum>,
    /// The texels' colours.
    pub colours: Vec<LinearRgb>,
    /// The texels as spectra.
    pub texture: Vec<RgbAlbedo>,
    /// The grey baseline.
    pub grey: Grey,
    /// The lights' whites, summed.
    pub white: Xyz,
}

impl Setup {
    /// The box lit by `lights` (one or two: a ceiling square each).
    pub fn new(lights: &[Named]) -> Result<Self, speclab::Error> {
        let colours = texture_colours();
        let texture = colours.iter().map(|&c| RgbAlbedo::new(c)).collect::<Result<Vec<_>, _>>()?;
        let patches: Vec<TabulatedSpectrum> = Patch::ALL.iter().map(|p| p.spectrum().clone()).collect();
        let white: Xyz = lights.iter().map(|l| reference::white(&l.spectrum)).sum();
        let space = RgbSpace::srgb();
        let under_all = |s: &TabulatedSpectrum| {
            lights.iter().map(|l| reference::xyz(&l.spectrum, s).y).sum::<f64>() / white.y
        };
        let mut surfaces: Vec<f64> = patches.iter().map(under_all).collect();
        surfaces.extend(colours.iter().map(|&c| space.xyz(c).y / space.white().y));
        let grey = Grey { surfaces, white };
        Ok(Setup {
            scene: scene(lights.len()),
            lights: lights.to_vec(),
            patches,
            colours,
            texture,
            grey,
            white,
        })
    }

    /// The lights' spectra.
    #[must_use]
    pub fn light_spectra(&self) -> Vec<TabulatedSpectrum> {
        self.lights.iter().map(|l| l.spectrum.clone()).collect()
    }

    /// The lights' names, joined: `F11 + A`.
    #[must_use]
    pub fn light_names(&self) -> String {
        self.lights.iter().map(|l| l.name.as_str()).collect::<Vec<_>>().join(" + ")
    }

    /// The exact image's spectra.
    #[must_use]
    pub fn exact(&self) -> ExactScene {
        ExactScene::new(&self.light_spectra(), &self.patches, &self.texture)
    }
}

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
fn texture_colours() -> Vec<LinearRgb> {
    let hue = |h: f64| [0.0, 2.0, 4.0].map(|o: f64| ((h * 6.0 + o) % 6.0 - 3.0).abs().clamp(1.0, 2.0) - 1.0);
    (0..tracer::TEXELS)
        .map(|t| {
            let (column, row) = (t / 8, t % 8);
            let lightness = 0.15 + 0.8 * (7 - row) as f64 / 7.0;
            LinearRgb::from(hue(column as f64 / 8.0).map(|c| lightness * (0.25 + 0.75 * c)))
        })
        .collect()
}

/// A pixel's seed: SplitMix64's finaliser of the pass and the pixel.
pub(crate) fn seed(pass: u64, pixel: usize) -> u64 {
    mix(pass.wrapping_mul(crate::sampling::seed::GOLDEN) ^ (pixel as u64).wrapping_add(0xD1B5_4A32_D192_ED03))
        | 1
}

/// An image of mean XYZ per pixel (and, if asked, the exact image of the
/// same paths), the vertices its paths met, and how long it took.
#[derive(Clone, Debug)]
pub struct Render {
    /// Mean XYZ per pixel, rows top to bottom.
    pub xyz: Vec<Xyz>,
    /// The exact image of the same paths, if asked.
    pub exact: Option<Vec<Xyz>>,
    /// Surfaces met by all paths.
    pub vertices: u64,
    /// Wall-clock time, s.
    pub seconds: f64,
}

/// Renders `spp` paths per pixel on `threads` threads, the primary numbers
/// seeded by `pass`; with `exact`, each path's exact colour too (not timed
/// apart: time the render without it).
pub fn render<C: Carry + Sync>(
    setup: &Setup,
    carry: &C,
    o: &Options,
    (spp, threads): (usize, usize),
    pass: u64,
    exact: Option<&ExactScene>,
) -> Render {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads.max(1)).build();
    let work = || render_rows(setup, carry, o, spp, pass, exact);
    let start = Instant::now();
    let (pixels, vertices) = match &pool {
        Ok(pool) => pool.install(work),
        Err(_) => work(),
    };
    let seconds = start.elapsed().as_secs_f64();
    let (xyz, truth): (Vec<Xyz>, Vec<Xyz>) = pixels.into_iter().unzip();
    Render { xyz, exact: exact.map(|_| truth), vertices, seconds }
}

/// Every pixel's (estimate, exact) and the vertices met, rows in parallel.
fn render_rows<C: Carry + Sync>(
    setup: &Setup,
    carry: &C,
    o: &Options,
    spp: usize,
    pass: u64,
    exact: Option<&ExactScene>,
) -> (Vec<(Xyz, Xyz)>, u64) {
    let mut pixels = vec![(Xyz::ZERO, Xyz::ZERO); o.width * o.height];
    let vertices = pixels
        .par_chunks_mut(o.width.max(1))
        .enumerate()
        .map(|(y, row)| {
            let mut count = 0;
            for (x, pixel) in row.iter_mut().enumerate() {
                let (value, n) =
                    trace_pixel(setup, carry, o, spp, (x, y), seed(pass, y * o.width + x), exact);
                *pixel = value;
                count += n;
            }
            count
        })
        .sum();
    (pixels, vertices)
}

/// One pixel's `spp` paths: its mean estimate and exact colour, and the
/// vertices met.
fn trace_pixel<C: Carry>(
    setup: &Setup,
    carry: &C,
    o: &Options,
    spp: usize,
    (x, y): (usize, usize),
    seed: u64,
    exact: Option<&ExactScene>,
) -> ((Xyz, Xyz), u64) {
    let mut rng = Rng(seed);
    let shift = rng.uniform();
    let (mut sum, mut truth, mut count) = (Xyz::ZERO, Xyz::ZERO, 0);
    for i in 0..spp {
        let u = if o.sampling.strata == Strata::Kronecker { shift } else { rng.uniform() };
        let path = carry.path(o.sampling.strata.point(i, spp, 4, u));
        let at = ((x as f64 + rng.uniform()) / o.width as f64, (y as f64 + rng.uniform()) / o.height as f64);
        let (value, n) = match exact {
            None => tracer::trace(&setup.scene, carry, &path, at, &mut rng, &mut ()),
            Some(e) => {
                let mut record = PathRecord::new();
                let traced = tracer::trace(&setup.scene, carry, &path, at, &mut rng, &mut record);
                truth += e.xyz(&record);
                traced
            }
        };
        sum += value;
        count += u64::from(n);
    }
    ((sum / spp as f64, truth / spp as f64), count)
}
