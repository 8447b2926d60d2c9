//! Random wavelengths: `HeroSample<K>`, K wavelengths with a pdf each, and
//! the Monte Carlo estimator.
//!
//! By default one uniform number `u ∈ [0, 1)` gives the hero wavelength
//! `λ₀ = 380 + u·W` (W = 350 nm) and `K − 1` rotations `λ₀ + j·W/K`, wrapped
//! into 380–730 nm (Wilkie et al. 2014, "Hero Wavelength Spectral
//! Sampling"). Every `λⱼ` is then uniform on the range, with pdf `1/W`.
//! `K = 1` is plain single-wavelength random sampling; `K = 0` does not
//! compile. A renderer with its own sampler or wavelength distribution
//! hands its wavelengths and their pdfs to [`HeroSample::from_wavelengths`],
//! or its uniform number and a [`WavelengthPdf`] to [`HeroSample::from_pdf`].
//!
//! A spectrum evaluated at a sample is a [`SampledSpectrum<K>`]. The sample's
//! XYZ contribution is `Σⱼ c̄(λⱼ)·vⱼ / (K·pdfⱼ)` (a wavelength of pdf 0, for
//! example one [terminated](HeroSample::terminate_secondary), contributes
//! nothing), and [`estimate`] averages n of them.
//!
//! ```
//! use rand::{SeedableRng, rngs::StdRng};
//! use speclab::{data::{lights, patches}, sampling::hero, HeroSample};
//! let h = HeroSample::<4>::new(0.0);
//! assert_eq!(h.lambda(), &[380.0, 467.5, 555.0, 642.5]);
//! let v = lights::D65.sample(&h) * patches::A1.sample(&h);
//! let one = h.to_xyz(v); // a one-sample estimate
//! assert!((h.y(v) - one.y).abs() < 1e-12 * one.y);
//! let n = std::num::NonZeroUsize::new(1000).unwrap();
//! let mean = hero::estimate::<4, _>(&lights::D65, &patches::A1, n, &mut StdRng::seed_from_u64(1));
//! assert!(one.y > 0.0 && (mean.y - 82.0).abs() < 5.0);
//! ```
//!
//! ```compile_fail
//! let nothing = speclab::HeroSample::<0>::new(0.5);
//! ```

use std::num::NonZeroUsize;

use rand::Rng;

use crate::color::Xyz;
use crate::error::Error;
use crate::sampling::pdf::{Uniform, WavelengthPdf};
use crate::sampling::strata::Strata;
use crate::spectrum::observer::{self, Cie1931, Observer};
use crate::spectrum::{LAMBDA_MIN, LAMBDA_WIDTH, SampledSpectrum, Spectrum, Wavelengths};

/// K wavelengths drawn together (a hero and K − 1 companions), each with
/// the probability density it was drawn with. The sample keeps each pdf's
/// reciprocal, `1/pdf` (nm; Mitsuba's "weight"), so that estimates multiply
/// rather than divide; 0 marks a wavelength that contributes nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeroSample<const K: usize> {
    lambda: [f64; K],
    inv_pdf: [f64; K],
}

impl<const K: usize> HeroSample<K> {
    /// Compile-time guard: a sample has at least one wavelength.
    const NONZERO: () = assert!(K > 0, "HeroSample needs at least one wavelength (K > 0)");

    /// The density of a uniform wavelength, 1/nm: `1/W` over 380–730 nm.
    pub const UNIFORM_PDF: f64 = 1.0 / LAMBDA_WIDTH;

    /// The uniform hero sample for `u`: `λⱼ = 380 + W·((u + j/K) mod 1)`,
    /// each of pdf `1/W`. Only the fractional part of `u` counts (1.25 acts
    /// as 0.25 and −0.25 as 0.75); a non-finite `u` acts as 0. Every
    /// wavelength lies in [380, 730) nm.
    #[inline]
    #[must_use]
    pub fn new(u: f64) -> Self {
        let () = Self::NONZERO;
        let u = fract(u);
        let lambda = std::array::from_fn(|j| {
            let v = u + j as f64 / K as f64;
            LAMBDA_MIN + LAMBDA_WIDTH * if v >= 1.0 { v - 1.0 } else { v }
        });
        HeroSample { lambda, inv_pdf: [LAMBDA_WIDTH; K] }
    }

    /// The sample of wavelengths `lambda` (nm) drawn with densities `pdf`
    /// (1/nm), from a renderer's own sampler and distribution. Each
    /// wavelength must be finite and each pdf finite and non-negative with a
    /// finite reciprocal; a pdf of 0 marks a wavelength that contributes
    /// nothing.
    pub fn from_wavelengths(lambda: [f64; K], pdf: [f64; K]) -> Result<Self, Error> {
        let () = Self::NONZERO;
        let mut inv_pdf = [0.0; K];
        for (index, ((&l, &p), w)) in lambda.iter().zip(&pdf).zip(&mut inv_pdf).enumerate() {
            // A pdf so small that its reciprocal overflows is as unusable as ∞.
            let reciprocal = if p > 0.0 { 1.0 / p } else { 0.0 };
            if !(l.is_finite() && p.is_finite() && p >= 0.0 && reciprocal.is_finite()) {
                return Err(Error::SampleWavelength { index, lambda: l, pdf: p });
            }
            *w = reciprocal;
        }
        Ok(HeroSample { lambda, inv_pdf })
    }

