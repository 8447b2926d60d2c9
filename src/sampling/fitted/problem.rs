//! The least-squares problem behind [`Rule::fit`](crate::sampling::rule::Rule::fit): choose
//! M of the candidate wavelengths (every nm from 380 to 730) and per
//! channel the weights that best reproduce the exact XYZ of light ×
//! reflectance over the prior (`prior.rs`).
//!
//! Rows are (light, path) pairs, a path being one to four of the prior's
//! reflectances multiplied (`prior::paths`): the row's values are
//! `L(λⱼ)·r(λⱼ)` at the candidates, its target the exact `∫ L·r·c̄`. Channel `c` of a row
//! is weighted by `t^(−2/3)/W꜀`, with `t` the reflectance's own colour
//! (X, Y or Z under an equal-energy light, relative to the white, at least
//! 0.01) and `W꜀` the light's white: CIELAB's sensitivity to a relative
//! error, `d(t^(1/3))/dt`, so that dark colours count as much as bright ones.
//! The perfect white and the prior's mean reflectance under each light are
//! anchors, weighted [`ANCHOR`] times the prior's mean weight, so that the
//! rule reproduces both.
//!
//! The normal equations need `Σ ω²·r(λⱼ)·r(λₖ)` over the prior for every
//! pair of candidates, which does not depend on the light: it is computed
//! once per process (about 70 ms in a release build) and scaled by `L(λⱼ)·L(λₖ)` per
//! light. The search for the nodes is in `search.rs`. Everything is
//! sequential and in a fixed order: the same rule on every run. Scales are
//! taken out first (the light's brightest white channel), so a light of any
//! power gives the same rule.

use std::sync::OnceLock;

use crate::error::Error;
use crate::sampling::prior::{PriorMean, paths, prior};
use crate::spectrum::{Constant, LAMBDA_MIN, Spectrum, integrate, observer, quadrature};

/// Candidate wavelengths: every nm from 380 to 730.
pub(crate) const CANDIDATES: usize = 351;

/// Candidate `j`, nm.
pub(super) fn candidate(j: usize) -> f64 {
    LAMBDA_MIN + j as f64
}

/// The anchors' weight, relative to the prior's mean row weight (squared).
pub(crate) const ANCHOR: f64 = 1e4;

/// The light-independent part: per channel, `Σₛ ω²·r(λⱼ)·r(λₖ)` (row-major
/// C × C), the prior's values at the candidates, the row weights ω², and
/// the mean of ω² per channel.
struct Moments {
    gram: [Vec<f64>; 3],
    values: Vec<[f64; CANDIDATES]>,
    omega2: Vec<[f64; 3]>,
    mean_omega2: [f64; 3],
}

fn moments() -> &'static Moments {
    static MOMENTS: OnceLock<Moments> = OnceLock::new();
    MOMENTS.get_or_init(|| {
        let p = paths();
        let equal = integrate::white(&Constant::new(1.0));
        let values: Vec<[f64; CANDIDATES]> =
            p.iter().map(|r| std::array::from_fn(|j| r.eval(candidate(j)))).collect();
        let (own, _) = targets(&Constant::new(1.0), 1.0);
        let omega2: Vec<[f64; 3]> = own
            .iter()
            .map(|own| std::array::from_fn(|c| (own[c] / equal[c]).max(0.01).powf(-4.0 / 3.0)))
            .collect();
        let gram = [0, 1, 2].map(|c| {
            let mut g = vec![0.0; CANDIDATES * CANDIDATES];
            for (v, w) in values.iter().zip(&omega2) {
                for j in 0..CANDIDATES {
                    let a = w[c] * v[j];
                    let row = &mut g[j * CANDIDATES..(j + 1) * CANDIDATES];
                    for (g, &vk) in row[j..].iter_mut().zip(&v[j..]) {
                        *g += a * vk;
                    }
                }
            }
            for j in 0..CANDIDATES {
                for k in 0..j {
                    g[j * CANDIDATES + k] = g[k * CANDIDATES + j];
                }
            }
            g
        });
        let mean_omega2 = [0, 1, 2].map(|c| omega2.iter().map(|w| w[c]).sum::<f64>() / p.len() as f64);
        Moments { gram, values, omega2, mean_omega2 }
    })
}

/// The normal equations for a set of lights, as sets of rows that share
/// the nodes: per set the Gram matrix of all candidates, the right-hand
/// side and the targets' weighted square. Sets `3g`, `3g + 1`, `3g + 2`
/// are X, Y and Z of group `g`; a group is all the lights together (one
/// weight set serving every light) or one light (weights of its own).
pub(crate) struct Problem {
    pub(super) sets: Vec<Rows>,
}

/// One set of rows: one channel of one group.
pub(super) struct Rows {
    pub(super) gram: Vec<f64>,
    pub(super) rhs: Vec<f64>,
    pub(super) square: f64,
}

