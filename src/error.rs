//! The library's error type.
//!
//! Every error says where it applies: text errors carry the origin (file
//! path or `<string>`), line and column; errors in in-memory samples carry
//! the index and the field; other variants carry the values that were out of
//! range. This file depends on `std` only: `build.rs` includes it.
//!
//! ```
//! use speclab::{Role, TabulatedSpectrum};
//! let err = TabulatedSpectrum::parse("{380, 1}, {370, 2}", "<string>", Role::Light).unwrap_err();
//! assert_eq!(err.to_string(), "<string>:1:11: expected a wavelength greater than 380 nm, found 370 nm");
//! let err = TabulatedSpectrum::new(vec![380.0, 370.0], vec![1.0, 2.0], Role::Light).unwrap_err();
//! assert_eq!(err.to_string(), "lambda[1]: expected a wavelength greater than 380 nm, found 370 nm");
//! ```

use std::fmt;
use std::path::PathBuf;

use crate::io::text::ParseError;
use crate::spectrum::validate::SampleError;

/// Errors of the public API.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// Text that does not form a valid spectrum, located by line and column.
    Parse(ParseError),
    /// In-memory samples that do not form a valid spectrum, located by index.
    Sample(SampleError),
    /// A file or stream that could not be read.
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
    /// A scale factor that is not finite and positive (for example the
    /// normalisation of a light with no power in the range).
    Scale {
        /// The factor.
        factor: f64,
    },
    /// A wavelength or pdf handed to a sample that cannot be used.
    SampleWavelength {
        /// Which wavelength of the sample.
        index: usize,
        /// The wavelength, nm.
        lambda: f64,
        /// Its pdf, 1/nm.
        pdf: f64,
    },
    /// A hero width with no compiled instance of `HeroSample<K>`.
    UnsupportedHeroWidth {
        /// The width asked for.
        k: usize,
    },
    /// A bucket count with no compiled instance of `RegularSpectrum<M>`.
    UnsupportedBuckets {
        /// The count asked for.
        m: usize,
        /// The largest compiled count (the smallest is 1).
        max: usize,
    },
    /// A built-in spectrum name that does not exist.
    UnknownSpectrum {
        /// The name asked for.
        name: String,
        /// The names that exist.
        expected: &'static str,
    },
    /// A scene with no light or no surface.
    EmptyScene,
    /// A ΔE00 budget that is not finite and positive.
    Budget {
        /// The budget given.
        value: f64,
    },
    /// A light with no power where the observer sees, within 380–730 nm: no
    /// wavelength pdf can follow it.
    DarkLight,
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
            Error::Sample(e) => e.fmt(f),
            Error::Io { path, source } => write!(f, "{}: cannot read: {source}", path.display()),
            Error::TooLarge { origin, limit } => {
                write!(f, "{origin}: expected at most {limit} bytes ({} MiB), found more", limit >> 20)
            }
            Error::Scale { factor } => write!(f, "expected a finite positive scale factor, found {factor}"),
            Error::SampleWavelength { index, lambda, pdf } => write!(
                f,
                "wavelength {index}: expected a finite wavelength with a finite non-negative pdf, \
                 found {lambda} nm with pdf {pdf}"
            ),
            Error::UnsupportedHeroWidth { k } => {
                write!(f, "expected a hero width of 1, 2, 3, 4, 8 or 16 wavelengths, found {k}")
            }
            Error::UnsupportedBuckets { m, max } => {
                write!(f, "expected a bucket count from 1 to {max}, found {m}")
            }
            Error::UnknownSpectrum { name, expected } => write!(f, "expected {expected}, found {name:?}"),
            Error::Identifier { name } => write!(f, "expected a Rust identifier, found {name:?}"),
            Error::EmptyScene => {
                write!(f, "expected a scene of at least one light and one surface, found none")
            }
            Error::Budget { value } => write!(f, "expected a finite positive ΔE00 budget, found {value}"),
            Error::DarkLight => {
                write!(f, "expected a light with power where the observer sees (380-730 nm), found none")
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Parse(e) => Some(e),
            Error::Sample(e) => Some(e),
            Error::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<ParseError> for Error {
    fn from(e: ParseError) -> Self {
        Error::Parse(e)
    }
}

impl From<SampleError> for Error {
    fn from(e: SampleError) -> Self {
        Error::Sample(e)
    }
}
