//! What a fit needs of its reflectances, whatever the lights: each
//! reflectance's values at the candidate wavelengths and at the nodes of
//! the quadrature the exact targets are computed on, the paths through
//! them (products of one to four), each path's row weight, and per channel
//! the Gram matrix `Σ ω²·v(λⱼ)·v(λₖ)` over the paths, which a light only
//! scales (`problem.rs`).
//!
//! The built-in prior's moments ([`Moments::builtin`]) are computed once per
//! process; a scene's own surfaces ([`Moments::of`]) once per
//! [`FittedRules::with_surfaces`](crate::sampling::fitted::FittedRules::with_surfaces).
//! Both take the same path: the built-in rules are the rules fitted to the
//! prior's 512 reflectances as surfaces (tested).

use std::sync::OnceLock;

use crate::error::Error;
use crate::sampling::prior::{PriorPath, draw_paths, prior};
use crate::spectrum::{LAMBDA_MIN, Spectrum, integrate, observer, quadrature};

/// Candidate wavelengths: every nm from 380 to 730.
pub(crate) const CANDIDATES: usize = 351;

/// Candidate `j`, nm.
pub(crate) fn candidate(j: usize) -> f64 {
    LAMBDA_MIN + j as f64
}

/// The most surfaces a fit takes (in a release build the moments take
/// about 40 ms for a few surfaces and 0.1 ms and 12 kB more for each).
pub const MAX_SURFACES: usize = 4096;

/// The largest magnitude of a surface's value a fit takes: reflectances,
/// fluorescent ones included, and products of four of them stay far from
/// overflow.
pub const MAX_REFLECTANCE: f64 = 1e3;

/// A fit's reflectances and what the fit needs of them.
pub(crate) struct Moments {
    /// Per channel, `Σ ω²·v(λⱼ)·v(λₖ)` over the paths (C × C, row-major).
    pub(super) gram: [Vec<f64>; 3],
    /// Each path's value at the candidates.
    pub(super) values: Vec<[f64; CANDIDATES]>,
    /// Each path's row weight per channel.
    pub(super) omega2: Vec<[f64; 3]>,
    /// The mean of `omega2` per channel.
    pub(super) mean_omega2: [f64; 3],
    /// The reflectances' mean at the candidates (an anchor).
    pub(super) mean: [f64; CANDIDATES],
    /// Each reflectance at the quadrature's nodes.
    members: Vec<Vec<f64>>,
    /// The paths, as reflectances multiplied.
    paths: Vec<PriorPath>,
}

/// The nodes the targets are computed on, 16-point Gauss–Legendre on each
/// 5 nm piece (the data's grid), with their weights.
fn nodes() -> &'static (Vec<f64>, Vec<f64>) {
    static NODES: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    NODES.get_or_init(|| {
        let (mut lambda, mut weight) = (Vec::new(), Vec::new());
        for i in 0..70 {
            let (mid, half) = (LAMBDA_MIN + 5.0 * f64::from(i) + 2.5, 2.5);
            for &(x, w) in quadrature::gauss(16) {
                lambda.push(mid + half * x);
                weight.push(w * half);
            }
        }
        (lambda, weight)
    })
}

