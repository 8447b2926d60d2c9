//! Wavelength distributions: where random wavelengths are drawn, and with
//! what density.
//!
//! A [`WavelengthPdf`] maps a uniform number `u ∈ [0, 1)` to a wavelength
//! by inverting its CDF (`sample`) and gives the density at any wavelength
//! (`pdf`, 1/nm). All are exact and allocate nothing per sample. A
//! renderer's own distribution implements the trait.
//!
//! - [`Uniform`]: `1/W` over a range: the assignment's random sampling
//!   (`Uniform::ASSIGNMENT`, 380–730 nm), or a renderer's
//!   (`Uniform::VISIBLE`, 360–830 nm).
//! - [`Visible`]: pbrt-v4's `SampleVisibleWavelengths` (Radziszewski et al.
//!   2009), `p ∝ 1/cosh²(0.0072·(λ − 538))`, over pbrt-v4's 360–830 nm
//!   (`Visible::VISIBLE`) or renormalised to 380–730 nm (`ASSIGNMENT`).
//! - The tabulated ones below are over 380–730 nm with the assignment's
//!   observer, or over any range with a CIE 1 nm observer
//!   ([`LightPdf::weighted_over`], [`LightPdf::spectrum_over`]).
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
//! [`Domain::hero`](crate::sampling::Domain::hero) and
//! [`HeroSample::from_pdf_with`](crate::HeroSample::from_pdf_with) draw
//! `λⱼ = P⁻¹((u + j/K) mod 1)`, so each `λⱼ` has density p. Each density
//! says where it draws ([`WavelengthPdf::support`]): an observer whose
//! data do not cover that is refused, never a silent 0.
//!
//! ```
//! use speclab::{data::lights, HeroSample, spectrum::{DenseObserver, Mixture}};
//! use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
//! let f11 = LightPdf::light(&lights::F11)?;
//! let lambda = f11.sample(0.5);
//! assert!(f11.pdf(lambda) > 0.0);
//! assert!((f11.cdf(lambda).unwrap() - 0.5).abs() < 1e-12);
//! assert!(Visible::ASSIGNMENT.pdf(555.0) > Visible::ASSIGNMENT.pdf(400.0));
//! // A scene with two lights, the second at half strength:
//! let scene = LightPdf::light(&Mixture::new().with(1.0, &lights::F11)?.with(0.5, &lights::D65)?)?;
//! // Chosen at run time, without a double reference:
//! let pdfs: [&dyn WavelengthPdf; 3] = [&Uniform::ASSIGNMENT, &Visible::VISIBLE, &scene];
//! for pdf in pdfs {
//!     let h = HeroSample::<4>::from_pdf_with(0.3, pdf, &DenseObserver::CIE_1931)?;
//!     assert!(h.pdf().iter().all(|&p| p > 0.0));
//! }
//! // The assignment's observer stops at 780 nm: pbrt-v4's 360–830 nm is refused.
//! assert!(HeroSample::<4>::from_pdf_with(0.3, &Visible::VISIBLE, &DenseObserver::ASSIGNMENT).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
pub use crate::sampling::analytic_pdf::{Uniform, Visible};
pub use crate::sampling::density::WavelengthPdf;
use crate::sampling::density::reciprocal;
use crate::sampling::light_pdf::PiecewisePdf;
use crate::sampling::reference;
use crate::spectrum::{Spectrum, StandardObserver, WavelengthRange};

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

    /// [`LightPdf::weighted`] over `range` with `observer` (a renderer's
    /// 360–830 nm with the CIE 1931 observer, or any range within the
    /// observer's data): an [`Error::RangeOutside`] beyond the data,
    /// [`Error::NoMass`] as `weighted`'s.
    ///
    /// ```
    /// use speclab::data::lights;
    /// use speclab::sampling::pdf::{LightPdf, WavelengthPdf};
    /// use speclab::spectrum::{StandardObserver, WavelengthRange};
    /// let e = LightPdf::weighted_over(&lights::E, [1.0; 3], StandardObserver::Cie1931, WavelengthRange::VISIBLE)?;
    /// assert!(e.pdf(370.0) > 0.0 && e.pdf(800.0) > 0.0 && e.pdf(850.0) == 0.0);
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn weighted_over(
        spectrum: &impl Spectrum,
        alpha: [f64; 3],
        observer: StandardObserver,
        range: WavelengthRange,
    ) -> Result<Self, Error> {
        let range = observer.check(range)?;
        let alpha = alpha.map(|a| if a.is_finite() && a > 0.0 { a } else { 0.0 });
        PiecewisePdf::new_over(spectrum, Some(alpha), observer, range)
            .map(|table| LightPdf { table })
            .ok_or(Error::NoMass)
    }

    /// [`LightPdf::spectrum`] over `range`: `p ∝ S(λ)` there; an
    /// [`Error::NoMass`] if `S` has none over it.
    pub fn spectrum_over(spectrum: &impl Spectrum, range: WavelengthRange) -> Result<Self, Error> {
        PiecewisePdf::new_over(spectrum, None, StandardObserver::Assignment, range)
            .map(|table| LightPdf { table })
            .ok_or(Error::NoMass)
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

    fn support(&self) -> WavelengthRange {
        self.table.support()
    }

    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let (lambda, pdf) = self.table.sample_with_pdf(u);
        (lambda, reciprocal(pdf))
    }
}
