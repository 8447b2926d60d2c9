//! A wavelength density made for a renderer's inner loop.
//!
//! [`BinnedPdf`] cuts 380–730 nm into `bins` bins of **equal probability**
//! at another density's quantiles, and is constant inside each: bin `i`
//! spans `[λᵢ, λᵢ₊₁]` with `λᵢ = P⁻¹(i/bins)` of the source `P`, and has
//! density `1/(bins·(λᵢ₊₁ − λᵢ))`. Sampling is then one index and one
//! multiply-add with no search and no branch: `λ = λᵢ + (λᵢ₊₁ − λᵢ)·f` for
//! `u·bins = i + f`, and `1/pdf = bins·(λᵢ₊₁ − λᵢ)`. Where the source is
//! dense (F11's lines) the bins are narrow and follow it closely; where it
//! is thin they are wide.
//!
//! The histogram is a density in its own right, so its samples and pdf
//! agree exactly and estimates stay unbiased wherever the source is
//! positive; it follows the source less closely inside a bin, which costs a
//! little variance. `pdf` and `cdf` find the bin by binary search (a
//! renderer's hero loop never asks).
//!
//! ```
//! use speclab::{data::lights, HeroSample};
//! use speclab::sampling::binned::BinnedPdf;
//! use speclab::sampling::pdf::{LightPdf, Visible, WavelengthPdf};
//! let f11 = BinnedPdf::new(&LightPdf::light(&lights::F11)?, 256)?;
//! let visible = BinnedPdf::new(&Visible::ASSIGNMENT, 256)?;
//! let h = HeroSample::<4>::from_pdf_with(0.3, &f11, &speclab::spectrum::DenseObserver::ASSIGNMENT).unwrap();
//! assert!(h.pdf().iter().all(|&p| p > 0.0));
//! // 545 nm is on one of F11's lines, 500 nm between them.
//! assert!(f11.pdf(545.0) > 10.0 * f11.pdf(500.0) && visible.pdf(545.0) > visible.pdf(400.0));
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::sampling::pdf::WavelengthPdf;
use crate::spectrum::WavelengthRange;

/// The most bins a [`BinnedPdf`] takes.
pub const MAX_BINS: usize = 1 << 14;

/// A piecewise-constant density on bins of equal probability.
#[derive(Clone, Debug, PartialEq)]
pub struct BinnedPdf {
    /// The `bins + 1` bin edges, nm, strictly increasing.
    knots: Box<[f64]>,
}

impl BinnedPdf {
    /// The histogram of `pdf` on `bins` bins of probability `1/bins`, cut at
    /// `pdf.sample(i/bins)`. An [`Error::Count`] for 0 or more than
    /// [`MAX_BINS`] bins; an [`Error::NoMass`] if the cuts are not strictly
    /// increasing finite wavelengths (a density with no spread, or a
    /// `sample` that is not an inverse CDF).
    pub fn new(pdf: &(impl WavelengthPdf + ?Sized), bins: usize) -> Result<Self, Error> {
        if !(1..=MAX_BINS).contains(&bins) {
            return Err(Error::Count { what: "a bin count", found: bins, min: 1, max: MAX_BINS });
        }
        let knots: Box<[f64]> = (0..=bins).map(|i| pdf.sample(i as f64 / bins as f64)).collect();
        let increasing = knots.windows(2).all(|w| w[0].is_finite() && w[1].is_finite() && w[1] > w[0]);
        if increasing { Ok(BinnedPdf { knots }) } else { Err(Error::NoMass) }
    }

    /// The number of bins.
    #[must_use]
    pub fn len(&self) -> usize {
        self.knots.len() - 1
    }

    /// Always false: a histogram has at least one bin.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The bin edges, nm.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The bin holding `lambda`, if any.
    fn bin_of(&self, lambda: f64) -> Option<usize> {
        let (first, last) = (self.knots[0], self.knots[self.knots.len() - 1]);
        let inside = lambda >= first && lambda <= last;
        inside.then(|| self.knots.partition_point(|&k| k <= lambda).saturating_sub(1).min(self.len() - 1))
    }
}

impl WavelengthPdf for BinnedPdf {
    /// The first cut to the last.
    fn support(&self) -> WavelengthRange {
        let (first, last) = (self.knots[0], self.knots[self.knots.len() - 1]);
        WavelengthRange::new(first, last).unwrap_or(WavelengthRange::VISIBLE)
    }

    #[inline]
    fn sample(&self, u: f64) -> f64 {
        self.sample_with_inv_pdf(u).0
    }

    fn pdf(&self, lambda: f64) -> f64 {
        self.bin_of(lambda).map_or(0.0, |i| 1.0 / (self.len() as f64 * (self.knots[i + 1] - self.knots[i])))
    }

    /// Linear inside each bin, `i/bins` at the start of bin `i`.
    fn cdf(&self, lambda: f64) -> Option<f64> {
        Some(match self.bin_of(lambda) {
            Some(i) => {
                let (a, b) = (self.knots[i], self.knots[i + 1]);
                (i as f64 + (lambda - a) / (b - a)) / self.len() as f64
            }
            None if lambda > self.knots[0] => 1.0,
            None => 0.0,
        })
    }

    /// `u·bins = i + f`: `λᵢ + (λᵢ₊₁ − λᵢ)·f`, and `bins·(λᵢ₊₁ − λᵢ)`.
    /// `u` is clamped into `[0, 1)`; NaN acts as 0.
    #[inline]
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let bins = self.len();
        let x = if u > 0.0 { u * bins as f64 } else { 0.0 };
        let i = (x as usize).min(bins - 1);
        let f = (x - i as f64).min(1.0);
        let (a, b) = (self.knots[i], self.knots[i + 1]);
        let width = b - a;
        (a + width * f, bins as f64 * width)
    }
}

#[cfg(test)]
#[path = "binned_tests.rs"]
mod tests;
