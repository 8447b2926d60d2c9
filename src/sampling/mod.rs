//! Where spectra are looked at, and how their product becomes XYZ.
//!
//! - [`HeroSample<K>`]: K random wavelengths with a pdf each (K = 1 is
//!   plain random sampling, K = 4 the usual hero sampling);
//!   [`SampledSpectrum<K>`]: a spectrum's values at them.
//! - [`RegularSpectrum<M, B>`](RegularSpectrum): M fixed buckets over
//!   380–730 nm, filled by centre samples ([`Centre`]) or exact bucket means
//!   ([`BoxAverage`]).
//! - [`pdf`]: wavelength densities (uniform, visible, following a light)
//!   behind the [`pdf::WavelengthPdf`] trait; [`strata`]: how the primary
//!   numbers of an estimate are spread (independent, jittered, Kronecker).
//! - [`reference`]: the exact integral, which the estimates are judged by;
//!   [`PreparedLight`]: the same as a dot product, for many reflectances.
//!
//! One estimator serves all: XYZ ≈ Σ c̄(λ)·value(λ) / pdf(λ), averaged. A
//! strategy only chooses the wavelengths and their pdf. **A new wavelength
//! distribution** implements [`pdf::WavelengthPdf`] (`sample`, `pdf`,
//! `cdf`) in `pdf.rs` or in the renderer; [`HeroSample::from_pdf`] rotates
//! it in primary-sample space, and [`hero::estimate_with`], the exact
//! variances and the study take it from there. Wavelengths from elsewhere
//! enter through [`HeroSample::with_pdf`].
//!
//! ```
//! use speclab::{data, HeroSample, RegularSpectrum, sampling::reference};
//! let h = HeroSample::<4>::new(0.5);
//! let one = h.to_xyz(data::A.sample(&h) * data::H4.sample(&h));
//! let buckets = (RegularSpectrum::<16>::centre(&data::A) * RegularSpectrum::centre(&data::H4)).to_xyz();
//! let exact = reference::xyz(&data::A, &data::H4);
//! assert!((buckets.y - exact.y).abs() < 0.01 * exact.y && one.y > 0.0);
//! ```

pub mod hero;
pub(crate) mod light_pdf;
pub mod pdf;
mod prepared;
pub(crate) mod quadrature;
pub mod reference;
pub mod regular;
mod sampled;
pub mod strata;
pub(crate) mod weights;

pub use hero::HeroSample;
pub use prepared::PreparedLight;
pub use regular::{BoxAverage, Centre, RegularSpectrum};
pub use sampled::SampledSpectrum;
