//! Wavelength distributions: where random wavelengths are drawn, and with
//! what density.
//!
//! A [`WavelengthPdf`] maps a uniform number `u ∈ [0, 1)` to a wavelength
//! by inverting its CDF (`sample`) and gives the density at any wavelength
//! (`pdf`, 1/nm). All are exact, over 380–730 nm, and allocate nothing per
//! sample. A renderer's own distribution implements the trait.
//!
//! - [`Uniform`]: `1/W`, the assignment's random sampling.
//! - [`Visible`]: pbrt-v4's `SampleVisibleWavelengths` (Radziszewski et al.
//!   2009), `p ∝ 1/cosh²(0.0072·(λ − 538))`, renormalised to 380–730 nm.
//! - [`LightPdf::light`]: `p ∝ L(λ)·(x̄ + ȳ + z̄)(λ)`, following a spiky
//!   light's lines.
//! - [`LightPdf::balanced`]: `p ∝ L(λ)·Σ꜀ c̄꜀(λ)/white꜀`, giving each
//!   channel its share relative to the light's white.
//! - [`LightPdf::weighted`]: any spectrum, any observer weights: a scene's
//!   lights summed ([`Mixture`](crate::spectrum::Mixture)), a light times a
//!   material, a table of the renderer's.
//!
//! Every density here takes any `u` (clamped into `[0, 1)`) and any
//! wavelength, and is object-safe: `&dyn WavelengthPdf` goes where a pdf
//! does, with no double reference.
//!
//! Hero sampling with any of them rotates in primary-sample space:
//! [`HeroSample::from_pdf`](crate::HeroSample::from_pdf) draws
//! `λⱼ = P⁻¹((u + j/K) mod 1)`, so each `λⱼ` has density p.
//!
//! ```
//! use speclab::{data::lights, HeroSample, spectrum::Mixture};
//! use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
//! let f11 = LightPdf::light(&lights::F11)?;
//! let lambda = f11.sample(0.5);
//! assert!(f11.pdf(lambda) > 0.0);
//! assert!((f11.cdf(lambda).unwrap() - 0.5).abs() < 1e-12);
//! assert!(Visible.pdf(555.0) > Visible.pdf(400.0));
//! // A scene with two lights, the second at half strength:
//! let scene = LightPdf::light(&Mixture::new().with(1.0, &lights::F11)?.with(0.5, &lights::D65)?)?;
//! // Chosen at run time, without a double reference:
//! let pdfs: [&dyn WavelengthPdf; 3] = [&Uniform, &Visible, &scene];
//! for pdf in pdfs {
//!     let h = HeroSample::<4>::from_pdf(0.3, pdf);
//!     assert!(h.pdf().iter().all(|&p| p > 0.0));
//! }
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::sampling::light_pdf::PiecewisePdf;
use crate::sampling::reference;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, Spectrum};

/// A probability density over wavelengths that can be sampled by inverting
/// its cumulative distribution.
pub trait WavelengthPdf {
    /// The wavelength (nm) whose CDF is `u`, for `u` in `[0, 1)`; values
    /// outside are clamped into it.
    fn sample(&self, u: f64) -> f64;
    /// The density at `lambda`, 1/nm; zero outside the support.
    fn pdf(&self, lambda: f64) -> f64;

    /// The cumulative distribution at `lambda`, `∫ pdf` up to it, in
    /// `[0, 1]` (0 for NaN), if the distribution knows it: renderers never
    /// ask; exact variances (`study::variance`) do. `None` by default.
    fn cdf(&self, _lambda: f64) -> Option<f64> {
        None
    }

    /// `1/pdf(λ)`, nm, what an estimate multiplies by; 0 where the density
    /// is 0 (or so small that its reciprocal overflows).
    fn inv_pdf(&self, lambda: f64) -> f64 {
        reciprocal(self.pdf(lambda))
    }

    /// `sample(u)` and its `inv_pdf`, together (a tabulated pdf finds the
    /// density where it found the wavelength).
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let lambda = self.sample(u);
        (lambda, self.inv_pdf(lambda))
    }
}

