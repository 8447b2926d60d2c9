//! The two densities given by a formula, over a range each carries:
//! [`Uniform`] and pbrt-v4's [`Visible`]. Each has the assignment's range
//! (`ASSIGNMENT`, 380–730 nm: the study's, Appendix 2's) and the
//! renderers' (`VISIBLE`, 360–830 nm: pbrt-v4's and Mitsuba 3's), or any
//! other (`over`).
//!
//! ```
//! use speclab::sampling::pdf::{Uniform, Visible, WavelengthPdf};
//! use speclab::spectrum::WavelengthRange;
//! assert_eq!(Uniform::VISIBLE.pdf(360.0), 1.0 / 470.0);
//! // pbrt-v4's VisibleWavelengthsPDF at 538 nm: 0.0039398042.
//! assert!((Visible::VISIBLE.pdf(538.0) - 0.003_939_804_2).abs() < 1e-10);
//! let uv = Uniform::over(WavelengthRange::new(300.0, 900.0)?);
//! assert_eq!(uv.sample(0.5), 600.0);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::sampling::density::{WavelengthPdf, reciprocal};
use crate::spectrum::WavelengthRange;
use crate::spectrum::float::sealed::Sealed;

/// Clamps `u` into `[0, 1)`; NaN becomes 0.
#[inline]
pub(crate) fn unit(u: f64) -> f64 {
    if u > 0.0 { u.min(f64::BELOW_ONE) } else { 0.0 }
}

/// The uniform density `1/W` over a range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Uniform {
    range: WavelengthRange,
}

impl Default for Uniform {
    /// The assignment's range, 380–730 nm.
    fn default() -> Self {
        Uniform::ASSIGNMENT
    }
}

impl Uniform {
    /// Over 380–730 nm.
    pub const ASSIGNMENT: Uniform = Uniform { range: WavelengthRange::ASSIGNMENT };
    /// Over 360–830 nm.
    pub const VISIBLE: Uniform = Uniform { range: WavelengthRange::VISIBLE };

    /// Over `range`.
    #[must_use]
    pub const fn over(range: WavelengthRange) -> Self {
        Uniform { range }
    }

    /// The range.
    #[must_use]
    pub const fn range(self) -> WavelengthRange {
        self.range
    }
}

impl WavelengthPdf for Uniform {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        self.range.min() + self.range.width() * unit(u)
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        if self.range.contains(lambda) { 1.0 / self.range.width() } else { 0.0 }
    }

    /// Exactly `W` inside the range.
    #[inline]
    fn inv_pdf(&self, lambda: f64) -> f64 {
        if self.range.contains(lambda) { self.range.width() } else { 0.0 }
    }

    fn cdf(&self, lambda: f64) -> Option<f64> {
        let c = (lambda - self.range.min()) / self.range.width();
        Some(if c > 0.0 { c.min(1.0) } else { 0.0 })
    }

    fn support(&self) -> WavelengthRange {
        self.range
    }

    fn is_uniform(&self) -> bool {
        true
    }
}

/// pbrt-v4's visible-wavelength density, `∝ 1/cosh²(a·(λ − 538))` with
/// `a = 0.0072/nm`, normalised over a range (pbrt-v4's own: 360–830 nm,
/// [`Visible::VISIBLE`]). Its CDF is a difference of `tanh`, inverted by
/// one `atanh` per wavelength.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Visible {
    range: WavelengthRange,
    /// `tanh(a·(min − 538))`.
    t0: f64,
    /// `tanh(a·(max − 538))`.
    t1: f64,
}

impl Default for Visible {
    /// The assignment's range, 380–730 nm.
    fn default() -> Self {
        Visible::ASSIGNMENT
    }
}

impl Visible {
    /// `a`, the density's slope, 1/nm (pbrt-v4's 0.0072).
    pub const SLOPE: f64 = 0.0072;
    /// The density's peak, nm (pbrt-v4's 538).
    pub const CENTER: f64 = 538.0;

    /// Renormalised to 380–730 nm (`tanh` at the ends as literals; a test
    /// checks them).
    pub const ASSIGNMENT: Visible = Visible {
        range: WavelengthRange::ASSIGNMENT,
        t0: -0.813_604_361_381_150_8,
        t1: 0.881_487_552_831_487_7,
    };
    /// Over 360–830 nm: pbrt-v4's `VisibleWavelengthsPDF` and
    /// `SampleVisibleWavelengths`.
    pub const VISIBLE: Visible =
        Visible { range: WavelengthRange::VISIBLE, t0: -0.856_910_625_469_828, t1: 0.970_591_346_940_269_8 };

    /// Normalised over `range`.
    #[must_use]
    pub fn over(range: WavelengthRange) -> Self {
        Visible { range, t0: Self::tanh_at(range.min()), t1: Self::tanh_at(range.max()) }
    }

