//! CIE XYZ tristimulus values and linear sRGB.
//!
//! [`Xyz`] is the integral of a spectrum against the CIE 1931 matching
//! functions, in the units of the spectrum times nanometres (no
//! normalisation: a light of arbitrary scale gives XYZ of that scale).
//! [`LinearSrgb`] applies the matrix of the assignment's Appendix 1, part D,
//! and is **not clamped**: a negative component means the colour is outside
//! the sRGB gamut, which is information, not an error.
//!
//! ```
//! use speclab::Xyz;
//! let rgb = Xyz::new(0.0, 1.0, 0.0).to_linear_srgb();
//! assert_eq!((rgb.r, rgb.g, rgb.b), (-1.5374, 1.8760, -0.2040));
//! assert!(!rgb.in_gamut());
//! ```

use std::ops::{Add, AddAssign, Div, Mul, Sub};

/// A 3×3 matrix, row-major, acting on column vectors.
pub type Matrix = [[f64; 3]; 3];

/// XYZ → linear sRGB, from `data/xyz_to_srgb.txt` (Appendix 1, part D).
pub const XYZ_TO_SRGB: Matrix = crate::data::XYZ_TO_SRGB;

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
        LinearSrgb { r, g, b }
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

/// `m · v`.
#[inline]
#[must_use]
pub fn mul(m: &Matrix, v: [f64; 3]) -> [f64; 3] {
    m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
}

/// The inverse of `m` by cofactors (all zero if `m` is singular).
#[must_use]
pub fn inverse(m: &Matrix) -> Matrix {
    let cof = |r: usize, c: usize| {
        let (r1, r2, c1, c2) = ((r + 1) % 3, (r + 2) % 3, (c + 1) % 3, (c + 2) % 3);
        m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]
    };
    let det = m[0][0] * cof(0, 0) + m[0][1] * cof(0, 1) + m[0][2] * cof(0, 2);
    let scale = if det != 0.0 { 1.0 / det } else { 0.0 };
    std::array::from_fn(|r| std::array::from_fn(|c| cof(c, r) * scale))
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

/// Linear (not gamma-encoded) sRGB, unclamped.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LinearSrgb {
    /// Red.
    pub r: f64,
    /// Green.
    pub g: f64,
    /// Blue.
    pub b: f64,
}

impl LinearSrgb {
    /// `[r, g, b]`.
    #[must_use]
    pub const fn to_array(self) -> [f64; 3] {
        [self.r, self.g, self.b]
    }

    /// True if no component is negative (the colour is inside sRGB's gamut,
    /// up to the light's arbitrary brightness scale).
    #[must_use]
    pub fn in_gamut(self) -> bool {
        self.r >= 0.0 && self.g >= 0.0 && self.b >= 0.0
    }

    /// Euclidean distance to `other`.
    #[must_use]
    pub fn distance(self, other: LinearSrgb) -> f64 {
        let d = [self.r - other.r, self.g - other.g, self.b - other.b];
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_inverts() {
        let m = XYZ_TO_SRGB;
        let inv = inverse(&m);
        for j in 0..3 {
            let e: [f64; 3] = std::array::from_fn(|i| f64::from(u8::from(i == j)));
            let back = mul(&m, mul(&inv, e));
            assert!((0..3).all(|i| (back[i] - e[i]).abs() < 1e-12), "{back:?} vs {e:?}");
        }
    }
}
