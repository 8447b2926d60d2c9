//! Fixed wavelength rules side by side: for each M, the worst ΔE00 over a
//! set of surfaces of the rule fitted to the light, centre buckets, box
//! buckets and the published rules of M wavelengths for the light
//! (`published::rules`: ASTM E308, Borges, Meyer, Wallis; all
//! deterministic), with the *stable* error of each (the
//! largest at M or any larger M up to 64); and, per light and path depth,
//! the smallest M each needs to stay within a budget beside the smallest n
//! hero needs.
//!
//! ```
//! use speclab_study::{experiments::rules, evaluate::scene::{self, Depth}};
//! let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let f11 = rules::by_m(&lights[2], &surfaces, Depth::ONE)?;
//! assert_eq!(f11.len(), 64);
//! let ten = &f11[9];
//! assert!(ten.fitted < 1.0 && ten.center > 10.0); // F11's lines
//! assert!(rules::stable(&f11, |r| r.fitted, 10) >= ten.fitted);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::Method;
use crate::evaluate::perceptual;
use crate::evaluate::scene::{Depth, Named};
use crate::evaluate::trials;
use crate::experiments::convergence::CONVERGENCE_MAX_N;
use crate::published::rules::Family;
use crate::sampling::choice::{PdfKind, Sampling};
use crate::sampling::strata::Strata;
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::fitted::FittedRules;
use speclab::sampling::reference;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::spectrum::Spectrum;

/// The worst ΔE00 over the surfaces of each fixed rule at one M.
#[derive(Clone, Debug, PartialEq)]
pub struct RuleRow {
    /// The light's name.
    pub light: String,
    /// Wavelengths or buckets.
    pub m: usize,
    /// The rule of M wavelengths fitted to the light.
    pub fitted: f64,
    /// M centre buckets.
    pub center: f64,
    /// M box buckets.
    pub boxed: f64,
    /// Each published rule of M wavelengths, in [`Family::ALL`]'s order
    /// (`None` where the family has no rule of M for the light).
    pub published: [Option<f64>; 4],
}

/// Every M from 1 to 64 under `light`, over `surfaces` to the power
/// `depth` (an error for no surfaces).
pub fn by_m(light: &Named, surfaces: &[Named], depth: Depth) -> Result<Vec<RuleRow>, StudyError> {
    rows_by_m(light, surfaces, depth, true)
}

/// [`by_m`], with the published rules' columns or without them (`None`).
fn rows_by_m(
    light: &Named,
    surfaces: &[Named],
    depth: Depth,
    published: bool,
) -> Result<Vec<RuleRow>, StudyError> {
    if surfaces.is_empty() {
        return Err(StudyError::EmptyScene);
    }
    let l = &light.spectrum;
    let white = reference::white(l);
    let exact: Vec<_> = surfaces.iter().map(|s| light.exact_at(depth, &s.spectrum)).collect();
    let fits = FittedRules::of(l)?;
    (1..=MAX_M)
        .map(|m| {
            let (mut fitted, mut center, mut boxed) = (0.0f64, 0.0f64, 0.0f64);
            let rule = fits.rule(m)?;
            let buckets = [Rule::buckets(m, BucketRule::Center)?, Rule::buckets(m, BucketRule::BoxAverage)?];
            let published = if published { published_rules(light, m)? } else { [None, None, None, None] };
            let mut published_worst = published.each_ref().map(|r| r.as_ref().map(|_| 0.0f64));
            for (s, &exact) in surfaces.iter().zip(&exact) {
                let path = depth.path(&s.spectrum);
                let mut factors: Vec<&dyn Spectrum> = vec![l];
                factors.extend_from_slice(path.factors());
                let de = |xyz| perceptual::delta_e00(xyz, exact, white);
                fitted = fitted.max(de(rule.xyz_of_product(&factors)));
                for (b, worst) in buckets.iter().zip([&mut center, &mut boxed]) {
                    *worst = worst.max(de(b.xyz_of_product(&factors)));
                }
                // A published rule's weights hold the light: the path alone.
                for (r, worst) in published.iter().zip(&mut published_worst) {
                    if let (Some(r), Some(worst)) = (r, worst) {
                        *worst = worst.max(de(r.xyz_of_product(&factors[1..])));
                    }
                }
            }
            Ok(RuleRow { light: light.name.clone(), m, fitted, center, boxed, published: published_worst })
        })
        .collect()
}

