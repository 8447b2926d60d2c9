//! Weights that control the worst case: for a rule's wavelengths, the
//! X, Y, Z weights (on light × surface, as a fitted rule's) that make the
//! largest ΔE00 over a set of surfaces as small as Lawson's iteration
//! finds it.
//!
//! Each step solves a weighted least-squares problem in CIELAB: surface
//! `s` contributes `uₛ·|Jₛ·(XYZₛ(w) − XYZₛ)|²`, with `Jₛ` the derivative of
//! (L*, a*, b*) at the surface's exact colour (relative to the light's
//! white), and the perfect white is held by a heavy row. Then each `uₛ` is
//! multiplied by the surface's ΔE00 and the `u` renormalised (Lawson
//! 1961: the weights drift to the surfaces that decide the worst case);
//! the best step seen is kept. Deterministic; the judge is ΔE00 itself.
//!
//! Used by the comparison's `oracle-minimax` (`compare::Candidate`): the
//! wavelengths of the rule fitted over the judged surfaces, weights by
//! this over the same surfaces: a reference point for what weights can do
//! there, not a method (Lawson's steps are a heuristic: not a proven
//! optimum).
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{fitted::FittedRules, reference};
//! use speclab::spectrum::Spectrum;
//! use speclab_study::published::minimax::{minimax, worst};
//! let six: Vec<&dyn Spectrum> = patches::ALL.iter().map(|&(_, p)| p as &dyn Spectrum).collect();
//! let rule = FittedRules::with_surfaces(&[&lights::D65], &six)?.rule(5)?.clone();
//! let better = minimax(&lights::D65, &rule, &six, 50)?;
//! assert!(worst(&lights::D65, &better, &six) < 0.8 * worst(&lights::D65, &rule, &six));
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use speclab::color::Xyz;
use speclab::color::lab::lab_jacobian;
use speclab::sampling::reference;
use speclab::sampling::rule::Rule;
use speclab::spectrum::Spectrum;

use crate::StudyError;
use crate::evaluate::perceptual::delta_e00;
use crate::published::solve::solve;

/// The white's row weight, relative to the surfaces' (which sum to one).
const WHITE: f64 = 1e3;

/// The largest ΔE00 over `surfaces` of `rule` under `light` (weights on
/// light × surface).
#[must_use]
pub fn worst(light: &dyn Spectrum, rule: &Rule, surfaces: &[&dyn Spectrum]) -> f64 {
    let white = reference::white(light);
    surfaces
        .iter()
        .map(|&s| delta_e00(rule.xyz_of_product(&[light, s]), reference::xyz(light, s), white))
        .fold(0.0, f64::max)
}

/// `rule`'s wavelengths with the weights of the smallest worst ΔE00 over
/// `surfaces` found in `iterations` of Lawson's iteration (`rule` itself
/// if none does better; a light the observer does not see leaves nothing
/// to solve and keeps it too). An error for no surfaces.
pub fn minimax(
    light: &dyn Spectrum,
    rule: &Rule,
    surfaces: &[&dyn Spectrum],
    iterations: usize,
) -> Result<Rule, StudyError> {
    if surfaces.is_empty() {
        return Err(StudyError::EmptyScene);
    }
    let white = reference::white(light);
    let lambda = rule.lambda().to_vec();
    let l: Vec<f64> = lambda.iter().map(|&x| light.eval(x)).collect();
    let rows: Vec<Row> = surfaces
        .iter()
        .map(|&s| {
            Row::new(
                lambda.iter().zip(&l).map(|(&x, &l)| l * s.eval(x)).collect(),
                reference::xyz(light, s),
                white,
            )
        })
        .collect();
    let anchor = Row::new(l.clone(), white, white);
    let mut best = (worst(light, rule, surfaces), rule.clone());
    let mut u = vec![1.0 / rows.len() as f64; rows.len()];
    for _ in 0..iterations {
        let Some(w) = step(&rows, &u, &anchor) else { break };
        let candidate = Rule::new(lambda.clone(), w)?;
        let errors: Vec<f64> = rows.iter().map(|r| r.delta_e(&candidate, white)).collect();
        let max = errors.iter().copied().fold(0.0, f64::max);
        if max < best.0 {
            best = (max, candidate);
        }
        if !reweight(&mut u, &errors) {
            break;
        }
    }
    Ok(best.1)
}

/// Lawson's step: `uₛ ← uₛ·eₛ / Σ u·e`, so that the weights sum to one
/// again; `false` (and `u` as it was) when `Σ u·e` is zero or not a number,
/// nothing left to reweight.
fn reweight(u: &mut [f64], errors: &[f64]) -> bool {
    let total: f64 = u.iter().zip(errors).map(|(u, e)| u * e).sum();
    if total.is_nan() || total <= 0.0 {
        return false;
    }
    u.iter_mut().zip(errors).for_each(|(u, e)| *u *= e / total);
    true
}

