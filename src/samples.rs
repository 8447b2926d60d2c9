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
//! assert_eq!(err.to_string(), "patch.txt:1:13: expected a value in [0, 1], found 1.5");
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

/// Checks samples; on failure gives the index of the offending sample.
pub fn validate(
    lambda: &[f64],
    values: &[f64],
    role: Role,
    interpolation: Interpolation,
) -> Result<(), (usize, ParseErrorKind)> {
    if lambda.len() != values.len() {
        let kind = ParseErrorKind::Count { found: values.len(), expected: lambda.len() };
        return Err((lambda.len().min(values.len()), kind));
    }
    for (i, (&x, &y)) in lambda.iter().zip(values).enumerate() {
        check_sample(x, y, role).map_err(|kind| (i, kind))?;
        if i > 0 && x <= lambda[i - 1] {
            return Err((i, ParseErrorKind::NotIncreasing { previous: lambda[i - 1], found: x }));
        }
    }
    let needed = interpolation.min_samples();
    if lambda.len() < needed {
        let kind = ParseErrorKind::TooFew { found: lambda.len(), needed };
        return Err((lambda.len().saturating_sub(1), kind));
    }
    Ok(())
}

fn check_sample(x: f64, y: f64, role: Role) -> Result<(), ParseErrorKind> {
    if !x.is_finite() || !y.is_finite() {
        let text = if x.is_finite() { y } else { x }.to_string();
        return Err(ParseErrorKind::NonFinite { text });
    }
    if !(PLAUSIBLE_NM[0]..=PLAUSIBLE_NM[1]).contains(&x) {
        return Err(ParseErrorKind::Wavelength { found: x });
    }
    let [min, max] = role.bounds();
    if role == Role::Light && y < 0.0 {
        return Err(ParseErrorKind::NegativePower { value: y });
    }
    if !(min..=max).contains(&y) {
        return Err(ParseErrorKind::OutOfRange { value: y, min, max });
    }
    Ok(())
}

/// Brace-notation text to validated samples, with errors at the place
/// they apply (the sample's opening brace).
pub fn read_brace(text: &str, origin: &str, role: Role) -> Result<Samples, ParseError> {
    let samples = parse_samples(text, origin)?;
    locate(samples, origin, role, role.interpolation())
}

/// Validates parsed samples, turning a sample index into its position.
pub fn locate(
    samples: Samples,
    origin: &str,
    role: Role,
    interpolation: Interpolation,
) -> Result<Samples, ParseError> {
    match validate(&samples.lambda, &samples.values, role, interpolation) {
        Ok(()) => Ok(samples),
        Err((index, kind)) => {
            let start = Position { line: 1, column: 1 };
            let position = samples.positions.get(index).copied().unwrap_or(start);
            Err(ParseError { origin: origin.to_string(), position, kind })
        }
    }
}
