//! A simple JSON form, `{"wavelengths": [...], "values": [...]}`, so that
//! other tools can hand spectra over. Both keys are required, in any order;
//! other keys are errors (a misspelt key must not go unnoticed). Whether
//! the arrays make a spectrum is checked afterwards, by [`crate::read`].
//!
//! ```
//! use speclab_tables::json::parse_json;
//! let s = parse_json(r#"{"wavelengths": [380, 390], "values": [0.5, 0.25]}"#, "<string>")?;
//! assert_eq!(s.values, vec![0.5, 0.25]);
//! # Ok::<(), speclab_tables::error::ParseError>(())
//! ```

use crate::error::{ParseError, ParseErrorKind, Position};
use crate::text::{Cursor, Samples};

const KEYS: &str = "\"wavelengths\" or \"values\"";

/// Reads the JSON form; errors name the line and column.
pub fn parse_json(text: &str, origin: &str) -> Result<Samples, ParseError> {
    let mut cursor = Cursor::new(text, origin);
    let start = cursor.position;
    let mut lambda: Option<Vec<(f64, Position)>> = None;
    let mut values: Option<Vec<(f64, Position)>> = None;
    cursor.skip_blank();
    cursor.expect('{', "'{' opening a JSON object")?;
    loop {
        cursor.skip_blank();
        let key_at = cursor.position;
        let key = string(&mut cursor)?;
        cursor.skip_blank();
        cursor.expect(':', "':' after a key")?;
        let slot = match key.as_str() {
            "wavelengths" => &mut lambda,
            "values" => &mut values,
            _ => return Err(cursor.error(key_at, ParseErrorKind::Key { found: key, expected: KEYS })),
        };
        *slot = Some(array(&mut cursor)?);
        cursor.skip_blank();
        if cursor.peek() == Some('}') {
            cursor.bump();
            break;
        }
        cursor.expect(',', "',' or '}' after an array")?;
    }
    cursor.skip_blank();
    if let Some(found) = cursor.peek() {
        let kind = ParseErrorKind::Unexpected { found, expected: "end of text after the JSON object" };
        return Err(cursor.error(cursor.position, kind));
    }
    let missing = |what| cursor.error(start, ParseErrorKind::Missing { expected: what });
    let lambda = lambda.ok_or_else(|| missing("a \"wavelengths\" array"))?;
    let values = values.ok_or_else(|| missing("a \"values\" array"))?;
    let mut samples = Samples::default();
    for (&(x, at), &(y, value_at)) in lambda.iter().zip(&values) {
        samples.push(x, y, at, value_at);
    }
    if lambda.len() != values.len() {
        let at = values.last().or(lambda.last()).map_or(start, |&(_, p)| p);
        let kind = ParseErrorKind::Count { found: values.len(), expected: lambda.len() };
        return Err(cursor.error(at, kind));
    }
    Ok(samples)
}

/// A JSON string without escapes (keys only).
fn string(cursor: &mut Cursor) -> Result<String, ParseError> {
    cursor.expect('"', "'\"' opening a key")?;
    let mut text = String::new();
    loop {
        match cursor.bump() {
            Some('"') => return Ok(text),
            Some(c) => text.push(c),
            None => {
                let kind = ParseErrorKind::UnexpectedEnd { expected: "'\"' closing a key" };
                return Err(cursor.error(cursor.position, kind));
            }
        }
    }
}

/// `[n, n, ...]` with the position of each number.
fn array(cursor: &mut Cursor) -> Result<Vec<(f64, Position)>, ParseError> {
    cursor.skip_blank();
    cursor.expect('[', "'[' opening an array")?;
    let mut out = Vec::new();
    cursor.skip_blank();
    if cursor.peek() == Some(']') {
        cursor.bump();
        return Ok(out);
    }
    loop {
        cursor.skip_blank();
        let at = cursor.position;
        out.push((cursor.number()?, at));
        cursor.skip_blank();
        if cursor.peek() == Some(']') {
            cursor.bump();
            return Ok(out);
        }
        cursor.expect(',', "',' or ']' in an array")?;
    }
}
