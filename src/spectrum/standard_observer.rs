//! The standard observers: the CIE's colour-matching functions x̄, ȳ, z̄,
//! chosen by name, with the range their data cover.
//!
//! - [`StandardObserver::Cie1931`] (the default) and [`StandardObserver::Cie1964`]: the
//!   CIE 1931 2° and CIE 1964 10° observers, the CIE's 1 nm tables over
//!   360–830 nm (`data/observers/`), linear between the nanometres as the
//!   CIE's tables are read (and pbrt-v4 and Mitsuba 3 read theirs).
//! - [`StandardObserver::Cie2015_2`] and [`StandardObserver::Cie2015_10`]:
//!   the CIE 2015 cone-fundamental-based observers (CIE 170-2:2015), 1 nm
//!   over 390–830 nm, linear.
//! - [`StandardObserver::Assignment`]: the assignment's 5 nm table of the 1931
//!   observer over 380–780 nm, with the four-point cubic
//!   ([`crate::spectrum::observer`]); Appendix 2, the study and the
//!   sampled paths (`HeroSample`, `RegularSpectrum`, the exact reference)
//!   use it.
//!
//! Values are zero outside an observer's data; an integral over a range
//! beyond them is refused ([`StandardObserver::check`]).
//!
//! ```
//! use speclab::spectrum::{StandardObserver, WavelengthRange};
//! let [_, y, _] = StandardObserver::Cie1931.xyz_bar(555.0);
//! assert_eq!(y, 1.0);
//! let integral = StandardObserver::Cie1931.y_integral(WavelengthRange::VISIBLE)?;
//! assert!((integral - 106.8569).abs() < 1e-4);
//! assert!(StandardObserver::Cie1964.y_integral(WavelengthRange::new(300.0, 830.0)?).is_err());
//! assert_eq!(StandardObserver::named("10°")?, StandardObserver::Cie1964);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::spectrum::data::cie1931::{X_BAR, Y_BAR, Z_BAR};
use crate::spectrum::data::observers as tables;
use crate::spectrum::{DenseObserver, Float, Observer, WavelengthRange, Wavelengths, observer};

/// A standard colorimetric observer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum StandardObserver {
    /// The CIE 1931 2° observer, 1 nm, 360–830 nm, linear.
    #[default]
    Cie1931,
    /// The CIE 1964 10° observer, 1 nm, 360–830 nm, linear.
    Cie1964,
    /// The assignment's 5 nm CIE 1931 table, 380–780 nm, cubic (Appendix 1).
    Assignment,
    /// The CIE 2015 2° observer (CIE 170-2:2015), 1 nm, 390–830 nm, linear.
    Cie2015_2,
    /// The CIE 2015 10° observer (CIE 170-2:2015), 1 nm, 390–830 nm, linear.
    Cie2015_10,
}

