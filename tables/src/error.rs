//! Errors that name their place: text errors carry the origin (a file path
//! or `<string>`), line and column; reading errors the file; and the
//! crate's [`Error`] gathers them for [`crate::Codegen`].
//!
//! Messages read `origin:line:column: expected …, found …`.
//!
//! ```
//! use speclab_tables::error::{ParseError, ParseErrorKind, Position};
//! let e = ParseError {
//!     origin: "lamp.txt".into(),
//!     position: Position { line: 3, column: 7 },
//!     kind: ParseErrorKind::BadNumber { text: "0.0l76".into() },
//! };
//! assert_eq!(e.to_string(), "lamp.txt:3:7: expected a number, found \"0.0l76\"");
//! ```

use std::fmt;
use std::path::PathBuf;

use crate::validate::Invalid;

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
    /// A wavelength off the table's uniform step.
    Step {
        /// The wavelength found, nm.
        found: f64,
        /// The wavelength the step asks for, nm.
        expected: f64,
    },
    /// A negative value where only non-negative ones belong.
    Negative {
        /// The token as written.
        text: String,
    },
    /// Well-formed text whose samples are not a valid spectrum (see
    /// [`crate::validate`]).
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
            ParseErrorKind::Step { found, expected } => {
                write!(f, "expected the wavelength {expected} nm (a uniform step), found {found}")
            }
            ParseErrorKind::Negative { text } => write!(f, "expected a non-negative value, found {text}"),
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

/// A file or stream that could not be read as text (speclab's
/// `Error::Read` carries it as it is).
#[derive(Debug)]
pub enum ReadError {
    /// The file or stream failed, or is not UTF-8 text.
    Io {
        /// The file (or the stream's name).
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A file or stream larger than the reading limit.
    TooLarge {
        /// The file or stream.
        origin: String,
        /// The limit, bytes.
        limit: u64,
    },
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io { path, source } => write!(f, "{}: cannot read: {source}", path.display()),
            ReadError::TooLarge { origin, limit } => {
                write!(f, "{origin}: expected at most {limit} bytes ({} MiB), found more", limit >> 20)
            }
        }
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReadError::Io { source, .. } => Some(source),
            ReadError::TooLarge { .. } => None,
        }
    }
}

/// What [`crate::Codegen`] can fail with.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// A file that does not form a valid spectrum, located by line and column.
    Parse(ParseError),
    /// A file that could not be read.
    Read(ReadError),
    /// A name for generated code that is not a Rust identifier.
    Identifier {
        /// The name given.
        name: String,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Parse(e) => e.fmt(f),
            Error::Read(e) => e.fmt(f),
            Error::Identifier { name } => write!(f, "expected a Rust identifier, found {name:?}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Parse(e) => Some(e),
            Error::Read(e) => Some(e),
            Error::Identifier { .. } => None,
        }
    }
}

impl From<ParseError> for Error {
    fn from(e: ParseError) -> Self {
        Error::Parse(e)
    }
}

impl From<ReadError> for Error {
    fn from(e: ReadError) -> Self {
        Error::Read(e)
    }
}
