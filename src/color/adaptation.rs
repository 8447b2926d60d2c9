//! Chromatic adaptation: a colour seen under one white, as it looks to an
//! eye adapted to another (the assignment's third remark, white balance).
//!
//! Every transform here is von Kries scaling in a cone space: the cone
//! responses of the colour are scaled by the ratio of the two whites'
//! responses. The [`Cat`] names the cone space: von Kries's own
//! (Hunt–Pointer–Estevez, normalised to D65), Bradford's (Lam 1985; ICC
//! profiles), CAT02's (CIECAM02) or CAT16's (CAM16). [`Cat::matrix`] is the
//! whole adaptation as one 3×3 matrix, for a renderer that applies it per
//! pixel.
//!
//! ```
//! use speclab::{Xyz, color::adaptation::Cat};
//! let (a, d65) = (Xyz::new(109.85, 100.0, 35.58), Xyz::new(95.047, 100.0, 108.883));
//! for cat in Cat::ALL {
//!     let adapted = cat.adapt(a, a, d65); // the white itself maps to the target white
//!     assert!((adapted - d65).to_array().iter().all(|c| c.abs() < 1e-9));
//! }
//! ```

use crate::Xyz;
use crate::color::matrix::{Matrix, inverse, mul};

/// A chromatic adaptation transform: the cone space of von Kries scaling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Cat {
    /// Hunt–Pointer–Estevez cones normalised to D65 (von Kries 1902's scaling).
    VonKries,
    /// Lam 1985 (CIECAM97s, ICC profiles); the default.
    #[default]
    Bradford,
    /// CIECAM02's CAT02 (CIE 159:2004).
    Cat02,
    /// CAM16's CAT16 (Li et al. 2017).
    Cat16,
    /// XYZ itself as the cone space (the "wrong von Kries" of ICC v2).
    XyzScaling,
}

impl Cat {
    /// Every transform, in the order above.
    pub const ALL: [Cat; 5] = [Cat::VonKries, Cat::Bradford, Cat::Cat02, Cat::Cat16, Cat::XyzScaling];

    /// The cone response matrix (XYZ to cone space), as published.
    #[must_use]
    pub const fn cones(self) -> Matrix {
        match self {
            Cat::VonKries => {
                [[0.40024, 0.70760, -0.08081], [-0.22630, 1.16532, 0.04570], [0.0, 0.0, 0.91822]]
            }
            Cat::Bradford => {
                [[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]]
            }
            Cat::Cat02 => [[0.7328, 0.4296, -0.1624], [-0.7036, 1.6975, 0.0061], [0.0030, 0.0136, 0.9834]],
            Cat::Cat16 => [
                [0.401288, 0.650173, -0.051461],
                [-0.250268, 1.204414, 0.045854],
                [-0.002079, 0.048952, 0.953127],
            ],
            Cat::XyzScaling => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        }
    }

    /// The adaptation from `from_white` to `to_white` as one matrix
    /// `M⁻¹ · diag(d/s) · M`. A white with a zero cone response adapts
    /// nothing in that cone (the ratio is taken as 1).
    #[must_use]
    pub fn matrix(self, from_white: Xyz, to_white: Xyz) -> Matrix {
        let m = self.cones();
        let (s, d) = (mul(&m, from_white.to_array()), mul(&m, to_white.to_array()));
        let gain = [0, 1, 2].map(|i| if s[i] != 0.0 { d[i] / s[i] } else { 1.0 });
        let scaled = [0, 1, 2].map(|i| m[i].map(|v| v * gain[i]));
        let inv = inverse(&m);
        std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|k| inv[r][k] * scaled[k][c]).sum()))
    }

    /// `xyz` seen under `from_white`, adapted to `to_white`.
    #[must_use]
    pub fn adapt(self, xyz: Xyz, from_white: Xyz, to_white: Xyz) -> Xyz {
        Xyz::from(mul(&self.matrix(from_white, to_white), xyz.to_array()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zero_cone_response_adapts_nothing_in_that_cone() {
        // Von Kries's third cone sees Z alone: a white with Z = 0 has none there.
        let m = Cat::VonKries.cones();
        let (white, target, colour) =
            (Xyz::new(1.0, 1.0, 0.0), Xyz::new(0.9, 1.0, 1.1), Xyz::new(0.3, 0.4, 0.5));
        let (s, d, c) = (mul(&m, white.to_array()), mul(&m, target.to_array()), mul(&m, colour.to_array()));
        assert_eq!(s[2], 0.0);
        let expected = [c[0] * d[0] / s[0], c[1] * d[1] / s[1], c[2]];
        let cones = mul(&m, Cat::VonKries.adapt(colour, white, target).to_array());
        expected
            .iter()
            .zip(cones)
            .for_each(|(e, c)| assert!((e - c).abs() < 1e-12, "{cones:?} against {expected:?}"));
    }

    #[test]
    fn the_same_white_is_the_identity() {
        let w = Xyz::new(96.42, 100.0, 82.51);
        for cat in Cat::ALL {
            let m = cat.matrix(w, w);
            for (r, row) in m.iter().enumerate() {
                row.iter().enumerate().for_each(|(c, v)| assert!((v - f64::from(r == c)).abs() < 1e-12));
            }
        }
    }
}
