//! The published few-wavelength rules, each built for one light as a
//! [`Rule`] whose weights include the light: `XYZ꜀ ≈ Σᵢ w꜀ᵢ·ρ(λᵢ)` for
//! the reflectance (or product of reflectances) `ρ` alone.
//!
//! With `w꜀(λ) = L(λ)·c̄(λ)` the light's weight for channel `c`:
//!
//! - **ASTM E308 / E2022** ([`Family::Astm`]): M wavelengths every
//!   `Δ = ⌊350/(M − 1)⌋` nm from 380 nm (10 nm at M = 36, 20 nm at
//!   M = 18); the weights are the Lagrange basis of the reflectance's
//!   cubic interpolant integrated against `w꜀` (E2022's construction of
//!   the E308 tables), exactly ([`PreparedLight::weights`]); where the
//!   last sample falls short of 730 nm the last cubic is extrapolated to
//!   730 nm and its share folded into the last four weights, as E308's end
//!   rows absorb what lies beyond them.
//! - **Wallis 1975** ([`Family::Wallis`]): three Gauss rules, one per
//!   `w꜀` (n_Y ≥ n_X ≥ n_Z, summing to M).
//! - **Meyer 1988** ([`Family::Meyer`]): one Gauss rule of M points for
//!   `L·(x̄ + ȳ + z̄)`, channel `c` weighted by `c̄/(x̄ + ȳ + z̄)` at its
//!   nodes: Meyer's one shared set of quadrature wavelengths (his paper
//!   chose them in an opponent space; this is the "one Gauss rule" form).
//! - **Borges 1994** ([`Family::Borges`]): M shared nodes that make each
//!   channel's interpolatory rule exact beyond degree M − 1: the node
//!   polynomial is orthogonal, under `w꜀`, to degrees below `r꜀`, the
//!   `r꜀` summing to M ("Gauss-like rules" for several weight functions
//!   sharing an integrand, Numer. Math. 67, 1994). A linear system for the
//!   polynomial; its roots must be real and inside the range. The even
//!   split (Y, then X, favoured for the remainder) is tried first, then
//!   splits one degree further from even; if none has real nodes inside,
//!   [`StudyError::NoRule`] (Borges's rules need not exist).
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::reference;
//! use speclab_study::published::rules::Family;
//! let exact = reference::xyz(&lights::D65, &patches::G4);
//! for family in [Family::Astm, Family::Borges, Family::Meyer] {
//!     let y = family.rule(&lights::D65, 12)?.xyz_of_product(&[&patches::G4]).y;
//!     assert!((y - exact.y).abs() < 0.02 * exact.y, "{family}: {y} against {}", exact.y);
//! }
//! // Wallis spends 12 wavelengths on three rules of 4: G4's Y is 25 % off.
//! let wallis = Family::Wallis.rule(&lights::D65, 12)?.xyz_of_product(&[&patches::G4]);
//! assert!((wallis.y - exact.y).abs() > 0.2 * exact.y);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::fmt;

use speclab::error::Error;
use speclab::sampling::PreparedLight;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::spectrum::observer::xyz_bar;
use speclab::spectrum::{Interpolation, LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, Spectrum};

use crate::StudyError;
use crate::published::gauss::{Measure, Recurrence, to_lambda};
use crate::published::solve::solve;

/// A published rule's construction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// ASTM E308 weighting factors by E2022's procedure, equal intervals.
    Astm,
    /// Borges 1994: shared nodes, one interpolatory rule per channel.
    Borges,
    /// Meyer 1988: one Gauss rule shared by the channels.
    Meyer,
    /// Wallis 1975: one Gauss rule per channel.
    Wallis,
}

impl Family {
    /// Every family.
    pub const ALL: [Family; 4] = [Family::Astm, Family::Borges, Family::Meyer, Family::Wallis];

    /// The names, in [`Family::ALL`]'s order.
    pub const NAMES: [&str; 4] = ["astm", "borges", "meyer", "wallis"];

    /// The fewest wavelengths it takes (ASTM's cubic needs four samples,
    /// Wallis one per channel).
    #[must_use]
    pub fn min_m(self) -> usize {
        match self {
            Family::Astm => 4,
            Family::Wallis => 3,
            Family::Borges | Family::Meyer => 1,
        }
    }