/// A table at a uniform step: first wavelength, step (nm), `[x̄, ȳ, z̄]` rows.
pub type Table = (f64, f64, &'static [[f64; 3]]);

/// The names [`StandardObserver::named`] takes (any case).
const NAMES: [&str; 11] = [
    "CIE 1931",
    "1931",
    "2°",
    "CIE 1964",
    "1964",
    "10°",
    "assignment",
    "CIE 2015 2°",
    "CIE 2015 10°",
    "2",
    "10",
];

impl StandardObserver {
    /// Every observer.
    pub const ALL: [StandardObserver; 5] = [
        StandardObserver::Cie1931,
        StandardObserver::Cie1964,
        StandardObserver::Assignment,
        StandardObserver::Cie2015_2,
        StandardObserver::Cie2015_10,
    ];

    /// The observer's name, as in errors and tables.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            StandardObserver::Cie1931 => "CIE 1931 2°",
            StandardObserver::Cie1964 => "CIE 1964 10°",
            StandardObserver::Assignment => "assignment's CIE 1931 (5 nm)",
            StandardObserver::Cie2015_2 => "CIE 2015 2°",
            StandardObserver::Cie2015_10 => "CIE 2015 10°",
        }
    }

    /// The observer named `name` (any case; `deg` for `°`): `CIE 1931`,
    /// `1931`, `2°`, `CIE 1964`, `1964`, `10°`, `assignment`, `CIE 2015 2°`,
    /// `CIE 2015 10°`.
    pub fn named(name: &str) -> Result<Self, Error> {
        let key = name.trim().to_lowercase().replace("deg", "°").replace(' ', "");
        match key.as_str() {
            "cie1931" | "1931" | "2°" | "2" | "cie19312°" => Ok(StandardObserver::Cie1931),
            "cie1964" | "1964" | "10°" | "10" | "cie196410°" => Ok(StandardObserver::Cie1964),
            "assignment" => Ok(StandardObserver::Assignment),
            "cie20152°" | "20152°" => Ok(StandardObserver::Cie2015_2),
            "cie201510°" | "201510°" => Ok(StandardObserver::Cie2015_10),
            _ => Err(Error::UnknownName {
                what: "an observer",
                expected: &NAMES[..9],
                found: name.to_string(),
            }),
        }
    }

    /// The range the observer's data cover.
    #[must_use]
    pub const fn data_range(self) -> WavelengthRange {
        match self {
            StandardObserver::Assignment => WavelengthRange::ASSIGNMENT.with_max(780.0),
            StandardObserver::Cie2015_2 | StandardObserver::Cie2015_10 => observer::CIE_2015_DATA,
            StandardObserver::Cie1931 | StandardObserver::Cie1964 => WavelengthRange::VISIBLE,
        }
    }

    /// The 1 nm table, `None` for the assignment's cubic.
    #[must_use]
    pub fn table(self) -> Option<Table> {
        match self {
            StandardObserver::Cie1931 => {
                Some((tables::CIE_1931_2_FIRST, tables::CIE_1931_2_STEP, &tables::CIE_1931_2))
            }
            StandardObserver::Cie1964 => {
                Some((tables::CIE_1964_10_FIRST, tables::CIE_1964_10_STEP, &tables::CIE_1964_10))
            }
            StandardObserver::Cie2015_2 => {
                Some((tables::CIE_2015_2_FIRST, tables::CIE_2015_2_STEP, &tables::CIE_2015_2))
            }
            StandardObserver::Cie2015_10 => {
                Some((tables::CIE_2015_10_FIRST, tables::CIE_2015_10_STEP, &tables::CIE_2015_10))
            }
            StandardObserver::Assignment => None,
        }
    }

    /// The observer at every whole nanometre from 360 to 830 nm: the fast
    /// path of a sampled renderer (one load per wavelength).
    #[must_use]
    pub const fn dense(self) -> DenseObserver {
        match self {
            StandardObserver::Cie1931 => DenseObserver::CIE_1931,
            StandardObserver::Cie1964 => DenseObserver::CIE_1964,
            StandardObserver::Assignment => DenseObserver::ASSIGNMENT,
            StandardObserver::Cie2015_2 => DenseObserver::CIE_2015_2,
            StandardObserver::Cie2015_10 => DenseObserver::CIE_2015_10,
        }
    }

    /// The standard observer whose 1 nm table `dense` is ([`dense`](Self::dense)'s inverse).
    #[must_use]
    pub fn of_dense(dense: &DenseObserver) -> StandardObserver {
        let tables = StandardObserver::ALL.into_iter().filter(|o| o.table().is_some());
        tables.into_iter().find(|o| o.dense() == *dense).unwrap_or(StandardObserver::Assignment)
    }

    /// `[x̄, ȳ, z̄]` at `lambda` nm; zero outside the data (and at NaN).
    #[must_use]
    pub fn xyz_bar(self, lambda: f64) -> [f64; 3] {
        match self.table() {
            Some(table) if self.data_range().contains(lambda) => lerp(table, lambda),
            Some(_) => [0.0; 3],
            None => observer::xyz_bar(lambda),
        }
    }

    /// `range` itself if the observer's data cover it, or an error naming both.
    pub fn check(self, range: WavelengthRange) -> Result<WavelengthRange, Error> {
        let data = self.data_range();
        if range.within(data) {
            Ok(range)
        } else {
            Err(Error::RangeOutside {
                range: [range.min(), range.max()],
                of: match self {
                    StandardObserver::Cie1931 => "the CIE 1931 2° observer",
                    StandardObserver::Cie1964 => "the CIE 1964 10° observer",
                    StandardObserver::Assignment => "the assignment's observer",
                    StandardObserver::Cie2015_2 => "the CIE 2015 2° observer",
                    StandardObserver::Cie2015_10 => "the CIE 2015 10° observer",
                },
                data: [data.min(), data.max()],
            })
        }
    }

    /// `∫ x̄, ∫ ȳ, ∫ z̄` over `range`, nm: exact, of the interpolant (the
    /// lines between the nanometres, or the assignment's clamped cubic).
    pub fn integrals(self, range: WavelengthRange) -> Result<[f64; 3], Error> {
        let range = self.check(range)?;
        Ok(match self.table() {
            Some(table) => integrate(table, range),
            None => [&X_BAR, &Y_BAR, &Z_BAR].map(|s| s.integral(range.min(), range.max())),
        })
    }

    /// `∫ ȳ dλ` over `range`, nm: the Y of a spectrum equal to 1 there.
    pub fn y_integral(self, range: WavelengthRange) -> Result<f64, Error> {
        self.integrals(range).map(|[_, y, _]| y)
    }
}

