//! ASTM E308 weighting tables: tristimulus values from reflectances
//! measured every 10 or 20 nm, as the ASTM computes its tables.
//!
//! A weight `Wᵢ` stands for a whole stretch of the 1 nm sum `Σ S·R·c̄`:
//! the reflectance between two measured wavelengths is taken as the
//! Lagrange polynomial through the nearest measurements (cubic inside,
//! quadratic in the first and last interval), so each 1 nm term `S·c̄`
//! is shared among those measurements by the Lagrange coefficients (ASTM
//! E2022; the construction of ASTM E308's Table 5). The observer's 1 nm
//! table over 360–830 nm is summed; nanometres past the last measured
//! wavelength go to the last weight; the table is scaled so that the
//! perfect white has `Y = 100`. [`Weights::trimmed`] folds the weights
//! outside a measured range into its ends (E308's adjustment).
//!
//! ```
//! use speclab::colorimetry::astm::Weights;
//! use speclab::data::lights;
//! use speclab::colorimetry::Tristimulus;
//! let w = Weights::e2022(&lights::CIE_D65, Tristimulus::CIE_1931.with_step(20.0)?)?;
//! assert_eq!((w.first(), w.step(), w.rows().len()), (360.0, 20.0, 24));
//! let y: f64 = w.rows().iter().map(|r| r[1]).sum();
//! assert!((y - 100.0).abs() < 1e-12);
//! # Ok::<(), speclab::Error>(())
//! ```

use super::Tristimulus;
use crate::color::Xyz;
use crate::error::Error;
use crate::spectrum::{Spectrum, StandardObserver, WavelengthRange};

/// The largest step, nm.
pub const MAX_STEP: usize = 20;

/// Weights `[W_x, W_y, W_z]` at `first + i·step` nm.
#[derive(Clone, Debug, PartialEq)]
pub struct Weights {
    first: f64,
    step: usize,
    rows: Vec<[f64; 3]>,
}

impl Weights {
    /// ASTM E2022's weights for `light` on `grid`: its observer's 1 nm
    /// table summed over its range, a weight every `grid.step()` nm (a
    /// whole number, 1 to [`MAX_STEP`]) from the range's start (a whole
    /// nanometre), scaled so that `Σ W_y = 100`. The light is read at
    /// every nanometre of the range as it is (a table stopping at 780 nm is
    /// zero beyond: hold its end with `io::Extend::Hold` for the ASTM's
    /// practice).
    pub fn e2022(light: &(impl Spectrum + ?Sized), grid: Tristimulus) -> Result<Self, Error> {
        let mut w = Self::e2022_unscaled(light, grid)?;
        let k = 100.0 / w.rows.iter().map(|r| r[1]).sum::<f64>();
        if !k.is_finite() {
            return Err(Error::Dark { range: [grid.range().min(), grid.range().max()] });
        }
        w.rows.iter_mut().for_each(|r| *r = r.map(|v| v * k));
        Ok(w)
    }

    /// [`Weights::e2022`] not normalised (`k = 1`): `Σ W_y` is the light's
    /// `Σ S·ȳ` over the range, nm. An [`Error::UnknownName`] for an
    /// observer without a 1 nm table, an [`Error::Step`] for a step that
    /// is not a whole number from 1 to [`MAX_STEP`] or leaves fewer than
    /// three weights, an [`Error::OffGrid`] for a range with ends off the
    /// table's nanometres.
    pub fn e2022_unscaled(light: &(impl Spectrum + ?Sized), grid: Tristimulus) -> Result<Self, Error> {
        let (first, cmf) = one_nm_table(grid.observer())?;
        let step = grid.step();
        if !(step.fract() == 0.0 && (1.0..=MAX_STEP as f64).contains(&step)) {
            return Err(Error::Step { step, width: MAX_STEP as f64 });
        }
        let (lo, hi) = (grid.range().min() - first, grid.range().max() - first);
        if lo.fract() != 0.0 || hi.fract() != 0.0 {
            return Err(Error::OffGrid { range: [grid.range().min(), grid.range().max()], first, step: 1.0 });
        }
        if hi - lo < 2.0 * step {
            // Three weights at least: the Lagrange polynomials' stencil.
            return Err(Error::Step { step, width: 0.5 * (hi - lo) });
        }
        let rows = &cmf[lo as usize..=hi as usize];
        let min = grid.range().min();
        let sc: Vec<[f64; 3]> =
            rows.iter().enumerate().map(|(i, c)| c.map(|v| v * light.eval(min + i as f64))).collect();
        Ok(Weights { first: min, step: step as usize, rows: lagrange_weights(&sc, step as usize) })
    }

