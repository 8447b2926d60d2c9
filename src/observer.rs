//! The CIE 1931 2° standard observer: x̄, ȳ, z̄ at any wavelength.
//!
//! The matching functions are the 5 nm table of Appendix 1, part C,
//! interpolated by the four-point cubic and clamped at zero (the cubic dips
//! to about −1e-5 where z̄ reaches zero near 630 nm; a matching function is
//! never negative, and the clamp keeps every sample's Y non-negative).
//!
//! The bucket tables of [`crate::RegularSpectrum`] are computed here by
//! `const fn`, so each `M` is evaluated once, at compile time.
//!
//! ```
//! let cmf = speclab::observer::xyz_bar(555.0);
//! assert_eq!(cmf.y, 1.0);
//! ```

use crate::data::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA,
};
use crate::interp;
use crate::samples::Role;
use crate::{LAMBDA_MIN, WIDTH, Xyz};

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

/// `(x̄, ȳ, z̄)` at the centres `380 + (i + ½)·W/M` of `M` buckets.
pub(crate) const fn centre_buckets<const M: usize>() -> [Xyz; M] {
    let mut out = [Xyz::ZERO; M];
    let mut i = 0;
    while i < M {
        let lambda = LAMBDA_MIN + (i as f64 + 0.5) * WIDTH / M as f64;
        out[i] = Xyz::new(
            interp::eval(&CIE_X_LAMBDA, &CIE_X_COEFFS, BOUNDS, lambda),
            interp::eval(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, BOUNDS, lambda),
            interp::eval(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, BOUNDS, lambda),
        );
        i += 1;
    }
    out
}

/// The exact means of `(x̄, ȳ, z̄)` over each of `M` equal buckets.
pub(crate) const fn box_buckets<const M: usize>() -> [Xyz; M] {
    let mut out = [Xyz::ZERO; M];
    let mut i = 0;
    while i < M {
        let a = LAMBDA_MIN + i as f64 * WIDTH / M as f64;
        let b = LAMBDA_MIN + (i + 1) as f64 * WIDTH / M as f64;
        out[i] = Xyz::new(
            interp::integral(&CIE_X_LAMBDA, &CIE_X_COEFFS, &CIE_X_BREAKS, BOUNDS, a, b) / (b - a),
            interp::integral(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, &CIE_Y_BREAKS, BOUNDS, a, b) / (b - a),
            interp::integral(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, &CIE_Z_BREAKS, BOUNDS, a, b) / (b - a),
        );
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::{CIE_X, CIE_Y, CIE_Z};

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
