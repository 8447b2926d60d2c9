//! sRGB: linear sRGB by the assignment's matrix, and the IEC 61966-2-1
//! transfer function that encodes it for display.
//!
//! Three XYZ → linear sRGB matrices, each for its own purpose:
//!
//! | matrix | first row | serves |
//! |---|---|---|
//! | [`XYZ_TO_SRGB`], [`Xyz::to_linear_srgb`] | 3.2410, −1.5374, −0.4986 | the assignment (Appendix 1 part D; Appendix 2's numbers) |
//! | [`IEC_XYZ_TO_SRGB`], [`Xyz::to_linear_srgb_iec`] | 3.2406, −1.5372, −0.4986 | IEC 61966-2-1 as printed, four decimals (colour-science's `XYZ_to_sRGB`) |
//! | `RgbSpace::srgb().rgb(xyz)` | 3.24096994, −1.53738318, −0.49861076 | derived from the primaries and D65's (0.3127, 0.3290): a renderer's (pbrt-v4, Mitsuba 3), and the crate's one derived sRGB matrix |
//!
//! The printed matrices round a derived one to four decimals: part D's is
//! within 4.5e-5 of the derived matrix in every entry, IEC's printed one
//! 3.7e-4 from it and 4.0e-4 from part D's; on colour-science's first test
//! colour the encoded sRGB moves by 1.6e-4 between the printed and the
//! derived matrix, 1.1e-4 between the printed and part D's, 5.1e-5
//! between the derived and part D's.
//!
//! [`LinearRgb`] is XYZ through the matrix of Appendix 1, part D
//! ([`XYZ_TO_SRGB`], four decimals as printed), **unclamped**. [`encode`]
//! and [`decode`] are the standard's piecewise curve (a linear toe below
//! 0.0031308, a 1/2.4 power above) and its inverse.
//!
//! ```
//! use speclab::color::srgb::{decode, encode};
//! assert_eq!(encode(0.0), 0.0);
//! assert!((encode(0.18) - 0.4614).abs() < 1e-4); // 18 % grey encodes to 46 %
//! assert!((decode(encode(0.5)) - 0.5).abs() < 1e-15);
//! ```

use crate::color::matrix::{Matrix, inverse, mul};
use crate::color::rgb::LinearRgb;
use crate::color::xyz::Xyz;
use crate::spectrum::data;

/// XYZ → linear sRGB, from `data/xyz_to_srgb.txt` (Appendix 1, part D).
pub const XYZ_TO_SRGB: Matrix = data::XYZ_TO_SRGB;

/// XYZ → linear sRGB as IEC 61966-2-1 prints it (four decimals).
pub const IEC_XYZ_TO_SRGB: Matrix =
    [[3.2406, -1.5372, -0.4986], [-0.9689, 1.8758, 0.0415], [0.0557, -0.2040, 1.0570]];

/// Linear sRGB → XYZ as IEC 61966-2-1 prints it (four decimals; not the
/// inverse of [`IEC_XYZ_TO_SRGB`] beyond them).
pub const IEC_SRGB_TO_XYZ: Matrix =
    [[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]];

/// Linear sRGB → XYZ: the inverse of [`XYZ_TO_SRGB`], computed at compile
/// time. Its middle row, the luminance of `r, g, b`, is 0.21262, 0.71514,
/// 0.07215 (the standard's 0.2126, 0.7152, 0.0722 to four decimals; the
/// part D matrix is printed with four), so the display white `(1, 1, 1)`
/// has Y = 0.99991.
pub const SRGB_TO_XYZ: Matrix = inverse(&XYZ_TO_SRGB);

/// Below this linear value the curve is a line of slope 12.92.
pub const LINEAR_TOE: f64 = 0.003_130_8;

/// The sRGB transfer function (IEC 61966-2-1): linear `c` in `[0, 1]` to
/// its encoded value. Values outside `[0, 1]` are clamped first; NaN gives 0.
#[must_use]
pub fn encode(c: f64) -> f64 {
    let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
    if c <= LINEAR_TOE { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 }
}

