//! A plan for a scene: the cheapest configuration, in measured ns per
//! estimate, whose worst RMS ΔE00 over every light × surface of the scene is
//! within a budget, stably.
//!
//! - **Candidates**: random and hero with every pdf × strata, n = 1, 2, 4,
//!   … 4096; and, where bias is allowed, centre and box buckets, M = 1 … 64.
//!   The reference is the yardstick, not a candidate: a renderer cannot
//!   integrate each path exactly.
//! - **Cost**: [`crate::study::cost`], on the first light × first surface.
//! - **Buckets** are deterministic: within budget *stably* means within
//!   budget at M and at every larger M up to 64 (under F11, box M = 22 is
//!   below ΔE00 1 but M = 23–25 are not: 22 is luck).
//! - **Monte Carlo** methods: within budget if, in every cell, the upper end
//!   of a 95 % confidence interval of the RMS ΔE00 over the trials is. A
//!   cell is first screened with a tenth of the trials: a clear failure
//!   (its interval's lower end above the budget) costs no more.
//! - Candidates are tried in increasing cost; the first within budget is the
//!   plan, the next three the runners-up; the rest are not tried.
//!
//! ```
//! use speclab::study::plan::{self, Request};
//! use speclab::study::scene::{builtin_lights, builtin_surfaces};
//! let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
//! let plan = plan::plan(&lights[..1], &surfaces, &Request::default())?; // illuminant A
//! let chosen = plan.chosen.expect("A is easy");
//! // A dozen buckets (about 10 ns) beat every Monte Carlo method that gets
//! // within budget (a microsecond and more).
//! assert!(!chosen.config.method.is_random());
//! # Ok::<(), speclab::Error>(())
//! ```

use std::num::NonZeroUsize;

use crate::sampling::reference;
use crate::sampling::regular::{self, MAX_BUCKETS, Rule};
use crate::study::cost::{self, Config, Cost};
use crate::study::method::{Method, derive_seed};
use crate::study::sampling::Sampling;
use crate::study::scene::Named;
use crate::study::{convergence, perceptual, trials};
use crate::{Error, Xyz};

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
}

