//! Fixed wavelength buckets: `RegularSpectrum<M>`.
//!
//! The range 380–730 nm (width W = 350 nm) is cut into `M` equal buckets.
//! A spectrum becomes `M` numbers in one of two ways, chosen by a type:
//!
//! - [`Centre`]: the value at each bucket centre `λᵢ = 380 + (i + ½)·W/M`;
//! - [`BoxAverage`]: the exact mean of the interpolant over each bucket.
//!
//! Products are point-wise ([`Mul`]), and [`RegularSpectrum::to_xyz`] is the
//! Riemann sum `W/M · Σ valueᵢ · c̄ᵢ`, where `c̄ᵢ` are the matching functions
//! bucketed the same way. Those tables are associated constants, computed
//! once per `M` at compile time. `M = 0` does not compile.
//!
//! On a smooth light both rules converge fast. On F11 centre sampling hits or
//! misses the spikes depending on `M`; box averaging keeps their energy.
//!
//! ```
//! use speclab::{data, RegularSpectrum};
//! let light = RegularSpectrum::<16>::centre(&data::D65);
//! let surface = RegularSpectrum::<16>::centre(&data::A1);
//! let rgb = (light * surface).to_xyz().to_linear_srgb();
//! assert!((rgb.g - 82.44).abs() < 1.0);
//! ```
//!
//! ```compile_fail
//! let empty = speclab::RegularSpectrum::<0>::centre(&speclab::data::D65);
//! ```
//!
//! Centre and box values are different types and cannot be multiplied
//! together (their products would be converted with the wrong c̄ᵢ):
//!
//! ```compile_fail
//! use speclab::{data, RegularSpectrum, BoxAverage, Centre};
//! let light = RegularSpectrum::<16, Centre>::centre(&data::D65);
//! let surface = RegularSpectrum::<16, BoxAverage>::box_average(&data::A1);
//! let mixed = light * surface;
//! ```

use std::marker::PhantomData;
use std::ops::Mul;

use crate::spectrum::data::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA,
};
use crate::spectrum::interp;
use crate::{Error, LAMBDA_MIN, Role, TabulatedSpectrum, WIDTH, Xyz};

/// A rule that turns a spectrum into `M` bucket values.
pub trait Bucketing<const M: usize>: Copy + Default + std::fmt::Debug {
    /// The matching functions bucketed by this rule, computed at compile
    /// time: x̄ᵢ, ȳᵢ and z̄ᵢ as three rows (one dot product each).
    const OBSERVER: [[f64; M]; 3];
    /// The `M` bucket values of `s`.
    fn buckets(s: &TabulatedSpectrum) -> [f64; M];
}

/// Point samples at bucket centres.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Centre;

/// Exact means over each bucket.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BoxAverage;

/// The lower edge of bucket `i` of `m`, nm (`edge(m, m)` is 730 nm).
#[inline]
const fn edge(i: usize, m: usize) -> f64 {
    LAMBDA_MIN + i as f64 * WIDTH / m as f64
}

/// The centre of bucket `i` of `m`, nm.
#[inline]
const fn centre(i: usize, m: usize) -> f64 {
    0.5 * (edge(i, m) + edge(i + 1, m))
}

impl<const M: usize> Bucketing<M> for Centre {
    const OBSERVER: [[f64; M]; 3] = centre_observer::<M>();
    /// The spectrum at the `M` centres, evaluated side by side.
    #[inline]
    fn buckets(s: &TabulatedSpectrum) -> [f64; M] {
        s.eval_lanes(&const { centres::<M>() })
    }
}

