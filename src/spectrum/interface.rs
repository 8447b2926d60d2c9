//! What every spectrum answers: [`Spectrum`], one interface over tabulated,
//! dense, constant, blackbody, RGB-derived and a renderer's own spectra.
//!
//! A spectrum gives its value at any wavelength in nanometres ([`eval`],
//! and [`eval_many`] / [`eval_many_f32`] for many at once), and its values
//! at K wavelengths as a [`SampledSpectrum<K, T>`] in `f64` or `f32`
//! ([`sample`]). Everything that integrates or
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
//! **Fast paths are capabilities, not types.** Every path the built-in
//! tables take is open to any spectrum that says what it can do: its
//! own `sample` (a dense table's one load per wavelength), its exact
//! [`running_integral`](Spectrum::running_integral) in O(1) (box
//! buckets), its polynomial
//! [`pieces`](Spectrum::pieces) (exact integration), the
//! [`samples`](Spectrum::samples) it interpolates (the reference as a dot
//! product, light pdfs from its polynomials). What is computed from a
//! spectrum once (a light's exact weights, its pdf, a fitted rule) is an
//! explicit value its owner keeps (`sampling::PreparedLight`,
//! `sampling::pdf::LightPdf`, `sampling::fitted::FittedRules`).
//!
//! [`eval`]: Spectrum::eval
//! [`eval_many`]: Spectrum::eval_many
//! [`eval_many_f32`]: Spectrum::eval_many_f32
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
//! use speclab::{data::lights, HeroSample, LinearRgb, RegularSpectrum, Xyz};
//! use speclab::sampling::reference;
//! use speclab::spectrum::{FnSpectrum};
//! use speclab::color::RgbAlbedo;
//! let paint = FnSpectrum(|l: f64| 0.2 + 0.6 / (1.0 + ((600.0 - l) / 20.0).exp())); // reddish
//! let texture = RgbAlbedo::new(LinearRgb::new(0.1, 0.5, 0.2))?; // greenish
//! for (surface, red) in [(&paint as &dyn speclab::Spectrum, true), (&texture, false)] {
//!     let h = HeroSample::<4>::new(0.5);
//!     let one = h.to_xyz(h.sample(&lights::D65) * h.sample(&surface));
//!     let exact = reference::xyz(&lights::D65, &surface);
//!     let buckets = (RegularSpectrum::<16>::center(&lights::D65) * RegularSpectrum::center(&surface)).to_xyz();
//!     let n = 1000;
//!     let mean = (0..n).map(|i| {
//!         let h = HeroSample::<4>::exact((i as f64 + 0.5) / n as f64);
//!         h.to_xyz(h.sample(&lights::D65) * h.sample(&surface))
//!     }).sum::<Xyz>() / n as f64;
//!     assert!(one.y > 0.0 && (buckets.y - exact.y).abs() < 0.02 * exact.y);
//!     assert!((mean.y - exact.y).abs() < 0.02 * exact.y);
//!     let rgb = exact.to_linear_srgb();
//!     assert_eq!(rgb.r > rgb.g, red);
//! }
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;

use crate::spectrum::dense_table::DenseSpectrum;
use crate::spectrum::float::Float;
use crate::spectrum::float::sealed::Precision;
use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};
use crate::spectrum::validate::{Interpolation, Role};

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

/// The samples a spectrum interpolates, and how: the spectrum is the
/// clamped interpolant of `values` at `lambda` by `interpolation`, within
/// the bounds of `role`, and zero outside `lambda` (as a
/// `TabulatedSpectrum` of them would be).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Samples<'a> {
    /// The wavelengths, nm, strictly increasing.
    pub lambda: &'a [f64],
    /// The value at each.
    pub values: &'a [f64],
    /// Linear or cubic.
    pub interpolation: Interpolation,
    /// What the spectrum is (its clamp bounds).
    pub role: Role,
}

/// A spectrum: a value at every wavelength, in nanometres.
pub trait Spectrum {
    /// The value at `lambda` nm.
    fn eval(&self, lambda: f64) -> f64;

