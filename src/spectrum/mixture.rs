//! A weighted sum of spectra, `Σ wᵢ·Sᵢ(λ)`: a scene's lights as one
//! spectrum (for a light-following wavelength pdf), or a blend of materials.
//! Piecewise polynomial when every term is (on the union of their breaks),
//! so its integrals stay exact.
//!
//! ```
//! use speclab::{data::lights, Spectrum, spectrum::Mixture};
//! let scene = Mixture::new().with(1.0, &lights::F11)?.with(0.5, &lights::D65)?;
//! let l = 555.0;
//! assert!((scene.eval(l) - (lights::F11.eval(l) + 0.5 * lights::D65.eval(l))).abs() < 1e-12);
//! assert!(scene.pieces().is_some());
//! assert!(Mixture::new().with(-1.0, &lights::A).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;

use crate::error::Error;
use crate::spectrum::interface::{Pieces, Spectrum};

/// `Σ wᵢ·Sᵢ(λ)` over borrowed spectra.
#[derive(Clone, Default)]
pub struct Mixture<'a> {
    terms: Vec<(f64, &'a dyn Spectrum)>,
}

impl std::fmt::Debug for Mixture<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let weights: Vec<f64> = self.terms.iter().map(|t| t.0).collect();
        f.debug_struct("Mixture").field("weights", &weights).finish_non_exhaustive()
    }
}

impl<'a> Mixture<'a> {
    /// The empty sum (zero everywhere).
    #[must_use]
    pub fn new() -> Self {
        Mixture { terms: Vec::new() }
    }

    /// The sum with `weight · spectrum` added; an [`Error::Weight`] unless
    /// the weight is finite and non-negative.
    pub fn with(mut self, weight: f64, spectrum: &'a dyn Spectrum) -> Result<Self, Error> {
        if !(weight.is_finite() && weight >= 0.0) {
            return Err(Error::Weight { index: self.terms.len(), weight });
        }
        self.terms.push((weight, spectrum));
        Ok(self)
    }
}

impl Spectrum for Mixture<'_> {
    fn eval(&self, lambda: f64) -> f64 {
        self.terms.iter().map(|(w, s)| w * s.eval(lambda)).sum()
    }

    /// The union of the terms' breaks and the largest degree, if every
    /// term is piecewise polynomial.
    fn pieces(&self) -> Option<Pieces<'_>> {
        let mut breaks = Vec::new();
        let mut degree = 0;
        for (_, s) in &self.terms {
            let p = s.pieces()?;
            breaks.extend_from_slice(&p.breaks);
            degree = degree.max(p.degree);
        }
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        Some(Pieces { breaks: Cow::Owned(breaks), degree })
    }

    /// The union of the terms' kinks.
    fn kinks(&self) -> Cow<'_, [f64]> {
        crate::spectrum::interface::union(self.terms.iter().map(|(_, s)| s.kinks()))
    }

    /// A bound: `Σ wᵢ·max Sᵢ` (the terms' maxima need not coincide).
    fn max_value(&self) -> f64 {
        self.terms.iter().map(|(w, s)| if *w > 0.0 { w * s.max_value() } else { 0.0 }).sum()
    }
}
