//! `SampledSpectrum<K>`: a spectrum's values at K wavelengths (those of a
//! `HeroSample<K>`, or any [`Wavelengths<K>`]), with the arithmetic a path
//! tracer does on them.
//!
//! Every operation is point-wise over the K values (see
//! [`super::pointwise`]): `+ - * /` with another sampled spectrum or with a
//! scalar on either side (and their `…Assign` forms), negation, `safe_div`,
//! `clamp`, `exp`, `sqrt`, `lerp`, `map`, the smallest, largest and mean
//! value. The values are a `Copy` array of K f64: nothing here allocates.
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

use crate::spectrum::pointwise::pointwise_spectrum;

/// K wavelengths, nm, at which spectra are sampled: a `HeroSample<K>`, or
/// a plain `[f64; K]`.
pub trait Wavelengths<const K: usize> {
    /// The wavelengths, nm.
    fn lambda(&self) -> &[f64; K];
}

impl<const K: usize> Wavelengths<K> for [f64; K] {
    #[inline]
    fn lambda(&self) -> &[f64; K] {
        self
    }
}

/// A spectrum's values at the K wavelengths of a sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledSpectrum<const K: usize> {
    /// One value per wavelength, in the sample's order.
    pub values: [f64; K],
}

impl<const K: usize> SampledSpectrum<K> {
    /// From values, one per wavelength.
    #[inline]
    #[must_use]
    pub const fn new(values: [f64; K]) -> Self {
        SampledSpectrum { values }
    }
}

pointwise_spectrum!([const K: usize] SampledSpectrum<K>, K, SampledSpectrum::new);
