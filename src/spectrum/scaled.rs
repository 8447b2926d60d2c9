//! A spectrum times a factor, inline: [`Scaled`], what `light * 4.0`
//! makes of a built-in kind of spectrum (a pbrt-v4 scene's `"scale"`, a
//! Mitsuba 3 emitter's intensity). No allocation, no `Result`: the
//! spectrum is borrowed (or owned) and the factor kept beside it.
//! `TabulatedSpectrum::scaled` makes a new table instead.
//!
//! ```
//! use speclab::{data::{lights, patches}, Spectrum, spectrum::Scaled};
//! use speclab::sampling::{reference, HeroSample};
//! let bright = &lights::D65 * 4.0;
//! assert_eq!(bright.eval(555.0), 4.0 * lights::D65.eval(555.0));
//! let h = HeroSample::<4>::new(0.3);
//! assert_eq!(h.sample(&bright), h.sample(&lights::D65) * 4.0);
//! let (once, four) = (reference::xyz(&lights::D65, &patches::G4), reference::xyz(&bright, &patches::G4));
//! assert!((four.y - 4.0 * once.y).abs() < 1e-12 * four.y);
//! let own = Scaled::new(speclab::spectrum::FnSpectrum(|l: f64| l), 0.5); // any spectrum
//! assert_eq!(own.eval(500.0), 250.0);
//! ```

use std::borrow::Cow;
use std::ops::Mul;

use crate::spectrum::float::Float;
use crate::spectrum::interface::{Pieces, Spectrum};
use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};
use crate::spectrum::{Blackbody, Constant, DenseSpectrum, Mixture, Product, TabulatedSpectrum};

/// `factor · spectrum(λ)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scaled<S> {
    spectrum: S,
    factor: f64,
}

impl<S> Scaled<S> {
    /// `factor` times `spectrum`.
    #[must_use]
    pub const fn new(spectrum: S, factor: f64) -> Self {
        Scaled { spectrum, factor }
    }

    /// The factor.
    #[must_use]
    pub const fn factor(&self) -> f64 {
        self.factor
    }

    /// The spectrum scaled.
    #[must_use]
    pub const fn spectrum(&self) -> &S {
        &self.spectrum
    }
}

impl<S: Spectrum> Spectrum for Scaled<S> {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.factor * self.spectrum.eval(lambda)
    }

    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        self.spectrum.eval_many(lambda, values);
        values.iter_mut().for_each(|v| *v *= self.factor);
    }

    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        self.spectrum.eval_many_f32(lambda, values);
        let factor = f32::from_f64(self.factor);
        values.iter_mut().for_each(|v| *v *= factor);
    }

    fn eval_many_nearest(&self, lambda: &[f64], nearest: &[u16], values: &mut [f64]) {
        self.spectrum.eval_many_nearest(lambda, nearest, values);
        values.iter_mut().for_each(|v| *v *= self.factor);
    }

    fn eval_many_nearest_f32(&self, lambda: &[f32], nearest: &[u16], values: &mut [f32]) {
        self.spectrum.eval_many_nearest_f32(lambda, nearest, values);
        let factor = f32::from_f64(self.factor);
        values.iter_mut().for_each(|v| *v *= factor);
    }

    /// The spectrum's own `sample` (a dense table's one load), scaled.
    #[inline]
    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        self.spectrum.sample(at) * T::from_f64(self.factor)
    }

    /// The spectrum's: a polynomial times a constant is one of the same
    /// degree.
    fn pieces(&self) -> Option<Pieces<'_>> {
        self.spectrum.pieces()
    }

    fn kinks(&self) -> Cow<'_, [f64]> {
        self.spectrum.kinks()
    }

    fn running_integral(&self, lambda: f64) -> Option<f64> {
        self.spectrum.running_integral(lambda).map(|v| self.factor * v)
    }

    /// The spectrum's maximum times a non-negative factor (exact where the
    /// spectrum's is); `+∞` for a negative one.
    fn max_value(&self) -> f64 {
        if self.factor >= 0.0 { self.factor * self.spectrum.max_value() } else { f64::INFINITY }
    }
}

/// `&spectrum * factor` for the crate's spectra (those of the colour floor
/// say so there).
macro_rules! scale_by_mul {
    ($($ty:ty),* $(,)?) => {$(
        impl<'a> ::std::ops::Mul<f64> for &'a $ty {
            type Output = $crate::spectrum::Scaled<Self>;
            /// The spectrum scaled by `factor`, borrowed: no allocation.
            fn mul(self, factor: f64) -> Self::Output {
                $crate::spectrum::Scaled::new(self, factor)
            }
        }
    )*};
}

pub(crate) use scale_by_mul;

scale_by_mul!(TabulatedSpectrum, DenseSpectrum, Constant, Blackbody, Mixture<'_>, Product<'_>);

impl<S> Mul<f64> for Scaled<S> {
    type Output = Scaled<S>;
    /// The factors multiplied.
    fn mul(self, factor: f64) -> Scaled<S> {
        Scaled { factor: self.factor * factor, ..self }
    }
}