impl Default for Request {
    fn default() -> Self {
        Request {
            budget: 1.0,
            allow_bias: true,
            trials: NonZeroUsize::new(200).unwrap_or(NonZeroUsize::MIN),
            seed: 1,
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
    /// Within budget at M, but not at the larger `m` (buckets).
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
/// measured now (see [`costs`]). Errors for an empty scene or a budget that
/// is not finite and positive.
pub fn plan(lights: &[Named], surfaces: &[Named], request: &Request) -> Result<Plan, Error> {
    validate(lights, surfaces, request)?;
    plan_with_costs(lights, surfaces, request, &costs(&lights[0], &surfaces[0])?)
}

/// An error for an empty scene or a budget that is not finite and positive.
fn validate(lights: &[Named], surfaces: &[Named], request: &Request) -> Result<(), Error> {
    if lights.is_empty() || surfaces.is_empty() {
        return Err(Error::EmptyScene);
    }
    if !(request.budget.is_finite() && request.budget > 0.0) {
        return Err(Error::Budget { value: request.budget });
    }
    Ok(())
}

/// Every candidate configuration with its cost measured on `light ×
/// surface` (the reference excepted), in increasing cost per estimate.
pub fn costs(light: &Named, surface: &Named) -> Result<Vec<(Config, Cost)>, Error> {
    let mut out = Vec::new();
    for config in configs() {
        out.push((config, cost::measure(config, &light.spectrum, &surface.spectrum)?));
    }
    out.sort_by(|a, b| a.1.per_estimate_ns.total_cmp(&b.1.per_estimate_ns));
    Ok(out)
}

/// [`plan`] with costs measured before (by [`costs`]): the same costs give
/// the same plan for any seed whose trials agree, which timing noise
/// would otherwise blur.
pub fn plan_with_costs(
    lights: &[Named],
    surfaces: &[Named],
    request: &Request,
    costs: &[(Config, Cost)],
) -> Result<Plan, Error> {
    validate(lights, surfaces, request)?;
    let scene = Scene::new(lights, surfaces);
    let mut candidates = costs.to_vec();
    candidates.sort_by(|a, b| a.1.per_estimate_ns.total_cmp(&b.1.per_estimate_ns));
    let (centre, boxed) = (scene.bucket_errors(Rule::Centre)?, scene.bucket_errors(Rule::BoxAverage)?);
    let mut plan = Plan { chosen: None, runners_up: Vec::new(), others: Vec::new() };
    for (config, cost) in candidates {
        let done = plan.runners_up.len() == 3;
        let verdict = match config.method {
            _ if done => Verdict::NotTried,
            Method::RegularCentre | Method::RegularBox if !request.allow_bias => Verdict::Biased,
            Method::RegularCentre => bucket_verdict(&centre, config.count.get(), request.budget),
            Method::RegularBox => bucket_verdict(&boxed, config.count.get(), request.budget),
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
        .flat_map(|m| convergence::counts(m).into_iter().map(move |n| Config::new(m, count(n))))
        .collect();
    for method in [Method::RegularCentre, Method::RegularBox] {
        out.extend((1..=MAX_BUCKETS).map(|m| Config::new(method, count(m))));
    }
    out
}

/// The verdict for M buckets from the worst ΔE00 at every M (index M − 1).
fn bucket_verdict(worst: &[(f64, String)], m: usize, budget: f64) -> Verdict {
    let (at, cell) = worst[m - 1].clone();
    if at > budget {
        return Verdict::Above { worst: at, cell };
    }
    match worst[m..].iter().position(|(e, _)| *e > budget) {
        Some(i) => Verdict::Unstable { worst: at, m: m + 1 + i },
        None => Verdict::Within { worst: at },
    }
}

/// The scene's cells with their references and whites.
struct Scene<'a> {
    cells: Vec<(&'a Named, &'a Named, Xyz, Xyz)>,
}

impl<'a> Scene<'a> {
    fn new(lights: &'a [Named], surfaces: &'a [Named]) -> Self {
        let cells = lights
            .iter()
            .flat_map(|l| {
                let white = reference::white(&l.spectrum);
                surfaces.iter().map(move |s| (l, s, reference::xyz(&l.spectrum, &s.spectrum), white))
            })
            .collect();
        Scene { cells }
    }

    /// For M = 1 … 64, the worst ΔE00 over the cells and where it is.
    fn bucket_errors(&self, rule: Rule) -> Result<Vec<(f64, String)>, Error> {
        (1..=MAX_BUCKETS)
            .map(|m| {
                let mut worst = (f64::NEG_INFINITY, String::new());
                for (l, s, exact, white) in &self.cells {
                    let de = perceptual::delta_e00(
                        regular::xyz_dyn(m, rule, &l.spectrum, &s.spectrum)?,
                        *exact,
                        *white,
                    );
                    // (`>=` would name the later of two cells tied exactly.)
                    if de > worst.0 {
                        worst = (de, format!("{} × {}", l.name, s.name));
                    }
                }
                Ok(worst)
            })
            .collect()
    }

    /// Screens every cell with a tenth of the trials, then runs them all;
    /// within budget if every cell's 95 % upper bound is.
    fn monte_carlo_verdict(&self, config: Config, request: &Request) -> Result<Verdict, Error> {
        let screen = NonZeroUsize::new(request.trials.get().div_ceil(10).max(10)).unwrap_or(request.trials);
        let mut worst = 0.0f64;
        for (stage, trials) in [(0u64, screen.min(request.trials)), (1, request.trials)] {
            for (c, (l, s, exact, white)) in self.cells.iter().enumerate() {
                let prepared = config.method.prepare(&l.spectrum)?;
                // One stream per cell and stage. Another injective choice
                // (`^` for `|` is the same here) changes only which draws.
                let base = derive_seed(request.seed, (c as u64) << 1 | stage);
                let stats = trials::run(*exact, *white, trials, base, |seed| {
                    prepared.xyz(&s.spectrum, config.count, seed)
                })?;
                let (lower, upper) = stats.rms_de00_interval();
                let cell = format!("{} × {}", l.name, s.name);
                // The screen only saves time: it stops a cell whose lower
                // bound from a tenth of the trials is already above budget,
                // which the full run would (almost surely) reject too.
                if stage == 0 && lower > request.budget {
                    return Ok(Verdict::Above { worst: lower, cell });
                }
                if stage == 1 {
                    if upper > request.budget {
                        return Ok(Verdict::Above { worst: stats.rms_de00, cell });
                    }
                    worst = worst.max(upper);
                }
            }
        }
        Ok(Verdict::Within { worst })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bucket_verdicts_on_hand_made_errors() {
        let worst = |v: &[f64]| v.iter().map(|&e| (e, "cell".to_string())).collect::<Vec<_>>();
        let errors = worst(&[2.0, 1.0, 1.0, 0.5]);
        assert_eq!(bucket_verdict(&errors, 1, 1.0), Verdict::Above { worst: 2.0, cell: "cell".into() });
        // Equal to the budget is within, at M and at every larger M.
        assert_eq!(bucket_verdict(&errors, 2, 1.0), Verdict::Within { worst: 1.0 });
        assert_eq!(bucket_verdict(&errors, 4, 1.0), Verdict::Within { worst: 0.5 });
        // Above again two counts later: the first such M is named.
        let errors = worst(&[0.5, 0.6, 2.0, 0.1]);
        assert_eq!(bucket_verdict(&errors, 1, 1.0), Verdict::Unstable { worst: 0.5, m: 3 });
        assert_eq!(bucket_verdict(&errors, 2, 1.0), Verdict::Unstable { worst: 0.6, m: 3 });
    }

    /// The upper end of the 95 % interval of each cell's full run, computed
    /// the way the module says: its own stream per cell, all the trials.
    fn full_run_bounds(scene: &Scene, config: Config, request: &Request) -> Vec<(f64, f64)> {
        let cells = scene.cells.iter().enumerate();
        cells
            .map(|(c, (l, s, exact, white))| {
                let prepared = config.method.prepare(&l.spectrum).unwrap();
                let base = derive_seed(request.seed, (c as u64) << 1 | 1);
                let stats = trials::run(*exact, *white, request.trials, base, |seed| {
                    prepared.xyz(&s.spectrum, config.count, seed)
                });
                let stats = stats.unwrap();
                (stats.rms_de00, stats.rms_de00_interval().1)
            })
            .collect()
    }

    #[test]
    fn monte_carlo_verdicts_use_the_full_run_of_every_cell() {
        let (lights, surfaces) =
            (crate::study::scene::builtin_lights(), crate::study::scene::builtin_surfaces());
        let scene = Scene::new(&lights[..1], &surfaces[..3]);
        let config = Config::new(Method::HERO, NonZeroUsize::new(4).unwrap());
        let loose = Request { budget: 100.0, trials: NonZeroUsize::new(40).unwrap(), ..Request::default() };
        let bounds = full_run_bounds(&scene, config, &loose);
        let worst = bounds.iter().map(|b| b.1).fold(0.0, f64::max);
        let within = scene.monte_carlo_verdict(config, &loose).unwrap();
        assert_eq!(within, Verdict::Within { worst });
        // A budget equal to the worst upper bound is met; just below, it is
        // not, and the cell named is the one with that bound.
        let at = Request { budget: worst, ..loose };
        assert_eq!(scene.monte_carlo_verdict(config, &at).unwrap(), Verdict::Within { worst });
        let below = Request { budget: worst * (1.0 - 1e-12), ..loose };
        let cell = bounds.iter().position(|b| b.1 == worst).unwrap();
        let name = format!("{} × {}", lights[0].name, surfaces[cell].name);
        let above = Verdict::Above { worst: bounds[cell].0, cell: name };
        assert_eq!(scene.monte_carlo_verdict(config, &below).unwrap(), above);
    }

    #[test]
    fn a_clear_failure_is_stopped_by_the_screen() {
        let (lights, surfaces) =
            (crate::study::scene::builtin_lights(), crate::study::scene::builtin_surfaces());
        let scene = Scene::new(&lights[..1], &surfaces[..1]);
        let config = Config::new(Method::RANDOM, NonZeroUsize::MIN);
        let request = Request { budget: 0.01, ..Request::default() };
        // The screen: a tenth of the trials (20), stream 0; its lower bound.
        let (_, _, exact, white) = scene.cells[0];
        let prepared = config.method.prepare(&lights[0].spectrum).unwrap();
        let screen = trials::run(exact, white, NonZeroUsize::new(20).unwrap(), derive_seed(1, 0), |seed| {
            prepared.xyz(&surfaces[0].spectrum, config.count, seed)
        });
        let lower = screen.unwrap().rms_de00_interval().0;
        assert!(lower > request.budget);
        let cell = format!("{} × {}", lights[0].name, surfaces[0].name);
        assert_eq!(
            scene.monte_carlo_verdict(config, &request).unwrap(),
            Verdict::Above { worst: lower, cell: cell.clone() }
        );
        // A budget exactly at the screen's lower bound passes the screen;
        // the full run then rejects the cell with its own RMS.
        let at = Request { budget: lower, ..Request::default() };
        match scene.monte_carlo_verdict(config, &at).unwrap() {
            Verdict::Above { worst, cell: c } => assert!(worst != lower && c == cell),
            other => panic!("expected the full run to reject the cell, got {other:?}"),
        }
    }
}
