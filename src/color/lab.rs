//! CIELAB (CIE 15): L\*a\*b\* of a colour relative to a white, and the
//! derivative of that map, for fitting colours in a perceptual space.
//!
//! The white is the XYZ of the perfect white under the light (or the
//! colour space's white), so Lab does not depend on the light's arbitrary
//! scale. ΔE00 (CIEDE2000) is in [`super::difference`].
//!
//! ```
//! use speclab::{Xyz, color::lab::lab};
//! let white = Xyz::new(95.047, 100.0, 108.883);
//! assert_eq!(lab(white, white), [100.0, 0.0, 0.0]);
//! let grey = lab(white * 0.18, white);
//! assert!((grey[0] - 49.496).abs() < 1e-3 && grey[1].abs() < 1e-12);
//! ```

use crate::color::xyz::Xyz;

/// The largest ratio of a tristimulus value to the white's, `X/Xn`, that
/// [`lab`] uses. A colour a million times brighter than the white (L* ≈
/// 11,600) is off any perceptual scale already; the cap keeps CIEDE2000,
/// which raises chroma to the 7th power, finite where a white component is
/// nearly zero (a light with almost no power where z̄ lives) and an estimate
/// puts energy there.
pub const MAX_RATIO: f64 = 1e6;

/// `6/29`: below `DELTA³` the cube root is replaced by a line.
const DELTA: f64 = 6.0 / 29.0;

/// CIE's `f(t)`: `∛t` above `(6/29)³`, the tangent line below.
fn f(t: f64) -> f64 {
    if t > DELTA * DELTA * DELTA { t.cbrt() } else { t / (3.0 * DELTA * DELTA) + 4.0 / 29.0 }
}

/// `f'(t)`.
fn df(t: f64) -> f64 {
    if t > DELTA * DELTA * DELTA { 1.0 / (3.0 * t.cbrt() * t.cbrt()) } else { 1.0 / (3.0 * DELTA * DELTA) }
}

/// `c / w`, 0 where the white component is not positive, limited to
/// ±[`MAX_RATIO`].
fn ratio(c: f64, w: f64) -> f64 {
    if w > 0.0 { (c / w).clamp(-MAX_RATIO, MAX_RATIO) } else { 0.0 }
}

/// CIELAB `[L*, a*, b*]` of `xyz` relative to the white `white`. A white
/// component that is not positive (a light with no power where that matching
/// function lives) makes its ratio 0: under a dark light everything is
/// black. Ratios are limited to ±[`MAX_RATIO`].
#[must_use]
pub fn lab(xyz: Xyz, white: Xyz) -> [f64; 3] {
    let (fx, fy, fz) = (f(ratio(xyz.x, white.x)), f(ratio(xyz.y, white.y)), f(ratio(xyz.z, white.z)));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

/// The XYZ of CIELAB `[L*, a*, b*]` relative to `white`: the inverse of
/// [`lab`] (CIE 015:2018, 8.2.1), exact to rounding for ratios within
/// ±[`MAX_RATIO`].
///
/// ```
/// use speclab::{Xyz, color::lab::{lab, xyz_from_lab}};
/// // colour-science's Lab_to_XYZ test, D65 white at xy (0.3127, 0.3290).
/// let white = Xyz::from_xy_luminance([0.3127, 0.3290], 100.0);
/// let xyz = xyz_from_lab([41.527875844653451, 52.638583607158087, 26.923219366067170], white);
/// assert!((xyz - Xyz::new(20.654008, 12.197225, 5.136952)).to_array().iter().all(|d| d.abs() < 1e-5));
/// ```
#[must_use]
pub fn xyz_from_lab([l, a, b]: [f64; 3], white: Xyz) -> Xyz {
    let fy = (l + 16.0) / 116.0;
    let (fx, fz) = (fy + a / 500.0, fy - b / 200.0);
    let inverse = |u: f64| if u > DELTA { u * u * u } else { 3.0 * DELTA * DELTA * (u - 4.0 / 29.0) };
    Xyz::new(inverse(fx) * white.x, inverse(fy) * white.y, inverse(fz) * white.z)
}

/// The Jacobian of [`lab`] at `xyz`: `d[L*, a*, b*] / d[X, Y, Z]`, rows by
/// Lab component (zero where a white component is not positive).
#[must_use]
pub fn lab_jacobian(xyz: Xyz, white: Xyz) -> [[f64; 3]; 3] {
    let d = |c: f64, w: f64| if w > 0.0 { df(ratio(c, w)) / w } else { 0.0 };
    let (dx, dy, dz) = (d(xyz.x, white.x), d(xyz.y, white.y), d(xyz.z, white.z));
    [[0.0, 116.0 * dy, 0.0], [500.0 * dx, -500.0 * dy, 0.0], [0.0, 200.0 * dy, -200.0 * dz]]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Jacobian against central differences, on both branches of f.
    #[test]
    fn jacobian_is_the_derivative() {
        let white = Xyz::new(0.95, 1.0, 1.09);
        for xyz in [Xyz::new(0.3, 0.4, 0.2), Xyz::new(0.001, 0.002, 0.0005), Xyz::new(0.9, 0.002, 1.2)] {
            let j = lab_jacobian(xyz, white);
            for c in 0..3 {
                let h = 1e-7;
                let mut up = xyz.to_array();
                let mut down = xyz.to_array();
                up[c] += h;
                down[c] -= h;
                let (a, b) = (lab(Xyz::from(up), white), lab(Xyz::from(down), white));
                for row in 0..3 {
                    let numeric = (a[row] - b[row]) / (2.0 * h);
                    assert!((numeric - j[row][c]).abs() < 1e-5 * (1.0 + numeric.abs()), "{xyz:?} {row} {c}");
                }
            }
        }
        assert_eq!(lab_jacobian(Xyz::new(0.5, 0.5, 0.5), Xyz::new(0.0, 1.0, 1.0))[1][0], 0.0);
    }
}