    /// A table of one's own (a published one): `rows` at `first + i·step`
    /// nm; an error unless there are rows and `step` is 1 to [`MAX_STEP`].
    pub fn from_rows(first: f64, step: usize, rows: Vec<[f64; 3]>) -> Result<Self, Error> {
        if !(1..=MAX_STEP).contains(&step) {
            return Err(Error::Step { step: step as f64, width: MAX_STEP as f64 });
        }
        if rows.is_empty() || !first.is_finite() {
            return Err(Error::Count {
                what: "a weighting table's rows",
                found: rows.len(),
                min: 1,
                max: usize::MAX,
            });
        }
        Ok(Weights { first, step, rows })
    }

    /// The first wavelength, nm.
    #[must_use]
    pub fn first(&self) -> f64 {
        self.first
    }

    /// The step, nm.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step as f64
    }

    /// The weights, one row per wavelength.
    #[must_use]
    pub fn rows(&self) -> &[[f64; 3]] {
        &self.rows
    }

    /// The table for reflectances measured over `range` only (its ends on
    /// the table's wavelengths): each weight below the range added to the
    /// first inside, each above to the last (ASTM E308, 7.3.2).
    pub fn trimmed(&self, range: WavelengthRange) -> Result<Self, Error> {
        let index = |lambda: f64| (lambda - self.first) / self.step as f64;
        let (lo, hi) = (index(range.min()), index(range.max()));
        let inside = |i: f64| i >= 0.0 && i <= (self.rows.len() - 1) as f64;
        if !(inside(lo) && inside(hi)) {
            return Err(Error::RangeOutside {
                range: [range.min(), range.max()],
                of: "the weighting table",
                data: [self.first, self.first + (self.step * (self.rows.len() - 1)) as f64],
            });
        }
        if lo.fract() != 0.0 || hi.fract() != 0.0 {
            let (first, step) = (self.first, self.step as f64);
            return Err(Error::OffGrid { range: [range.min(), range.max()], first, step });
        }
        let (lo, hi) = (lo as usize, hi as usize);
        let mut rows = self.rows[lo..=hi].to_vec();
        let sum =
            |part: &[[f64; 3]]| part.iter().fold([0.0; 3], |a, r| [a[0] + r[0], a[1] + r[1], a[2] + r[2]]);
        let (below, above) = (sum(&self.rows[..lo]), sum(&self.rows[hi + 1..]));
        let last = rows.len() - 1;
        (0..3).for_each(|c| {
            rows[0][c] += below[c];
            rows[last][c] += above[c];
        });
        Ok(Weights { first: range.min(), step: self.step, rows })
    }

    /// `Σ Wᵢ·R(λᵢ)`: the tristimulus values of `reflectance` read at the
    /// table's wavelengths.
    pub fn xyz(&self, reflectance: &(impl Spectrum + ?Sized)) -> Xyz {
        let mut sum = [0.0; 3];
        for (i, w) in self.rows.iter().enumerate() {
            let r = reflectance.eval(self.first + (self.step * i) as f64);
            (0..3).for_each(|c| sum[c] += w[c] * r);
        }
        Xyz::from(sum)
    }
}

/// The observer's 1 nm table (its first wavelength and rows), or an
/// [`Error::UnknownName`] for an observer without one.
pub(super) fn one_nm_table(observer: StandardObserver) -> Result<(f64, &'static [[f64; 3]]), Error> {
    match observer.table() {
        Some((first, 1.0, rows)) => Ok((first, rows)),
        _ => Err(Error::UnknownName {
            what: "an observer with a 1 nm table",
            expected: &["CIE 1931", "CIE 1964"],
            found: observer.name().to_string(),
        }),
    }
}