/// The inverse of [`encode`]: an encoded value in `[0, 1]` to linear.
/// Values outside `[0, 1]` are clamped first; NaN gives 0.
#[must_use]
pub fn decode(v: f64) -> f64 {
    let v = if v > 0.0 { v.min(1.0) } else { 0.0 };
    if v <= 12.92 * LINEAR_TOE { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
}

/// An encoded value in `[0, 1]` quantised to 8 bits (round to nearest).
#[must_use]
pub fn to_8bit(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

impl Xyz {
    /// Linear sRGB by the part D matrix, unclamped: the assignment's
    /// conversion, which Appendix 2's numbers use. A renderer's sRGB, the
    /// matrix derived from IEC 61966-2-1's primaries (as pbrt-v4's
    /// `ToRGB`), is [`RgbSpace::srgb`](crate::color::RgbSpace::srgb)'s
    /// `rgb`; the two differ by up to 5e-4.
    #[inline]
    #[must_use]
    pub fn to_linear_srgb(self) -> LinearRgb {
        LinearRgb::from(mul(&XYZ_TO_SRGB, self.to_array()))
    }

    /// Linear sRGB by IEC 61966-2-1's printed matrix ([`IEC_XYZ_TO_SRGB`]),
    /// unclamped: colour-science's `XYZ_to_sRGB` before its encoding.
    ///
    /// ```
    /// use speclab::{Xyz, color::srgb::encode};
    /// let rgb = Xyz::new(0.20654008, 0.12197225, 0.05136952).to_linear_srgb_iec();
    /// assert!((encode(rgb.r) - 0.70573936).abs() < 1e-7); // colour-science's test
    /// ```
    #[must_use]
    pub fn to_linear_srgb_iec(self) -> LinearRgb {
        LinearRgb::from(mul(&IEC_XYZ_TO_SRGB, self.to_array()))
    }

    /// Linear sRGB back to XYZ by [`SRGB_TO_XYZ`].
    #[must_use]
    pub fn from_linear_srgb(rgb: LinearRgb) -> Xyz {
        Xyz::from(mul(&SRGB_TO_XYZ, rgb.to_array()))
    }
}

/// CIE Y (luminance) of linear sRGB, by the middle row of [`SRGB_TO_XYZ`].
#[inline]
#[must_use]
pub fn luminance(rgb: LinearRgb) -> f64 {
    let [wr, wg, wb] = SRGB_TO_XYZ[1];
    wr * rgb.r + wg * rgb.g + wb * rgb.b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The three matrices and how far apart they put one colour (the
    /// module's table).
    #[test]
    fn three_matrices_apart() {
        let derived = crate::color::RgbSpace::srgb().to_rgb_matrix();
        let apart = |a: &Matrix, b: &Matrix| {
            a.iter().flatten().zip(b.iter().flatten()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
        };
        assert!((apart(derived, &XYZ_TO_SRGB) - 4.5e-5).abs() < 0.1e-5);
        assert!((apart(derived, &IEC_XYZ_TO_SRGB) - 3.7e-4).abs() < 0.1e-4);
        assert!((apart(&IEC_XYZ_TO_SRGB, &XYZ_TO_SRGB) - 4.0e-4).abs() < 1e-12);
        let xyz = Xyz::new(0.20654008, 0.12197225, 0.05136952);
        let encoded = |v: LinearRgb| [encode(v.r), encode(v.g), encode(v.b)];
        let (iec, part_d) = (encoded(xyz.to_linear_srgb_iec()), encoded(xyz.to_linear_srgb()));
        let derived = encoded(LinearRgb::from(mul(derived, xyz.to_array())));
        let far = |a: [f64; 3], b: [f64; 3]| (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max);
        assert!((far(iec, derived) - 1.6e-4).abs() < 0.05e-4);
        assert!((far(iec, part_d) - 1.1e-4).abs() < 0.05e-4);
        assert!((far(derived, part_d) - 5.1e-5).abs() < 0.05e-5);
        // The printed pair are each other's inverses to their four decimals.
        let product = crate::color::matrix::product(&IEC_XYZ_TO_SRGB, &IEC_SRGB_TO_XYZ);
        (0..3).for_each(|i| (0..3).for_each(|j| assert!((product[i][j] - f64::from(i == j)).abs() < 1e-3)));
    }

    /// IEC 61966-2-1: the two pieces meet at 0.0031308 (encoded 0.040450),
    /// up to a step of 2.9e-8 that the standard's rounded constants leave;
    /// 1 encodes to 1.
    #[test]
    fn transfer_function_at_its_breakpoints() {
        assert_eq!(encode(LINEAR_TOE), 12.92 * LINEAR_TOE);
        let step = encode(LINEAR_TOE * (1.0 + 1e-12)) - encode(LINEAR_TOE);
        assert!(step < 0.0 && step > -3e-8, "{step:e}");
        assert!((encode(1.0) - 1.0).abs() < 1e-15, "1.055 − 0.055 rounds to 1 − 2⁻⁵³");
        assert_eq!(encode(2.0), encode(1.0));
        assert_eq!(encode(-0.5), 0.0);
        assert_eq!(encode(f64::NAN), 0.0);
        assert!((encode(0.001) - 0.012_92).abs() < 1e-12);
        assert!((decode(0.04045) - LINEAR_TOE).abs() < 1e-7);
    }

    #[test]
    fn round_trips() {
        for i in 0..=1000 {
            let c = f64::from(i) / 1000.0;
            assert!((decode(encode(c)) - c).abs() < 1e-12, "{c}");
            assert!((encode(decode(c)) - c).abs() < 1e-12, "{c}");
        }
        assert_eq!(to_8bit(encode(1.0)), 255);
        assert_eq!(to_8bit(encode(0.0)), 0);
        assert_eq!(to_8bit(encode(0.18)), 118);
    }

    #[test]
    fn back_to_xyz() {
        let xyz = Xyz::new(0.3, 0.5, 0.2);
        let back = Xyz::from_linear_srgb(xyz.to_linear_srgb());
        assert!((back - xyz).to_array().iter().all(|d| d.abs() < 1e-12), "{back:?}");
        assert!((luminance(xyz.to_linear_srgb()) - 0.5).abs() < 1e-12);
    }
}
