//! The assignment's brace notation: `{380, 0.045345}, {385, 0.050435}, ...`.
//!
//! A text is a comma-separated list of *tuples*, each a comma-separated list
//! of numbers in braces. Spectra are tuples of two numbers (wavelength in
//! nanometres, value); the XYZ→sRGB matrix is three tuples of three numbers.
//! Whitespace and line breaks are free, and `#` starts a comment that runs to
//! the end of the line. Every number must be finite; whether the samples
//! make a spectrum is checked afterwards, by [`crate::read`].
//!
//! ```
//! use speclab_tables::brace::parse_samples;
//! let s = parse_samples("{380, 0.5}, {390, 0.25}", "<string>").unwrap();
//! assert_eq!(s.lambda, vec![380.0, 390.0]);
//! assert_eq!(s.values, vec![0.5, 0.25]);
//! ```

use crate::error::{ParseError, ParseErrorKind, Position};
use crate::text::{Cursor, Samples};

/// One tuple of a text, with the position of its opening brace.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Tuple<const N: usize> {
    /// The numbers, in order.
    pub(crate) numbers: [f64; N],
    /// Where the tuple starts.
    pub(crate) position: Position,
    /// Where each number starts.
    pub(crate) number_positions: [Position; N],
}

/// Reads `{λ, v}` pairs of finite numbers.
pub fn parse_samples(text: &str, origin: &str) -> Result<Samples, ParseError> {
    let mut samples = Samples::default();
    for tuple in parse_tuples::<2>(text, origin)? {
        let [lambda, value] = tuple.numbers;
        samples.push(lambda, value, tuple.position, tuple.number_positions[1]);
    }
    Ok(samples)
}

/// Reads a list of exactly `rows` tuples of `N` finite numbers each (a
/// matrix, for example); any other count is an error at the last tuple.
pub fn parse_rows<const N: usize>(
    text: &str,
    origin: &str,
    rows: usize,
) -> Result<Vec<[f64; N]>, ParseError> {
    let tuples = parse_tuples::<N>(text, origin)?;
    if tuples.len() != rows {
        let position = tuples.last().map_or(Position::START, |t| t.position);
        let kind = ParseErrorKind::Count { found: tuples.len(), expected: rows };
        return Err(ParseError { origin: origin.to_string(), position, kind });
    }
    Ok(tuples.into_iter().map(|t| t.numbers).collect())
}

/// Reads a comma-separated list of tuples of exactly `N` finite numbers.
pub(crate) fn parse_tuples<const N: usize>(text: &str, origin: &str) -> Result<Vec<Tuple<N>>, ParseError> {
    let mut cursor = Cursor::new(text, origin);
    let mut tuples = Vec::new();
    loop {
        cursor.skip_blank();
        if cursor.peek().is_none() {
            return Ok(tuples);
        }
        if !tuples.is_empty() {
            cursor.expect(',', "',' between tuples")?;
            cursor.skip_blank();
        }
        tuples.push(tuple::<N>(&mut cursor)?);
    }
}

/// One `{n, n, ...}` with exactly `N` numbers.
fn tuple<const N: usize>(cursor: &mut Cursor) -> Result<Tuple<N>, ParseError> {
    let position = cursor.position;
    cursor.expect('{', "'{' opening a tuple")?;
    let mut numbers = [0.0; N];
    let mut number_positions = [position; N];
    let mut found = 0;
    loop {
        cursor.skip_blank();
        let at = cursor.position;
        let number = cursor.number()?;
        if found < N {
            numbers[found] = number;
            number_positions[found] = at;
        }
        found += 1;
        cursor.skip_blank();
        match cursor.peek() {
            Some(',') => {
                cursor.bump();
            }
            Some('}') => {
                cursor.bump();
                break;
            }
            Some(c) => {
                let kind = ParseErrorKind::Unexpected { found: c, expected: "',' or '}'" };
                return Err(cursor.error(cursor.position, kind));
            }
            None => {
                let kind = ParseErrorKind::UnexpectedEnd { expected: "'}' closing a tuple" };
                return Err(cursor.error(cursor.position, kind));
            }
        }
    }
    if found != N {
        return Err(cursor.error(position, ParseErrorKind::Arity { found, expected: N }));
    }
    Ok(Tuple { numbers, position, number_positions })
}
