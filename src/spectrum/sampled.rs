//! `SampledSpectrum<K, T>`: a spectrum's values at K wavelengths (any
//! [`Wavelengths<K, T>`]: a hero sample's, a fixed rule's, an array), with
//! the arithmetic a path tracer does on them, in `f64` (the default) or
//! `f32` ([`Float`]).
//!
//! Every operation is point-wise over the K values (see
//! [`super::pointwise`]): `+ - * /` with another sampled spectrum or with a
//! scalar on either side (and their `…Assign` forms), negation, `safe_div`,
//! `clamp`, `exp`, `sqrt`, `lerp`, `map`, the smallest, largest and mean
//! value. The values are a `Copy` array of K numbers: nothing here
//! allocates.
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, SampledSpectrum};
//! let h = HeroSample::<4>::new(0.3);
//! let (le, albedo) = (lights::D65.sample(&h), patches::G4.sample(&h));
//! let mut beta = SampledSpectrum::splat(1.0);
//! let mut l = SampledSpectrum::zero();
//! for _bounce in 0..3 {
//!     l += beta * le;
//!     beta *= albedo;
//!     if beta.max_value() < 0.01 { break; }
//! }
//! assert!(!l.is_black() && h.to_xyz(l).y > h.to_xyz(le).y);
//! assert_eq!(beta.clamp(0.0, 0.1).max_value(), 0.1_f64.min(beta.max_value()));
//! ```

use crate::spectrum::float::Float;
use crate::spectrum::lookup;
use crate::spectrum::pointwise::pointwise_spectrum;

/// K wavelengths, nm, at which spectra are sampled: a
/// `HeroSample<K, T>` or `FixedWavelengths<K, T>` (drawn or fixed), or a plain
/// `[T; K]`.
pub trait Wavelengths<const K: usize, T: Float = f64> {
    /// The wavelengths, nm.
    fn lambda(&self) -> &[T; K];

    /// Each wavelength's place on the 1 nm grid of dense tables: the
    /// nearest whole nanometre from 360 to 830 nm as 0 to 470, and 471 for
    /// a wavelength outside (or NaN), where dense tables are zero. A
    /// hero sample computes these once, when it is drawn.
    #[inline]
    fn nearest_nm(&self) -> [u16; K] {
        let lambda = self.lambda();
        std::array::from_fn(|j| lookup::nearest_nm(lambda[j].to_f64()))
    }
}

impl<const K: usize, T: Float> Wavelengths<K, T> for [T; K] {
    #[inline]
    fn lambda(&self) -> &[T; K] {
        self
    }
}

/// A spectrum's values at the K wavelengths of a sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledSpectrum<const K: usize, T: Float = f64> {
    /// One value per wavelength, in the sample's order.
    pub values: [T; K],
}

impl<const K: usize, T: Float> SampledSpectrum<K, T> {
    /// From values, one per wavelength.
    #[inline]
    #[must_use]
    pub const fn new(values: [T; K]) -> Self {
        SampledSpectrum { values }
    }
}

pointwise_spectrum!([const K: usize] SampledSpectrum[K], K, SampledSpectrum::new);
