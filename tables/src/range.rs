//! The wavelength range that every integral and every sampling strategy
//! covers: 380–730 nm, the common support of the assignment's data.
//!
//! One range for everything: the exact reference, the perfect white used
//! for CIELAB, random and hero wavelengths and regular buckets all stop at
//! [`LAMBDA_MAX`], even where a light or the observer is tabulated further
//! (D65, F11 and the CIE tables go to 780 nm).
//!
//! ```
//! use speclab_tables::range::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH};
//! assert_eq!(LAMBDA_WIDTH, LAMBDA_MAX - LAMBDA_MIN);
//! ```

/// Lower end of the integration and sampling range, nm.
pub const LAMBDA_MIN: f64 = 380.0;
/// Upper end of the integration and sampling range, nm.
pub const LAMBDA_MAX: f64 = 730.0;
/// Width W of the range, nm.
pub const LAMBDA_WIDTH: f64 = LAMBDA_MAX - LAMBDA_MIN;
