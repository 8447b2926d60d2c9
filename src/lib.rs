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
//! - a set of wavelengths with their XYZ weights ([`sampling`]), of two
//!   kinds told apart by type: drawn, a [`HeroSample<K>`] (random, with a
//!   pdf each), or fixed, a [`FixedWavelengths<M>`] (bucket centres or a
//!   rule fitted to the scene's lights; no pdf), and the `M` buckets of a
//!   [`RegularSpectrum<M>`];
//! - the values at them: [`SampledSpectrum<K>`] or the buckets' values,
//!   turned into [`Xyz`] and [`LinearRgb`] ([`color`]).
//!
//! Floors, each using only those below it: [`error`] and [`spectrum`] →
//! [`color`] → [`sampling`] → [`io`] (`ARCHITECTURE.md`).
//! Spectra are read by [`io`] at run time, or turned into static data at
//! compile time by the `speclab-tables` crate (the built-in data, [`data`],
//! is made so). This crate is the renderer's core: its dependencies are
//! `speclab-tables`, `wide` (the SIMD registers of the per-sample
//! arithmetic) and, by the default feature, the wide-gamut spaces' tables;
//! it draws no random numbers (a renderer brings its own sampler).
//! The accuracy study (trials, the comparison grid, charts and plans) is
//! the crate `speclab-study`, and what its programs show is `speclab-cli`.
//!
//! A renderer's inner loop, as one computing in `f32` writes it: its own
//! uniform numbers, spectra as dense 1 nm tables (the fast path, as
//! pbrt-v4's), one `HeroSample<4, f32>` per path carrying its wavelengths
//! and weights (`new` weighs by the dense observer), and XYZ at the end,
//! summed in `f64` (see [`spectrum::Float`] on long sums). No conversion
//! is written, and each operation runs four lanes at a time.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::reference, HeroSample, SampledSpectrum, Xyz};
//! use speclab::spectrum::DenseSpectrum;
//! let light = DenseSpectrum::new(&lights::F11); // once per scene
//! let walls = [&patches::G4, &patches::A1].map(DenseSpectrum::new);
//! let mut pixel = Xyz::ZERO;
//! for i in 0..1024_u16 {
//!     let u = (f32::from(i) + 0.5) / 1024.0; // the renderer's own number
//!     let path = HeroSample::<4, f32>::new(u); // one value per path
//!     let (le, mut beta, mut l) = (light.sample(&path), SampledSpectrum::splat(1.0), SampledSpectrum::zero());
//!     for wall in &walls {
//!         beta *= wall.sample(&path); // a bounce off each wall
//!         l += beta * le * 0.5; // and half the light seen there
//!     }
//!     pixel += path.to_xyz(l);
//! }
//! let pixel = pixel / 1024.0;
//! let g4 = reference::xyz(&lights::F11, &patches::G4);
//! let g4_a1 = reference::xyz_of_product(&[&lights::F11, &patches::G4, &patches::A1]);
//! let exact = (g4 + g4_a1) * 0.5;
//! assert!((pixel.y - exact.y).abs() < 2e-3 * exact.y, "{pixel:?} against {exact:?}");
//! ```
//!
//! The same loop as the reference computes it: `f64` (the default),
//! the exact interpolants of the tables, and the exact observer
//! ([`HeroSample::exact`]): unbiased for the exact integrals the
//! estimates are judged by.
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, SampledSpectrum, Xyz};
//! let mut pixel = Xyz::ZERO;
//! for i in 0..64 {
//!     let h = HeroSample::<4>::exact((i as f64 + 0.5) / 64.0);
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
// `unsafe` is allowed in two places alone: one block in
// `spectrum/lookup.rs`, and `spectrum/simd/x86.rs` (AVX2 loads, and calls
// into AVX2 code made only after the processor said it has it).
#![deny(unsafe_code)]

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The Rust blocks of every page of `docs/`, compiled and run.
#[cfg(doctest)]
mod doc_pages {
    #[doc = include_str!("../docs/accuracy.md")]
    pub struct Accuracy;
    #[doc = include_str!("../docs/chart-and-plans.md")]
    pub struct ChartAndPlans;
    #[doc = include_str!("../docs/color.md")]
    pub struct Color;
    #[doc = include_str!("../docs/convergence.md")]
    pub struct Convergence;
    #[doc = include_str!("../docs/film.md")]
    pub struct Film;
    #[doc = include_str!("../docs/fitted.md")]
    pub struct Fitted;
    #[doc = include_str!("../docs/gpu.md")]
    pub struct Gpu;
    #[doc = include_str!("../docs/grid.md")]
    pub struct Grid;
    #[doc = include_str!("../docs/library.md")]
    pub struct Library;
    #[doc = include_str!("../docs/named-data.md")]
    pub struct NamedData;
    #[doc = include_str!("../docs/published-rules.md")]
    pub struct PublishedRules;
    #[doc = include_str!("../docs/render.md")]
    pub struct Render;
    #[doc = include_str!("../docs/speed.md")]
    pub struct Speed;
    #[doc = include_str!("../docs/textures.md")]
    pub struct Textures;
}

pub mod color;
pub mod colorimetry;
pub mod error;
pub mod film;
pub mod io;
mod names;
pub mod sampling;
pub mod spectrum;

/// What `speclab_tables::Codegen` writes calls: not part of the API, and
/// not covered by semantic versioning.
#[doc(hidden)]
pub mod __codegen {
    pub use crate::spectrum::Tables;
    use crate::spectrum::{Interpolation, Role, TabulatedSpectrum};

    /// A spectrum over generated static tables (`None` if they do not fit
    /// together).
    #[must_use]
    pub const fn tabulated(role: Role, interpolation: Interpolation, t: Tables) -> Option<TabulatedSpectrum> {
        TabulatedSpectrum::from_static(role, interpolation, t)
    }
}

pub use color::{LinearRgb, Xyz};
pub use error::Error;
pub use sampling::{BoxAverage, Center, FixedWavelengths, HeroSample, RegularSpectrum};
#[doc(no_inline)]
pub use spectrum::{Interpolation, Role};
pub use spectrum::{
    LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, SampledSpectrum, Spectrum, TabulatedSpectrum, data,
};