impl Moments {
    /// The built-in prior's (`prior.rs`), computed on first use.
    pub(crate) fn builtin() -> &'static Moments {
        static BUILTIN: OnceLock<Moments> = OnceLock::new();
        BUILTIN.get_or_init(|| {
            let members: Vec<&dyn Spectrum> = prior().iter().map(|r| r as &dyn Spectrum).collect();
            // The prior's members lie in (0, 1) (prior.rs's test): never an error.
            let (at_candidates, at_nodes) = sample(&members).unwrap_or_else(|_| unreachable!());
            Moments::new(&at_candidates, at_nodes)
        })
    }

    /// The moments of `surfaces`: each alone, then products of two to
    /// four drawn as the built-in prior's are. An [`Error::Count`] for none
    /// or more than [`MAX_SURFACES`]; an [`Error::Surface`] for a value
    /// that is not finite or above [`MAX_REFLECTANCE`] in magnitude.
    pub(crate) fn of(surfaces: &[&dyn Spectrum]) -> Result<Moments, Error> {
        if !(1..=MAX_SURFACES).contains(&surfaces.len()) {
            let (found, max) = (surfaces.len(), MAX_SURFACES);
            return Err(Error::Count { what: "a fit's surfaces", found, min: 1, max });
        }
        let (at_candidates, at_nodes) = sample(surfaces)?;
        Ok(Moments::new(&at_candidates, at_nodes))
    }

    fn new(at_candidates: &[[f64; CANDIDATES]], members: Vec<Vec<f64>>) -> Moments {
        let paths = draw_paths(members.len());
        let values: Vec<[f64; CANDIDATES]> = paths
            .iter()
            .map(|p| std::array::from_fn(|j| p.members().iter().map(|&i| at_candidates[i][j]).product()))
            .collect();
        let count = at_candidates.len() as f64;
        let mean = std::array::from_fn(|j| at_candidates.iter().map(|m| m[j]).sum::<f64>() / count);
        let mut moments = Moments {
            gram: [Vec::new(), Vec::new(), Vec::new()],
            values,
            omega2: Vec::new(),
            mean_omega2: [0.0; 3],
            mean,
            members,
            paths,
        };
        let equal = integrate::white(&crate::spectrum::Constant::new(1.0));
        let (own, _) = moments.targets(&crate::spectrum::Constant::new(1.0), 1.0);
        moments.omega2 = own
            .iter()
            .map(|own| std::array::from_fn(|c| (own[c] / equal[c]).max(0.01).powf(-4.0 / 3.0)))
            .collect();
        moments.gram = [0, 1, 2].map(|c| gram(&moments.values, &moments.omega2, c));
        let n = moments.paths.len() as f64;
        moments.mean_omega2 = [0, 1, 2].map(|c| moments.omega2.iter().map(|w| w[c]).sum::<f64>() / n);
        moments
    }

    /// The XYZ of `light / scale` times each path, and times the
    /// reflectances' mean, by the quadrature of [`nodes`]. Exact to about
    /// 1e-12 relative for lights and reflectances whose breaks lie on the
    /// 5 nm grid (the built-in lights; the prior's members are smooth); a
    /// light with kinks between grid points is integrated less exactly
    /// (about 1e-4), which moves the fit by far less than its own error.
    pub(super) fn targets(&self, light: &dyn Spectrum, scale: f64) -> (Vec<[f64; 3]>, [f64; 3]) {
        let (lambda, weight) = nodes();
        let kernel: Vec<[f64; 3]> = lambda
            .iter()
            .zip(weight)
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
        let members = &self.members;
        let targets = self
            .paths
            .iter()
            .map(|p| integrate(&|q| p.members().iter().map(|&i| members[i][q]).product::<f64>()))
            .collect();
        let count = members.len() as f64;
        let mean = integrate(&|q| members.iter().map(|m| m[q]).sum::<f64>() / count);
        (targets, mean)
    }
}

/// Surfaces sampled: at the candidates, and at the quadrature's nodes.
type Sampled = (Vec<[f64; CANDIDATES]>, Vec<Vec<f64>>);

/// Each surface at the candidates and at the quadrature's nodes; an
/// [`Error::Surface`] for a value that is not finite or above
/// [`MAX_REFLECTANCE`] in magnitude.
fn sample(surfaces: &[&dyn Spectrum]) -> Result<Sampled, Error> {
    let (lambda, _) = nodes();
    let mut at_candidates = Vec::with_capacity(surfaces.len());
    let mut at_nodes = Vec::with_capacity(surfaces.len());
    for (index, s) in surfaces.iter().enumerate() {
        let c: [f64; CANDIDATES] = std::array::from_fn(|j| s.eval(candidate(j)));
        let n: Vec<f64> = lambda.iter().map(|&l| s.eval(l)).collect();
        let mut values = c.iter().zip((0..).map(candidate)).chain(n.iter().zip(lambda.iter().copied()));
        if let Some((&value, lambda)) = values.find(|(v, _)| v.is_nan() || v.abs() > MAX_REFLECTANCE) {
            return Err(Error::Surface { index, lambda, value });
        }
        at_candidates.push(c);
        at_nodes.push(n);
    }
    Ok((at_candidates, at_nodes))
}

