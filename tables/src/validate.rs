//! What makes samples a valid spectrum, checked the same way at build time
//! ([`crate::Codegen`]) and at run time (speclab's loading and constructors).
//!
//! Samples are valid when every number is finite, wavelengths are plausible
//! nanometres (`100 ≤ λ ≤ 10000`: a table in micrometres is an error, not a
//! colour shifted out of the visible range) and strictly increasing, there
//! are enough samples for the interpolation, and every value fits its
//! [`Role`]: light power is non-negative, a reflectance lies in `[0, 1]`, a
//! matching function is non-negative, a refractive index is positive, an
//! extinction coefficient non-negative, a basis function any finite
//! number. No value may exceed [`MAX_VALUE`] in
//! magnitude, so that every product, square and sum the library forms from
//! it stays finite.
//!
//! ```
//! use speclab_tables::validate::{validate, Field, Invalid};
//! use speclab_tables::{Interpolation, Role};
//! let err = validate(&[380.0, 390.0], &[0.5, -1.0], Role::Light, Interpolation::Linear).unwrap_err();
//! assert_eq!((err.index, err.field), (1, Field::Value));
//! assert!(matches!(err.problem, Invalid::NegativePower { value } if value == -1.0));
//! assert_eq!(err.to_string(), "values[1]: expected a non-negative light power, found -1");
//! ```

use std::fmt;

/// The plausible range of wavelengths in nanometres.
pub const PLAUSIBLE_NM: [f64; 2] = [100.0, 10_000.0];

/// The largest magnitude a sample value may have. With values up to 1e100,
/// squares (exact variances) stay below 1e200 and every integral, sum of
/// estimates and ratio the library forms stays far from f64's 1.8e308.
pub const MAX_VALUE: f64 = 1e100;

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
    #[must_use]
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
    /// The real part η of a refractive index. Linear, `> 0`.
    Index,
    /// The extinction coefficient k (the imaginary part of a conductor's
    /// refractive index). Linear, `≥ 0`.
    Extinction,
    /// A basis function that a spectrum is a combination of (the CIE
    /// daylight components S₀, S₁, S₂). Linear, any sign.
    Basis,
}

impl Role {
    /// The interpolation the assignment's reference uses for this role.
    #[must_use]
    pub const fn interpolation(self) -> Interpolation {
        match self {
            Role::Light | Role::Index | Role::Extinction | Role::Basis => Interpolation::Linear,
            Role::Reflectance | Role::Observer => Interpolation::Cubic,
        }
    }

    /// The range of valid values, and the interval that interpolated values
    /// are clamped to.
    #[must_use]
    pub const fn bounds(self) -> [f64; 2] {
        match self {
            Role::Light | Role::Observer | Role::Index | Role::Extinction => [0.0, f64::INFINITY],
            Role::Reflectance => [0.0, 1.0],
            Role::Basis => [f64::NEG_INFINITY, f64::INFINITY],
        }
    }
}

/// What is wrong with a sample, or with a table as a whole. Each variant
/// carries what was found; its message says what was expected.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Invalid {
    /// A NaN or infinite number.
    NonFinite {
        /// The number.
        value: f64,
    },
    /// A wavelength outside the plausible range of nanometres.
    Wavelength {
        /// The wavelength.
        found: f64,
    },
    /// A wavelength not greater than the one before it.
    NotIncreasing {
        /// The previous wavelength.
        previous: f64,
        /// This wavelength.
        found: f64,
    },
    /// A light with negative power.
    NegativePower {
        /// The value.
        value: f64,
    },
    /// A refractive index that is not positive.
    NotPositive {
        /// The value.
        value: f64,
    },
    /// A value outside the range its role allows.
    OutOfRange {
        /// The value.
        value: f64,
        /// Smallest allowed value.
        min: f64,
        /// Largest allowed value.
        max: f64,
    },
    /// A value whose magnitude exceeds [`MAX_VALUE`].
    TooLarge {
        /// The value.
        value: f64,
        /// The largest magnitude allowed.
        max: f64,
    },
    /// Fewer samples than the interpolation needs.
    TooFew {
        /// Samples found.
        found: usize,
        /// Samples needed.
        needed: usize,
    },
    /// A different number of values than wavelengths.
    Lengths {
        /// Wavelengths given.
        lambda: usize,
        /// Values given.
        values: usize,
    },
    /// A loaded light with no power within the integration range: every
    /// colour under it is black and every ratio to its white undefined.
    NoPower {
        /// The range it must have power in, nm.
        range: [f64; 2],
    },
    /// A loaded spectrum that does not cover the integration range.
    Support {
        /// First and last wavelength found, nm.
        found: [f64; 2],
        /// The range it must cover, nm.
        required: [f64; 2],
    },
}

