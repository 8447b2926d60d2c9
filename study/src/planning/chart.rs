//! Speed against accuracy: for each light, every charted configuration's
//! measured cost per estimate beside its worst-patch RMS ΔE00, and the
//! Pareto front of the two.
//!
//! The charted methods are [`curves`]: the assignment's random and hero,
//! hero with each strata and with each pdf, centre and box buckets, the
//! fitted rule, and the reference as a single point; on paths of any depth
//! (light × surface^depth). Random and hero run
//! n = 1, 2, 4, … [`CHART_MAX_N`]; buckets every M up to 64. The `chart`
//! tool (`tools/src/bin/chart.rs`) draws the points; a method added to
//! [`curves`] appears there unchanged. Costs are measured now
//! ([`points`]) or passed in ([`points_with_costs`], as the tests do).
//!
//! ```
//! use speclab_study::planning::chart::pareto;
//! // (cost, error): the middle point is beaten on both by the first.
//! assert_eq!(pareto(&[(1.0, 1.0), (2.0, 2.0), (3.0, 0.5)]), [true, false, true]);
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::Method;
use crate::evaluate::scene::{Depth, Named};
use crate::evaluate::trials;
use crate::planning::cost::{self, Config, Cost};
use crate::sampling::choice::{PdfKind, Sampling};
use crate::sampling::strata::Strata;

/// The largest n charted for random and hero.
pub const CHART_MAX_N: usize = 1024;

/// The charted methods, one curve each (the reference is one point): the
/// assignment's random, hero with every strata under the uniform pdf, hero
/// with every other pdf under jittered numbers, both bucket rules, the
/// rule fitted to the light, and of the published ones ASTM's, Borges's
/// and prefiltering in sharpened RGB (the strongest of their kinds in
/// docs/published-rules.md). A pdf
/// or strata added to [`PdfKind::ALL`] or [`Strata::ALL`] is charted with no
/// change here.
#[must_use]
pub fn curves() -> Vec<Method> {
    let hero = |pdf, strata| Method::HERO.with_sampling(Sampling { pdf, strata });
    let mut out = vec![Method::Reference, Method::RANDOM];
    out.extend(Strata::ALL.map(|strata| hero(PdfKind::Uniform, strata)));
    out.extend(
        PdfKind::ALL.into_iter().filter(|&p| p != PdfKind::Uniform).map(|pdf| hero(pdf, Strata::Jittered)),
    );
    out.extend([Method::CENTER, Method::BOX, Method::FITTED]);
    out.extend([Method::PUBLISHED[0], Method::PUBLISHED[1], Method::PUBLISHED[6]]);
    out
}

/// The counts charted for `method`: [`Method::counts`] up to
/// [`CHART_MAX_N`], and the reference's one point.
#[must_use]
pub fn chart_counts(method: Method) -> Vec<usize> {
    match method {
        Method::Reference => vec![1],
        _ => method.counts(CHART_MAX_N),
    }
}

/// One point of the chart.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// The light's name.
    pub light: String,
    /// The configuration.
    pub config: Config,
    /// Its measured cost (on the light × the first surface).
    pub cost: Cost,
    /// The largest RMS ΔE00 over the surfaces.
    pub worst_rms: f64,
    /// The mean RMS ΔE00 over the surfaces.
    pub mean_rms: f64,
    /// Trials behind each RMS (1 for deterministic methods).
    pub trials: usize,
    /// On the light's Pareto front of cost against worst RMS ΔE00 among
    /// the sampling methods (never the reference: see [`points`]).
    pub pareto: bool,
}

/// Every configuration of `methods` under `light`, over `surfaces` (at
/// least one) to the power `depth`, with `trials` trials per random point
/// (costs are measured at depth 1); Pareto flags set
/// among the sampling methods. The reference is charted as a point but is
/// not on the front: it is the yardstick (ΔE00 0 by definition), and it
/// integrates one light × one surface exactly, which a path's product of
/// many spectra does not allow.
pub fn points(
    light: &Named,
    surfaces: &[Named],
    methods: &[Method],
    depth: Depth,
    trials: NonZeroUsize,
    seed: u64,
) -> Result<Vec<Point>, StudyError> {
    let first = surfaces.first().ok_or(StudyError::EmptyScene)?;
    let measure = |config| cost::measure(config, light, &first.spectrum);
    points_with_costs(light, surfaces, methods, depth, trials, seed, measure)
}

