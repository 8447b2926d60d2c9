//! The arithmetic of a colour's three numbers, shared by [`super::Xyz`] and
//! [`super::LinearRgb`]: component-wise `+ - * /` with the type and with
//! `f64` on either side, the `…Assign` forms, `Neg`, `Sum`, and
//! conversions from and to `[f64; 3]`. Users never unpack fields to do
//! arithmetic.
//!
//! ```
//! use speclab::Xyz;
//! let a = Xyz::from([1.0, 2.0, 3.0]);
//! let mut b = 2.0 * a - a / 2.0;
//! b += Xyz::splat(1.0);
//! assert_eq!(<[f64; 3]>::from(-b), [-2.5, -4.0, -5.5]);
//! assert_eq!([a, b].into_iter().sum::<Xyz>(), Xyz::new(3.5, 6.0, 8.5));
//! ```

/// See the module documentation.
macro_rules! triple_arithmetic {
    ($ty:ident { $a:ident, $b:ident, $c:ident }) => {
        impl $ty {
            /// All three components `v`.
            #[inline]
            #[must_use]
            pub const fn splat(v: f64) -> Self {
                $ty { $a: v, $b: v, $c: v }
            }

            /// The components as an array, in order.
            #[inline]
            #[must_use]
            pub const fn to_array(self) -> [f64; 3] {
                [self.$a, self.$b, self.$c]
            }

            /// `f` applied to each component.
            #[inline]
            #[must_use]
            pub fn map(self, f: impl Fn(f64) -> f64) -> Self {
                $ty { $a: f(self.$a), $b: f(self.$b), $c: f(self.$c) }
            }

            /// True if every component is finite.
            #[inline]
            #[must_use]
            pub fn is_finite(self) -> bool {
                self.$a.is_finite() && self.$b.is_finite() && self.$c.is_finite()
            }
        }

        impl From<[f64; 3]> for $ty {
            #[inline]
            fn from([$a, $b, $c]: [f64; 3]) -> Self {
                $ty { $a, $b, $c }
            }
        }

        impl From<$ty> for [f64; 3] {
            #[inline]
            fn from(v: $ty) -> [f64; 3] {
                v.to_array()
            }
        }

        impl std::ops::Neg for $ty {
            type Output = $ty;
            #[inline]
            fn neg(self) -> $ty {
                self.map(|v| -v)
            }
        }

        impl std::iter::Sum for $ty {
            fn sum<I: Iterator<Item = $ty>>(iter: I) -> $ty {
                iter.fold($ty::splat(0.0), |s, v| s + v)
            }
        }

        $crate::color::triple::triple_arithmetic!(@op $ty { $a, $b, $c };
            Add add AddAssign add_assign +;
            Sub sub SubAssign sub_assign -;
            Mul mul MulAssign mul_assign *;
            Div div DivAssign div_assign /;
        );
    };
    (@op $ty:ident { $a:ident, $b:ident, $c:ident }; $($op:ident $m:ident $assign:ident $am:ident $sym:tt;)*) => {$(
        impl std::ops::$op for $ty {
            type Output = $ty;
            #[inline]
            fn $m(self, o: $ty) -> $ty {
                $ty { $a: self.$a $sym o.$a, $b: self.$b $sym o.$b, $c: self.$c $sym o.$c }
            }
        }
        impl std::ops::$op<f64> for $ty {
            type Output = $ty;
            #[inline]
            fn $m(self, s: f64) -> $ty {
                self.map(|v| v $sym s)
            }
        }
        impl std::ops::$op<$ty> for f64 {
            type Output = $ty;
            #[inline]
            fn $m(self, o: $ty) -> $ty {
                o.map(|v| self $sym v)
            }
        }
        impl std::ops::$assign for $ty {
            #[inline]
            fn $am(&mut self, o: $ty) {
                *self = *self $sym o;
            }
        }
        impl std::ops::$assign<f64> for $ty {
            #[inline]
            fn $am(&mut self, s: f64) {
                *self = *self $sym s;
            }
        }
    )*};
}
pub(crate) use triple_arithmetic;
