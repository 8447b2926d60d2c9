//! Random wavelengths: `HeroSample<K, T>`, K wavelengths drawn together
//! with their XYZ weights (the study's estimators average them).
//!
//! By default one uniform number `u ∈ [0, 1)` gives the hero wavelength
//! `λ₀ = 380 + u·W` (W = 350 nm) and `K − 1` rotations `λ₀ + j·W/K`, wrapped
//! into 380–730 nm (Wilkie et al. 2014, "Hero Wavelength Spectral
//! Sampling"). Every `λⱼ` is then uniform on the range, with pdf `1/W`.
//! `K = 1` is plain single-wavelength random sampling; `K = 0` does not
//! compile. A renderer names its range, density and observer once in a
//! [`Domain`](crate::sampling::Domain) and draws from it
//! ([`Domain::hero`](crate::sampling::Domain::hero)); with its own sampler
//! it hands its wavelengths and their pdfs to
//! [`HeroSample::from_wavelengths_with`].
//!
//! A hero sample is the drawn kind of wavelengths (see
//! [`super::wavelengths`]): drawing it looks up the observer once per
//! wavelength and keeps the weights `c̄(λⱼ)/(K·pdfⱼ)`, so a sample's XYZ
//! contribution `Σⱼ c̄(λⱼ)·vⱼ / (K·pdfⱼ)` is one weighted sum (a wavelength
//! of pdf 0, for example one [terminated](HeroSample::terminate_secondary),
//! contributes nothing). The constructors without an observer weigh by the
//! dense one (`DenseObserver`: a load per wavelength, as pbrt-v4); the
//! exact one ([`AssignmentObserver`]) is [`HeroSample::exact`] and the `…_with`
//! constructors' choice: an estimate judged against the exact integrals
//! uses it.
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, Xyz};
//! let h = HeroSample::<4>::exact(0.0);
//! assert_eq!(h.lambda(), &[380.0, 467.5, 555.0, 642.5]);
//! let v = lights::D65.sample(&h) * patches::A1.sample(&h);
//! let one = h.to_xyz(v); // a one-sample estimate
//! assert!((h.y(v) - one.y).abs() < 1e-12 * one.y);
//! let n = 1000; // the mean of n, from the renderer's own numbers
//! let mean: Xyz = (0..n).map(|i| {
//!     let h = HeroSample::<4>::exact((i as f64 + 0.5) / n as f64);
//!     h.to_xyz(lights::D65.sample(&h) * patches::A1.sample(&h))
//! }).sum::<Xyz>() / n as f64;
//! assert!(one.y > 0.0 && (mean.y - 82.0).abs() < 1.0);
//! ```
//!
//! ```compile_fail
//! let nothing = speclab::HeroSample::<0>::new(0.5);
//! ```

use crate::error::Error;
use crate::sampling::pdf::WavelengthPdf;
use crate::sampling::wavelengths::{Weighted, weighted_wavelengths};
use crate::spectrum::DenseObserver;
use crate::spectrum::lookup::{ASSIGNMENT_OFFSET, DENSE_RANGE};
use crate::spectrum::observer::{AssignmentObserver, Observer};
use crate::spectrum::{Float, LAMBDA_WIDTH, SampledSpectrum, WavelengthRange};

/// K wavelengths drawn together (a hero and K − 1 companions), each with
/// its density, and their weights `c̄(λⱼ)/(K·pdfⱼ)`: the drawn kind of
/// wavelengths (see [`FixedWavelengths`](super::wavelengths::FixedWavelengths)
/// for the fixed kind, which has no density).
///
/// **Size**: `HeroSample<4, f32>` is 88 bytes (16 of wavelengths, 8 of
/// their whole nanometres, 64 of weight rows `[w_X, w_Y, w_Z, 1/(K·pdf)]`);
/// pbrt-v4's `SampledWavelengths` is 32 (wavelengths and pdfs). The
/// weights are found once, when the sample is drawn, so that `to_xyz` and
/// a film's splat need no observer and cost one multiply-add per
/// wavelength; a renderer whose rays must stay small carries the hero
/// wavelength alone (4 bytes) and rebuilds the sample with
/// [`Domain::hero_at`](crate::sampling::Domain::hero_at).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeroSample<const K: usize, T: Float = f64>(pub(crate) Weighted<K, T>);

weighted_wavelengths!(HeroSample);

impl<const K: usize, T: Float> HeroSample<K, T> {
    /// Drawn wavelengths from what they hold.
    pub(crate) fn from_weighted(w: Weighted<K, T>) -> Self {
        HeroSample(w)
    }

