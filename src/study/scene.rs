//! What is looked at: lights and surfaces with the names they have in
//! tables, chosen by built-in name or loaded from files.
//!
//! ```
//! use speclab::study::scene::{Choice, builtin_surfaces};
//! use speclab::Role;
//! let d65 = Choice::Name("d65".into()).resolve(Role::Light)?;
//! assert_eq!(d65.name, "D65");
//! assert_eq!(builtin_surfaces().len(), 6);
//! let err = Choice::Name("F12".into()).resolve(Role::Light).unwrap_err();
//! assert_eq!(err.to_string(), "expected a built-in light (A, D65 or F11), found \"F12\"");
//! # Ok::<(), speclab::study::StudyError>(())
//! ```

use std::path::PathBuf;

use crate::io::Load;
use crate::spectrum::data::{Light, Patch};
use crate::spectrum::{Role, TabulatedSpectrum};
use crate::study::error::StudyError;

/// A spectrum with the name it has in tables.
#[derive(Clone, Debug, PartialEq)]
pub struct Named {
    /// Name, e.g. `D65`, or a file's stem.
    pub name: String,
    /// The spectrum.
    pub spectrum: TabulatedSpectrum,
}

impl Named {
    /// `spectrum`, called `name`.
    #[must_use]
    pub fn new(name: impl Into<String>, spectrum: TabulatedSpectrum) -> Self {
        Named { name: name.into(), spectrum }
    }
}

/// A spectrum chosen on a command line: a built-in name or a file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Choice {
    /// A built-in spectrum by name, any case (A, D65, F11; E2, F4, G4, H4, J4, A1).
    Name(String),
    /// A file in any format [`Load`] reads.
    File(PathBuf),
}

impl Choice {
    /// The spectrum, named as tables show it (a file by its stem). Names are
    /// looked up among the built-in lights for [`Role::Light`] and among the
    /// patches otherwise.
    pub fn resolve(&self, role: Role) -> Result<Named, StudyError> {
        match self {
            Choice::Name(name) => Ok(match role {
                Role::Light => {
                    name.parse::<Light>().map(|l| Named::new(l.to_string(), l.spectrum().clone()))?
                }
                _ => name.parse::<Patch>().map(|p| Named::new(p.to_string(), p.spectrum().clone()))?,
            }),
            Choice::File(path) => {
                let spectrum = Load::new(role).file(path)?;
                let name =
                    path.file_stem().map_or_else(|| "file".into(), |s| s.to_string_lossy().into_owned());
                Ok(Named::new(name, spectrum))
            }
        }
    }
}

/// The three appendix lights, named.
#[must_use]
pub fn builtin_lights() -> Vec<Named> {
    Light::ALL.iter().map(|l| Named::new(l.to_string(), l.spectrum().clone())).collect()
}

/// The six appendix patches, named.
#[must_use]
pub fn builtin_surfaces() -> Vec<Named> {
    Patch::ALL.iter().map(|p| Named::new(p.to_string(), p.spectrum().clone())).collect()
}