    /// The sample for `u` under the density `pdf`, rotated in primary-sample
    /// space: `λⱼ = P⁻¹((u + j/K) mod 1)`, so that every `λⱼ` has density p
    /// and the estimate `Σⱼ c̄·vⱼ / (K·p(λⱼ))` stays unbiased. With
    /// [`Uniform`] this is
    /// [`HeroSample::new`]. `u` is taken as in [`HeroSample::new`].
    #[inline]
    #[must_use]
    pub fn from_pdf<P: WavelengthPdf + ?Sized>(u: f64, pdf: &P) -> Self {
        let () = Self::NONZERO;
        let u = fract(u);
        let (mut lambda, mut inv_pdf) = ([0.0; K], [0.0; K]);
        for (j, (l, w)) in lambda.iter_mut().zip(&mut inv_pdf).enumerate() {
            let v = u + j as f64 / K as f64;
            (*l, *w) = pdf.sample_with_inv_pdf(if v >= 1.0 { v - 1.0 } else { v });
        }
        HeroSample { lambda, inv_pdf }
    }

    /// The wavelengths, nm; the hero first.
    #[inline]
    #[must_use]
    pub fn lambda(&self) -> &[f64; K] {
        &self.lambda
    }

    /// The density of each wavelength, 1/nm (0 for a dropped wavelength).
    #[inline]
    #[must_use]
    pub fn pdf(&self) -> [f64; K] {
        self.inv_pdf.map(|w| if w > 0.0 { 1.0 / w } else { 0.0 })
    }

    /// The reciprocal of each wavelength's density, nm (0 for a dropped
    /// wavelength): what an estimate multiplies by.
    #[inline]
    #[must_use]
    pub fn inv_pdf(&self) -> &[f64; K] {
        &self.inv_pdf
    }

    /// Keeps the hero alone (pbrt-v4's `TerminateSecondary`, for dispersion:
    /// a wavelength-dependent path must follow one wavelength). The other
    /// pdfs become 0, and the hero's is divided by K (its reciprocal
    /// multiplied), so that its single term `c̄·v₀ / (K·pdf₀/K)` is still an
    /// unbiased estimate. Doing it twice changes nothing.
    #[inline]
    pub fn terminate_secondary(&mut self) {
        if self.secondary_terminated() {
            return;
        }
        self.inv_pdf[1..].fill(0.0);
        self.inv_pdf[0] *= K as f64;
    }

    /// True if only the hero contributes (always true for `K = 1`).
    #[inline]
    #[must_use]
    pub fn secondary_terminated(&self) -> bool {
        self.inv_pdf[1..].iter().all(|&w| w == 0.0)
    }

    /// `s` at the sample's wavelengths (what `s.sample(&self)` gives).
    #[inline(always)]
    #[must_use]
    pub fn sample(&self, s: &impl Spectrum) -> SampledSpectrum<K> {
        s.sample(self)
    }

    /// The sample's XYZ estimate of a spectrum with values `v`:
    /// `Σⱼ c̄(λⱼ)·vⱼ / (K·pdfⱼ)`, with the exact observer. Each wavelength's
    /// term is formed on its own and the K terms are summed at the end, so
    /// the work has no chain through the sample.
    #[inline(always)]
    #[must_use]
    pub fn to_xyz(&self, v: SampledSpectrum<K>) -> Xyz {
        self.to_xyz_with(&Cie1931, v)
    }

    /// [`HeroSample::to_xyz`] with the matching functions of `observer`
    /// (the exact [`Cie1931`], or a dense table: `DenseObserver`).
    #[inline(always)]
    #[must_use]
    pub fn to_xyz_with(&self, observer: &impl Observer, v: SampledSpectrum<K>) -> Xyz {
        let cmf = observer.xyz_bar_lanes(&self.lambda);
        let terms: [[f64; 3]; K] =
            std::array::from_fn(|j| cmf[j].map(|c| c * (v.values[j] * self.inv_pdf[j])));
        Xyz::from(tree_sum(terms)) * (1.0 / K as f64)
    }

    /// The luminance alone, `Σⱼ ȳ(λⱼ)·vⱼ / (K·pdfⱼ)`: the Y of
    /// [`HeroSample::to_xyz`] (to rounding), from ȳ's table alone, for
    /// Russian roulette and other decisions. In the units of `v` times nm,
    /// like every Y here: divide by
    /// [`observer::Y_BAR_INTEGRAL`]
    /// for the luminance of a constant spectrum to come out as that constant.
    #[inline]
    #[must_use]
    pub fn y(&self, v: SampledSpectrum<K>) -> f64 {
        let y_bar = observer::y_bar_lanes(&self.lambda);
        let terms: [[f64; 1]; K] = std::array::from_fn(|j| [y_bar[j] * (v.values[j] * self.inv_pdf[j])]);
        tree_sum(terms)[0] * (1.0 / K as f64)
    }
}

