//! Gauss–Legendre quadrature over pieces, the one rule behind every exact
//! integral of a product (the reference, the weights, the exact variances).
//!
//! Between two consecutive *breaks* (sample wavelengths of every factor,
//! plus the points where an interpolant meets its clamp bound) each factor
//! is one polynomial, so a product of factors is a polynomial too, and an
//! n-point rule (exact to degree 2n − 1) integrates it exactly up to
//! rounding: [`for_degree`] picks the smallest such rule.
//!
//! The rules are computed once, on first use, by Newton's method on the
//! Legendre polynomials (nodes to full precision, checked against the
//! published 5- and 8-point tables in the tests).

use std::sync::OnceLock;

/// A rule on `[-1, 1]`: (node, weight) pairs.
pub(crate) type GaussRule = [(f64, f64)];

/// The most points a rule has: exact to degree 63.
pub(crate) const MAX_POINTS: usize = 32;

/// The `n`-point Gauss–Legendre rule (`1 ≤ n ≤` [`MAX_POINTS`]; other `n`
/// are clamped into that range).
pub(crate) fn gauss(n: usize) -> &'static GaussRule {
    static RULES: OnceLock<Vec<Vec<(f64, f64)>>> = OnceLock::new();
    let rules = RULES.get_or_init(|| (1..=MAX_POINTS).map(legendre_rule).collect());
    &rules[n.clamp(1, MAX_POINTS) - 1]
}

/// The smallest rule exact for polynomials of `degree` (2n − 1 ≥ degree).
pub(crate) fn for_degree(degree: usize) -> &'static GaussRule {
    gauss(degree / 2 + 1)
}

/// Nodes and weights of the n-point rule: the roots of Pₙ by Newton's
/// method from Tricomi's guess, weights `2 / ((1 − x²)·Pₙ'(x)²)`.
fn legendre_rule(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            for _ in 0..100 {
                let (p, dp) = legendre(n, x);
                let step = p / dp;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            let (_, dp) = legendre(n, x);
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// `Pₙ(x)` and `Pₙ'(x)` by the three-term recurrence.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 2..=n {
        let k = k as f64;
        (p0, p1) = (p1, ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k);
    }
    if n == 0 {
        return (1.0, 0.0);
    }
    (p1, n as f64 * (x * p1 - p0) / (x * x - 1.0))
}

/// `∫ f` over `[pieces[0], pieces[last]]`, the rule applied to each piece
/// between consecutive points; `f` has `D` components.
pub(crate) fn integrate<const D: usize>(
    rule: &GaussRule,
    pieces: &[f64],
    mut f: impl FnMut(f64) -> [f64; D],
) -> [f64; D] {
    let mut sum = [0.0; D];
    for w in pieces.windows(2) {
        let (mid, half) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
        for &(node, weight) in rule {
            let v = f(mid + half * node);
            for (s, v) in sum.iter_mut().zip(v) {
                *s += v * (weight * half);
            }
        }
    }
    sum
}

/// `points` sorted, without repeats: the ends of the pieces to integrate.
pub(crate) fn pieces(points: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = points.collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every rule integrates x^d exactly on [0, 2] for every degree it
    /// claims; for the next degree its relative error is the textbook
    /// `(n!)⁴/((2n)!)² = 1/C(2n, n)²` (while that is above rounding).
    #[test]
    fn rules_are_exact_to_their_degree() {
        for n in 1..=MAX_POINTS {
            let rule = gauss(n);
            assert_eq!(rule.len(), n);
            for d in 0..2 * n as i32 {
                let [got] = integrate(rule, &[0.0, 0.5, 2.0], |x| [x.powi(d)]);
                let want = 2f64.powi(d + 1) / f64::from(d + 1);
                assert!((got - want).abs() < 1e-12 * want, "n = {n}, degree {d}: {got} vs {want}");
            }
            if n <= 6 {
                let [over] = integrate(rule, &[0.0, 2.0], |x| [x.powi(2 * n as i32)]);
                let want = 2f64.powi(2 * n as i32 + 1) / (2 * n + 1) as f64;
                let binomial = (1..=n).fold(1.0, |c, i| c * (n + i) as f64 / i as f64);
                let relative = (want - over) / want;
                let theory = 1.0 / (binomial * binomial);
                assert!((relative / theory - 1.0).abs() < 1e-6, "n = {n}: {relative:e} vs {theory:e}");
            }
        }
        assert_eq!(for_degree(9).len(), 5);
        assert_eq!(for_degree(10).len(), 6);
        assert_eq!(gauss(0).len(), 1);
        assert_eq!(gauss(1000).len(), MAX_POINTS);
    }

    /// Published truth: the 5- and 8-point tables (Abramowitz and Stegun,
    /// table 25.4), to the 16 digits printed.
    #[test]
    fn published_nodes_and_weights() {
        let five = [
            (0.0, 0.568_888_888_888_888_9),
            (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
            (0.906_179_845_938_664, 0.236_926_885_056_189_1),
        ];
        let eight = [
            (0.183_434_642_495_649_8, 0.362_683_783_378_362),
            (0.525_532_409_916_329, 0.313_706_645_877_887_3),
            (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
            (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
        ];
        for (n, table) in [(5, &five[..]), (8, &eight[..])] {
            for &(x, w) in table {
                let found = gauss(n).iter().find(|(node, _)| (node.abs() - x).abs() < 1e-15);
                let (_, weight) = found.unwrap_or_else(|| panic!("n = {n}: no node ±{x}"));
                assert!((weight - w).abs() < 1e-15, "n = {n}, node {x}: {weight} vs {w}");
            }
        }
    }

    #[test]
    fn pieces_are_sorted_and_unique() {
        assert_eq!(pieces([3.0, 1.0, 3.0, 2.0].into_iter()), vec![1.0, 2.0, 3.0]);
    }
}
