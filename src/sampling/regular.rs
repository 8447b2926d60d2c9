//! Fixed wavelength buckets with M known at compile time:
//! `RegularSpectrum<M, B>`, the renderer's type.
//!
//! The range 380–730 nm is cut into `M` equal buckets, and a spectrum
//! becomes `M` numbers by a rule chosen by a type (see
//! [`super::buckets`] for the rules themselves):
//!
//! - [`Center`]: the value at each bucket center `λᵢ = 380 + (i + ½)·W/M`;
//! - [`BoxAverage`]: the exact mean of the interpolant over each bucket.
//!
//! Values have the same point-wise arithmetic as a `SampledSpectrum` (`+ -
//! * /` with each other and with scalars, assign forms, `safe_div`,
//! `clamp`, `exp`, …), so a path's throughput can be carried in buckets
//! too, and [`RegularSpectrum::to_xyz`] is the Riemann sum
//! `W/M · Σ valueᵢ · c̄ᵢ`, where `c̄ᵢ` are the matching functions bucketed
//! the same way: associated constants, computed once per `M` at compile
//! time. `M = 0` does not compile.
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
use crate::sampling::buckets::{BucketRule, box_means, center, dot4};
use crate::spectrum::pointwise::pointwise_spectrum;
use crate::spectrum::{LAMBDA_WIDTH, Spectrum};

/// A bucket rule as a type, so that values bucketed by different rules
/// cannot be mixed.
pub trait Bucketing<const M: usize>: Copy + Default + std::fmt::Debug {
    /// The rule this type stands for.
    const RULE: BucketRule;
    /// The matching functions bucketed by this rule, computed at compile
    /// time: x̄ᵢ, ȳᵢ and z̄ᵢ as three rows (one dot product each).
    const OBSERVER: [[f64; M]; 3] = observer_rows::<M>(Self::RULE);
    /// The `M` bucket values of `s`.
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M];
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

/// `rule`'s bucketed observer as three rows, at compile time.
const fn observer_rows<const M: usize>(rule: BucketRule) -> [[f64; M]; 3] {
    let mut out = [[0.0; M]; 3];
    let mut i = 0;
    while i < M {
        let [x, y, z] = rule.observer(i, M);
        out[0][i] = x;
        out[1][i] = y;
        out[2][i] = z;
        i += 1;
    }
    out
}

/// A spectrum as `M` equidistant buckets over 380–730 nm, bucketed by `B`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegularSpectrum<const M: usize, B: Bucketing<M> = Center> {
    values: [f64; M],
    rule: PhantomData<B>,
}

impl<const M: usize, B: Bucketing<M>> RegularSpectrum<M, B> {
    /// Compile-time guard: there is no spectrum of zero buckets.
    const NONZERO: () = assert!(M > 0, "RegularSpectrum needs at least one bucket (M > 0)");

    /// Buckets `s` by the rule `B`.
    #[inline]
    #[must_use]
    pub fn from_spectrum(s: &impl Spectrum) -> Self {
        Self::from_values(B::buckets(s))
    }

    /// From bucket values directly.
    #[inline]
    #[must_use]
    pub fn from_values(values: [f64; M]) -> Self {
        let () = Self::NONZERO;
        RegularSpectrum { values, rule: PhantomData }
    }

    /// The bucket values.
    #[inline]
    #[must_use]
    pub fn values(&self) -> &[f64; M] {
        &self.values
    }

    /// The center wavelength of bucket `i`, nm.
    #[must_use]
    pub fn lambda(i: usize) -> f64 {
        center(i, M)
    }

    /// The Riemann sum `W/M · Σ valueᵢ · c̄ᵢ`: three dot products, each
    /// with four independent partial sums.
    #[inline]
    #[must_use]
    pub fn to_xyz(&self) -> Xyz {
        let [x, y, z] = &B::OBSERVER;
        let dot = |row: &[f64; M]| dot4(M, |i| self.values[i] * row[i]);
        Xyz::new(dot(x), dot(y), dot(z)) * (LAMBDA_WIDTH / M as f64)
    }
}

impl<const M: usize> RegularSpectrum<M, Center> {
    /// Point samples of `s` at the bucket centers.
    #[must_use]
    pub fn center(s: &impl Spectrum) -> Self {
        Self::from_spectrum(s)
    }
}

impl<const M: usize> RegularSpectrum<M, BoxAverage> {
    /// Exact means of `s` over each bucket.
    #[must_use]
    pub fn box_average(s: &impl Spectrum) -> Self {
        Self::from_spectrum(s)
    }
}

pointwise_spectrum!([const M: usize, B: Bucketing<M>] RegularSpectrum<M, B>, M, RegularSpectrum::from_values);
