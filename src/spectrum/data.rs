//! The assignment's built-in spectra, as static data generated at build time.
//!
//! `build.rs` reads `data/*.txt` (brace notation, values exactly as printed
//! in Appendix 1) with `speclab_tables::Codegen`, the build helper that users
//! get too, and emits the samples plus precomputed segment coefficients.
//! Provenance, units, step and range of every file are in `data/SOURCES.md`.
//!
//! Grouped so that a light cannot be mistaken for a patch:
//! - [`lights`] (5 nm, linear): `A` 380–730 nm, `D65` and `F11` 380–780 nm;
//!   also by name, [`Light`].
//! - [`patches`], ColorChecker SG (10 nm, cubic, 380–730 nm): `E2`, `F4`,
//!   `G4`, `H4`, `J4`, `A1`; also by name, [`Patch`].
//! - [`cie1931`], the 2° matching functions (5 nm, cubic, 380–780 nm):
//!   `X_BAR`, `Y_BAR`, `Z_BAR`.
//!
//! ```
//! use speclab::data::{lights, patches, Light, Patch};
//! assert_eq!(lights::F11.eval(545.0), 72.84);
//! assert_eq!("f11".parse::<Light>()?.spectrum(), &lights::F11);
//! assert_eq!(Patch::A1.to_string(), "A1");
//! assert!(patches::A1.eval(555.0) > 0.8);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::named_choices;
use crate::spectrum::TabulatedSpectrum;

mod generated {
    include!(concat!(env!("OUT_DIR"), "/data.rs"));
}

/// The three appendix lights (relative spectral power; see `data/SOURCES.md`).
pub mod lights {
    pub use super::generated::{A, D65, F11};
}

/// The six ColorChecker SG patches of the appendix (reflectance, 0–1).
pub mod patches {
    pub use super::generated::{A1, E2, F4, G4, H4, J4};
}

/// The CIE 1931 2° standard observer's matching functions x̄, ȳ, z̄.
pub mod cie1931 {
    pub use super::generated::{CIE_X as X_BAR, CIE_Y as Y_BAR, CIE_Z as Z_BAR};
}

pub(crate) use generated::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA, XYZ_TO_SRGB,
};

/// The three appendix lights, by name.
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
            Light::A => &lights::A,
            Light::D65 => &lights::D65,
            Light::F11 => &lights::F11,
        }
    }
}

named_choices!(Light, "a built-in light": A => "A", D65 => "D65", F11 => "F11");

/// The six ColorChecker SG patches of the appendix, by name.
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
            Patch::E2 => &patches::E2,
            Patch::F4 => &patches::F4,
            Patch::G4 => &patches::G4,
            Patch::H4 => &patches::H4,
            Patch::J4 => &patches::J4,
            Patch::A1 => &patches::A1,
        }
    }
}

named_choices!(Patch, "a built-in patch": E2 => "E2", F4 => "F4", G4 => "G4", H4 => "H4", J4 => "J4", A1 => "A1");
