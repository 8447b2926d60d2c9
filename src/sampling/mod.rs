//! Where spectra are looked at, and how their product becomes XYZ.
//!
//! - Wavelengths with their XYZ weights, in `f64` or `f32`, of two kinds
//!   told apart by type: drawn, [`HeroSample<K, T>`] (K random wavelengths
//!   with a pdf each; K = 1 is plain random sampling, K = 4 the usual hero
//!   sampling), and fixed, [`FixedWavelengths<M, T>`] (a rule's, with no
//!   pdf); a spectrum sampled at either is a
//!   [`SampledSpectrum<K, T>`](crate::SampledSpectrum), and one weighted
//!   sum turns its values into XYZ (see [`wavelengths`]).
//! - [`RegularSpectrum<M, B, T>`](RegularSpectrum): M fixed buckets over
//!   380–730 nm, filled by center samples ([`Center`]) or exact bucket means
//!   ([`BoxAverage`]); [`buckets`]: the two rules.
//! - [`rule::Rule`]: M wavelengths and weights chosen at run time, buckets
//!   or [`fitted`] to a scene's lights over a reflectance prior
//!   (`prior.rs`); a renderer takes it as a `FixedWavelengths<M, T>`.
//! - [`pdf`]: wavelength densities (uniform, visible, following a light)
//!   behind the [`pdf::WavelengthPdf`] trait, and [`binned`]: any of them
//!   as equal-probability bins, sampled without a search.
//! - [`mod@reference`]: the exact integral, which the estimates are judged by;
//!   [`PreparedLight`]: the same as a dot product, for many reflectances;
//!   [`variance`]: the exact variance of one random or hero sample.
//!
//! One estimator serves all: XYZ ≈ Σ c̄(λ)·value(λ) / pdf(λ), averaged. A
//! strategy only chooses the wavelengths and their pdf. **A new wavelength
//! distribution** implements [`pdf::WavelengthPdf`] in `pdf.rs` or in the
//! renderer; [`Domain::new`] checks it against an observer once and
//! [`Domain::hero`] rotates it in primary-sample space, and the exact
//! variances and the study take it from there. Wavelengths from elsewhere
//! enter through [`HeroSample::from_wavelengths_with`].
//!
//! This floor uses the spectrum and colour floors below it.
//!
//! **From a renderer's own numbers.** Nothing here needs a random-number
//! generator: a renderer with its own sampler (Sobol', blue noise, a
//! hash) draws wavelengths from its uniform numbers with any pdf, or hands
//! over its own wavelengths:
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, Xyz};
//! use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
//! use speclab::{sampling::Domain, spectrum::DenseObserver};
//! let f11 = LightPdf::light(&lights::F11)?;
//! let pdfs: [&dyn WavelengthPdf; 3] = [&Uniform::ASSIGNMENT, &Visible::VISIBLE, &f11];
//! let n = 64;
//! // The renderer's own numbers, stratified over [0, 1/4): the hero rotations fill the rest.
//! let own = |i: usize| (i as f64 + 0.5) / (4 * n) as f64;
//! for pdf in pdfs {
//!     let domain = Domain::new(pdf, DenseObserver::CIE_1931)?; // checked once
//!     let mut pixel = Xyz::ZERO;
//!     for i in 0..n {
//!         let h = domain.hero::<4, f64>(own(i));
//!         pixel += h.to_xyz(h.sample(&lights::F11) * h.sample(&patches::G4));
//!     }
//!     let exact = speclab::sampling::reference::xyz(&lights::F11, &patches::G4);
//!     assert!(((pixel / n as f64).y - exact.y).abs() < 0.1 * exact.y);
//! }
//! // Or wavelengths and densities from the renderer's own distribution:
//! let h = HeroSample::from_wavelengths_with([450.0, 520.0, 610.0, 680.0], [1.0 / 350.0; 4], &DenseObserver::CIE_1931)?;
//! assert!(h.to_xyz(h.sample(&lights::D65)).y > 0.0);
//! # Ok::<(), speclab::Error>(())
//! ```
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, RegularSpectrum, sampling::reference};
//! let h = HeroSample::<4>::new(0.5);
//! let one = h.to_xyz(lights::A.sample(&h) * patches::H4.sample(&h));
//! let buckets = (RegularSpectrum::<16>::center(&lights::A) * RegularSpectrum::center(&patches::H4)).to_xyz();
//! let exact = reference::xyz(&lights::A, &patches::H4);
//! assert!((buckets.y - exact.y).abs() < 0.01 * exact.y && one.y > 0.0);
//! ```

mod analytic_pdf;
pub mod binned;
pub mod buckets;
mod density;
pub mod domain;
pub mod fitted;
pub mod hero;
mod light_pdf;
mod paths;
pub mod pdf;
mod prepared;
pub(crate) mod prior;
pub mod reference;
pub mod regular;
pub mod rule;
mod seed;
pub mod variance;
pub mod wavelengths;
mod widths;

pub use domain::Domain;
pub use hero::HeroSample;
pub use prepared::PreparedLight;
pub use regular::{AssignmentBand, Band, BoxAverage, Center, RegularSpectrum, VisibleBand};
pub use wavelengths::{Emission, FixedWavelengths};
pub use widths::{AtWidth, with_lanes};
