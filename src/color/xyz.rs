//! CIE XYZ tristimulus values, with the arithmetic of sums of estimates
//! (see [`super::triple`]). The conversion to linear sRGB,
//! [`Xyz::to_linear_srgb`], lives with the colour space (`srgb.rs`).
//!
//! **Two conventions.** Every XYZ this crate computes is an integral,
//! `∫ v(λ)·c̄(λ) dλ` over the range its wavelengths were drawn in (or its
//! buckets cut, or its reference integrated over), in the units of the
//! spectrum `v` times nanometres, so a constant spectrum of 1 has
//! `Y = ∫ȳ`: 106.8489 over the assignment's 380–730 nm
//! ([`Y_BAR_INTEGRAL`]), what Appendix 2 tabulates. A renderer's divides
//! by what weighed it, so that a constant 1 has `Y = 1`:
//! [`Domain::normalized`](crate::sampling::Domain::normalized) for drawn
//! wavelengths and the exact reference (106.8569 over 360–830 nm with the
//! CIE 1931 1 nm table: pbrt-v4's `CIE_Y_integral`, 106.856895; Mitsuba 3
//! divides by 106.7502594, its own 5 nm table's sum), `to_normalized_xyz`
//! for fixed wavelengths and buckets (their own white).
//!
//! ```
//! use speclab::{Xyz, spectrum::{Constant, observer::Y_BAR_INTEGRAL}, sampling::{reference, Domain}};
//! let sum: Xyz = [Xyz::new(1.0, 2.0, 3.0), Xyz::from([0.5, 0.5, 0.5])].into_iter().sum();
//! assert_eq!(sum / 2.0, Xyz::new(0.75, 1.25, 1.75));
//! let one = reference::white(&Constant::new(1.0)); // the assignment's: Y = ∫ȳ
//! assert!((one.y - Y_BAR_INTEGRAL).abs() < 1e-12 * one.y);
//! let domain = Domain::VISIBLE; // a renderer's: Y = 1
//! assert!((domain.normalized(domain.reference(&[&Constant::new(1.0)])?).y - 1.0).abs() < 1e-12);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::spectrum::Float;

use crate::color::triple::triple_arithmetic;

/// CIE 1931 XYZ tristimulus values.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Xyz {
    /// X.
    pub x: f64,
    /// Y (luminance).
    pub y: f64,
    /// Z.
    pub z: f64,
}

impl Xyz {
    /// The sums of a weighted sum, `[X, Y, Z]` (and any lanes after,
    /// ignored) in the precision they were summed in: the one place a
    /// sample's, a bucket spectrum's or a rule's XYZ is assembled.
    #[inline(always)]
    pub(crate) fn of_sums<T: Float, const N: usize>(sums: [T; N]) -> Xyz {
        const { assert!(N >= 3) };
        Xyz::new(sums[0].to_f64(), sums[1].to_f64(), sums[2].to_f64())
    }

    /// All zero.
    pub const ZERO: Xyz = Xyz::new(0.0, 0.0, 0.0);

    /// From components.
    #[inline]
    #[must_use]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Xyz { x, y, z }
    }

    /// The chromaticity `[x, y] = [X, Y] / (X + Y + Z)`; `None` where
    /// `X + Y + Z` is zero (black has none).
    ///
    /// ```
    /// use speclab::Xyz;
    /// let [x, y] = Xyz::new(95.047, 100.0, 108.883).xy().unwrap();
    /// assert!((x - 0.312727).abs() < 1e-6 && (y - 0.329023).abs() < 1e-6);
    /// assert_eq!(Xyz::ZERO.xy(), None);
    /// ```
    #[must_use]
    pub fn xy(self) -> Option<[f64; 2]> {
        let sum = self.x + self.y + self.z;
        (sum != 0.0).then(|| [self.x / sum, self.y / sum])
    }

    /// The XYZ of chromaticity `[x, y]` at luminance `Y` (xyY); zero where
    /// `y` is zero.
    ///
    /// ```
    /// use speclab::Xyz;
    /// let white = Xyz::from_xy_luminance([0.3127, 0.3290], 100.0);
    /// assert!((white.x - 95.0456).abs() < 1e-4 && (white.z - 108.9058).abs() < 1e-4);
    /// ```
    #[must_use]
    pub fn from_xy_luminance([x, y]: [f64; 2], luminance: f64) -> Xyz {
        if y == 0.0 {
            return Xyz::ZERO;
        }
        Xyz::new(x * luminance / y, luminance, (1.0 - x - y) * luminance / y)
    }
}

triple_arithmetic!(Xyz { x, y, z });

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_componentwise() {
        let (a, b) = (Xyz::new(1.0, 2.0, 3.0), Xyz::new(0.5, -1.0, 4.0));
        assert_eq!(a - b, Xyz::new(0.5, 3.0, -1.0));
        assert_eq!(a + b, Xyz::new(1.5, 1.0, 7.0));
        assert_eq!(a * b, Xyz::new(0.5, -2.0, 12.0));
        assert_eq!(a / b, Xyz::new(2.0, -2.0, 0.75));
        assert_eq!(a * 2.0, Xyz::new(2.0, 4.0, 6.0));
        assert_eq!(2.0 * a, a * 2.0);
        assert_eq!(a / 2.0, Xyz::new(0.5, 1.0, 1.5));
        assert_eq!(6.0 / a, Xyz::new(6.0, 3.0, 2.0));
        assert_eq!(1.0 + a, a + 1.0);
        assert_eq!(1.0 - a, -(a - 1.0));
        assert_eq!(-a, Xyz::new(-1.0, -2.0, -3.0));
        let mut c = a;
        c += b;
        c -= a;
        assert_eq!(c, b);
        c *= 2.0;
        c /= Xyz::splat(2.0);
        c += 1.0;
        c -= 1.0;
        c *= Xyz::new(1.0, 1.0, 0.5);
        c /= 2.0;
        assert_eq!(c, Xyz::new(0.25, -0.5, 1.0));
        assert_eq!([a, b, a].into_iter().sum::<Xyz>(), Xyz::new(2.5, 3.0, 10.0));
        assert_eq!(std::iter::empty::<Xyz>().sum::<Xyz>(), Xyz::default());
        assert_eq!(Xyz::from([1.0, 2.0, 3.0]), a);
        assert_eq!(<[f64; 3]>::from(a), [1.0, 2.0, 3.0]);
        assert!(a.is_finite() && !Xyz::new(0.0, f64::NAN, 0.0).is_finite());
        assert!(!Xyz::new(f64::INFINITY, 0.0, 0.0).is_finite() && !Xyz::new(0.0, 0.0, f64::NAN).is_finite());
    }
}
