//! Fixed wavelength buckets with M known at compile time:
//! `RegularSpectrum<M, B, T>`, the renderer's type, in `f64` (the default)
//! or `f32`.
//!
//! The range 380–730 nm is cut into `M` equal buckets, and a spectrum
//! becomes `M` numbers by a rule chosen by a type (see
//! [`super::buckets`] for the rules themselves):
//!
//! - [`Center`]: the value at each bucket center `λᵢ = 380 + (i + ½)·W/M`;
//! - [`BoxAverage`]: the exact mean of the interpolant over each bucket.
//!
//! Values have the same point-wise arithmetic as a `SampledSpectrum`
//! (`+ - * /` with each other and with scalars, assign forms, `safe_div`,
//! `clamp`, `exp`, …), so a path's throughput can be carried in buckets
//! too, and [`RegularSpectrum::to_xyz`] is the Riemann sum
//! `W/M · Σ valueᵢ · c̄ᵢ`, where `c̄ᵢ` are the matching functions bucketed
//! the same way, computed once per `M` at compile time in both precisions
//! and summed as the fixed kinds of wavelengths are, from the weights'
//! three columns (the buckets as [`FixedWavelengths<M, T>`]:
//! [`Bucketing::wavelengths`]).
//! `M = 0` does not compile.
//!
//! On a smooth light both rules converge fast. On F11 center sampling hits or
//! misses the spikes depending on `M`; box averaging keeps their energy.
//!
//! ```
//! use speclab::{data::{lights, patches}, RegularSpectrum};
//! let light = RegularSpectrum::<16>::center(&lights::D65);
//! let surface = RegularSpectrum::<16>::center(&patches::A1);
//! let mut beta = RegularSpectrum::splat(1.0);
//! beta *= surface;
//! let rgb = (beta * light).to_xyz().to_linear_srgb();
//! assert!((rgb.g - 82.44).abs() < 1.0);
//! ```
//!
//! ```compile_fail
//! let empty = speclab::RegularSpectrum::<0>::center(&speclab::data::lights::D65);
//! ```
//!
//! Center and box values are different types and cannot be multiplied
//! together (their products would be converted with the wrong c̄ᵢ):
//!
//! ```compile_fail
//! use speclab::{data::{lights, patches}, RegularSpectrum, BoxAverage, Center};
//! let light = RegularSpectrum::<16, Center>::center(&lights::D65);
//! let surface = RegularSpectrum::<16, BoxAverage>::box_average(&patches::A1);
//! let mixed = light * surface;
//! ```

use std::marker::PhantomData;

use crate::color::Xyz;
use crate::sampling::buckets::{BucketRule, box_means, center};
use crate::sampling::wavelengths::{FixedWavelengths, Weighted};
use crate::spectrum::pointwise::pointwise_spectrum;
use crate::spectrum::simd::{column_sums, columns};
use crate::spectrum::{Float, LAMBDA_WIDTH, Spectrum};

/// A bucket rule as a type, so that values bucketed by different rules
/// cannot be mixed.
pub trait Bucketing<const M: usize>: Copy + Default + std::fmt::Debug {
    /// The rule this type stands for.
    const RULE: BucketRule;
    /// The buckets' weights, computed at compile time: one row
    /// `[W/M·x̄ᵢ, W/M·ȳᵢ, W/M·z̄ᵢ, 0]` per bucket, with `c̄ᵢ` the matching
    /// functions bucketed by this rule (the width folded in, so that XYZ is
    /// `Σᵢ rowᵢ·valueᵢ`; `to_xyz` sums the same weights as columns).
    const ROWS_F64: &'static [[f64; 4]; M] = &rows::<M>(Self::RULE);
    /// The same, rounded to `f32`.
    const ROWS_F32: &'static [[f32; 4]; M] = &crate::spectrum::float::rounded(Self::ROWS_F64);
    /// The `M` bucket values of `s`.
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M];

    /// The buckets as fixed wavelengths (the centres) with their weights.
    /// Sampling at them gives centre values: for box buckets, use
    /// [`RegularSpectrum::box_average`] for the values.
    #[must_use]
    fn wavelengths<T: Float>() -> FixedWavelengths<M, T> {
        let lambda = const { centers::<M>() }.map(T::from_f64);
        let rows = T::choose(Self::ROWS_F32, Self::ROWS_F64);
        FixedWavelengths::from_weighted(Weighted::at(lambda).fixed(|c, i| rows[i][c]))
    }
}

