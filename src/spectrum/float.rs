//! The element type of per-sample values: [`f32`], as renderers compute, or
//! [`f64`], as the exact reference and the study do.
//!
//! [`Float`] is implemented for those two types only (it is sealed). Every
//! per-sample type takes it as a parameter that defaults to `f64`:
//! `SampledSpectrum<K, T>`, `HeroSample<K, T>`, `FixedWavelengths<M, T>`,
//! `RegularSpectrum<M, B, T>`. One source serves both precisions; a
//! renderer that names `f32` gets `f32` values, wavelengths and weights,
//! and never converts. Dense tables (`DenseSpectrum`, `DenseObserver`)
//! keep both and are read in the wavelengths' precision.
//!
//! **Why a parameter, not two families**: the element type is the one
//! place where users choose (glam generates `Vec4` and `DVec4` from one
//! template; Mitsuba 3 makes it a template parameter). A parameter with a
//! default keeps the f64 names as they were (`SampledSpectrum<4>`), needs
//! no generator, and lets one generic function serve both.
//!
//! **Sums**: a pixel's sum of estimates is the caller's. Summed one by one
//! in `f32`, n estimates lose about n·2⁻²⁴ relative in the worst case
//! (1 % after 2¹⁷ ≈ 130 000 samples, typically √n times less); XYZ comes
//! out of a sample as `f64` ([`crate::Xyz`]), so adding it to an `f64`
//! pixel, as pbrt-v4's film does, costs nothing in accuracy.
//!
//! ```
//! use speclab::spectrum::Float;
//! fn half<T: Float>(v: T) -> T {
//!     v * T::from_f64(0.5)
//! }
//! assert_eq!(half(3.0_f32), 1.5_f32);
//! assert_eq!(half(3.0_f64).to_f64(), 1.5);
//! ```

use std::fmt::Debug;
use std::iter::Sum;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// `f32` or `f64`: the element type of per-sample values.
pub trait Float:
    Copy
    + Default
    + Debug
    + PartialEq
    + PartialOrd
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + Sum
    + sealed::Sealed
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// `v`, rounded to the nearest value of this type.
    fn from_f64(v: f64) -> Self;
    /// The value as `f64` (exact).
    fn to_f64(self) -> f64;
    /// `eᵛ`.
    #[must_use]
    fn exp(self) -> Self;
    /// `√v` (NaN for negative values).
    #[must_use]
    fn sqrt(self) -> Self;
    /// The larger of the two, ignoring a NaN (as `f64::max`).
    #[must_use]
    fn max(self, other: Self) -> Self;
    /// The smaller of the two, ignoring a NaN (as `f64::min`).
    #[must_use]
    fn min(self, other: Self) -> Self;
}

/// What only the crate uses of a precision: the trait is sealed, and
/// these are not part of the API.
pub(crate) mod sealed {
    /// Four lanes of a precision in SIMD registers (`wide`'s `f32x4` and
    /// `f64x4`): what [`crate::spectrum::simd`] computes with.
    pub trait Vector:
        Copy
        + std::ops::Add<Output = Self>
        + std::ops::Sub<Output = Self>
        + std::ops::Mul<Output = Self>
        + std::ops::Div<Output = Self>
    {
        /// `self·m + a`, fused where the build has FMA.
        #[must_use]
        fn mul_add(self, m: Self, a: Self) -> Self;
    }

    /// Implemented for `f32` and `f64` alone.
    pub trait Sealed: Sized {
        /// Four lanes of this precision.
        type V4: Vector;
        /// The largest value below 1: the last `u` of `[0, 1)` (an `f64`
        /// just below 1 rounds to 1 in `f32`).
        const BELOW_ONE: Self;
        /// Four values as a vector.
        fn v4(a: [Self; 4]) -> Self::V4;
        /// A vector's four values.
        fn array(v: Self::V4) -> [Self; 4];
        /// One value in all four lanes.
        fn splat(v: Self) -> Self::V4;
        /// Each of three vectors' lanes summed as `(a₀ + a₂) + (a₁ + a₃)`.
        #[inline(always)]
        fn sums3(v: [Self::V4; 3]) -> [Self; 3]
        where
            Self: std::ops::Add<Output = Self> + Copy,
        {
            v.map(|a| {
                let [a0, a1, a2, a3] = Self::array(a);
                (a0 + a2) + (a1 + a3)
            })
        }

