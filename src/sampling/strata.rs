//! How the n primary numbers of one estimate are spread over `[0, 1)`.
//!
//! - [`Strata::Independent`]: n independent uniform numbers (the
//!   assignment's random sampling).
//! - [`Strata::Jittered`]: one uniform number in each of n equal strata.
//! - [`Strata::Kronecker`]: the golden-ratio sequence `{s + i·φ⁻¹}` with one
//!   uniform random shift `s` (a randomised low-discrepancy sequence).
//!
//! For hero samples of K wavelengths the stratified numbers are spread over
//! `[0, 1/K)` only: the K rotations `u + j/K` fill the other K − 1 copies,
//! so n hero samples stratify `[0, 1)` into n·K strata. (Independent
//! numbers stay on `[0, 1)`, as before: the rotations make the same set of
//! wavelengths either way.) Every number is uniform on its range on its
//! own, so every estimate stays unbiased.
//!
//! ```
//! use rand::{SeedableRng, rngs::StdRng};
//! use speclab::sampling::strata::Strata;
//! let mut rng = StdRng::seed_from_u64(1);
//! let u: Vec<f64> = Strata::Jittered.points(4, 1, &mut rng).collect();
//! for (i, u) in u.iter().enumerate() {
//!     assert!((i as f64 / 4.0..(i + 1) as f64 / 4.0).contains(u));
//! }
//! ```

use rand::{Rng, RngExt};

/// How an estimate's primary numbers are spread.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Strata {
    /// Independent uniform numbers.
    #[default]
    Independent,
    /// One uniform number per stratum of width `1/n` (of `[0, 1/K)`).
    Jittered,
    /// The golden-ratio Kronecker sequence with a uniform random shift.
    Kronecker,
}

/// `1/φ`, the golden ratio's reciprocal: the most evenly spreading step.
const INV_PHI: f64 = 0.618_033_988_749_894_9;

impl Strata {
    /// All choices, in CLI order.
    pub const ALL: [Strata; 3] = [Strata::Independent, Strata::Jittered, Strata::Kronecker];

    /// The name used on the command line and in CSV.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Strata::Independent => "independent",
            Strata::Jittered => "jitter",
            Strata::Kronecker => "kronecker",
        }
    }

    /// The choice with this name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Strata> {
        Strata::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The `n` primary numbers of one estimate made of samples of `k`
    /// wavelengths: each uniform on `[0, 1/k)`, or on `[0, 1)` when
    /// independent.
    pub fn points<R: Rng + ?Sized>(self, n: usize, k: usize, rng: &mut R) -> Points<'_, R> {
        let scale = if self == Strata::Independent { 1.0 } else { 1.0 / k.max(1) as f64 };
        let shift = if self == Strata::Kronecker { rng.random::<f64>() } else { 0.0 };
        Points { strata: self, n, i: 0, scale, shift, rng }
    }
}

/// The primary numbers of [`Strata::points`], drawn as they are needed.
#[derive(Debug)]
pub struct Points<'a, R: ?Sized> {
    strata: Strata,
    n: usize,
    i: usize,
    scale: f64,
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
        let i = self.i as f64;
        self.i += 1;
        let u = match self.strata {
            Strata::Independent => self.rng.random::<f64>(),
            Strata::Jittered => (i + self.rng.random::<f64>()) / self.n as f64,
            Strata::Kronecker => {
                let v = self.shift + (i * INV_PHI).fract();
                if v >= 1.0 { v - 1.0 } else { v }
            }
        };
        // Below 1/k: a jittered (i + ξ)/n can round up to 1.
        Some((u * self.scale).min(self.scale * (1.0 - f64::EPSILON)))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.n - self.i;
        (left, Some(left))
    }
}
