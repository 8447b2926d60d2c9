//! The assignment's brace notation: `{380, 0.045345}, {385, 0.050435}, ...`.
//!
//! A text is a comma-separated list of *tuples*, each a comma-separated list
//! of numbers in braces. Spectra are tuples of two numbers (wavelength in
//! nanometres, value); the XYZ→sRGB matrix is three tuples of three numbers.
//! Whitespace and line breaks are free, and `#` starts a comment that runs to
//! the end of the line.
//!
//! This file has no dependencies beyond `std`: `build.rs` includes it with
//! `#[path]`, so the build-time data and the run-time loader share one parser.
//!
//! ```
//! use speclab::parse::parse_samples;
//! let s = parse_samples("{380, 0.5}, {390, 0.25}", "<string>").unwrap();
//! assert_eq!(s.lambda, vec![380.0, 390.0]);
//! assert_eq!(s.values, vec![0.5, 0.25]);
//! ```

use std::fmt;

/// A place in a text: 1-based line and column (columns count characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Position {
    /// 1-based line number.
    pub line: usize,
    /// 1-based column number, in characters.
    pub column: usize,
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
    /// A wavelength not greater than the one before it.
    NotIncreasing {
        /// The previous wavelength.
        previous: f64,
        /// This wavelength.
        found: f64,
    },
    /// A table that must have an exact number of tuples has another.
    Count {
        /// Tuples found.
        found: usize,
        /// Tuples expected.
        expected: usize,
    },
    /// A wavelength outside the plausible range of nanometres.
    Wavelength {
        /// The wavelength as read.
        found: f64,
    },
    /// A light with negative power.
    NegativePower {
        /// The value as read.
        value: f64,
    },
    /// A value outside the range its role allows.
    OutOfRange {
        /// The value as read.
        value: f64,
        /// Smallest allowed value.
        min: f64,
        /// Largest allowed value.
        max: f64,
    },
    /// A spectrum that does not cover the integration range.
    Support {
        /// First and last wavelength found, nm.
        found: [f64; 2],
        /// The range it must cover, nm.
        required: [f64; 2],
    },
    /// Fewer tuples than needed.
    TooFew {
        /// Tuples found.
        found: usize,
        /// Tuples needed.
        needed: usize,
    },
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
        write!(f, "{}:{line}:{column}: ", self.origin)?;
        match &self.kind {
            ParseErrorKind::Unexpected { found, expected } => {
                write!(f, "expected {expected}, found {found:?}")
            }
            ParseErrorKind::Missing { expected } => write!(f, "expected {expected}, found nothing"),
            ParseErrorKind::Key { found, expected } => write!(f, "expected {expected}, found {found:?}"),
            ParseErrorKind::UnexpectedEnd { expected } => {
                write!(f, "expected {expected}, found end of text")
            }
            ParseErrorKind::BadNumber { text } => write!(f, "expected a number, found {text:?}"),
            ParseErrorKind::NonFinite { text } => {
                write!(f, "expected a finite number, found {text:?}")
            }
            ParseErrorKind::Arity { found, expected } => {
                write!(f, "expected {expected} numbers per entry, found {found}")
            }
            ParseErrorKind::NotIncreasing { previous, found } => {
                write!(f, "expected a wavelength greater than {previous} nm, found {found} nm")
            }
            ParseErrorKind::Count { found, expected } => {
                write!(f, "expected {expected} entries, found {found}")
            }
            ParseErrorKind::Wavelength { found } => write!(
                f,
                "expected a wavelength in nanometres (100 to 10000), found {found} \
                 (micrometres? multiply by 1000)"
            ),
            ParseErrorKind::NegativePower { value } => {
                write!(f, "expected a non-negative light power, found {value}")
            }
            ParseErrorKind::OutOfRange { value, min, max } if max.is_finite() => {
                write!(f, "expected a value in [{min}, {max}], found {value}")
            }
            ParseErrorKind::OutOfRange { value, min, .. } => {
                write!(f, "expected a value of at least {min}, found {value}")
            }
            ParseErrorKind::Support { found, required } => write!(
                f,
                "expected samples covering {}-{} nm, found {}-{} nm",
                required[0], required[1], found[0], found[1]
            ),
            ParseErrorKind::TooFew { found, needed } => {
                write!(f, "expected at least {needed} samples, found {found}")
            }
        }
    }
}

impl std::error::Error for ParseError {}

/// One tuple of a text, with the position of its opening brace.
#[derive(Clone, Debug, PartialEq)]
pub struct Tuple<const N: usize> {
    /// The numbers, in order.
    pub numbers: [f64; N],
    /// Where the tuple starts.
    pub position: Position,
    /// Where each number starts.
    pub number_positions: [Position; N],
}

/// Tabulated samples read from a text: strictly increasing, finite.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Samples {
    /// Wavelengths in nanometres, strictly increasing.
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

/// Reads `{λ, v}` pairs and checks that every number is finite and the
/// wavelengths strictly increase.
pub fn parse_samples(text: &str, origin: &str) -> Result<Samples, ParseError> {
    let mut samples = Samples::default();
    for tuple in parse_tuples::<2>(text, origin)? {
        let [lambda, value] = tuple.numbers;
        if let Some(&previous) = samples.lambda.last()
            && lambda <= previous
        {
            let kind = ParseErrorKind::NotIncreasing { previous, found: lambda };
            return Err(ParseError { origin: origin.to_string(), position: tuple.position, kind });
        }
        samples.push(lambda, value, tuple.position, tuple.number_positions[1]);
    }
    Ok(samples)
}

/// Reads a comma-separated list of tuples of exactly `N` finite numbers.
pub fn parse_tuples<const N: usize>(text: &str, origin: &str) -> Result<Vec<Tuple<N>>, ParseError> {
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
        tuples.push(cursor.tuple::<N>()?);
    }
}

/// Reads one number token as written (`text`), with the error it deserves.
pub fn number(text: &str, origin: &str, position: Position) -> Result<f64, ParseError> {
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
        let position = Position { line: 1, column: 1 };
        Cursor { chars: text.chars().peekable(), origin, position }
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

    fn tuple<const N: usize>(&mut self) -> Result<Tuple<N>, ParseError> {
        let position = self.position;
        self.expect('{', "'{' opening a tuple")?;
        let mut numbers = [0.0; N];
        let mut number_positions = [position; N];
        let mut found = 0;
        loop {
            self.skip_blank();
            let at = self.position;
            let number = self.number()?;
            if found < N {
                numbers[found] = number;
                number_positions[found] = at;
            }
            found += 1;
            self.skip_blank();
            match self.peek() {
                Some(',') => {
                    self.bump();
                }
                Some('}') => {
                    self.bump();
                    break;
                }
                Some(c) => {
                    let kind = ParseErrorKind::Unexpected { found: c, expected: "',' or '}'" };
                    return Err(self.error(self.position, kind));
                }
                None => {
                    let kind = ParseErrorKind::UnexpectedEnd { expected: "'}' closing a tuple" };
                    return Err(self.error(self.position, kind));
                }
            }
        }
        if found != N {
            return Err(self.error(position, ParseErrorKind::Arity { found, expected: N }));
        }
        Ok(Tuple { numbers, position, number_positions })
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