    /// `[X, Y, Z, Σ w₀·v]` of values `v`, from the rows.
    #[inline(always)]
    fn sums(&self, v: &SampledSpectrum<K, T>) -> [T; 4] {
        self.0.sums(v)
    }

    /// Compile-time guard: a sample has at least one wavelength.
    const NONZERO: () = assert!(K > 0, "HeroSample needs at least one wavelength (K > 0)");

    /// The density of a uniform wavelength, 1/nm: `1/W` over 380–730 nm.
    pub const UNIFORM_PDF: f64 = 1.0 / LAMBDA_WIDTH;

    /// The uniform hero sample for `u`, weighted by the dense observer
    /// ([`DenseObserver::ASSIGNMENT`]: the assignment's CIE 1931 observer at
    /// the nearest whole nanometre, as pbrt-v4 looks its own up; over dense spectra its
    /// estimates are unbiased for the integral of the 1 nm steps, whose ∫ȳ
    /// is 6e-8 from the exact one): the fast path, and the one a renderer
    /// wants.
    /// [`HeroSample::exact`] weighs by the exact observer.
    ///
    /// `λⱼ = 380 + W·((u + j/K) mod 1)`, each of pdf `1/W`. The wavelengths
    /// are found in fixed point, as a hand-tuned kernel finds them: `u·W`
    /// rounded down to 2⁻¹⁶ nm, rotated by `W/K` to the same resolution
    /// (each wavelength stays uniform: a fixed rotation of a uniform
    /// wavelength is uniform), so their nearest whole nanometres come
    /// without a conversion. Only the fractional part of `u` counts (1.25
    /// acts as 0.25 and −0.25 as 0.75); a non-finite `u` acts as 0. Every
    /// wavelength lies in [380, 730) nm.
    #[inline(always)]
    #[must_use]
    pub fn new(u: T) -> Self {
        Self::uniform(u, &DenseObserver::ASSIGNMENT)
    }

    /// [`HeroSample::new`] weighted by the exact observer ([`AssignmentObserver`],
    /// the interpolated 5 nm tables of Appendix 1): the reference's
    /// estimator, unbiased for the exact integrals. Costs a cubic
    /// evaluation of the three matching functions per wavelength.
    #[inline(always)]
    #[must_use]
    pub fn exact(u: T) -> Self {
        Self::uniform(u, &AssignmentObserver)
    }

    /// [`HeroSample::new`] with the weights of `observer`: an
    /// [`Error::RangeOutside`] if its data do not cover 380–730 nm (a
    /// sensor's that stop short would weigh those wavelengths 0).
    #[inline]
    pub fn with_observer(u: T, observer: &impl Observer) -> Result<Self, Error> {
        covers(observer, WavelengthRange::ASSIGNMENT)?;
        Ok(Self::uniform(u, observer))
    }

    /// [`HeroSample::new`] weighted by `observer` (covering 380–730 nm).
    #[inline(always)]
    fn uniform(u: T, observer: &impl Observer) -> Self {
        Self::uniform_in(u, UniformGrid::ASSIGNMENT, observer)
    }

    /// Uniform over `grid`'s whole nanometres, in fixed point (see
    /// [`HeroSample::new`]), weighted by `observer` (covering it).
    #[inline(always)]
    pub(crate) fn uniform_in(u: T, grid: UniformGrid, observer: &impl Observer) -> Self {
        let () = Self::NONZERO;
        // Positions in 2⁻¹⁶ nm from the range's start: [0, period).
        let period = grid.width << 16;
        // (The minimum only tells the compiler that p0 < period, so that the
        // nearest whole nanometres are known to be in the table.)
        let p0 = ((fract(u.to_f64()) * f64::from(period)) as u32).min(period - 1);
        let position = |j: usize| {
            let p = p0 + (u64::from(period) * j as u64 / K as u64) as u32;
            if p >= period { p - period } else { p }
        };
        let p: [u32; K] = std::array::from_fn(position);
        let start = DENSE_START + f64::from(grid.offset);
        let lambda = std::array::from_fn(|j| T::from_f64(start + f64::from(p[j]) * (1.0 / 65536.0)));
        // The nearest whole nanometre's index from 360 nm: half a nanometre
        // and the range's offset added in one constant before the shift.
        let round = 0x8000 + (grid.offset << 16);
        let nearest = std::array::from_fn(|j| ((p[j] + round) >> 16) as u16);
        let h = HeroSample(Weighted { lambda, nearest, rows: [[T::ZERO; 4]; K] });
        Self::weighted(h, [T::from_f64(f64::from(grid.width)); K], observer)
    }

