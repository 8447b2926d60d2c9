//! The reflectance prior that fitted wavelength rules are fitted over:
//! [`PRIOR_SIZE`] smooth reflectances, generated (not measured), the same
//! on every machine.
//!
//! Two families, alternating, drawn by SplitMix64 from the seed
//! [`PRIOR_SEED`]:
//!
//! - **sigmoid quadratics** (even indices): `σ(q(λ))` with `σ(x) =
//!   1/(1 + e⁻ˣ)` and `q` the quadratic through `logit` of three values
//!   drawn uniformly in [0.03, 0.97] at 380, 555 and 730 nm: the family of
//!   RGB upsampling (Jakob and Hanika 2019), monotone edges, bumps and dips
//!   across the whole range;
//! - **bumps** (odd indices): `σ(a + Σₖ hₖ·exp(−(λ − μₖ)²/(2σₖ²)))` with 1
//!   to 3 Gaussian terms, `a ∈ [−3, 3]`, `hₖ ∈ [−5, 5]`, `μₖ ∈ [380, 730]`
//!   nm and `σₖ ∈ [10, 60]` nm: narrower features anywhere in the range.
//!
//! Every member lies strictly inside (0, 1) and is smooth. None is one of
//! the six appendix patches or of the named test shapes the study judges
//! rules on (`speclab_study::evaluate::shapes`): those are tables, these
//! are formulas (tested below).

use std::sync::OnceLock;

use crate::sampling::seed::SplitMix64;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, Spectrum};

/// How many reflectances the prior holds.
pub const PRIOR_SIZE: usize = 512;

/// The seed the prior is drawn from.
pub const PRIOR_SEED: u64 = 0x5EC1_AB00_0000_0001;

/// One reflectance of the prior: `σ(a + b·t + c·t² + Σₖ hₖ·g(λ; μₖ, σₖ))`
/// with `t = (λ − 555)/175`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PriorReflectance {
    /// `[a, b, c]` of the quadratic in `t`.
    quadratic: [f64; 3],
    /// Up to three `(h, μ, σ)` bumps (`h = 0` for none).
    bumps: [[f64; 3]; 3],
}

impl Spectrum for PriorReflectance {
    /// The formula over 380–730 nm, zero outside.
    fn eval(&self, lambda: f64) -> f64 {
        if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) {
            return 0.0;
        }
        self.value(lambda)
    }
}

impl PriorReflectance {
    /// The formula at any wavelength (a fit over a wider range reads it
    /// there).
    pub(crate) fn value(&self, lambda: f64) -> f64 {
        let t = (lambda - 555.0) / 175.0;
        let [a, b, c] = self.quadratic;
        let bumps: f64 = self
            .bumps
            .iter()
            .filter(|k| k[0] != 0.0)
            .map(|&[h, mu, sigma]| h * (-(lambda - mu).powi(2) / (2.0 * sigma * sigma)).exp())
            .sum();
        let x = a + t * (b + t * c) + bumps;
        1.0 / (1.0 + (-x).exp())
    }
}

/// The prior's generator: the crate's [`SplitMix64`], drawing in ranges.
struct SplitMix(SplitMix64);

impl SplitMix {
    /// A uniform number in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.0.next_f64()
    }
}

fn logit(p: f64) -> f64 {
    (p / (1.0 - p)).ln()
}

/// Member `i`'s parameters, drawn from `rng`.
fn draw(i: usize, rng: &mut SplitMix) -> PriorReflectance {
    let mut bumps = [[0.0; 3]; 3];
    if i.is_multiple_of(2) {
        // Through logit(v) at t = −1, 0, 1: a = y0, b = (y1 − y−1)/2,
        // c = (y1 + y−1)/2 − y0.
        let [lo, mid, hi] = [(); 3].map(|()| logit(rng.uniform(0.03, 0.97)));
        let quadratic = [mid, 0.5 * (hi - lo), 0.5 * (hi + lo) - mid];
        return PriorReflectance { quadratic, bumps };
    }
    let count = 1 + (rng.uniform(0.0, 3.0) as usize).min(2);
    for bump in bumps.iter_mut().take(count) {
        *bump = [rng.uniform(-5.0, 5.0), rng.uniform(LAMBDA_MIN, LAMBDA_MAX), rng.uniform(10.0, 60.0)];
    }
    PriorReflectance { quadratic: [rng.uniform(-3.0, 3.0), 0.0, 0.0], bumps }
}

