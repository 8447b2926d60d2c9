//! Glue shared by the examples: option values and exit statuses.

// Each example uses part of this module.
#![allow(dead_code)]

use std::io::{self, IsTerminal};
use std::process::ExitCode;

use speclab::color::GamutMap;
use speclab::sampling::strata::Strata;
use speclab::study::remarks::Normalization;
use speclab::study::sampling::Pdf;

/// Prints `message` as the program's error and returns exit status 2.
pub fn fail(program: &str, message: impl std::fmt::Display) -> ExitCode {
    eprintln!("{program}: {message}");
    ExitCode::from(2)
}

/// Success, or status 2 for a write error other than a closed pipe (`| head`).
pub fn finish(program: &str, written: io::Result<()>) -> ExitCode {
    match written {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => fail(program, e),
        _ => ExitCode::SUCCESS,
    }
}

/// The `--pdf` value, or a message naming the choices.
pub fn pdf(name: &str) -> Result<Pdf, String> {
    Pdf::from_name(name)
        .ok_or_else(|| format!("unknown pdf {name:?}: expected uniform, visible, light or balanced"))
}

/// The `--strata` value, or a message naming the choices.
pub fn strata(name: &str) -> Result<Strata, String> {
    Strata::from_name(name)
        .ok_or_else(|| format!("unknown strata {name:?}: expected independent, jitter or kronecker"))
}

/// The `--normalize` value, or a message naming the choices.
pub fn normalization(name: &str) -> Result<Normalization, String> {
    Normalization::from_name(name)
        .ok_or_else(|| format!("unknown normalisation {name:?}: expected none, power or luminance"))
}

/// The `--gamut` value, or a message naming the choices.
pub fn gamut(name: &str) -> Result<GamutMap, String> {
    GamutMap::from_name(name).ok_or_else(|| format!("unknown gamut map {name:?}: expected clip or chroma"))
}

/// True if standard output takes truecolour swatches: a terminal, and
/// `NO_COLOR` unset or empty.
pub fn colour() -> bool {
    io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}
