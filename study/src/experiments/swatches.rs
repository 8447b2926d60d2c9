//! Swatches: every light × patch shown by every method, one swatch each,
//! so that error becomes something to look at.
//!
//! A swatch is a square of `size × size` pixels. In a Monte Carlo swatch
//! (random, hero) **every pixel is its own independent estimate** with n
//! samples, seeded by [`derive_seed`] from the base seed and the pixel's
//! place, so the swatch shows the estimator's noise as grain, and the image
//! does not depend on the number of threads. A deterministic swatch
//! (reference, regular buckets, fitted rules) is flat: its error is bias, a uniform shift.
//!
//! The columns ([`columns`]): the exact reference; random (n); hero (n,
//! K = 4); regular-center (M); regular-box (M); fitted (M wavelengths
//! fitted to the light); then hero with jittered
//! strata (uniform pdf), and hero with jittered strata and the light's pdf.
//! Of the 4 pdfs × 3 strata those two show the two levers a renderer has,
//! one at a time: stratification alone, then importance sampling of the
//! light on top (which matters on F11's spikes). The other ten combinations
//! are in `converge` and `compare`.
//!
//! Pixels go through [`crate::display`]: exposed so that the light's
//! perfect white just fits the display in its own colour
//! ([`Exposure::fit_white`], after white balance if asked), then the chosen
//! gamut map and sRGB.
//! `speclab_cli::sheet` lays the swatches out with labels.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab_study::{evaluate::scene, experiments::swatches::{self, SwatchOptions}};
//! let (lights, patches) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let settings = SwatchOptions { size: 4, ..SwatchOptions::default() };
//! let sheet = swatches::render(&lights[1..2], &patches[..2], &settings)?;
//! assert_eq!(sheet.columns.len(), 8);
//! let reference = sheet.swatch(0, 1, 0); // D65 × F4, exact: flat
//! assert!(reference.iter().all(|&p| p == reference[0]));
//! let random = sheet.swatch(0, 1, 1); // every pixel its own estimate
//! assert!(random.iter().any(|&p| p != random[0]));
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use rand::SeedableRng;
use rand::rngs::StdRng;
use rayon::prelude::*;

use crate::StudyError;
use crate::display::{Exposure, GamutMap, PixelPipeline, Srgb8};
use crate::evaluate::method::{Estimator, Method, derive_seed};
use crate::evaluate::scene::Named;
use crate::evaluate::viewing;
use crate::sampling::choice::{PdfKind, Sampling};
use crate::sampling::strata::Strata;
use speclab::color::Xyz;
use speclab::color::adaptation::Cat;
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::reference;
use speclab::spectrum::TabulatedSpectrum;

/// The largest swatch side [`render`] draws.
pub const MAX_SIZE: usize = 1024;

/// What the swatches show, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SwatchOptions {
    /// Samples per estimate for the random and hero columns.
    pub n: NonZeroUsize,
    /// Buckets for the regular columns (1 to 64).
    pub m: NonZeroUsize,
    /// Base seed.
    pub seed: u64,
    /// Bradford-adapt each light's white to D65's before display.
    pub white_balance: bool,
    /// How out-of-gamut colours are shown.
    pub gamut: GamutMap,
    /// Pixels per side of a swatch (estimates per Monte Carlo swatch: its
    /// square), at most [`MAX_SIZE`]: larger values render at that size.
    pub size: usize,
}

impl Default for SwatchOptions {
    /// n = 16 (a renderer's count, where the methods differ at a glance),
    /// M = 16, seed 1, no white balance, chroma gamut map, 64 × 64.
    fn default() -> Self {
        let nz = |n| NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
        SwatchOptions {
            n: nz(16),
            m: nz(16),
            seed: 1,
            white_balance: false,
            gamut: GamutMap::Chroma,
            size: 64,
        }
    }
}

/// One column of swatches: a method and its count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Column {
    /// The method.
    pub method: Method,
    /// Its samples (random, hero) or buckets (regular).
    pub samples: NonZeroUsize,
}

impl Column {
    /// Three short lines naming the column: the method, how it samples,
    /// and its count, e.g. `["HERO K=4", "LIGHT+JITTER", "N=16"]`.
    #[must_use]
    pub fn label(&self) -> [String; 3] {
        let (n, m) = (format!("N={}", self.samples), format!("M={}", self.samples));
        match self.method {
            Method::Reference => ["REFERENCE".into(), "EXACT".into(), String::new()],
            Method::Hero { k: 1, sampling } => ["RANDOM".into(), how(sampling), n],
            Method::Hero { k, sampling } => [format!("HERO K={k}"), how(sampling), n],
            Method::Buckets { rule: BucketRule::Center } => ["CENTER".into(), "BUCKETS".into(), m],
            Method::Buckets { rule: BucketRule::BoxAverage } => ["BOX".into(), "BUCKETS".into(), m],
            Method::Fitted => ["FITTED".into(), "RULE".into(), m],
            Method::Published { family } => [family.to_string().to_uppercase(), "RULE".into(), m],
            Method::Prefiltered { space } => {
                ["PREFILTER".into(), space.to_string().to_uppercase(), String::new()]
            }
        }
    }
}

/// A sampling in a few capitals: `UNIFORM` (independent), `JITTER`
/// (uniform, jittered), `LIGHT+JITTER`, `VISIBLE`, …
fn how(sampling: Sampling) -> String {
    let pdf = sampling.pdf.to_string().to_uppercase();
    match (sampling.pdf, sampling.strata) {
        (_, Strata::None) => pdf,
        (PdfKind::Uniform, strata) => strata.to_string().to_uppercase(),
        (_, strata) => format!("{pdf}+{}", strata.to_string().to_uppercase()),
    }
}