/// The prior's reflectances, generated on first use.
#[must_use]
pub fn prior() -> &'static [PriorReflectance] {
    static PRIOR: OnceLock<Vec<PriorReflectance>> = OnceLock::new();
    PRIOR.get_or_init(|| {
        let mut rng = SplitMix(SplitMix64::new(PRIOR_SEED));
        (0..PRIOR_SIZE).map(|i| draw(i, &mut rng)).collect()
    })
}

/// How many products of two, three and four reflectances [`draw_paths`] adds.
pub const PATHS: [usize; 3] = [256, 128, 128];

/// A path through a fit's reflectances (the prior's or a scene's): the
/// product of one to four of them, by index, what a path of that many
/// bounces reflects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PriorPath {
    members: [usize; 4],
    depth: usize,
}

impl PriorPath {
    /// The reflectances multiplied, as indices into the fit's list.
    #[must_use]
    pub fn members(&self) -> &[usize] {
        &self.members[..self.depth]
    }
}

/// The rows rules are fitted over, for `n` reflectances (the prior's or a
/// scene's): each alone, then [`PATHS`] products of 2, 3 and 4 of them
/// drawn uniformly (SplitMix64 from `PRIOR_SEED + 1`), so that one rule
/// serves paths of every depth.
pub(crate) fn draw_paths(n: usize) -> Vec<PriorPath> {
    let mut rng = SplitMix(SplitMix64::new(PRIOR_SEED.wrapping_add(1)));
    let singles = (0..n).map(|i| PriorPath { members: [i, 0, 0, 0], depth: 1 });
    let mut out: Vec<PriorPath> = singles.collect();
    for (depth, &count) in (2..).zip(&PATHS) {
        for _ in 0..count {
            let members = [(); 4].map(|()| (rng.uniform(0.0, n as f64) as usize).min(n.saturating_sub(1)));
            out.push(PriorPath { members, depth });
        }
    }
    out
}

/// The prior's mean reflectance, `(1/N)·Σ rᵢ(λ)`.
#[cfg(test)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PriorMean;

#[cfg(test)]
impl Spectrum for PriorMean {
    fn eval(&self, lambda: f64) -> f64 {
        let p = prior();
        p.iter().map(|r| r.eval(lambda)).sum::<f64>() / p.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both families, inside (0, 1), and the same draw every time.
    #[test]
    fn the_prior_is_fixed_and_bounded() {
        let p = prior();
        assert_eq!(p[0].bumps, [[0.0; 3]; 3]);
        assert!(p[1].bumps[0][0] != 0.0 && p[1].quadratic[1] == 0.0);
        let again: Vec<_> = {
            let mut rng = SplitMix(SplitMix64::new(PRIOR_SEED));
            (0..PRIOR_SIZE).map(|i| draw(i, &mut rng)).collect()
        };
        assert_eq!(p, &again[..]);
        for r in p {
            for lambda in (380..=730).step_by(5) {
                let v = r.eval(f64::from(lambda));
                assert!(v > 0.0 && v < 1.0, "{r:?} at {lambda}: {v}");
            }
        }
        // The even members pass through their drawn values' range.
        let v = p[0].eval(555.0);
        assert!((0.03..=0.97).contains(&v));
        assert_eq!(p[0].eval(379.0), 0.0);
        assert!(p[0].value(379.0) > 0.0 && p[0].value(830.0) < 1.0 && p[1].value(360.0) > 0.0);
        let mean = PriorMean.eval(555.0);
        assert!(mean > 0.2 && mean < 0.8, "{mean}");
    }
}
