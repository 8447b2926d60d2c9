//! The text toolkit that every input format shares: positions (line and
//! column), the error type, the samples a text yields, and a character
//! cursor that skips blanks and `#` comments.
//!
//! Formats live beside this file: [`super::brace`] (the assignment's
//! notation), [`super::columns`] (CSV, TSV, whitespace) and [`super::json`].
//! A new format reads its text with the crate's `Cursor` or line by line, reports
//! every problem as a [`ParseError`] at a [`Position`], and returns
//! [`Samples`]; [`super::read`] then validates them the same way for every
//! format.
//!
//! This file depends on `std` only: `build.rs` includes it with `#[path]`.
//!
//! ```
//! use speclab::io::text::{ParseError, ParseErrorKind, Position};
//! let e = ParseError {
//!     origin: "lamp.txt".into(),
//!     position: Position { line: 3, column: 7 },
//!     kind: ParseErrorKind::BadNumber { text: "0.0l76".into() },
//! };
//! assert_eq!(e.to_string(), "lamp.txt:3:7: expected a number, found \"0.0l76\"");
//! ```

use std::fmt;

use crate::spectrum::validate::Invalid;

/// A place in a text: 1-based line and column (columns count characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Position {
    /// 1-based line number.
    pub line: usize,
    /// 1-based column number, in characters.
    pub column: usize,
}

impl Position {
    /// Line 1, column 1.
    pub const START: Position = Position { line: 1, column: 1 };
}

/// What went wrong while reading a text.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ParseErrorKind {
    /// A character that does not fit the grammar at this place.
    Unexpected {
        /// The character found.
        found: char,
        /// What the grammar expected instead.
        expected: &'static str,
    },
    /// An empty field where a number belongs.
    Missing {
        /// What was expected.
        expected: &'static str,
    },
    /// A key that the format does not have.
    Key {
        /// The key as written.
        found: String,
        /// The keys expected.
        expected: &'static str,
    },
    /// The text ended early.
    UnexpectedEnd {
        /// What the grammar expected instead.
        expected: &'static str,
    },
    /// A token that is not a number.
    BadNumber {
        /// The token as written.
        text: String,
    },
    /// A number that is NaN or infinite (for example `1e999`).
    NonFinite {
        /// The token as written.
        text: String,
    },
    /// A tuple with the wrong number of entries.
    Arity {
        /// Entries found.
        found: usize,
        /// Entries expected.
        expected: usize,
    },
    /// A table that must have an exact number of entries has another.
    Count {
        /// Entries found.
        found: usize,
        /// Entries expected.
        expected: usize,
    },
    /// Well-formed text whose samples are not a valid spectrum (see
    /// [`crate::spectrum::validate`]).
    Invalid(Invalid),
}

impl fmt::Display for ParseErrorKind {
    /// `expected …, found …`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParseErrorKind::Unexpected { found, expected } => {
                write!(f, "expected {expected}, found {found:?}")
            }
            ParseErrorKind::Missing { expected } => write!(f, "expected {expected}, found nothing"),
            ParseErrorKind::Key { found, expected } => write!(f, "expected {expected}, found {found:?}"),
            ParseErrorKind::UnexpectedEnd { expected } => write!(f, "expected {expected}, found end of text"),
            ParseErrorKind::BadNumber { text } => write!(f, "expected a number, found {text:?}"),
            ParseErrorKind::NonFinite { text } => write!(f, "expected a finite number, found {text:?}"),
            ParseErrorKind::Arity { found, expected } => {
                write!(f, "expected {expected} numbers per entry, found {found}")
            }
            ParseErrorKind::Count { found, expected } => {
                write!(f, "expected {expected} entries, found {found}")
            }
            ParseErrorKind::Invalid(problem) => problem.fmt(f),
        }
    }
}

/// An error in a text, with the place it applies to.
#[derive(Clone, Debug, PartialEq)]
pub struct ParseError {
    /// The text's name: a file path or `<string>`.
    pub origin: String,
    /// Where in the text.
    pub position: Position,
    /// What went wrong.
    pub kind: ParseErrorKind,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Position { line, column } = self.position;
        write!(f, "{}:{line}:{column}: {}", self.origin, self.kind)
    }
}

impl std::error::Error for ParseError {}

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
