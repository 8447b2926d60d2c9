//! # speclab: light–surface arithmetic for spectral rendering
//!
//! Spectra of lights and surfaces, their point-wise product, its conversion
//! to CIE XYZ and linear sRGB, and three ways of sampling wavelengths with
//! a known cost and error, checked against an exact reference.
//!
//! Three nouns (see `ARCHITECTURE.md`):
//! - a continuous spectrum, [`TabulatedSpectrum`], evaluated at any
//!   wavelength in nanometres;
//! - a set of wavelengths: a [`HeroSample<K>`] (random) or the `M` buckets of
//!   a [`RegularSpectrum<M>`] (fixed);
//! - the values at them: [`SampledSpectrum<K>`] or the buckets' values.
//!
//! ```
//! use rand::{SeedableRng, rngs::StdRng};
//! use speclab::{data, hero, reference, RegularSpectrum};
//! let exact = reference::xyz(&data::D65, &data::F4).to_linear_srgb();
//! let n = std::num::NonZeroUsize::new(100).unwrap();
//! let mut rng = StdRng::seed_from_u64(1);
//! let by_hero = hero::estimate::<4, _>(&data::D65, &data::F4, n, &mut rng).to_linear_srgb();
//! let buckets = RegularSpectrum::<16>::centre(&data::D65) * RegularSpectrum::centre(&data::F4);
//! let by_buckets = buckets.to_xyz().to_linear_srgb();
//! assert!((exact.g - 24.67).abs() < 0.01);
//! assert!(by_hero.distance(exact) < 5.0 && by_buckets.distance(exact) < 5.0);
//! ```

#![warn(missing_docs)]

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub mod color;
pub mod columns;
pub mod data;
pub mod error;
#[doc(hidden)]
pub mod fuzzing;
pub mod grid;
pub mod hero;
pub mod interp;
pub mod json;
pub mod load;
pub mod method;
pub mod observer;
pub mod parse;
pub mod perceptual;
pub mod reference;
pub mod regular;
pub mod remarks;
pub mod samples;
pub mod spectrum;
pub mod study;
pub mod variance;

pub use color::{LinearSrgb, Xyz};
pub use error::Error;
pub use hero::{HeroSample, SampledSpectrum};
pub use regular::{BoxAverage, Centre, RegularSpectrum};
pub use samples::{Interpolation, Role};
pub use spectrum::TabulatedSpectrum;

/// Lower end of the integration and sampling range, nm.
pub const LAMBDA_MIN: f64 = 380.0;
/// Upper end of the integration and sampling range, nm.
pub const LAMBDA_MAX: f64 = 730.0;
/// Width W of the range, nm.
pub const WIDTH: f64 = LAMBDA_MAX - LAMBDA_MIN;