impl fmt::Display for Invalid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Invalid::NonFinite { value } => write!(f, "expected a finite number, found {value}"),
            Invalid::Wavelength { found } => write!(
                f,
                "expected a wavelength in nanometres (100 to 10000), found {found} \
                 (micrometres? multiply by 1000)"
            ),
            Invalid::NotIncreasing { previous, found } => {
                write!(f, "expected a wavelength greater than {previous} nm, found {found} nm")
            }
            Invalid::NegativePower { value } => {
                write!(f, "expected a non-negative light power, found {value}")
            }
            Invalid::NotPositive { value } => {
                write!(f, "expected a positive refractive index, found {value}")
            }
            Invalid::OutOfRange { value, min, max } if max.is_finite() => {
                write!(f, "expected a value in [{min}, {max}], found {value}")
            }
            Invalid::OutOfRange { value, min, .. } => {
                write!(f, "expected a value of at least {min}, found {value}")
            }
            Invalid::TooLarge { value, max } => {
                write!(f, "expected a value of magnitude at most {max:e}, found {value:e}")
            }
            Invalid::TooFew { found, needed } => {
                write!(f, "expected at least {needed} samples, found {found}")
            }
            Invalid::Lengths { lambda, values } => {
                write!(f, "expected {lambda} values, one per wavelength, found {values}")
            }
            Invalid::NoPower { range } => {
                write!(f, "expected a light with power within {}-{} nm, found none", range[0], range[1])
            }
            Invalid::Support { found, required } => write!(
                f,
                "expected samples covering {}-{} nm, found {}-{} nm",
                required[0], required[1], found[0], found[1]
            ),
        }
    }
}

/// The part of a sample that is at fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// The wavelength.
    Wavelength,
    /// The value at it.
    Value,
}

/// An invalid sample of an in-memory table: which one, which part, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct SampleError {
    /// Index of the sample (0-based).
    pub index: usize,
    /// Its wavelength or its value.
    pub field: Field,
    /// What is wrong.
    pub problem: Invalid,
}

impl fmt::Display for SampleError {
    /// `values[1]: expected …, found …`, or `lambda: …` for a table-wide
    /// problem (too few samples, lengths that differ).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let array = match self.field {
            Field::Wavelength => "lambda",
            Field::Value => "values",
        };
        match self.problem {
            Invalid::TooFew { .. } | Invalid::Lengths { .. } => write!(f, "{array}: {}", self.problem),
            _ => write!(f, "{array}[{}]: {}", self.index, self.problem),
        }
    }
}

impl std::error::Error for SampleError {}

/// Checks samples for `role` and `interpolation`; the first problem found,
/// in sample order, is the error.
pub fn validate(
    lambda: &[f64],
    values: &[f64],
    role: Role,
    interpolation: Interpolation,
) -> Result<(), SampleError> {
    let invalid = |index, field, problem| Err(SampleError { index, field, problem });
    if lambda.len() != values.len() {
        let problem = Invalid::Lengths { lambda: lambda.len(), values: values.len() };
        return invalid(lambda.len().min(values.len()), Field::Value, problem);
    }
    for (i, (&x, &y)) in lambda.iter().zip(values).enumerate() {
        if let Err(problem) = check_wavelength(x, i.checked_sub(1).map(|p| lambda[p])) {
            return invalid(i, Field::Wavelength, problem);
        }
        if let Err(problem) = check_value(y, role) {
            return invalid(i, Field::Value, problem);
        }
    }
    let needed = interpolation.min_samples();
    if lambda.len() < needed {
        let problem = Invalid::TooFew { found: lambda.len(), needed };
        return invalid(lambda.len().saturating_sub(1), Field::Wavelength, problem);
    }
    Ok(())
}

fn check_wavelength(x: f64, previous: Option<f64>) -> Result<(), Invalid> {
    if !x.is_finite() {
        Err(Invalid::NonFinite { value: x })
    } else if !(PLAUSIBLE_NM[0]..=PLAUSIBLE_NM[1]).contains(&x) {
        Err(Invalid::Wavelength { found: x })
    } else if let Some(previous) = previous.filter(|&p| x <= p) {
        Err(Invalid::NotIncreasing { previous, found: x })
    } else {
        Ok(())
    }
}

fn check_value(y: f64, role: Role) -> Result<(), Invalid> {
    let [min, max] = role.bounds();
    if !y.is_finite() {
        Err(Invalid::NonFinite { value: y })
    } else if y.abs() > MAX_VALUE {
        Err(Invalid::TooLarge { value: y, max: MAX_VALUE })
    } else if role == Role::Light && y < 0.0 {
        Err(Invalid::NegativePower { value: y })
    } else if role == Role::Index && y <= 0.0 {
        Err(Invalid::NotPositive { value: y })
    } else if !(min..=max).contains(&y) {
        Err(Invalid::OutOfRange { value: y, min, max })
    } else {
        Ok(())
    }
}
