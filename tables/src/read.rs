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

/// What to do with samples that do not reach a range: the caller names it,
/// nothing is filled in silently.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Extend {
    /// Refuse samples that do not cover 380–730 nm (the default): the
    /// error names the range found and the range required.
    #[default]
    Refuse,
    /// Zero outside the samples (every spectrum is zero outside its table).
    Zero,
    /// The end values held out to 360 and 830 nm, as pbrt-v4 pads: samples
    /// added at the end's step (at least [`HOLD_STEP`] nm), the last at
    /// the range's end.
    Hold,
}

/// The smallest step of the samples [`Extend::Hold`] adds, nm.
pub const HOLD_STEP: f64 = 5.0;

/// How far [`Extend::Hold`] holds the end values, nm (360–830).
pub const HOLD_RANGE: [f64; 2] = [360.0, 830.0];

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
    samples_with(text, origin, role, interpolation, format, Extend::Refuse)
}

/// [`samples`] with samples short of 380–730 nm treated as `extend` says.
pub fn samples_with(
    text: &str,
    origin: &str,
    role: Role,
    interpolation: Interpolation,
    format: Option<Format>,
    extend: Extend,
) -> Result<Samples, ParseError> {
    let parsed = format.unwrap_or_else(|| Format::detect(text)).parse(text, origin)?;
    let mut samples = locate(parsed, origin, role, interpolation)?;
    match extend {
        Extend::Refuse => covers_range(&samples, origin)?,
        Extend::Zero => {}
        Extend::Hold => samples = hold(samples),
    }
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

/// The samples with their end values held out to [`HOLD_RANGE`].
pub fn hold(s: Samples) -> Samples {
    let n = s.lambda.len();
    if n < 2 {
        return s;
    }
    let mut out = Samples::default();
    let (first, last) = (s.lambda[0], s.lambda[n - 1]);
    // Samples from `from` (excluded) to `to` (included) going `direction`;
    // none where the samples already reach `to`.
    let pad = |from: f64, to: f64, direction: f64, step: f64| {
        let count = ((to - from) * direction / step).ceil().max(0.0) as usize;
        (1..count).map(move |i| from + direction * step * i as f64).chain((count > 0).then_some(to))
    };
    let low: Vec<f64> = pad(first, HOLD_RANGE[0], -1.0, (s.lambda[1] - first).max(HOLD_STEP)).collect();
    for &l in low.iter().rev() {
        out.push(l, s.values[0], s.positions[0], s.value_positions[0]);
    }
    for i in 0..n {
        out.push(s.lambda[i], s.values[i], s.positions[i], s.value_positions[i]);
    }
    for l in pad(last, HOLD_RANGE[1], 1.0, (last - s.lambda[n - 2]).max(HOLD_STEP)) {
        out.push(l, s.values[n - 1], s.positions[n - 1], s.value_positions[n - 1]);
    }
    out
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

#[cfg(test)]
mod tests {
    use super::*;

    fn load(text: &str, extend: Extend) -> Result<Samples, ParseError> {
        samples_with(text, "t.csv", Role::Reflectance, Interpolation::Linear, None, extend)
    }

    #[test]
    fn a_partial_spectrum_needs_a_policy() {
        let text = "400,0.2\n410,0.3\n700,0.6\n";
        let refused = load(text, Extend::Refuse).unwrap_err();
        assert_eq!(refused.to_string(), "t.csv:1:1: expected samples covering 380-730 nm, found 400-700 nm");
        assert_eq!(load(text, Extend::Zero).unwrap().lambda, [400.0, 410.0, 700.0]);
        let held = load(text, Extend::Hold).unwrap();
        let low = [360.0, 370.0, 380.0, 390.0, 400.0, 410.0];
        assert_eq!(held.lambda[..6], low, "the first step (10 nm) down to 360 nm");
        assert_eq!(held.lambda[6..], [700.0, 830.0], "the last step (290 nm) reaches 830 nm at once");
        assert_eq!(held.values, [0.2, 0.2, 0.2, 0.2, 0.2, 0.3, 0.6, 0.6]);
        assert_eq!(held.positions[0], held.positions[4], "a held sample is placed at the sample it repeats");
        let fine = load("379,1\n380,1\n731,0.5\n", Extend::Hold).unwrap();
        assert_eq!(fine.lambda[..4], [360.0, 364.0, 369.0, 374.0], "steps of at least 5 nm, 360 last");
        assert_eq!(fine.lambda[4..6], [379.0, 380.0]);
        assert_eq!(fine.lambda[fine.lambda.len() - 2..], [731.0, 830.0]);
        let whole = load("350,0.1\n900,0.2\n", Extend::Hold).unwrap();
        assert_eq!(whole.lambda, [350.0, 900.0], "nothing to hold");
    }
}
