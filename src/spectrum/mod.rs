//! Continuous spectra, the bottom floor: samples plus an interpolant,
//! evaluated at any wavelength in nanometres, and integrated exactly.
//!
//! - [`Spectrum`]: what every spectrum answers (a value at any wavelength,
//!   values at K wavelengths, its polynomial pieces if it has them); one
//!   interface over the kinds below and a renderer's own.
//! - [`TabulatedSpectrum`]: a light, a reflectance or a matching function
//!   from samples. Its [`Role`] picks the [`Interpolation`] and the value
//!   bounds. The reference: exact, and the slowest to evaluate.
//! - [`DenseSpectrum`]: any spectrum at every whole nanometre, in `f32` or
//!   `f64`, one load per wavelength (the fast path); [`DenseObserver`],
//!   the observer so.
//! - [`Constant`], [`Blackbody`] (peak 1, or absolute: [`planck`]),
//!   [`FnSpectrum`] (a closure), [`Mixture`] (a weighted sum: a scene's
//!   lights), [`Scaled`] (`light * 4.0`).
//! - [`SigmoidPolynomial`]: the function behind the spectra of RGB
//!   colours (`color::RgbAlbedo` and its siblings, one floor up).
//! - [`SampledSpectrum`]: a spectrum's values at K wavelengths (any
//!   [`Wavelengths`]), with point-wise arithmetic, in `f64` or `f32`
//!   ([`Float`]).
//! - [`validate`]: what makes samples a spectrum (shared with build
//!   scripts through `speclab_tables`).
//! - [`observer`]: the CIE 1931 x̄, ȳ, z̄ at any wavelength.
//! - [`Conductor`] (η and k; its [`NormalReflectance`]), [`Sellmeier`],
//!   [`Cauchy`]: optical constants as spectra.
//! - [`data`]: the built-in spectra, static data made at compile time:
//!   [`data::lights`] (the assignment's and the CIE's), [`data::patches`],
//!   [`data::conductors`], [`data::glasses`], [`data::daylight`],
//!   [`data::cie1931`].
//! - The range every integral and sampler covers: [`LAMBDA_MIN`] to
//!   [`LAMBDA_MAX`] (380–730 nm, width [`LAMBDA_WIDTH`] = 350 nm).
//!
//! This floor uses nothing above it: colour (`color`), sampling, reading
//! files (`io`) and the study build on it. It does not parse text.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::spectrum::observer;
//! let v = lights::F11.eval(545.0) * patches::G4.eval(545.0) * observer::xyz_bar(545.0)[1];
//! assert!(v > 0.0);
//! ```

mod analytic;
pub mod data;
mod dense;
mod dense_table;
pub(crate) mod float;
pub(crate) mod integrate;
mod interface;
pub(crate) mod lookup;
mod mixture;
pub mod observer;
mod optics;
pub(crate) mod piecewise;
pub(crate) mod pointwise;
mod product;
pub(crate) mod quadrature;
mod range;
mod sampled;
pub(crate) mod scaled;
pub(crate) mod sigmoid;
pub(crate) mod simd;
mod sprague;
mod standard_observer;
mod tabulated;
pub(crate) mod weights;

pub(crate) use speclab_tables::interp;
pub use speclab_tables::range::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH};
/// Validation of samples (`speclab_tables::validate`, whose pages its own
/// docs hold; its `Role` and `Interpolation` are this module's too).
#[doc(no_inline)]
pub use speclab_tables::validate;

pub use analytic::{Blackbody, Constant, FnSpectrum, PlanckConstants, planck};
pub use dense_table::DenseSpectrum;
pub use float::Float;
pub use interface::{Pieces, Samples, Spectrum};
pub use mixture::Mixture;
pub use observer::{AssignmentObserver, DenseObserver, Observer};
pub use optics::{Cauchy, Conductor, NormalReflectance, Sellmeier};
pub use product::{MAX_POWER, Product};
pub use range::WavelengthRange;
pub use sampled::{SampledSpectrum, Wavelengths};
pub use scaled::Scaled;
pub use sigmoid::{SigmoidPolynomial, sigmoid, sigmoid_f32};
pub use sprague::Sprague;
pub use standard_observer::{StandardObserver, Table as ObserverTable};
#[doc(hidden)]
pub use tabulated::Tables;
pub use tabulated::TabulatedSpectrum;
#[doc(no_inline)]
pub use validate::{Interpolation, Role};
