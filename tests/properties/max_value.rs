//! `max_value` bounds every spectrum: never below its value at any point
//! of a 0.01 nm grid over 360–830 nm (the renderers' range); where it says it is exact (tables,
//! dense tables, constants, blackbodies, sigmoid polynomials, Cauchy and
//! Sellmeier formulas), no more than the grid's maximum plus what the grid
//! can miss between its points.

use proptest::prelude::*;
use speclab::color::{RgbAlbedo, RgbUnbounded};
use speclab::data::{conductors, glasses, lights, patches};
use speclab::spectrum::{
    Blackbody, Cauchy, Constant, DenseSpectrum, FnSpectrum, Mixture, Product, SigmoidPolynomial,
};
use speclab::{LinearRgb, Role, Spectrum, TabulatedSpectrum};

/// The grid's step, nm.
const H: f64 = 0.01;

/// The largest value on a 0.01 nm grid over 360–830 nm and at the
/// spectrum's own samples there (a table's maximum can sit at the end of
/// its support, between grid points), and what the grid can miss around
/// its largest point: a smooth maximum between grid points lies at most
/// `f''·(H/2)²/2 = |Δ²f|/8` above them.
fn grid_max(s: &dyn Spectrum) -> (f64, f64) {
    let grid: Vec<f64> = (0..=47_000).map(|i| s.eval(360.0 + f64::from(i) * H)).collect();
    let (i, top) = grid
        .iter()
        .enumerate()
        .fold((0, f64::NEG_INFINITY), |best, (i, &v)| if v > best.1 { (i, v) } else { best });
    let miss = match (i.checked_sub(1).map(|j| grid[j]), grid.get(i + 1)) {
        (Some(before), Some(after)) => (before - 2.0 * top + after).abs() / 8.0,
        _ => 0.0,
    };
    let knots = s.samples().map(|k| k.lambda.to_vec()).unwrap_or_default();
    let knots = knots.into_iter().filter(|l| (360.0..=830.0).contains(l));
    (knots.map(|l| s.eval(l)).fold(top, f64::max), miss)
}

/// A bound: at least every grid value (to rounding, 1e-14 relative: a
/// formula's maximum is computed at the same point by another route).
/// Returns how far it lies above the grid's maximum, less what the grid
/// can miss.
fn bounds(s: &dyn Spectrum) -> Result<f64, TestCaseError> {
    let (bound, (seen, miss)) = (s.max_value(), grid_max(s));
    prop_assert!(bound >= seen - 1e-14 * seen.abs(), "max_value {bound} below a grid value {seen}");
    Ok(bound - seen - miss)
}

/// Exact: a bound, and no more than what the grid can miss plus `slack`
/// (relative: rounding) above the grid's maximum.
fn exact(s: &dyn Spectrum, slack: f64) -> Result<(), TestCaseError> {
    let over = bounds(s)?;
    prop_assert!(over <= slack * s.max_value().abs().max(1e-300), "{over} over the grid's maximum");
    Ok(())
}

/// `values` spread evenly over `from`–`to` nm.
fn table(values: Vec<f64>, from: f64, to: f64, role: Role) -> TabulatedSpectrum {
    let step = (to - from) / (values.len() - 1) as f64;
    let lambda = (0..values.len()).map(|i| from + i as f64 * step).collect();
    TabulatedSpectrum::new(lambda, values, role).expect("valid samples")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Tables, lights (linear) and reflectances (cubic, overshooting their
    /// samples between them, clamped to [0, 1]), covering the range or
    /// not, and their dense forms: exact.
    #[test]
    fn tables_and_dense_tables(
        light in prop::collection::vec(0.0..100.0f64, 2..40),
        reflectance in prop::collection::vec(0.0..=1.0f64, 4..30),
        from in 300.0..500.0f64,
        to in 600.0..800.0f64,
    ) {
        let l = table(light, from, to, Role::Light);
        let r = table(reflectance, from, to, Role::Reflectance);
        exact(&l, 1e-12)?;
        exact(&r, 1e-12)?;
        exact(&DenseSpectrum::new(&l), 0.0)?;
        exact(&DenseSpectrum::new(&r), 0.0)?;
    }

    /// Constants, blackbodies (normalised and absolute) and sigmoid
    /// polynomials of any shape: exact. RGB albedos and unbounded colours
    /// are the polynomial's (scaled).
    #[test]
    fn formulas(
        value in -5.0..5.0f64,
        kelvin in 500.0..20_000.0f64,
        c in prop::array::uniform3(-300.0..300.0f64),
        rgb in prop::array::uniform3(0.0..=1.0f64),
    ) {
        exact(&Constant::new(value), 0.0)?;
        exact(&Blackbody::new(kelvin).unwrap(), 1e-12)?;
        exact(&Blackbody::absolute(kelvin).unwrap(), 1e-12)?;
        let poly = SigmoidPolynomial::new(c);
        exact(&RgbAlbedo::from_polynomial(poly), 1e-12)?;
        exact(&RgbAlbedo::new(LinearRgb::from(rgb)).unwrap(), 1e-12)?;
        exact(&RgbUnbounded::from_parts(3.0, poly), 1e-12)?;
    }

    /// Cauchy's formula, its vertex inside the range or not: exact.
    #[test]
    fn cauchy(a in 1.2..2.0f64, b in -0.02..0.02f64, c in -0.002..0.002f64) {
        if let Ok(n) = Cauchy::new(a, b, c) {
            exact(&n, 1e-12)?;
        }
    }

    /// Mixtures and products: bounds.
    #[test]
    fn sums_and_products(w in prop::array::uniform3(0.0..3.0f64)) {
        let m = Mixture::new().with(w[0], &lights::F11).unwrap().with(w[1], &lights::A).unwrap();
        let m = m.with(w[2], &patches::G4).unwrap();
        bounds(&m)?;
        bounds(&Product::new(vec![&lights::D65, &patches::J4, &m]))?;
    }
}

/// The built-in data: every light, patch, glass (exact) and metal (the
/// bound 1); a closure is bounded by nothing; a product with a negative
/// factor has no bound.
#[test]
fn built_in_spectra() {
    let check = |s: &dyn Spectrum, slack: f64| exact(s, slack).unwrap();
    for (_, l) in &lights::ALL {
        check(*l, 1e-12);
    }
    for (_, p) in &patches::ALL {
        check(*p, 1e-12);
    }
    for (_, g) in &glasses::ALL {
        check(*g, 1e-12);
    }
    for (_, c) in &conductors::ALL {
        let r = c.reflectance();
        bounds(&r).unwrap();
        assert_eq!(r.max_value(), 1.0);
    }
    let closure = FnSpectrum(|l: f64| l * 1e-3);
    assert_eq!(closure.max_value(), f64::INFINITY);
    let below = Constant::new(-1.0);
    assert_eq!(Product::new(vec![&lights::A, &below]).max_value(), f64::INFINITY);
    // The interpolant's maximum, not the samples': G4 overshoots between
    // its samples.
    let samples = patches::G4.values().iter().copied().fold(0.0, f64::max);
    assert!(patches::G4.max_value() >= samples);
}
