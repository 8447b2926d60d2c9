//! Tristimulus values as colour scientists compute them: sums over a grid
//! of wavelengths at a step, relative to the perfect white under the light.
//!
//! `X = k · Σ S(λ)·R(λ)·x̄(λ)·Δλ` over `λ = min, min + Δλ, …, ≤ max`, and
//! `k = 100 / Σ S(λ)·ȳ(λ)·Δλ`, so that the perfect white (R = 1) has
//! `Y = 100` (CIE 015:2018, 7.1; colour-science's "integration" method).
//! The spectra are read at the grid's wavelengths as they are: their own
//! interpolants between their samples, and what they give outside their
//! data (see the partial-spectrum policy of `io::Load`).
//!
//! ```
//! use speclab::colorimetry::Tristimulus;
//! use speclab::data::{lights, patches};
//! let t = Tristimulus::CIE_1931;
//! let white = t.white(&lights::D65)?;
//! assert!((white.y - 100.0).abs() < 1e-12);
//! let red = t.relative(&lights::D65, &patches::G4)?;
//! assert!(red.y > 5.0 && red.y < 30.0);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::Error;
use crate::spectrum::{Constant, Spectrum, StandardObserver, WavelengthRange};

/// An observer, a range within its data and a step: how to sum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tristimulus {
    observer: StandardObserver,
    range: WavelengthRange,
    step: f64,
}

impl Tristimulus {
    /// The CIE 1931 2° observer over 360–830 nm at 1 nm.
    pub const CIE_1931: Tristimulus =
        Tristimulus { observer: StandardObserver::Cie1931, range: WavelengthRange::VISIBLE, step: 1.0 };
    /// The CIE 1964 10° observer over 360–830 nm at 1 nm.
    pub const CIE_1964: Tristimulus =
        Tristimulus { observer: StandardObserver::Cie1964, range: WavelengthRange::VISIBLE, step: 1.0 };

    /// Sums with `observer` over `range` at `step` nm; an error if the
    /// observer has no data over the range, or the step is not positive,
    /// finite and at most the range's width.
    pub fn new(observer: StandardObserver, range: WavelengthRange, step: f64) -> Result<Self, Error> {
        let range = observer.check(range)?;
        if !(step > 0.0 && step <= range.width()) {
            return Err(Error::Step { step, width: range.width() });
        }
        Ok(Tristimulus { observer, range, step })
    }

    /// The same sums at `step` nm; an error as [`Tristimulus::new`]'s.
    pub fn with_step(self, step: f64) -> Result<Self, Error> {
        Tristimulus::new(self.observer, self.range, step)
    }

    /// The same sums over `range`, checked as [`Tristimulus::new`] checks.
    pub fn over(self, range: WavelengthRange) -> Result<Self, Error> {
        Tristimulus::new(self.observer, range, self.step)
    }

    /// The same sums over `range` (for constants; the caller checks it
    /// against the observer's data).
    pub(crate) const fn with_range(self, range: WavelengthRange) -> Self {
        Tristimulus { range, ..self }
    }

    /// The observer.
    #[must_use]
    pub const fn observer(self) -> StandardObserver {
        self.observer
    }

    /// The range.
    #[must_use]
    pub const fn range(self) -> WavelengthRange {
        self.range
    }

    /// The step, nm.
    #[must_use]
    pub const fn step(self) -> f64 {
        self.step
    }

    /// The grid: `min + i·step` for every `i` up to `max` (within 1e-9 of a step).
    pub fn wavelengths(self) -> impl Iterator<Item = f64> {
        let count = (self.range.width() / self.step + 1e-9).floor() as usize;
        (0..=count).map(move |i| self.range.min() + self.step * i as f64)
    }

    /// `Σ S·R·c̄·Δλ`: in the light's units times nm, not normalised.
    pub fn absolute<L, R>(self, light: &L, reflectance: &R) -> Xyz
    where
        L: Spectrum + ?Sized,
        R: Spectrum + ?Sized,
    {
        let mut sum = [0.0; 3];
        for lambda in self.wavelengths() {
            let s = light.eval(lambda) * reflectance.eval(lambda);
            let bar = self.observer.xyz_bar(lambda);
            (0..3).for_each(|c| sum[c] += s * bar[c]);
        }
        Xyz::from(sum) * self.step
    }

    /// Relative tristimulus values: [`Tristimulus::absolute`] scaled so
    /// that the perfect white under `light` has `Y = 100`; an error if the
    /// light has no power under ȳ on the grid.
    pub fn relative<L, R>(self, light: &L, reflectance: &R) -> Result<Xyz, Error>
    where
        L: Spectrum + ?Sized,
        R: Spectrum + ?Sized,
    {
        let white = self.absolute(light, &Constant::new(1.0)).y;
        if !(white > 0.0 && white.is_finite()) {
            return Err(Error::Dark { range: [self.range.min(), self.range.max()] });
        }
        Ok(self.absolute(light, reflectance) * (100.0 / white))
    }

    /// The perfect white under `light` ([`Tristimulus::relative`] of a
    /// reflectance of 1): the light's own colour with `Y = 100`.
    pub fn white<L: Spectrum + ?Sized>(self, light: &L) -> Result<Xyz, Error> {
        self.relative(light, &Constant::new(1.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_and_checks() {
        let r = WavelengthRange::new(360.0, 830.0).unwrap();
        let t = Tristimulus::new(StandardObserver::Cie1931, r, 20.0).unwrap();
        let grid: Vec<f64> = t.wavelengths().collect();
        assert_eq!(
            (grid.len(), grid[0], grid[23]),
            (24, 360.0, 820.0),
            "830 is not on a 20 nm grid from 360"
        );
        assert_eq!(Tristimulus::new(StandardObserver::Cie1931, r, 10.0).unwrap().wavelengths().count(), 48);
        for step in [0.0, -1.0, f64::NAN, 471.0] {
            assert!(matches!(Tristimulus::new(StandardObserver::Cie1931, r, step), Err(Error::Step { .. })));
        }
        let wide = WavelengthRange::new(300.0, 830.0).unwrap();
        assert!(matches!(
            Tristimulus::new(StandardObserver::Cie1964, wide, 1.0),
            Err(Error::RangeOutside { .. })
        ));
        let t = Tristimulus::CIE_1964;
        assert_eq!(
            (t.observer(), t.range(), t.step()),
            (StandardObserver::Cie1964, WavelengthRange::VISIBLE, 1.0)
        );
    }

    #[test]
    fn the_equal_energy_white_sums_the_tables() {
        let e = Constant::new(1.0);
        let xyz = Tristimulus::CIE_1931.absolute(&e, &e);
        let (_, _, rows) = StandardObserver::Cie1931.table().unwrap();
        let y: f64 = rows.iter().map(|r| r[1]).sum();
        assert!((xyz.y - y).abs() < 1e-12);
        let rel = Tristimulus::CIE_1931.relative(&e, &Constant::new(0.5)).unwrap();
        assert!((rel.y - 50.0).abs() < 1e-12);
        let dark = Tristimulus::CIE_1931.white(&Constant::new(0.0)).unwrap_err();
        assert_eq!(dark.to_string(), "expected a light with power under ȳ within 360–830 nm, found none");
    }
}
