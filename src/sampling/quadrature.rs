//! Gauss–Legendre quadrature over pieces, the one rule behind every exact
//! integral of a product (the reference, the exact variances).
//!
//! Between two consecutive *breaks* (sample wavelengths of every factor,
//! plus the points where an interpolant meets its clamp bound) each factor
//! is one polynomial of degree ≤ 3, so a product of a few factors is a
//! polynomial too, and an n-point rule (exact to degree 2n − 1) integrates
//! it exactly up to rounding.
//!
//! This file depends on `std` only: `build.rs` includes it to compute the
//! built-in lights' reference weights.

/// A rule on `[-1, 1]`: (node, weight) pairs.
pub(crate) type Rule<const N: usize> = [(f64, f64); N];

/// 5 points, exact to degree 9: light × reflectance × matching function.
pub(crate) const GAUSS_5: Rule<5> = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// 8 points, exact to degree 15: squares of such products (variances).
#[allow(dead_code)] // used by the study, not by build.rs
pub(crate) const GAUSS_8: Rule<8> = [
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// `∫ f` over `[pieces[0], pieces[last]]`, the rule applied to each piece
/// between consecutive points; `f` has `D` components.
pub(crate) fn integrate<const N: usize, const D: usize>(
    rule: &Rule<N>,
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

    /// Both rules integrate x^d exactly on [0, 2] for every degree they claim.
    fn exact_to<const N: usize>(rule: &Rule<N>) {
        for d in 0..2 * N as i32 {
            let [got] = integrate(rule, &[0.0, 0.5, 2.0], |x| [x.powi(d)]);
            let want = 2f64.powi(d + 1) / f64::from(d + 1);
            assert!((got - want).abs() < 1e-13 * want, "degree {d}: {got} vs {want}");
        }
        let [over] = integrate(rule, &[0.0, 2.0], |x| [x.powi(2 * N as i32)]);
        let want = 2f64.powi(2 * N as i32 + 1) / (2 * N + 1) as f64;
        assert!((over - want).abs() > 1e-9 * want, "degree {} should not be exact", 2 * N);
    }

    #[test]
    fn rules_are_exact_to_their_degree() {
        exact_to(&GAUSS_5);
        exact_to(&GAUSS_8);
    }

    #[test]
    fn pieces_are_sorted_and_unique() {
        assert_eq!(pieces([3.0, 1.0, 3.0, 2.0].into_iter()), vec![1.0, 2.0, 3.0]);
    }
}
