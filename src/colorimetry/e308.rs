//! ASTM E308's practice: the tristimulus values of a reflectance measured
//! every 1, 5, 10 or 20 nm, each interval summed as the standard says
//! (ASTM E308-15, section 7; colour-science's `sd_to_XYZ_ASTME308`).
//!
//! - **1 nm**: the sum `Σ S·R·c̄` over the observer's 1 nm table.
//! - **5 nm**: the same sum every 5 nm, against every fifth row of the
//!   1 nm table (E308's "omission" of the rows between), or with 5 nm
//!   weights.
//! - **10 nm**: ASTM E2022 weights (see [`super::astm`]) at 10 nm,
//!   adjusted to the measured range.
//! - **20 nm**: the measurements interpolated to 10 nm (a cubic Lagrange
//!   midpoint between each pair, the ends extended by a quadratic), then
//!   10 nm weights; or 20 nm weights.
//!
//! A measurement at 10 or 20 nm that does not start and end on a multiple
//! of 10 nm is read at 1 nm through its Sprague interpolant (E308 says
//! nothing of it; colour-science does this). The sums run over 360–780 nm
//! (E308's practice range) or the observer's whole table (a CIE 1 nm
//! table: the assignment's observer is refused). Outside the measured
//! range, the sums at 1 and 5 nm read what the [`Sprague`] gives (its end
//! values, or zero if made zero outside); weights fold the rows outside
//! into the end samples (E308's adjustment: the end values held, whatever
//! the interpolant says). The light is read as it is.
//!
//! ```
//! use speclab::colorimetry::e308::Practice;
//! use speclab::data::lights;
//! use speclab::spectrum::{FnSpectrum, Spectrum, StandardObserver, Sprague};
//! let a = FnSpectrum(|l: f64| lights::CIE_A.eval(l.min(780.0))); // held past 780 nm
//! let grey = Sprague::new(400.0, 20.0, vec![0.5; 16])?; // 400–700 nm every 20 nm
//! let xyz = Practice::E308.relative(&grey, &a, StandardObserver::Cie1931)?;
//! assert!((xyz.y - 50.0).abs() < 1e-9);
//! # Ok::<(), speclab::Error>(())
//! ```

use super::Tristimulus;
use super::astm::{Weights, one_nm_table};
use crate::color::Xyz;
use crate::error::Error;
use crate::spectrum::{Constant, Spectrum, Sprague, StandardObserver, WavelengthRange};

/// How the sums are made: ASTM E308's choices, each of which can be
/// turned off to reach the standard's alternatives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Practice {
    /// Sum over 360–780 nm (E308's practice) instead of the observer's
    /// whole table.
    pub practice_range: bool,
    /// 5 nm measurements against every fifth row of the 1 nm observer
    /// instead of 5 nm weights.
    pub omit_5nm: bool,
    /// 20 nm measurements interpolated to 10 nm instead of 20 nm weights.
    pub interpolate_20nm: bool,
}

impl Default for Practice {
    fn default() -> Self {
        Practice::E308
    }
}

/// The sums of a measurement: `Σ S·R·c̄` and the perfect white's `Σ S·ȳ`.
struct Sums {
    xyz: Xyz,
    white: f64,
}

impl Practice {
    /// E308's recommendations: every option on.
    pub const E308: Practice = Practice { practice_range: true, omit_5nm: true, interpolate_20nm: true };
    /// Weights at the measured interval over the observer's whole table
    /// (colour-science's `sd_to_XYZ_tristimulus_weighting_factors_ASTME308`
    /// for 5, 10 and 20 nm).
    pub const WEIGHTS: Practice =
        Practice { practice_range: false, omit_5nm: false, interpolate_20nm: false };

    /// Relative tristimulus values: `Y = 100` for the perfect white under
    /// `light`; errors as [`Practice::absolute`]'s, and
    /// [`Error::Dark`] for a light with no power under ȳ.
    pub fn relative(
        &self,
        measured: &Sprague,
        light: &(impl Spectrum + ?Sized),
        observer: StandardObserver,
    ) -> Result<Xyz, Error> {
        let sums = self.sums(measured, light, observer)?;
        if !(sums.white > 0.0 && sums.white.is_finite()) {
            let range = self.range(observer)?;
            return Err(Error::Dark { range: [range.min(), range.max()] });
        }
        Ok(sums.xyz * (100.0 / sums.white))
    }

