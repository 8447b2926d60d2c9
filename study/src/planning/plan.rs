//! A plan for a scene: the cheapest configuration, in measured ns per
//! estimate, whose worst RMS ΔE00 over every light × surface of the scene is
//! within a budget, stably.
//!
//! - **Candidates**: random and hero with every pdf × strata, n = 1, 2, 4,
//!   … 4096; and, where bias is allowed, centre and box buckets and the
//!   rule fitted to the scene's lights (all of them at once), M = 1 … 64.
//!   The reference is the yardstick, not a candidate: a renderer cannot
//!   integrate each path exactly.
//! - **Cost**: [`crate::planning::cost`], on the first light × first surface.
//! - **Buckets** and **fitted rules** are deterministic: within budget
//!   *stably* means within budget at M and at every larger M up to 64
//!   (under F11, box M = 22 is below ΔE00 1 but M = 23–25 are not: 22 is
//!   luck).
//! - **Depth**: every cell is light × surface^depth ([`Request::depth`]);
//!   costs are measured at depth 1 (a deeper path adds one multiplication
//!   per bounce to every method alike).
//! - **Monte Carlo** methods: within budget if, in every cell, the upper end
//!   of a 95 % confidence interval of the RMS ΔE00 over the trials is. A
//!   cell is first screened with a tenth of the trials: a clear failure
//!   (its interval's lower end above the budget) costs no more.
//! - **Published rules and prefiltering** ([`crate::published`]) are
//!   built for one light: candidates only in a scene of one light, judged
//!   like fitted rules (prefiltering at its one size, 3).
//! - Candidates are tried in increasing cost; the first within budget is the
//!   plan, the next three the runners-up; the rest are not tried.
//!
//! ```
//! use speclab_study::planning::plan::{self, Request};
//! use speclab_study::evaluate::scene::{builtin_lights, builtin_surfaces};
//! let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
//! let plan = plan::plan(&lights[..1], &surfaces, &Request::default())?; // illuminant A
//! let chosen = plan.chosen.expect("A is easy");
//! // A dozen buckets (about 10 ns) beat every Monte Carlo method that gets
//! // within budget (a microsecond and more).
//! assert!(!chosen.config.method.is_random());
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::collections::HashMap;
use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::{Method, derive_seed};
use crate::evaluate::perceptual;
use crate::evaluate::scene::{Depth, Named};
use crate::evaluate::trials::{self, Stats};
use crate::experiments::convergence::CONVERGENCE_MAX_N;
use crate::planning::cost::{self, Config, Cost};
use crate::published::rules::Family;
use crate::sampling::choice::Sampling;
use speclab::color::Xyz;
use speclab::error::Error;
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::fitted::FittedRules;
use speclab::sampling::reference;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::spectrum::Spectrum;

/// What the plan must meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Request {
    /// The largest acceptable RMS ΔE00 in any cell (default 1).
    pub budget: f64,
    /// Whether biased methods (buckets) may be chosen (default true).
    pub allow_bias: bool,
    /// Trials per Monte Carlo cell (default 200).
    pub trials: NonZeroUsize,
    /// Base seed (default 1).
    pub seed: u64,
    /// Surfaces per path (default 1).
    pub depth: Depth,
}

impl Default for Request {
    fn default() -> Self {
        Request {
            budget: 1.0,
            allow_bias: true,
            trials: NonZeroUsize::new(200).unwrap_or(NonZeroUsize::MIN),
            seed: 1,
            depth: Depth::ONE,
        }
    }
}

/// What became of a candidate.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// Within budget: the worst cell's RMS ΔE00 (upper end of its 95 %
    /// interval for Monte Carlo methods).
    Within {
        /// That worst value.
        worst: f64,
    },
    /// Above budget in a cell.
    Above {
        /// The value there (for Monte Carlo, the RMS; the interval's lower
        /// end if screening stopped it).
        worst: f64,
        /// The cell, `light × surface`.
        cell: String,
    },
    /// Within budget at M, but not at the larger `m` (buckets, fitted).
    Unstable {
        /// The worst RMS ΔE00 at M.
        worst: f64,
        /// The first larger M above budget.
        m: usize,
    },
    /// Biased, and the request excludes bias.
    Biased,
    /// Not needed: costlier than the plan and its runners-up.
    NotTried,
}

