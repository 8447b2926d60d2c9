//! From bytes to validated samples, the one route every input takes: read
//! at most [`MAX_BYTES`], detect the format, parse, validate for the role,
//! check that the samples cover 380–730 nm, and that a light has power
//! there. Run-time loading (speclab's `io::Load`) and compile-time data
//! ([`crate::Codegen`], in build scripts) both call [`samples`], so they
//! accept and reject the same files with the same messages.
//!
//! ```
//! use speclab_tables::read::{self, Format};
//! use speclab_tables::Role;
//! let text = "nm,power\n380,1\n730,2\n";
//! assert_eq!(Format::detect(text), Format::Columns);
//! let s = read::samples(text, "lamp.csv", Role::Light, Role::Light.interpolation(), None)?;
//! assert_eq!(s.values, vec![1.0, 2.0]);
//! # Ok::<(), speclab_tables::error::ParseError>(())
//! ```

use std::io::Read;
use std::path::{Path, PathBuf};

use crate::error::{ParseError, ParseErrorKind, Position, ReadError};
use crate::range::{LAMBDA_MAX, LAMBDA_MIN};
use crate::text::Samples;
use crate::validate::{Field, Interpolation, Invalid, Role, validate};
use crate::{brace, columns, interp, json};

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
/// 380–730 nm (and, for a light, with power there); every error names
/// `origin`, the line and the column.
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
    if role == Role::Light {
        has_power(&samples, origin, interpolation)?;
    }
    Ok(samples)
}

/// Validates parsed samples; an invalid one becomes an error at the place
/// its wavelength or value was written.
fn locate(
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

/// Errors unless the light's interpolant has power somewhere in 380–730 nm
/// (it is clamped at zero, so its integral there is positive).
fn has_power(s: &Samples, origin: &str, interpolation: Interpolation) -> Result<(), ParseError> {
    let c = interp::coeffs(interpolation, &s.lambda, &s.values);
    let bounds = Role::Light.bounds();
    let brk = interp::breaks(&s.lambda, &c, bounds);
    if interp::integral(&s.lambda, &c, &brk, bounds, LAMBDA_MIN, LAMBDA_MAX) > 0.0 {
        return Ok(());
    }
    let position = s.value_positions.first().copied().unwrap_or(Position::START);
    let kind = ParseErrorKind::Invalid(Invalid::NoPower { range: [LAMBDA_MIN, LAMBDA_MAX] });
    Err(ParseError { origin: origin.to_string(), position, kind })
}

/// All of `reader` as UTF-8 text, or an error naming `origin` if it holds
/// more than `limit` bytes or is not text. Reads at most `limit + 1` bytes.
pub fn text(reader: impl Read, origin: &str, limit: u64) -> Result<String, ReadError> {
    let mut bytes = Vec::new();
    let io = |source| ReadError::Io { path: PathBuf::from(origin), source };
    reader.take(limit.saturating_add(1)).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLarge { origin: origin.to_string(), limit });
    }
    String::from_utf8(bytes).map_err(|e| io(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))
}

/// The file at `path` as text, at most [`MAX_BYTES`].
pub fn file(path: &Path) -> Result<String, ReadError> {
    let io = |source| ReadError::Io { path: path.to_path_buf(), source };
    let file = std::fs::File::open(path).map_err(io)?;
    text(file, &path.display().to_string(), MAX_BYTES)
}
