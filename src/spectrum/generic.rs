//! What every spectrum answers: [`Spectrum`], one interface over tabulated,
//! dense, constant, blackbody, RGB-derived and a renderer's own spectra.
//!
//! A spectrum gives its value at any wavelength in nanometres ([`eval`],
//! and [`eval_many`] for many at once), and its values at K wavelengths
//! as a [`SampledSpectrum<K>`] ([`sample`]). Everything that integrates or
//! samples a spectrum takes any `Spectrum`: integration is **exact** where
//! the spectrum says it is piecewise polynomial ([`pieces`]), and otherwise
//! by Gauss–Legendre quadrature on pieces of at most 5 nm with more points
//! than the polynomial part needs (see `integrate.rs`; for the smooth
//! spectra of this crate, blackbody and sigmoid polynomials, within about
//! 1e-12 relative, tested against a rule with twice the points).
//!
//! The trait is object-safe: a renderer holds mixed spectra as
//! `Box<dyn Spectrum + Send + Sync>` (or `&dyn Spectrum`), and those are
//! spectra too.
//!
//! [`eval`]: Spectrum::eval
//! [`eval_many`]: Spectrum::eval_many
//! [`sample`]: Spectrum::sample
//! [`pieces`]: Spectrum::pieces
//!
//! ```
//! use speclab::{data::lights, HeroSample, Spectrum};
//! use speclab::spectrum::{Constant, FnSpectrum};
//! let mixed: Vec<Box<dyn Spectrum + Send + Sync>> = vec![
//!     Box::new(lights::D65.clone()),
//!     Box::new(Constant::new(0.5)),
//!     Box::new(FnSpectrum(|l: f64| (l - 380.0) / 350.0)), // a ramp
//! ];
//! let h = HeroSample::<4>::new(0.25);
//! let values: Vec<_> = mixed.iter().map(|s| s.sample(&h)).collect();
//! assert_eq!(values[1].values, [0.5; 4]);
//! assert_eq!(values[2].values[0], mixed[2].eval(h.lambda()[0]));
//! ```
//!
//! A renderer's own spectrum and an RGB texture's albedo go through every
//! path unchanged: a hero sample, the exact reference, buckets and the
//! Monte Carlo estimate.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use rand::{SeedableRng, rngs::StdRng};
//! use speclab::{data::lights, HeroSample, LinearSrgb, RegularSpectrum};
//! use speclab::sampling::{hero, reference};
//! use speclab::spectrum::{FnSpectrum, RgbAlbedo};
//! let paint = FnSpectrum(|l: f64| 0.2 + 0.6 / (1.0 + ((600.0 - l) / 20.0).exp())); // reddish
//! let texture = RgbAlbedo::new(LinearSrgb::new(0.1, 0.5, 0.2))?; // greenish
//! for (surface, red) in [(&paint as &dyn speclab::Spectrum, true), (&texture, false)] {
//!     let h = HeroSample::<4>::new(0.5);
//!     let one = h.to_xyz(h.sample(&lights::D65) * h.sample(&surface));
//!     let exact = reference::xyz(&lights::D65, &surface);
//!     let buckets = (RegularSpectrum::<16>::center(&lights::D65) * RegularSpectrum::center(&surface)).to_xyz();
//!     let n = NonZeroUsize::new(1000).unwrap();
//!     let mean = hero::estimate::<4, _>(&lights::D65, &surface, n, &mut StdRng::seed_from_u64(1));
//!     assert!(one.y > 0.0 && (buckets.y - exact.y).abs() < 0.02 * exact.y);
//!     assert!((mean.y - exact.y).abs() < 0.02 * exact.y);
//!     let rgb = exact.to_linear_srgb();
//!     assert_eq!(rgb.r > rgb.g, red);
//! }
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;

use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};
use crate::spectrum::tabulated::TabulatedSpectrum;

/// Where a spectrum is a polynomial: between consecutive `breaks` (nm,
/// sorted), and below the first and above the last, it is one polynomial of
/// degree at most `degree`. No breaks: one polynomial everywhere.
#[derive(Clone, Debug, PartialEq)]
pub struct Pieces<'a> {
    /// The points where the polynomial changes, nm, sorted.
    pub breaks: Cow<'a, [f64]>,
    /// The largest degree of a piece.
    pub degree: usize,
}

/// A spectrum: a value at every wavelength, in nanometres.
pub trait Spectrum {
    /// The value at `lambda` nm.
    fn eval(&self, lambda: f64) -> f64;

    /// The values at `lambda`, into `values` (as many as the shorter of
    /// the two). Override it for speed: [`Spectrum::sample`] and every
    /// estimator evaluate through it.
    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = self.eval(l);
        }
    }

    /// The values at K wavelengths (a `HeroSample<K>`'s, or a `[f64; K]`).
    #[inline]
    #[must_use]
    fn sample<const K: usize>(&self, at: &impl Wavelengths<K>) -> SampledSpectrum<K>
    where
        Self: Sized,
    {
        let mut values = [0.0; K];
        self.eval_many(at.lambda(), &mut values);
        SampledSpectrum::new(values)
    }

    /// Where the spectrum is a polynomial, if it is piecewise polynomial
    /// (then its integrals are exact); `None` for other spectra, which are
    /// integrated by quadrature.
    fn pieces(&self) -> Option<Pieces<'_>> {
        None
    }

    /// The table behind the spectrum, if it is a [`TabulatedSpectrum`]: the
    /// exact reference and bucket means take faster exact paths for tables.
    fn as_tabulated(&self) -> Option<&TabulatedSpectrum> {
        None
    }
}

/// A reference or a box to a spectrum is the spectrum.
macro_rules! forward_spectrum {
    ($($pointer:ty),*) => {$(
        impl<S: Spectrum + ?Sized> Spectrum for $pointer {
            #[inline]
            fn eval(&self, lambda: f64) -> f64 {
                (**self).eval(lambda)
            }
            #[inline]
            fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
                (**self).eval_many(lambda, values);
            }
            fn pieces(&self) -> Option<Pieces<'_>> {
                (**self).pieces()
            }
            fn as_tabulated(&self) -> Option<&TabulatedSpectrum> {
                (**self).as_tabulated()
            }
        }
    )*};
}

forward_spectrum!(&S, Box<S>);