impl Rows {
    fn new() -> Self {
        Rows { gram: vec![0.0; CANDIDATES * CANDIDATES], rhs: vec![0.0; CANDIDATES], square: 0.0 }
    }
}

impl Problem {
    /// One group, all of `lights` together: the rule that serves them all
    /// with one set of weights. An [`Error::NoMass`] if there are none or
    /// one has no power the observer sees (a white that is zero, or not
    /// finite, in every channel).
    pub(crate) fn new(lights: &[&dyn Spectrum]) -> Result<Self, Error> {
        Self::grouped(lights, false)
    }

    /// One group per light: shared nodes, each light its own weights.
    pub(crate) fn each(lights: &[&dyn Spectrum]) -> Result<Self, Error> {
        Self::grouped(lights, true)
    }

    fn grouped(lights: &[&dyn Spectrum], each: bool) -> Result<Self, Error> {
        if lights.is_empty() {
            return Err(Error::NoMass);
        }
        let m = moments();
        let groups = if each { lights.len() } else { 1 };
        let mut problem = Problem { sets: (0..3 * groups).map(|_| Rows::new()).collect() };
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
        let white = integrate::white(light);
        let scale = white.iter().copied().fold(0.0, f64::max);
        if !(scale.is_finite() && scale > 0.0) {
            return Err(Error::NoMass);
        }
        let white = white.map(|w| w / scale);
        let l: [f64; CANDIDATES] = std::array::from_fn(|j| light.eval(candidate(j)) / scale);
        let (targets, mean_target) = targets(light, scale);
        let mean: [f64; CANDIDATES] = std::array::from_fn(|j| PriorMean.eval(candidate(j)));
        for c in 0..3 {
            let channel = 1.0 / white[c].max(1e-3).powi(2);
            let Rows { gram, rhs, square } = &mut self.sets[3 * group + c];
            for j in 0..CANDIDATES {
                for k in 0..CANDIDATES {
                    gram[j * CANDIDATES + k] += channel * l[j] * l[k] * m.gram[c][j * CANDIDATES + k];
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
            for (row, target) in [(&[1.0; CANDIDATES], white[c]), (&mean, mean_target[c])] {
                for j in 0..CANDIDATES {
                    let aj = l[j] * row[j];
                    rhs[j] += kappa * aj * target;
                    for k in 0..CANDIDATES {
                        gram[j * CANDIDATES + k] += kappa * aj * l[k] * row[k];
                    }
                }
                *square += kappa * target * target;
            }
        }
        Ok(())
    }
}

/// The quadrature nodes the targets are computed on, 16-point
/// Gauss–Legendre on each 5 nm piece (the data's grid), with their weights;
/// and every prior member's values there (computed once per process).
struct Nodes {
    lambda: Vec<f64>,
    weight: Vec<f64>,
    members: Vec<Vec<f64>>,
}

fn nodes() -> &'static Nodes {
    static NODES: OnceLock<Nodes> = OnceLock::new();
    NODES.get_or_init(|| {
        let (mut lambda, mut weight) = (Vec::new(), Vec::new());
        for i in 0..70 {
            let (mid, half) = (LAMBDA_MIN + 5.0 * f64::from(i) + 2.5, 2.5);
            for &(x, w) in quadrature::gauss(16) {
                lambda.push(mid + half * x);
                weight.push(w * half);
            }
        }
        let members = prior().iter().map(|r| lambda.iter().map(|&l| r.eval(l)).collect()).collect();
        Nodes { lambda, weight, members }
    })
}

/// The XYZ of `light / scale` times each of the prior's paths, and times
/// the prior's mean, by the quadrature of [`nodes`]. Exact to about 1e-12
/// relative for lights whose breaks lie on the 5 nm grid (the built-in
/// ones: the prior's members are smooth, with features of 10 nm and more);
/// a light with kinks between grid points is integrated less exactly
/// (about 1e-4), which moves the fit by far less than its own error.
fn targets(light: &dyn Spectrum, scale: f64) -> (Vec<[f64; 3]>, [f64; 3]) {
    let n = nodes();
    let kernel: Vec<[f64; 3]> = n
        .lambda
        .iter()
        .zip(&n.weight)
        .map(|(&l, &w)| {
            let k = light.eval(l) / scale * w;
            observer::xyz_bar(l).map(|c| c * k)
        })
        .collect();
    let integrate = |f: &dyn Fn(usize) -> f64| {
        kernel.iter().enumerate().fold([0.0; 3], |acc, (q, k)| {
            let v = f(q);
            [acc[0] + k[0] * v, acc[1] + k[1] * v, acc[2] + k[2] * v]
        })
    };
    let members = &n.members;
    let targets = paths()
        .iter()
        .map(|p| integrate(&|q| p.members().iter().map(|&i| members[i][q]).product::<f64>()))
        .collect();
    let count = members.len() as f64;
    let mean = integrate(&|q| members.iter().map(|m| m[q]).sum::<f64>() / count);
    (targets, mean)
}
