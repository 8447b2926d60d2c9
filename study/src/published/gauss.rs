//! Orthogonal polynomials and Gauss rules for a weight function known on a
//! fine grid: the machinery of the published quadratures (Wallis 1975,
//! Meyer 1988, Borges 1994).
//!
//! A [`Measure`] is a weight function `w(λ) ≥ 0` sampled every
//! [`STEP`] nm over 380–730 nm (trapezoid masses), in the variable
//! `t = (λ − 555)/175 ∈ [−1, 1]`. [`Measure::orthonormal`] runs the
//! discretised Stieltjes procedure (with full reorthogonalisation) to the
//! polynomials `p₀ … pₙ` orthonormal for it, kept as their three-term
//! recurrence ([`Recurrence`]) and as values on the grid.
//! [`Recurrence::gauss`] gives the n-point Gauss rule: the nodes are the
//! eigenvalues of the Jacobi matrix (Golub and Welsch 1969), found by Sturm
//! bisection; the weights are the Christoffel numbers `1/Σₖ pₖ(tᵢ)²`.
//!
//! ```
//! use speclab_study::published::gauss::Recurrence;
//! // Gauss–Legendre, 3 points: 0 and ±√(3/5), weights 8/9 and 5/9.
//! let (t, w) = Recurrence::legendre(3).gauss();
//! assert!((t[2] - 0.6f64.sqrt()).abs() < 1e-14 && (w[1] - 8.0 / 9.0).abs() < 1e-14);
//! ```

use speclab::spectrum::{LAMBDA_MIN, LAMBDA_WIDTH};

/// The grid step of a [`Measure`], nm.
pub const STEP: f64 = 0.25;

/// The centre and half-width of the range, nm: `t = (λ − CENTRE)/HALF`.
const CENTRE: f64 = LAMBDA_MIN + 0.5 * LAMBDA_WIDTH;
const HALF: f64 = 0.5 * LAMBDA_WIDTH;

/// `λ` in the normalised variable `t ∈ [−1, 1]`.
#[must_use]
pub fn to_t(lambda: f64) -> f64 {
    (lambda - CENTRE) / HALF
}

/// `t` back in nm.
#[must_use]
pub fn to_lambda(t: f64) -> f64 {
    CENTRE + HALF * t
}

/// A weight function on the grid: points `t` and their masses (nm × the
/// weight's unit).
#[derive(Clone, Debug)]
pub struct Measure {
    t: Vec<f64>,
    mass: Vec<f64>,
}

impl Measure {
    /// `w` sampled every [`STEP`] nm over 380–730 nm, trapezoid masses
    /// (negative values count as 0).
    pub fn new(w: impl Fn(f64) -> f64) -> Measure {
        let n = (LAMBDA_WIDTH / STEP).round() as usize;
        let lambda = (0..=n).map(|j| LAMBDA_MIN + j as f64 * STEP);
        let mass = lambda
            .clone()
            .enumerate()
            .map(|(j, l)| w(l).max(0.0) * STEP * if j == 0 || j == n { 0.5 } else { 1.0 })
            .collect();
        Measure { t: lambda.map(to_t).collect(), mass }
    }

    /// The points, in `t`.
    #[must_use]
    pub fn points(&self) -> &[f64] {
        &self.t
    }

    /// `∫ f·w dλ` for `f` given on the points.
    #[must_use]
    pub fn integrate(&self, f: &[f64]) -> f64 {
        self.mass.iter().zip(f).map(|(m, f)| m * f).sum()
    }

    /// `∫ f·g·w dλ` for `f` and `g` given on the points.
    #[must_use]
    pub fn inner(&self, f: &[f64], g: &[f64]) -> f64 {
        self.mass.iter().zip(f).zip(g).map(|((m, f), g)| m * f * g).sum()
    }

