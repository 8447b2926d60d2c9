//! The assignment's built-in spectra, as static data generated at build time.
//!
//! `build.rs` reads `data/*.txt` (brace notation, values exactly as printed
//! in Appendix 1) with [`crate::codegen`], the build helper that users get
//! too, and emits the samples plus precomputed segment coefficients.
//! Provenance, units, step and range of every file are in `data/SOURCES.md`.
//!
//! - Lights (5 nm, linear): [`A`] 380–730 nm, [`D65`] and [`F11`] 380–780 nm.
//! - ColorChecker SG patches (10 nm, cubic, 380–730 nm): [`E2`], [`F4`],
//!   [`G4`], [`H4`], [`J4`], [`A1`].
//! - CIE 1931 2° matching functions (5 nm, cubic, 380–780 nm): [`CIE_X`],
//!   [`CIE_Y`], [`CIE_Z`].
//!
//! ```
//! use speclab::data::{Light, Patch};
//! assert_eq!(Light::F11.spectrum().eval(545.0), 72.84);
//! assert_eq!(Patch::A1.name(), "A1");
//! ```

use crate::TabulatedSpectrum;
use crate::sampling::light_pdf::PiecewisePdf;
use crate::sampling::pdf::Weighting;
use crate::sampling::weights::Weights;

mod generated {
    include!(concat!(env!("OUT_DIR"), "/data.rs"));
}

/// The compiled-in reference weights of `light`, if it is a built-in light
/// or a clone of one (its tables are the static ones), for reflectances on
/// the patches' 10 nm grid. Computed by `build.rs`.
pub(crate) fn builtin_weights(light: &TabulatedSpectrum) -> Option<&'static Weights> {
    let weights = [&generated::A_WEIGHTS, &generated::D65_WEIGHTS, &generated::F11_WEIGHTS];
    builtin_light(light).map(|i| weights[i])
}

/// The compiled-in wavelength pdf of `light` (see `builtin_weights`).
pub(crate) fn builtin_pdf(light: &TabulatedSpectrum, weighting: Weighting) -> Option<&'static PiecewisePdf> {
    let pdfs = match weighting {
        Weighting::Light => [&generated::A_PDF_LIGHT, &generated::D65_PDF_LIGHT, &generated::F11_PDF_LIGHT],
        Weighting::Balanced => {
            [&generated::A_PDF_BALANCED, &generated::D65_PDF_BALANCED, &generated::F11_PDF_BALANCED]
        }
    };
    builtin_light(light).map(|i| pdfs[i])
}

/// Which built-in light `light` is (by its static tables), if any.
fn builtin_light(light: &TabulatedSpectrum) -> Option<usize> {
    let same = |s: &TabulatedSpectrum| {
        let (a, b) = (s.values(), light.values());
        std::ptr::eq(a, b) && std::ptr::eq(s.lambda(), light.lambda()) && s.role() == light.role()
    };
    [&A, &D65, &F11].into_iter().position(same)
}

pub use generated::{A, A1, CIE_X, CIE_Y, CIE_Z, D65, E2, F4, F11, G4, H4, J4};
pub(crate) use generated::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA, XYZ_TO_SRGB,
};

/// The three appendix lights.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Light {
    /// CIE illuminant A (incandescent).
    A,
    /// CIE illuminant D65 (daylight).
    D65,
    /// F11 (narrow-band fluorescent; spiky).
    F11,
}

impl Light {
    /// All lights, in the order of Appendix 2's columns.
    pub const ALL: [Light; 3] = [Light::A, Light::D65, Light::F11];

    /// The light's spectrum.
    #[must_use]
    pub fn spectrum(self) -> &'static TabulatedSpectrum {
        match self {
            Light::A => &A,
            Light::D65 => &D65,
            Light::F11 => &F11,
        }
    }

    /// Its name as Appendix 2 writes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Light::A => "A",
            Light::D65 => "D65",
            Light::F11 => "F11",
        }
    }

    /// The light with this name (case-insensitive).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Light> {
        Light::ALL.into_iter().find(|l| l.name().eq_ignore_ascii_case(name))
    }
}

/// The six ColorChecker SG patches of the appendix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Patch {
    /// E2, dark skin.
    E2,
    /// F4, green.
    F4,
    /// G4, red.
    G4,
    /// H4, yellow.
    H4,
    /// J4, cyan.
    J4,
    /// A1, white.
    A1,
}

impl Patch {
    /// All patches, in the order of Appendix 2's rows.
    pub const ALL: [Patch; 6] = [Patch::E2, Patch::F4, Patch::G4, Patch::H4, Patch::J4, Patch::A1];

    /// The patch's reflectance.
    #[must_use]
    pub fn spectrum(self) -> &'static TabulatedSpectrum {
        match self {
            Patch::E2 => &E2,
            Patch::F4 => &F4,
            Patch::G4 => &G4,
            Patch::H4 => &H4,
            Patch::J4 => &J4,
            Patch::A1 => &A1,
        }
    }

    /// Its name as Appendix 2 writes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Patch::E2 => "E2",
            Patch::F4 => "F4",
            Patch::G4 => "G4",
            Patch::H4 => "H4",
            Patch::J4 => "J4",
            Patch::A1 => "A1",
        }
    }

    /// The patch with this name (case-insensitive).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Patch> {
        Patch::ALL.into_iter().find(|p| p.name().eq_ignore_ascii_case(name))
    }
}
