//! The point-wise product of spectra, `Πᵢ Sᵢ(λ)`: what a path reflects
//! after several bounces (a light and its reflectances, or one reflectance
//! to a power). Piecewise polynomial when every factor is, with the degrees
//! added, so its integrals stay exact.
//!
//! ```
//! use speclab::{data::{lights, patches}, Spectrum, spectrum::Product};
//! let twice = Product::new(vec![&patches::G4, &patches::G4]);
//! let l = 610.0;
//! assert_eq!(twice.eval(l), patches::G4.eval(l) * patches::G4.eval(l));
//! assert_eq!(twice.pieces().map(|p| p.degree), Some(6));
//! let path = Product::power(&patches::G4, 3)?;
//! assert_eq!(path.len(), 3);
//! assert!(Product::power(&patches::G4, usize::MAX).is_err());
//! assert_eq!(Product::new(vec![]).eval(l), 1.0);
//! # let _ = lights::A;
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;

use crate::error::Error;
use crate::spectrum::interface::{Pieces, Spectrum};

/// The most factors [`Product::power`] makes (a path of 64 bounces off one
/// surface).
pub const MAX_POWER: usize = 64;

/// `Πᵢ Sᵢ(λ)` over borrowed spectra (1 for none).
#[derive(Clone, Default)]
pub struct Product<'a> {
    factors: Vec<&'a dyn Spectrum>,
}

impl std::fmt::Debug for Product<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Product").field("factors", &self.factors.len()).finish_non_exhaustive()
    }
}

impl<'a> Product<'a> {
    /// The product of `factors`.
    #[must_use]
    pub fn new(factors: Vec<&'a dyn Spectrum>) -> Self {
        Product { factors }
    }

    /// `s` to the power `depth` (`depth` factors of `s`): an
    /// [`Error::Count`] past [`MAX_POWER`] factors.
    pub fn power(s: &'a dyn Spectrum, depth: usize) -> Result<Self, Error> {
        if depth > MAX_POWER {
            return Err(Error::Count { what: "a power of a spectrum", found: depth, min: 0, max: MAX_POWER });
        }
        Ok(Product { factors: vec![s; depth] })
    }

    /// The number of factors.
    #[must_use]
    pub fn len(&self) -> usize {
        self.factors.len()
    }

    /// True for the empty product (1 everywhere).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.factors.is_empty()
    }

    /// The factors.
    #[must_use]
    pub fn factors(&self) -> &[&'a dyn Spectrum] {
        &self.factors
    }
}

impl Spectrum for Product<'_> {
    fn eval(&self, lambda: f64) -> f64 {
        self.factors.iter().map(|s| s.eval(lambda)).product()
    }

    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        values.iter_mut().for_each(|v| *v = 1.0);
        let mut scratch = [0.0; 16];
        for (lambda, values) in lambda.chunks(16).zip(values.chunks_mut(16)) {
            for s in &self.factors {
                let part = &mut scratch[..lambda.len()];
                s.eval_many(lambda, part);
                values.iter_mut().zip(part.iter()).for_each(|(v, p)| *v *= p);
            }
        }
    }

    /// The union of the factors' breaks and the sum of their degrees, if
    /// every factor is piecewise polynomial (the empty product: constant).
    fn pieces(&self) -> Option<Pieces<'_>> {
        let mut breaks = Vec::new();
        let mut degree = 0;
        for s in &self.factors {
            let p = s.pieces()?;
            breaks.extend_from_slice(&p.breaks);
            degree += p.degree;
        }
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        Some(Pieces { breaks: Cow::Owned(breaks), degree })
    }

    /// The union of the factors' kinks.
    fn kinks(&self) -> Cow<'_, [f64]> {
        crate::spectrum::interface::union(self.factors.iter().map(|s| s.kinks()))
    }

    /// A bound: `Π max Sᵢ` when every factor is non-negative (bounded
    /// below by 0, as lights and reflectances are: a maximum of 0 or
    /// more); `+∞` if a factor's maximum is negative or unknown.
    fn max_value(&self) -> f64 {
        let maxima = self.factors.iter().map(|s| s.max_value());
        maxima.fold(1.0, |product, m| if m >= 0.0 { product * m } else { f64::INFINITY })
    }
}
