//! Two-column text: CSV, TSV or whitespace-separated `wavelength value` rows.
//!
//! - `#` starts a comment, to the end of the line; blank lines are skipped.
//! - One optional header line before the first row. If it names micrometres
//!   (`µm`, `um`, `micro`), wavelengths are converted to nanometres.
//! - Fields are separated by commas, semicolons, tabs or spaces.
//! - Wavelengths are in nanometres (a plausibility check catches µm tables
//!   without a header).
//!
//! Whether the rows make a spectrum is checked afterwards, by
//! [`crate::read`].
//!
//! ```
//! use speclab_tables::columns::parse_columns;
//! let s = parse_columns("wavelength_um,power\n0.38,1\n0.39,2\n", "<string>")?;
//! assert_eq!(s.lambda, vec![380.0, 390.0]);
//! # Ok::<(), speclab_tables::error::ParseError>(())
//! ```

use crate::error::{ParseError, ParseErrorKind, Position};
use crate::text::{Samples, number};

/// Reads rows of two finite numbers; errors name the line and column of the field.
pub fn parse_columns(text: &str, origin: &str) -> Result<Samples, ParseError> {
    let mut samples = Samples::default();
    let mut scale = 1.0;
    let mut seen_content = false;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or_default();
        let fields = fields(line);
        if fields.is_empty() {
            continue;
        }
        let at = |column| Position { line: i + 1, column };
        let first_content = !seen_content;
        seen_content = true;
        let is_header = !looks_numeric(fields[0].1);
        if first_content && is_header {
            scale = if names_micrometres(line) { 1000.0 } else { 1.0 };
            continue;
        }
        if fields.len() != 2 {
            let kind = ParseErrorKind::Arity { found: fields.len(), expected: 2 };
            return Err(ParseError { origin: origin.to_string(), position: at(fields[0].0), kind });
        }
        let lambda = number(fields[0].1, origin, at(fields[0].0))? * scale;
        let value = number(fields[1].1, origin, at(fields[1].0))?;
        samples.push(lambda, value, at(fields[0].0), at(fields[1].0));
    }
    Ok(samples)
}

/// The fields of a line with their 1-based character columns. Commas and
/// semicolons separate fields (an empty field between two is kept, so a
/// missing value is reported); otherwise tabs and spaces do.
pub(crate) fn fields(line: &str) -> Vec<(usize, &str)> {
    let line = line.trim_end_matches('\r');
    if line.trim().is_empty() {
        return Vec::new();
    }
    let mut out = Vec::new();
    let delimited = line.contains([',', ';']);
    let mut start = 0;
    for (idx, c) in line.char_indices().chain([(line.len(), '\n')]) {
        let split =
            if delimited { c == ',' || c == ';' || c == '\n' } else { c.is_whitespace() || c == '\n' };
        if split {
            let field = &line[start..idx];
            let trimmed = field.trim();
            if delimited || !trimmed.is_empty() {
                let lead = field.len() - field.trim_start().len();
                out.push((line[..start + lead].chars().count() + 1, trimmed));
            }
            start = idx + c.len_utf8();
        }
    }
    out
}

/// True for tokens that are meant as numbers even if malformed (`1.2.3`,
/// `nan`, `inf`, empty): a row starting so is a row, not a header.
pub(crate) fn looks_numeric(field: &str) -> bool {
    let lower = field.to_ascii_lowercase();
    field.is_empty()
        || field.starts_with(|c: char| c.is_ascii_digit() || c == '.' || c == '-' || c == '+')
        || ["nan", "inf", "infinity"].contains(&lower.as_str())
}

/// True if a header line says the wavelengths are in micrometres.
fn names_micrometres(header: &str) -> bool {
    let lower = header.to_lowercase();
    lower.contains("µm")
        || lower.contains("μm")
        || lower.contains("micro")
        || lower.split(|c: char| !c.is_alphanumeric()).any(|w| w == "um")
}
