//! The least-squares problem behind [`Rule::fit`](crate::sampling::rule::Rule::fit): choose
//! M of the candidate wavelengths (every nm of the range: 380 to 730 by
//! default, `moments::Grid`) and per
//! channel the weights that best reproduce the exact XYZ of light ×
//! reflectance over the prior (`prior.rs`), or over a scene's own surfaces
//! (`FittedRules::with_surfaces`).
//!
//! Rows are (light, path) pairs, a path being one to four of the
//! reflectances multiplied (`prior::draw_paths`): the row's values are
//! `L(λⱼ)·r(λⱼ)` at the candidates, its target the exact `∫ L·r·c̄`. Channel `c` of a row
//! is weighted by `t^(−2/3)/W꜀`, with `t` the reflectance's own colour
//! (X, Y or Z under an equal-energy light, relative to the white, at least
//! 0.01) and `W꜀` the light's white: CIELAB's sensitivity to a relative
//! error, `d(t^(1/3))/dt`, so that dark colours count as much as bright ones.
//! The perfect white and the reflectances' mean under each light are
//! anchors, weighted [`ANCHOR`] times the mean row weight, so that the
//! rule reproduces both.
//!
//! The normal equations need `Σ ω²·r(λⱼ)·r(λₖ)` over the paths for every
//! pair of candidates, which does not depend on the light (`moments.rs`:
//! for the prior, computed once per process, about 70 ms in a release
//! build) and is scaled by `L(λⱼ)·L(λₖ)` per
//! light. The search for the nodes is in `search.rs`. Everything is
//! sequential and in a fixed order: the same rule on every run. Scales are
//! taken out first (the light's brightest white channel), so a light of any
//! power gives the same rule.

use crate::error::Error;
use crate::sampling::fitted::moments::{Grid, Moments};
use crate::spectrum::Spectrum;

/// The anchors' weight, relative to the prior's mean row weight (squared).
pub(crate) const ANCHOR: f64 = 1e4;

/// The normal equations for a set of lights, as sets of rows that share
/// the nodes: per set the Gram matrix of all candidates, the right-hand
/// side and the targets' weighted square. Sets `3g`, `3g + 1`, `3g + 2`
/// are X, Y and Z of group `g`; a group is all the lights together (one
/// weight set serving every light) or one light (weights of its own).
pub(crate) struct Problem {
    pub(super) grid: Grid,
    pub(super) sets: Vec<Rows>,
}

/// One set of rows: one channel of one group.
pub(super) struct Rows {
    pub(super) gram: Vec<f64>,
    pub(super) rhs: Vec<f64>,
    pub(super) square: f64,
}

impl Rows {
    fn new(n: usize) -> Self {
        Rows { gram: vec![0.0; n * n], rhs: vec![0.0; n], square: 0.0 }
    }
}

impl Problem {
    /// One group, all of `lights` together: the rule that serves them all
    /// with one set of weights. An [`Error::NoMass`] if there are none or
    /// one has no power the observer sees (a white that is zero, or not
    /// finite, in every channel).
    pub(crate) fn new(lights: &[&dyn Spectrum], grid: Grid) -> Result<Self, Error> {
        Self::grouped(lights, false, &Moments::builtin(grid))
    }

    /// One group per light: shared nodes, each light its own weights.
    pub(crate) fn each(lights: &[&dyn Spectrum], grid: Grid) -> Result<Self, Error> {
        Self::grouped(lights, true, &Moments::builtin(grid))
    }

    /// One group, all of `lights` together, over `surfaces` instead of the
    /// built-in prior (errors as [`Moments::of`] and [`Problem::new`]).
    pub(crate) fn over(
        lights: &[&dyn Spectrum],
        surfaces: &[&dyn Spectrum],
        grid: Grid,
    ) -> Result<Self, Error> {
        if lights.is_empty() {
            return Err(Error::NoMass);
        }
        Self::grouped(lights, false, &Moments::of(surfaces, grid)?)
    }

    fn grouped(lights: &[&dyn Spectrum], each: bool, m: &Moments) -> Result<Self, Error> {
        if lights.is_empty() {
            return Err(Error::NoMass);
        }
        let groups = if each { lights.len() } else { 1 };
        let n = m.grid.count();
        let mut problem = Problem { grid: m.grid, sets: (0..3 * groups).map(|_| Rows::new(n)).collect() };
        for (i, &light) in lights.iter().enumerate() {
            let group = if each { i } else { 0 };
            problem.add(m, light, group)?;
        }
        Ok(problem)
    }

    /// Adds one light's rows to `group`: the prior's paths and the two
    /// anchors.
    fn add(&mut self, m: &Moments, light: &dyn Spectrum, group: usize) -> Result<(), Error> {
        // Everything in units of the light's brightest white channel, so
        // that any scale of light (subnormal to 1e100) gives the same
        // numbers; a channel far below the others is weighted as if at a
        // thousandth of it.
        let grid = m.grid;
        let white = grid.white(light);
        let scale = white.iter().copied().fold(0.0, f64::max);
        if !(scale.is_finite() && scale > 0.0) {
            return Err(Error::NoMass);
        }
        let white = white.map(|w| w / scale);
        let n = grid.count();
        let l: Vec<f64> = (0..n).map(|j| light.eval(grid.lambda(j)) / scale).collect();
        let (targets, mean_target) = m.targets(light, scale);
        let mean = &m.mean;
        for c in 0..3 {
            let channel = 1.0 / white[c].max(1e-3).powi(2);
            let Rows { gram, rhs, square } = &mut self.sets[3 * group + c];
            for j in 0..n {
                for k in 0..n {
                    gram[j * n + k] += channel * l[j] * l[k] * m.gram[c][j * n + k];
                }
            }
            for ((v, w), t) in m.values.iter().zip(&m.omega2).zip(&targets) {
                let a = channel * w[c] * t[c];
                for (b, (&lj, &vj)) in rhs.iter_mut().zip(l.iter().zip(v)) {
                    *b += a * lj * vj;
                }
                *square += channel * w[c] * t[c] * t[c];
            }
            // Anchors: the white (r = 1) and the prior's mean.
            let kappa = ANCHOR * m.mean_omega2[c] * channel;
            let ones = vec![1.0; n];
            for (row, target) in [(&ones, white[c]), (mean, mean_target[c])] {
                for j in 0..n {
                    let aj = l[j] * row[j];
                    rhs[j] += kappa * aj * target;
                    for k in 0..n {
                        gram[j * n + k] += kappa * aj * l[k] * row[k];
                    }
                }
                *square += kappa * target * target;
            }
        }
        Ok(())
    }
}
