//! The arithmetic every fixed-size spectral value shares: a sampled
//! spectrum's K values ([`super::SampledSpectrum`]) and a bucketed
//! spectrum's M values (`sampling::RegularSpectrum`) are added, multiplied,
//! clamped and mapped point-wise, in the same way, by one definition.
//!
//! `pointwise_spectrum!([generics] Type, N, from_values)` implements, for a
//! type with a field `values: [f64; N]` and a constructor
//! `from_values([f64; N]) -> Self`:
//! - `+ - * /` with the type and with `f64` on either side, and the
//!   `…Assign` forms; `Neg`; `Sum`; `Index`/`IndexMut`;
//! - `zero`, `splat`, `average`, `min_value`, `max_value`, `is_black`,
//!   `safe_div` (0 where the divisor is 0), `map`, `clamp`, `exp`, `sqrt`,
//!   `lerp`.
//!
//! Plain `/` follows IEEE (x/0 is ±∞ or NaN); `safe_div` is pbrt's
//! `SafeDiv`. Nothing here allocates.

/// See the module documentation.
macro_rules! pointwise_spectrum {
    ([$($g:tt)*] $ty:ty, $n:ident, $from:path) => {
        impl<$($g)*> $ty {
            /// All values 0.
            #[inline]
            #[must_use]
            pub fn zero() -> Self {
                $from([0.0; $n])
            }

            /// All values `c`.
            #[inline]
            #[must_use]
            pub fn splat(c: f64) -> Self {
                $from([c; $n])
            }

            /// The mean of the values.
            #[inline]
            #[must_use]
            pub fn average(&self) -> f64 {
                self.values.iter().sum::<f64>() / $n as f64
            }

            /// `Σ selfᵢ·otherᵢ`.
            #[inline]
            #[must_use]
            pub fn dot(&self, other: &Self) -> f64 {
                self.values.iter().zip(&other.values).map(|(a, b)| a * b).sum()
            }

            /// The largest value (NaN values are ignored unless all are NaN).
            #[inline]
            #[must_use]
            pub fn max_value(&self) -> f64 {
                self.values.iter().copied().fold(f64::NEG_INFINITY, f64::max)
            }

            /// The smallest value (NaN values are ignored unless all are NaN).
            #[inline]
            #[must_use]
            pub fn min_value(&self) -> f64 {
                self.values.iter().copied().fold(f64::INFINITY, f64::min)
            }

            /// True if every value is 0.
            #[inline]
            #[must_use]
            pub fn is_black(&self) -> bool {
                self.values.iter().all(|&v| v == 0.0)
            }

            /// Point-wise `self / d`, with 0 wherever `d` is 0 (so 0/0 is 0,
            /// not NaN): pbrt's `SafeDiv`, for dividing by pdfs that a
            /// terminated wavelength sets to 0.
            #[inline]
            #[must_use]
            pub fn safe_div(self, d: Self) -> Self {
                $from(std::array::from_fn(
                    |j| if d.values[j] != 0.0 { self.values[j] / d.values[j] } else { 0.0 },
                ))
            }

            /// `f` applied to every value.
            #[inline]
            #[must_use]
            pub fn map(self, f: impl Fn(f64) -> f64) -> Self {
                $from(self.values.map(f))
            }

            /// Every value limited to `[lo, hi]`: below `lo` gives `lo`, else
            /// above `hi` gives `hi` (NaN stays NaN; never panics, unlike
            /// `f64::clamp` with `lo > hi`).
            #[inline]
            #[must_use]
            pub fn clamp(self, lo: f64, hi: f64) -> Self {
                self.map(|v| if v < lo { lo } else if v > hi { hi } else { v })
            }

            /// `e^v` of every value (a transmittance from an optical depth).
            #[inline]
            #[must_use]
            pub fn exp(self) -> Self {
                self.map(f64::exp)
            }

            /// `√v` of every value (NaN for negative values, as `f64::sqrt`).
            #[inline]
            #[must_use]
            pub fn sqrt(self) -> Self {
                self.map(f64::sqrt)
            }

            /// `(1 − t)·self + t·other`, point-wise.
            #[inline]
            #[must_use]
            pub fn lerp(self, other: Self, t: f64) -> Self {
                $from(std::array::from_fn(|j| (1.0 - t) * self.values[j] + t * other.values[j]))
            }
        }

        impl<$($g)*> Default for $ty {
            /// All values 0.
            fn default() -> Self {
                Self::zero()
            }
        }

        impl<$($g)*> std::ops::Index<usize> for $ty {
            type Output = f64;
            #[inline]
            fn index(&self, j: usize) -> &f64 {
                &self.values[j]
            }
        }

        impl<$($g)*> std::ops::IndexMut<usize> for $ty {
            #[inline]
            fn index_mut(&mut self, j: usize) -> &mut f64 {
                &mut self.values[j]
            }
        }

        impl<$($g)*> std::ops::Neg for $ty {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self {
                self.map(|v| -v)
            }
        }

        impl<$($g)*> std::iter::Sum for $ty {
            fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
                iter.fold(Self::zero(), |a, b| a + b)
            }
        }

        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $ty, $from; Add add AddAssign add_assign +);
        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $ty, $from; Sub sub SubAssign sub_assign -);
        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $ty, $from; Mul mul MulAssign mul_assign *);
        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $ty, $from; Div div DivAssign div_assign /);
    };
    (@op [$($g:tt)*] $ty:ty, $from:path; $op:ident $method:ident $assign:ident $assign_method:ident $sym:tt) => {
        impl<$($g)*> std::ops::$op for $ty {
            type Output = Self;
            #[inline]
            fn $method(self, o: Self) -> Self {
                $from(std::array::from_fn(|j| self.values[j] $sym o.values[j]))
            }
        }
        impl<$($g)*> std::ops::$op<f64> for $ty {
            type Output = Self;
            #[inline]
            fn $method(self, s: f64) -> Self {
                self.map(|v| v $sym s)
            }
        }
        impl<$($g)*> std::ops::$op<$ty> for f64 {
            type Output = $ty;
            #[inline]
            fn $method(self, o: $ty) -> $ty {
                o.map(|v| self $sym v)
            }
        }
        impl<$($g)*> std::ops::$assign for $ty {
            #[inline]
            fn $assign_method(&mut self, o: Self) {
                *self = *self $sym o;
            }
        }
        impl<$($g)*> std::ops::$assign<f64> for $ty {
            #[inline]
            fn $assign_method(&mut self, s: f64) {
                *self = *self $sym s;
            }
        }
    };
}
pub(crate) use pointwise_spectrum;
