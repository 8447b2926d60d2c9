//! The CIE 1931 2° standard observer: x̄, ȳ, z̄ at any wavelength.
//!
//! The matching functions are the 5 nm table of Appendix 1, part C,
//! interpolated by the four-point cubic and clamped at zero (the raw cubic
//! of z̄ dips to −6.4e-6 at 632.1 nm, where z̄ reaches zero; a matching
//! function is never negative, and the clamp keeps every sample's Y
//! non-negative).
//!
//! Values are plain `[x̄, ȳ, z̄]` arrays at this floor; `speclab::Xyz`
//! (one floor up, in `color`) takes them with `Xyz::from`.
//!
//! ```
//! let [x, y, z] = speclab::spectrum::observer::xyz_bar(555.0);
//! assert_eq!(y, 1.0);
//! assert!(x > 0.5 && z < 0.01);
//! ```

use crate::spectrum::data::cie1931::{X_BAR, Y_BAR, Z_BAR};
use crate::spectrum::data::{CIE_X_COEFFS, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_COEFFS};
use crate::spectrum::interp;
use crate::spectrum::lookup::UniformLookup;
use crate::spectrum::piecewise::View;
use crate::spectrum::tabulated::TabulatedSpectrum;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};

/// `∫ ȳ dλ` over 380–730 nm, in nm: the Y of a spectrum that is 1
/// everywhere (the 5 nm table of Appendix 1, interpolated by the clamped
/// cubic as everywhere here; computed at compile time). Dividing a Y by it
/// gives the luminance in the units of the spectrum's values. It differs
/// from pbrt-v4's 106.856895 and Mitsuba's 106.7502594, which integrate
/// other tables over 360–830 nm.
pub const Y_BAR_INTEGRAL: f64 = interp::integral(
    &CIE_Y_LAMBDA,
    &CIE_Y_COEFFS,
    &CIE_Y_BREAKS,
    [0.0, f64::INFINITY],
    LAMBDA_MIN,
    LAMBDA_MAX,
);

/// x̄, ȳ and z̄ as spectra, in that order.
pub static CMFS: [&TabulatedSpectrum; 3] = [&X_BAR, &Y_BAR, &Z_BAR];

/// x̄, ȳ and z̄'s tables, for exact integration.
pub(crate) fn views() -> [View<'static>; 3] {
    CMFS.map(|s| s.view())
}

/// One row per 5 nm segment: the coefficients of x̄, ȳ and z̄ together
/// (`[x0..x3, y0..y3, z0..z3]`, in `t = λ − λₖ`), so that one lookup serves
/// all three. 80 rows of 96 bytes.
pub(crate) const ROWS: [[f64; 12]; SEGMENTS] = rows();

const SEGMENTS: usize = CIE_Y_LAMBDA.len() - 1;

const fn rows() -> [[f64; 12]; SEGMENTS] {
    let mut out = [[0.0; 12]; SEGMENTS];
    let mut k = 0;
    while k < SEGMENTS {
        let mut i = 0;
        while i < 4 {
            out[k][i] = CIE_X_COEFFS[k][i];
            out[k][4 + i] = CIE_Y_COEFFS[k][i];
            out[k][8 + i] = CIE_Z_COEFFS[k][i];
            i += 1;
        }
        k += 1;
    }
    out
}

/// Colour matching functions x̄, ȳ, z̄ at K wavelengths at once: the exact
/// interpolated CIE 1931 observer, [`Cie1931`], or a dense table
/// (`DenseObserver`). `HeroSample::to_xyz_with` converts with either.
pub trait Observer {
    /// `[x̄, ȳ, z̄]` at each wavelength, nm.
    fn xyz_bar_lanes<const K: usize>(&self, lambda: &[f64; K]) -> [[f64; 3]; K];
}

/// The CIE 1931 2° observer of Appendix 1, interpolated by the clamped
/// cubic: the exact one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Cie1931;

impl Observer for Cie1931 {
    #[inline(always)]
    fn xyz_bar_lanes<const K: usize>(&self, lambda: &[f64; K]) -> [[f64; 3]; K] {
        xyz_bar_lanes(lambda)
    }
}

