//! # speclab: light–surface arithmetic for spectral rendering
//!
//! Spectra of lights and surfaces, their point-wise product, its conversion
//! to CIE XYZ and linear sRGB, and ways of sampling wavelengths with a known
//! cost and error, checked against an exact reference.
//!
//! Three nouns (see `ARCHITECTURE.md`):
//! - a continuous spectrum, anything that implements [`Spectrum`]
//!   ([`TabulatedSpectrum`], dense, constant, blackbody, RGB-derived or a
//!   closure), evaluated at any wavelength in nanometres ([`spectrum`]);
//! - a set of wavelengths: a [`HeroSample<K>`] (random, with a pdf each),
//!   the `M` buckets of a [`RegularSpectrum<M>`] (fixed) or the `M`
//!   wavelengths of a rule fitted to the scene's lights ([`sampling`]);
//! - the values at them: [`SampledSpectrum<K>`] or the buckets' values,
//!   turned into [`Xyz`] and [`LinearSrgb`] ([`color`]).
//!
//! Floors, each using only those below it: [`error`] and [`spectrum`] →
//! [`color`] → [`sampling`] → [`io`] → `study` (`ARCHITECTURE.md`;
//! `tests/floors.rs` checks the `use` lines). Spectra are read by [`io`] at
//! run time, or turned into static data at compile time by the
//! `speclab-tables` crate (the built-in data, [`data`], is made so). The
//! accuracy study (`speclab::study`: trials, ΔE00, the comparison grid) is behind
//! the default feature `study`; a renderer can leave it out with
//! `default-features = false`, which leaves `rand` (re-exported as
//! [`rand`], the version the API names) and `speclab-tables` as the only
//! dependencies.
//!
//! A renderer's inner loop, per sample:
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, SampledSpectrum, Xyz};
//! let mut pixel = Xyz::ZERO;
//! for i in 0..64 {
//!     let h = HeroSample::<4>::new((i as f64 + 0.5) / 64.0);
//!     let (le, albedo) = (lights::D65.sample(&h), patches::F4.sample(&h));
//!     let (mut beta, mut l) = (SampledSpectrum::splat(1.0), SampledSpectrum::zero());
//!     for _bounce in 0..2 {
//!         beta *= albedo; // reflect off the patch
//!         l += beta * le; // and see the light
//!     }
//!     pixel += h.to_xyz(l);
//! }
//! let pixel = pixel / 64.0;
//! assert!(pixel.y > 0.0 && pixel.to_linear_srgb().g > pixel.to_linear_srgb().r);
//! ```

#![warn(missing_docs)]

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub mod color;
pub mod error;
#[doc(hidden)]
pub mod fuzzing;
pub mod io;
pub mod sampling;
pub mod spectrum;
#[cfg(feature = "study")]
pub mod study;

pub use color::{LinearSrgb, Xyz};
pub use error::Error;
pub use rand;
pub use sampling::{BoxAverage, Center, HeroSample, RegularSpectrum};
pub use spectrum::{
    Interpolation, LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, Role, SampledSpectrum, Spectrum, TabulatedSpectrum,
    data,
};
