//! Exact integrals against the observer: `∫ Π factors · c̄ dλ` over
//! 380–730 nm, piece by piece, for any spectra.
//!
//! The pieces are the intervals between consecutive breaks of every factor
//! that is piecewise polynomial and of x̄, ȳ, z̄ (every 5 nm): at most 5 nm
//! long. Where every factor is piecewise polynomial, the integrand is one
//! polynomial on each piece, and a Gauss–Legendre rule with enough points
//! for its degree integrates it exactly, up to rounding. A factor that is
//! not (a blackbody, a sigmoid polynomial, a closure) gets a rule
//! [`SMOOTH_EXTRA`] degrees beyond the polynomial part's: for the smooth
//! spectra of this crate that agrees with a rule of twice the points to
//! about 1e-12 relative (`tests/properties/spectra.rs`). Results are `[X, Y, Z]`
//! arrays at this floor; `sampling::reference` makes them `Xyz`.

use crate::error::Error;
use crate::spectrum::interface::Spectrum;
use crate::spectrum::observer;
use crate::spectrum::quadrature;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};
use crate::spectrum::{StandardObserver, WavelengthRange};

/// The degrees added to the rule for factors that are not piecewise
/// polynomial: on pieces of at most 5 nm, a 12-point rule for a light, a
/// smooth surface and a matching function.
pub(crate) const SMOOTH_EXTRA: usize = 16;

/// The pieces of `[a, b]`: its ends, every break of `factors` and of the
/// observer inside, sorted; and the degree of the integrand of the factors'
/// product times a matching function.
fn pieces(factors: &[&dyn Spectrum], a: f64, b: f64) -> (Vec<f64>, usize) {
    let mut points = vec![a, b];
    for s in observer::CMFS {
        points.extend(s.breaks().iter().copied().filter(|&x| x > a && x < b));
    }
    factor_pieces(factors, points, 3, a, b)
}

/// `points` with every break of `factors` inside `(a, b)`, as pieces, and
/// `degree` (the observer's) raised by the factors'.
fn factor_pieces(
    factors: &[&dyn Spectrum],
    mut points: Vec<f64>,
    mut degree: usize,
    a: f64,
    b: f64,
) -> (Vec<f64>, usize) {
    for f in factors {
        match f.pieces() {
            Some(p) => {
                points.extend(p.breaks.iter().copied().filter(|&x| x > a && x < b));
                degree += p.degree;
            }
            None => {
                points.extend(f.kinks().iter().copied().filter(|&x| x > a && x < b));
                degree += SMOOTH_EXTRA;
            }
        }
    }
    (quadrature::pieces(points.into_iter()), degree)
}

/// `[X, Y, Z]` of the product of `factors` over 380–730 nm: exact where
/// every factor is piecewise polynomial, any number of factors.
pub(crate) fn xyz_of_product(factors: &[&dyn Spectrum]) -> [f64; 3] {
    let (pieces, degree) = pieces(factors, LAMBDA_MIN, LAMBDA_MAX);
    quadrature::integrate(quadrature::for_degree(degree), &pieces, |lambda| {
        let f: f64 = factors.iter().map(|s| s.eval(lambda)).product();
        observer::xyz_bar(lambda).map(|c| c * f)
    })
}

/// `[X, Y, Z]` of the product of `factors` over `range` with `observer`
/// (within its data): exact where every factor is piecewise polynomial.
/// The CIE's 1 nm observers are lines between their nanometres (degree 1,
/// a break at each); the assignment's is its cubic.
pub(crate) fn xyz_of_product_with(
    observer: StandardObserver,
    range: WavelengthRange,
    factors: &[&dyn Spectrum],
) -> Result<[f64; 3], Error> {
    let range = observer.check(range)?;
    let (a, b) = (range.min(), range.max());
    let (pieces, degree) = match observer.table() {
        None => pieces(factors, a, b),
        Some((first, step, rows)) => {
            let knots = (0..rows.len()).map(|i| first + step * i as f64).filter(|&x| x > a && x < b);
            factor_pieces(factors, [a, b].into_iter().chain(knots).collect(), 1, a, b)
        }
    };
    Ok(quadrature::integrate(quadrature::for_degree(degree), &pieces, |lambda| {
        let f: f64 = factors.iter().map(|s| s.eval(lambda)).product();
        observer.xyz_bar(lambda).map(|c| c * f)
    }))
}