/// A candidate configuration, its cost and its verdict.
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate {
    /// The configuration.
    pub config: Config,
    /// Its measured cost.
    pub cost: Cost,
    /// What it did against the budget.
    pub verdict: Verdict,
}

/// The outcome of planning.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The cheapest candidate within budget, if any.
    pub chosen: Option<Candidate>,
    /// The next cheapest within budget (up to three).
    pub runners_up: Vec<Candidate>,
    /// Every other candidate, in increasing cost, with its verdict.
    pub others: Vec<Candidate>,
}

/// Plans `lights × surfaces` for `request`, with every candidate's cost
/// measured now ([`crate::planning::cost::measure`]). Errors for an empty scene or a budget that
/// is not finite and positive.
pub fn plan(lights: &[Named], surfaces: &[Named], request: &Request) -> Result<Plan, StudyError> {
    validate(lights, surfaces, request)?;
    let mut measured = Vec::new();
    // Published rules and prefiltering: measured only where they can be
    // chosen (biased, and built for one light).
    let per_light = request.allow_bias && lights.len() == 1;
    for config in configs() {
        if per_light || !config.method.is_published() {
            measured.extend(measured_cost(config, &lights[0], &surfaces[0])?);
        }
    }
    plan_with_costs(lights, surfaces, request, &measured)
}

/// An error for an empty scene or a budget that is not finite and positive.
fn validate(lights: &[Named], surfaces: &[Named], request: &Request) -> Result<(), StudyError> {
    if lights.is_empty() || surfaces.is_empty() {
        return Err(StudyError::EmptyScene);
    }
    if !(request.budget.is_finite() && request.budget > 0.0) {
        return Err(StudyError::Budget { value: request.budget });
    }
    Ok(())
}

/// `config` with its cost on `light × surface`; none for a Borges rule
/// without real nodes for this light.
fn measured_cost(
    config: Config,
    light: &Named,
    surface: &Named,
) -> Result<Option<(Config, Cost)>, StudyError> {
    match cost::measure(config, light, &surface.spectrum) {
        Ok(cost) => Ok(Some((config, cost))),
        Err(StudyError::NoRule { .. }) => Ok(None),
        Err(e) => Err(e),
    }
}

/// [`plan`] with costs measured before: the same costs give
/// the same plan for any seed whose trials agree, which timing noise
/// would otherwise blur.
pub fn plan_with_costs(
    lights: &[Named],
    surfaces: &[Named],
    request: &Request,
    costs: &[(Config, Cost)],
) -> Result<Plan, StudyError> {
    validate(lights, surfaces, request)?;
    let scene = Scene::new(lights, surfaces, request.depth);
    let mut candidates = costs.to_vec();
    // A published rule or a prefiltering is built for one light.
    candidates.retain(|(c, _)| lights.len() == 1 || !c.method.is_published());
    candidates.sort_by(|a, b| a.1.per_estimate_ns.total_cmp(&b.1.per_estimate_ns));
    let (center, boxed) =
        (scene.bucket_errors(BucketRule::Center)?, scene.bucket_errors(BucketRule::BoxAverage)?);
    // Fitted rules are fitted (every M) only if one is tried.
    let mut fitted: Option<Vec<(f64, String)>> = None;
    let mut published: HashMap<Family, Vec<(f64, String)>> = HashMap::new();
    let mut plan = Plan { chosen: None, runners_up: Vec::new(), others: Vec::new() };
    for (config, cost) in candidates {
        let m = config.count.get();
        if config.method.is_fixed() && m > MAX_M {
            return Err(Error::Count { what: "a fixed rule's size", found: m, min: 1, max: MAX_M }.into());
        }
        let done = plan.runners_up.len() == 3;
        let verdict = match config.method {
            _ if done => Verdict::NotTried,
            m if m.is_fixed() && !request.allow_bias => Verdict::Biased,
            Method::Fitted => {
                if fitted.is_none() {
                    fitted = Some(scene.fitted_errors(lights)?);
                }
                bucket_verdict(fitted.as_deref().unwrap_or_default(), config.count.get(), request.budget)
            }
            Method::Buckets { rule: BucketRule::Center } => {
                bucket_verdict(&center, config.count.get(), request.budget)
            }
            Method::Buckets { rule: BucketRule::BoxAverage } => {
                bucket_verdict(&boxed, config.count.get(), request.budget)
            }
            Method::Published { family } => {
                let worst = published.entry(family).or_insert_with(|| scene.published_errors(family));
                bucket_verdict(worst, config.count.get(), request.budget)
            }
            Method::Prefiltered { space } => {
                let worst = scene.prefiltered_error(space)?;
                bucket_verdict(&[worst], 1, request.budget)
            }
            _ => scene.monte_carlo_verdict(config, request)?,
        };
        let candidate = Candidate { config, cost, verdict };
        match (&candidate.verdict, &plan.chosen) {
            (Verdict::Within { .. }, None) => plan.chosen = Some(candidate),
            (Verdict::Within { .. }, Some(_)) => plan.runners_up.push(candidate),
            _ => plan.others.push(candidate),
        }
    }
    Ok(plan)
}

