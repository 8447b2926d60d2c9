//! The library's error type, at the bottom floor: it depends on nothing in
//! the crate, so every floor can return it.
//!
//! Every error says where it applies: text errors carry the origin (file
//! path or `<string>`), line and column ([`ParseError`], with its
//! [`Position`] and [`ParseErrorKind`]); errors in in-memory samples carry
//! the index and the field ([`SampleError`]); other variants carry the
//! values that were out of range. Text positions, kinds and read failures
//! are `speclab_tables`' own errors, carried as they are and re-exported
//! here: build scripts and run-time loading report the same errors.
//!
//! ```
//! use speclab::{io::Load, Role, TabulatedSpectrum};
//! let err = Load::new(Role::Light).text("{380, 1}, {370, 2}", "<string>").unwrap_err();
//! assert_eq!(err.to_string(), "<string>:1:11: expected a wavelength greater than 380 nm, found 370 nm");
//! let err = TabulatedSpectrum::new(vec![380.0, 370.0], vec![1.0, 2.0], Role::Light).unwrap_err();
//! assert_eq!(err.to_string(), "lambda[1]: expected a wavelength greater than 380 nm, found 370 nm");
//! ```

use std::fmt;

// speclab-tables' types, documented there (one page per type).
#[doc(no_inline)]
pub use speclab_tables::error::{ParseError, ParseErrorKind, Position, ReadError};
#[doc(no_inline)]
pub use speclab_tables::validate::{Field, Invalid, SampleError};