/// A reference or a box to a density is the density (a renderer holds
/// mixed densities as `&dyn WavelengthPdf` or `Box<dyn WavelengthPdf>`).
macro_rules! forward_pdf {
    ($($pointer:ty),*) => {$(
        impl<P: WavelengthPdf + ?Sized> WavelengthPdf for $pointer {
            #[inline]
            fn sample(&self, u: f64) -> f64 {
                (**self).sample(u)
            }
            #[inline]
            fn pdf(&self, lambda: f64) -> f64 {
                (**self).pdf(lambda)
            }
            fn cdf(&self, lambda: f64) -> Option<f64> {
                (**self).cdf(lambda)
            }
            #[inline]
            fn inv_pdf(&self, lambda: f64) -> f64 {
                (**self).inv_pdf(lambda)
            }
            #[inline]
            fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
                (**self).sample_with_inv_pdf(u)
            }
        }
    )*};
}

forward_pdf!(&P, Box<P>);

/// `1/p`, or 0 where `p` is 0 or its reciprocal overflows.
#[inline]
fn reciprocal(p: f64) -> f64 {
    let w = 1.0 / p;
    if p > 0.0 && w.is_finite() { w } else { 0.0 }
}

/// Clamps `u` into `[0, 1)`; NaN becomes 0.
fn unit(u: f64) -> f64 {
    if u > 0.0 { u.min(1.0 - f64::EPSILON / 2.0) } else { 0.0 }
}

/// The uniform density `1/W` over 380–730 nm.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Uniform;

impl WavelengthPdf for Uniform {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        LAMBDA_MIN + LAMBDA_WIDTH * unit(u)
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        if (LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) { 1.0 / LAMBDA_WIDTH } else { 0.0 }
    }

    /// Exactly `W` inside the range.
    #[inline]
    fn inv_pdf(&self, lambda: f64) -> f64 {
        if (LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) { LAMBDA_WIDTH } else { 0.0 }
    }

    fn cdf(&self, lambda: f64) -> Option<f64> {
        let c = (lambda - LAMBDA_MIN) / LAMBDA_WIDTH;
        Some(if c > 0.0 { c.min(1.0) } else { 0.0 })
    }
}

/// pbrt-v4's visible-wavelength density, `∝ 1/cosh²(a·(λ − 538))` with
/// `a = 0.0072/nm`, renormalised to 380–730 nm. Its CDF is a difference of
/// `tanh`, inverted by one `atanh` per wavelength; its constants are
/// computed once (here, as literals; a test checks them against `tanh`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Visible;

impl Visible {
    const A: f64 = 0.0072;
    const CENTER: f64 = 538.0;
    /// `tanh(a·(380 − 538))`.
    pub(crate) const T0: f64 = -0.813_604_361_381_150_8;
    /// `tanh(a·(730 − 538))`.
    pub(crate) const T1: f64 = 0.881_487_552_831_487_7;
    /// `a / (T1 − T0)`: the density is this times `1 − tanh²`.
    const NORM: f64 = Self::A / (Self::T1 - Self::T0);

    /// `tanh(a·(λ − 538))`, the CDF's numerator, for λ in the range.
    #[inline]
    fn tanh_at(lambda: f64) -> f64 {
        (Self::A * (lambda - Self::CENTER)).tanh()
    }
}

impl WavelengthPdf for Visible {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        self.sample_with_inv_pdf(u).0
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) {
            return 0.0;
        }
        let y = Self::tanh_at(lambda);
        Self::NORM * (1.0 - y * y)
    }

    fn cdf(&self, lambda: f64) -> Option<f64> {
        if lambda.is_nan() {
            return Some(0.0);
        }
        let l = lambda.clamp(LAMBDA_MIN, LAMBDA_MAX);
        Some((Self::tanh_at(l) - Self::T0) / (Self::T1 - Self::T0))
    }

    /// One `atanh`: at `y = tanh(a·(λ − 538))`, `1/cosh² = 1 − y²`, so the
    /// density needs no `cosh`.
    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let y = Self::T0 + unit(u) * (Self::T1 - Self::T0);
        let lambda = (Self::CENTER + y.atanh() / Self::A).clamp(LAMBDA_MIN, LAMBDA_MAX);
        (lambda, reciprocal(Self::NORM * (1.0 - y * y)))
    }
}

/// A density that follows a light, or any spectrum: `∝ L(λ)·Σ꜀ α꜀·c̄꜀(λ)`,
/// tabulated exactly (see `light_pdf.rs`) when the pdf is made (about 7 µs
/// for a built-in light): the general piecewise pdf for a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct LightPdf {
    table: PiecewisePdf,
}