/// Every candidate configuration (the reference excepted).
fn configs() -> Vec<Config> {
    let count = |n: usize| NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
    let random = [Method::RANDOM, Method::HERO];
    let mut out: Vec<Config> = Sampling::all()
        .into_iter()
        .flat_map(|s| random.map(|m| m.with_sampling(s)))
        .flat_map(|m| m.counts(CONVERGENCE_MAX_N).into_iter().map(move |n| Config::new(m, count(n))))
        .collect();
    for method in [Method::CENTER, Method::BOX, Method::FITTED].into_iter().chain(Method::PUBLISHED) {
        out.extend(method.counts(CONVERGENCE_MAX_N).into_iter().map(|m| Config::new(method, count(m))));
    }
    out
}

/// The verdict for M buckets (or fitted wavelengths) from the worst ΔE00
/// at every M (index M − 1). A published rule that does not exist at some
/// M has NaN there: above budget at that M, and not judged as a larger M.
fn bucket_verdict(worst: &[(f64, String)], m: usize, budget: f64) -> Verdict {
    let (at, cell) = worst[m - 1].clone();
    if at.is_nan() || at > budget {
        return Verdict::Above { worst: at, cell };
    }
    match worst[m..].iter().position(|(e, _)| *e > budget) {
        Some(i) => Verdict::Unstable { worst: at, m: m + 1 + i },
        None => Verdict::Within { worst: at },
    }
}

/// The scene's cells with their references (at the scene's depth) and
/// whites.
struct Scene<'a> {
    cells: Vec<(&'a Named, &'a Named, Xyz, Xyz)>,
    depth: Depth,
}

impl<'a> Scene<'a> {
    fn new(lights: &'a [Named], surfaces: &'a [Named], depth: Depth) -> Self {
        let cells = lights
            .iter()
            .flat_map(|l| {
                let white = reference::white(&l.spectrum);
                surfaces.iter().map(move |s| (l, s, l.exact_at(depth, &s.spectrum), white))
            })
            .collect();
        Scene { cells, depth }
    }

    /// For M = 1 … 64, the worst ΔE00 over the cells of `estimate(M, light,
    /// surface)` and where it is.
    fn worst_by_m(
        &self,
        max: usize,
        mut estimate: impl FnMut(usize, &Named, &Named) -> Result<Xyz, StudyError>,
    ) -> Result<Vec<(f64, String)>, StudyError> {
        (1..=max)
            .map(|m| {
                let mut worst = (f64::NEG_INFINITY, String::new());
                for (l, s, exact, white) in &self.cells {
                    let de = perceptual::delta_e00(estimate(m, l, s)?, *exact, *white);
                    if de > worst.0 {
                        worst = (de, format!("{} × {}", l.name, s.name));
                    }
                }
                Ok(worst)
            })
            .collect()
    }

