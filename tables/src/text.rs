//! The text toolkit that every input format shares: the samples a text
//! yields, with where each was written, and a character cursor that tracks
//! lines and columns and skips blanks and `#` comments.
//!
//! Formats live beside this file: [`crate::brace`] (the assignment's
//! notation), [`crate::columns`] (CSV, TSV, whitespace) and [`crate::json`].
//! A new format reads its text with the crate's `Cursor` or line by line,
//! reports every problem as a [`ParseError`] at a [`Position`], and returns
//! [`Samples`]; [`crate::read`] then validates them the same way for every
//! format.
//!
//! ```
//! use speclab_tables::text::Samples;
//! use speclab_tables::error::Position;
//! let mut s = Samples::default();
//! s.push(380.0, 0.5, Position::START, Position { line: 1, column: 6 });
//! assert_eq!((s.lambda[0], s.value_positions[0].column), (380.0, 6));
//! ```

use crate::error::{ParseError, ParseErrorKind, Position};

/// Tabulated samples read from a text, with where each was written. Not
/// yet validated: see [`super::read`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Samples {
    /// Wavelengths in nanometres.
    pub lambda: Vec<f64>,
    /// The value at each wavelength.
    pub values: Vec<f64>,
    /// Where each sample (its wavelength) was written.
    pub positions: Vec<Position>,
    /// Where each value was written.
    pub value_positions: Vec<Position>,
}

impl Samples {
    /// Appends one sample.
    pub fn push(&mut self, lambda: f64, value: f64, at: Position, value_at: Position) {
        self.lambda.push(lambda);
        self.values.push(value);
        self.positions.push(at);
        self.value_positions.push(value_at);
    }
}

/// Reads one number token as written (`text`), with the error it deserves.
pub(crate) fn number(text: &str, origin: &str, position: Position) -> Result<f64, ParseError> {
    let error = |kind| ParseError { origin: origin.to_string(), position, kind };
    if text.is_empty() {
        return Err(error(ParseErrorKind::Missing { expected: "a number" }));
    }
    match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(error(ParseErrorKind::NonFinite { text: text.to_string() })),
        Err(_) => Err(error(ParseErrorKind::BadNumber { text: text.to_string() })),
    }
}

/// A character cursor that tracks lines and columns.
pub(crate) struct Cursor<'a> {
    chars: std::iter::Peekable<std::str::Chars<'a>>,
    origin: &'a str,
    pub(crate) position: Position,
}

impl<'a> Cursor<'a> {
    pub(crate) fn new(text: &'a str, origin: &'a str) -> Self {
        Cursor { chars: text.chars().peekable(), origin, position: Position::START }
    }

    pub(crate) fn peek(&mut self) -> Option<char> {
        self.chars.peek().copied()
    }

    pub(crate) fn bump(&mut self) -> Option<char> {
        let c = self.chars.next()?;
        if c == '\n' {
            self.position.line += 1;
            self.position.column = 1;
        } else {
            self.position.column += 1;
        }
        Some(c)
    }

    /// Skips whitespace and `#` comments.
    pub(crate) fn skip_blank(&mut self) {
        while let Some(c) = self.peek() {
            if c == '#' {
                while self.peek().is_some_and(|c| c != '\n') {
                    self.bump();
                }
            } else if c.is_whitespace() {
                self.bump();
            } else {
                return;
            }
        }
    }

    pub(crate) fn error(&self, position: Position, kind: ParseErrorKind) -> ParseError {
        ParseError { origin: self.origin.to_string(), position, kind }
    }

    pub(crate) fn expect(&mut self, wanted: char, expected: &'static str) -> Result<(), ParseError> {
        match self.peek() {
            Some(c) if c == wanted => {
                self.bump();
                Ok(())
            }
            Some(found) => Err(self.error(self.position, ParseErrorKind::Unexpected { found, expected })),
            None => Err(self.error(self.position, ParseErrorKind::UnexpectedEnd { expected })),
        }
    }

    pub(crate) fn number(&mut self) -> Result<f64, ParseError> {
        let position = self.position;
        let mut text = String::new();
        while let Some(c) = self.peek().filter(|c| c.is_ascii_alphanumeric() || "+-.".contains(*c)) {
            text.push(c);
            self.bump();
        }
        if text.is_empty() {
            return Err(match self.peek() {
                Some(found) => {
                    self.error(position, ParseErrorKind::Unexpected { found, expected: "a number" })
                }
                None => self.error(position, ParseErrorKind::UnexpectedEnd { expected: "a number" }),
            });
        }
        number(&text, self.origin, position)
    }
}
