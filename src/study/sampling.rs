//! How the random methods choose wavelengths, chosen at run time: a pdf
//! (uniform, visible, light, balanced) and a way of spreading the primary
//! numbers (independent, jittered, Kronecker).
//!
//! ```
//! use speclab::study::sampling::{Pdf, Sampling};
//! use speclab::sampling::{pdf::WavelengthPdf, strata::Strata};
//! let s = Sampling { pdf: Pdf::Light, strata: Strata::Jittered };
//! assert_eq!(s.to_string(), "light/jitter");
//! let f11 = s.pdf.build(&speclab::data::F11)?;
//! assert!(f11.pdf(545.0) > f11.pdf(500.0)); // F11's line at 545 nm
//! # Ok::<(), speclab::Error>(())
//! ```

use std::fmt;

use crate::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
use crate::sampling::strata::Strata;
use crate::{Error, TabulatedSpectrum};

/// Which density wavelengths are drawn from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Pdf {
    /// [`Uniform`]: `1/W`.
    #[default]
    Uniform,
    /// [`Visible`]: pbrt-v4's visible-wavelength density.
    Visible,
    /// [`LightPdf::light`]: `∝ L·(x̄ + ȳ + z̄)`.
    Light,
    /// [`LightPdf::balanced`]: `∝ L·Σ c̄꜀/white꜀`.
    Balanced,
}

impl Pdf {
    /// All choices, in CLI order.
    pub const ALL: [Pdf; 4] = [Pdf::Uniform, Pdf::Visible, Pdf::Light, Pdf::Balanced];

    /// The name used on the command line and in CSV.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Pdf::Uniform => "uniform",
            Pdf::Visible => "visible",
            Pdf::Light => "light",
            Pdf::Balanced => "balanced",
        }
    }

    /// The choice with this name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Pdf> {
        Pdf::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The density for `light` (an error for a light the observer cannot
    /// see, with `Light` and `Balanced`).
    pub fn build(self, light: &TabulatedSpectrum) -> Result<AnyPdf, Error> {
        Ok(match self {
            Pdf::Uniform => AnyPdf::Uniform,
            Pdf::Visible => AnyPdf::Visible,
            Pdf::Light => AnyPdf::Light(LightPdf::light(light)?),
            Pdf::Balanced => AnyPdf::Light(LightPdf::balanced(light)?),
        })
    }
}

/// One of the library's densities, built for a light.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyPdf {
    /// [`Uniform`].
    Uniform,
    /// [`Visible`].
    Visible,
    /// A [`LightPdf`] (light or balanced).
    Light(LightPdf),
}

impl WavelengthPdf for AnyPdf {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        match self {
            AnyPdf::Uniform => Uniform.sample(u),
            AnyPdf::Visible => Visible.sample(u),
            AnyPdf::Light(p) => p.sample(u),
        }
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        match self {
            AnyPdf::Uniform => Uniform.pdf(lambda),
            AnyPdf::Visible => Visible.pdf(lambda),
            AnyPdf::Light(p) => p.pdf(lambda),
        }
    }

    #[inline]
    fn inv_pdf(&self, lambda: f64) -> f64 {
        match self {
            AnyPdf::Uniform => Uniform.inv_pdf(lambda),
            AnyPdf::Visible => Visible.inv_pdf(lambda),
            AnyPdf::Light(p) => p.inv_pdf(lambda),
        }
    }

    fn cdf(&self, lambda: f64) -> f64 {
        match self {
            AnyPdf::Uniform => Uniform.cdf(lambda),
            AnyPdf::Visible => Visible.cdf(lambda),
            AnyPdf::Light(p) => p.cdf(lambda),
        }
    }

    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        match self {
            AnyPdf::Uniform => Uniform.sample_with_inv_pdf(u),
            AnyPdf::Visible => Visible.sample_with_inv_pdf(u),
            AnyPdf::Light(p) => p.sample_with_inv_pdf(u),
        }
    }
}

/// A pdf and a strata: how a random method draws its wavelengths.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Sampling {
    /// The density.
    pub pdf: Pdf,
    /// How the primary numbers are spread.
    pub strata: Strata,
}

impl Sampling {
    /// Uniform and independent: the assignment's random sampling.
    pub const DEFAULT: Sampling = Sampling { pdf: Pdf::Uniform, strata: Strata::Independent };

    /// Every pdf × strata, uniform/independent first.
    #[must_use]
    pub fn all() -> Vec<Sampling> {
        Pdf::ALL.iter().flat_map(|&pdf| Strata::ALL.map(|strata| Sampling { pdf, strata })).collect()
    }
}

impl fmt::Display for Sampling {
    /// `pdf/strata`, e.g. `light/jitter`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.pdf.name(), self.strata.name())
    }
}
