//! `SampledSpectrum<K>`: a spectrum's values at the K wavelengths of a
//! [`HeroSample<K>`](crate::HeroSample), with the arithmetic a path tracer
//! does on them.
//!
//! Every operation is point-wise over the K values: `+ - * /` with another
//! sampled spectrum or with a scalar (and their `…Assign` forms), negation,
//! and `scalar * spectrum`. Plain `/` follows IEEE (x/0 is ±∞ or NaN);
//! [`SampledSpectrum::safe_div`] gives 0 wherever the divisor is 0, as
//! pbrt's `SafeDiv` does, for dividing by pdfs that may be 0. The values are
//! a `Copy` array of K f64: nothing here allocates.
//!
//! ```
//! use speclab::{data, HeroSample, SampledSpectrum, Xyz};
//! let h = HeroSample::<4>::new(0.3);
//! let (le, albedo) = (data::D65.sample(&h), data::G4.sample(&h));
//! let mut beta = SampledSpectrum::splat(1.0);
//! let mut l = SampledSpectrum::zero();
//! for _bounce in 0..3 {
//!     l += beta * le;
//!     beta *= albedo;
//!     if beta.max_value() < 0.01 { break; }
//! }
//! assert!(!l.is_black() && h.to_xyz(l).y > h.to_xyz(le).y);
//! ```

use std::ops::{Add, AddAssign, Div, DivAssign, Index, IndexMut, Mul, MulAssign, Neg, Sub, SubAssign};

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

    /// All values 0.
    #[inline]
    #[must_use]
    pub const fn zero() -> Self {
        Self::splat(0.0)
    }

    /// All values `c`.
    #[inline]
    #[must_use]
    pub const fn splat(c: f64) -> Self {
        SampledSpectrum { values: [c; K] }
    }

    /// The mean of the values.
    #[inline]
    #[must_use]
    pub fn average(&self) -> f64 {
        self.values.iter().sum::<f64>() / K as f64
    }

    /// The largest value (NaN values are ignored unless all are NaN).
    #[inline]
    #[must_use]
    pub fn max_value(&self) -> f64 {
        self.values.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    }

    /// True if every value is 0.
    #[inline]
    #[must_use]
    pub fn is_black(&self) -> bool {
        self.values.iter().all(|&v| v == 0.0)
    }

    /// Point-wise `self / d`, with 0 wherever `d` is 0 (so 0/0 is 0, not
    /// NaN): the division by pdfs that a terminated wavelength sets to 0.
    #[inline]
    #[must_use]
    pub fn safe_div(self, d: Self) -> Self {
        Self::new(std::array::from_fn(
            |j| if d.values[j] != 0.0 { self.values[j] / d.values[j] } else { 0.0 },
        ))
    }
}

impl<const K: usize> Default for SampledSpectrum<K> {
    /// All values 0.
    fn default() -> Self {
        Self::zero()
    }
}

impl<const K: usize> Index<usize> for SampledSpectrum<K> {
    type Output = f64;
    #[inline]
    fn index(&self, j: usize) -> &f64 {
        &self.values[j]
    }
}

impl<const K: usize> IndexMut<usize> for SampledSpectrum<K> {
    #[inline]
    fn index_mut(&mut self, j: usize) -> &mut f64 {
        &mut self.values[j]
    }
}

impl<const K: usize> Neg for SampledSpectrum<K> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(self.values.map(|v| -v))
    }
}

/// `Op` and `OpAssign` with another sampled spectrum and with a scalar.
macro_rules! pointwise {
    ($($op:ident $method:ident $assign:ident $assign_method:ident $symbol:tt;)*) => {$(
        impl<const K: usize> $op for SampledSpectrum<K> {
            type Output = Self;
            #[inline]
            fn $method(self, o: Self) -> Self {
                Self::new(std::array::from_fn(|j| self.values[j] $symbol o.values[j]))
            }
        }
        impl<const K: usize> $op<f64> for SampledSpectrum<K> {
            type Output = Self;
            #[inline]
            fn $method(self, s: f64) -> Self {
                Self::new(self.values.map(|v| v $symbol s))
            }
        }
        impl<const K: usize> $assign for SampledSpectrum<K> {
            #[inline]
            fn $assign_method(&mut self, o: Self) {
                *self = *self $symbol o;
            }
        }
        impl<const K: usize> $assign<f64> for SampledSpectrum<K> {
            #[inline]
            fn $assign_method(&mut self, s: f64) {
                *self = *self $symbol s;
            }
        }
    )*};
}

pointwise! {
    Add add AddAssign add_assign +;
    Sub sub SubAssign sub_assign -;
    Mul mul MulAssign mul_assign *;
    Div div DivAssign div_assign /;
}

impl<const K: usize> Mul<SampledSpectrum<K>> for f64 {
    type Output = SampledSpectrum<K>;
    #[inline]
    fn mul(self, s: SampledSpectrum<K>) -> SampledSpectrum<K> {
        s * self
    }
}
