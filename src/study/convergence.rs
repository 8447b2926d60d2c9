//! Accuracy in sequence: every method at increasing sample counts, each
//! over many trials, and where each crosses an error threshold.
//!
//! Random and hero use n = 1, 2, 4, … 4096 (powers of two), once for each
//! pdf × strata asked for; regular buckets every M from 1 to 64. [`crossing`] reads, per light and method, the
//! worst RMS ΔE00 over the light's surfaces at each count, and reports the
//! first count below a threshold and the count from which it stays below.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::study::convergence::{self, counts};
//! use speclab::study::{method::Method, sampling::Sampling, scene::Choice};
//! use speclab::Role;
//! let light = Choice::Name("D65".into()).resolve(Role::Light)?;
//! let patch = Choice::Name("A1".into()).resolve(Role::Reflectance)?;
//! let rows = convergence::sequence(&light, &patch, &[Sampling::DEFAULT], NonZeroUsize::new(20).unwrap(), 1)?;
//! assert_eq!(rows.len(), 2 * counts(Method::RANDOM).len() + 2 * counts(Method::RegularBox).len());
//! let boxed = convergence::crossing(&rows, "D65", Method::RegularBox, 1.0);
//! assert!(boxed.first.is_some() && boxed.stable >= boxed.first);
//! # Ok::<(), speclab::Error>(())
//! ```

use std::num::NonZeroUsize;

use crate::Error;
use crate::sampling::regular::MAX_BUCKETS;
use crate::study::method::Method;
use crate::study::sampling::Sampling;
use crate::study::scene::Named;
use crate::study::threshold::{self, Crossing};
use crate::study::trials::{self, Stats};

/// The methods a sequence studies with `samplings`, in order: random and
/// hero with each sampling, then centre and box buckets.
#[must_use]
pub fn methods(samplings: &[Sampling]) -> Vec<Method> {
    let random = [Method::RANDOM, Method::HERO];
    let mut out: Vec<Method> =
        random.iter().flat_map(|m| samplings.iter().map(|&s| m.with_sampling(s))).collect();
    out.extend([Method::RegularCentre, Method::RegularBox]);
    out
}

/// The largest n studied for random and hero: 2¹² = 4096.
pub const MAX_N: usize = 1 << 12;

/// The sample counts studied for `method`: powers of two up to [`MAX_N`]
/// for random and hero, every M up to [`MAX_BUCKETS`] for buckets, none for
/// the reference.
#[must_use]
pub fn counts(method: Method) -> Vec<usize> {
    match method {
        Method::Random { .. } | Method::Hero { .. } => {
            std::iter::successors(Some(1), |n| Some(n * 2)).take_while(|&n| n <= MAX_N).collect()
        }
        Method::RegularCentre | Method::RegularBox => (1..=MAX_BUCKETS).collect(),
        Method::Reference => Vec::new(),
    }
}

/// One count of one method on one light × surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The light's name.
    pub light: String,
    /// The surface's name.
    pub surface: String,
    /// The method.
    pub method: Method,
    /// n or M.
    pub samples: usize,
    /// What `trials` measured (one trial for buckets).
    pub stats: Stats,
}

/// Every method of [`methods`] at every count of [`counts`], on
/// `light × surface`, with `trials` trials per random row.
pub fn sequence(
    light: &Named,
    surface: &Named,
    samplings: &[Sampling],
    trials: NonZeroUsize,
    seed: u64,
) -> Result<Vec<Row>, Error> {
    let mut rows = Vec::new();
    for method in methods(samplings) {
        for samples in counts(method) {
            let n = NonZeroUsize::new(samples).unwrap_or(NonZeroUsize::MIN);
            let stats = trials::method(&light.spectrum, &surface.spectrum, method, n, trials, seed)?;
            let (light, surface) = (light.name.clone(), surface.name.clone());
            rows.push(Row { light, surface, method, samples, stats });
        }
    }
    Ok(rows)
}

/// Per count of `method` under `light`, the worst RMS ΔE00 over the light's
/// surfaces in `rows`; counts missing any surface are left out.
#[must_use]
pub fn worst_over_surfaces(rows: &[Row], light: &str, method: Method) -> Vec<(usize, f64)> {
    let mut surfaces: Vec<&str> =
        rows.iter().filter(|r| r.light == light).map(|r| r.surface.as_str()).collect();
    surfaces.sort_unstable();
    surfaces.dedup();
    counts(method)
        .into_iter()
        .filter_map(|n| {
            let cell: Vec<f64> = rows
                .iter()
                .filter(|r| r.light == light && r.method == method && r.samples == n)
                .map(|r| r.stats.rms_de00)
                .collect();
            (cell.len() == surfaces.len() && !cell.is_empty())
                .then(|| (n, cell.iter().copied().fold(0.0, f64::max)))
        })
        .collect()
}

/// Where `method` under `light` gets below `threshold` RMS ΔE00 for all of
/// the light's surfaces at once: first, and for good.
#[must_use]
pub fn crossing(rows: &[Row], light: &str, method: Method, threshold: f64) -> Crossing {
    threshold::crossing(&worst_over_surfaces(rows, light, method), threshold)
}
