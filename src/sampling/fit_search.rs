//! Choosing a fitted rule's nodes: greedy forward selection, then local
//! refinement, on the normal equations of `fit.rs`.
//!
//! - **Greedy**: each step adds the candidate that lowers the weighted
//!   residual (summed over X, Y, Z) most. For every candidate at once, the
//!   reduction is `(bⱼ − zⱼ·y)² / (Gⱼⱼ − |zⱼ|²)` per channel, with `zⱼ =
//!   L⁻¹·G[S, j]` and `y = L⁻¹·b[S]` for the Cholesky factor `L` of the
//!   chosen set's Gram matrix; adding a node extends `L` and every `zⱼ` by
//!   one entry.
//! - **Refinement**: each node in turn is taken out (the others factored
//!   once) and put back at the best candidate within ±[`WINDOW`] nm of
//!   where it was, by the same formula; sweeps repeat while any move lowers
//!   the residual.

use crate::sampling::fit::{CANDIDATES, Problem};

/// How far refinement moves a node, nm (candidates).
const WINDOW: usize = 10;

/// A Cholesky factor of the Gram matrix of a set of nodes for one channel,
/// and `y = L⁻¹·b` on them.
struct Factor {
    n: usize,
    l: Vec<f64>,
    y: Vec<f64>,
}

impl Problem {
    /// `G[j][k]` of channel `c`.
    fn g(&self, c: usize, j: usize, k: usize) -> f64 {
        self.gram[c][j * CANDIDATES + k]
    }

    /// A tiny ridge on channel `c`'s diagonal, against rounding.
    fn ridge(&self, c: usize) -> f64 {
        1e-13 * (0..CANDIDATES).map(|j| self.g(c, j, j)).fold(0.0, f64::max)
    }

    /// The M nodes (candidate indices, increasing) and per channel their
    /// weights, by greedy choice and local refinement.
    pub(crate) fn fit(&self, m: usize) -> (Vec<usize>, [Vec<f64>; 3]) {
        let mut nodes = self.greedy(m.min(CANDIDATES));
        self.refine(&mut nodes);
        nodes.sort_unstable();
        let weights = [0, 1, 2].map(|c| self.weights(c, &nodes));
        (nodes, weights)
    }

    /// Greedy forward selection of `m` nodes.
    fn greedy(&self, m: usize) -> Vec<usize> {
        let mut z =
            [(); 3].map(|()| (0..CANDIDATES).map(|_| Vec::with_capacity(m)).collect::<Vec<Vec<f64>>>());
        let mut d: [Vec<f64>; 3] = [0, 1, 2].map(|c| (0..CANDIDATES).map(|j| self.g(c, j, j)).collect());
        let mut y = [(); 3].map(|()| Vec::with_capacity(m));
        let ridge = [0, 1, 2].map(|c| self.ridge(c));
        let mut nodes = Vec::with_capacity(m);
        for _ in 0..m {
            let score = |j: usize| -> f64 {
                (0..3)
                    .map(|c| {
                        let num = self.rhs[c][j] - dot(&z[c][j], &y[c]);
                        num * num / (d[c][j] + ridge[c])
                    })
                    .sum()
            };
            let open = (0..CANDIDATES).filter(|&j| !nodes.contains(&j) && (0..3).all(|c| d[c][j] > ridge[c]));
            let Some(s) = best(open.map(|j| (j, -score(j)))) else { break };
            for c in 0..3 {
                let root = d[c][s].sqrt();
                let zs = z[c][s].clone();
                y[c].push((self.rhs[c][s] - dot(&zs, &y[c])) / root);
                for j in 0..CANDIDATES {
                    let e = (self.g(c, s, j) - dot(&zs, &z[c][j])) / root;
                    z[c][j].push(e);
                    d[c][j] -= e * e;
                }
            }
            nodes.push(s);
        }
        nodes
    }