/// One surface: its values at the wavelengths (light included), its exact
/// XYZ, and `Jᵀ·J` of CIELAB at that colour.
struct Row {
    v: Vec<f64>,
    xyz: Xyz,
    metric: [[f64; 3]; 3],
}

impl Row {
    fn new(v: Vec<f64>, xyz: Xyz, white: Xyz) -> Row {
        let j = lab_jacobian(xyz, white);
        let metric =
            std::array::from_fn(|c| std::array::from_fn(|d| (0..3).map(|k| j[k][c] * j[k][d]).sum()));
        Row { v, xyz, metric }
    }

    fn delta_e(&self, rule: &Rule, white: Xyz) -> f64 {
        delta_e00(rule.xyz_of_values(&self.v), self.xyz, white)
    }
}

/// The weights of least `Σ uₛ·|Jₛ·(XYZₛ(w) − XYZₛ)|²` plus the white's row.
fn step(rows: &[Row], u: &[f64], anchor: &Row) -> Option<[Vec<f64>; 3]> {
    let m = anchor.v.len();
    let mut a = vec![vec![0.0; 3 * m]; 3 * m];
    let mut b = vec![0.0; 3 * m];
    for (row, &u) in rows.iter().zip(u).chain([(anchor, &WHITE)]) {
        let t = row.xyz.to_array();
        for c in 0..3 {
            let gt: f64 = (0..3).map(|d| row.metric[c][d] * t[d]).sum();
            for i in 0..m {
                b[c * m + i] += u * row.v[i] * gt;
                for d in 0..3 {
                    let g = u * row.metric[c][d] * row.v[i];
                    for k in 0..m {
                        a[c * m + i][d * m + k] += g * row.v[k];
                    }
                }
            }
        }
    }
    let x = solve(a, b)?;
    Some([0, 1, 2].map(|c| x[c * m..(c + 1) * m].to_vec()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use speclab::data::{lights, patches};
    use speclab::sampling::fitted::FittedRules;

    fn six() -> Vec<&'static dyn Spectrum> {
        patches::ALL.iter().map(|&(_, p)| p as &dyn Spectrum).collect()
    }

    /// On the surfaces it is given, Lawson's weights lower the worst error
    /// of the least-squares fit at the same wavelengths (regression
    /// snapshot of the size: more than a third lower at M = 4 and 5 under
    /// D65 and F11), keep the wavelengths, and hold the white.
    #[test]
    fn lawson_lowers_the_worst_case_on_its_own_surfaces() {
        let six = six();
        for light in [&lights::D65 as &dyn Spectrum, &lights::F11] {
            for m in [4, 5] {
                let rule = FittedRules::with_surfaces(&[light], &six).unwrap().rule(m).unwrap().clone();
                let better = minimax(light, &rule, &six, 100).unwrap();
                let (before, after) = (worst(light, &rule, &six), worst(light, &better, &six));
                assert!(before > 0.1, "{before}");
                eprintln!("M = {m}: worst ΔE00 {before:.3} -> {after:.3}");
                assert!(after < 0.66 * before, "M = {m}: {before} -> {after}");
                assert_eq!(better.lambda(), rule.lambda());
                let (white, got) = (reference::white(light), better.xyz_of_product(&[light]));
                assert!(delta_e00(got, white, white) < 0.05, "{got:?} against {white:?}");
            }
        }
        assert!(matches!(
            minimax(
                &lights::D65,
                &Rule::buckets(4, speclab::sampling::buckets::BucketRule::Center).unwrap(),
                &[],
                5
            ),
            Err(StudyError::EmptyScene)
        ));
    }

    /// Lawson's step keeps the weights a distribution, moved towards the
    /// larger errors; none when there is nothing to move.
    #[test]
    fn reweighting_moves_weight_to_the_larger_errors() {
        let mut u = vec![0.25, 0.25, 0.5];
        assert!(reweight(&mut u, &[1.0, 3.0, 2.0]));
        let total = 0.25 + 0.75 + 1.0;
        for (got, want) in u.iter().zip([0.25 / total, 0.75 / total, 1.0 / total]) {
            assert!((got - want).abs() < 1e-15, "{u:?}");
        }
        assert!((u.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        for errors in [[0.0; 3], [f64::NAN, 1.0, 1.0]] {
            let before = u.clone();
            assert!(!reweight(&mut u, &errors));
            assert_eq!(u, before);
        }
    }

    /// No step at all, or nothing to solve, keeps the rule as it was.
    #[test]
    fn no_steps_keep_the_rule() {
        let six = six();
        let rule = FittedRules::of(&lights::A).unwrap().rule(6).unwrap().clone();
        assert_eq!(minimax(&lights::A, &rule, &six, 0).unwrap(), rule);
        // A black light leaves nothing to solve: no step, the rule as it was.
        let (zero, black) = (Xyz::default(), speclab::spectrum::Constant::new(0.0));
        assert!(step(&[], &[], &Row::new(vec![0.0; 6], zero, zero)).is_none());
        assert_eq!(minimax(&black, &rule, &six, 5).unwrap(), rule);
    }
}
