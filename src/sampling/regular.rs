//! Fixed wavelength buckets with M known at compile time:
//! `RegularSpectrum<M, B, T>`, the renderer's type, in `f64` (the default)
//! or `f32`.
//!
//! A range, the assignment's 380–730 nm by default, is cut into `M`
//! equal buckets, and a spectrum becomes `M` numbers by a rule chosen by a
//! type (see [`super::buckets`] for the rules themselves):
//!
//! - [`Center`]: the value at each bucket center `λᵢ = min + (i + ½)·W/M`;
//! - [`BoxAverage`]: the exact mean of the interpolant over each bucket.
//!
//! The range and its observer are a type too, a [`Band`]:
//! [`AssignmentBand`] (380–730 nm, the assignment's observer: the
//! default, so `Center` is `Center<AssignmentBand>`) or [`VisibleBand`]
//! (360–830 nm, the CIE 1931 2° observer's 1 nm table, as pbrt-v4 and
//! Mitsuba 3 integrate): `RegularSpectrum<16, Center<VisibleBand>>`.
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
//! together (their products would be converted with the wrong c̄ᵢ), and
//! neither can values over different bands:
//!
//! ```compile_fail
//! use speclab::{data::{lights, patches}, RegularSpectrum, Center, sampling::VisibleBand};
//! let light = RegularSpectrum::<16, Center<VisibleBand>>::center(&lights::D65);
//! let surface = RegularSpectrum::<16, Center>::center(&patches::A1);
//! let mixed = light * surface;
//! ```
//!
//! Over 360–830 nm with the CIE 1931 observer:
//!
//! ```
//! use speclab::{data::lights, RegularSpectrum, BoxAverage, sampling::{VisibleBand, reference}};
//! use speclab::spectrum::{DenseSpectrum, StandardObserver, WavelengthRange};
//! let d65 = DenseSpectrum::new(&lights::CIE_D65);
//! let xyz = RegularSpectrum::<32, BoxAverage<VisibleBand>>::box_average(&d65).to_xyz();
//! // Values over one band multiply (the twin of the example above that does not compile).
//! let g4 = RegularSpectrum::<32, BoxAverage<VisibleBand>>::box_average(&speclab::data::patches::G4);
//! assert!(((RegularSpectrum::box_average(&d65) * g4).to_xyz().y) < xyz.y);
//! let exact = reference::xyz_over(StandardObserver::Cie1931, WavelengthRange::VISIBLE, &[&d65])?;
//! assert!((xyz.y / exact.y - 1.0).abs() < 1e-3);
//! # Ok::<(), speclab::Error>(())
//! ```
//!
//!
//! ```compile_fail
//! use speclab::{data::{lights, patches}, RegularSpectrum, BoxAverage, Center};
//! let light = RegularSpectrum::<16, Center>::center(&lights::D65);
//! let surface = RegularSpectrum::<16, BoxAverage>::box_average(&patches::A1);
//! let mixed = light * surface;
//! ```

use std::marker::PhantomData;

use crate::color::Xyz;
use crate::sampling::buckets::{BucketRule, box_means_in, center_in};
use crate::sampling::wavelengths::{FixedWavelengths, Weighted};
use crate::spectrum::pointwise::pointwise_spectrum;
use crate::spectrum::simd::{column_sums, columns};
use crate::spectrum::{Float, Spectrum, StandardObserver, WavelengthRange};

/// A range and an observer as a type, so that values bucketed over
/// different ranges cannot be mixed.
pub trait Band:
    Copy + Default + std::fmt::Debug + PartialEq + Eq + std::hash::Hash + Send + Sync + 'static
{
    /// The range the buckets cut.
    const RANGE: WavelengthRange;
    /// The observer the buckets' weights come from.
    const OBSERVER: StandardObserver;
}

/// The assignment's 380–730 nm with its observer (Appendix 2's).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct AssignmentBand;

impl Band for AssignmentBand {
    const RANGE: WavelengthRange = WavelengthRange::ASSIGNMENT;
    const OBSERVER: StandardObserver = StandardObserver::Assignment;
}

