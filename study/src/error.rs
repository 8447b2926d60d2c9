//! The study's error type: everything the library below can fail with,
//! plus what only a study asks (an empty scene, a budget).
//!
//! ```
//! use speclab_study::{planning::plan::{self, Request}, evaluate::scene, StudyError};
//! let err = plan::plan(&[], &scene::builtin_surfaces(), &Request::default()).unwrap_err();
//! assert!(matches!(err, StudyError::EmptyScene));
//! assert_eq!(err.to_string(), "expected a scene of at least one light and one surface, found none");
//! ```

use std::fmt;

use speclab::error::Error;

/// Errors of the study: the library's [`Error`], or a request the study
/// cannot meet.
#[derive(Debug)]
#[non_exhaustive]
pub enum StudyError {
    /// An error of the library below (a file that fails to load, a bucket
    /// count, a light no pdf can follow, …).
    Spectra(Error),
    /// A scene with no light or no surface.
    EmptyScene,
    /// A ΔE00 budget that is not finite and positive.
    Budget {
        /// The budget given.
        value: f64,
    },
    /// A published rule that does not exist for the light: a Gauss rule of
    /// more points than the light's weight has support, or a Borges rule
    /// whose shared nodes are not real and inside 380–730 nm.
    NoRule {
        /// The family's name, e.g. `borges`.
        family: String,
        /// The wavelengths asked for.
        m: usize,
    },
    /// Rules of a fitted way that do not share their wavelengths (each
    /// light's rule must be made at the same wavelengths, as
    /// `Rule::fit_each` makes them): the rule at `index` differs from the
    /// first.
    RulesDiffer {
        /// Which rule.
        index: usize,
    },
    /// A path depth outside 1 ..= `max`.
    Depth {
        /// What was given.
        found: String,
        /// The deepest path studied.
        max: usize,
    },
}

impl fmt::Display for StudyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StudyError::Spectra(e) => e.fmt(f),
            StudyError::EmptyScene => {
                write!(f, "expected a scene of at least one light and one surface, found none")
            }
            StudyError::Budget { value } => {
                write!(f, "expected a finite positive ΔE00 budget, found {value}")
            }
            StudyError::NoRule { family, m } => write!(
                f,
                "expected a light with a {family} rule of {m} wavelengths, found none (no real nodes inside 380–730 nm)"
            ),
            StudyError::RulesDiffer { index } => write!(
                f,
                "expected rules at one set of wavelengths (as Rule::fit_each makes them), found rule {index} at others"
            ),
            StudyError::Depth { found, max } => {
                write!(f, "expected a path depth from 1 to {max}, found {found:?}")
            }
        }
    }
}

impl std::error::Error for StudyError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            StudyError::Spectra(e) => Some(e),
            _ => None,
        }
    }
}

impl From<Error> for StudyError {
    fn from(e: Error) -> Self {
        StudyError::Spectra(e)
    }
}