/// [`points`] with each configuration's cost given by `cost` instead of
/// measured on the light × the first surface.
pub fn points_with_costs(
    light: &Named,
    surfaces: &[Named],
    methods: &[Method],
    depth: Depth,
    trials: NonZeroUsize,
    seed: u64,
    mut cost: impl FnMut(Config) -> Result<Cost, StudyError>,
) -> Result<Vec<Point>, StudyError> {
    if surfaces.is_empty() {
        return Err(StudyError::EmptyScene);
    }
    let mut out = Vec::new();
    for &method in methods {
        for count in chart_counts(method) {
            // A Borges rule without real nodes for this light: no point.
            if let Method::Published { family } = method
                && matches!(light.published(family, count), Err(StudyError::NoRule { .. }))
            {
                continue;
            }
            let config = Config::new(method, NonZeroUsize::new(count).unwrap_or(NonZeroUsize::MIN));
            let cost = cost(config)?;
            let mut rms = Vec::with_capacity(surfaces.len());
            let mut ran = 1;
            for s in surfaces {
                let s = &s.spectrum;
                let stats = trials::method_at_depth(light, s, depth, method, config.count, trials, seed)?;
                ran = stats.trials;
                rms.push(stats.rms_de00);
            }
            let worst_rms = rms.iter().copied().fold(0.0, f64::max);
            let mean_rms = rms.iter().sum::<f64>() / rms.len() as f64;
            let point = Point {
                light: light.name.clone(),
                config,
                cost,
                worst_rms,
                mean_rms,
                trials: ran,
                pareto: false,
            };
            out.push(point);
        }
    }
    // The reference is the yardstick, not a contender: its ΔE00 is 0 by
    // definition, and it needs every spectrum of a path, which a renderer
    // multiplying many spectra per path does not integrate exactly.
    let contenders: Vec<(f64, f64)> = out
        .iter()
        .map(|p| match p.config.method {
            Method::Reference => (f64::NAN, f64::NAN),
            _ => (p.cost.per_estimate_ns, p.worst_rms),
        })
        .collect();
    for (p, on) in out.iter_mut().zip(pareto(&contenders)) {
        p.pareto = on;
    }
    Ok(out)
}

/// For each `(cost, error)` point, whether no other point is at least as
/// good in both and better in one. NaN points are never on the front.
#[must_use]
pub fn pareto(points: &[(f64, f64)]) -> Vec<bool> {
    points
        .iter()
        .map(|&(c, e)| {
            !c.is_nan()
                && !e.is_nan()
                && !points.iter().any(|&(c2, e2)| c2 <= c && e2 <= e && (c2 < c || e2 < e))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pareto_on_hand_made_points() {
        // A staircase with points above it, a tie, a duplicate and a NaN.
        let points = [
            (1.0, 5.0),
            (2.0, 3.0),
            (2.0, 4.0),
            (3.0, 3.0),
            (4.0, 1.0),
            (4.0, 1.0),
            (5.0, 0.5),
            (f64::NAN, 0.1),
        ];
        assert_eq!(pareto(&points), [true, true, false, false, true, true, true, false]);
        assert_eq!(pareto(&[]), Vec::<bool>::new());
        assert_eq!(pareto(&[(3.0, 3.0)]), [true]);
    }

    #[test]
    fn curves_and_counts() {
        let curves = curves();
        // Reference, random, hero × every strata, hero × every other pdf, 2
        // bucket rules, fitted, ASTM, Borges, prefiltering.
        assert_eq!(curves.len(), 2 + Strata::ALL.len() + PdfKind::ALL.len() - 1 + 3 + 3);
        assert_eq!(curves[curves.len() - 4], Method::FITTED);
        assert_eq!(curves.last().map(ToString::to_string).as_deref(), Some("prefilter-sharp"));
        for (i, a) in curves.iter().enumerate() {
            assert!(curves[i + 1..].iter().all(|b| b != a), "{a:?} twice");
        }
        for pdf in PdfKind::ALL.into_iter().filter(|&p| p != PdfKind::Uniform) {
            let hero = Method::HERO.with_sampling(Sampling { pdf, strata: Strata::Jittered });
            assert!(curves.contains(&hero), "{hero:?}");
        }
        assert_eq!(chart_counts(Method::HERO), [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]);
        assert_eq!(chart_counts(Method::BOX), (1..=64).collect::<Vec<_>>());
        assert_eq!(chart_counts(Method::FITTED), (1..=64).collect::<Vec<_>>());
        assert_eq!(chart_counts(Method::Reference), [1]);
        assert_eq!(chart_counts(Method::PUBLISHED[0]), (4..=64).collect::<Vec<_>>());
        assert_eq!(chart_counts(Method::PUBLISHED[6]), [3]);
    }
}