    /// For M = 1 … 64 buckets under `rule`, the worst ΔE00 and where.
    fn bucket_errors(&self, rule: BucketRule) -> Result<Vec<(f64, String)>, StudyError> {
        let depth = self.depth.get();
        self.worst_by_m(MAX_M, |m, l, s| {
            let buckets = Rule::buckets(m, rule)?;
            let (lv, sv) = (buckets.values(&l.spectrum), buckets.values(&s.spectrum));
            let mut factors: Vec<&[f64]> = vec![&lv];
            factors.extend(std::iter::repeat_n(&sv[..], depth));
            Ok(buckets.xyz_of_factors(&factors))
        })
    }

    /// For M = 1 … 64, the worst ΔE00 of the rule fitted to all of
    /// `lights` at once, and where.
    fn fitted_errors(&self, lights: &[Named]) -> Result<Vec<(f64, String)>, StudyError> {
        let fits = match lights {
            // One light keeps its own rules.
            [light] => light.rules()?,
            _ => FittedRules::new(&lights.iter().map(|l| &l.spectrum).collect::<Vec<_>>())?,
        };
        let rules: Vec<Rule> = (1..=MAX_M).map(|m| fits.rule(m).cloned()).collect::<Result<_, _>>()?;
        self.worst_by_m(MAX_M, |m, l, s| {
            let path = self.depth.path(&s.spectrum);
            let mut factors: Vec<&dyn Spectrum> = vec![&l.spectrum];
            factors.extend_from_slice(path.factors());
            Ok(rules[m - 1].xyz_of_product(&factors))
        })
    }

    /// Screens every cell with a tenth of the trials, then runs them all;
    /// within budget if every cell's 95 % upper bound is. Each cell and
    /// stage draws from a stream of its own.
    fn monte_carlo_verdict(&self, config: Config, request: &Request) -> Result<Verdict, StudyError> {
        let screen = NonZeroUsize::new(request.trials.get().div_ceil(10).max(10)).unwrap_or(request.trials);
        let stages = [screen.min(request.trials), request.trials];
        let mut prepared = Vec::with_capacity(self.cells.len());
        for (l, ..) in &self.cells {
            prepared.push(config.method.prepare(l)?.at_depth(self.depth));
        }
        let names: Vec<String> =
            self.cells.iter().map(|(l, s, ..)| format!("{} × {}", l.name, s.name)).collect();
        judge(&names, request.budget, |c, stage| {
            let (_, s, exact, white) = &self.cells[c];
            let base = derive_seed(request.seed, (c as u64) << 1 | stage as u64);
            trials::run(*exact, *white, stages[stage], base, |seed| {
                prepared[c].xyz(&s.spectrum, config.count, seed)
            })
        })
    }
}

/// The Monte Carlo verdict for `cells` from `run(cell, stage)`, the trials
/// of stage 0 (the screen, a tenth of the trials) or 1 (all of them): a
/// cell whose screened RMS ΔE00 has its 95 % interval's lower end above
/// `budget` stops the run (the full run would almost surely reject it too:
/// the screen only saves time); otherwise within budget if every cell's
/// full-run upper end is, the worst upper end reported.
fn judge(
    cells: &[String],
    budget: f64,
    mut run: impl FnMut(usize, usize) -> Result<Stats, StudyError>,
) -> Result<Verdict, StudyError> {
    for (c, cell) in cells.iter().enumerate() {
        let (lower, _) = run(c, 0)?.rms_de00_interval();
        if lower > budget {
            return Ok(Verdict::Above { worst: lower, cell: cell.clone() });
        }
    }
    let mut worst = 0.0f64;
    for (c, cell) in cells.iter().enumerate() {
        let stats = run(c, 1)?;
        let (_, upper) = stats.rms_de00_interval();
        if upper > budget {
            return Ok(Verdict::Above { worst: stats.rms_de00, cell: cell.clone() });
        }
        worst = worst.max(upper);
    }
    Ok(Verdict::Within { worst })
}

#[path = "plan_published.rs"]
mod published;

#[cfg(test)]
#[path = "plan_tests.rs"]
mod tests;
