//! Unit tests of the interpolation kernels: exactness on cubics, the clamp's
//! roots, the guards, the uniform fast path and the prefix integrals.

use speclab_tables::interp::*;

#[test]
fn cubic_reproduces_cubics_exactly() {
    let f = |x: f64| 2.0 - 0.5 * x + 0.01 * x * x - 1e-4 * x * x * x;
    let lambda = [0.0, 3.0, 7.0, 10.0, 12.0, 20.0];
    let values = lambda.map(f);
    let coeffs = cubic_coeffs(&lambda, &values);
    let free = [f64::NEG_INFINITY, f64::INFINITY];
    for i in 0..=200 {
        let x = i as f64 * 0.1;
        assert!((eval(&lambda, &coeffs, free, x) - f(x)).abs() < 1e-12, "at {x}");
    }
}

#[test]
fn integral_is_exact_for_cubics() {
    let lambda = [0.0, 1.0, 2.0, 3.0];
    let coeffs = cubic_coeffs(&lambda, &[0.0, 1.0, 8.0, 27.0]); // x³
    let free = [f64::NEG_INFINITY, f64::INFINITY];
    let brk = breaks(&lambda, &coeffs, free);
    assert!(
        (integral(&lambda, &coeffs, &brk, free, 0.5, 2.5) - (2.5f64.powi(4) - 0.5f64.powi(4)) / 4.0).abs()
            < 1e-12
    );
}

#[test]
fn roots_split_clamped_pieces() {
    // Cubic through 0, 1, 1, 0 on 0..30 exceeds 1 on the middle segment.
    let lambda = [0.0, 10.0, 20.0, 30.0];
    let coeffs = cubic_coeffs(&lambda, &[0.0, 1.0, 1.0, 0.0]);
    let brk = breaks(&lambda, &coeffs, [0.0, 1.0]);
    assert_eq!(brk, vec![0.0, 10.0, 20.0, 30.0], "crossings at the knots only");
    let coeffs = cubic_coeffs(&lambda, &[0.0, 0.9, 0.95, 0.0]);
    assert_eq!(breaks(&lambda, &coeffs, [0.0, 1.0]).len(), 6, "two crossings of 1 inside");
}

/// A quadratic segment (c₃ = 0, c₂ ≠ 0): its one critical point splits
/// it, and bisection finds both crossings to full precision.
/// p(t) = t − 0.1·t² meets 2 at t = 5 ± √5.
#[test]
fn roots_of_a_quadratic_segment() {
    let (roots, count) = roots_in([0.0, 1.0, -0.1, 0.0], 2.0, 10.0);
    let want = [5.0 - 5f64.sqrt(), 5.0 + 5f64.sqrt()];
    assert_eq!(count, 2, "{roots:?}");
    for (r, w) in roots.iter().zip(want) {
        assert!((r - w).abs() < 1e-12, "{r} vs {w}");
    }
    // A line has no critical point: one crossing, found by bisection.
    let (line, count) = roots_in([0.0, 0.5, 0.0, 0.0], 1.0, 10.0);
    assert_eq!(count, 1);
    assert!((line[0] - 2.0).abs() < 1e-12, "{line:?}");
    // Touching the level only at an end is not a crossing inside.
    assert_eq!(roots_in([0.0, 0.1, 0.0, 0.0], 1.0, 10.0).1, 0);
    // A cubic crossing a level three times: (t − 1)(t − 2)(t − 3) = 0 on (0, 4).
    let (three, count) = roots_in([-6.0, 11.0, -6.0, 1.0], 0.0, 4.0);
    assert_eq!(count, 3);
    for (r, w) in three.iter().zip([1.0, 2.0, 3.0]) {
        assert!((r - w).abs() < 1e-12, "{three:?}");
    }
}