    /// The sample for `u` under the density `pdf`, rotated in primary-sample
    /// space: `λⱼ = P⁻¹((u + j/K) mod 1)`, so that every `λⱼ` has density p
    /// and the estimate `Σⱼ c̄·vⱼ / (K·p(λⱼ))` stays unbiased; weighted by
    /// `observer` (`DenseObserver::CIE_1931` for a renderer's,
    /// [`AssignmentObserver`] for the exact assignment's). An
    /// [`Error::RangeOutside`] if the pdf draws where the observer has no
    /// data (those wavelengths would weigh nothing). `u` is taken as in
    /// [`HeroSample::new`]. A renderer checks once and draws without a
    /// `Result`: [`Domain::hero`](crate::sampling::Domain::hero).
    #[inline]
    pub fn from_pdf_with<P: WavelengthPdf + ?Sized>(
        u: T,
        pdf: &P,
        observer: &impl Observer,
    ) -> Result<Self, Error> {
        covers(observer, pdf.support())?;
        Ok(Self::drawn(u, pdf, observer))
    }

    /// [`HeroSample::from_pdf_with`] without the check (the caller's own).
    #[inline(always)]
    pub(crate) fn drawn<P: WavelengthPdf + ?Sized>(u: T, pdf: &P, observer: &impl Observer) -> Self {
        let () = Self::NONZERO;
        let u = fract(u.to_f64());
        let (mut lambda, mut inv_pdf) = ([T::ZERO; K], [T::ZERO; K]);
        for (j, (l, w)) in lambda.iter_mut().zip(&mut inv_pdf).enumerate() {
            let (drawn, reciprocal) = pdf.sample_with_inv_pdf(rotation(u, j, K));
            (*l, *w) = (T::from_f64(drawn), T::from_f64(reciprocal));
        }
        Self::weighted(HeroSample(Weighted::at(lambda)), inv_pdf, observer)
    }

    /// The sample of wavelengths `lambda` (nm) drawn with densities `pdf`
    /// (1/nm), from a renderer's own sampler and distribution, weighted by
    /// `observer`. Each wavelength must be finite and inside the
    /// observer's data (else an [`Error::SampleWavelength`] naming it), and
    /// each pdf finite and non-negative with a finite reciprocal; a pdf of
    /// 0 marks a wavelength that contributes nothing (and may lie anywhere).
    pub fn from_wavelengths_with(
        lambda: [T; K],
        pdf: [T; K],
        observer: &impl Observer,
    ) -> Result<Self, Error> {
        let () = Self::NONZERO;
        let data = observer.data_range();
        let mut inv_pdf = [T::ZERO; K];
        for (index, ((&l, &p), w)) in lambda.iter().zip(&pdf).zip(&mut inv_pdf).enumerate() {
            let (l, p) = (l.to_f64(), p.to_f64());
            // A pdf so small that its reciprocal overflows is as unusable as ∞.
            let reciprocal = T::from_f64(if p > 0.0 { 1.0 / p } else { 0.0 });
            let seen = p == 0.0 || data.contains(l);
            if !(l.is_finite() && p.is_finite() && p >= 0.0 && reciprocal.to_f64().is_finite() && seen) {
                return Err(Error::SampleWavelength { index, lambda: l, pdf: p });
            }
            *w = reciprocal;
        }
        Ok(Self::weighted(HeroSample(Weighted::at(lambda)), inv_pdf, observer))
    }

    /// The sample `h` (wavelengths drawn with reciprocal densities
    /// `inv_pdf`) with its weights from `observer`.
    #[inline(always)]
    fn weighted(h: Self, inv_pdf: [T; K], observer: &impl Observer) -> Self {
        let cmf = observer.xyz_bar_at(&h);
        let per_k = T::from_f64(1.0 / K as f64);
        HeroSample(h.0.drawn(cmf, inv_pdf.map(|w| w * per_k)))
    }

    /// The density of each wavelength, 1/nm (0 for a dropped wavelength).
    #[inline]
    #[must_use]
    pub fn pdf(&self) -> [T; K] {
        let k = T::from_f64(K as f64);
        self.0.rows.map(|[.., w]| if w > T::ZERO { T::ONE / (k * w) } else { T::ZERO })
    }

    /// The reciprocal of each wavelength's density, nm (0 for a dropped
    /// wavelength).
    #[inline]
    #[must_use]
    pub fn inv_pdf(&self) -> [T; K] {
        let k = T::from_f64(K as f64);
        self.0.rows.map(|[.., w]| w * k)
    }