/// Channel `c`'s `Σ ω²·v(λⱼ)·v(λₖ)` (C × C, row-major, symmetric).
fn gram(values: &[[f64; CANDIDATES]], omega2: &[[f64; 3]], c: usize) -> Vec<f64> {
    let mut g = vec![0.0; CANDIDATES * CANDIDATES];
    for (v, w) in values.iter().zip(omega2) {
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Constant;

    /// The built-in prior's moments are those of its 512 reflectances
    /// handed over as surfaces, bit for bit: one path for both.
    #[test]
    fn the_prior_is_a_list_of_surfaces() {
        let members: Vec<&dyn Spectrum> = prior().iter().map(|r| r as &dyn Spectrum).collect();
        let (builtin, given) = (Moments::builtin(), Moments::of(&members).unwrap());
        assert_eq!(builtin.values.len(), 512 + 512);
        assert_eq!(builtin.gram, given.gram);
        assert_eq!(builtin.values, given.values);
        assert_eq!(builtin.omega2, given.omega2);
        assert_eq!(builtin.mean, given.mean);
        assert_eq!(builtin.mean_omega2, given.mean_omega2);
        // The mean is the members' mean, and a path their product.
        let j = 175;
        let mean = members.iter().map(|m| m.eval(candidate(j))).sum::<f64>() / 512.0;
        assert!((builtin.mean[j] - mean).abs() <= 1e-15);
        let p = &builtin.paths[600];
        let product: f64 = p.members().iter().map(|&i| members[i].eval(candidate(j))).product();
        assert!(p.members().len() >= 2 && (builtin.values[600][j] - product).abs() <= 1e-15 * product);
    }

    /// A row's weight is CIELAB's sensitivity at the surface's own colour:
    /// a grey of 0.5 weighs `0.5^(−4/3)`, a black the floor `0.01^(−4/3)`.
    #[test]
    fn rows_are_weighted_by_lightness() {
        let (grey, black) = (Constant::new(0.5), Constant::new(0.0));
        let m = Moments::of(&[&grey as &dyn Spectrum, &black]).unwrap();
        for c in 0..3 {
            assert!((m.omega2[0][c] - 0.5f64.powf(-4.0 / 3.0)).abs() < 1e-9, "{:?}", m.omega2[0]);
            assert!((m.omega2[1][c] - 0.01f64.powf(-4.0 / 3.0)).abs() < 1e-6, "{:?}", m.omega2[1]);
        }
        assert!((m.mean[10] - 0.25).abs() < 1e-15);
    }

    /// None, too many, or a value that is not finite: an error naming it.
    #[test]
    fn bad_surfaces_are_errors() {
        let grey = Constant::new(0.5);
        let none: [&dyn Spectrum; 0] = [];
        assert!(matches!(Moments::of(&none), Err(Error::Count { found: 0, .. })));
        let many = vec![&grey as &dyn Spectrum; MAX_SURFACES + 1];
        assert!(matches!(Moments::of(&many), Err(Error::Count { found, .. }) if found == MAX_SURFACES + 1));
        let nan = crate::spectrum::Constant::new(f64::NAN);
        match Moments::of(&[&grey as &dyn Spectrum, &nan]) {
            Err(e @ Error::Surface { index: 1, lambda, value }) => {
                assert!(lambda == 380.0 && value.is_nan());
                assert_eq!(
                    e.to_string(),
                    "surface 1: expected a reflectance from -1000 to 1000, found NaN at 380 nm"
                );
            }
            other => panic!("{:?}", other.map(|_| ())),
        }
        // Finite but past overflow in a product of four: an error too,
        // while a fluorescent 1.5 is a reflectance.
        let (huge, bright) = (Constant::new(-1e100), Constant::new(1.5));
        assert!(matches!(Moments::of(&[&huge as &dyn Spectrum]), Err(Error::Surface { index: 0, .. })));
        assert!(Moments::of(&[&bright as &dyn Spectrum]).is_ok());
        // The limit itself is in.
        let (top, over) = (Constant::new(-MAX_REFLECTANCE), Constant::new(MAX_REFLECTANCE * (1.0 + 1e-15)));
        assert!(Moments::of(&[&top as &dyn Spectrum]).is_ok());
        assert!(Moments::of(&[&over as &dyn Spectrum]).is_err());
    }
}