/// A bucket rule's weights as three columns, `w_X`, `w_Y`, `w_Z` of every
/// bucket (the rows of [`Bucketing::ROWS_F64`] transposed, at compile
/// time): what [`RegularSpectrum::to_xyz`] sums.
struct Columns<const M: usize, B>(PhantomData<B>);

impl<const M: usize, B: Bucketing<M>> Columns<M, B> {
    const F64: &'static [[f64; M]; 3] = &columns(B::ROWS_F64);
    const F32: &'static [[f32; M]; 3] = &columns(B::ROWS_F32);
}

/// Point samples at bucket centers ([`BucketRule::Center`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Center;

/// Exact means over each bucket ([`BucketRule::BoxAverage`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BoxAverage;

impl<const M: usize> Bucketing<M> for Center {
    const RULE: BucketRule = BucketRule::Center;
    /// The spectrum at the `M` centers, evaluated side by side.
    #[inline]
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M] {
        let mut out = [0.0; M];
        s.eval_many(&const { centers::<M>() }, &mut out);
        out
    }
}

impl<const M: usize> Bucketing<M> for BoxAverage {
    const RULE: BucketRule = BucketRule::BoxAverage;
    #[inline]
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M] {
        let mut out = [0.0; M];
        box_means(s, &mut out);
        out
    }
}

/// The `M` bucket centers, nm.
const fn centers<const M: usize>() -> [f64; M] {
    let mut out = [0.0; M];
    let mut i = 0;
    while i < M {
        out[i] = center(i, M);
        i += 1;
    }
    out
}

/// `rule`'s bucketed observer times the width, one row
/// `[W/M·x̄ᵢ, W/M·ȳᵢ, W/M·z̄ᵢ, 0]` per bucket, at compile time.
const fn rows<const M: usize>(rule: BucketRule) -> [[f64; 4]; M] {
    let mut out = [[0.0; 4]; M];
    let width = LAMBDA_WIDTH / M as f64;
    let mut i = 0;
    while i < M {
        let w = rule.observer(i, M);
        out[i] = [width * w[0], width * w[1], width * w[2], 0.0];
        i += 1;
    }
    out
}

/// A spectrum as `M` equidistant buckets over 380–730 nm, bucketed by `B`,
/// in precision `T`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegularSpectrum<const M: usize, B: Bucketing<M> = Center, T: Float = f64> {
    values: [T; M],
    rule: PhantomData<B>,
}

impl<const M: usize, B: Bucketing<M>, T: Float> RegularSpectrum<M, B, T> {
    /// Compile-time guard: there is no spectrum of zero buckets.
    const NONZERO: () = assert!(M > 0, "RegularSpectrum needs at least one bucket (M > 0)");

    /// Buckets `s` by the rule `B` (in `f64`, rounded to `T`).
    #[inline]
    #[must_use]
    pub fn from_spectrum(s: &impl Spectrum) -> Self {
        Self::from_values(B::buckets(s).map(T::from_f64))
    }

    /// From bucket values directly.
    #[inline]
    #[must_use]
    pub fn from_values(values: [T; M]) -> Self {
        let () = Self::NONZERO;
        RegularSpectrum { values, rule: PhantomData }
    }

    /// The bucket values.
    #[inline]
    #[must_use]
    pub fn values(&self) -> &[T; M] {
        &self.values
    }

    /// The center wavelength of bucket `i`, nm.
    #[must_use]
    pub fn lambda(i: usize) -> f64 {
        center(i, M)
    }

    /// The Riemann sum `W/M · Σ valueᵢ · c̄ᵢ`, the bucketed observer times
    /// the width as three columns of weights (the fixed kinds' sum: three
    /// four-lane multiply-adds per four buckets), summed in `T`.
    #[inline]
    #[must_use]
    pub fn to_xyz(&self) -> Xyz {
        let columns = T::choose(Columns::<M, B>::F32, Columns::<M, B>::F64);
        Xyz::of_sums(column_sums(columns.each_ref().map(|c| &c[..]), &self.values))
    }
}

impl<const M: usize, T: Float> RegularSpectrum<M, Center, T> {
    /// Point samples of `s` at the bucket centers.
    #[must_use]
    pub fn center(s: &impl Spectrum) -> Self {
        Self::from_spectrum(s)
    }
}

impl<const M: usize, T: Float> RegularSpectrum<M, BoxAverage, T> {
    /// Exact means of `s` over each bucket.
    #[must_use]
    pub fn box_average(s: &impl Spectrum) -> Self {
        Self::from_spectrum(s)
    }
}

pointwise_spectrum!([const M: usize, B: Bucketing<M>] RegularSpectrum[M, B], M, RegularSpectrum::from_values);