/// ASTM E2022's Lagrange coefficients for a measurement `interval` (in
/// whole nanometres): for each of the `interval − 1` nanometres between
/// two measurements, the weights of the four around it inside the range
/// (cubic, `inner`) and of the three at its ends (quadratic,
/// `boundary`): E2022's Tables A and B (colour-science's
/// `lagrange_coefficients_ASTME2022`). Empty for an interval below 2.
///
/// ```
/// use speclab::colorimetry::astm::lagrange_coefficients;
/// let (inner, boundary) = lagrange_coefficients(10);
/// assert_eq!((inner.len(), boundary.len()), (9, 9));
/// assert_eq!(inner[4], [-0.0625, 0.5625, 0.5625, -0.0625]);
/// assert!((boundary[0][0] - 0.855).abs() < 1e-15);
/// ```
#[must_use]
pub fn lagrange_coefficients(interval: usize) -> (Vec<[f64; 4]>, Vec<[f64; 3]>) {
    let at = |t: usize| t as f64 / interval as f64;
    let inner = (1..interval).map(|t| lagrange::<4>(1.0 + at(t))).collect();
    let boundary = (1..interval).map(|t| lagrange::<3>(at(t))).collect();
    (inner, boundary)
}

/// The Lagrange basis polynomials through nodes 0, 1, …, n − 1, at `r`.
fn lagrange<const N: usize>(r: f64) -> [f64; N] {
    std::array::from_fn(|j| {
        (0..N).filter(|&m| m != j).map(|m| (r - m as f64) / (j as f64 - m as f64)).product()
    })
}

