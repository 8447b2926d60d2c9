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
//!
//! Hero sampling with any of them rotates in primary-sample space:
//! [`HeroSample::from_pdf`](crate::HeroSample::from_pdf) draws
//! `λⱼ = P⁻¹((u + j/K) mod 1)`, so each `λⱼ` has density p.
//!
//! ```
//! use speclab::{data::lights, sampling::pdf::{LightPdf, Visible, WavelengthPdf}};
//! let f11 = LightPdf::light(&lights::F11)?;
//! let lambda = f11.sample(0.5);
//! assert!(f11.pdf(lambda) > 0.0);
//! assert!((f11.cdf(lambda) - 0.5).abs() < 1e-12);
//! assert!(Visible.pdf(555.0) > Visible.pdf(400.0));
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::sampling::light_pdf::PiecewisePdf;
use crate::sampling::reference;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, TabulatedSpectrum, observer};

/// A probability density over wavelengths that can be sampled by inverting
/// its cumulative distribution.
pub trait WavelengthPdf {
    /// The wavelength (nm) whose CDF is `u`, for `u` in `[0, 1)`; values
    /// outside are clamped into it.
    fn sample(&self, u: f64) -> f64;
    /// The density at `lambda`, 1/nm; zero outside the support.
    fn pdf(&self, lambda: f64) -> f64;

    /// The cumulative distribution at `lambda`: `∫ pdf` up to it, in
    /// `[0, 1]` (0 for NaN).
    fn cdf(&self, lambda: f64) -> f64;

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

    fn cdf(&self, lambda: f64) -> f64 {
        let c = (lambda - LAMBDA_MIN) / LAMBDA_WIDTH;
        if c > 0.0 { c.min(1.0) } else { 0.0 }
    }
}

/// pbrt-v4's visible-wavelength density, `∝ 1/cosh²(a·(λ − 538))` with
/// `a = 0.0072/nm`, renormalised to 380–730 nm. Its CDF is a difference of
/// `tanh`, inverted by `atanh`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Visible;

impl Visible {
    const A: f64 = 0.0072;
    const CENTRE: f64 = 538.0;

    /// `tanh(a·(λ − 538))` at the two ends of the range.
    fn ends() -> (f64, f64) {
        let at = |l: f64| (Self::A * (l - Self::CENTRE)).tanh();
        (at(LAMBDA_MIN), at(LAMBDA_MAX))
    }
}

impl WavelengthPdf for Visible {
    fn sample(&self, u: f64) -> f64 {
        let (t0, t1) = Self::ends();
        let lambda = Self::CENTRE + (t0 + unit(u) * (t1 - t0)).atanh() / Self::A;
        lambda.clamp(LAMBDA_MIN, LAMBDA_MAX)
    }

    fn pdf(&self, lambda: f64) -> f64 {
        if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) {
            return 0.0;
        }
        let (t0, t1) = Self::ends();
        let c = (Self::A * (lambda - Self::CENTRE)).cosh();
        Self::A / (c * c * (t1 - t0))
    }

    fn cdf(&self, lambda: f64) -> f64 {
        if lambda.is_nan() {
            return 0.0;
        }
        let (t0, t1) = Self::ends();
        let l = lambda.clamp(LAMBDA_MIN, LAMBDA_MAX);
        ((Self::A * (l - Self::CENTRE)).tanh() - t0) / (t1 - t0)
    }
}

/// A density that follows a light: `∝ L(λ)·Σ꜀ α꜀·c̄꜀(λ)`, tabulated exactly
/// (see `light_pdf.rs`) when the pdf is made, for any light.
#[derive(Clone, Debug, PartialEq)]
pub struct LightPdf {
    table: PiecewisePdf,
}

impl LightPdf {
    /// `p ∝ L(λ)·(x̄ + ȳ + z̄)(λ)`. An error if the light has no power where
    /// the observer sees, within 380–730 nm.
    pub fn light(light: &TabulatedSpectrum) -> Result<Self, Error> {
        Self::new(light, [1.0; 3])
    }

    /// `p ∝ L(λ)·Σ꜀ c̄꜀(λ)/white꜀`, with white꜀ the light's perfect white
    /// (a channel whose white is zero gets no weight: its estimate is zero
    /// anyway). The same error as [`LightPdf::light`].
    pub fn balanced(light: &TabulatedSpectrum) -> Result<Self, Error> {
        let alpha = reference::white(light).to_array().map(|w| if w > 0.0 { 1.0 / w } else { 0.0 });
        Self::new(light, alpha)
    }

    /// `p ∝ L·Σ alpha꜀·c̄꜀`, or [`Error::DarkLight`] if that has no mass.
    fn new(light: &TabulatedSpectrum, alpha: [f64; 3]) -> Result<Self, Error> {
        let table = PiecewisePdf::new(&light.view(), &observer::views(), alpha);
        table.map(|table| LightPdf { table }).ok_or(Error::DarkLight)
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

    fn cdf(&self, lambda: f64) -> f64 {
        self.table.cdf(lambda)
    }

    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let (lambda, pdf) = self.table.sample_with_pdf(u);
        (lambda, reciprocal(pdf))
    }
}