impl<const M: usize> Bucketing<M> for BoxAverage {
    const OBSERVER: [[f64; M]; 3] = box_observer::<M>();
    /// Differences of the exact cumulative integral at the `M + 1` edges:
    /// O(1) per edge from the integrals stored with the spectrum.
    #[inline]
    fn buckets(s: &TabulatedSpectrum) -> [f64; M] {
        let inv_width = M as f64 / WIDTH;
        let mut out = [0.0; M];
        let mut below = s.cumulative(edge(0, M));
        for (i, v) in out.iter_mut().enumerate() {
            let above = s.cumulative(edge(i + 1, M));
            *v = (above - below) * inv_width;
            below = above;
        }
        out
    }
}

const CMF_BOUNDS: [f64; 2] = Role::Observer.bounds();

/// The `M` bucket centres, nm.
const fn centres<const M: usize>() -> [f64; M] {
    let mut out = [0.0; M];
    let mut i = 0;
    while i < M {
        out[i] = centre(i, M);
        i += 1;
    }
    out
}

/// `(x̄, ȳ, z̄)` at the centres of `M` buckets, evaluated at compile time.
const fn centre_observer<const M: usize>() -> [[f64; M]; 3] {
    let mut out = [[0.0; M]; 3];
    let mut i = 0;
    while i < M {
        let lambda = centre(i, M);
        out[0][i] = interp::eval(&CIE_X_LAMBDA, &CIE_X_COEFFS, CMF_BOUNDS, lambda);
        out[1][i] = interp::eval(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, CMF_BOUNDS, lambda);
        out[2][i] = interp::eval(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, CMF_BOUNDS, lambda);
        i += 1;
    }
    out
}

/// The exact means of `(x̄, ȳ, z̄)` over each of `M` buckets, evaluated at
/// compile time.
const fn box_observer<const M: usize>() -> [[f64; M]; 3] {
    let mut out = [[0.0; M]; 3];
    let mut i = 0;
    while i < M {
        let (a, b) = (edge(i, M), edge(i + 1, M));
        out[0][i] = interp::integral(&CIE_X_LAMBDA, &CIE_X_COEFFS, &CIE_X_BREAKS, CMF_BOUNDS, a, b) / (b - a);
        out[1][i] = interp::integral(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, &CIE_Y_BREAKS, CMF_BOUNDS, a, b) / (b - a);
        out[2][i] = interp::integral(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, &CIE_Z_BREAKS, CMF_BOUNDS, a, b) / (b - a);
        i += 1;
    }
    out
}

/// A spectrum as `M` equidistant buckets over 380–730 nm, bucketed by `B`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegularSpectrum<const M: usize, B: Bucketing<M> = Centre> {
    values: [f64; M],
    rule: PhantomData<B>,
}

impl<const M: usize, B: Bucketing<M>> RegularSpectrum<M, B> {
    /// Compile-time guard: there is no spectrum of zero buckets.
    const NONZERO: () = assert!(M > 0, "RegularSpectrum needs at least one bucket (M > 0)");

    /// Buckets `s` by the rule `B`.
    #[inline]
    #[must_use]
    pub fn from_spectrum(s: &TabulatedSpectrum) -> Self {
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

    /// The centre wavelength of bucket `i`, nm.
    #[must_use]
    pub fn lambda(i: usize) -> f64 {
        centre(i, M)
    }

    /// The Riemann sum `W/M · Σ valueᵢ · c̄ᵢ`: three dot products, each
    /// with four independent partial sums.
    #[inline]
    #[must_use]
    pub fn to_xyz(&self) -> Xyz {
        let [x, y, z] = &B::OBSERVER;
        Xyz::new(dot(&self.values, x), dot(&self.values, y), dot(&self.values, z)) * (WIDTH / M as f64)
    }
}

impl<const M: usize> RegularSpectrum<M, Centre> {
    /// Point samples of `s` at the bucket centres.
    #[must_use]
    pub fn centre(s: &TabulatedSpectrum) -> Self {
        Self::from_spectrum(s)
    }
}

impl<const M: usize> RegularSpectrum<M, BoxAverage> {
    /// Exact means of `s` over each bucket.
    #[must_use]
    pub fn box_average(s: &TabulatedSpectrum) -> Self {
        Self::from_spectrum(s)
    }
}

impl<const M: usize, B: Bucketing<M>> Mul for RegularSpectrum<M, B> {
    type Output = Self;
    /// The point-wise product.
    #[inline]
    fn mul(mut self, o: Self) -> Self {
        for (a, b) in self.values.iter_mut().zip(o.values) {
            *a *= b;
        }
        self
    }
}

/// `Σ aᵢ·bᵢ` in four interleaved partial sums, so that the additions do not
/// wait on each other.
#[inline(always)]
fn dot<const M: usize>(a: &[f64; M], b: &[f64; M]) -> f64 {
    let mut acc = [0.0; 4];
    for i in 0..M {
        acc[i % 4] += a[i] * b[i];
    }
    (acc[0] + acc[2]) + (acc[1] + acc[3])
}

/// A bucket rule chosen at run time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rule {
    /// [`Centre`]: point samples at bucket centres.
    Centre,
    /// [`BoxAverage`]: exact means over buckets.
    BoxAverage,
}

