//! Accuracy in sequence: every method at increasing sample counts, each
//! over many trials, and where each crosses an error threshold.
//!
//! Random and hero use n = 1, 2, 4, … [`CONVERGENCE_MAX_N`] (powers of
//! two), once for each pdf × strata asked for; regular buckets and fitted
//! rules every M from 1 to 64 ([`Method::counts`]); on paths of any depth. [`crossing`] reads, per light and method,
//! the worst RMS ΔE00 over the light's surfaces at each count, and reports
//! the first count below a threshold and the count from which it stays
//! below.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab_study::experiments::convergence::{self, CONVERGENCE_MAX_N};
//! use speclab_study::sampling::choice::Sampling;
//! use speclab_study::{evaluate::method::Method, evaluate::scene::{Choice, Depth}};
//! use speclab::Role;
//! let light = Choice::Name("D65".into()).resolve(Role::Light)?;
//! let patch = Choice::Name("A1".into()).resolve(Role::Reflectance)?;
//! let rows = convergence::sequence(&light, &patch, &[Sampling::DEFAULT], Depth::ONE, NonZeroUsize::new(20).unwrap(), 1)?;
//! let counts = |m: Method| m.counts(CONVERGENCE_MAX_N).len();
//! assert_eq!(rows.len(), 2 * counts(Method::RANDOM) + 2 * counts(Method::BOX) + counts(Method::FITTED));
//! let boxed = convergence::crossing(&rows, "D65", Method::BOX, 1.0);
//! assert!(boxed.first.is_some() && boxed.stable >= boxed.first);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::Method;
use crate::evaluate::scene::{Depth, Named};
use crate::evaluate::trials::{self, Stats};
use crate::experiments::threshold::{self, Crossing};
use crate::sampling::choice::Sampling;

/// The methods a sequence studies with `samplings`, in order: random and
/// hero with each sampling, then centre and box buckets and the fitted rule.
#[must_use]
pub fn methods(samplings: &[Sampling]) -> Vec<Method> {
    let random = [Method::RANDOM, Method::HERO];
    let mut out: Vec<Method> =
        random.iter().flat_map(|m| samplings.iter().map(|&s| m.with_sampling(s))).collect();
    out.extend([Method::CENTER, Method::BOX, Method::FITTED]);
    out
}

/// The largest n studied for random and hero: 2¹² = 4096.
pub const CONVERGENCE_MAX_N: usize = 1 << 12;

/// One count of one method on one light × surface.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvergenceRow {
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

/// Every method of [`methods`] at every count it studies
/// ([`Method::counts`] up to [`CONVERGENCE_MAX_N`]), on `light × surface`
/// (to the power `depth`), with `trials` trials per random row.
pub fn sequence(
    light: &Named,
    surface: &Named,
    samplings: &[Sampling],
    depth: Depth,
    trials: NonZeroUsize,
    seed: u64,
) -> Result<Vec<ConvergenceRow>, StudyError> {
    let mut rows = Vec::new();
    for method in methods(samplings) {
        for samples in method.counts(CONVERGENCE_MAX_N) {
            let n = NonZeroUsize::new(samples).unwrap_or(NonZeroUsize::MIN);
            let s = &surface.spectrum;
            let stats = trials::method_at_depth(light, s, depth, method, n, trials, seed)?;
            let (light, surface) = (light.name.clone(), surface.name.clone());
            rows.push(ConvergenceRow { light, surface, method, samples, stats });
        }
    }
    Ok(rows)
}

/// Per count of `method` under `light`, the worst RMS ΔE00 over the light's
/// surfaces in `rows`; counts missing any surface are left out.
#[must_use]
pub fn worst_over_surfaces(rows: &[ConvergenceRow], light: &str, method: Method) -> Vec<(usize, f64)> {
    let mut surfaces: Vec<&str> =
        rows.iter().filter(|r| r.light == light).map(|r| r.surface.as_str()).collect();
    surfaces.sort_unstable();
    surfaces.dedup();
    method
        .counts(CONVERGENCE_MAX_N)
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
pub fn crossing(rows: &[ConvergenceRow], light: &str, method: Method, threshold: f64) -> Crossing {
    threshold::crossing(&worst_over_surfaces(rows, light, method), threshold)
}
