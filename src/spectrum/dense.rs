//! Dense tables: any spectrum at every whole nanometre from 360 to 830 nm,
//! kept in `f32` and `f64`, looked up at the nearest one: the fast
//! tabulated path, as pbrt-v4's `DenselySampledSpectrum` (also 1 nm, also
//! rounded). Wavelengths in `f32` read the `f32` table, in `f64` the `f64`
//! one: the table has no precision of its own to choose.
//!
//! A hero sample finds each wavelength's nearest whole nanometre once,
//! when it is drawn ([`Wavelengths::nearest_nm`]); a [`DenseSpectrum`]
//! sampled at it is then one load per wavelength, with no conversion and
//! no interpolation, and a [`DenseObserver`] gives the wavelength's x̄, ȳ,
//! z̄ as one 16-byte (`f32`) row. Outside 360–830 nm a dense table is
//! zero (and so is a spectrum outside its own data: the assignment's
//! patches beyond 730 nm).
//!
//! **Accuracy** (measured in `tests/properties/dense.rs`). Point by point a dense
//! table is a step: off its source by up to half a nanometre's change (the
//! largest |dense − source| over 380–730 nm, every 0.01 nm: 0.014 for the
//! patches' reflectances, 0.040 for the observer, 4.6 for F11 beside its
//! lines, whose peak is 72.8). Integrals are what estimates see: the
//! integral of a product of steps is the 1 nm midpoint sum of the product,
//! whose error is second order. The exact XYZ of a dense light times a
//! dense patch differs from the tables' by at most 1e-4 relative in any
//! channel over the 18 light × patch pairs (A 8.1e-5, D65 6.4e-5, F11
//! 9.3e-5), in `f64` and in `f32` alike (an `f32` table's rounding is
//! about 6e-8 relative). An emission line narrower than a nanometre is
//! seen only at the whole nanometre nearest to it.
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, sampling::reference};
//! use speclab::spectrum::DenseSpectrum;
//! let (light, surface) = (DenseSpectrum::new(&lights::F11), DenseSpectrum::new(&patches::H4));
//! let mut pixel = speclab::Xyz::ZERO;
//! for i in 0..256_u16 {
//!     // `new` weighs by the dense observer (`with_observer(u, &DenseObserver::ASSIGNMENT)?`).
//!     let h = HeroSample::<4, f32>::new((f32::from(i) + 0.5) / 256.0);
//!     pixel += h.to_xyz(light.sample(&h) * surface.sample(&h));
//! }
//! let exact = reference::xyz(&lights::F11, &patches::H4);
//! assert!((pixel.y / 256.0 - exact.y).abs() < 1e-2 * exact.y);
//! ```

use std::borrow::Cow;

use crate::spectrum::dense_table::DenseSpectrum;
use crate::spectrum::float::Float;
use crate::spectrum::interface::{Pieces, Spectrum};
use crate::spectrum::lookup::{DENSE_ENTRIES, DENSE_RANGE, DENSE_VALUES, nearest_nm};
use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};

impl DenseSpectrum {
    /// `s` at every whole nanometre from 360 to 830 (and rounded to `f32`).
    #[must_use]
    pub fn new(s: &(impl Spectrum + ?Sized)) -> Self {
        let knots: Vec<f64> = (0..DENSE_VALUES).map(|i| DENSE_RANGE.min() + i as f64).collect();
        let mut at = vec![0.0; knots.len()];
        s.eval_many(&knots, &mut at);
        let values: [f64; DENSE_ENTRIES] = std::array::from_fn(|i| at.get(i).copied().unwrap_or(0.0));
        DenseSpectrum::from_values(values)
    }
}

impl Spectrum for DenseSpectrum {
    #[inline(always)]
    fn eval(&self, lambda: f64) -> f64 {
        self.at::<f64>(nearest_nm(lambda))
    }

    #[inline(always)]
    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = self.eval(l);
        }
    }

    #[inline(always)]
    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = self.at::<f32>(nearest_nm(f64::from(l)));
        }
    }

    /// One load per wavelength, at the known nearest whole nanometres.
    #[inline(always)]
    fn eval_many_nearest(&self, _lambda: &[f64], nearest: &[u16], values: &mut [f64]) {
        for (v, &i) in values.iter_mut().zip(nearest) {
            *v = self.at::<f64>(i);
        }
    }

    /// One load per wavelength, at the known nearest whole nanometres.
    #[inline(always)]
    fn eval_many_nearest_f32(&self, _lambda: &[f32], nearest: &[u16], values: &mut [f32]) {
        for (v, &i) in values.iter_mut().zip(nearest) {
            *v = self.at::<f32>(i);
        }
    }

    /// Itself: its lookup reaches it behind any pointer.
    #[inline(always)]
    fn as_dense(&self) -> Option<&DenseSpectrum> {
        Some(self)
    }

    /// One load per wavelength ([`DenseSpectrum::sample`]).
    #[inline(always)]
    fn sample<const K: usize, U: Float>(&self, at: &impl Wavelengths<K, U>) -> SampledSpectrum<K, U> {
        DenseSpectrum::sample(self, at)
    }

    /// Exact: the largest of its 471 values (it is a step function over
    /// 360–830 nm).
    fn max_value(&self) -> f64 {
        self.values::<f64>().iter().copied().fold(f64::NEG_INFINITY, f64::max)
    }

    /// Steps: constant between half nanometres (and zero outside
    /// 360–830 nm).
    fn pieces(&self) -> Option<Pieces<'_>> {
        static BREAKS: std::sync::OnceLock<Vec<f64>> = std::sync::OnceLock::new();
        let breaks = BREAKS.get_or_init(|| {
            let halves = (0..DENSE_VALUES - 1).map(|i| DENSE_RANGE.min() + 0.5 + i as f64);
            std::iter::once(DENSE_RANGE.min()).chain(halves).chain([DENSE_RANGE.max()]).collect()
        });
        Some(Pieces { breaks: Cow::Borrowed(breaks), degree: 0 })
    }
}
