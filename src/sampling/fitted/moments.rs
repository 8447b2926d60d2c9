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

use std::borrow::Cow;
use std::sync::OnceLock;

use crate::error::Error;
use crate::sampling::prior::{PriorPath, draw_paths, prior};
use crate::spectrum::{FnSpectrum, Spectrum, StandardObserver, WavelengthRange, integrate, quadrature};

/// The candidate wavelengths of the assignment's range: every nm from 380
/// to 730.
pub(crate) const CANDIDATES: usize = 351;

/// Where a fit's rules may put their wavelengths (every whole nanometre of
/// a range) and the observer whose XYZ they reproduce.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Grid {
    range: WavelengthRange,
    observer: StandardObserver,
}

impl Grid {
    /// 380–730 nm with the assignment's observer: the study's, the default.
    pub(crate) const ASSIGNMENT: Grid =
        Grid { range: WavelengthRange::ASSIGNMENT, observer: StandardObserver::Assignment };

    /// A grid with `observer` over `range`: an error unless the range has
    /// whole-nanometre ends within the observer's data.
    pub(crate) fn new(observer: StandardObserver, range: WavelengthRange) -> Result<Grid, Error> {
        let range = observer.check(range)?;
        if range.min().fract() != 0.0 || range.max().fract() != 0.0 {
            return Err(Error::OffGrid { range: [range.min(), range.max()], first: 0.0, step: 1.0 });
        }
        Ok(Grid { range, observer })
    }

    /// How many candidates.
    pub(crate) fn count(self) -> usize {
        self.range.width() as usize + 1
    }

    /// Candidate `j`, nm.
    pub(crate) fn lambda(self, j: usize) -> f64 {
        self.range.min() + j as f64
    }

    /// `[X, Y, Z]` of the perfect white under `light` on this grid's range
    /// and observer, exactly.
    pub(crate) fn white(self, light: &dyn Spectrum) -> [f64; 3] {
        if self == Grid::ASSIGNMENT {
            return integrate::white(light);
        }
        integrate::xyz_of_product_with(self.observer, self.range, &[light]).unwrap_or([f64::NAN; 3])
    }

    /// The nodes the targets are computed on, with their weights:
    /// 16-point Gauss–Legendre on pieces of at most 5 nm for the
    /// assignment's observer (its data's grid), 4-point on each nanometre
    /// for a 1 nm table (lines between nanometres).
    fn nodes(self) -> (Vec<f64>, Vec<f64>) {
        let (nominal, points) = if self.observer.table().is_some() { (1.0, 4) } else { (5.0, 16) };
        // Whole pieces of at most the nominal width covering the range
        // (380–730 nm: seventy of 5 nm).
        let pieces = (self.range.width() / nominal).ceil().max(1.0) as usize;
        let piece = self.range.width() / pieces as f64;
        let (mut lambda, mut weight) = (Vec::new(), Vec::new());
        for i in 0..pieces {
            let (mid, half) = (self.range.min() + piece * i as f64 + 0.5 * piece, 0.5 * piece);
            for &(x, w) in quadrature::gauss(points) {
                lambda.push(mid + half * x);
                weight.push(w * half);
            }
        }
        (lambda, weight)
    }
}

/// The most surfaces a fit takes (in a release build the moments take
/// about 40 ms for a few surfaces and 0.1 ms and 12 kB more for each).
pub const MAX_SURFACES: usize = 4096;

/// The largest magnitude of a surface's value a fit takes: reflectances,
/// fluorescent ones included, and products of four of them stay far from
/// overflow.
pub const MAX_REFLECTANCE: f64 = 1e3;

/// A fit's reflectances and what the fit needs of them.
#[derive(Clone)]
pub(crate) struct Moments {
    /// The candidates and the observer.
    pub(super) grid: Grid,
    /// Per channel, `Σ ω²·v(λⱼ)·v(λₖ)` over the paths (C × C, row-major).
    pub(super) gram: [Vec<f64>; 3],
    /// Each path's value at the candidates.
    pub(super) values: Vec<Vec<f64>>,
    /// Each path's row weight per channel.
    pub(super) omega2: Vec<[f64; 3]>,
    /// The mean of `omega2` per channel.
    pub(super) mean_omega2: [f64; 3],
    /// The reflectances' mean at the candidates (an anchor).
    pub(super) mean: Vec<f64>,
    /// The quadrature's nodes and weights.
    nodes: (Vec<f64>, Vec<f64>),
    /// Each reflectance at the quadrature's nodes.
    members: Vec<Vec<f64>>,
    /// The paths, as reflectances multiplied.
    paths: Vec<PriorPath>,
}

