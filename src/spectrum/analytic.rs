//! Spectra given by a formula: [`Constant`], [`Blackbody`] (Planck's law),
//! and [`FnSpectrum`], a renderer's own function of the wavelength.
//!
//! A constant is a polynomial (exact integrals); a blackbody and a closure
//! are integrated by quadrature (see [`super::Spectrum`]).
//!
//! ```
//! use speclab::Spectrum;
//! use speclab::spectrum::{Blackbody, Constant, FnSpectrum};
//! let tungsten = Blackbody::new(2856.0)?; // about illuminant A
//! assert!((tungsten.eval(1014.6) - 1.0).abs() < 1e-6); // normalised to its peak (Wien)
//! assert!(tungsten.eval(700.0) > tungsten.eval(400.0));
//! assert_eq!(Constant::new(0.5).eval(555.0), 0.5);
//! let ramp = FnSpectrum(|lambda: f64| lambda / 1000.0);
//! assert_eq!(ramp.eval(500.0), 0.5);
//! assert!(Blackbody::new(-1.0).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;

use crate::error::Error;
use crate::spectrum::WavelengthRange;
use crate::spectrum::interface::{Pieces, Spectrum};

/// The same value at every wavelength.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constant {
    value: f64,
}

impl Constant {
    /// `value` everywhere (NaN or infinite values are kept as given).
    #[must_use]
    pub const fn new(value: f64) -> Self {
        Constant { value }
    }

    /// The value.
    #[must_use]
    pub const fn value(&self) -> f64 {
        self.value
    }
}

impl Spectrum for Constant {
    #[inline]
    fn eval(&self, _lambda: f64) -> f64 {
        self.value
    }

    #[inline]
    fn eval_many(&self, _lambda: &[f64], values: &mut [f64]) {
        values.fill(self.value);
    }

    /// One polynomial of degree 0 everywhere.
    fn pieces(&self) -> Option<Pieces<'_>> {
        Some(Pieces { breaks: Cow::Borrowed(&[]), degree: 0 })
    }

    /// Exact: the value.
    fn max_value(&self) -> f64 {
        self.value
    }
}

/// A blackbody's spectral radiance by Planck's law, at a temperature in
/// kelvin: normalised so that its peak (at Wien's `λ = b/T`) is 1, as
/// pbrt-v4's `BlackbodySpectrum` ([`Blackbody::new`]), or in absolute units,
/// W·sr⁻¹·m⁻²·nm⁻¹ ([`Blackbody::absolute`], [`planck`]). Zero at
/// wavelengths that are not positive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blackbody {
    kelvin: f64,
    /// `1 / B(λ_peak, T)`, or 1e-9 (per m → per nm) in absolute units.
    normalization: f64,
}

/// Planck's constant, J·s (CODATA 2018, exact).
const PLANCK: f64 = 6.626_070_15e-34;
/// The speed of light, m/s (exact).
const LIGHT: f64 = 299_792_458.0;
/// Boltzmann's constant, J/K (CODATA 2018, exact).
const BOLTZMANN: f64 = 1.380_649e-23;
/// Wien's displacement constant, m·K (CODATA 2018).
const WIEN: f64 = 2.897_771_955e-3;

/// Planck's radiation constants, chosen by name: [`planck`] and
/// [`Blackbody`] use CODATA 2018's, the CIE's daylight and Planckian loci
/// its own c₂ (`lights::daylight_with`, `colorimetry::planckian_xy` take
/// either, so that a blackbody and a daylight agree by choice).
///
/// ```
/// use speclab::spectrum::PlanckConstants;
/// let (codata, cie) = (PlanckConstants::CODATA_2018, PlanckConstants::CIE);
/// assert!((codata.c2 - 1.438_776_877e-2).abs() < 1e-11);
/// assert_eq!(cie.c2, 1.4388e-2);
/// // colour-science: planck_law(500e-9, 5500) = 20472701909806.5 W·sr⁻¹·m⁻³.
/// assert!((cie.radiance(500.0, 5500.0) * 1e9 / 20_472_701_909_806.5 - 1.0).abs() < 1e-13);
/// assert_eq!(codata.radiance(600.0, 6000.0), speclab::spectrum::planck(600.0, 6000.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanckConstants {
    /// The first radiation constant for spectral radiance, c₁L = 2hc², W·m²·sr⁻¹.
    pub c1: f64,
    /// The second radiation constant c₂ = hc/k, m·K.
    pub c2: f64,
}

impl PlanckConstants {
    /// CODATA 2018 (exact h, c and k): c₂ = 1.438 776 877…e-2 m·K.
    pub const CODATA_2018: PlanckConstants =
        PlanckConstants { c1: 2.0 * PLANCK * LIGHT * LIGHT, c2: PLANCK * LIGHT / BOLTZMANN };
    /// The CIE's c₂ = 1.4388e-2 m·K (CIE 015:2018: the temperature scale
    /// of its loci and of D65's 6504 K), with c₁ = 3.741771e-16 W·m² / π
    /// (2πhc² to seven digits, as colour-science's `planck_law` takes it).
    pub const CIE: PlanckConstants =
        PlanckConstants { c1: 3.741_771e-16 / std::f64::consts::PI, c2: 1.4388e-2 };

