//! Accuracy over many trials: bias, spread, perceptual error and gamut.
//!
//! [`run`] repeats an estimator T times, trial `t` seeded with
//! `derive_seed(base_seed, t)`, and compares every result with the exact
//! reference: bias (mean − reference, XYZ), standard deviation (XYZ), RMS
//! and 95th-percentile ΔE00 (CIELAB relative to the light's white), and how
//! often the gamut flag disagrees with the reference's. Deterministic methods
//! (regular buckets, the reference) run once, with zero spread. Trials run
//! on all cores (rayon); results do not depend on the number of threads.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::data::{Light, lights, patches};
//! use speclab_study::{evaluate::method::Method, evaluate::trials};
//! let n = NonZeroUsize::new(64).unwrap();
//! let t = NonZeroUsize::new(200).unwrap();
//! let hero = trials::method(&Light::D65.into(), &patches::F4, Method::HERO, n, t, 1)?;
//! let random = trials::method(&Light::D65.into(), &patches::F4, Method::RANDOM, n, t, 1)?;
//! assert!(hero.rms_de00 < random.rms_de00);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::{Method, derive_seed};
use crate::evaluate::perceptual;
use crate::evaluate::scene::Depth;
use crate::evaluate::scene::Named;
use rayon::prelude::*;
use speclab::color::Xyz;
use speclab::sampling::reference;
use speclab::spectrum::TabulatedSpectrum;

/// What a study measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    /// Trials run (1 for deterministic methods).
    pub trials: usize,
    /// Mean estimate minus reference.
    pub bias: Xyz,
    /// Standard deviation of the estimates (0 for one trial).
    pub sd: Xyz,
    /// Root mean square ΔE00 to the reference.
    pub rms_de00: f64,
    /// Standard error of the mean of ΔE00² (0 for one trial): the mean
    /// square is `rms_de00²` ± this.
    pub mean_square_se: f64,
    /// 95th percentile (nearest rank) of ΔE00.
    pub p95_de00: f64,
    /// If the reference is in gamut: the share of trials out of gamut.
    pub false_out_of_gamut: Option<f64>,
    /// If the reference is out of gamut: the share of trials in gamut.
    pub false_in_gamut: Option<f64>,
}

impl Stats {
    /// A 95 % confidence interval for the RMS ΔE00 (normal, on the mean of
    /// ΔE00²): `√(mean square ∓ 1.96·se)`, the lower end at least 0.
    #[must_use]
    pub fn rms_de00_interval(&self) -> (f64, f64) {
        let (square, margin) = (self.rms_de00 * self.rms_de00, 1.96 * self.mean_square_se);
        ((square - margin).max(0.0).sqrt(), (square + margin).sqrt())
    }
}

/// Studies `method` on `light × surface` with `samples` samples or buckets.
pub fn method(
    light: &Named,
    surface: &TabulatedSpectrum,
    method: Method,
    samples: NonZeroUsize,
    trials: NonZeroUsize,
    base_seed: u64,
) -> Result<Stats, StudyError> {
    method_at_depth(light, surface, Depth::ONE, method, samples, trials, base_seed)
}

/// [`method`] on paths of `depth` surfaces, light × surface^depth, against
/// that product's exact XYZ (Lab relative to the light's white).
pub fn method_at_depth(
    light: &Named,
    surface: &TabulatedSpectrum,
    depth: Depth,
    method: Method,
    samples: NonZeroUsize,
    trials: NonZeroUsize,
    base_seed: u64,
) -> Result<Stats, StudyError> {
    let trials = if method.is_random() { trials } else { NonZeroUsize::MIN };
    let reference = light.exact_at(depth, surface);
    let white = reference::white(&light.spectrum);
    let prepared = method.prepare(light)?.at_depth(depth);
    run(reference, white, trials, base_seed, |seed| prepared.xyz(surface, samples, seed))
}

/// Runs `estimate(seed)` for `trials` seeds derived from `base_seed` and
/// compares each result with `reference`, in Lab relative to `white`.
pub fn run<F>(
    reference: Xyz,
    white: Xyz,
    trials: NonZeroUsize,
    base_seed: u64,
    estimate: F,
) -> Result<Stats, StudyError>
where
    F: Fn(u64) -> Result<Xyz, StudyError> + Sync,
{
    let estimates = parallel_trials(trials.get(), base_seed, &estimate)?;
    Ok(summarise(&estimates, reference, white))
}

/// Estimates for trials `0..trials`, in trial order, on all cores (each
/// trial seeded by its number: the same estimates on any number of
/// threads).
fn parallel_trials<F>(trials: usize, base_seed: u64, estimate: &F) -> Result<Vec<Xyz>, StudyError>
where
    F: Fn(u64) -> Result<Xyz, StudyError> + Sync,
{
    (0..trials as u64).into_par_iter().map(|t| estimate(derive_seed(base_seed, t))).collect()
}

/// The statistics of `estimates` against `reference`.
fn summarise(estimates: &[Xyz], reference: Xyz, white: Xyz) -> Stats {
    let n = estimates.len() as f64;
    let mean = estimates.iter().copied().sum::<Xyz>() / n;
    let sd = if estimates.len() > 1 {
        let sq = |d: Xyz| Xyz::new(d.x * d.x, d.y * d.y, d.z * d.z);
        let var = estimates.iter().fold(Xyz::ZERO, |s, &e| s + sq(e - mean)) / (n - 1.0);
        Xyz::new(var.x.sqrt(), var.y.sqrt(), var.z.sqrt())
    } else {
        Xyz::ZERO
    };
    let mut de: Vec<f64> = estimates.iter().map(|&e| perceptual::delta_e00(e, reference, white)).collect();
    de.sort_by(f64::total_cmp);
    let mean_square = de.iter().map(|d| d * d).sum::<f64>() / n;
    let rms_de00 = mean_square.sqrt();
    let mean_square_se = if estimates.len() > 1 {
        (de.iter().map(|d| (d * d - mean_square).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt()
    } else {
        0.0
    };
    let p95_de00 = de[((0.95 * n).ceil() as usize).clamp(1, de.len()) - 1];
    let in_gamut = |x: Xyz| x.to_linear_srgb().in_gamut();
    let share = |want: bool| estimates.iter().filter(|&&e| in_gamut(e) == want).count() as f64 / n;
    let (false_out_of_gamut, false_in_gamut) =
        if in_gamut(reference) { (Some(share(false)), None) } else { (None, Some(share(true))) };
    Stats {
        trials: estimates.len(),
        bias: mean - reference,
        sd,
        rms_de00,
        mean_square_se,
        p95_de00,
        false_out_of_gamut,
        false_in_gamut,
    }
}