impl LightPdf {
    /// `p ∝ L(λ)·(x̄ + ȳ + z̄)(λ)`, for any light (a sum of lights:
    /// [`Mixture`](crate::spectrum::Mixture)). An error if the light has no
    /// power where the observer sees, within 380–730 nm.
    pub fn light(light: &impl Spectrum) -> Result<Self, Error> {
        Self::weighted(light, [1.0; 3])
    }

    /// `p ∝ L(λ)·Σ꜀ c̄꜀(λ)/white꜀`, with white꜀ the light's perfect white
    /// (a channel whose white is zero gets no weight: its estimate is zero
    /// anyway). The same error as [`LightPdf::light`].
    pub fn balanced(light: &impl Spectrum) -> Result<Self, Error> {
        let alpha = reference::white(light).to_array().map(|w| if w > 0.0 { 1.0 / w } else { 0.0 });
        Self::weighted(light, alpha)
    }

    /// `p ∝ S(λ)·Σ꜀ alpha꜀·c̄꜀(λ)` for any spectrum `S` and observer weights
    /// `alpha` (each finite and non-negative; others count as 0): exact
    /// where `S` is piecewise polynomial (see `light_pdf.rs`). An
    /// [`Error::NoMass`] if that has no mass over 380–730 nm.
    pub fn weighted(spectrum: &impl Spectrum, alpha: [f64; 3]) -> Result<Self, Error> {
        let alpha = alpha.map(|a| if a.is_finite() && a > 0.0 { a } else { 0.0 });
        PiecewisePdf::new(spectrum, Some(alpha)).map(|table| LightPdf { table }).ok_or(Error::NoMass)
    }

    /// `p ∝ S(λ)` over 380–730 nm: a density proportional to a spectrum
    /// alone, without the observer (Mitsuba 3's `sample_spectrum` and
    /// `pdf_spectrum`): for an emitter's own spectrum, or any weight a
    /// renderer wants its wavelengths to follow. Exact where `S` is
    /// piecewise polynomial; [`BinnedPdf`](super::binned::BinnedPdf) of it
    /// samples without a search. An [`Error::NoMass`] if `S` has no mass
    /// over 380–730 nm (negative values count as none).
    ///
    /// ```
    /// use speclab::data::lights;
    /// use speclab::sampling::pdf::{LightPdf, WavelengthPdf};
    /// let f11 = LightPdf::spectrum(&lights::F11)?;
    /// let ratio = f11.pdf(545.0) / f11.pdf(500.0);
    /// assert!((ratio - lights::F11.eval(545.0) / lights::F11.eval(500.0)).abs() < 1e-9 * ratio);
    /// assert!(LightPdf::spectrum(&speclab::spectrum::Constant::new(0.0)).is_err());
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn spectrum(spectrum: &impl Spectrum) -> Result<Self, Error> {
        PiecewisePdf::new(spectrum, None).map(|table| LightPdf { table }).ok_or(Error::NoMass)
    }
}

impl WavelengthPdf for LightPdf {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        self.table.sample(u)
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        self.table.pdf(lambda)
    }

    fn cdf(&self, lambda: f64) -> Option<f64> {
        Some(self.table.cdf(lambda))
    }

    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let (lambda, pdf) = self.table.sample_with_pdf(u);
        (lambda, reciprocal(pdf))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The literal constants are what they say they are.
    #[test]
    fn visible_constants_are_tanh_of_the_range_ends() {
        let t0 = (Visible::A * (LAMBDA_MIN - Visible::CENTER)).tanh();
        let t1 = (Visible::A * (LAMBDA_MAX - Visible::CENTER)).tanh();
        assert!((Visible::T0 - t0).abs() <= 2.0 * f64::EPSILON, "{} against {t0}", Visible::T0);
        assert!((Visible::T1 - t1).abs() <= 2.0 * f64::EPSILON, "{} against {t1}", Visible::T1);
        // The density integrates to 1 over the range (midpoint rule, 0.01 nm).
        let n = 35_000;
        let total: f64 =
            (0..n).map(|i| Visible.pdf(LAMBDA_MIN + (i as f64 + 0.5) * LAMBDA_WIDTH / n as f64)).sum::<f64>();
        assert!((total * LAMBDA_WIDTH / n as f64 - 1.0).abs() < 1e-9);
    }
}