    /// The values at `lambda`, into `values` (as many as the shorter of
    /// the two). Override it for speed: [`Spectrum::sample`] and every
    /// estimator in `f64` evaluate through it.
    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = self.eval(l);
        }
    }

    /// [`Spectrum::eval_many`] in `f32`: by default each value is
    /// evaluated in `f64` and rounded.
    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = f32::from_f64(self.eval(f64::from(l)));
        }
    }

    /// [`Spectrum::eval_many`] at wavelengths whose nearest whole
    /// nanometres are known (`nearest`, as
    /// [`Wavelengths::nearest_nm`] finds them: a hero sample finds them once,
    /// when drawn). A dense table reads its entries there instead of
    /// finding them; by default `nearest` is ignored. This is how the fast
    /// lookup reaches a spectrum behind `&dyn Spectrum` or
    /// `Box<dyn Spectrum>`.
    fn eval_many_nearest(&self, lambda: &[f64], nearest: &[u16], values: &mut [f64]) {
        let _ = nearest;
        self.eval_many(lambda, values);
    }

    /// [`Spectrum::eval_many_nearest`] in `f32`.
    fn eval_many_nearest_f32(&self, lambda: &[f32], nearest: &[u16], values: &mut [f32]) {
        let _ = nearest;
        self.eval_many_f32(lambda, values);
    }

    /// The spectrum as a dense table, if it is one: how a dense table's
    /// lookup (one load per wavelength, its count known at compile time)
    /// reaches it behind `&dyn Spectrum`, `Box<dyn Spectrum>` or a
    /// renderer's own wrapper, through [`Spectrum::sample`]. `None` by
    /// default.
    fn as_dense(&self) -> Option<&DenseSpectrum> {
        None
    }

    /// The values at K wavelengths (a hero sample's, a fixed rule's, or a
    /// `[T; K]`), in the wavelengths' precision `T`. By default a dense
    /// table's lookup where [`Spectrum::as_dense`] finds one, and
    /// otherwise through [`Spectrum::eval_many_nearest`] or
    /// [`Spectrum::eval_many_nearest_f32`] (so through a reference or a box
    /// too); a spectrum with a faster way overrides it.
    #[inline]
    #[must_use]
    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T>
    where
        Self: Sized,
    {
        if let Some(dense) = self.as_dense() {
            return dense.sample(at);
        }
        let mut values = [T::ZERO; K];
        let nearest = at.nearest_nm();
        match T::lanes(at.lambda(), &mut values) {
            Precision::F32 { lambda, values } => self.eval_many_nearest_f32(lambda, &nearest, values),
            Precision::F64 { lambda, values } => self.eval_many_nearest(lambda, &nearest, values),
        }
        SampledSpectrum::new(values)
    }

    /// Where the spectrum is a polynomial, if it is piecewise polynomial
    /// (then its integrals are exact); `None` for other spectra, which are
    /// integrated by quadrature.
    fn pieces(&self) -> Option<Pieces<'_>> {
        None
    }

    /// Where the spectrum may bend (its slope jump), nm, sorted: a
    /// piecewise polynomial's breaks, and for another spectrum the breaks
    /// of a table it is built on (a tinted illuminant's), so that
    /// quadrature splits there. Empty by default.
    fn kinks(&self) -> Cow<'_, [f64]> {
        self.pieces().map_or(Cow::Borrowed(&[]), |p| p.breaks)
    }

    /// The samples the spectrum interpolates, if it is the interpolant of
    /// samples (a table): the exact reference then takes a light's weights
    /// for them, and a light pdf their polynomials.
    fn samples(&self) -> Option<Samples<'_>> {
        None
    }

    /// The exact integral of the spectrum from its start (−∞) up to
    /// `lambda` nm, if the spectrum has it at hand (a table's running sums:
    /// O(1)); box buckets take differences of it. `None` (the default)
    /// makes callers integrate piece by piece.
    fn running_integral(&self, _lambda: f64) -> Option<f64> {
        None
    }

    /// The largest value the spectrum takes between 360 and 830 nm (the
    /// widest range a sampler draws from), or a bound above it, as pbrt-v4's
    /// `MaxValue`, for sampling and clamping: exact for tables (the
    /// interpolant's maximum, not only the samples'), dense tables,
    /// constants, blackbodies and sigmoid polynomials; a bound for
    /// mixtures, products, RGB illuminants and metals (each kind's
    /// documentation says which). By default `+∞`: a spectrum that says
    /// nothing of itself (a closure) is bounded by nothing.
    fn max_value(&self) -> f64 {
        f64::INFINITY
    }
}

/// A reference, a box or a shared pointer to a spectrum is the spectrum.
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
            #[inline]
            fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
                (**self).eval_many_f32(lambda, values);
            }
            #[inline]
            fn eval_many_nearest(&self, lambda: &[f64], nearest: &[u16], values: &mut [f64]) {
                (**self).eval_many_nearest(lambda, nearest, values);
            }
            #[inline]
            fn eval_many_nearest_f32(&self, lambda: &[f32], nearest: &[u16], values: &mut [f32]) {
                (**self).eval_many_nearest_f32(lambda, nearest, values);
            }
            #[inline]
            fn as_dense(&self) -> Option<&DenseSpectrum> {
                (**self).as_dense()
            }
            fn pieces(&self) -> Option<Pieces<'_>> {
                (**self).pieces()
            }
            fn kinks(&self) -> Cow<'_, [f64]> {
                (**self).kinks()
            }
            fn samples(&self) -> Option<Samples<'_>> {
                (**self).samples()
            }
            fn running_integral(&self, lambda: f64) -> Option<f64> {
                (**self).running_integral(lambda)
            }
            fn max_value(&self) -> f64 {
                (**self).max_value()
            }
        }
    )*};
}

forward_spectrum!(&S, Box<S>, std::sync::Arc<S>, std::rc::Rc<S>);

/// The sorted union of `sets` of wavelengths.
pub(crate) fn union<'a>(sets: impl Iterator<Item = Cow<'a, [f64]>>) -> Cow<'a, [f64]> {
    let mut all: Vec<f64> = sets.flat_map(|s| s.into_owned()).collect();
    all.sort_by(f64::total_cmp);
    all.dedup();
    Cow::Owned(all)
}
