//! The arithmetic every fixed-size spectral value shares: a sampled
//! spectrum's K values ([`super::SampledSpectrum`]) and a bucketed
//! spectrum's M values (`sampling::RegularSpectrum`) are added, multiplied,
//! clamped and mapped point-wise, in the same way, by one definition, in
//! either precision ([`super::Float`]).
//!
//! `pointwise_spectrum!([generics] Type[args], N, from_values)` implements,
//! for `Type<args…, T>` with a field `values: [T; N]` and a constructor
//! `from_values([T; N]) -> Self`:
//! - `+ - * /` with the type and with `T` on either side (`f32` and `f64`
//!   on the left), and the `…Assign` forms; `Neg`; `Sum`;
//!   `Index`/`IndexMut`;
//! - `zero`, `splat`, `average`, `dot`, `min_value`, `max_value`,
//!   `is_black`, `safe_div` (0 where the divisor is 0), `map`, `clamp`,
//!   `exp`, `sqrt`, `lerp`.
//!
//! `+ − × ÷` run four values per instruction (see [`super::simd`]).
//! Plain `/` follows IEEE (x/0 is ±∞ or NaN); `safe_div` is pbrt's
//! `SafeDiv`. Nothing here allocates.

/// See the module documentation.
macro_rules! pointwise_spectrum {
    ([$($g:tt)*] $name:ident [$($a:tt),*], $n:ident, $from:path) => {
        impl<$($g)*, T: $crate::spectrum::Float> $name<$($a,)* T> {
            /// All values 0.
            #[inline]
            #[must_use]
            pub fn zero() -> Self {
                $from([T::ZERO; $n])
            }

            /// All values `c`.
            #[inline]
            #[must_use]
            pub fn splat(c: T) -> Self {
                $from([c; $n])
            }

            /// The mean of the values.
            #[inline]
            #[must_use]
            pub fn average(&self) -> T {
                self.values.iter().copied().sum::<T>() / T::from_f64($n as f64)
            }

            /// `Σ selfᵢ·otherᵢ`.
            #[inline]
            #[must_use]
            pub fn dot(&self, other: &Self) -> T {
                self.values.iter().zip(&other.values).map(|(&a, &b)| a * b).sum()
            }

            /// The largest value (NaN values are ignored unless all are NaN).
            #[inline]
            #[must_use]
            pub fn max_value(&self) -> T {
                self.values.iter().copied().fold(T::from_f64(f64::NEG_INFINITY), T::max)
            }

            /// The smallest value (NaN values are ignored unless all are NaN).
            #[inline]
            #[must_use]
            pub fn min_value(&self) -> T {
                self.values.iter().copied().fold(T::from_f64(f64::INFINITY), T::min)
            }

            /// True if every value is 0.
            #[inline]
            #[must_use]
            pub fn is_black(&self) -> bool {
                self.values.iter().all(|&v| v == T::ZERO)
            }

            /// Point-wise `self / d`, with 0 wherever `d` is 0 (so 0/0 is 0,
            /// not NaN): pbrt's `SafeDiv`.
            #[inline]
            #[must_use]
            pub fn safe_div(self, d: Self) -> Self {
                $from(std::array::from_fn(
                    |j| if d.values[j] != T::ZERO { self.values[j] / d.values[j] } else { T::ZERO },
                ))
            }

            /// `f` applied to every value.
            #[inline]
            #[must_use]
            pub fn map(self, f: impl Fn(T) -> T) -> Self {
                $from(std::array::from_fn(|j| f(self.values[j])))
            }

            /// Every value limited to `[lo, hi]`: below `lo` gives `lo`, else
            /// above `hi` gives `hi` (NaN stays NaN; never panics, unlike
            /// `f64::clamp` with `lo > hi`).
            #[inline]
            #[must_use]
            pub fn clamp(self, lo: T, hi: T) -> Self {
                self.map(|v| if v < lo { lo } else if v > hi { hi } else { v })
            }

            /// `e^v` of every value (a transmittance from an optical depth).
            #[inline]
            #[must_use]
            pub fn exp(self) -> Self {
                self.map(T::exp)
            }

            /// `√v` of every value (NaN for negative values).
            #[inline]
            #[must_use]
            pub fn sqrt(self) -> Self {
                self.map(T::sqrt)
            }

            /// `(1 − t)·self + t·other`, point-wise.
            #[inline]
            #[must_use]
            pub fn lerp(self, other: Self, t: T) -> Self {
                $from(std::array::from_fn(|j| (T::ONE - t) * self.values[j] + t * other.values[j]))
            }
        }

        impl<$($g)*, T: $crate::spectrum::Float> Default for $name<$($a,)* T> {
            /// All values 0.
            fn default() -> Self {
                Self::zero()
            }
        }

        impl<$($g)*, T: $crate::spectrum::Float> std::ops::Index<usize> for $name<$($a,)* T> {
            type Output = T;
            #[inline]
            fn index(&self, j: usize) -> &T {
                &self.values[j]
            }
        }

        impl<$($g)*, T: $crate::spectrum::Float> std::ops::IndexMut<usize> for $name<$($a,)* T> {
            #[inline]
            fn index_mut(&mut self, j: usize) -> &mut T {
                &mut self.values[j]
            }
        }

        impl<$($g)*, T: $crate::spectrum::Float> std::ops::Neg for $name<$($a,)* T> {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self {
                self.map(|v| -v)
            }
        }

        impl<$($g)*, T: $crate::spectrum::Float> std::iter::Sum for $name<$($a,)* T> {
            fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
                iter.fold(Self::zero(), |a, b| a + b)
            }
        }

        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $name [$($a),*], $from; Add add AddAssign add_assign +);
        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $name [$($a),*], $from; Sub sub SubAssign sub_assign -);
        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $name [$($a),*], $from; Mul mul MulAssign mul_assign *);
        $crate::spectrum::pointwise::pointwise_spectrum!(@op [$($g)*] $name [$($a),*], $from; Div div DivAssign div_assign /);
    };
    (@op [$($g:tt)*] $name:ident [$($a:tt),*], $from:path; $op:ident $method:ident $assign:ident $assign_method:ident $sym:tt) => {
        impl<$($g)*, T: $crate::spectrum::Float> std::ops::$op for $name<$($a,)* T> {
            type Output = Self;
            #[inline]
            fn $method(self, o: Self) -> Self {
                $from($crate::spectrum::simd::zip(&self.values, &o.values, |a, b| a $sym b))
            }
        }
        impl<$($g)*, T: $crate::spectrum::Float> std::ops::$op<T> for $name<$($a,)* T> {
            type Output = Self;
            #[inline]
            fn $method(self, s: T) -> Self {
                let s = <T as $crate::spectrum::float::sealed::Sealed>::splat(s);
                $from($crate::spectrum::simd::map(&self.values, |a| a $sym s))
            }
        }
        impl<$($g)*, T: $crate::spectrum::Float> std::ops::$assign for $name<$($a,)* T> {
            #[inline]
            fn $assign_method(&mut self, o: Self) {
                *self = *self $sym o;
            }
        }
        impl<$($g)*, T: $crate::spectrum::Float> std::ops::$assign<T> for $name<$($a,)* T> {
            #[inline]
            fn $assign_method(&mut self, s: T) {
                *self = *self $sym s;
            }
        }
        $crate::spectrum::pointwise::pointwise_spectrum!(@left [$($g)*] $name [$($a),*], $from; $op $method $sym; f32);
        $crate::spectrum::pointwise::pointwise_spectrum!(@left [$($g)*] $name [$($a),*], $from; $op $method $sym; f64);
    };
    (@left [$($g:tt)*] $name:ident [$($a:tt),*], $from:path; $op:ident $method:ident $sym:tt; $t:ty) => {
        impl<$($g)*> std::ops::$op<$name<$($a,)* $t>> for $t {
            type Output = $name<$($a,)* $t>;
            #[inline]
            fn $method(self, o: $name<$($a,)* $t>) -> $name<$($a,)* $t> {
                let s = <$t as $crate::spectrum::float::sealed::Sealed>::splat(self);
                $from($crate::spectrum::simd::map(&o.values, |a| s $sym a))
            }
        }
    };
}
pub(crate) use pointwise_spectrum;