impl<const K: usize> HeroSample<K> {
    /// The weights of [`HeroSample::y`], `ȳ(λⱼ)/(K·pdfⱼ)`: `v.dot(&w)` is
    /// `y(v)` to rounding, for any `v`. A path keeps its wavelengths, so a
    /// renderer computes these once per path and each bounce's luminance
    /// (for Russian roulette) is a dot product of K numbers.
    ///
    /// ```
    /// use speclab::{data::patches, HeroSample};
    /// let h = HeroSample::<4>::new(0.3);
    /// let (w, albedo) = (h.y_weights(), patches::F4.sample(&h));
    /// assert!((albedo.dot(&w) - h.y(albedo)).abs() <= 1e-12 * h.y(albedo));
    /// ```
    #[inline]
    #[must_use]
    pub fn y_weights(&self) -> SampledSpectrum<K> {
        let y_bar = observer::y_bar_lanes(&self.lambda);
        SampledSpectrum::new(std::array::from_fn(|j| y_bar[j] * self.inv_pdf[j] * (1.0 / K as f64)))
    }
}

/// `Σ terms` pairwise, `(t₀ + t₁) + (t₂ + t₃)`: the additions of
/// different wavelengths do not wait on each other (the same sum as
/// `HeroSample::y`'s, term for term, so `y` is `to_xyz`'s Y to the bit).
#[inline(always)]
fn tree_sum<const K: usize, const D: usize>(mut terms: [[f64; D]; K]) -> [f64; D] {
    let mut width = 1;
    while width < K {
        let mut i = 0;
        while i + width < K {
            terms[i] = std::array::from_fn(|c| terms[i][c] + terms[i + width][c]);
            i += 2 * width;
        }
        width *= 2;
    }
    if K == 0 { [0.0; D] } else { terms[0] }
}

/// `u − ⌊u⌋` in [0, 1), without libm (baseline x86-64 has no rounding
/// instruction): `u` itself in the usual case of `u ∈ [0, 1)`; otherwise 0
/// for NaN, ±∞ and magnitudes of 2⁵² and more (which are integers).
#[inline]
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

impl<const K: usize> Wavelengths<K> for HeroSample<K> {
    #[inline]
    fn lambda(&self) -> &[f64; K] {
        &self.lambda
    }
}

/// The mean of `n` one-sample estimates of `light × surface`, wavelengths
/// uniform and independent, drawn with `rng`; accumulates in f64. The same
/// seed gives the same result. `n` is non-zero by type: a mean of no
/// samples does not exist.
#[must_use]
pub fn estimate<const K: usize, R: Rng + ?Sized>(
    light: &impl Spectrum,
    surface: &impl Spectrum,
    n: NonZeroUsize,
    rng: &mut R,
) -> Xyz {
    estimate_with::<K, _, R>(light, surface, n, &Uniform, Strata::None, rng)
}

/// [`estimate`] with wavelengths drawn from `pdf` and the n primary numbers
/// spread by `strata`: unbiased for every pdf that is positive wherever
/// `light × surface` is, and every strata.
#[must_use]
pub fn estimate_with<const K: usize, P: WavelengthPdf + ?Sized, R: Rng + ?Sized>(
    light: &impl Spectrum,
    surface: &impl Spectrum,
    n: NonZeroUsize,
    pdf: &P,
    strata: Strata,
    rng: &mut R,
) -> Xyz {
    let sum: Xyz = strata
        .points(n.get(), K, rng)
        .map(|u| {
            let h = HeroSample::<K>::from_pdf(u, pdf);
            h.to_xyz(light.sample(&h) * surface.sample(&h))
        })
        .sum();
    sum / n.get() as f64
}

/// The usual hero width: four wavelengths per sample.
pub const USUAL_K: usize = 4;

/// The one list of hero widths compiled for a width known only at run
/// time: [`WIDTHS`], and [`estimate_dyn`]'s dispatch over them.
macro_rules! hero_widths {
    ($($k:literal)*) => {
        /// The hero widths K that [`estimate_dyn`] dispatches to compiled instances.
        pub const WIDTHS: &[usize] = &[$($k),*];

        /// [`estimate_with`] for a hero width `k` known only at run time:
        /// dispatches to `HeroSample<K>` for K in [`WIDTHS`], an error otherwise.
        pub fn estimate_dyn<P: WavelengthPdf + ?Sized, R: Rng + ?Sized>(
            k: usize,
            light: &impl Spectrum,
            surface: &impl Spectrum,
            n: NonZeroUsize,
            pdf: &P,
            strata: Strata,
            rng: &mut R,
        ) -> Result<Xyz, Error> {
            match k {
                $($k => Ok(estimate_with::<$k, P, R>(light, surface, n, pdf, strata, rng)),)*
                _ => Err(Error::HeroWidth { k, widths: WIDTHS }),
            }
        }
    };
}
hero_widths!(1 2 3 4 8 16);

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
