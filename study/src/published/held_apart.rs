//! The held-apart reflectances: 53 measured surfaces that no fitted rule's
//! prior contains, for judging rules on surfaces they never saw.
//!
//! - `tcs`: CIE 13.3 test colour samples TCS01–TCS14;
//! - `cqs`: NIST Colour Quality Scale 9.0 samples VS1–VS15;
//! - `ohta`: the 24 ColorChecker Classic patches as measured by N. Ohta.
//!
//! Each set is a file in `data/held-apart/` (sources in `data/SOURCES.md`),
//! one reflectance per row: a name, then 81 values at 380, 385, …, 780 nm.
//! Read at compile time; a malformed row is an error naming the file, the
//! line and the column.
//!
//! ```
//! use speclab_study::published::held_apart;
//! let all = held_apart::all()?;
//! assert_eq!(all.len(), 53);
//! assert_eq!(all[0].name, "tcs/tcs01");
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use speclab::error::{Error, ParseError, ParseErrorKind, Position};
use speclab::spectrum::{Role, TabulatedSpectrum};

use crate::StudyError;
use crate::evaluate::scene::Named;

/// The sets: name, file, text.
const SETS: [(&str, &str, &str); 3] = [
    ("tcs", "data/held-apart/tcs.csv", include_str!("../../../data/held-apart/tcs.csv")),
    ("cqs", "data/held-apart/cqs.csv", include_str!("../../../data/held-apart/cqs.csv")),
    ("ohta", "data/held-apart/ohta.csv", include_str!("../../../data/held-apart/ohta.csv")),
];

/// The values per row: 380 to 780 nm every 5 nm.
const VALUES: usize = 81;

/// Every held-apart reflectance, named `set/name`, in the sets' order.
pub fn all() -> Result<Vec<Named>, StudyError> {
    let mut out = Vec::new();
    for (set, origin, text) in SETS {
        out.extend(parse(set, origin, text)?);
    }
    Ok(out)
}

/// The reflectances of one set's text (`origin` names it in errors).
pub fn parse(set: &str, origin: &str, text: &str) -> Result<Vec<Named>, StudyError> {
    let lambda: Vec<f64> = (0..VALUES).map(|i| 380.0 + 5.0 * i as f64).collect();
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or_default().trim();
        if line.is_empty() {
            continue;
        }
        let fail = |column: usize, kind: ParseErrorKind| {
            Error::Parse(ParseError {
                origin: origin.to_string(),
                position: Position { line: i + 1, column },
                kind,
            })
        };
        let mut fields = line.split(',');
        let name = fields.next().unwrap_or_default().trim();
        let mut values = Vec::with_capacity(VALUES);
        let mut column = name.len() + 2;
        for field in fields {
            let v = field.trim().parse::<f64>();
            values.push(
                v.map_err(|_| fail(column, ParseErrorKind::BadNumber { text: field.trim().to_string() }))?,
            );
            column += field.len() + 1;
        }
        if values.len() != VALUES {
            let expected = "a name and 81 reflectances at 380, 385, …, 780 nm";
            return Err(fail(column.saturating_sub(1), ParseErrorKind::Missing { expected }).into());
        }
        let spectrum = TabulatedSpectrum::new(lambda.clone(), values, Role::Reflectance)?;
        out.push(Named::new(format!("{set}/{name}"), spectrum));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_row_and_a_bad_number_name_their_line() {
        let short = parse("x", "f.csv", "# c\nok,0.5,0.5\n").unwrap_err().to_string();
        assert!(short.starts_with("f.csv:2:") && short.contains("81 reflectances"), "{short}");
        let row = format!("a,{}\nb,0.1,zz\n", vec!["0.5"; 81].join(","));
        let bad = parse("x", "f.csv", &row).unwrap_err().to_string();
        assert!(bad.starts_with("f.csv:2:7:") && bad.contains("zz"), "{bad}");
        assert!(parse("x", "f.csv", &format!("a,{}\n", vec!["2"; 81].join(","))).is_err());
    }

    #[test]
    fn the_sets_hold_their_published_counts_and_stay_reflectances() {
        let all = all().unwrap();
        let count = |p: &str| all.iter().filter(|n| n.name.starts_with(p)).count();
        assert_eq!((count("tcs/"), count("cqs/"), count("ohta/")), (14, 15, 24));
        let mut names: Vec<&str> = all.iter().map(|n| n.name.as_str()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), 53);
        let lambda = all[52].spectrum.lambda();
        assert_eq!((lambda.len(), lambda[1], lambda[80]), (81, 385.0, 780.0));
        // TCS01's and VS1's values at 380 nm, as published.
        assert_eq!((all[0].spectrum.values()[0], all[14].spectrum.values()[0]), (0.219, 0.053));
    }
}