    /// The unnormalised sums (`k = 1`), in the light's units times nm; an
    /// error for an interval other than 1, 5, 10 or 20 nm, an observer
    /// without a 1 nm table, or a measured range off the weights' grid.
    pub fn absolute(
        &self,
        measured: &Sprague,
        light: &(impl Spectrum + ?Sized),
        observer: StandardObserver,
    ) -> Result<Xyz, Error> {
        Ok(self.sums(measured, light, observer)?.xyz)
    }

    /// The range of the sums: the observer's data, to 780 nm in practice.
    fn range(&self, observer: StandardObserver) -> Result<WavelengthRange, Error> {
        let data = observer.data_range();
        let max = if self.practice_range { data.max().min(780.0) } else { data.max() };
        WavelengthRange::new(data.min(), max)
    }

    fn sums(
        &self,
        measured: &Sprague,
        light: &(impl Spectrum + ?Sized),
        observer: StandardObserver,
    ) -> Result<Sums, Error> {
        let step = measured.step();
        if ![1.0, 5.0, 10.0, 20.0].contains(&step) {
            return Err(Error::UnknownName {
                what: "an ASTM E308 measurement interval in nm",
                expected: &["1", "5", "10", "20"],
                found: step.to_string(),
            });
        }
        one_nm_table(observer)?;
        let range = self.range(observer)?;
        // At 10 or 20 nm the last sample is off a multiple of 10 nm when
        // the first is.
        let off_tens = measured.range().min() % 10.0 != 0.0;
        let every = |step: f64| integrate(Tristimulus::new(observer, range, step)?, light, measured);
        match step {
            10.0 | 20.0 if off_tens => every(1.0),
            1.0 => every(1.0),
            5.0 if self.omit_5nm => every(5.0),
            _ => {
                let (first, values) = within(measured, range)?;
                let (step, values) = if step == 20.0 && self.interpolate_20nm {
                    (10.0, twenty_to_ten(&values)?)
                } else {
                    (step, values)
                };
                weigh(Tristimulus::new(observer, range, step)?, light, first, &values)
            }
        }
    }
}

/// `Σ S·R·c̄·Δλ` on the grid, and the white's.
fn integrate(grid: Tristimulus, light: &(impl Spectrum + ?Sized), measured: &Sprague) -> Result<Sums, Error> {
    Ok(Sums { xyz: grid.absolute(light, measured), white: grid.absolute(light, &Constant::new(1.0)).y })
}

/// The measured samples within `range`, and the first one's wavelength.
fn within(measured: &Sprague, range: WavelengthRange) -> Result<(f64, Vec<f64>), Error> {
    let (first, step) = (measured.range().min(), measured.step());
    let kept: Vec<(f64, f64)> = (measured.values().iter().enumerate())
        .map(|(i, &v)| (first + step * i as f64, v))
        .filter(|&(lambda, _)| range.contains(lambda))
        .collect();
    match kept[..] {
        [(lambda, _), _, ..] => Ok((lambda, kept.into_iter().map(|(_, v)| v).collect())),
        [_] => Err(Error::Count {
            what: "measured samples within the sums' range",
            found: 1,
            min: 2,
            max: usize::MAX,
        }),
        [] => Err(Error::RangeOutside {
            range: [measured.range().min(), measured.range().max()],
            of: "the sums",
            data: [range.min(), range.max()],
        }),
    }
}

/// E2022 weights at the grid's step, adjusted to the measured range, on
/// the measured values.
fn weigh(
    grid: Tristimulus,
    light: &(impl Spectrum + ?Sized),
    first: f64,
    values: &[f64],
) -> Result<Sums, Error> {
    let last = first + grid.step() * (values.len() - 1) as f64;
    let w = Weights::e2022_unscaled(light, grid)?.trimmed(WavelengthRange::new(first, last)?)?;
    let mut xyz = [0.0; 3];
    for (row, r) in w.rows().iter().zip(values) {
        (0..3).for_each(|c| xyz[c] += row[c] * r);
    }
    Ok(Sums { xyz: Xyz::from(xyz), white: w.rows().iter().map(|r| r[1]).sum() })
}