    /// The rule of `m` wavelengths for `light`. An [`Error::Count`] for `m`
    /// outside `min_m ..=` [`MAX_M`]; a [`StudyError::NoRule`] where the
    /// rule does not exist for the light (a light the observer cannot see,
    /// a Gauss rule of more points than its weight has support, Borges
    /// nodes that are not real and inside 380–730 nm).
    pub fn rule(self, light: &(impl Spectrum + ?Sized), m: usize) -> Result<Rule, StudyError> {
        if !(self.min_m()..=MAX_M).contains(&m) {
            let what = "a published rule's wavelength count";
            return Err(Error::Count { what, found: m, min: self.min_m(), max: MAX_M }.into());
        }
        let rule = match self {
            Family::Astm => Some(astm(light, m)?),
            Family::Borges => borges(light, m),
            Family::Meyer => meyer(light, m),
            Family::Wallis => wallis(light, m),
        };
        rule.ok_or_else(|| StudyError::NoRule { family: self.to_string(), m })
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let i = Family::ALL.iter().position(|x| x == self).unwrap_or(0);
        f.write_str(Family::NAMES[i])
    }
}

/// ASTM's interval for `m` wavelengths from 380 nm: `⌊350/(m − 1)⌋` nm.
#[must_use]
pub fn astm_interval(m: usize) -> f64 {
    (LAMBDA_WIDTH / (m.max(2) - 1) as f64).floor()
}

fn astm(light: &(impl Spectrum + ?Sized), m: usize) -> Result<Rule, Error> {
    let step = astm_interval(m);
    let grid: Vec<f64> = (0..m).map(|i| LAMBDA_MIN + step * i as f64).collect();
    let prepared = PreparedLight::for_grid(light, &grid, Interpolation::Cubic)?;
    let mut weights = prepared.weights().clone();
    let last = &grid[m - 4..];
    for (j, share) in tail(light, last).into_iter().enumerate() {
        (0..3).for_each(|c| weights[c][m - 4 + j] += share[c]);
    }
    Rule::new(grid, weights)
}

/// Gauss–Legendre's 4 points on [−1, 1] and their weights (exact to
/// degree 7: a cubic × a linear light × a cubic observer on a 1 nm
/// segment, whose breaks lie on whole nanometres).
const GAUSS_4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// `∫ ℓⱼ·L·c̄` from the last sample to 730 nm, for the Lagrange basis `ℓⱼ`
/// of the cubic through the last four samples `nodes`: what extrapolating
/// the reflectance's last cubic adds to each of their weights.
fn tail(light: &(impl Spectrum + ?Sized), nodes: &[f64]) -> [[f64; 3]; 4] {
    let mut out = [[0.0; 3]; 4];
    let mut from = nodes[3];
    while from < LAMBDA_MAX {
        let to = (from.floor() + 1.0).min(LAMBDA_MAX);
        let (mid, half) = (0.5 * (from + to), 0.5 * (to - from));
        for (x, w) in GAUSS_4 {
            let l = mid + half * x;
            let (weight, bar) = (w * half * light.eval(l), xyz_bar(l));
            for (j, out) in out.iter_mut().enumerate() {
                let basis: f64 =
                    (0..4).filter(|&k| k != j).map(|k| (l - nodes[k]) / (nodes[j] - nodes[k])).product();
                (0..3).for_each(|c| out[c] += weight * basis * bar[c]);
            }
        }
        from = to;
    }
    out
}

/// The light's weight for each channel, and for their sum, as measures.
fn measures(light: &(impl Spectrum + ?Sized)) -> [Measure; 4] {
    let channel = |c: usize| Measure::new(|l| light.eval(l) * xyz_bar(l)[c]);
    [channel(0), channel(1), channel(2), Measure::new(|l| light.eval(l) * xyz_bar(l).iter().sum::<f64>())]
}

/// `m` split over the channels, Y first, then X, then Z.
fn split(m: usize) -> [usize; 3] {
    let (q, r) = (m / 3, m % 3);
    [q + usize::from(r >= 2), q + usize::from(r >= 1), q]
}

fn wallis(light: &(impl Spectrum + ?Sized), m: usize) -> Option<Rule> {
    let (mut lambda, mut weights) = (Vec::new(), [Vec::new(), Vec::new(), Vec::new()]);
    let measures = measures(light);
    for (c, n) in split(m).into_iter().enumerate() {
        let (rec, _) = measures[c].orthonormal(n)?;
        let (t, w) = rec.gauss();
        for (t, w) in t.into_iter().zip(w) {
            lambda.push(to_lambda(t));
            for (row, weights) in weights.iter_mut().enumerate() {
                weights.push(if row == c { w } else { 0.0 });
            }
        }
    }
    Rule::new(lambda, weights).ok()
}