/// `[X, Y, Z]` of the perfect white (reflectance 1) under `light`:
/// `∫ L·c̄` over 380–730 nm.
pub(crate) fn white(light: &dyn Spectrum) -> [f64; 3] {
    xyz_of_product(&[light])
}

/// `∫ s` over `[a, b]` nm (zero if `b ≤ a`): exact for a piecewise
/// polynomial, by quadrature on pieces of at most 5 nm otherwise (ending on
/// the data's 5 nm grid, so a closure that computes a tabulated spectrum
/// integrates exactly).
pub(crate) fn integral(s: &dyn Spectrum, a: f64, b: f64) -> f64 {
    if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
        return 0.0;
    }
    let (points, degree) = match s.pieces() {
        Some(p) => {
            let inside = p.breaks.iter().copied().filter(|&x| x > a && x < b);
            (quadrature::pieces(inside.chain([a, b])), p.degree)
        }
        None => {
            // The data's 5 nm grid (from 380 nm), where tabulated spectra
            // change polynomial: pieces of at most 5 nm that end on it.
            let (first, last) = (((a - LAMBDA_MIN) / 5.0).floor(), ((b - LAMBDA_MIN) / 5.0).ceil());
            let count = (last - first).clamp(0.0, 1e6) as usize;
            let grid = (0..=count).map(|k| LAMBDA_MIN + 5.0 * (first + k as f64));
            let kinks = s.kinks().into_owned();
            let inside = grid.chain(kinks).filter(|&x| x > a && x < b);
            (quadrature::pieces(inside.chain([a, b])), SMOOTH_EXTRA)
        }
    };
    let [sum] = quadrature::integrate(quadrature::for_degree(degree), &points, |x| [s.eval(x)]);
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::data::{lights, patches};
    use crate::spectrum::{Blackbody, FnSpectrum, Scaled, SigmoidPolynomial, TabulatedSpectrum};

    /// With the assignment's observer over its range, the same integral;
    /// with a 1 nm observer, a constant integrates to the table's trapezoids.
    #[test]
    fn observers_and_ranges() {
        let f: [&dyn Spectrum; 2] = [&lights::F11, &patches::G4];
        let same =
            xyz_of_product_with(StandardObserver::Assignment, WavelengthRange::ASSIGNMENT, &f).unwrap();
        assert_eq!(same, xyz_of_product(&f));
        let one = crate::spectrum::Constant::new(1.0);
        for o in [StandardObserver::Cie1931, StandardObserver::Cie1964] {
            let r = WavelengthRange::new(361.25, 829.5).unwrap();
            let exact = xyz_of_product_with(o, r, &[&one]).unwrap();
            let trapezoids = o.integrals(r).unwrap();
            (0..3).for_each(|c| assert!((exact[c] - trapezoids[c]).abs() < 1e-12 * trapezoids[c], "{o:?}"));
        }
        let e =
            xyz_of_product_with(StandardObserver::Cie1931, WavelengthRange::new(300.0, 700.0).unwrap(), &f);
        assert!(matches!(e, Err(Error::RangeOutside { .. })));
    }

    /// A tint of a 1 nm table (not a polynomial, but bending only at the
    /// table's nanometres) integrates as exactly as the table alone: its
    /// kinks split the pieces. Without them the rule would straddle
    /// D65's 1 nm kinks (about 3e-9 off).
    #[test]
    fn a_tinted_illuminant_splits_at_its_tables_kinks() {
        use crate::color::RgbIlluminant;
        let tint = RgbIlluminant::from_parts(1.0, SigmoidPolynomial::new([0.0, 0.0, 0.0]), &lights::CIE_D65);
        assert_eq!(tint.kinks().len(), lights::CIE_D65.breaks().len());
        let halved = Scaled::new(&tint, 2.0);
        assert_eq!(halved.kinks(), tint.kinks());
        let product = crate::spectrum::Product::new(vec![&tint as &dyn Spectrum, &patches::G4]);
        assert!(product.kinks().len() >= tint.kinks().len());
        // A table's kinks are its breaks (the default for a piecewise polynomial).
        assert_eq!(patches::G4.kinks(), patches::G4.breaks());
        let mixture = crate::spectrum::Mixture::new().with(1.0, &tint).unwrap();
        assert_eq!(mixture.kinks(), tint.kinks());
        // The tint of a constant polynomial is half the illuminant.
        let (tinted, plain) = (white(&tint), white(&lights::CIE_D65));
        (0..3).for_each(|c| assert!((tinted[c] - 0.5 * plain[c]).abs() < 1e-13 * plain[c], "{tinted:?}"));
        let one = integral(&tint, 400.0, 700.0);
        assert!((one - 0.5 * lights::CIE_D65.integral(400.0, 700.0)).abs() < 1e-12 * one, "{one}");
    }

    /// A closure that computes a 5 nm table integrates as the table does
    /// (its pieces end on the data's 5 nm grid, from 380 nm), over ranges
    /// starting on and off the grid, past its first 5 nm and within one
    /// step, and from below 380 nm: the cubic G4, the spiky linear F11 and
    /// D50 (linear, 5 nm from 300 nm).
    #[test]
    fn a_closure_of_a_table_integrates_on_the_5_nm_grid() {
        let g4 = FnSpectrum(|lambda: f64| patches::G4.eval(lambda));
        let f11 = FnSpectrum(|lambda: f64| lights::F11.eval(lambda));
        let d50 = FnSpectrum(|lambda: f64| lights::D50.eval(lambda));
        let pairs: [(&dyn Spectrum, &TabulatedSpectrum); 3] =
            [(&g4, &patches::G4), (&f11, &lights::F11), (&d50, &lights::D50)];
        let ranges =
            [(380.0, 730.0), (383.2, 611.7), (437.5, 702.25), (402.5, 404.0), (372.5, 700.0), (322.5, 700.0)];
        for (closure, table) in pairs {
            for (a, b) in ranges {
                let (got, exact) = (integral(closure, a, b), integral(table, a, b));
                assert!((got - exact).abs() <= 1e-12 * exact.abs(), "[{a}, {b}]: {got} vs {exact}");
            }
        }
    }

    /// The documented accuracy of quadrature for smooth spectra: the rule
    /// used agrees with one of twice the points to 1e-12 relative.
    #[test]
    fn smooth_spectra_agree_with_twice_the_points() {
        let sun = Blackbody::new(3000.0).unwrap();
        let poly = SigmoidPolynomial::new([-40.0, 60.0, -18.0]);
        let steep = FnSpectrum(|lambda: f64| poly.eval(lambda)); // an RGB albedo's shape
        let cases: [[&dyn Spectrum; 2]; 3] = [[&sun, &patches::G4], [&lights::F11, &steep], [&sun, &steep]];
        for factors in cases {
            let (points, degree) = pieces(&factors, LAMBDA_MIN, LAMBDA_MAX);
            let f = |lambda: f64| {
                let v: f64 = factors.iter().map(|s| s.eval(lambda)).product();
                observer::xyz_bar(lambda).map(|c| c * v)
            };
            let used = quadrature::integrate(quadrature::for_degree(degree), &points, f);
            let finer = quadrature::integrate(quadrature::gauss(2 * (degree / 2 + 1)), &points, f);
            for (a, b) in used.iter().zip(finer) {
                assert!((a - b).abs() <= 1e-12 * b.abs(), "{a} vs {b}");
            }
        }
    }
}