    /// The range.
    #[must_use]
    pub const fn range(self) -> WavelengthRange {
        self.range
    }

    /// `[tanh(a·(min − 538)), tanh(a·(max − 538))]`: the CDF's numerator
    /// at the range's ends (what a shader drawing from this density needs
    /// besides [`Visible::SLOPE`] and [`Visible::CENTER`]).
    #[must_use]
    pub const fn tanh_ends(self) -> [f64; 2] {
        [self.t0, self.t1]
    }

    /// `tanh(a·(λ − 538))`, the CDF's numerator.
    #[inline]
    fn tanh_at(lambda: f64) -> f64 {
        (Self::SLOPE * (lambda - Self::CENTER)).tanh()
    }

    /// `a / (t1 − t0)`: the density is this times `1 − tanh²`.
    #[inline]
    fn norm(&self) -> f64 {
        Self::SLOPE / (self.t1 - self.t0)
    }
}

impl WavelengthPdf for Visible {
    #[inline]
    fn sample(&self, u: f64) -> f64 {
        self.sample_with_inv_pdf(u).0
    }

    #[inline]
    fn pdf(&self, lambda: f64) -> f64 {
        if !self.range.contains(lambda) {
            return 0.0;
        }
        let y = Self::tanh_at(lambda);
        self.norm() * (1.0 - y * y)
    }

    fn cdf(&self, lambda: f64) -> Option<f64> {
        if lambda.is_nan() {
            return Some(0.0);
        }
        let l = lambda.clamp(self.range.min(), self.range.max());
        Some((Self::tanh_at(l) - self.t0) / (self.t1 - self.t0))
    }

    fn support(&self) -> WavelengthRange {
        self.range
    }

    /// One `atanh`: at `y = tanh(a·(λ − 538))`, `1/cosh² = 1 − y²`, so the
    /// density needs no `cosh`.
    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let y = self.t0 + unit(u) * (self.t1 - self.t0);
        let lambda = (Self::CENTER + y.atanh() / Self::SLOPE).clamp(self.range.min(), self.range.max());
        (lambda, reciprocal(self.norm() * (1.0 - y * y)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_literals_are_the_tanh_of_the_ends() {
        for v in [Visible::ASSIGNMENT, Visible::VISIBLE] {
            let computed = Visible::over(v.range());
            assert!((v.t0 - computed.t0).abs() <= 2.0 * f64::EPSILON, "{v:?}");
            assert!((v.t1 - computed.t1).abs() <= 2.0 * f64::EPSILON, "{v:?}");
            // What a shader is given, from the public constants alone.
            let ends =
                [v.range().min(), v.range().max()].map(|l| (Visible::SLOPE * (l - Visible::CENTER)).tanh());
            (0..2).for_each(|i| assert!((v.tanh_ends()[i] - ends[i]).abs() <= 2.0 * f64::EPSILON, "{v:?}"));
            // The density integrates to 1 over its range (midpoint rule, 0.01 nm).
            let (r, n) = (v.range(), 47_000);
            let h = r.width() / f64::from(n);
            let total: f64 = (0..n).map(|i| v.pdf(r.min() + (f64::from(i) + 0.5) * h)).sum::<f64>() * h;
            assert!((total - 1.0).abs() < 1e-9, "{total}");
        }
        assert_eq!(Visible::default(), Visible::ASSIGNMENT);
        assert_eq!(Uniform::default().range(), WavelengthRange::ASSIGNMENT);
    }

    /// pbrt-v4's own formulas (src/pbrt/util/spectrum.h), their constants as printed.
    #[test]
    fn visible_over_360_830_is_pbrt_v4s() {
        let pbrt_pdf = |l: f64| 0.003_939_804_2 / (0.0072 * (l - 538.0)).cosh().powi(2);
        let pbrt_sample = |u: f64| 538.0 - 138.888_889 * (0.856_910_62 - 1.827_501_97 * u).atanh();
        for i in 0..=470 {
            let l = 360.0 + f64::from(i);
            let (ours, theirs) = (Visible::VISIBLE.pdf(l), pbrt_pdf(l));
            assert!((ours - theirs).abs() <= 1e-6 * theirs, "{l} nm: {ours} against {theirs}");
        }
        for i in 0..1000 {
            let u = (f64::from(i) + 0.5) / 1000.0;
            let (ours, theirs) = (Visible::VISIBLE.sample(u), pbrt_sample(u));
            assert!((ours - theirs).abs() < 1e-4, "u = {u}: {ours} against {theirs} nm");
        }
        assert_eq!((Visible::VISIBLE.pdf(359.9), Visible::VISIBLE.pdf(830.1)), (0.0, 0.0));
    }
}
