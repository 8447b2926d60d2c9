//! CIE XYZ tristimulus values, with the arithmetic of sums of estimates.

use std::iter::Sum;
use std::ops::{Add, AddAssign, Div, Mul, Sub};

use crate::color::matrix::mul;
use crate::color::{LinearSrgb, XYZ_TO_SRGB};

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
    /// All zero.
    pub const ZERO: Xyz = Xyz::new(0.0, 0.0, 0.0);

    /// From components.
    #[inline]
    #[must_use]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Xyz { x, y, z }
    }

    /// Linear sRGB by the part D matrix, unclamped.
    #[inline]
    #[must_use]
    pub fn to_linear_srgb(self) -> LinearSrgb {
        let [r, g, b] = mul(&XYZ_TO_SRGB, self.to_array());
        LinearSrgb::new(r, g, b)
    }

    /// `[x, y, z]`.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    /// True if every component is finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.to_array().iter().all(|c| c.is_finite())
    }
}

impl Add for Xyz {
    type Output = Xyz;
    #[inline]
    fn add(self, o: Xyz) -> Xyz {
        Xyz::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl AddAssign for Xyz {
    #[inline]
    fn add_assign(&mut self, o: Xyz) {
        *self = *self + o;
    }
}

impl Sub for Xyz {
    type Output = Xyz;
    #[inline]
    fn sub(self, o: Xyz) -> Xyz {
        Xyz::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Mul<f64> for Xyz {
    type Output = Xyz;
    #[inline]
    fn mul(self, s: f64) -> Xyz {
        Xyz::new(self.x * s, self.y * s, self.z * s)
    }
}

impl Div<f64> for Xyz {
    type Output = Xyz;
    #[inline]
    fn div(self, s: f64) -> Xyz {
        Xyz::new(self.x / s, self.y / s, self.z / s)
    }
}

impl Sum for Xyz {
    fn sum<I: Iterator<Item = Xyz>>(iter: I) -> Xyz {
        iter.fold(Xyz::ZERO, |a, b| a + b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_componentwise() {
        let (a, b) = (Xyz::new(1.0, 2.0, 3.0), Xyz::new(0.5, -1.0, 4.0));
        assert_eq!(a - b, Xyz::new(0.5, 3.0, -1.0));
        assert_eq!(a + b, Xyz::new(1.5, 1.0, 7.0));
        assert_eq!(a * 2.0, Xyz::new(2.0, 4.0, 6.0));
        assert_eq!(a / 2.0, Xyz::new(0.5, 1.0, 1.5));
        assert_eq!([a, b, a].into_iter().sum::<Xyz>(), Xyz::new(2.5, 3.0, 10.0));
        assert_eq!(std::iter::empty::<Xyz>().sum::<Xyz>(), Xyz::default());
        assert!(a.is_finite() && !Xyz::new(0.0, f64::NAN, 0.0).is_finite());
    }
}
