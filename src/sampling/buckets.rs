//! Equidistant wavelength buckets: the one definition of the two rules.
//!
//! The range 380–730 nm (width W = 350 nm) is cut into M equal buckets;
//! bucket i spans `[380 + i·W/M, 380 + (i+1)·W/M]`. A [`BucketRule`] turns
//! a spectrum into M numbers:
//!
//! - [`BucketRule::Center`]: the value at each bucket center;
//! - [`BucketRule::BoxAverage`]: the exact mean of the interpolant over
//!   each bucket (differences of the spectrum's exact running integral).
//!
//! and XYZ is the Riemann sum `W/M · Σᵢ valueᵢ·c̄ᵢ`, with c̄ᵢ the matching
//! functions bucketed by the same rule ([`BucketRule::observer`], a
//! `const fn`). Renderers use `RegularSpectrum<M, B>` (M a compile-time
//! constant, the rule a type); the study, which tries every M from 1 to 64,
//! uses a run-time [`Rule`](super::rule::Rule) of buckets: the same
//! numbers.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{buckets::BucketRule, rule::Rule};
//! use speclab::{Center, RegularSpectrum};
//! let sixteen = Rule::buckets(16, BucketRule::Center)?;
//! let fixed = RegularSpectrum::<16, Center>::center(&lights::A) * RegularSpectrum::center(&patches::G4);
//! let (run_time, compiled) = (sixteen.xyz(&lights::A, &patches::G4), fixed.to_xyz());
//! assert!((run_time.y - compiled.y).abs() <= 1e-14 * compiled.y);
//! assert!(Rule::buckets(0, BucketRule::Center).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::named_choices;
use crate::spectrum::data::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA,
};
use crate::spectrum::{LAMBDA_MIN, LAMBDA_WIDTH, Role, Spectrum, integrate, interp};

/// How a spectrum becomes bucket values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BucketRule {
    /// Point samples at bucket centers.
    #[default]
    Center,
    /// Exact means over each bucket.
    BoxAverage,
}

named_choices!(BucketRule, "a bucket rule": Center => "center", BoxAverage => "box");

/// The lower edge of bucket `i` of `m`, nm (`edge(m, m)` is 730 nm).
#[inline]
pub(crate) const fn edge(i: usize, m: usize) -> f64 {
    LAMBDA_MIN + i as f64 * LAMBDA_WIDTH / m as f64
}

/// The center of bucket `i` of `m`, nm.
#[inline]
pub(crate) const fn center(i: usize, m: usize) -> f64 {
    0.5 * (edge(i, m) + edge(i + 1, m))
}

const CMF_BOUNDS: [f64; 2] = Role::Observer.bounds();

impl BucketRule {
    /// `[x̄ᵢ, ȳᵢ, z̄ᵢ]` of bucket `i` of `m` under this rule: the matching
    /// functions at the center, or their exact means over the bucket (a
    /// bucket's weights are these times its width `W/M`). A `const fn`, so
    /// `RegularSpectrum<M, B>` has them at compile time.
    #[must_use]
    pub const fn observer(self, i: usize, m: usize) -> [f64; 3] {
        match self {
            BucketRule::Center => {
                let lambda = center(i, m);
                [
                    interp::eval(&CIE_X_LAMBDA, &CIE_X_COEFFS, CMF_BOUNDS, lambda),
                    interp::eval(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, CMF_BOUNDS, lambda),
                    interp::eval(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, CMF_BOUNDS, lambda),
                ]
            }
            BucketRule::BoxAverage => {
                let (a, b) = (edge(i, m), edge(i + 1, m));
                [
                    interp::integral(&CIE_X_LAMBDA, &CIE_X_COEFFS, &CIE_X_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                    interp::integral(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, &CIE_Y_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                    interp::integral(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, &CIE_Z_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                ]
            }
        }
    }

    /// The `out.len()` bucket values of `s` under this rule.
    pub fn values_into<S: Spectrum + ?Sized>(self, s: &S, out: &mut [f64]) {
        let m = out.len();
        match self {
            BucketRule::Center => {
                for (i, v) in out.iter_mut().enumerate() {
                    *v = s.eval(center(i, m));
                }
            }
            BucketRule::BoxAverage => box_means(s, out),
        }
    }
}

/// The exact means of `s` over each of `out.len()` buckets: differences of
/// the spectrum's running integral at the edges where it has one at hand
/// (a table's: O(1) per edge), otherwise each bucket's integral piece by
/// piece (exact for a piecewise polynomial, else by quadrature).
#[inline]
pub(crate) fn box_means<S: Spectrum + ?Sized>(s: &S, out: &mut [f64]) {
    let m = out.len();
    let inv_width = m as f64 / LAMBDA_WIDTH;
    if let Some(mut below) = s.running_integral(edge(0, m)) {
        for (i, v) in out.iter_mut().enumerate() {
            let above = s.running_integral(edge(i + 1, m)).unwrap_or(below);
            *v = (above - below) * inv_width;
            below = above;
        }
        return;
    }
    for (i, v) in out.iter_mut().enumerate() {
        *v = integrate::integral(&s, edge(i, m), edge(i + 1, m)) * inv_width;
    }
}