/// 360–830 nm with the CIE 1931 2° observer's 1 nm table (pbrt-v4's and
/// Mitsuba 3's range).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct VisibleBand;

impl Band for VisibleBand {
    const RANGE: WavelengthRange = WavelengthRange::VISIBLE;
    const OBSERVER: StandardObserver = StandardObserver::Cie1931;
}

/// A bucket rule as a type, so that values bucketed by different rules
/// cannot be mixed.
pub trait Bucketing<const M: usize>: Copy + Default + std::fmt::Debug {
    /// The rule this type stands for.
    const RULE: BucketRule;
    /// The range cut into buckets and the observer of the weights.
    type Band: Band;
    /// The buckets' weights, computed at compile time: one row
    /// `[W/M·x̄ᵢ, W/M·ȳᵢ, W/M·z̄ᵢ, 0]` per bucket, with `c̄ᵢ` the matching
    /// functions bucketed by this rule (the width folded in, so that XYZ is
    /// `Σᵢ rowᵢ·valueᵢ`; `to_xyz` sums the same weights as columns).
    const ROWS_F64: &'static [[f64; 4]; M] =
        &rows::<M>(Self::RULE, <Self::Band as Band>::OBSERVER, <Self::Band as Band>::RANGE);
    /// The same, rounded to `f32`.
    const ROWS_F32: &'static [[f32; 4]; M] = &crate::spectrum::float::rounded(Self::ROWS_F64);
    /// The `M` bucket values of `s`.
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M];

    /// The buckets as fixed wavelengths (the centres) with their weights.
    /// Sampling at them gives centre values: for box buckets, use
    /// [`RegularSpectrum::box_average`] for the values.
    #[must_use]
    fn wavelengths<T: Float>() -> FixedWavelengths<M, T> {
        let lambda = const { centers::<M>(<Self::Band as Band>::RANGE) }.map(T::from_f64);
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

/// Point samples at bucket centers ([`BucketRule::Center`]) over the
/// band `R`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Center<R: Band = AssignmentBand>(PhantomData<R>);

/// Exact means over each bucket ([`BucketRule::BoxAverage`]) of the band `R`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct BoxAverage<R: Band = AssignmentBand>(PhantomData<R>);

impl<const M: usize, R: Band> Bucketing<M> for Center<R> {
    const RULE: BucketRule = BucketRule::Center;
    type Band = R;
    /// The spectrum at the `M` centers, evaluated side by side.
    #[inline]
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M] {
        let mut out = [0.0; M];
        s.eval_many(&const { centers::<M>(R::RANGE) }, &mut out);
        out
    }
}

impl<const M: usize, R: Band> Bucketing<M> for BoxAverage<R> {
    const RULE: BucketRule = BucketRule::BoxAverage;
    type Band = R;
    #[inline]
    fn buckets<S: Spectrum + ?Sized>(s: &S) -> [f64; M] {
        let mut out = [0.0; M];
        box_means_in(s, R::RANGE, &mut out);
        out
    }
}

/// The `M` bucket centers over `range`, nm.
const fn centers<const M: usize>(range: WavelengthRange) -> [f64; M] {
    let mut out = [0.0; M];
    let mut i = 0;
    while i < M {
        out[i] = center_in(range, i, M);
        i += 1;
    }
    out
}

/// `rule`'s bucketed observer times the width, one row
/// `[W/M·x̄ᵢ, W/M·ȳᵢ, W/M·z̄ᵢ, 0]` per bucket, at compile time.
const fn rows<const M: usize>(
    rule: BucketRule,
    observer: StandardObserver,
    range: WavelengthRange,
) -> [[f64; 4]; M] {
    let mut out = [[0.0; 4]; M];
    let width = range.width() / M as f64;
    let mut i = 0;
    while i < M {
        let w = rule.observer_over(observer, range, i, M);
        out[i] = [width * w[0], width * w[1], width * w[2], 0.0];
        i += 1;
    }
    out
}

