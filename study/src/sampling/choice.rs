//! Wavelength densities chosen by name at run time: the one named choice
//! of a pdf ([`PdfKind`]: uniform, visible, light, balanced), the density
//! it makes for a light ([`ChosenPdf`]), and a pdf with a way of spreading
//! the primary numbers ([`Sampling`]). The study and the path tracer both
//! take their densities from here.
//!
//! ```
//! use speclab::data::lights;
//! use speclab_study::sampling::choice::{PdfKind, Sampling};
//! use speclab::sampling::{pdf::WavelengthPdf, HeroSample};
//! use speclab_study::sampling::strata::Strata;
//! let s = Sampling { pdf: PdfKind::Light, strata: Strata::Jittered };
//! assert_eq!(s.to_string(), "light/jitter");
//! assert_eq!("balanced".parse::<PdfKind>()?, PdfKind::Balanced);
//! let f11 = s.pdf.for_light(&lights::F11)?;
//! assert!(f11.pdf(545.0) > f11.pdf(500.0)); // F11's line at 545 nm
//! let h = HeroSample::<4>::from_pdf_with(0.3, &f11, &speclab::spectrum::DenseObserver::ASSIGNMENT).unwrap();
//! assert!(h.pdf().iter().all(|&p| p > 0.0));
//! # Ok::<(), speclab::Error>(())
//! ```

use std::fmt;
use std::sync::Arc;

use crate::sampling::strata::Strata;
use speclab::Error;
use speclab::Spectrum;
use speclab::named_choices;
use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};

/// Which density wavelengths are drawn from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PdfKind {
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

named_choices!(PdfKind, "a pdf": Uniform => "uniform", Visible => "visible", Light => "light", Balanced => "balanced");

impl PdfKind {
    /// True for the densities that follow a light (tabulated for it).
    #[must_use]
    pub fn follows_light(self) -> bool {
        matches!(self, PdfKind::Light | PdfKind::Balanced)
    }

    /// This density for `light`: the two that follow it are tabulated now
    /// (about 7 µs; keep the result, a cheap clone, as long as the light);
    /// an [`Error::NoMass`] for a light the observer cannot see.
    pub fn for_light(self, light: &(impl Spectrum + ?Sized)) -> Result<ChosenPdf, Error> {
        Ok(match self {
            PdfKind::Uniform => ChosenPdf::Uniform,
            PdfKind::Visible => ChosenPdf::Visible,
            PdfKind::Light => ChosenPdf::Table(Arc::new(LightPdf::light(&light)?)),
            PdfKind::Balanced => ChosenPdf::Table(Arc::new(LightPdf::balanced(&light)?)),
        })
    }
}

/// A density made by a [`PdfKind`]: the one place a choice of density is
/// dispatched (a `match` per draw, no allocation, no virtual call).
#[derive(Clone, Debug, PartialEq)]
pub enum ChosenPdf {
    /// [`Uniform`].
    Uniform,
    /// [`Visible`].
    Visible,
    /// A density tabulated for a light ([`LightPdf`]), shared by its
    /// clones.
    Table(Arc<LightPdf>),
}

impl WavelengthPdf for ChosenPdf {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        self.sample_with_inv_pdf(u).0
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        match self {
            ChosenPdf::Uniform => Uniform::ASSIGNMENT.pdf(lambda),
            ChosenPdf::Visible => Visible::ASSIGNMENT.pdf(lambda),
            ChosenPdf::Table(t) => t.pdf(lambda),
        }
    }

    fn support(&self) -> speclab::spectrum::WavelengthRange {
        match self {
            ChosenPdf::Uniform | ChosenPdf::Visible => speclab::spectrum::WavelengthRange::ASSIGNMENT,
            ChosenPdf::Table(t) => t.support(),
        }
    }

    fn cdf(&self, lambda: f64) -> Option<f64> {
        match self {
            ChosenPdf::Uniform => Uniform::ASSIGNMENT.cdf(lambda),
            ChosenPdf::Visible => Visible::ASSIGNMENT.cdf(lambda),
            ChosenPdf::Table(t) => t.cdf(lambda),
        }
    }

    #[inline]
    fn inv_pdf(&self, lambda: f64) -> f64 {
        match self {
            ChosenPdf::Uniform => Uniform::ASSIGNMENT.inv_pdf(lambda),
            ChosenPdf::Visible => Visible::ASSIGNMENT.inv_pdf(lambda),
            ChosenPdf::Table(t) => t.inv_pdf(lambda),
        }
    }

    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        match self {
            ChosenPdf::Uniform => Uniform::ASSIGNMENT.sample_with_inv_pdf(u),
            ChosenPdf::Visible => Visible::ASSIGNMENT.sample_with_inv_pdf(u),
            ChosenPdf::Table(t) => t.sample_with_inv_pdf(u),
        }
    }
}

/// A pdf and a strata: how a random method draws its wavelengths.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Sampling {
    /// The density.
    pub pdf: PdfKind,
    /// How the primary numbers are spread.
    pub strata: Strata,
}

impl Sampling {
    /// Uniform and independent: the assignment's random sampling.
    pub const DEFAULT: Sampling = Sampling { pdf: PdfKind::Uniform, strata: Strata::None };

    /// Every pdf × strata, uniform/none first.
    #[must_use]
    pub fn all() -> Vec<Sampling> {
        PdfKind::ALL.iter().flat_map(|&pdf| Strata::ALL.map(|strata| Sampling { pdf, strata })).collect()
    }
}

impl fmt::Display for Sampling {
    /// `pdf/strata`, e.g. `light/jitter`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.pdf, self.strata)
    }
}