/// Each family's rule of `m` wavelengths for `light`, `None` where there
/// is none (fewer wavelengths than the family takes, or no rule of `m` for
/// the light).
fn published_rules(light: &Named, m: usize) -> Result<[Option<Rule>; 4], StudyError> {
    let rule = |family: Family| -> Result<Option<Rule>, StudyError> {
        if m < family.min_m() {
            return Ok(None);
        }
        match light.published(family, m) {
            Ok(r) => Ok(Some(r)),
            Err(StudyError::NoRule { .. }) => Ok(None),
            Err(e) => Err(e),
        }
    };
    let mut rules = [None, None, None, None];
    for (r, family) in rules.iter_mut().zip(Family::ALL) {
        *r = rule(family)?;
    }
    Ok(rules)
}

/// The stable error at `m` of the rule `pick` reads: the largest over
/// every row with M at least `m` (0 if there is none).
#[must_use]
pub fn stable(rows: &[RuleRow], pick: impl Fn(&RuleRow) -> f64, m: usize) -> f64 {
    rows.iter().filter(|r| r.m >= m).map(pick).fold(0.0, f64::max)
}

/// The smallest M from which every larger M studied stays strictly below
/// `budget` under the rule `pick` reads.
#[must_use]
pub fn smallest_stable(rows: &[RuleRow], pick: impl Fn(&RuleRow) -> f64, budget: f64) -> Option<usize> {
    let points: Vec<(usize, f64)> = rows.iter().map(|r| (r.m, pick(r))).collect();
    crate::experiments::threshold::crossing(&points, budget).stable
}

/// What one light at one depth needs to stay within a budget.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthRow {
    /// The light's name.
    pub light: String,
    /// Surfaces per path.
    pub depth: Depth,
    /// Smallest stable M of centre buckets, box buckets and the fitted
    /// rule (`None`: not within 64).
    pub center: Option<usize>,
    /// See `center`.
    pub boxed: Option<usize>,
    /// See `center`.
    pub fitted: Option<usize>,
    /// Smallest n (a power of two up to 4096) at which hero, uniform
    /// jittered wavelengths, has its RMS ΔE00 below the budget for every
    /// surface, over `trials` trials.
    pub hero: Option<usize>,
}

/// For every light and depth 1 to 4, the smallest counts within `budget`
/// over `surfaces` (see [`DepthRow`]).
pub fn depth_table(
    lights: &[Named],
    surfaces: &[Named],
    budget: f64,
    trials: NonZeroUsize,
    seed: u64,
) -> Result<Vec<DepthRow>, StudyError> {
    let mut out = Vec::new();
    for light in lights {
        for depth in Depth::ALL {
            out.push(needs(light, surfaces, depth, budget, trials, seed)?);
        }
    }
    Ok(out)
}

/// What `light` needs at `depth` to keep every one of `surfaces` within
/// `budget`: the smallest stable M of each fixed rule, and the smallest n
/// of hero with uniform jittered wavelengths (see [`DepthRow`]).
pub fn needs(
    light: &Named,
    surfaces: &[Named],
    depth: Depth,
    budget: f64,
    trials: NonZeroUsize,
    seed: u64,
) -> Result<DepthRow, StudyError> {
    let hero = Method::HERO.with_sampling(Sampling { pdf: PdfKind::Uniform, strata: Strata::Jittered });
    let rows = rows_by_m(light, surfaces, depth, false)?;
    let mut hero_n = None;
    'counts: for n in hero.counts(CONVERGENCE_MAX_N) {
        let count = NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
        for s in surfaces {
            let stats = trials::method_at_depth(light, &s.spectrum, depth, hero, count, trials, seed)?;
            if stats.rms_de00 >= budget {
                continue 'counts;
            }
        }
        hero_n = Some(n);
        break;
    }
    Ok(DepthRow {
        light: light.name.clone(),
        depth,
        center: smallest_stable(&rows, |r| r.center, budget),
        boxed: smallest_stable(&rows, |r| r.boxed, budget),
        fitted: smallest_stable(&rows, |r| r.fitted, budget),
        hero: hero_n,
    })
}
