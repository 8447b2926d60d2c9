//! The observers' rows, integrals and tables against their definitions.

use super::*;
use crate::spectrum::data::{CIE_X_LAMBDA, CIE_Z_BREAKS, CIE_Z_COEFFS, CIE_Z_LAMBDA};

#[test]
fn fused_lookup_equals_separate_evaluation() {
    assert_eq!(CIE_X_LAMBDA, CIE_Y_LAMBDA);
    assert_eq!(CIE_Z_LAMBDA, CIE_Y_LAMBDA);
    for i in 0..=8000 {
        let lambda = 370.0 + i as f64 * 0.05;
        let separate = [X_BAR.eval(lambda), Y_BAR.eval(lambda), Z_BAR.eval(lambda)];
        assert_eq!(xyz_bar(lambda), separate, "at {lambda}");
    }
    assert_eq!(xyz_bar(f64::NAN), [0.0; 3]);
    for i in 0..=8000 {
        let lambda = 380.0 + i as f64 * 0.05;
        let (a, b) = (xyz_bar_const(lambda), xyz_bar(lambda));
        assert!(a.iter().zip(b).all(|(a, b)| (a - b).abs() <= 1e-15), "at {lambda}: {a:?} {b:?}");
    }
}

/// The row is `[x̄, ȳ, z̄, 1]`: the scalar rule's x̄, ȳ, z̄ bit for bit
/// inside the table (the fourth lane exactly 1, whatever the segment),
/// `[0, 0, 0, 1]` outside it and for NaN, for draws of one wavelength
/// and of four alike.
#[test]
fn the_row_carries_a_one_inside_and_nothing_outside() {
    for i in 0..=8000 {
        let lambda = 380.0 + i as f64 * 0.05;
        let row = xyz_bar_row(lambda).map(f64::to_bits);
        assert_eq!(row, lone_row(lambda).map(f64::to_bits), "at {lambda}");
        assert_eq!(f64::from_bits(row[3]), 1.0, "at {lambda}");
    }
    let none = [0.0, 0.0, 0.0, 1.0].map(f64::to_bits);
    for outside in [379.99, 780.01, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(xyz_bar_row(outside).map(f64::to_bits), none, "at {outside}");
        assert_eq!(lone_row(outside).map(f64::to_bits), none, "at {outside}");
        let four = AssignmentObserver.xyz_bar_at(&[outside; 4]).map(|r| r.map(f64::to_bits));
        assert_eq!(four, [none; 4], "at {outside}");
    }
}

/// `rows` (a shader's buffer) is what a wavelength's nearest
/// nanometre reads, in each precision: `[x̄, ȳ, z̄, 1]` at 360 + i nm.
#[test]
fn the_public_rows_are_what_a_sample_reads() {
    let o = DenseObserver::CIE_1931;
    for lambda in [360.0, 555.0, 700.4, 830.0] {
        let i = (lambda - 360.0f64).round() as usize;
        assert_eq!(o.rows::<f64>()[i], o.xyz_bar_at(&[lambda])[0], "{lambda}");
        assert_eq!(o.rows::<f32>()[i], o.xyz_bar_at(&[lambda as f32])[0], "{lambda}");
    }
    assert_eq!(o.rows::<f64>()[195][3], 1.0);
    assert!((o.rows::<f64>()[195][1] - 1.0).abs() < 1e-3, "ȳ(555 nm)");
}

/// The constant is the exact integral: a 0.001 nm midpoint sum of ȳ
/// agrees to 1e-9 relative (ȳ is smooth between its 5 nm knots).
#[test]
fn y_bar_integral() {
    let h = 0.001;
    let sum: f64 = (0..350_000).map(|i| xyz_bar(380.0 + (f64::from(i) + 0.5) * h)[1] * h).sum();
    assert!((sum - Y_BAR_INTEGRAL).abs() < 1e-9 * sum, "{sum} vs {Y_BAR_INTEGRAL}");
    assert!((Y_BAR_INTEGRAL - 106.0).abs() < 2.0, "{Y_BAR_INTEGRAL}");
}

/// Decision: matching functions are clamped at zero. The raw cubic of z̄
/// dips below zero between 630 and 635 nm (minimum −6.4e-6 at 632.1 nm);
/// the clamp keeps every sample's contribution physical and changes ∫z̄
/// (≈ 106.9 nm) by 2.1e-5 nm, 2e-7 of it.
#[test]
fn z_bar_dip_is_clamped_and_negligible() {
    let free = [f64::NEG_INFINITY, f64::INFINITY];
    let raw_min = (0..=4000)
        .map(|i| 380.0 + i as f64 * 0.1)
        .map(|x| interp::eval(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, free, x))
        .fold(f64::INFINITY, f64::min);
    assert!(raw_min < 0.0, "the raw cubic dips: {raw_min}");
    assert!((0..=4000).all(|i| Z_BAR.eval(380.0 + i as f64 * 0.1) >= 0.0));
    let negative_part =
        interp::integral(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, &CIE_Z_BREAKS, [f64::NEG_INFINITY, 0.0], 380.0, 780.0);
    assert!(negative_part < 0.0 && negative_part > -3e-5, "∫min(z̄, 0) = {negative_part}");
    let total = Z_BAR.integral(380.0, 780.0);
    assert!((total - 106.9).abs() < 0.5, "∫z̄ = {total}");
    eprintln!("raw z̄ minimum {raw_min:e}, ∫min(z̄, 0) = {negative_part:e} nm");
}