/// Errors of the public API.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// Text that does not form a valid spectrum, located by line and column.
    Parse(ParseError),
    /// In-memory samples that do not form a valid spectrum, located by index.
    Sample(SampleError),
    /// A file or stream that could not be read, or is larger than the
    /// reading limit ([`ReadError`]: the file and why).
    Read(ReadError),
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
    /// A count outside its range: a hero width, a number of buckets, of
    /// fitted wavelengths, of bins, or a rule taken as a value of another
    /// size.
    Count {
        /// What was counted, e.g. `a bucket count`.
        what: &'static str,
        /// The count given.
        found: usize,
        /// The smallest count allowed.
        min: usize,
        /// The largest count allowed.
        max: usize,
    },
    /// A rule of box buckets asked for as wavelengths: its values are
    /// means over its buckets, not values at wavelengths.
    BoxRule,
    /// A light or a density with no mass where the observer sees, within
    /// 380–730 nm (or a mass that is not finite): nothing to follow,
    /// sample or fit.
    NoMass,
    /// A blackbody temperature that is not finite and positive (kelvin).
    Temperature {
        /// The temperature given, K.
        kelvin: f64,
    },
    /// A colour that is not an albedo: linear sRGB components must lie in
    /// [0, 1].
    Albedo {
        /// The components given.
        rgb: [f64; 3],
    },
    /// An RGB table file that is not one, or is damaged: its message names
    /// the file and what was expected.
    TableFile(speclab_tables::rgb_file::FileError),
    /// An RGB table given to a space it was not fitted for.
    TableSpace {
        /// The name the table's file gives its space.
        table: String,
        /// The space it was given to.
        space: &'static str,
    },
    /// Chromaticities that do not make an RGB space: every primary and the
    /// white point must be finite with a non-zero y (the white's positive),
    /// and the primaries must span a space.
    Primaries,
    /// A table of another role than the one asked for (a light given as a
    /// conductor's η).
    Role {
        /// What the table was given as, e.g. `a conductor's η`.
        what: &'static str,
        /// The role that part takes.
        expected: crate::spectrum::Role,
        /// The table's role.
        found: crate::spectrum::Role,
    },
    /// Dispersion coefficients that do not give a real, finite, positive
    /// refractive index over 360–830 nm.
    Dispersion,
    /// A correlated colour temperature outside the CIE daylight formula's
    /// range (4000–25000 K).
    Daylight {
        /// The temperature given, K.
        kelvin: f64,
    },
    /// A chromaticity that is not finite.
    Chromaticity {
        /// The chromaticity given, `[x, y]`.
        xy: [f64; 2],
    },
    /// A weight of a sum that is not finite and non-negative.
    Weight {
        /// Which term.
        index: usize,
        /// The weight given.
        weight: f64,
    },
    /// An entry of a rule given by its wavelengths and weights
    /// (`Rule::new`): a wavelength outside 380–730 nm, or a weight that is
    /// not finite.
    RuleEntry {
        /// Which wavelength of the rule.
        index: usize,
        /// The wavelength given, nm.
        lambda: f64,
    },
    /// A weight row of a rule (`Rule::new`) whose length is not the number
    /// of wavelengths.
    RuleShape {
        /// Which row: 0, 1, 2 for X, Y, Z.
        row: usize,
        /// Its length.
        len: usize,
        /// The number of wavelengths.
        expected: usize,
    },
    /// A surface handed to a fit (`FittedRules::with_surfaces`) whose value
    /// at some wavelength is not a number of magnitude at most 1,000
    /// (`fitted::MAX_REFLECTANCE`).
    Surface {
        /// Which surface of the list.
        index: usize,
        /// Where, nm.
        lambda: f64,
        /// The value found there.
        value: f64,
    },
    /// A wavelength range that is not `0 < min < max`, finite.
    Range {
        /// The lower end given, nm.
        min: f64,
        /// The upper end given, nm.
        max: f64,
    },
    /// A range whose ends must lie on a grid (a 1 nm table's nanometres,
    /// a fit's candidates, a weighting table's wavelengths) and do not.
    OffGrid {
        /// The range given, nm.
        range: [f64; 2],
        /// The grid's first wavelength, nm.
        first: f64,
        /// The grid's step, nm.
        step: f64,
    },
    /// A wavelength range beyond an observer's data (or a weighting
    /// table's wavelengths).
    RangeOutside {
        /// The range asked for, nm.
        range: [f64; 2],
        /// Whose data: `the CIE 1931 2° observer`, `the weighting table`.
        of: &'static str,
        /// The range its data cover, nm.
        data: [f64; 2],
    },
    /// A wavelength step that is not positive, finite and at most the
    /// range's width.
    Step {
        /// The step given, nm.
        step: f64,
        /// The range's width, nm.
        width: f64,
    },
    /// A light with no power under ȳ where tristimulus values are summed.
    Dark {
        /// The range summed over, nm.
        range: [f64; 2],
    },
    /// A sensor's response curve that is negative or not finite.
    Response {
        /// The curve: 0, 1, 2 for r, g, b.
        channel: usize,
        /// Where, nm.
        lambda: f64,
        /// The value found there.
        value: f64,
    },
    /// A pixel outside an image, or an image whose size is not
    /// `width × height × channels` values.
    Pixel {
        /// What was wrong: `the pixel (9, 2)`, `the image's values`.
        what: String,
        /// What was expected: `within 8 × 8`, `64 values`.
        expected: String,
    },
    /// A spectral image that cannot be developed as asked: an emissive
    /// image with a light, a reflective one without, wavelengths that do
    /// not increase.
    Develop(&'static str),
    /// A name that names none of the choices (a built-in light, a pdf, …).
    UnknownName {
        /// What was looked up, e.g. `a built-in light`.
        what: &'static str,
        /// The names that exist, e.g. `["A", "D65", "F11"]`.
        expected: &'static [&'static str],
        /// The name given.
        found: String,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Parse(e) => e.fmt(f),
            Error::Sample(e) => e.fmt(f),
            Error::Read(e) => e.fmt(f),
            Error::Scale { factor } => write!(f, "expected a finite positive scale factor, found {factor}"),
            Error::SampleWavelength { index, lambda, pdf } => write!(
                f,
                "wavelength {index}: expected a finite wavelength with a finite non-negative pdf, \
                 found {lambda} nm with pdf {pdf}"
            ),
            Error::Count { what, found, min, max } if min == max => {
                write!(f, "expected {what} of {min}, found {found}")
            }
            Error::Count { what, found, min, max: usize::MAX } => {
                write!(f, "expected {what}: at least {min}, found {found}")
            }
            Error::Count { what, found, min, max } => {
                write!(f, "expected {what} from {min} to {max}, found {found}")
            }
            Error::BoxRule => write!(
                f,
                "expected a rule whose values are taken at its wavelengths, found box buckets \
                 (their values are means over the buckets)"
            ),
            Error::NoMass => write!(
                f,
                "expected a light or density with finite positive mass where the observer sees \
                 (380-730 nm), found none"
            ),
            Error::Temperature { kelvin } => {
                write!(f, "expected a finite positive temperature in kelvin, found {kelvin}")
            }
            Error::Albedo { rgb } => write!(
                f,
                "expected linear sRGB components in [0, 1], found ({}, {}, {})",
                rgb[0], rgb[1], rgb[2]
            ),
            Error::TableFile(e) => e.fmt(f),
            Error::TableSpace { table, space } => write!(
                f,
                "expected a table fitted for the RGB space {space}, found one fitted for {table:?} \
                 (another XYZ to RGB matrix, or an illuminant of another white)"
            ),
            Error::Primaries => write!(
                f,
                "expected primaries and a white point of finite chromaticities with non-zero y \
                 (the white's positive), the primaries spanning a space, found others"
            ),
            Error::Role { what, expected, found } => {
                write!(f, "expected a table of role {expected:?} for {what}, found one of role {found:?}")
            }
            Error::Dispersion => write!(
                f,
                "expected dispersion coefficients giving a real, finite, positive refractive index \
                 over 380-730 nm, found others"
            ),
            Error::Daylight { kelvin } => {
                write!(f, "expected a daylight temperature from 4000 to 25000 K, found {kelvin} K")
            }
            Error::Chromaticity { xy: [x, y] } => {
                write!(f, "expected a finite chromaticity, found ({x}, {y})")
            }
            Error::Response { channel, lambda, value } => write!(
                f,
                "a sensor's {} curve at {lambda} nm: expected a finite non-negative response, found {value}",
                ["r", "g", "b"].get(*channel).unwrap_or(&"?")
            ),
            Error::Pixel { what, expected } => write!(f, "{what}: expected {expected}"),
            Error::Develop(why) => f.write_str(why),
            Error::Weight { index, weight } => {
                write!(f, "term {index}: expected a finite non-negative weight, found {weight}")
            }
            Error::RuleEntry { index, lambda } => write!(
                f,
                "rule wavelength {index}: expected a wavelength in 360–830 nm with a finite weight in each of X, Y and Z, found {lambda} nm"
            ),
            Error::RuleShape { row, len, expected } => {
                let name = ["X", "Y", "Z"].get(*row).copied().unwrap_or("?");
                write!(f, "rule weights for {name}: expected {expected} (one per wavelength), found {len}")
            }
            Error::Surface { index, lambda, value } => {
                write!(
                    f,
                    "surface {index}: expected a reflectance from -1000 to 1000, found {value} at {lambda} nm"
                )
            }
            Error::Range { min, max } => {
                write!(f, "expected a wavelength range 0 < min < max nm, finite, found {min}–{max}")
            }
            Error::OffGrid { range: [a, b], first, step } => {
                write!(
                    f,
                    "expected a range with ends on {first}, {}, {}, … nm, found {a}–{b} nm",
                    first + step,
                    first + 2.0 * step
                )
            }
            Error::RangeOutside { range: [a, b], of, data: [lo, hi] } => {
                write!(f, "expected a range within {of}'s data ({lo}–{hi} nm), found {a}–{b} nm")
            }
            Error::Step { step, width } => {
                write!(f, "expected a wavelength step in (0, {width}] nm, found {step}")
            }
            Error::Dark { range: [a, b] } => {
                write!(f, "expected a light with power under ȳ within {a}–{b} nm, found none")
            }
            Error::UnknownName { what, expected, found } if expected.len() <= 12 => {
                write!(f, "expected {what} ({}), found {found:?}", or_list(expected.iter()))
            }
            Error::UnknownName { what, expected, found } => write!(
                f,
                "expected {what} (nearest: {}; {} names in all), found {found:?}",
                or_list(nearest(expected, found, 3).iter()),
                expected.len()
            ),
        }
    }
}