/// ASTM E2022's unscaled weights from the 1 nm products `S·c̄`: the
/// sample's own term, then each nanometre between measurements shared by
/// the Lagrange coefficients of its interval (quadratic in the first and
/// last, cubic inside), then the nanometres past the last measurement.
fn lagrange_weights(sc: &[[f64; 3]], step: usize) -> Vec<[f64; 3]> {
    let n = sc.len();
    let inner_count = step - 1;
    let mut w: Vec<[f64; 3]> = sc.iter().step_by(step).copied().collect();
    let last = w.len() - 1;
    let (inner, boundary) = lagrange_coefficients(step);
    let mut add = |row: usize, coefficient: f64, term: [f64; 3]| {
        (0..3).for_each(|c| w[row][c] += coefficient * term[c])
    };
    for t in 0..inner_count {
        (0..3).for_each(|g| add(g, boundary[t][g], sc[t + 1]));
    }
    let first_of_last = n - (n - 1) % step - 1 - inner_count;
    for t in 0..inner_count {
        for g in (last - 2..=last).rev() {
            add(g, boundary[inner_count - t - 1][last - g], sc[first_of_last + t]);
        }
    }
    for q in 0..last - 2 {
        for (t, coefficients) in inner.iter().enumerate() {
            let at = step * (q + 1) + 1 + t;
            (0..4).for_each(|j| add(q + j, coefficients[j], sc[at]));
        }
    }
    for term in &sc[n - (n - 1) % step..] {
        add(last, 1.0, *term);
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Constant;

    #[test]
    fn lagrange_coefficients_interpolate() {
        // Nodes 0, 1, 2, 3 at 1.5: the cubic's midpoint weights.
        assert_eq!(lagrange::<4>(1.5), [-0.0625, 0.5625, 0.5625, -0.0625]);
        assert_eq!(lagrange::<3>(0.5), [0.375, 0.75, -0.125]);
        for r in [0.1, 0.7, 1.3] {
            assert!((lagrange::<4>(r).iter().sum::<f64>() - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn one_nanometre_weights_are_the_table() {
        let w = Weights::e2022_unscaled(&Constant::new(1.0), Tristimulus::CIE_1931).unwrap();
        let (_, _, rows) = StandardObserver::Cie1931.table().unwrap();
        assert_eq!(w.rows(), rows);
        // Any step: a constant reflectance sums to the white, Y = 100.
        for step in [2.0, 5.0, 10.0, 20.0] {
            let w =
                Weights::e2022(&Constant::new(1.0), Tristimulus::CIE_1964.with_step(step).unwrap()).unwrap();
            assert!((w.xyz(&Constant::new(0.5)).y - 50.0).abs() < 1e-12, "{step}");
        }
    }

    #[test]
    fn bad_steps_observers_and_ranges() {
        let e = Constant::new(1.0);
        for step in [21.0, 2.5] {
            let grid = Tristimulus::CIE_1931.with_step(step).unwrap();
            assert!(matches!(Weights::e2022(&e, grid), Err(Error::Step { .. })), "{step}");
        }
        let assignment =
            Tristimulus::new(StandardObserver::Assignment, WavelengthRange::ASSIGNMENT, 10.0).unwrap();
        let a = Weights::e2022(&e, assignment).unwrap_err().to_string();
        assert!(a.contains("an observer with a 1 nm table"), "{a}");
        assert!(matches!(
            Weights::e2022(&Constant::new(0.0), Tristimulus::CIE_1931.with_step(10.0).unwrap()),
            Err(Error::Dark { .. })
        ));
        let w = Weights::e2022(&e, Tristimulus::CIE_1931.with_step(20.0).unwrap()).unwrap();
        for (a, b) in [(340.0, 700.0), (400.0, 840.0), (359.0, 700.0), (400.0, 821.0)] {
            let e = w.trimmed(WavelengthRange::new(a, b).unwrap()).unwrap_err().to_string();
            let expected =
                format!("expected a range within the weighting table's data (360–820 nm), found {a}–{b} nm");
            assert_eq!(e, expected);
        }
        for (a, b) in [(410.0, 700.0), (400.0, 710.0)] {
            let e = w.trimmed(WavelengthRange::new(a, b).unwrap()).unwrap_err().to_string();
            assert_eq!(e, format!("expected a range with ends on 360, 380, 400, … nm, found {a}–{b} nm"));
        }
        let whole = w.trimmed(WavelengthRange::new(360.0, 820.0).unwrap()).unwrap();
        assert_eq!(whole, w);
        let t = w.trimmed(WavelengthRange::new(400.0, 700.0).unwrap()).unwrap();
        assert_eq!((t.first(), t.step(), t.rows().len()), (400.0, 20.0, 16));
        assert!(Weights::from_rows(f64::NAN, 20, vec![[1.0; 3]]).is_err());
        assert!(Weights::from_rows(360.0, 20, vec![]).is_err());
        assert!(Weights::from_rows(360.0, 0, vec![[1.0; 3]]).is_err());
        let own = Weights::from_rows(400.0, 5, vec![[1.0; 3]; 3]).unwrap();
        assert_eq!((own.first(), own.step(), own.rows().len()), (400.0, 5.0, 3));
        // Each weight reads the reflectance at its own wavelength.
        let diagonal =
            Weights::from_rows(400.0, 10, vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).unwrap();
        let ramp = crate::spectrum::FnSpectrum(|lambda: f64| lambda);
        assert_eq!(diagonal.xyz(&ramp), Xyz::new(400.0, 410.0, 420.0));
        for c in 0..3 {
            let (all, kept): (f64, f64) =
                (w.rows().iter().map(|r| r[c]).sum(), t.rows().iter().map(|r| r[c]).sum());
            assert!((all - kept).abs() < 1e-12, "nothing lost in channel {c}");
        }
    }

    #[test]
    fn weights_over_a_range_of_whole_nanometres() {
        let e = Constant::new(1.0);
        let r = |a, b| WavelengthRange::new(a, b).unwrap();
        let grid = |a, b, step| Tristimulus::new(StandardObserver::Cie1931, r(a, b), step).unwrap();
        let w = Weights::e2022_unscaled(&e, grid(400.0, 700.0, 1.0)).unwrap();
        let (_, _, rows) = StandardObserver::Cie1931.table().unwrap();
        assert_eq!((w.first(), w.rows()), (400.0, &rows[40..=340]));
        let ten = Weights::e2022(&e, grid(360.0, 780.0, 10.0)).unwrap();
        assert_eq!((ten.first(), ten.step(), ten.rows().len()), (360.0, 10.0, 43));
        for (a, b) in [(400.5, 700.0), (400.0, 700.5)] {
            let off = Weights::e2022(&e, grid(a, b, 10.0)).unwrap_err().to_string();
            assert_eq!(off, format!("expected a range with ends on 360, 361, 362, … nm, found {a}–{b} nm"));
        }
        let short = Weights::e2022(&e, grid(400.0, 419.0, 10.0)).unwrap_err().to_string();
        assert_eq!(short, "expected a wavelength step in (0, 9.5] nm, found 10");
        assert_eq!(Weights::e2022(&e, grid(400.0, 420.0, 10.0)).unwrap().rows().len(), 3);
        // The light is read at each nanometre of the range: a ramp's
        // 1 nm weights are the table's rows times the wavelength.
        let ramp = crate::spectrum::FnSpectrum(|lambda: f64| lambda);
        let w = Weights::e2022_unscaled(&ramp, grid(400.0, 420.0, 1.0)).unwrap();
        for (i, row) in w.rows().iter().enumerate() {
            let want = rows[40 + i].map(|v| v * (400.0 + i as f64));
            assert_eq!(*row, want, "{i}");
        }
    }
}
