//! Perceptual error: CIELAB relative to the light's own white, and CIEDE2000.
//!
//! The white is the exact XYZ of the perfect white (reflectance 1) under the
//! same light, so L\*a\*b\* does not depend on the light's arbitrary scale
//! (F11's "huge numbers" in Appendix 2 give the same Lab as a normalised
//! F11). ΔE00 is palette's `Ciede2000` (Sharma, Wu and Dalal 2005), checked
//! against their published test pairs in `tests/ciede2000.rs`. ΔE00 ≈ 1 is
//! a just-noticeable difference between two colours side by side.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::reference, study::evaluate::perceptual};
//! let white = reference::white(&lights::D65);
//! let lab = perceptual::lab(reference::xyz(&lights::D65, &patches::A1), white);
//! assert!(lab[0] > 95.0 && lab[1].abs() < 2.0); // A1 is a near-white patch
//! assert_eq!(perceptual::delta_e00(white, white, white), 0.0);
//! ```

use palette::color_difference::Ciede2000;
use palette::white_point::D65;

use crate::color::Xyz;

pub use crate::color::lab::{MAX_RATIO, lab};

/// CIEDE2000 between two L\*a\*b\* colours.
#[must_use]
pub fn ciede2000(lab1: [f64; 3], lab2: [f64; 3]) -> f64 {
    // The white point type parameter does not enter the formula.
    let c1 = palette::Lab::<D65, f64>::new(lab1[0], lab1[1], lab1[2]);
    let c2 = palette::Lab::<D65, f64>::new(lab2[0], lab2[1], lab2[2]);
    c1.difference(c2)
}

/// ΔE00 between an estimate and the reference, both relative to `white`.
#[must_use]
pub fn delta_e00(estimate: Xyz, reference: Xyz, white: Xyz) -> f64 {
    ciede2000(lab(estimate, white), lab(reference, white))
}
