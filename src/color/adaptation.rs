//! Chromatic adaptation: a colour seen under one white, as it looks to an
//! eye adapted to another (the assignment's third remark, white balance).
//!
//! [`bradford`] is von Kries scaling in the cone space of Bradford's matrix
//! (Lam 1985), the transform of CIECAM97s and ICC profiles.
//!
//! ```
//! use speclab::{Xyz, color::adaptation::bradford};
//! let (a, d65) = (Xyz::new(109.85, 100.0, 35.58), Xyz::new(95.047, 100.0, 108.883));
//! let adapted = bradford(a, a, d65); // the white itself maps to the target white
//! assert!((adapted - d65).to_array().iter().all(|c| c.abs() < 1e-9));
//! ```

use crate::Xyz;
use crate::color::matrix::{Matrix, inverse, mul};

/// Bradford's cone response matrix (Lam 1985).
pub const BRADFORD: Matrix =
    [[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]];

/// `xyz` seen under `from_white`, adapted to `to_white`. A white with a zero
/// cone response adapts nothing in that cone (the ratio is taken as 1).
#[must_use]
pub fn bradford(xyz: Xyz, from_white: Xyz, to_white: Xyz) -> Xyz {
    let (c, s, d) = (
        mul(&BRADFORD, xyz.to_array()),
        mul(&BRADFORD, from_white.to_array()),
        mul(&BRADFORD, to_white.to_array()),
    );
    let adapted = [0, 1, 2].map(|i| if s[i] != 0.0 { c[i] * d[i] / s[i] } else { c[i] });
    let [x, y, z] = mul(&inverse(&BRADFORD), adapted);
    Xyz::new(x, y, z)
}