/// 20 nm measurements at 10 nm: each midpoint the cubic Lagrange
/// polynomial through the four nearest measurements, one more added at
/// each end by a quadratic (ASTM E308-15, 7.5.3).
fn twenty_to_ten(v: &[f64]) -> Result<Vec<f64>, Error> {
    let m = v.len();
    if m < 3 {
        return Err(Error::Count {
            what: "20 nm measurements to interpolate",
            found: m,
            min: 3,
            max: usize::MAX,
        });
    }
    let mut e = Vec::with_capacity(m + 2);
    e.push(3.0 * v[0] - 3.0 * v[1] + v[2]);
    e.extend_from_slice(v);
    e.push(v[m - 3] - 3.0 * v[m - 2] + 3.0 * v[m - 1]);
    let mut out = Vec::with_capacity(2 * m - 1);
    for j in 0..m - 1 {
        out.push(v[j]);
        out.push(-0.0625 * e[j] + 0.5625 * e[j + 1] + 0.5625 * e[j + 2] - 0.0625 * e[j + 3]);
    }
    out.push(v[m - 1]);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn midpoints_follow_cubics_and_ends_quadratics() {
        // A cubic through every point: its midpoints inside, exactly.
        let cubic = |x: f64| 1.0 + x * (0.5 + x * (-0.3 + 0.1 * x));
        let v: Vec<f64> = (0..6).map(|i| cubic(f64::from(i))).collect();
        let ten = twenty_to_ten(&v).unwrap();
        assert_eq!(ten.len(), 11);
        for (i, t) in ten.iter().enumerate().skip(2).take(7) {
            assert!((t - cubic(i as f64 / 2.0)).abs() < 1e-12, "{i}");
        }
        // A quadratic: the extended ends too, so every midpoint.
        let quadratic = |x: f64| 2.0 - x + 0.25 * x * x;
        for m in [3, 6] {
            let v: Vec<f64> = (0..m).map(|i| quadratic(f64::from(i))).collect();
            let ten = twenty_to_ten(&v).unwrap();
            assert_eq!(ten.len(), 2 * m as usize - 1);
            for (i, t) in ten.iter().enumerate() {
                assert!((t - quadratic(i as f64 / 2.0)).abs() < 1e-12, "{m}: {i}");
            }
        }
        assert!(twenty_to_ten(&[1.0, 2.0]).is_err());
    }

    #[test]
    fn intervals_ranges_and_lights_are_checked() {
        let e = Constant::new(1.0);
        let two = Sprague::new(400.0, 2.0, vec![0.5; 151]).unwrap();
        let message = Practice::E308.relative(&two, &e, StandardObserver::Cie1931).unwrap_err().to_string();
        assert_eq!(message, "expected an ASTM E308 measurement interval in nm (1, 5, 10 or 20), found \"2\"");
        let beyond = Sprague::new(790.0, 10.0, vec![0.5; 6]).unwrap();
        let message =
            Practice::E308.relative(&beyond, &e, StandardObserver::Cie1931).unwrap_err().to_string();
        assert_eq!(message, "expected a range within the sums's data (360–780 nm), found 790–840 nm");
        let last = Sprague::new(780.0, 10.0, vec![0.5; 6]).unwrap();
        let message = Practice::E308.relative(&last, &e, StandardObserver::Cie1931).unwrap_err().to_string();
        assert_eq!(message, "expected measured samples within the sums' range: at least 2, found 1");
        let off_grid = Sprague::new(402.0, 5.0, vec![0.5; 40]).unwrap();
        let message = Practice::WEIGHTS.relative(&off_grid, &e, StandardObserver::Cie1931).unwrap_err();
        assert!(matches!(message, Error::OffGrid { first: 360.0, step: 5.0, .. }), "{message}");
        let grey = Sprague::new(400.0, 10.0, vec![0.5; 31]).unwrap();
        let dark = Practice::E308.relative(&grey, &Constant::new(0.0), StandardObserver::Cie1964);
        assert_eq!(
            dark.unwrap_err().to_string(),
            "expected a light with power under ȳ within 360–780 nm, found none"
        );
        let one_nm = Sprague::new(400.0, 1.0, vec![0.5; 301]).unwrap();
        for measured in [&grey, &one_nm] {
            let message = Practice::E308.relative(measured, &e, StandardObserver::Assignment).unwrap_err();
            assert!(matches!(message, Error::UnknownName { .. }), "{message}");
        }
        assert_eq!(Practice::default(), Practice::E308);
    }

    #[test]
    fn a_grey_is_its_reflectance_at_every_interval() {
        let e = Constant::new(1.0);
        for step in [1.0, 5.0, 10.0, 20.0] {
            let n = (300.0 / step) as usize + 1;
            for practice in [Practice::E308, Practice::WEIGHTS] {
                let grey = Sprague::new(400.0, step, vec![0.25; n]).unwrap();
                let xyz = practice.relative(&grey, &e, StandardObserver::Cie1931).unwrap();
                assert!((xyz.y - 25.0).abs() < 1e-12, "{step} nm, {practice:?}: {xyz:?}");
                let sums = practice.absolute(&grey, &e, StandardObserver::Cie1931).unwrap();
                // Σ ȳ·Δλ of the 1 nm table, over 360–780 nm (E308) or 360–830 nm.
                let y = StandardObserver::Cie1931.y_integral(self::range(practice)).unwrap();
                assert!((sums.y / xyz.y - y / 100.0).abs() < 2e-3 * y / 100.0, "{step} nm: {sums:?}");
            }
        }
    }

    #[test]
    fn one_nm_and_off_tens_measurements_are_summed_every_nanometre() {
        let ramp = crate::spectrum::FnSpectrum(|lambda: f64| lambda / 100.0);
        let every_nm =
            Tristimulus::new(StandardObserver::Cie1931, WavelengthRange::new(360.0, 780.0).unwrap(), 1.0)
                .unwrap();
        // A 1 nm measurement, zero outside, and a 10 nm one starting at 405 nm.
        let one = Sprague::new(400.0, 1.0, (0..301).map(|i| 0.2 + 0.001 * f64::from(i)).collect()).unwrap();
        let ten = Sprague::new(405.0, 10.0, (0..30).map(|i| 0.3 + 0.01 * f64::from(i)).collect()).unwrap();
        let close = |a: Xyz, b: Xyz| (a - b).to_array().iter().all(|d| d.abs() < 1e-12);
        for measured in [one.zero_outside(), ten] {
            let e308 = Practice::E308.relative(&measured, &ramp, StandardObserver::Cie1931).unwrap();
            let sum = every_nm.relative(&ramp, &measured).unwrap();
            assert!(close(e308, sum), "{e308:?} against {sum:?}");
        }
        // 5 nm: E308 sums every fifth row; weights differ from it.
        let five =
            Sprague::new(400.0, 5.0, (0..61).map(|i| 0.2 + 0.1 * (0.3 * f64::from(i)).sin()).collect())
                .unwrap();
        let e308 = Practice::E308.relative(&five, &ramp, StandardObserver::Cie1931).unwrap();
        let every_5nm = every_nm.with_step(5.0).unwrap().relative(&ramp, &five).unwrap();
        let weights =
            Practice { omit_5nm: false, ..Practice::E308 }.relative(&five, &ramp, StandardObserver::Cie1931);
        assert!(close(e308, every_5nm) && !close(e308, weights.unwrap()), "{e308:?}");
        // Samples past 780 nm are left out of E308's sums, as if never measured.
        let wide: Vec<f64> = (0..48).map(|i| 0.5 + 0.2 * (0.4 * f64::from(i)).cos()).collect();
        let (all, kept) = (
            Sprague::new(360.0, 10.0, wide.clone()).unwrap(),
            Sprague::new(360.0, 10.0, wide[..43].to_vec()).unwrap(),
        );
        let (a, b) = [all, kept]
            .map(|m| Practice::E308.relative(&m, &ramp, StandardObserver::Cie1931).unwrap())
            .into();
        assert!(close(a, b), "{a:?} against {b:?}");
    }

    fn range(practice: Practice) -> WavelengthRange {
        practice.range(StandardObserver::Cie1931).unwrap()
    }
}