/// The `count` names closest to `found` by edit distance (ignoring case),
/// closest first (ties in the list's order).
fn nearest(names: &[&'static str], found: &str, count: usize) -> Vec<&'static str> {
    let found: Vec<char> = found.to_lowercase().chars().collect();
    let distance = |name: &str| {
        let name: Vec<char> = name.to_lowercase().chars().collect();
        let mut row: Vec<usize> = (0..=name.len()).collect();
        for (i, a) in found.iter().enumerate() {
            let mut previous = row[0];
            row[0] = i + 1;
            for (j, b) in name.iter().enumerate() {
                let next = (previous + usize::from(a != b)).min(row[j] + 1).min(row[j + 1] + 1);
                previous = row[j + 1];
                row[j + 1] = next;
            }
        }
        row[name.len()]
    };
    let mut ranked: Vec<(usize, usize, &'static str)> =
        names.iter().enumerate().map(|(i, n)| (distance(n), i, *n)).collect();
    ranked.sort_unstable();
    ranked.into_iter().take(count).map(|(_, _, n)| n).collect()
}

/// `1, 2 or 3`.
fn or_list(items: impl Iterator<Item = impl fmt::Display>) -> String {
    let names: Vec<String> = items.map(|i| i.to_string()).collect();
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => names.concat(),
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Parse(e) => Some(e),
            Error::Sample(e) => Some(e),
            Error::Read(e) => Some(e),
            Error::TableFile(e) => Some(e),
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

impl From<ReadError> for Error {
    fn from(e: ReadError) -> Self {
        Error::Read(e)
    }
}