    /// Keeps the hero alone (pbrt-v4's `TerminateSecondary`, for dispersion:
    /// a wavelength-dependent path must follow one wavelength). The other
    /// weights become 0, and the hero's are multiplied by K, so that its
    /// single term `c̄·v₀ / (K·pdf₀/K)` is still an unbiased estimate. Doing
    /// it twice changes nothing.
    #[inline]
    pub fn terminate_secondary(&mut self) {
        if self.secondary_terminated() {
            return;
        }
        let k = T::from_f64(K as f64);
        let rows = &mut self.0.rows;
        rows[0] = rows[0].map(|w| w * k);
        rows[1..].fill([T::ZERO; 4]);
    }

    /// True if only the hero contributes (always true for `K = 1`).
    #[inline]
    #[must_use]
    pub fn secondary_terminated(&self) -> bool {
        self.0.rows[1..].iter().all(|&[.., w]| w == T::ZERO)
    }
}

/// `Ok` if `observer`'s data cover `range` (what a density of that support
/// draws), else an [`Error::RangeOutside`].
pub(crate) fn covers(observer: &impl Observer, range: WavelengthRange) -> Result<(), Error> {
    let data = observer.data_range();
    if range.within(data) {
        Ok(())
    } else {
        let of = "the weighing observer";
        Err(Error::RangeOutside { range: [range.min(), range.max()], of, data: [data.min(), data.max()] })
    }
}

/// Rotation `j` of `K` from `u ∈ [0, 1)`: `(u + j/K) mod 1`.
#[inline(always)]
fn rotation(u: f64, j: usize, k: usize) -> f64 {
    let v = u + j as f64 / k as f64;
    if v >= 1.0 { v - 1.0 } else { v }
}

/// `u − ⌊u⌋` in [0, 1), without libm (baseline x86-64 has no rounding
/// instruction): `u` itself in the usual case of `u ∈ [0, 1)`; otherwise 0
/// for NaN, ±∞ and magnitudes of 2⁵² and more (which are integers).
#[inline(always)]
fn fract(u: f64) -> f64 {
    if (0.0..1.0).contains(&u) {
        return u;
    }
    fract_slow(u)
}

#[cold]
fn fract_slow(u: f64) -> f64 {
    // False for NaN too.
    let exact_integer_part = u.abs() < 4_503_599_627_370_496.0;
    if !exact_integer_part {
        return 0.0;
    }
    let f = u - (u as i64) as f64;
    let f = if f < 0.0 { f + 1.0 } else { f };
    // −1e-17 + 1 rounds to 1.
    if f < 1.0 { f } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fract_matches_floor() {
        for u in [0.0f64, 0.25, 1.0, 1.25, -0.25, -1.0, -1e-17, 3.5e15 + 0.5, -7.75, 0.999_999_999] {
            let want = u - u.floor();
            let want = if want < 1.0 { want } else { 0.0 };
            assert_eq!(fract(u), want, "u = {u}");
        }
        for u in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 4.6e15, -1e300] {
            assert_eq!(fract(u), 0.0, "u = {u}");
        }
    }
}

/// The first dense-table wavelength, nm (360).
const DENSE_START: f64 = DENSE_RANGE.min();

/// A uniform density's range as whole nanometres of the dense tables:
/// `offset` from 360 nm, `width` nm (both whole, the range within
/// 360–830 nm), where hero samples are drawn in fixed point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct UniformGrid {
    pub(crate) offset: u32,
    pub(crate) width: u32,
}

impl UniformGrid {
    /// 380–730 nm.
    pub(crate) const ASSIGNMENT: UniformGrid =
        UniformGrid { offset: ASSIGNMENT_OFFSET as u32, width: LAMBDA_WIDTH as u32 };
    /// 360–830 nm.
    pub(crate) const VISIBLE: UniformGrid = UniformGrid { offset: 0, width: DENSE_RANGE.width() as u32 };

    /// The grid of `range` if it is whole nanometres within 360–830 nm.
    pub(crate) fn of(range: WavelengthRange) -> Option<UniformGrid> {
        let (a, b) = (range.min() - DENSE_START, range.max() - DENSE_START);
        let whole = a.fract() == 0.0 && b.fract() == 0.0 && a >= 0.0 && b > a;
        (whole && range.max() <= DENSE_RANGE.max())
            .then_some(UniformGrid { offset: a as u32, width: (b - a) as u32 })
    }
}
