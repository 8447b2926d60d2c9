//! Loading spectra that users measured or downloaded.
//!
//! Three formats, told apart by content (not by file name):
//! - the assignment's brace notation, `{380, 0.04}, {385, 0.05}, ...`
//!   (text starting with `{` followed by a number);
//! - JSON, `{"wavelengths": [...], "values": [...]}` (text starting with
//!   `{` followed by `"`), see [`crate::json`];
//! - two-column text (anything else): CSV, TSV or whitespace, with `#`
//!   comments and an optional header, see [`crate::columns`].
//!
//! Samples are validated for their [`Role`] (see [`crate::samples`]), and a
//! loaded spectrum **must cover the integration range** 380–730 nm: a lamp
//! file that stops at 700 nm is an error, not a silently darker colour. (A
//! spectrum built in code with [`TabulatedSpectrum::new`] is instead zero
//! outside its samples, as documented there.) Every error names the source,
//! line and column.
//!
//! ```
//! use speclab::load::Load;
//! use speclab::Role;
//! let text = "nm,power\n380,1\n730,2\n";
//! let lamp = Load::new(Role::Light).text(text, "lamp.csv")?;
//! assert_eq!(lamp.eval(555.0), 1.5);
//! let short = Load::new(Role::Light).text("380,1\n700,2\n", "short.csv").unwrap_err();
//! assert_eq!(short.to_string(), "short.csv:2:1: expected samples covering 380-730 nm, found 380-700 nm");
//! # Ok::<(), speclab::Error>(())
//! ```

use std::path::Path;

use crate::parse::{ParseError, ParseErrorKind, Position, Samples, parse_samples};
use crate::samples::{Interpolation, Role, locate};
use crate::{Error, LAMBDA_MAX, LAMBDA_MIN, TabulatedSpectrum, columns, json};

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
    /// The format of `text`, from its first character that is not blank or
    /// in a `#` comment.
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
}

/// How to load: the role, the interpolation (by default the role's) and the
/// format (by default detected).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Load {
    /// What the spectrum is; sets validation and clamping.
    pub role: Role,
    /// How to interpolate.
    pub interpolation: Interpolation,
    /// The format, or `None` to detect it.
    pub format: Option<Format>,
}

impl Load {
    /// Loading as `role`, with its interpolation and a detected format.
    #[must_use]
    pub fn new(role: Role) -> Self {
        Load { role, interpolation: role.interpolation(), format: None }
    }

    /// The same, with `interpolation` stated explicitly.
    #[must_use]
    pub fn with_interpolation(self, interpolation: Interpolation) -> Self {
        Load { interpolation, ..self }
    }

    /// The same, with the format stated explicitly.
    #[must_use]
    pub fn with_format(self, format: Format) -> Self {
        Load { format: Some(format), ..self }
    }

    /// A spectrum from `text`; `origin` names it in errors.
    pub fn text(&self, text: &str, origin: &str) -> Result<TabulatedSpectrum, Error> {
        let samples = match self.format.unwrap_or_else(|| Format::detect(text)) {
            Format::Brace => parse_samples(text, origin)?,
            Format::Json => json::parse_json(text, origin)?,
            Format::Columns => columns::parse_columns(text, origin)?,
        };
        let samples = locate(samples, origin, self.role, self.interpolation)?;
        covers_range(&samples, origin)?;
        Ok(TabulatedSpectrum::from_samples(samples, self.role, self.interpolation))
    }

    /// A spectrum from the file at `path`.
    pub fn file(&self, path: impl AsRef<Path>) -> Result<TabulatedSpectrum, Error> {
        let path = path.as_ref();
        let text =
            std::fs::read_to_string(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        self.text(&text, &path.display().to_string())
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
    let at = at.copied().unwrap_or(Position { line: 1, column: 1 });
    let kind = ParseErrorKind::Support { found: [first, last], required: [LAMBDA_MIN, LAMBDA_MAX] };
    Err(ParseError { origin: origin.to_string(), position: at, kind })
}
