//! From bytes to validated samples, the one route every input takes: read
//! at most [`MAX_BYTES`], detect the format, parse, validate for the role,
//! and check that the samples cover 380–730 nm. Run-time loading
//! ([`super::Load`]) and compile-time data ([`crate::codegen`], used by
//! `build.rs`) both call [`samples`], so they accept and reject the same
//! files with the same messages.
//!
//! This file depends on `std` only: `build.rs` includes it with `#[path]`.
//!
//! ```
//! use speclab::io::read::{self, Format};
//! use speclab::Role;
//! let text = "nm,power\n380,1\n730,2\n";
//! assert_eq!(Format::detect(text), Format::Columns);
//! let s = read::samples(text, "lamp.csv", Role::Light, Role::Light.interpolation(), None)?;
//! assert_eq!(s.values, vec![1.0, 2.0]);
//! # Ok::<(), speclab::io::text::ParseError>(())
//! ```

use std::io::Read;
use std::path::{Path, PathBuf};

use crate::error::Error;
use crate::io::text::{ParseError, ParseErrorKind, Position, Samples};
use crate::io::{brace, columns, json};
use crate::spectrum::range::{LAMBDA_MAX, LAMBDA_MIN};
use crate::spectrum::validate::{Field, Interpolation, Invalid, Role, validate};

/// The most bytes read from one file or stream: 64 MiB. A spectrum is a few
/// kilobytes; anything larger is a wrong file (or `/dev/zero`).
pub const MAX_BYTES: u64 = 64 << 20;

/// A text format for spectra.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// `{λ, v}, {λ, v}, ...`
    Brace,
    /// `{"wavelengths": [...], "values": [...]}`
    Json,
    /// Rows of `λ, v` (CSV, TSV or whitespace).
    Columns,
}

impl Format {
    /// The format of `text`, from its first two characters that are not
    /// blank or in a `#` comment: `{"` is JSON, `{` brace notation, anything
    /// else rows.
    #[must_use]
    pub fn detect(text: &str) -> Format {
        let mut chars = text
            .lines()
            .flat_map(|line| line.split('#').next().unwrap_or_default().chars().chain(['\n']))
            .filter(|c| !c.is_whitespace());
        match (chars.next(), chars.next()) {
            (Some('{'), Some('"')) => Format::Json,
            (Some('{'), _) => Format::Brace,
            _ => Format::Columns,
        }
    }

    /// Parses `text` in this format, without validating it.
    pub fn parse(self, text: &str, origin: &str) -> Result<Samples, ParseError> {
        match self {
            Format::Brace => brace::parse_samples(text, origin),
            Format::Json => json::parse_json(text, origin),
            Format::Columns => columns::parse_columns(text, origin),
        }
    }
}

/// Validated samples from `text` in `format` (detected if `None`), covering
/// 380–730 nm; every error names `origin`, the line and the column.
pub fn samples(
    text: &str,
    origin: &str,
    role: Role,
    interpolation: Interpolation,
    format: Option<Format>,
) -> Result<Samples, ParseError> {
    let parsed = format.unwrap_or_else(|| Format::detect(text)).parse(text, origin)?;
    let samples = locate(parsed, origin, role, interpolation)?;
    covers_range(&samples, origin)?;
    Ok(samples)
}

/// Validates parsed samples; an invalid one becomes an error at the place
/// its wavelength or value was written.
pub(crate) fn locate(
    samples: Samples,
    origin: &str,
    role: Role,
    interpolation: Interpolation,
) -> Result<Samples, ParseError> {
    match validate(&samples.lambda, &samples.values, role, interpolation) {
        Ok(()) => Ok(samples),
        Err(e) => {
            let at = match e.field {
                Field::Wavelength => &samples.positions,
                Field::Value => &samples.value_positions,
            };
            let position = at.get(e.index).copied().unwrap_or(Position::START);
            Err(ParseError { origin: origin.to_string(), position, kind: ParseErrorKind::Invalid(e.problem) })
        }
    }
}

/// Errors unless the samples span 380–730 nm.
fn covers_range(s: &Samples, origin: &str) -> Result<(), ParseError> {
    let (Some(&first), Some(&last)) = (s.lambda.first(), s.lambda.last()) else {
        return Ok(()); // validation already required enough samples
    };
    if first <= LAMBDA_MIN && last >= LAMBDA_MAX {
        return Ok(());
    }
    let at = if first > LAMBDA_MIN { s.positions.first() } else { s.positions.last() };
    let problem = Invalid::Support { found: [first, last], required: [LAMBDA_MIN, LAMBDA_MAX] };
    let position = at.copied().unwrap_or(Position::START);
    Err(ParseError { origin: origin.to_string(), position, kind: ParseErrorKind::Invalid(problem) })
}

/// All of `reader` as UTF-8 text, or an error naming `origin` if it holds
/// more than `limit` bytes or is not text. Reads at most `limit + 1` bytes.
pub fn text(reader: impl Read, origin: &str, limit: u64) -> Result<String, Error> {
    let mut bytes = Vec::new();
    let io = |source| Error::Io { path: PathBuf::from(origin), source };
    reader.take(limit.saturating_add(1)).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(Error::TooLarge { origin: origin.to_string(), limit });
    }
    String::from_utf8(bytes).map_err(|e| io(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))
}

/// The file at `path` as text, at most [`MAX_BYTES`].
pub fn file(path: &Path) -> Result<String, Error> {
    let io = |source| Error::Io { path: path.to_path_buf(), source };
    let file = std::fs::File::open(path).map_err(io)?;
    text(file, &path.display().to_string(), MAX_BYTES)
}