/// The columns for `s`, in order (see the module overview).
#[must_use]
pub fn columns(s: &SwatchOptions) -> Vec<Column> {
    let jitter = |pdf| Method::HERO.with_sampling(Sampling { pdf, strata: Strata::Jittered });
    let column = |method, samples| Column { method, samples };
    vec![
        column(Method::Reference, s.n),
        column(Method::RANDOM, s.n),
        column(Method::HERO, s.n),
        column(Method::CENTER, s.m),
        column(Method::BOX, s.m),
        column(Method::FITTED, s.m),
        column(jitter(PdfKind::Uniform), s.n),
        column(jitter(PdfKind::Light), s.n),
    ]
}

/// The rendered swatches of every light × patch × column.
#[derive(Clone, Debug, PartialEq)]
pub struct Swatches {
    /// Light names, in order.
    pub lights: Vec<String>,
    /// Patch names, in order.
    pub patches: Vec<String>,
    /// The columns, in order.
    pub columns: Vec<Column>,
    /// What they were rendered with.
    pub settings: SwatchOptions,
    /// `size²` pixels per swatch, row-major, swatches light-major, then
    /// patch, then column.
    pixels: Vec<Srgb8>,
}

impl Swatches {
    /// The pixels of one swatch (`size²`, row-major); empty if an index is
    /// out of range.
    #[must_use]
    pub fn swatch(&self, light: usize, patch: usize, column: usize) -> &[Srgb8] {
        let (patches, columns) = (self.patches.len(), self.columns.len());
        if light >= self.lights.len() || patch >= patches || column >= columns {
            return &[];
        }
        let area = self.settings.size * self.settings.size;
        let start = ((light * patches + patch) * columns + column) * area;
        &self.pixels[start..start + area]
    }
}

/// How an XYZ under one light becomes a pixel: white balance (the light's
/// white and the D65 white it is adapted to), then the display.
#[derive(Clone, Copy, Debug)]
struct Look {
    balance: Option<(Xyz, Xyz)>,
    display: PixelPipeline,
}

impl Look {
    fn new(light: &TabulatedSpectrum, s: &SwatchOptions) -> Look {
        let white = reference::white(light);
        let balance = s.white_balance.then(|| (white, viewing::target_white(light)));
        let white = balance.map_or(white, |(_, target)| target);
        Look { balance, display: PixelPipeline::new(Exposure::fit_white(white), s.gamut) }
    }

    fn pixel(&self, xyz: Xyz) -> Srgb8 {
        let xyz = self.balance.map_or(xyz, |(from, to)| Cat::Bradford.adapt(xyz, from, to));
        self.display.pixel(xyz.to_linear_srgb())
    }
}

/// What one swatch needs: a flat pixel, or an estimator and its look.
enum Job<'a> {
    Flat(Srgb8),
    Noisy { prepared: Box<Estimator<'a>>, surface: &'a TabulatedSpectrum, samples: NonZeroUsize, look: Look },
}

/// Renders every light × surface × column of [`columns`], on all cores.
/// Errors if a count is not compiled (M outside 1 to 64) or a light pdf
/// cannot follow a light (one the observer cannot see).
pub fn render(lights: &[Named], surfaces: &[Named], s: &SwatchOptions) -> Result<Swatches, StudyError> {
    let s = &SwatchOptions { size: s.size.min(MAX_SIZE), ..*s };
    let columns = columns(s);
    let mut jobs = Vec::with_capacity(lights.len() * surfaces.len() * columns.len());
    for light in lights {
        let look = Look::new(&light.spectrum, s);
        let prepared: Vec<Estimator> =
            columns.iter().map(|c| c.method.prepare(light)).collect::<Result<_, _>>()?;
        for surface in surfaces.iter().map(|n| &n.spectrum) {
            for (column, prepared) in columns.iter().zip(&prepared) {
                let samples = column.samples;
                jobs.push(if column.method.is_random() {
                    Job::Noisy { prepared: Box::new(prepared.clone()), surface, samples, look }
                } else {
                    Job::Flat(look.pixel(prepared.xyz(surface, samples, s.seed)?))
                });
            }
        }
    }
    let pixels = run_jobs(&jobs, s)?;
    let names = |v: &[Named]| v.iter().map(|n| n.name.clone()).collect();
    Ok(Swatches { lights: names(lights), patches: names(surfaces), columns, settings: *s, pixels })
}

/// The pixels of every job, the swatches on all cores (each pixel seeded
/// by its place: the same sheet on any number of threads).
fn run_jobs(jobs: &[Job], s: &SwatchOptions) -> Result<Vec<Srgb8>, StudyError> {
    let area = s.size * s.size;
    let mut pixels = vec![Srgb8::default(); jobs.len() * area];
    if area == 0 {
        return Ok(pixels);
    }
    pixels
        .par_chunks_mut(area)
        .enumerate()
        .try_for_each(|(index, swatch)| fill(&jobs[index], index, swatch, s.seed))?;
    Ok(pixels)
}

/// Fills swatch `index`: every pixel of a noisy one its own estimate, seeded
/// from the base seed and the pixel's number in the whole sheet.
fn fill(job: &Job, index: usize, swatch: &mut [Srgb8], seed: u64) -> Result<(), StudyError> {
    match job {
        Job::Flat(pixel) => swatch.fill(*pixel),
        Job::Noisy { prepared, surface, samples, look } => {
            let first = (index * swatch.len()) as u64;
            for (i, pixel) in swatch.iter_mut().enumerate() {
                let mut rng = StdRng::seed_from_u64(derive_seed(seed, first + i as u64));
                *pixel = look.pixel(prepared.xyz_with_rng(surface, *samples, &mut rng)?);
            }
        }
    }
    Ok(())
}
