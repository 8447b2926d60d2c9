//! Unit tests of `tabulated.rs`: the fast path is the reference interpolant,
//! the search path for uneven tables, and the cumulative integral.

use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};

use super::*;
use crate::spectrum::data::cie1931::{X_BAR, Y_BAR, Z_BAR};
use crate::spectrum::data::lights::{A, D65, F11};
use crate::spectrum::data::patches::{A1, E2, F4, G4, H4, J4};

/// The fast path (O(1) segment, branch-free) against the reference
/// interpolant's definition (binary search, clamp), at 10⁵ random
/// wavelengths from 370 to 790 nm per spectrum: within 1e-12 relative.
fn agrees_with_reference(s: &TabulatedSpectrum, seed: u64) -> f64 {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut worst = 0.0f64;
    for _ in 0..100_000 {
        let l = 370.0 + 420.0 * rng.random::<f64>();
        let (fast, reference) = (s.eval(l), interp::eval(&s.lambda, &s.coeffs, s.bounds, l));
        let gap = (fast - reference).abs();
        assert!(gap <= 1e-12 * reference.abs(), "at {l}: {fast} vs {reference}");
        worst = worst.max(gap / reference.abs().max(f64::MIN_POSITIVE));
    }
    worst
}

#[test]
fn fast_path_is_the_reference_interpolant() {
    for (i, s) in
        [&A, &D65, &F11, &E2, &F4, &G4, &H4, &J4, &A1, &X_BAR, &Y_BAR, &Z_BAR].into_iter().enumerate()
    {
        assert!(s.lookup.is_some(), "built-in tables are equidistant");
        agrees_with_reference(s, i as u64);
    }
}

#[test]
fn non_uniform_spectrum_takes_the_search() {
    let lambda = vec![380.0, 390.0, 415.0, 470.0, 555.0, 600.0, 610.0, 690.0, 730.0];
    let values = vec![0.1, 0.3, 0.2, 0.9, 0.99, 0.4, 0.05, 0.5, 0.7];
    let s = TabulatedSpectrum::new(lambda, values, Role::Reflectance).expect("valid");
    assert!(s.lookup.is_none());
    agrees_with_reference(&s, 99);
    assert_eq!(s.eval(f64::NAN), 0.0);
    assert_eq!(s.eval(379.999), 0.0);
    assert!((s.eval(730.0) - 0.7).abs() < 1e-15, "the cubic at its last knot, to rounding");
}

/// The cumulative integral (prefix + primitive) equals direct exact
/// integration, on clean and clamped segments alike.
#[test]
fn cumulative_is_the_exact_integral() {
    let overshooting = TabulatedSpectrum::new(
        (0..36).map(|i| 380.0 + 10.0 * f64::from(i)).collect(),
        (0..36).map(|i| if i % 3 == 0 { 1.0 } else { 0.02 }).collect(),
        Role::Reflectance,
    )
    .expect("valid");
    assert!(overshooting.clean.contains(&false), "the clamp acts somewhere");
    for s in [&F11, &G4, &Z_BAR, &overshooting] {
        for i in 0..=700 {
            let x = 375.0 + 0.5 * f64::from(i);
            let direct = interp::integral(&s.lambda, &s.coeffs, &s.breaks, s.bounds, s.ends[0], x);
            let fast = s.cumulative(x);
            assert!((fast - direct).abs() <= 1e-12 * direct.abs().max(1.0), "at {x}: {fast} vs {direct}");
        }
    }
}

/// Four lanes at once give the bits of one lane at a time, on linear,
/// cubic and clamped tables, inside and outside the support, at the knots
/// and for the values that are not numbers.
#[test]
fn four_lanes_are_one_lane_four_times() {
    let mut rng = StdRng::seed_from_u64(31);
    let odd = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 379.999, 380.0, 730.0, 780.0, 1e300];
    for s in [&A, &F11, &E2, &G4, &X_BAR, &Z_BAR] {
        let lookup = s.lookup.expect("equidistant");
        for i in 0..20_000 {
            let lambda: [f64; 4] = std::array::from_fn(|j| match (i + j) % 9 {
                8 => odd[(i / 9 + j) % odd.len()],
                7 => 380.0 + 5.0 * ((i + 3 * j) % 81) as f64,
                _ => 360.0 + 440.0 * rng.random::<f64>(),
            });
            let four = s.eval4(lookup, &lambda).map(f64::to_bits);
            let one = lambda.map(|l| s.eval_at(lookup, l).to_bits());
            assert_eq!(four, one, "{lambda:?}");
        }
    }
}

/// Many wavelengths at once (`eval_many`) give each wavelength's own value,
/// bit for bit, for every count up to 13 (whole vectors of four and the
/// one-lane tail), and fill only as many values as the shorter slice has.
#[test]
fn many_at_once_are_each_alone() {
    let lambda: Vec<f64> = (0..13).map(|i| 372.5 + 31.0 * f64::from(i)).collect();
    for s in [&F11, &G4, &Y_BAR] {
        for n in 0..=lambda.len() {
            let mut values = vec![-1.0; n + 2];
            s.eval_many(&lambda[..n], &mut values);
            let alone: Vec<u64> = lambda[..n].iter().map(|&l| s.eval(l).to_bits()).collect();
            assert_eq!(values[..n].iter().map(|v| v.to_bits()).collect::<Vec<_>>(), alone, "{n}");
            assert_eq!(values[n..], [-1.0, -1.0], "{n}: only {n} values written");
            let mut short = vec![-1.0; n / 2];
            s.eval_many(&lambda[..n], &mut short);
            assert_eq!(short.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), alone[..n / 2], "{n}");
        }
    }
}

/// A spectrum built in code takes the policies a loaded file has: zero
/// outside (itself), its ends held to 360–830 nm, or refused short of
/// 380–730 nm.
#[test]
fn extension_policies() {
    use speclab_tables::read::Extend;
    let s = TabulatedSpectrum::new(vec![400.0, 410.0, 700.0], vec![2.0, 3.0, 8.0], Role::Light).unwrap();
    assert_eq!(s.extended(Extend::Zero).unwrap(), s);
    let held = s.extended(Extend::Hold).unwrap();
    assert_eq!(held.support(), (360.0, 830.0));
    assert_eq!(
        (held.eval(360.0), held.eval(399.0), held.eval(829.0), held.eval(500.0)),
        (2.0, 2.0, 8.0, s.eval(500.0))
    );
    assert!(matches!(
        s.extended(Extend::Refuse),
        Err(Error::RangeOutside { range: [380.0, 730.0], data: [400.0, 700.0], .. })
    ));
    let wide = TabulatedSpectrum::new(vec![380.0, 730.0], vec![1.0, 1.0], Role::Light).unwrap();
    assert_eq!(wide.extended(Extend::Refuse).unwrap(), wide);
    let short_top = TabulatedSpectrum::new(vec![380.0, 729.0], vec![1.0, 1.0], Role::Light).unwrap();
    assert!(short_top.extended(Extend::Refuse).is_err());
}
