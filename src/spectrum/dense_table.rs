//! The table behind [`DenseSpectrum`]: a spectrum's values at every whole
//! nanometre from 360 to 830 nm in `f32` and `f64`, and their lookup at K
//! wavelengths. Below the `Spectrum` trait, which names this type for the
//! dense table's fast path behind a pointer
//! ([`Spectrum::as_dense`](super::Spectrum::as_dense)); the trait's
//! implementation and the constructor from any spectrum are `dense.rs`'s.
//!
//! ```
//! use speclab::{data::patches, HeroSample, Spectrum};
//! use speclab::spectrum::Wavelengths;
//! use speclab::spectrum::DenseSpectrum;
//! let g4 = DenseSpectrum::new(&patches::G4);
//! let h = HeroSample::<4, f32>::new(0.25);
//! assert_eq!(g4.sample(&h).values[0], g4.values::<f32>()[usize::from(h.nearest_nm()[0])]);
//! ```

use crate::spectrum::float::Float;
use crate::spectrum::lookup::{DENSE_ENTRIES, DENSE_VALUES, entry};
use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};

/// A spectrum at every whole nanometre from 360 to 830 nm, in `f32` and
/// `f64`, looked up at the nearest one.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseSpectrum {
    /// At 360, 361, …, 830 nm, then zeros (for wavelengths outside).
    values: Box<[f64; DENSE_ENTRIES]>,
    /// The same, rounded to `f32`.
    values_f32: Box<[f32; DENSE_ENTRIES]>,
}

impl DenseSpectrum {
    /// The table of `values` at 360, 361, …, 830 nm, then zeros (`f64`), and
    /// the same rounded to `f32`.
    pub(crate) fn from_values(values: [f64; DENSE_ENTRIES]) -> Self {
        let values_f32 = values.map(|v| v as f32);
        DenseSpectrum { values: Box::new(values), values_f32: Box::new(values_f32) }
    }

    /// The entry of index `i` (a nearest-nanometre index), in precision `T`.
    #[inline(always)]
    pub(crate) fn at<T: Float>(&self, i: u16) -> T {
        entry(T::choose_row(&self.values_f32, &self.values), i)
    }

    /// The values at 360, 361, …, 830 nm, in precision `T` (index 20 is 380 nm).
    #[must_use]
    pub fn values<T: Float>(&self) -> &[T; DENSE_VALUES] {
        let all = T::choose_row(&self.values_f32, &self.values);
        all.first_chunk().expect("471 of 472 entries")
    }

    /// The values at K wavelengths (a hero sample's or a fixed rule's), at
    /// the nearest whole nanometre each carries, from the table of the
    /// wavelengths' precision: one load per wavelength.
    #[inline(always)]
    #[must_use]
    pub fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        let (nearest, table) = (at.nearest_nm(), T::choose_row(&self.values_f32, &self.values));
        SampledSpectrum::new(std::array::from_fn(|j| entry(table, nearest[j])))
    }
}
