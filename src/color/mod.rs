//! Colour: CIE XYZ, linear sRGB by the assignment's matrix, the sRGB
//! transfer function, and chromatic adaptation.
//!
//! - [`Xyz`]: the integral of a spectrum against the CIE 1931 matching
//!   functions, in the units of the spectrum times nanometres (no
//!   normalisation: a light of arbitrary scale gives XYZ of that scale).
//! - [`LinearRgb`]: linear RGB in a space the caller keeps track of; the
//!   assignment's linear sRGB is XYZ through the matrix of Appendix 1,
//!   part D ([`Xyz::to_linear_srgb`]), **unclamped**: a negative component
//!   means the colour is outside the sRGB gamut, which is information, not
//!   an error.
//! - [`srgb`]: the IEC 61966-2-1 transfer function, and sRGB's luminance.
//! - [`adaptation`]: chromatic adaptation between whites (von Kries,
//!   Bradford, CAT02, CAT16), as a function or a matrix.
//! - [`lab`]: CIELAB relative to a white; [`difference`]: CIEDE2000
//!   (ΔE00) between two colours.
//! - [`RgbAlbedo`], [`RgbUnbounded`], [`RgbIlluminant`] ([`rgb_spectra`]):
//!   an RGB colour as a spectrum, fitted in CIELAB (`upsample.rs`), or
//!   looked up in [`rgb_table`].
//!
//! [`Xyz`] and [`LinearRgb`] have the whole component-wise operator set
//! (`+ - * /` with each other and with scalars on either side, the assign
//! forms, `Neg`, `Sum`, `From<[f64; 3]>`). This floor uses only the
//! spectrum floor below it (the observer's and the matrix's tables).
//!
//! ```
//! use speclab::Xyz;
//! let rgb = Xyz::new(0.0, 1.0, 0.0).to_linear_srgb();
//! assert_eq!((rgb.r, rgb.g, rgb.b), (-1.5374, 1.8760, -0.2040));
//! assert!(!rgb.in_gamut());
//! ```

pub mod adaptation;
pub mod builtin;
pub mod difference;
pub mod lab;
pub mod matrix;
mod rgb;
pub mod rgb_spectra;
pub mod rgb_table;
pub mod space;
mod space_spectra;
pub mod srgb;
mod texel;
pub(crate) mod triple;
mod upsample;
mod xyz;

pub use builtin::BuiltIn;
pub use matrix::Matrix;
pub use rgb::LinearRgb;
pub use rgb_spectra::{RgbAlbedo, RgbIlluminant, RgbUnbounded};
pub use space::RgbSpace;
pub use space_spectra::Clamp;
pub use srgb::XYZ_TO_SRGB;
pub use texel::RgbTexel;
pub use xyz::Xyz;
