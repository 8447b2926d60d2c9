//! Continuous spectra: samples plus an interpolant, evaluated at any
//! wavelength in nanometres.
//!
//! - [`TabulatedSpectrum`]: a light, a reflectance or a matching function.
//!   Its [`Role`] picks the [`Interpolation`] and the value bounds.
//! - [`validate`]: what makes samples a spectrum (shared with `build.rs`).
//! - [`observer`]: the CIE 1931 x̄, ȳ, z̄ at any wavelength.
//! - [`data`]: the assignment's built-in spectra, static data made at
//!   compile time.
//! - The range every integral and sampler covers: [`LAMBDA_MIN`] to
//!   [`LAMBDA_MAX`] (380–730 nm, width [`WIDTH`] = 350 nm).
//!
//! ```
//! use speclab::{data, spectrum::observer};
//! let v = data::F11.eval(545.0) * data::G4.eval(545.0) * observer::xyz_bar(545.0).y;
//! assert!(v > 0.0);
//! ```

pub mod data;
mod grid;
pub(crate) mod interp;
#[cfg(test)]
mod interp_tests;
pub mod observer;
pub(crate) mod range;
mod tabulated;
pub mod validate;

pub use range::{LAMBDA_MAX, LAMBDA_MIN, WIDTH};
pub use tabulated::{Tables, TabulatedSpectrum};
pub use validate::{Interpolation, Role};
