//! Perceptual error: CIELAB relative to the light's own white, and
//! CIEDE2000 — the core's (`speclab::color::difference`), re-exported.
//!
//! The white is the exact XYZ of the perfect white (reflectance 1) under the
//! same light, so L\*a\*b\* does not depend on the light's arbitrary scale
//! (F11's "huge numbers" in Appendix 2 give the same Lab as a normalised
//! F11). ΔE00 ≈ 1 is a just-noticeable difference between two colours
//! side by side.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::reference};
//! use speclab_study::evaluate::perceptual;
//! let white = reference::white(&lights::D65);
//! let lab = perceptual::lab(reference::xyz(&lights::D65, &patches::A1), white);
//! assert!(lab[0] > 95.0 && lab[1].abs() < 2.0); // A1 is a near-white patch
//! assert_eq!(perceptual::delta_e00(white, white, white), 0.0);
//! ```

pub use speclab::color::difference::{ciede2000, delta_e00};
pub use speclab::color::lab::{MAX_RATIO, lab};
