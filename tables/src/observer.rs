//! Three responses per wavelength at a uniform step: the CIE's
//! colour-matching functions x̄, ȳ, z̄ (or a camera's three channels), as
//! `nm,x,y,z` rows.
//!
//! - `#` starts a comment; one optional header line (`nm,x,y,z`); fields
//!   are separated as in [`crate::columns`].
//! - Wavelengths in nanometres, increasing by one uniform step (the first
//!   two rows set it); values finite and non-negative; at least two rows.
//!
//! [`ObserverTable::source`] writes the table as Rust source, for a build
//! script.
//!
//! ```
//! use speclab_tables::observer::parse_observer;
//! let t = parse_observer("nm,x,y,z\n360,0.1,0.2,0.3\n361,0.2,0.3,0.4\n", "<string>")?;
//! assert_eq!((t.first, t.step, t.rows.len()), (360.0, 1.0, 2));
//! let bad = parse_observer("360,0,0,0\n361,0,0,0\n363,0,0,0\n", "cmf.csv").unwrap_err();
//! assert_eq!(bad.to_string(), "cmf.csv:3:1: expected the wavelength 362 nm (a uniform step), found 363");
//! # Ok::<(), speclab_tables::error::ParseError>(())
//! ```

use crate::columns::{fields, looks_numeric};
use crate::error::{ParseError, ParseErrorKind, Position};
use crate::text::number;

/// Three responses per wavelength, at `first + i·step` nm.
#[derive(Clone, Debug, PartialEq)]
pub struct ObserverTable {
    /// The first wavelength, nm.
    pub first: f64,
    /// The step, nm (positive).
    pub step: f64,
    /// `[x̄, ȳ, z̄]` at each wavelength.
    pub rows: Vec<[f64; 3]>,
}

/// Reads `nm,x,y,z` rows; errors name the line and column and what was expected.
pub fn parse_observer(text: &str, origin: &str) -> Result<ObserverTable, ParseError> {
    let mut lambda: Vec<f64> = Vec::new();
    let mut rows = Vec::new();
    let mut last = Position::START;
    for (i, raw) in text.lines().enumerate() {
        let fields = fields(raw.split('#').next().unwrap_or_default());
        let Some(&(column, first)) = fields.first() else { continue };
        let at = |column| Position { line: i + 1, column };
        let error = |column, kind| ParseError { origin: origin.to_string(), position: at(column), kind };
        if lambda.is_empty() && rows.is_empty() && !looks_numeric(first) && last == Position::START {
            last = at(column);
            continue;
        }
        if fields.len() != 4 {
            return Err(error(column, ParseErrorKind::Arity { found: fields.len(), expected: 4 }));
        }
        let l = number(first, origin, at(column))?;
        if let [a, b, ..] = lambda[..] {
            let expected = a + (b - a) * lambda.len() as f64;
            if (l - expected).abs() > 1e-9 * expected.abs() {
                return Err(error(column, ParseErrorKind::Step { found: l, expected }));
            }
        } else if let [a] = lambda[..]
            && l <= a
        {
            return Err(error(column, ParseErrorKind::Step { found: l, expected: a + 1.0 }));
        }
        let mut row = [0.0; 3];
        for (v, &(c, token)) in row.iter_mut().zip(&fields[1..]) {
            *v = number(token, origin, at(c))?;
            if *v < 0.0 {
                return Err(error(c, ParseErrorKind::Negative { text: token.to_string() }));
            }
        }
        lambda.push(l);
        rows.push(row);
        last = at(column);
    }
    if rows.len() < 2 {
        let kind = ParseErrorKind::Count { found: rows.len(), expected: 2 };
        return Err(ParseError { origin: origin.to_string(), position: last, kind });
    }
    Ok(ObserverTable { first: lambda[0], step: lambda[1] - lambda[0], rows })
}

impl ObserverTable {
    /// The last wavelength, nm.
    #[must_use]
    pub fn last(&self) -> f64 {
        self.first + self.step * (self.rows.len() - 1) as f64
    }

    /// Rust source declaring `pub static {name}: [[f64; 3]; N]` and the
    /// constants `{name}_FIRST` and `{name}_STEP` (nm).
    #[must_use]
    pub fn source(&self, name: &str) -> String {
        let rows: Vec<String> = self.rows.iter().map(|[x, y, z]| format!("[{x:?}, {y:?}, {z:?}]")).collect();
        format!(
            "/// The first wavelength of [`{name}`], nm.\npub const {name}_FIRST: f64 = {:?};\n\
             /// The step of [`{name}`], nm.\npub const {name}_STEP: f64 = {:?};\n\
             /// `[x̄, ȳ, z̄]` at `{name}_FIRST + i·{name}_STEP` nm.\n\
             pub static {name}: [[f64; 3]; {}] = [{}];\n",
            self.first,
            self.step,
            self.rows.len(),
            rows.join(", ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kind(text: &str) -> (usize, ParseErrorKind) {
        let e = parse_observer(text, "t").unwrap_err();
        (e.position.line, e.kind)
    }

    #[test]
    fn reads_a_table_and_writes_it_as_source() {
        let t = parse_observer("# c\nnm,x,y,z\n400,1,2,3\n405,4,5,6\n410,0,0,0.5\n", "t").unwrap();
        assert_eq!((t.first, t.step, t.last()), (400.0, 5.0, 410.0));
        assert_eq!(t.rows[1], [4.0, 5.0, 6.0]);
        let code = t.source("OBS");
        assert!(code.contains(
            "pub static OBS: [[f64; 3]; 3] = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [0.0, 0.0, 0.5]];"
        ));
        assert!(code.contains("pub const OBS_FIRST: f64 = 400.0;") && code.contains("OBS_STEP: f64 = 5.0;"));
    }

    #[test]
    fn names_what_is_wrong_and_where() {
        assert_eq!(kind("400,1,2\n"), (1, ParseErrorKind::Arity { found: 3, expected: 4 }));
        assert_eq!(
            kind("400,1,2,3\n399,1,2,3\n"),
            (2, ParseErrorKind::Step { found: 399.0, expected: 401.0 })
        );
        assert_eq!(kind("400,1,2,3\n400,1,2,3\n").1, ParseErrorKind::Step { found: 400.0, expected: 401.0 });
        assert_eq!(
            kind("1,0,0,0\n2,0,0,0\n4,0,0,0\n"),
            (3, ParseErrorKind::Step { found: 4.0, expected: 3.0 })
        );
        assert_eq!(kind("400,1,-2,3\n"), (1, ParseErrorKind::Negative { text: "-2".into() }));
        assert_eq!(kind("nm,x,y,z\n400,1,2,3\n"), (2, ParseErrorKind::Count { found: 1, expected: 2 }));
        assert_eq!(kind("nm,x,y,z\nnm,x,y,z\n").0, 2, "a second header is a bad number");
        assert_eq!(kind(""), (1, ParseErrorKind::Count { found: 0, expected: 2 }));
    }
}