impl Moments {
    /// The built-in prior's on `grid` (`prior.rs`; read over the grid's
    /// range): kept for the assignment's grid and for 360–830 nm with
    /// either CIE observer (computed on first use), made afresh for
    /// any other grid.
    pub(crate) fn builtin(grid: Grid) -> Cow<'static, Moments> {
        static KEPT: [OnceLock<Moments>; 3] = [const { OnceLock::new() }; 3];
        let visible = |observer| Grid { range: WavelengthRange::VISIBLE, observer };
        let kept = [Grid::ASSIGNMENT, visible(StandardObserver::Cie1931), visible(StandardObserver::Cie1964)];
        match kept.iter().position(|&g| g == grid) {
            Some(i) => Cow::Borrowed(KEPT[i].get_or_init(|| Moments::prior(grid))),
            None => Cow::Owned(Moments::prior(grid)),
        }
    }

    /// The prior's moments on `grid`.
    fn prior(grid: Grid) -> Moments {
        let formulas: Vec<_> = prior().iter().map(|r| FnSpectrum(|lambda| r.value(lambda))).collect();
        let members: Vec<&dyn Spectrum> = formulas.iter().map(|r| r as &dyn Spectrum).collect();
        // The prior's members lie in (0, 1) (prior.rs's test): never an error.
        let (at_candidates, at_nodes) = sample(&members, grid).unwrap_or_else(|_| unreachable!());
        Moments::new(grid, &at_candidates, at_nodes)
    }

    /// The moments of `surfaces` on `grid`: each alone, then products of
    /// two to four drawn as the built-in prior's are. An [`Error::Count`]
    /// for none or more than [`MAX_SURFACES`]; an [`Error::Surface`] for a
    /// value that is not finite or above [`MAX_REFLECTANCE`] in magnitude.
    pub(crate) fn of(surfaces: &[&dyn Spectrum], grid: Grid) -> Result<Moments, Error> {
        if !(1..=MAX_SURFACES).contains(&surfaces.len()) {
            let (found, max) = (surfaces.len(), MAX_SURFACES);
            return Err(Error::Count { what: "a fit's surfaces", found, min: 1, max });
        }
        let (at_candidates, at_nodes) = sample(surfaces, grid)?;
        Ok(Moments::new(grid, &at_candidates, at_nodes))
    }

    fn new(grid: Grid, at_candidates: &[Vec<f64>], members: Vec<Vec<f64>>) -> Moments {
        let paths = draw_paths(members.len());
        let values: Vec<Vec<f64>> = paths
            .iter()
            .map(|p| {
                (0..grid.count())
                    .map(|j| p.members().iter().map(|&i| at_candidates[i][j]).product())
                    .collect()
            })
            .collect();
        let count = at_candidates.len() as f64;
        let mean =
            (0..grid.count()).map(|j| at_candidates.iter().map(|m| m[j]).sum::<f64>() / count).collect();
        let mut moments = Moments {
            grid,
            gram: [Vec::new(), Vec::new(), Vec::new()],
            values,
            omega2: Vec::new(),
            mean_omega2: [0.0; 3],
            mean,
            nodes: grid.nodes(),
            members,
            paths,
        };
        let equal = grid.white(&crate::spectrum::Constant::new(1.0));
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
        let (lambda, weight) = &self.nodes;
        let kernel: Vec<[f64; 3]> = lambda
            .iter()
            .zip(weight)
            .map(|(&l, &w)| {
                let k = light.eval(l) / scale * w;
                self.grid.observer.xyz_bar(l).map(|c| c * k)
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
type Sampled = (Vec<Vec<f64>>, Vec<Vec<f64>>);

/// Each surface at the candidates and at the quadrature's nodes; an
/// [`Error::Surface`] for a value that is not finite or above
/// [`MAX_REFLECTANCE`] in magnitude.
fn sample(surfaces: &[&dyn Spectrum], grid: Grid) -> Result<Sampled, Error> {
    let (lambda, _) = grid.nodes();
    let mut at_candidates = Vec::with_capacity(surfaces.len());
    let mut at_nodes = Vec::with_capacity(surfaces.len());
    for (index, s) in surfaces.iter().enumerate() {
        let c: Vec<f64> = (0..grid.count()).map(|j| s.eval(grid.lambda(j))).collect();
        let n: Vec<f64> = lambda.iter().map(|&l| s.eval(l)).collect();
        let mut values =
            c.iter().zip((0..).map(|j| grid.lambda(j))).chain(n.iter().zip(lambda.iter().copied()));
        if let Some((&value, lambda)) = values.find(|(v, _)| v.is_nan() || v.abs() > MAX_REFLECTANCE) {
            return Err(Error::Surface { index, lambda, value });
        }
        at_candidates.push(c);
        at_nodes.push(n);
    }
    Ok((at_candidates, at_nodes))
}

/// Channel `c`'s `Σ ω²·v(λⱼ)·v(λₖ)` (C × C, row-major, symmetric).
fn gram(values: &[Vec<f64>], omega2: &[[f64; 3]], c: usize) -> Vec<f64> {
    let n = values.first().map_or(0, Vec::len);
    let mut g = vec![0.0; n * n];
    for (v, w) in values.iter().zip(omega2) {
        for j in 0..n {
            let a = w[c] * v[j];
            let row = &mut g[j * n..(j + 1) * n];
            for (g, &vk) in row[j..].iter_mut().zip(&v[j..]) {
                *g += a * vk;
            }
        }
    }
    for j in 0..n {
        for k in 0..j {
            g[j * n + k] = g[k * n + j];
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
        let (builtin, given) =
            (Moments::builtin(Grid::ASSIGNMENT), Moments::of(&members, Grid::ASSIGNMENT).unwrap());
        assert_eq!(builtin.values.len(), 512 + 512);
        assert_eq!(builtin.gram, given.gram);
        assert_eq!(builtin.values, given.values);
        assert_eq!(builtin.omega2, given.omega2);
        assert_eq!(builtin.mean, given.mean);
        assert_eq!(builtin.mean_omega2, given.mean_omega2);
        // The mean is the members' mean, and a path their product.
        let j = 175;
        let mean = members.iter().map(|m| m.eval(Grid::ASSIGNMENT.lambda(j))).sum::<f64>() / 512.0;
        assert!((builtin.mean[j] - mean).abs() <= 1e-15);
        let p = &builtin.paths[600];
        let product: f64 = p.members().iter().map(|&i| members[i].eval(Grid::ASSIGNMENT.lambda(j))).product();
        assert!(p.members().len() >= 2 && (builtin.values[600][j] - product).abs() <= 1e-15 * product);
    }

    /// A row's weight is CIELAB's sensitivity at the surface's own colour:
    /// a grey of 0.5 weighs `0.5^(−4/3)`, a black the floor `0.01^(−4/3)`.
    #[test]
    fn rows_are_weighted_by_lightness() {
        let (grey, black) = (Constant::new(0.5), Constant::new(0.0));
        let m = Moments::of(&[&grey as &dyn Spectrum, &black], Grid::ASSIGNMENT).unwrap();
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
        assert!(matches!(Moments::of(&none, Grid::ASSIGNMENT), Err(Error::Count { found: 0, .. })));
        let many = vec![&grey as &dyn Spectrum; MAX_SURFACES + 1];
        assert!(
            matches!(Moments::of(&many, Grid::ASSIGNMENT), Err(Error::Count { found, .. }) if found == MAX_SURFACES + 1)
        );
        let nan = crate::spectrum::Constant::new(f64::NAN);
        match Moments::of(&[&grey as &dyn Spectrum, &nan], Grid::ASSIGNMENT) {
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
        assert!(matches!(
            Moments::of(&[&huge as &dyn Spectrum], Grid::ASSIGNMENT),
            Err(Error::Surface { index: 0, .. })
        ));
        assert!(Moments::of(&[&bright as &dyn Spectrum], Grid::ASSIGNMENT).is_ok());
        // The limit itself is in.
        let (top, over) = (Constant::new(-MAX_REFLECTANCE), Constant::new(MAX_REFLECTANCE * (1.0 + 1e-15)));
        assert!(Moments::of(&[&top as &dyn Spectrum], Grid::ASSIGNMENT).is_ok());
        assert!(Moments::of(&[&over as &dyn Spectrum], Grid::ASSIGNMENT).is_err());
    }
}