/// Outside the table, at NaN and for inconsistent tables, the clamped
/// interpolant is 0 and integrals are 0, even where the end polynomials
/// would extrapolate to something else.
#[test]
fn guards_of_eval_and_integral() {
    let lambda = [400.0, 410.0, 420.0, 430.0];
    let coeffs = cubic_coeffs(&lambda, &[1.0, 2.0, 3.0, 4.0]);
    let free = [f64::NEG_INFINITY, f64::INFINITY];
    let brk = breaks(&lambda, &coeffs, free);
    assert_eq!(eval(&lambda, &coeffs, free, 400.0), 1.0);
    assert_eq!(eval(&lambda, &coeffs, free, 430.0), 4.0);
    for x in [399.0, 431.0, f64::NAN, f64::NEG_INFINITY, f64::INFINITY] {
        assert_eq!(eval(&lambda, &coeffs, free, x), 0.0, "at {x}");
    }
    assert_eq!(eval(&lambda[..3], &coeffs, free, 405.0), 0.0, "coefficients do not fit the table");
    assert_eq!(eval(&lambda[..1], &coeffs[..0], free, 400.0), 0.0, "one sample is no table");
    assert!((integral(&lambda, &coeffs, &brk, free, 400.0, 430.0) - 75.0).abs() < 1e-12);
    assert_eq!(integral(&lambda, &coeffs, &brk, free, 420.0, 410.0), 0.0, "reversed");
    assert_eq!(integral(&lambda, &coeffs, &brk, free, 410.0, 410.0), 0.0, "empty");
    assert_eq!(integral(&lambda, &coeffs, &brk, free, f64::NAN, 410.0), 0.0);
    assert_eq!(integral(&lambda, &coeffs, &brk, free, 400.0, f64::NAN), 0.0);
    assert_eq!(integral(&lambda[..3], &coeffs, &brk, free, 400.0, 430.0), 0.0, "inconsistent");
    // Beyond the table the integral counts nothing.
    assert!((integral(&lambda, &coeffs, &brk, free, 300.0, 500.0) - 75.0).abs() < 1e-12);
}

#[test]
fn uniform_step_is_detected() {
    assert_eq!(uniform_inv_step(&[400.0, 410.0, 420.0]), 0.1);
    assert_eq!(uniform_inv_step(&[400.0, 410.0, 421.0]), 0.0);
    assert_eq!(uniform_inv_step(&[400.0]), 0.0);
}

/// The prefix integrals equal the direct integrals, and a segment is
/// clean exactly when no clamp acts on it.
#[test]
fn prefix_and_clean() {
    let lambda = [0.0, 10.0, 20.0, 30.0, 40.0];
    let coeffs = cubic_coeffs(&lambda, &[0.0, 0.9, 0.95, 0.0, 0.5]);
    let bounds = [0.0, 1.0];
    let brk = breaks(&lambda, &coeffs, bounds);
    let p = prefix(&lambda, &coeffs, &brk, bounds);
    for k in 0..lambda.len() {
        let direct = integral(&lambda, &coeffs, &brk, bounds, 0.0, lambda[k]);
        assert!((p[k] - direct).abs() < 1e-12, "{k}: {} vs {direct}", p[k]);
    }
    // Independently: a segment is clean when its raw polynomial stays in
    // the bounds at 1001 points.
    let by_sampling: Vec<bool> = (0..4)
        .map(|k| (0..=1000).all(|i| (0.0..=1.0).contains(&segment_value(coeffs[k], f64::from(i) * 0.01))))
        .collect();
    assert_eq!(clean(&lambda, &coeffs, &brk, bounds), by_sampling);
    assert!(by_sampling.contains(&true) && by_sampling.contains(&false), "{by_sampling:?}");
    // A segment wholly above the bound has no crossing inside, and is not clean.
    let high = [[2.0, 0.0, 0.0, 0.0]];
    assert_eq!(clean(&[0.0, 1.0], &high, &[0.0, 1.0], bounds), [false]);
    assert_eq!(prefix(&[0.0, 1.0], &high, &[0.0, 1.0], bounds), [0.0, 1.0]);
}

proptest::proptest! {
    /// Raw helpers accept mismatched and non-finite slices without panicking.
    #[test]
    fn raw_helpers_take_anything(
        lambda in proptest::collection::vec(proptest::num::f64::ANY, 0..12),
        values in proptest::collection::vec(proptest::num::f64::ANY, 0..12),
    ) {
        let coeffs = cubic_coeffs(&lambda, &values);
        let linear = linear_coeffs(&lambda, &values);
        let brk = breaks(&lambda, &coeffs, [0.0, 1.0]);
        let _ = breaks(&lambda, &linear, [f64::NEG_INFINITY, f64::INFINITY]);
        for x in [f64::NAN, 400.0, -1.0] {
            let _ = eval(&lambda, &coeffs, [0.0, 1.0], x);
            let _ = integral(&lambda, &coeffs, &brk, [0.0, 1.0], x, 500.0);
        }
        let _ = segment_of(&lambda, 500.0);
        let _ = uniform_inv_step(&lambda);
    }
}
