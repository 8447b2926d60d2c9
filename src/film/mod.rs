//! The film: what a renderer's samples become. A [`Sensor`] (a CIE
//! observer, or a camera's r, g, b curves) weighs wavelengths; a
//! [`SpectralFilm`] keeps M buckets per pixel of what hero samples carried,
//! divided by their pdfs; [`Develop`] turns the [`SpectralImage`] it makes
//! (or one read from a file) into XYZ under a sensor, a light, a sensor →
//! XYZ matrix ([`Sensor::fit_xyz`]), a [`WhiteBalance`] and an exposure.
//!
//! Units: wavelengths in nm; a film's values are the mean spectral value
//! per nm over each bucket (radiance for an emissive image, a ratio to
//! the light for a reflective one); XYZ in those units times nm, as
//! [`HeroSample::to_xyz`](crate::HeroSample::to_xyz) gives them.
//!
//! A reflective film of a scene lit by one light keeps each path's
//! throughput without the light (a wavelength's radiance is linear in
//! that light's power there), so the image can be developed under any
//! light afterwards, exactly per wavelength and to the buckets' width
//! across them.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::film::{Buckets, Develop, Kind, Sensor, SpectralFilm};
//! use speclab::sampling::pdf::Uniform;
//! use speclab::spectrum::{StandardObserver, WavelengthRange};
//! use speclab::HeroSample;
//!
//! // 1 × 1 pixel, 35 buckets of 10 nm over 380–730 nm: a grey card's
//! // reflectance, kept without the light.
//! let buckets = Buckets::new(WavelengthRange::ASSIGNMENT, 35)?;
//! let mut film = SpectralFilm::new((1, 1), buckets, Kind::Reflective)?;
//! let sensor = Sensor::observer(StandardObserver::Cie1931);
//! for i in 0..1024 {
//!     let h = HeroSample::<4>::from_pdf_with((i as f64 + 0.5) / 1024.0, &Uniform::ASSIGNMENT, &sensor)?;
//!     film.splat((0, 0), &h, patches::A1.sample(&h))?;
//! }
//! // Developed under D65 and under A: the card's colour under each.
//! let image = film.image();
//! for light in [&lights::D65, &lights::A] {
//!     let xyz = Develop::new(sensor.clone()).light(light).xyz(&image)?[0];
//!     let exact = speclab::colorimetry::Tristimulus::new(
//!         StandardObserver::Cie1931, WavelengthRange::ASSIGNMENT, 1.0)?.absolute(light, &patches::A1);
//!     assert!((xyz.y - exact.y).abs() < 0.01 * exact.y, "{xyz:?} against {exact:?}");
//! }
//! # Ok::<(), speclab::Error>(())
//! ```

mod balance;
mod develop;
mod image;
mod sensor;
mod spectral;

pub use balance::WhiteBalance;
pub use develop::{Develop, Quadrature};
pub use image::{Kind, SpectralImage};
pub use sensor::{Sensor, SensorFit};
pub use spectral::{Buckets, FilmRow, SpectralFilm};

#[cfg(test)]
mod film_tests;
#[cfg(test)]
mod tests;