/// The largest `M` that [`xyz_dyn`] dispatches to a compiled instance.
pub const MAX_BUCKETS: usize = 64;

/// XYZ of `light × surface` with `m` buckets under `rule`, for `m` known only
/// at run time: dispatches to the compiled `RegularSpectrum<M>` for every
/// `m` from 1 to [`MAX_BUCKETS`], and returns an error for any other `m`.
///
/// ```
/// use speclab::{data, sampling::regular::{self, Rule}, RegularSpectrum};
/// let dynamic = regular::xyz_dyn(16, Rule::Centre, &data::A, &data::G4)?;
/// let fixed = RegularSpectrum::<16>::centre(&data::A) * RegularSpectrum::centre(&data::G4);
/// assert_eq!(dynamic, fixed.to_xyz());
/// assert!(regular::xyz_dyn(0, Rule::Centre, &data::A, &data::G4).is_err());
/// # Ok::<(), speclab::Error>(())
/// ```
pub fn xyz_dyn(
    m: usize,
    rule: Rule,
    light: &TabulatedSpectrum,
    surface: &TabulatedSpectrum,
) -> Result<Xyz, Error> {
    struct Product<'a>(&'a TabulatedSpectrum, &'a TabulatedSpectrum);
    impl WithBuckets for Product<'_> {
        type Output = Xyz;
        fn run<const M: usize, B: Bucketing<M>>(self) -> Xyz {
            (RegularSpectrum::<M, B>::from_spectrum(self.0) * RegularSpectrum::<M, B>::from_spectrum(self.1))
                .to_xyz()
        }
    }
    with_buckets(m, rule, Product(light, surface))
}

/// Work on `RegularSpectrum<M, B>` for an `M` and rule known only at run
/// time (see [`with_buckets`]).
pub(crate) trait WithBuckets {
    /// What the work returns.
    type Output;
    /// Does the work with the compiled `M` and rule `B`.
    fn run<const M: usize, B: Bucketing<M>>(self) -> Self::Output;
}

/// Runs `work` with the compiled `RegularSpectrum<M, B>` for `m` from 1 to
/// [`MAX_BUCKETS`] and `rule`; an error for any other `m`.
pub(crate) fn with_buckets<W: WithBuckets>(m: usize, rule: Rule, work: W) -> Result<W::Output, Error> {
    macro_rules! dispatch {
        ($($n:literal)*) => {
            match (m, rule) {
                $(
                    ($n, Rule::Centre) => Ok(work.run::<$n, Centre>()),
                    ($n, Rule::BoxAverage) => Ok(work.run::<$n, BoxAverage>()),
                )*
                _ => Err(Error::UnsupportedBuckets { m, max: MAX_BUCKETS }),
            }
        };
    }
    dispatch!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32
        33 34 35 36 37 38 39 40 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55 56 57 58 59 60 61 62 63 64)
}
