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
use crate::spectrum::interp;
use crate::spectrum::validate::Role;

/// `(x̄, ȳ, z̄)` at `lambda` nm; zero outside 380–780 nm.
///
/// The three tables share one wavelength grid (checked in the tests), so the
/// segment is found once for all three.
#[inline]
#[must_use]
pub fn xyz_bar(lambda: f64) -> Xyz {
    const N: usize = CIE_Y_LAMBDA.len();
    const FIRST: f64 = CIE_Y_LAMBDA[0];
    const INV_STEP: f64 = (N - 1) as f64 / (CIE_Y_LAMBDA[N - 1] - FIRST);
    if !(FIRST..=CIE_Y_LAMBDA[N - 1]).contains(&lambda) {
        return Xyz::ZERO;
    }
    let k = (((lambda - FIRST) * INV_STEP) as usize).min(N - 2);
    let t = lambda - CIE_Y_LAMBDA[k];
    let at = |c: &[[f64; 4]]| interp::clamp(interp::segment_value(c[k], t), BOUNDS);
    Xyz::new(at(&CIE_X_COEFFS), at(&CIE_Y_COEFFS), at(&CIE_Z_COEFFS))
}

const BOUNDS: [f64; 2] = Role::Observer.bounds();

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