fn meyer(light: &(impl Spectrum + ?Sized), m: usize) -> Option<Rule> {
    let [.., sum] = measures(light);
    let (rec, _) = sum.orthonormal(m)?;
    let (t, w) = rec.gauss();
    let lambda: Vec<f64> = t.into_iter().map(to_lambda).collect();
    let weights = [0, 1, 2].map(|c| {
        lambda.iter().zip(&w).map(|(&l, w)| w * xyz_bar(l)[c] / xyz_bar(l).iter().sum::<f64>()).collect()
    });
    Rule::new(lambda, weights).ok()
}

fn borges(light: &(impl Spectrum + ?Sized), m: usize) -> Option<Rule> {
    let [x, y, z, sum] = measures(light);
    let (rec, p) = sum.orthonormal(m)?;
    let nodes = splits(m).into_iter().find_map(|r| shared_nodes(&rec, &p, [&x, &y, &z], r, sum.points()))?;
    let row = |w: &Measure| interpolatory(&rec, &p, w, &nodes);
    let weights = [row(&x)?, row(&y)?, row(&z)?];
    Rule::new(nodes.iter().map(|&t| to_lambda(t)).collect(), weights).ok()
}

/// The ways of sharing `m` extra degrees among X, Y and Z, the even
/// split first (Y, then X, favoured on ties), then those one degree
/// further from it (Σ(3·r꜀ − m)² ≤ 54): Borges's rules exist for some and
/// not others.
fn splits(m: usize) -> Vec<[usize; 3]> {
    let mut all: Vec<[usize; 3]> =
        (0..=m).flat_map(|rx| (0..=m - rx).map(move |ry| [rx, ry, m - rx - ry])).collect();
    let spread = |r: &[usize; 3]| r.iter().map(|&k| (3 * k).abs_diff(m).pow(2)).sum::<usize>();
    let order = |r: &[usize; 3]| (spread(r), std::cmp::Reverse(r[1]), std::cmp::Reverse(r[0]));
    all.sort_by_key(order);
    all.retain(|r| spread(r) <= 54);
    all
}

/// The roots of the node polynomial `ω = p_m + Σ_{j<m} α_j p_j` (a
/// multiple of the monic one)
/// with `∫ ω·p_k·w꜀ = 0` for `k < r꜀`, if all `m` are real and inside.
fn shared_nodes(
    rec: &Recurrence,
    p: &[Vec<f64>],
    channels: [&Measure; 3],
    r: [usize; 3],
    points: &[f64],
) -> Option<Vec<f64>> {
    let m = rec.n();
    let (mut rows, mut rhs) = (Vec::with_capacity(m), Vec::with_capacity(m));
    for (w, r) in channels.iter().zip(r) {
        for k in 0..r {
            rows.push((0..m).map(|j| w.inner(&p[j], &p[k])).collect::<Vec<_>>());
            rhs.push(-w.inner(&p[m], &p[k]));
        }
    }
    let alpha = solve(rows, rhs)?;
    let omega = |t: f64| {
        let mut v = vec![0.0; m + 1];
        rec.values_into(t, &mut v);
        v[m] + alpha.iter().zip(&v).map(|(a, v)| a * v).sum::<f64>()
    };
    roots(&omega, points, m)
}

/// The weights of the interpolatory rule on `nodes` for the measure `w`:
/// exact for polynomials below degree `nodes.len()`.
fn interpolatory(rec: &Recurrence, p: &[Vec<f64>], w: &Measure, nodes: &[f64]) -> Option<Vec<f64>> {
    let m = nodes.len();
    let mut values = vec![0.0; rec.n() + 1];
    let mut rows = vec![vec![0.0; m]; m];
    for (i, &t) in nodes.iter().enumerate() {
        rec.values_into(t, &mut values);
        (0..m).for_each(|k| rows[k][i] = values[k]);
    }
    let moments = (0..m).map(|k| w.integrate(&p[k])).collect();
    solve(rows, moments)
}

/// The `m` roots of `f` between consecutive points, by bisection; `None`
/// unless there are exactly `m` sign changes.
fn roots(f: &impl Fn(f64) -> f64, points: &[f64], m: usize) -> Option<Vec<f64>> {
    let mut found = Vec::with_capacity(m);
    for pair in points.windows(2) {
        let (mut lo, mut hi) = (pair[0], pair[1]);
        let (flo, fhi) = (f(lo), f(hi));
        if flo == 0.0 {
            found.push(lo);
            continue;
        }
        if flo * fhi >= 0.0 {
            continue;
        }
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if (f(mid) < 0.0) == (flo < 0.0) { lo = mid } else { hi = mid }
        }
        found.push(0.5 * (lo + hi));
    }
    (found.len() == m).then_some(found)
}
