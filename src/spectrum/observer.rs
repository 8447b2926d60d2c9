//! The CIE 1931 2° standard observer: x̄, ȳ, z̄ at any wavelength.
//!
//! The matching functions are the 5 nm table of Appendix 1, part C,
//! interpolated by the four-point cubic and clamped at zero (the raw cubic
//! of z̄ dips to −6.4e-6 at 632.1 nm, where z̄ reaches zero; a matching
//! function is never negative, and the clamp keeps every sample's Y
//! non-negative).
//!
//! ```
//! let cmf = speclab::spectrum::observer::xyz_bar(555.0);
//! assert_eq!(cmf.y, 1.0);
//! ```

use crate::spectrum::data::{CIE_X, CIE_X_COEFFS, CIE_Y, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z, CIE_Z_COEFFS};
use crate::{TabulatedSpectrum, Xyz};

/// x̄, ȳ and z̄ as spectra, in that order.
pub static CMFS: [&TabulatedSpectrum; 3] = [&CIE_X, &CIE_Y, &CIE_Z];

/// x̄, ȳ and z̄'s tables, for exact integration.
pub(crate) fn views() -> [View<'static>; 3] {
    CMFS.map(|s| s.view())
}
use crate::sampling::weights::View;
use crate::spectrum::grid::Grid;
use crate::spectrum::interp;

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

/// `(x̄, ȳ, z̄)` at `lambda` nm; zero outside 380–780 nm.
///
/// The three tables share one wavelength grid (checked in the tests), so the
/// segment is found once for all three, in one multiplication, and its row
/// holds all twelve coefficients.
#[inline(always)]
#[must_use]
pub fn xyz_bar(lambda: f64) -> Xyz {
    xyz_bar_lanes(&[lambda])[0]
}

/// [`xyz_bar`] at K wavelengths.
#[inline(always)]
pub(crate) fn xyz_bar_lanes<const K: usize>(lambda: &[f64; K]) -> [Xyz; K] {
    const FIRST: f64 = CIE_Y_LAMBDA[0];
    const LAST: f64 = CIE_Y_LAMBDA[SEGMENTS];
    let mut out = [Xyz::ZERO; K];
    for (out, &l) in out.iter_mut().zip(lambda) {
        let k = GRID.segment(l);
        // SAFETY: GRID has SEGMENTS segments, one per row of ROWS, and one
        // fewer than the knots of CIE_Y_LAMBDA; segment() is below that.
        let (r, knot) = unsafe { (ROWS.get_unchecked(k), *CIE_Y_LAMBDA.get_unchecked(k)) };
        let t = l - knot;
        let at = |i: usize| {
            let p = interp::segment_value([r[i], r[i + 1], r[i + 2], r[i + 3]], t);
            if p > 0.0 { p } else { 0.0 }
        };
        // FIRST ≤ λ ≤ LAST in one comparison (NaN compares false).
        let inside = (l - FIRST) * (LAST - l) >= 0.0;
        *out = if inside { Xyz::new(at(0), at(4), at(8)) } else { Xyz::ZERO };
    }
    out
}

/// The observer's 5 nm grid.
const GRID: Grid = match Grid::of(&CIE_Y_LAMBDA) {
    Some(g) if g.segments() == SEGMENTS => g,
    _ => panic!("the CIE tables are equidistant"),
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::data::{CIE_X_LAMBDA, CIE_Z_LAMBDA};

    #[test]
    fn fused_lookup_equals_separate_evaluation() {
        assert_eq!(CIE_X_LAMBDA, CIE_Y_LAMBDA);
        assert_eq!(CIE_Z_LAMBDA, CIE_Y_LAMBDA);
        for i in 0..=8000 {
            let lambda = 370.0 + i as f64 * 0.05;
            let separate = Xyz::new(CIE_X.eval(lambda), CIE_Y.eval(lambda), CIE_Z.eval(lambda));
            assert_eq!(xyz_bar(lambda), separate, "at {lambda}");
        }
        assert_eq!(xyz_bar(f64::NAN), Xyz::ZERO);
    }
}
