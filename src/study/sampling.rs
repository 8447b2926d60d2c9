//! How the random methods choose wavelengths, chosen at run time: a pdf
//! (uniform, visible, light, balanced) and a way of spreading the primary
//! numbers (none, jittered, Kronecker).
//!
//! [`Pdf`] names a density of `sampling::pdf`; the two that follow a light
//! are tabulated for it by [`Pdf::table`]. The study estimates with the
//! density's own type (no dynamic dispatch per wavelength), so its costs are
//! a renderer's.
//!
//! ```
//! use speclab::study::sampling::{Pdf, Sampling};
//! use speclab::sampling::{pdf::WavelengthPdf, strata::Strata};
//! let s = Sampling { pdf: Pdf::Light, strata: Strata::Jittered };
//! assert_eq!(s.to_string(), "light/jitter");
//! assert_eq!("balanced".parse::<Pdf>()?, Pdf::Balanced);
//! let f11 = s.pdf.table(&speclab::data::lights::F11)?.expect("a light-following pdf");
//! assert!(f11.pdf(545.0) > f11.pdf(500.0)); // F11's line at 545 nm
//! # Ok::<(), speclab::Error>(())
//! ```

use std::fmt;

use crate::error::{Error, named_choices};
use crate::sampling::pdf::LightPdf;
use crate::sampling::strata::Strata;
use crate::spectrum::TabulatedSpectrum;

/// Which density wavelengths are drawn from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Pdf {
    /// [`Uniform`](crate::sampling::pdf::Uniform): `1/W`.
    #[default]
    Uniform,
    /// [`Visible`](crate::sampling::pdf::Visible): pbrt-v4's visible-wavelength density.
    Visible,
    /// [`LightPdf::light`]: `∝ L·(x̄ + ȳ + z̄)`.
    Light,
    /// [`LightPdf::balanced`]: `∝ L·Σ c̄꜀/white꜀`.
    Balanced,
}

named_choices!(Pdf, "a pdf": Uniform => "uniform", Visible => "visible", Light => "light", Balanced => "balanced");

impl Pdf {
    /// All choices, in CLI order.
    pub const ALL: [Pdf; 4] = [Pdf::Uniform, Pdf::Visible, Pdf::Light, Pdf::Balanced];

    /// The table of a density that follows `light` (`Light`, `Balanced`;
    /// an error for a light the observer cannot see); `None` for the
    /// others, which need no table.
    pub fn table(self, light: &TabulatedSpectrum) -> Result<Option<LightPdf>, Error> {
        match self {
            Pdf::Uniform | Pdf::Visible => Ok(None),
            Pdf::Light => LightPdf::light(light).map(Some),
            Pdf::Balanced => LightPdf::balanced(light).map(Some),
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
    pub const DEFAULT: Sampling = Sampling { pdf: Pdf::Uniform, strata: Strata::None };

    /// Every pdf × strata, uniform/none first.
    #[must_use]
    pub fn all() -> Vec<Sampling> {
        Pdf::ALL.iter().flat_map(|&pdf| Strata::ALL.map(|strata| Sampling { pdf, strata })).collect()
    }
}

impl fmt::Display for Sampling {
    /// `pdf/strata`, e.g. `light/jitter`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.pdf, self.strata)
    }
}