    /// Planck's law with these constants: spectral radiance at `lambda` nm
    /// and `kelvin`, W·sr⁻¹·m⁻²·nm⁻¹; 0 at wavelengths that are not positive.
    #[must_use]
    pub fn radiance(self, lambda: f64, kelvin: f64) -> f64 {
        self.per_m(lambda, kelvin) * 1e-9
    }

    /// Per metre of wavelength, W·sr⁻¹·m⁻³.
    fn per_m(self, lambda: f64, kelvin: f64) -> f64 {
        if lambda <= 0.0 {
            return 0.0;
        }
        let l = lambda * 1e-9;
        self.c1 / (l * l * l * l * l * (self.c2 / (l * kelvin)).exp_m1())
    }
}

/// Planck's law: a blackbody's spectral radiance at `lambda` nm and
/// `kelvin`, in W·sr⁻¹·m⁻²·nm⁻¹ (CODATA 2018's exact h, c and k:
/// [`PlanckConstants::CODATA_2018`]); 0 at wavelengths that are not
/// positive.
///
/// ```
/// // At 6000 K and 600 nm: 2.867639e13 W·sr⁻¹·m⁻³, 2.867639e4 per nm.
/// let b = speclab::spectrum::planck(600.0, 6000.0);
/// assert!((b - 2.867639e4).abs() < 1e-6 * b);
/// ```
#[must_use]
pub fn planck(lambda: f64, kelvin: f64) -> f64 {
    PlanckConstants::CODATA_2018.radiance(lambda, kelvin)
}

/// Planck's law per metre of wavelength, W·sr⁻¹·m⁻³.
fn planck_per_m(lambda: f64, kelvin: f64) -> f64 {
    PlanckConstants::CODATA_2018.per_m(lambda, kelvin)
}

impl Blackbody {
    /// The blackbody at `kelvin`, normalised to a peak of 1; an error
    /// unless the temperature is finite and positive.
    pub fn new(kelvin: f64) -> Result<Self, Error> {
        let normalization = 1.0 / planck_per_m(WIEN / kelvin * 1e9, kelvin);
        if !(kelvin.is_finite() && kelvin > 0.0 && normalization.is_finite() && normalization > 0.0) {
            return Err(Error::Temperature { kelvin });
        }
        Ok(Blackbody { kelvin, normalization })
    }

    /// The blackbody at `kelvin` in absolute units: its spectral radiance,
    /// W·sr⁻¹·m⁻²·nm⁻¹ ([`planck`]); an error unless the temperature is
    /// finite and positive.
    pub fn absolute(kelvin: f64) -> Result<Self, Error> {
        Self::new(kelvin).map(|b| Blackbody { normalization: 1e-9, ..b })
    }

    /// The wavelength of its peak, nm (Wien's law, `b/T`).
    #[must_use]
    pub fn peak(&self) -> f64 {
        WIEN / self.kelvin * 1e9
    }

    /// The temperature, K.
    #[must_use]
    pub fn kelvin(&self) -> f64 {
        self.kelvin
    }
}

impl Spectrum for Blackbody {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        planck_per_m(lambda, self.kelvin) * self.normalization
    }

    /// Exact: Planck's law rises to its peak and falls after, so over
    /// 360–830 nm it is largest at the peak or the end nearest it.
    fn max_value(&self) -> f64 {
        self.eval(self.peak().clamp(WavelengthRange::VISIBLE.min(), WavelengthRange::VISIBLE.max()))
    }
}

/// A renderer's own spectrum: a function of the wavelength in nm. Integrated
/// by quadrature, so a function with kinks or jumps inside the observer's
/// 5 nm pieces integrates less accurately than a smooth one.
#[derive(Clone, Copy, Debug)]
pub struct FnSpectrum<F>(pub F);

impl<F: Fn(f64) -> f64> Spectrum for FnSpectrum<F> {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        (self.0)(lambda)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Planck's law against a published value: at 5000 K and 500 nm the
    /// spectral radiance is 1.2107e13 W/(sr·m³) (CIE 15's constants give
    /// the same to 4 digits); the peak is where Wien puts it.
    #[test]
    fn planck_and_its_peak() {
        let b = planck_per_m(500.0, 5000.0);
        assert!((b / 1.2107e13 - 1.0).abs() < 1e-3, "{b:e}");
        let sun = Blackbody::new(5000.0).unwrap();
        let peak = WIEN / 5000.0 * 1e9;
        assert!((sun.eval(peak) - 1.0).abs() < 1e-12);
        assert!(sun.eval(peak - 1.0) < 1.0 && sun.eval(peak + 1.0) < 1.0);
        assert_eq!(sun.eval(0.0), 0.0);
        assert_eq!(sun.eval(-5.0), 0.0);
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e-300] {
            assert!(matches!(Blackbody::new(bad), Err(Error::Temperature { .. })), "{bad}");
        }
        assert_eq!(Blackbody::new(6500.0).unwrap().kelvin(), 6500.0);
    }
}
