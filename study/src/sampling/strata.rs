//! How the n primary numbers of one estimate are spread over `[0, 1)`.
//!
//! - [`Strata::None`]: n independent uniform numbers, no stratification
//!   (the assignment's random sampling).
//! - [`Strata::Jittered`]: one uniform number in each of n equal strata.
//! - [`Strata::Kronecker`]: the golden-ratio sequence `{s + i·φ⁻¹}` with one
//!   uniform random shift `s` (a randomised low-discrepancy sequence).
//!
//! For hero samples of K wavelengths the stratified numbers are spread over
//! `[0, 1/K)` only: the K rotations `u + j/K` fill the other K − 1 copies,
//! so n hero samples stratify `[0, 1)` into n·K strata. (Independent
//! numbers stay on `[0, 1)`: the rotations make the same set of wavelengths
//! either way.) Every number is uniform on its range on its own, so every
//! estimate stays unbiased.
//!
//! [`Strata::point`] takes a sample's index and a uniform number (the path
//! tracer's own): no random-number generator is involved. [`Strata::points`] draws the
//! uniform numbers from an `Rng` (`rand`) for a whole estimate.
//!
//! ```
//! use speclab_study::sampling::strata::Strata;
//! // Sample 2 of 4, from the renderer's own number 0.5: the middle of stratum 2.
//! assert_eq!(Strata::Jittered.point(2, 4, 1, 0.5), 0.625);
//! // Hero samples of 4 wavelengths: the same stratum of [0, 1/4).
//! assert_eq!(Strata::Jittered.point(2, 4, 4, 0.5), 0.15625);
//! assert_eq!(Strata::None.point(2, 4, 4, 0.5), 0.5);
//! assert_eq!("jitter".parse::<Strata>()?, Strata::Jittered);
//! # Ok::<(), speclab::Error>(())
//! ```

use rand::{Rng, RngExt};

use speclab::named_choices;

/// How an estimate's primary numbers are spread.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Strata {
    /// Independent uniform numbers: no stratification.
    #[default]
    None,
    /// One uniform number per stratum of width `1/n` (of `[0, 1/K)`).
    Jittered,
    /// The golden-ratio Kronecker sequence with a uniform random shift.
    Kronecker,
}

named_choices!(Strata, "a strata": None => "none", Jittered => "jitter", Kronecker => "kronecker");

/// `1/φ`, the golden ratio's reciprocal: the most evenly spreading step.
const INV_PHI: f64 = 0.618_033_988_749_894_9;

impl Strata {
    /// Primary number `i` of the `n` of one estimate made of samples of `k`
    /// wavelengths, from a uniform number `u` in `[0, 1)`:
    /// - `None`: `u` itself (a fresh `u` per sample);
    /// - `Jittered`: `(i + u)/n`, scaled to `[0, 1/k)` (a fresh `u` per sample);
    /// - `Kronecker`: `{u + i·φ⁻¹}`, scaled to `[0, 1/k)`, where `u` is the
    ///   estimate's random shift: **the same `u` for every `i`**.
    ///
    /// Any `u` is taken (its fractional part for the shift, clamped for the
    /// others); the result is always in `[0, 1)` (`[0, 1/k)` when
    /// stratified); `k = 0` acts as 1.
    #[inline]
    #[must_use]
    pub fn point(self, i: usize, n: usize, k: usize, u: f64) -> f64 {
        let scale = if self == Strata::None { 1.0 } else { 1.0 / k.max(1) as f64 };
        let u = if u > 0.0 { u } else { 0.0 };
        let i = i as f64;
        let v = match self {
            Strata::None => u,
            Strata::Jittered => (i + u) / n.max(1) as f64,
            Strata::Kronecker => {
                let v = u.fract() + (i * INV_PHI).fract();
                if v >= 1.0 { v - 1.0 } else { v }
            }
        };
        // Below the top: a jittered (i + ξ)/n can round up to 1.
        (v * scale).min(scale * (1.0 - f64::EPSILON))
    }

    /// The `n` primary numbers of one estimate made of samples of `k`
    /// wavelengths, their uniform numbers drawn from `rng` as they are
    /// needed ([`Strata::point`] of each).
    pub fn points<R: Rng + ?Sized>(self, n: usize, k: usize, rng: &mut R) -> Points<'_, R> {
        let shift = if self == Strata::Kronecker { rng.random::<f64>() } else { 0.0 };
        Points { strata: self, n, k, i: 0, shift, rng }
    }
}

/// The primary numbers of [`Strata::points`], drawn as they are needed.
#[derive(Debug)]
pub struct Points<'a, R: ?Sized> {
    strata: Strata,
    n: usize,
    k: usize,
    i: usize,
    shift: f64,
    rng: &'a mut R,
}

impl<R: Rng + ?Sized> Iterator for Points<'_, R> {
    type Item = f64;

    #[inline]
    fn next(&mut self) -> Option<f64> {
        if self.i >= self.n {
            return None;
        }
        let u = match self.strata {
            Strata::Kronecker => self.shift,
            Strata::None | Strata::Jittered => self.rng.random::<f64>(),
        };
        let point = self.strata.point(self.i, self.n, self.k, u);
        self.i += 1;
        Some(point)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.n - self.i;
        (left, Some(left))
    }
}