        /// Wavelengths and the values to fill at them, in this precision (how
        /// a spectrum reaches its `f32` or `f64` evaluation).
        fn lanes<'a>(lambda: &'a [Self], values: &'a mut [Self]) -> Precision<'a>;
        /// The table of this precision out of a pair (for tables computed at
        /// compile time in both).
        fn choose<'a, const N: usize, const R: usize>(
            f32s: &'a [[f32; N]; R],
            f64s: &'a [[f64; N]; R],
        ) -> &'a [[Self; N]; R];
        /// The row of this precision out of a pair.
        fn choose_row<'a, const N: usize>(f32s: &'a [f32; N], f64s: &'a [f64; N]) -> &'a [Self; N];
        /// A film's splat, in this precision (four lanes at a time in
        /// `f32`): each wavelength's bucket `⌊(λ − min)·per⌋` clamped to
        /// `0..=last` (a NaN to 0), and what it adds there, `w·v` as
        /// `f64`, or 0 where `w` is 0 or `λ` is outside `[min, max]`.
        fn splat_lanes<const K: usize>(
            lambda: &[Self; K],
            wv: [[Self; 2]; K],
            range: [Self; 3],
            last: usize,
        ) -> [(usize, f64); K];
    }

    /// Wavelengths (nm) and the values a spectrum fills at them, in one of the
    /// two precisions: what [`Spectrum::sample`](super::Spectrum::sample)
    /// hands to `eval_many` or `eval_many_f32`.
    #[derive(Debug)]
    pub enum Precision<'a> {
        /// Single precision.
        F32 {
            /// The wavelengths, nm.
            lambda: &'a [f32],
            /// The values to fill.
            values: &'a mut [f32],
        },
        /// Double precision.
        F64 {
            /// The wavelengths, nm.
            lambda: &'a [f64],
            /// The values to fill.
            values: &'a mut [f64],
        },
    }
}

impl Float for f32 {
    const ZERO: f32 = 0.0;
    const ONE: f32 = 1.0;
    #[inline(always)]
    fn from_f64(v: f64) -> f32 {
        v as f32
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    #[inline]
    fn exp(self) -> f32 {
        f32::exp(self)
    }
    #[inline]
    fn sqrt(self) -> f32 {
        f32::sqrt(self)
    }
    #[inline(always)]
    fn max(self, other: f32) -> f32 {
        f32::max(self, other)
    }
    #[inline(always)]
    fn min(self, other: f32) -> f32 {
        f32::min(self, other)
    }
}

impl sealed::Vector for wide::f32x4 {
    #[inline(always)]
    fn mul_add(self, m: Self, a: Self) -> Self {
        wide::f32x4::mul_add(self, m, a)
    }
}

impl sealed::Sealed for f32 {
    type V4 = wide::f32x4;
    const BELOW_ONE: f32 = 1.0 - f32::EPSILON / 2.0;
    #[inline(always)]
    fn v4(a: [f32; 4]) -> wide::f32x4 {
        wide::f32x4::new(a)
    }
    #[inline(always)]
    fn array(v: wide::f32x4) -> [f32; 4] {
        v.to_array()
    }
    #[inline(always)]
    fn splat(v: f32) -> wide::f32x4 {
        wide::f32x4::splat(v)
    }
    /// Transposed, the three sums are one vector's lanes: three vector
    /// additions instead of nine scalar ones and their extractions, in
    /// the same order (the same bits).
    #[inline(always)]
    fn sums3([x, y, z]: [wide::f32x4; 3]) -> [f32; 3] {
        let [t0, t1, t2, t3] = wide::f32x4::transpose([x, y, z, wide::f32x4::ZERO]);
        let [sx, sy, sz, _] = ((t0 + t2) + (t1 + t3)).to_array();
        [sx, sy, sz]
    }
    #[inline(always)]
    fn lanes<'a>(lambda: &'a [f32], values: &'a mut [f32]) -> sealed::Precision<'a> {
        sealed::Precision::F32 { lambda, values }
    }
    #[inline(always)]
    fn choose<'a, const N: usize, const R: usize>(
        f32s: &'a [[f32; N]; R],
        _: &'a [[f64; N]; R],
    ) -> &'a [[f32; N]; R] {
        f32s
    }
    #[inline(always)]
    fn choose_row<'a, const N: usize>(f32s: &'a [f32; N], _: &'a [f64; N]) -> &'a [f32; N] {
        f32s
    }
    #[inline(always)]
    fn splat_lanes<const K: usize>(
        lambda: &[f32; K],
        wv: [[f32; 2]; K],
        [min, max, per]: [f32; 3],
        last: usize,
    ) -> [(usize, f64); K] {
        use wide::{CmpGe, CmpLe, CmpNe, f32x4};
        let mut out = [(0, 0.0); K];
        let (top, chunks) = (f32x4::splat(last as f32), K / 4);
        for c in 0..chunks {
            let at = 4 * c;
            let l = f32x4::new([lambda[at], lambda[at + 1], lambda[at + 2], lambda[at + 3]]);
            let w = f32x4::new([wv[at][0], wv[at + 1][0], wv[at + 2][0], wv[at + 3][0]]);
            let v = f32x4::new([wv[at][1], wv[at + 1][1], wv[at + 2][1], wv[at + 3][1]]);
            // max puts a NaN at 0 and the clamp keeps the truncation in
            // 0..=last (at most 4095, exact in f32), so no lane needs
            // clamping again as an integer.
            let x = ((l - f32x4::splat(min)) * f32x4::splat(per)).fast_max(f32x4::ZERO).fast_min(top);
            let adds = l.cmp_ge(f32x4::splat(min)) & l.cmp_le(f32x4::splat(max)) & w.cmp_ne(f32x4::ZERO);
            let (i, value) = (x.fast_trunc_int().to_array(), adds.blend(w * v, f32x4::ZERO).to_array());
            (0..4).for_each(|j| out[4 * c + j] = (i[j] as usize, f64::from(value[j])));
        }
        for j in 4 * chunks..K {
            let (l, [w, v]) = (lambda[j], wv[j]);
            let adds = l >= min && l <= max && w != 0.0;
            out[j] =
                ((((l - min) * per).max(0.0) as usize).min(last), if adds { f64::from(w * v) } else { 0.0 });
        }
        out
    }
}

