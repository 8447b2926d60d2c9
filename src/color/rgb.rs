//! [`LinearRgb`]: linear RGB in some [`RgbSpace`](super::space::RgbSpace),
//! unclamped. The space is the caller's to keep track of, as a renderer's
//! working space is (pbrt-v4's `RGB` is the same): the assignment's linear
//! sRGB ([`Xyz::to_linear_srgb`](super::Xyz::to_linear_srgb)), a space's
//! `rgb`, a display's input.
//!
//! ```
//! use speclab::LinearRgb;
//! let c = LinearRgb::new(0.2, 0.4, 0.8) * 0.5 + LinearRgb::splat(0.1);
//! assert_eq!(c.to_array(), [0.2, 0.30000000000000004, 0.5]);
//! assert_eq!(LinearRgb::new(1.0, 0.5, 0.0).max_component(), 1.0);
//! ```

use crate::color::triple::triple_arithmetic;

/// Linear RGB in some space, unclamped (a negative component is outside
/// that space's gamut).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LinearRgb {
    /// Red.
    pub r: f64,
    /// Green.
    pub g: f64,
    /// Blue.
    pub b: f64,
}

impl LinearRgb {
    /// From components.
    #[inline]
    #[must_use]
    pub const fn new(r: f64, g: f64, b: f64) -> Self {
        LinearRgb { r, g, b }
    }

    /// The largest component.
    #[inline]
    #[must_use]
    pub fn max_component(self) -> f64 {
        self.r.max(self.g).max(self.b)
    }

    /// True if no component is negative (inside the space's gamut, up to
    /// brightness).
    #[must_use]
    pub fn in_gamut(self) -> bool {
        self.r >= 0.0 && self.g >= 0.0 && self.b >= 0.0
    }

    /// Euclidean distance to `other`.
    #[must_use]
    pub fn distance(self, other: LinearRgb) -> f64 {
        let [r, g, b] = (self - other).to_array();
        (r * r + g * g + b * b).sqrt()
    }
}

triple_arithmetic!(LinearRgb { r, g, b });
