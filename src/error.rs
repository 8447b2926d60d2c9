//! The library's error type.
//!
//! Every error says where it applies: text errors carry the origin (file
//! path or `<string>`), line and column; other variants carry the values
//! that were out of range.
//!
//! ```
//! use speclab::{Role, TabulatedSpectrum};
//! let err = TabulatedSpectrum::parse("{380, 1}, {370, 2}", "<string>", Role::Light).unwrap_err();
//! assert_eq!(
//!     err.to_string(),
//!     "<string>:1:11: expected a wavelength greater than 380 nm, found 370 nm"
//! );
//! ```

use std::fmt;
use std::path::PathBuf;

use crate::parse::ParseError;

/// Errors of the public API.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// Text or samples that do not form a valid spectrum.
    Parse(ParseError),
    /// A file that could not be read.
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A scale factor that is not finite and positive (for example the
    /// normalisation of a light with no power in the range).
    Scale {
        /// The factor.
        factor: f64,
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
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Parse(e) => e.fmt(f),
            Error::Io { path, source } => write!(f, "{}: cannot read: {source}", path.display()),
            Error::Scale { factor } => write!(f, "expected a finite positive scale factor, found {factor}"),
            Error::UnsupportedHeroWidth { k } => {
                write!(f, "expected a hero width of 1, 2, 3, 4, 8 or 16 wavelengths, found {k}")
            }
            Error::UnsupportedBuckets { m, max } => {
                write!(f, "expected a bucket count from 1 to {max}, found {m}")
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Parse(e) => Some(e),
            Error::Io { source, .. } => Some(source),
            Error::Scale { .. } | Error::UnsupportedHeroWidth { .. } | Error::UnsupportedBuckets { .. } => {
                None
            }
        }
    }
}

impl From<ParseError> for Error {
    fn from(e: ParseError) -> Self {
        Error::Parse(e)
    }
}