impl Float for f64 {
    const ZERO: f64 = 0.0;
    const ONE: f64 = 1.0;
    #[inline(always)]
    fn from_f64(v: f64) -> f64 {
        v
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn exp(self) -> f64 {
        f64::exp(self)
    }
    #[inline]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn max(self, other: f64) -> f64 {
        f64::max(self, other)
    }
    #[inline(always)]
    fn min(self, other: f64) -> f64 {
        f64::min(self, other)
    }
}

impl sealed::Vector for wide::f64x4 {
    #[inline(always)]
    fn mul_add(self, m: Self, a: Self) -> Self {
        wide::f64x4::mul_add(self, m, a)
    }
}

impl sealed::Sealed for f64 {
    type V4 = wide::f64x4;
    const BELOW_ONE: f64 = 1.0 - f64::EPSILON / 2.0;
    #[inline(always)]
    fn v4(a: [f64; 4]) -> wide::f64x4 {
        wide::f64x4::new(a)
    }
    #[inline(always)]
    fn array(v: wide::f64x4) -> [f64; 4] {
        v.to_array()
    }
    #[inline(always)]
    fn splat(v: f64) -> wide::f64x4 {
        wide::f64x4::splat(v)
    }
    #[inline(always)]
    fn lanes<'a>(lambda: &'a [f64], values: &'a mut [f64]) -> sealed::Precision<'a> {
        sealed::Precision::F64 { lambda, values }
    }
    #[inline(always)]
    fn choose<'a, const N: usize, const R: usize>(
        _: &'a [[f32; N]; R],
        f64s: &'a [[f64; N]; R],
    ) -> &'a [[f64; N]; R] {
        f64s
    }
    #[inline(always)]
    fn choose_row<'a, const N: usize>(_: &'a [f32; N], f64s: &'a [f64; N]) -> &'a [f64; N] {
        f64s
    }
    #[inline(always)]
    fn splat_lanes<const K: usize>(
        lambda: &[f64; K],
        wv: [[f64; 2]; K],
        [min, max, per]: [f64; 3],
        last: usize,
    ) -> [(usize, f64); K] {
        std::array::from_fn(|j| {
            let (l, [w, v]) = (lambda[j], wv[j]);
            let adds = (l >= min) & (l <= max) & (w != 0.0);
            ((((l - min) * per).max(0.0) as usize).min(last), if adds { w * v } else { 0.0 })
        })
    }
}

/// Weight rows rounded to `f32`, at compile time (the dense observer's
/// and the buckets' `f32` tables).
pub(crate) const fn rounded<const M: usize>(rows: &[[f64; 4]; M]) -> [[f32; 4]; M] {
    let mut out = [[0.0; 4]; M];
    let mut i = 0;
    while i < M {
        let mut c = 0;
        while c < 4 {
            out[i][c] = rows[i][c] as f32;
            c += 1;
        }
        i += 1;
    }
    out
}