/// A spectrum as `M` equidistant buckets over a range (380–730 nm unless
/// `B`'s band says otherwise), bucketed by `B`, in precision `T`.
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
        center_in(<B::Band as Band>::RANGE, i, M)
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

    /// The `Y` of a constant 1, `W/M·Σ ȳᵢ` of the bucketed observer: what
    /// these buckets normalise by (a constant, at compile time).
    pub const WHITE_Y: f64 = white_y(B::ROWS_F64);

    /// [`to_xyz`](Self::to_xyz) over [`WHITE_Y`](Self::WHITE_Y): a constant
    /// 1 has `Y = 1` exactly, whatever the band.
    #[inline]
    #[must_use]
    pub fn to_normalized_xyz(&self) -> Xyz {
        self.to_xyz() / Self::WHITE_Y
    }
}

/// `Σ rowsᵢ[1]`.
const fn white_y<const M: usize>(rows: &[[f64; 4]; M]) -> f64 {
    let mut sum = 0.0;
    let mut i = 0;
    while i < M {
        sum += rows[i][1];
        i += 1;
    }
    sum
}

impl<const M: usize, R: Band, T: Float> RegularSpectrum<M, Center<R>, T> {
    /// Point samples of `s` at the bucket centers.
    #[must_use]
    pub fn center(s: &impl Spectrum) -> Self {
        Self::from_spectrum(s)
    }
}

impl<const M: usize, R: Band, T: Float> RegularSpectrum<M, BoxAverage<R>, T> {
    /// Exact means of `s` over each bucket.
    #[must_use]
    pub fn box_average(s: &impl Spectrum) -> Self {
        Self::from_spectrum(s)
    }
}

pointwise_spectrum!([const M: usize, B: Bucketing<M>] RegularSpectrum[M, B], M, RegularSpectrum::from_values);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Constant;

    /// Box means of a constant are the observer's integral over the band
    /// at any M; over 360–830 nm the 1 nm table's trapezoids, exactly.
    #[test]
    fn the_visible_band_integrates_the_cie_table() {
        let exact = StandardObserver::Cie1931.integrals(WavelengthRange::VISIBLE).unwrap();
        let one = Constant::new(1.0);
        let sums = [
            RegularSpectrum::<1, BoxAverage<VisibleBand>>::box_average(&one).to_xyz(),
            RegularSpectrum::<7, BoxAverage<VisibleBand>>::box_average(&one).to_xyz(),
            RegularSpectrum::<47, BoxAverage<VisibleBand>>::box_average(&one).to_xyz(),
            // Centres of whole nanometres: the midpoints of the lines.
            RegularSpectrum::<470, Center<VisibleBand>>::center(&one).to_xyz(),
        ];
        for xyz in sums {
            for (got, want) in xyz.to_array().into_iter().zip(exact) {
                assert!((got - want).abs() < 1e-12 * want, "{xyz:?} against {exact:?}");
            }
        }
        let assignment = StandardObserver::Assignment.integrals(WavelengthRange::ASSIGNMENT).unwrap();
        let xyz = RegularSpectrum::<5, BoxAverage>::box_average(&one).to_xyz();
        assert!((xyz.y - assignment[1]).abs() < 1e-12 * assignment[1]);
    }

    #[test]
    fn centres_follow_the_band() {
        type Visible = RegularSpectrum<47, Center<VisibleBand>>;
        assert_eq!((Visible::lambda(0), Visible::lambda(46)), (365.0, 825.0));
        assert_eq!(RegularSpectrum::<35>::lambda(0), 385.0);
        let rows = <Center<VisibleBand> as Bucketing<47>>::ROWS_F64;
        for (i, row) in rows.iter().enumerate() {
            let bar = StandardObserver::Cie1931.xyz_bar(Visible::lambda(i));
            (0..3).for_each(|c| assert!((row[c] - 10.0 * bar[c]).abs() < 1e-15, "{i}"));
        }
        let ramp = crate::spectrum::FnSpectrum(|lambda: f64| lambda);
        assert_eq!(Visible::center(&ramp).values()[1], 375.0);
        assert!(
            (RegularSpectrum::<47, BoxAverage<VisibleBand>>::box_average(&ramp).values()[1] - 375.0).abs()
                < 1e-9
        );
    }
}