    /// Moves each node to the best candidate near it while that helps.
    fn refine(&self, nodes: &mut [usize]) {
        let mut current = self.residual(nodes);
        for _sweep in 0..16 {
            let mut improved = false;
            for i in 0..nodes.len() {
                let others: Vec<usize> =
                    nodes.iter().enumerate().filter(|&(k, _)| k != i).map(|(_, &j)| j).collect();
                let factors = [0, 1, 2].map(|c| self.factor(c, &others));
                let base: f64 = (0..3).map(|c| self.square[c] - dot(&factors[c].y, &factors[c].y)).sum();
                let here = nodes[i];
                let (lo, hi) = (here.saturating_sub(WINDOW), (here + WINDOW).min(CANDIDATES - 1));
                let open = (lo..=hi).filter(|j| !others.contains(j));
                let scored = open.filter_map(|j| {
                    let gain: Option<f64> = (0..3).map(|c| self.gain(c, &factors[c], &others, j)).sum();
                    gain.map(|g| (j, base - g))
                });
                if let Some(j) = best(scored).filter(|&j| j != here) {
                    let moved = {
                        nodes[i] = j;
                        self.residual(nodes)
                    };
                    if moved < current * (1.0 - 1e-12) {
                        current = moved;
                        improved = true;
                    } else {
                        nodes[i] = here;
                    }
                }
            }
            if !improved {
                break;
            }
        }
    }

    /// The residual lowered by adding candidate `j` to `nodes` (factored
    /// in `f`) for channel `c`; `None` if `j` adds nothing independent.
    fn gain(&self, c: usize, f: &Factor, nodes: &[usize], j: usize) -> Option<f64> {
        let z = f.forward(&nodes.iter().map(|&k| self.g(c, k, j)).collect::<Vec<_>>());
        let d = self.g(c, j, j) - dot(&z, &z);
        let num = self.rhs[c][j] - dot(&z, &f.y);
        (d > self.ridge(c)).then(|| num * num / d)
    }

    /// The weighted residual of the best weights on `nodes`, summed over
    /// the channels.
    fn residual(&self, nodes: &[usize]) -> f64 {
        (0..3)
            .map(|c| {
                let f = self.factor(c, nodes);
                self.square[c] - dot(&f.y, &f.y)
            })
            .sum()
    }

    /// Channel `c`'s Cholesky factor on `nodes`, and `y`.
    fn factor(&self, c: usize, nodes: &[usize]) -> Factor {
        let n = nodes.len();
        let ridge = self.ridge(c);
        let mut l = vec![0.0; n * n];
        for i in 0..n {
            for k in 0..=i {
                let sum: f64 = (0..k).map(|p| l[i * n + p] * l[k * n + p]).sum();
                let g = self.g(c, nodes[i], nodes[k]) + if i == k { ridge } else { 0.0 };
                l[i * n + k] = if i == k { (g - sum).max(ridge).sqrt() } else { (g - sum) / l[k * n + k] };
            }
        }
        let mut f = Factor { n, l, y: Vec::new() };
        f.y = f.forward(&nodes.iter().map(|&j| self.rhs[c][j]).collect::<Vec<_>>());
        f
    }

    /// Channel `c`'s least-squares weights on `nodes`.
    fn weights(&self, c: usize, nodes: &[usize]) -> Vec<f64> {
        let f = self.factor(c, nodes);
        let (n, l) = (f.n, &f.l);
        let mut w = vec![0.0; n];
        for i in (0..n).rev() {
            w[i] = (f.y[i] - (i + 1..n).map(|p| l[p * n + i] * w[p]).sum::<f64>()) / l[i * n + i];
        }
        w
    }
}

impl Factor {
    /// `L⁻¹·b`.
    fn forward(&self, b: &[f64]) -> Vec<f64> {
        let (n, l) = (self.n, &self.l);
        let mut x = vec![0.0; n];
        for i in 0..n {
            x[i] = (b[i] - (0..i).map(|p| l[i * n + p] * x[p]).sum::<f64>()) / l[i * n + i];
        }
        x
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The index with the smallest score (the first of equals); `None` for none.
fn best(scored: impl Iterator<Item = (usize, f64)>) -> Option<usize> {
    scored
        .fold(None, |acc: Option<(usize, f64)>, (j, s)| match acc {
            Some((_, b)) if b <= s => acc,
            _ => Some((j, s)),
        })
        .map(|(j, _)| j)
}