/// `[x̄, ȳ, z̄]` at `lambda` nm; zero outside 380–780 nm.
///
/// The three tables share one wavelength grid (checked in the tests), so the
/// segment is found once for all three, in one multiplication, and its row
/// holds all twelve coefficients.
#[inline(always)]
#[must_use]
pub fn xyz_bar(lambda: f64) -> [f64; 3] {
    xyz_bar_lanes(&[lambda])[0]
}

/// [`xyz_bar`] at K wavelengths.
#[inline(always)]
pub(crate) fn xyz_bar_lanes<const K: usize>(lambda: &[f64; K]) -> [[f64; 3]; K] {
    const FIRST: f64 = CIE_Y_LAMBDA[0];
    const LAST: f64 = CIE_Y_LAMBDA[SEGMENTS];
    let mut out = [[0.0; 3]; K];
    for (out, &l) in out.iter_mut().zip(lambda) {
        let k = LOOKUP.segment(l);
        // SAFETY: LOOKUP has SEGMENTS segments, one per row of ROWS, and one
        // fewer than the knots of CIE_Y_LAMBDA; segment() is below that.
        let (r, knot) = unsafe { (ROWS.get_unchecked(k), *CIE_Y_LAMBDA.get_unchecked(k)) };
        let t = l - knot;
        let at = |i: usize| {
            let p = interp::segment_value([r[i], r[i + 1], r[i + 2], r[i + 3]], t);
            if p > 0.0 { p } else { 0.0 }
        };
        // FIRST ≤ λ ≤ LAST in one comparison (NaN compares false).
        let inside = (l - FIRST) * (LAST - l) >= 0.0;
        *out = if inside { [at(0), at(4), at(8)] } else { [0.0; 3] };
    }
    out
}

/// ȳ alone at K wavelengths (the luminance weight): one 32-byte row of
/// ȳ's coefficients per wavelength, the same values as [`xyz_bar_lanes`]'s
/// middle column.
#[inline(always)]
pub(crate) fn y_bar_lanes<const K: usize>(lambda: &[f64; K]) -> [f64; K] {
    const FIRST: f64 = CIE_Y_LAMBDA[0];
    const LAST: f64 = CIE_Y_LAMBDA[SEGMENTS];
    let mut out = [0.0; K];
    for (out, &l) in out.iter_mut().zip(lambda) {
        let k = LOOKUP.segment(l);
        // SAFETY: as in `xyz_bar_lanes`: k < SEGMENTS = CIE_Y_COEFFS.len().
        let (c, knot) = unsafe { (*CIE_Y_COEFFS.get_unchecked(k), *CIE_Y_LAMBDA.get_unchecked(k)) };
        let p = interp::segment_value(c, l - knot);
        let p = if p > 0.0 { p } else { 0.0 };
        *out = if (l - FIRST) * (LAST - l) >= 0.0 { p } else { 0.0 };
    }
    out
}

/// The observer's 5 nm grid.
const LOOKUP: UniformLookup = match UniformLookup::of(&CIE_Y_LAMBDA) {
    Some(g) if g.segments() == SEGMENTS => g,
    _ => panic!("the CIE tables are equidistant"),
};

#[cfg(test)]
mod tests {
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
            let lambda = [370.0 + i as f64 * 0.05];
            assert_eq!(y_bar_lanes(&lambda)[0], xyz_bar(lambda[0])[1], "at {lambda:?}");
        }
        assert_eq!(y_bar_lanes(&[f64::NAN, 379.9, 780.1]), [0.0; 3]);
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
        let negative_part = interp::integral(
            &CIE_Z_LAMBDA,
            &CIE_Z_COEFFS,
            &CIE_Z_BREAKS,
            [f64::NEG_INFINITY, 0.0],
            380.0,
            780.0,
        );
        assert!(negative_part < 0.0 && negative_part > -3e-5, "∫min(z̄, 0) = {negative_part}");
        let total = Z_BAR.integral(380.0, 780.0);
        assert!((total - 106.9).abs() < 0.5, "∫z̄ = {total}");
        eprintln!("raw z̄ minimum {raw_min:e}, ∫min(z̄, 0) = {negative_part:e} nm");
    }
}
