//! What one estimate costs: a configuration (method, pdf and strata, n or
//! M) timed in the running process.
//!
//! The cost has two parts, measured apart:
//! - **per estimate**: what a renderer pays every time (n samples drawn,
//!   evaluated and converted; or a bucketed product and its conversion);
//! - **preparation**: what it pays once per spectrum (building a light's
//!   pdf table; bucketing the light and the surface).
//!
//! Each is the median of repeated timings, after a warm-up, on the calling
//! thread, with batches long enough (about 0.2 ms) for the clock. Figures
//! move with the machine's load: compare them within one run.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::data::{Light, patches};
//! use speclab_study::{planning::cost::{self, Config}, evaluate::method::Method};
//! let hero = Config::new(Method::HERO, NonZeroUsize::new(16).unwrap());
//! let c = cost::measure(hero, &Light::D65.into(), &patches::A1)?;
//! assert!(c.per_estimate_ns > 0.0);
//! assert_eq!(hero.to_string(), "hero uniform/none n=16");
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::fmt;
use std::hint::black_box;
use std::num::NonZeroUsize;
use std::time::Instant;

use rand::SeedableRng;
use rand::rngs::StdRng;

use crate::StudyError;
use crate::evaluate::method::Method;
use crate::evaluate::scene::Named;
use crate::published::prefilter::{Prefiltered, Space};
use speclab::sampling::rule::Rule;
use speclab::spectrum::TabulatedSpectrum;

/// A method with its sample count n or bucket count M.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Config {
    /// The method, with its pdf and strata for the random ones.
    pub method: Method,
    /// n (random, hero) or M (buckets); ignored by the reference.
    pub count: NonZeroUsize,
}

impl Config {
    /// `method` with `count` samples or buckets.
    #[must_use]
    pub fn new(method: Method, count: NonZeroUsize) -> Self {
        Config { method, count }
    }
}

impl fmt::Display for Config {
    /// `hero light/jitter n=32`, `regular-box M=39`, `reference`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.method {
            Method::Reference => write!(f, "reference"),
            Method::Prefiltered { .. } => write!(f, "{}", self.method),
            Method::Buckets { .. } | Method::Fitted | Method::Published { .. } => {
                write!(f, "{} M={}", self.method, self.count)
            }
            m => {
                let sampling = m.sampling().unwrap_or_default();
                write!(f, "{m} {sampling} n={}", self.count)
            }
        }
    }
}

/// The measured cost of a configuration, ns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cost {
    /// One estimate, ns.
    pub per_estimate_ns: f64,
    /// Once per light and surface (pdf table, bucketing), ns.
    pub preparation_ns: f64,
}

/// The cost of `config` on `light × surface`. Preparation is what is done
/// once per light (a pdf table, built now) or per spectrum (its M bucket
/// values); per estimate, what a renderer repeats.
pub fn measure(config: Config, light: &Named, surface: &TabulatedSpectrum) -> Result<Cost, StudyError> {
    let m = config.count.get();
    let rule = match config.method {
        Method::Fitted => light.rules()?.rule(m)?.clone(),
        Method::Buckets { rule } => Rule::buckets(m, rule)?,
        Method::Published { family } => light.published(family, m)?,
        Method::Prefiltered { space } => return prefiltered(space, light, surface),
        method => {
            let preparation_ns = median_ns(|| drop(black_box(method.prepare(light))));
            let prepared = method.prepare(light)?;
            let mut rng = StdRng::seed_from_u64(0x5EED);
            let per_estimate_ns =
                median_ns(|| drop(black_box(prepared.xyz_with_rng(surface, config.count, &mut rng))));
            return Ok(Cost { per_estimate_ns, preparation_ns });
        }
    };
    Ok(fixed(&rule, &light.spectrum, surface))
}

/// The cost of a fixed rule (buckets or fitted): preparation takes the
/// light's and the surface's values for it (a fit itself is once per
/// scene's lights, tens of milliseconds, and not counted); an estimate
/// multiplies and weights the stored values.
fn fixed(rule: &Rule, light: &TabulatedSpectrum, surface: &TabulatedSpectrum) -> Cost {
    let (mut l, mut s) = (vec![0.0; rule.m()], vec![0.0; rule.m()]);
    let preparation_ns = median_ns(|| {
        rule.values_into(black_box(light), &mut l);
        rule.values_into(black_box(surface), &mut s);
        black_box((&l, &s));
    });
    let per_estimate_ns = median_ns(|| {
        black_box(rule.xyz_of_factors(&[black_box(&l), black_box(&s)]));
    });
    Cost { per_estimate_ns, preparation_ns }
}

/// The cost of prefiltering: preparation integrates the surface under the
/// light exactly and keeps three numbers (the light's own, once per scene,
/// is not counted); an estimate multiplies them and converts to XYZ.
fn prefiltered(space: Space, light: &Named, surface: &TabulatedSpectrum) -> Result<Cost, StudyError> {
    let p = Prefiltered::new(space, light.white())?;
    let preparation_ns = median_ns(|| {
        black_box(p.surface(light.exact(black_box(surface))));
    });
    let s = p.surface(light.exact(surface));
    let per_estimate_ns = median_ns(|| {
        black_box(p.xyz(&[black_box(s)]));
    });
    Ok(Cost { per_estimate_ns, preparation_ns })
}

/// The median over 7 timings of `f`'s duration, ns, after a warm-up; each
/// timing runs `f` often enough to last about 0.2 ms.
fn median_ns(mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    f();
    // The calibration sets only how long each timing lasts, not what it
    // reports.
    let once = start.elapsed().as_secs_f64() / 2.0;
    let repeats = ((2e-4 / once.max(1e-9)).ceil() as usize).clamp(1, 1 << 20);
    let times: Vec<f64> = (0..7)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..repeats {
                f();
            }
            ns_per_call(start.elapsed().as_secs_f64(), repeats)
        })
        .collect();
    median(times)
}

/// `seconds` for `calls` calls, as ns per call.
fn ns_per_call(seconds: f64, calls: usize) -> f64 {
    seconds * 1e9 / calls as f64
}

/// The middle value of an odd number of values.
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_arithmetic() {
        let n = |k| NonZeroUsize::new(k).unwrap();
        assert_eq!(Config::new(Method::BOX, n(39)).to_string(), "regular-box M=39");
        assert_eq!(Config::new(Method::Reference, n(1)).to_string(), "reference");
        assert_eq!(Config::new(Method::RANDOM, n(8)).to_string(), "random uniform/none n=8");
        assert_eq!(ns_per_call(2e-4, 50), 4000.0);
        assert_eq!(median(vec![5.0, 1.0, 4.0, 2.0, 3.0, 7.0, 6.0]), 4.0);
    }
}
