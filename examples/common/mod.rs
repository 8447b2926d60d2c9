//! Glue shared by the examples: choosing a light and a surface by name or
//! by file, and reporting errors.

use std::path::PathBuf;

use speclab::data::{Light, Patch};
use speclab::load::Load;
use speclab::remarks::Normalization;
use speclab::{Role, TabulatedSpectrum};

/// A spectrum chosen on the command line: a built-in name or a file.
#[derive(Clone, Debug)]
pub enum Choice {
    /// A built-in spectrum by name (A, D65, F11; E2, F4, G4, H4, J4, A1).
    Name(String),
    /// A file in any format the loader reads.
    File(PathBuf),
}

impl Choice {
    /// The spectrum and the name to show, or a message for stderr.
    pub fn resolve(&self, role: Role) -> Result<(String, TabulatedSpectrum), String> {
        match self {
            Choice::Name(name) => {
                let builtin = match role {
                    Role::Light => Light::from_name(name).map(|l| (l.name(), l.spectrum())),
                    _ => Patch::from_name(name).map(|p| (p.name(), p.spectrum())),
                };
                let (name, spectrum) = builtin.ok_or_else(|| match role {
                    Role::Light => format!("unknown light {name:?}: expected A, D65 or F11"),
                    _ => format!("unknown surface {name:?}: expected E2, F4, G4, H4, J4 or A1"),
                })?;
                Ok((name.to_string(), spectrum.clone()))
            }
            Choice::File(path) => {
                let spectrum = Load::new(role).file(path).map_err(|e| e.to_string())?;
                let name =
                    path.file_stem().map_or_else(|| "file".into(), |s| s.to_string_lossy().into_owned());
                Ok((name, spectrum))
            }
        }
    }
}

/// Prints `message` as the program's error and returns exit status 2.
pub fn fail(program: &str, message: impl std::fmt::Display) -> std::process::ExitCode {
    eprintln!("{program}: {message}");
    std::process::ExitCode::from(2)
}

/// The `--normalize` value, or a message naming the choices.
#[allow(dead_code)] // converge has no --normalize
pub fn normalization(name: &str) -> Result<Normalization, String> {
    Normalization::from_name(name)
        .ok_or_else(|| format!("unknown normalisation {name:?}: expected none, power or luminance"))
}