/// A sampled path's observer: `HeroSample::with_observer(u, &StandardObserver::Cie1964)?`
/// weighs its wavelengths by the 10° observer.
impl Observer for StandardObserver {
    fn data_range(&self) -> WavelengthRange {
        StandardObserver::data_range(*self)
    }

    /// The exact integral of its interpolation (0 past its data).
    fn y_integral(&self, range: WavelengthRange) -> f64 {
        StandardObserver::y_integral(*self, range).unwrap_or(0.0)
    }

    fn xyz_bar_at<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> [[T; 4]; K] {
        at.lambda().map(|l| {
            let [x, y, z] = self.xyz_bar(l.to_f64());
            [x, y, z, 1.0].map(T::from_f64)
        })
    }
}

/// The table's line between the two nearest rows; zero outside.
fn lerp((first, step, rows): Table, lambda: f64) -> [f64; 3] {
    let t = (lambda - first) / step;
    let last = (rows.len() - 1) as f64;
    if !(0.0..=last).contains(&t) {
        return [0.0; 3];
    }
    let i = (t as usize).min(rows.len() - 2);
    let (f, a, b) = (t - i as f64, rows[i], rows[i + 1]);
    [0, 1, 2].map(|c| a[c] + f * (b[c] - a[c]))
}

/// The exact integral of the table's lines over `range` (within the data):
/// a trapezoid per piece of a step.
fn integrate(table @ (first, step, rows): Table, range: WavelengthRange) -> [f64; 3] {
    let (lo, hi) = (range.min(), range.max());
    let start = ((lo - first) / step).floor().max(0.0) as usize;
    let end = (((hi - first) / step).ceil() as usize).min(rows.len() - 1);
    let mut sum = [0.0; 3];
    for i in start..end {
        let (a, b) = (first + step * i as f64, first + step * (i + 1) as f64);
        let (u, v) = (a.max(lo), b.min(hi));
        if v > u {
            let (fu, fv) = (lerp(table, u), lerp(table, v));
            for c in 0..3 {
                sum[c] += 0.5 * (v - u) * (fu[c] + fv[c]);
            }
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_read_as_published_and_linear_between() {
        let (o, p) = (StandardObserver::Cie1931, StandardObserver::Cie1964);
        assert_eq!(o.xyz_bar(360.0), [0.0001299, 3.917e-06, 0.0006061]);
        assert_eq!(o.xyz_bar(830.0), [1.251141e-06, 4.5181e-07, 0.0]);
        assert_eq!(p.xyz_bar(555.0), [0.616053, 0.99911, 0.001091]);
        let (a, b, m) = (o.xyz_bar(600.0), o.xyz_bar(601.0), o.xyz_bar(600.25));
        (0..3).for_each(|c| assert!((m[c] - (0.75 * a[c] + 0.25 * b[c])).abs() < 1e-15));
        for outside in [359.999, 830.001, f64::NAN, f64::INFINITY] {
            assert_eq!(o.xyz_bar(outside), [0.0; 3], "{outside}");
        }
        assert_eq!(StandardObserver::Assignment.xyz_bar(555.0), observer::xyz_bar(555.0));
    }

    #[test]
    fn integrals_are_trapezoids_over_the_range() {
        let (first, step, rows) = StandardObserver::Cie1931.table().unwrap();
        assert_eq!((first, step, rows.len()), (360.0, 1.0, 471));
        let sum: f64 = rows.iter().map(|r| r[1]).sum();
        let trapezoids = sum - 0.5 * (rows[0][1] + rows[470][1]);
        let y = StandardObserver::Cie1931.y_integral(WavelengthRange::VISIBLE).unwrap();
        assert!((y - trapezoids).abs() < 1e-12, "{y} against {trapezoids}");
        // A piece of one step: 555.5–556 is a quarter of 555–557's lines.
        let half = WavelengthRange::new(555.5, 556.0).unwrap();
        let expected = 0.5 * 0.5 * (StandardObserver::Cie1931.xyz_bar(555.5)[1] + rows[196][1]);
        assert!((StandardObserver::Cie1931.y_integral(half).unwrap() - expected).abs() < 1e-15);
        let a = StandardObserver::Assignment.y_integral(WavelengthRange::ASSIGNMENT).unwrap();
        assert!((a - observer::Y_BAR_INTEGRAL).abs() < 1e-9 * a);
        // As the observer of a path (the trait), the same integral.
        let traced = Observer::y_integral(&StandardObserver::Cie1964, WavelengthRange::VISIBLE);
        assert_eq!(traced, StandardObserver::Cie1964.y_integral(WavelengthRange::VISIBLE).unwrap());
        assert!((traced - 116.6).abs() < 0.1, "{traced}");
    }

    #[test]
    fn names_and_ranges() {
        assert_eq!(
            StandardObserver::named(StandardObserver::Cie1931.name()).unwrap(),
            StandardObserver::Cie1931
        );
        assert_eq!(
            StandardObserver::named(StandardObserver::Cie1964.name()).unwrap(),
            StandardObserver::Cie1964
        );
        assert_eq!(StandardObserver::named("cie 1931 2deg").unwrap(), StandardObserver::Cie1931);
        assert_eq!(StandardObserver::named("Assignment").unwrap(), StandardObserver::Assignment);
        let e = StandardObserver::named("1976").unwrap_err().to_string();
        assert!(e.contains("an observer") && e.contains("1976"), "{e}");
        let wide = WavelengthRange::new(300.0, 830.0).unwrap();
        let e = StandardObserver::Cie1931.check(wide).unwrap_err().to_string();
        assert_eq!(
            e,
            "expected a range within the CIE 1931 2° observer's data (360–830 nm), found 300–830 nm"
        );
        let e = StandardObserver::Assignment.check(WavelengthRange::VISIBLE).unwrap_err().to_string();
        assert_eq!(
            e,
            "expected a range within the assignment's observer's data (380–780 nm), found 360–830 nm"
        );
        let e = StandardObserver::Cie1964.check(wide).unwrap_err().to_string();
        assert!(e.starts_with("expected a range within the CIE 1964 10° observer's data"), "{e}");
        assert!(StandardObserver::Assignment.check(WavelengthRange::new(380.0, 780.0).unwrap()).is_ok());
    }
}