    /// The polynomials `p₀ … pₙ` orthonormal for this measure: their
    /// recurrence, and their values on the points (`n + 1` rows). `None`
    /// if the measure has fewer than `n + 1` points of mass (no such
    /// polynomials) or no mass.
    #[must_use]
    pub fn orthonormal(&self, n: usize) -> Option<(Recurrence, Vec<Vec<f64>>)> {
        let mu0: f64 = self.mass.iter().sum();
        let support = self.mass.iter().filter(|&&m| m > 0.0).count();
        if support <= n || !mu0.is_finite() {
            return None;
        }
        let mut p = vec![vec![1.0 / mu0.sqrt(); self.t.len()]];
        let (mut a, mut b): (Vec<f64>, Vec<f64>) = (Vec::with_capacity(n), vec![0.0]);
        for k in 0..n {
            // t·pₖ less its components along p₀ … pₖ (Gram–Schmidt, twice):
            // the three-term recurrence's step, kept orthogonal to rounding.
            let mut q: Vec<f64> = self.t.iter().zip(&p[k]).map(|(t, p)| t * p).collect();
            a.push(self.inner(&q, &p[k]));
            for _ in 0..2 {
                for prev in &p {
                    let c = self.inner(&q, prev);
                    q.iter_mut().zip(prev).for_each(|(q, p)| *q -= c * p);
                }
            }
            // Positive: more points of mass than degrees (checked above).
            let norm2 = self.inner(&q, &q);
            b.push(norm2);
            p.push(q.iter().map(|q| q / norm2.sqrt()).collect());
        }
        Some((Recurrence { a, b, mu0 }, p))
    }
}

/// The three-term recurrence of orthonormal polynomials:
/// `√bₖ₊₁·pₖ₊₁(t) = (t − aₖ)·pₖ(t) − √bₖ·pₖ₋₁(t)`, `p₀ = 1/√μ₀`.
#[derive(Clone, Debug, PartialEq)]
pub struct Recurrence {
    /// `a₀ … aₙ₋₁`.
    a: Vec<f64>,
    /// `b₀ = 0, b₁ … bₙ`.
    b: Vec<f64>,
    /// The measure's mass.
    mu0: f64,
}

impl Recurrence {
    /// The Legendre recurrence (weight 1 on [−1, 1]) to degree `n`:
    /// `aₖ = 0`, `bₖ = k²/(4k² − 1)`, `μ₀ = 2`.
    #[must_use]
    pub fn legendre(n: usize) -> Recurrence {
        let b = (0..=n).map(|k| (k * k) as f64 / (4 * k * k).saturating_sub(1).max(1) as f64).collect();
        Recurrence { a: vec![0.0; n], b, mu0: 2.0 }
    }

    /// The degree `n` it reaches.
    #[must_use]
    pub fn n(&self) -> usize {
        self.a.len()
    }

    /// `aₖ`.
    #[must_use]
    pub fn a(&self) -> &[f64] {
        &self.a
    }

    /// `bₖ` (`b₀ = 0`).
    #[must_use]
    pub fn b(&self) -> &[f64] {
        &self.b
    }

    /// `p₀(t) … pₙ(t)` into `out` (as many as it holds, up to `n + 1`).
    pub fn values_into(&self, t: f64, out: &mut [f64]) {
        let Some(first) = out.first_mut() else { return };
        *first = 1.0 / self.mu0.sqrt();
        let n = self.n().min(out.len() - 1);
        for k in 0..n {
            let before = if k > 0 { self.b[k].sqrt() * out[k - 1] } else { 0.0 };
            out[k + 1] = ((t - self.a[k]) * out[k] - before) / self.b[k + 1].sqrt();
        }
    }

    /// The n-point Gauss rule (`n` = [`Recurrence::n`]): nodes in `t`,
    /// increasing, and weights (summing to μ₀).
    #[must_use]
    pub fn gauss(&self) -> (Vec<f64>, Vec<f64>) {
        let n = self.n();
        let nodes: Vec<f64> = (0..n).map(|i| self.eigenvalue(i)).collect();
        let mut p = vec![0.0; n + 1];
        let weights = nodes
            .iter()
            .map(|&t| {
                self.values_into(t, &mut p);
                1.0 / p[..n].iter().map(|p| p * p).sum::<f64>()
            })
            .collect();
        (nodes, weights)
    }

