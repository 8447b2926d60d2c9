//! What makes samples a valid spectrum, checked the same way at build time
//! (`build.rs` includes this file) and at run time.
//!
//! Samples are valid when every number is finite, wavelengths are plausible
//! nanometres (`100 ≤ λ ≤ 10000`: a table in micrometres is an error, not a
//! colour shifted out of the visible range) and strictly increasing, there
//! are enough samples for the interpolation, and every value fits its
//! [`Role`]: light power is non-negative, a reflectance lies in `[0, 1]`, a
//! matching function is non-negative.
//!
//! ```
//! use speclab::samples::{read_brace, Role};
//! let err = read_brace("{380, 0.5}, {390, 1.5}, {400, 0.1}, {410, 0.2}", "patch.txt", Role::Reflectance)
//!     .unwrap_err();
//! assert_eq!(err.to_string(), "patch.txt:1:19: expected a value in [0, 1], found 1.5");
//! ```

use crate::parse::{ParseError, ParseErrorKind, Position, Samples, parse_samples};

/// The plausible range of wavelengths in nanometres.
pub const PLAUSIBLE_NM: [f64; 2] = [100.0, 10_000.0];

/// How a table is interpolated between its samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Interpolation {
    /// Straight lines between samples; keeps spikes (F11) as tabulated.
    Linear,
    /// The cubic through the four nearest samples; smooth curves.
    Cubic,
}

impl Interpolation {
    /// The fewest samples this interpolation can use.
    pub const fn min_samples(self) -> usize {
        match self {
            Interpolation::Linear => 2,
            Interpolation::Cubic => 4,
        }
    }
}

/// What a spectrum is; sets its default interpolation and its value bounds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Role {
    /// Spectral power of a light, any non-negative scale. Linear, `≥ 0`.
    Light,
    /// Reflectance of a surface. Cubic, clamped to `[0, 1]`.
    Reflectance,
    /// A colour matching function. Cubic, clamped to `≥ 0`.
    Observer,
}

impl Role {
    /// The interpolation the assignment's reference uses for this role.
    pub const fn interpolation(self) -> Interpolation {
        match self {
            Role::Light => Interpolation::Linear,
            Role::Reflectance | Role::Observer => Interpolation::Cubic,
        }
    }

    /// The range of valid values, and the interval that interpolated values
    /// are clamped to.
    pub const fn bounds(self) -> [f64; 2] {
        match self {
            Role::Light | Role::Observer => [0.0, f64::INFINITY],
            Role::Reflectance => [0.0, 1.0],
        }
    }
}

/// Which sample is invalid, whether the fault is its value (rather than its
/// wavelength), and what is wrong.
#[derive(Clone, Debug, PartialEq)]
pub struct Invalid {
    /// Index of the sample.
    pub index: usize,
    /// True if the value is at fault, false for the wavelength.
    pub on_value: bool,
    /// What is wrong.
    pub kind: ParseErrorKind,
}

/// Checks samples for `role` and `interpolation`.
pub fn validate(
    lambda: &[f64],
    values: &[f64],
    role: Role,
    interpolation: Interpolation,
) -> Result<(), Invalid> {
    let invalid = |index, on_value, kind| Err(Invalid { index, on_value, kind });
    if lambda.len() != values.len() {
        let kind = ParseErrorKind::Count { found: values.len(), expected: lambda.len() };
        return invalid(lambda.len().min(values.len()), true, kind);
    }
    for (i, (&x, &y)) in lambda.iter().zip(values).enumerate() {
        if !x.is_finite() {
            return invalid(i, false, ParseErrorKind::NonFinite { text: x.to_string() });
        }
        if !(PLAUSIBLE_NM[0]..=PLAUSIBLE_NM[1]).contains(&x) {
            return invalid(i, false, ParseErrorKind::Wavelength { found: x });
        }
        if i > 0 && x <= lambda[i - 1] {
            return invalid(i, false, ParseErrorKind::NotIncreasing { previous: lambda[i - 1], found: x });
        }
        if let Err(kind) = check_value(y, role) {
            return invalid(i, true, kind);
        }
    }
    let needed = interpolation.min_samples();
    if lambda.len() < needed {
        let kind = ParseErrorKind::TooFew { found: lambda.len(), needed };
        return invalid(lambda.len().saturating_sub(1), false, kind);
    }
    Ok(())
}

fn check_value(y: f64, role: Role) -> Result<(), ParseErrorKind> {
    let [min, max] = role.bounds();
    if !y.is_finite() {
        Err(ParseErrorKind::NonFinite { text: y.to_string() })
    } else if role == Role::Light && y < 0.0 {
        Err(ParseErrorKind::NegativePower { value: y })
    } else if !(min..=max).contains(&y) {
        Err(ParseErrorKind::OutOfRange { value: y, min, max })
    } else {
        Ok(())
    }
}

/// Brace-notation text to validated samples, with errors at the place
/// they apply.
pub fn read_brace(text: &str, origin: &str, role: Role) -> Result<Samples, ParseError> {
    let samples = parse_samples(text, origin)?;
    locate(samples, origin, role, role.interpolation())
}

/// Validates parsed samples, turning an [`Invalid`] into a position.
pub fn locate(
    samples: Samples,
    origin: &str,
    role: Role,
    interpolation: Interpolation,
) -> Result<Samples, ParseError> {
    match validate(&samples.lambda, &samples.values, role, interpolation) {
        Ok(()) => Ok(samples),
        Err(Invalid { index, on_value, kind }) => {
            let at = if on_value { &samples.value_positions } else { &samples.positions };
            let position = at.get(index).copied().unwrap_or(Position { line: 1, column: 1 });
            Err(ParseError { origin: origin.to_string(), position, kind })
        }
    }
}