    /// How many eigenvalues of the n × n Jacobi matrix lie below `x`
    /// (Sturm: the negative pivots of `J − x·I`; `b₀ = 0` starts it).
    fn below(&self, x: f64) -> usize {
        let mut d = 1.0;
        let mut count = 0;
        for k in 0..self.n() {
            d = self.a[k] - x - self.b[k] / d;
            if d == 0.0 {
                // A zero pivot: perturbed, as the next pivot's division needs.
                d = -f64::EPSILON * (1.0 + x.abs());
            }
            count += usize::from(d < 0.0);
        }
        count
    }

    /// The i-th smallest eigenvalue, by bisection inside a bound on every
    /// eigenvalue (Gershgorin: `|λ − aₖ| ≤ √bₖ + √bₖ₊₁`).
    fn eigenvalue(&self, i: usize) -> f64 {
        let reach = self.b.iter().map(|b| b.sqrt()).fold(0.0, f64::max);
        let (lo, hi) =
            self.a.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &a| (l.min(a), h.max(a)));
        let (mut lo, mut hi) = (lo - 2.0 * reach, hi + 2.0 * reach);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if self.below(mid) > i { hi = mid } else { lo = mid }
        }
        0.5 * (lo + hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_five_points_match_the_tables() {
        // Abramowitz and Stegun, Table 25.4.
        let (t, w) = Recurrence::legendre(5).gauss();
        let nodes = [-0.906_179_845_938_664, -0.538_469_310_105_683_1, 0.0];
        let weights = [0.236_926_885_056_189_1, 0.478_628_670_499_366_5, 0.568_888_888_888_888_9];
        for i in 0..3 {
            assert!((t[i] - nodes[i]).abs() < 1e-14 && (t[4 - i] + nodes[i]).abs() < 1e-14, "{t:?}");
            assert!((w[i] - weights[i]).abs() < 1e-14 && (w[4 - i] - weights[i]).abs() < 1e-14, "{w:?}");
        }
    }

    #[test]
    fn stieltjes_on_a_flat_weight_finds_the_legendre_recurrence() {
        // Weight 1 over 380–730 nm is Legendre in t, scaled by HALF nm.
        let (rec, p) = Measure::new(|_| 1.0).orthonormal(6).unwrap();
        let legendre = Recurrence::legendre(6);
        for k in 0..6 {
            assert!(rec.a()[k].abs() < 1e-9, "a{k} = {}", rec.a()[k]);
            assert!((rec.b()[k + 1] - legendre.b()[k + 1]).abs() < 1e-5, "b{}", k + 1);
        }
        let m = Measure::new(|_| 1.0);
        assert!((m.inner(&p[3], &p[5])).abs() < 1e-12 && (m.inner(&p[4], &p[4]) - 1.0).abs() < 1e-12);
        let mut at = [0.0; 7];
        rec.values_into(m.points()[100], &mut at);
        assert!((at[6] - p[6][100]).abs() < 1e-9 * p[6][100].abs().max(1.0));
        let mut two = [0.0; 2];
        rec.values_into(m.points()[100], &mut two);
        assert_eq!(two, [at[0], at[1]]);
        rec.values_into(0.0, &mut []);
    }

    #[test]
    fn a_gauss_rule_integrates_degree_2n_minus_1_exactly() {
        let m = Measure::new(|l| 1.0 + ((l - 450.0) / 40.0).powi(2));
        let (rec, _) = m.orthonormal(4).unwrap();
        let (t, w) = rec.gauss();
        let f = |t: f64| t.powi(7) - 2.0 * t.powi(3) + 0.5;
        let exact = m.integrate(&m.points().iter().map(|&t| f(t)).collect::<Vec<_>>());
        let rule: f64 = t.iter().zip(&w).map(|(t, w)| w * f(*t)).sum();
        assert!((rule - exact).abs() < 1e-10 * exact.abs(), "{rule} against {exact}");
        assert!(Measure::new(|_| 0.0).orthonormal(2).is_none());
        assert!(Measure::new(|l| if l < 400.0 { f64::INFINITY } else { 1.0 }).orthonormal(2).is_none());
        assert!(Measure::new(|l| f64::from(u8::from((l - 500.0).abs() < 0.3))).orthonormal(3).is_none());
    }
}
