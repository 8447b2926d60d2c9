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
//!   the E308 tables), exactly, over 380–730 nm
//!   ([`PreparedLight::weights`]).
//! - **Wallis 1975** ([`Family::Wallis`]): three Gauss rules, one per
//!   `w꜀` (n_Y ≥ n_X ≥ n_Z, summing to M).
//! - **Meyer 1988** ([`Family::Meyer`]): one Gauss rule of M points for
//!   `L·(x̄ + ȳ + z̄)`, channel `c` weighted by `c̄/(x̄ + ȳ + z̄)` at its
//!   nodes: Meyer's one shared set of quadrature wavelengths (his paper
//!   chose them in an opponent space; this is the "one Gauss rule" form).
//! - **Borges 1994** ([`Family::Borges`]): M shared nodes that make each
//!   channel's interpolatory rule exact beyond degree M − 1: the monic
//!   node polynomial is orthogonal, under `w꜀`, to degrees below `r꜀`,
//!   with `r_Y ≥ r_X ≥ r_Z` summing to M ("Gauss-like rules" for several
//!   weight functions sharing an integrand, Numer. Math. 67, 1994). A
//!   linear system for the polynomial; its roots must be real and inside
//!   the range, else [`Error::NoMass`] (Borges's rules need not exist).
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
//! # Ok::<(), speclab::Error>(())
//! ```

use std::fmt;

use speclab::error::Error;
use speclab::sampling::PreparedLight;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::spectrum::observer::xyz_bar;
use speclab::spectrum::{Interpolation, LAMBDA_MIN, LAMBDA_WIDTH, Spectrum};

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
    /// outside `min_m ..=` [`MAX_M`]; an [`Error::NoMass`] for a light the
    /// observer cannot see, or (Borges) nodes that are not real and inside
    /// 380–730 nm.
    pub fn rule(self, light: &(impl Spectrum + ?Sized), m: usize) -> Result<Rule, Error> {
        if !(self.min_m()..=MAX_M).contains(&m) {
            return Err(Error::Count {
                what: "a published rule's wavelength count",
                found: m,
                min: self.min_m(),
                max: MAX_M,
            });
        }
        match self {
            Family::Astm => astm(light, m),
            Family::Borges => borges(light, m),
            Family::Meyer => meyer(light, m),
            Family::Wallis => wallis(light, m),
        }
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
    Rule::new(grid, prepared.weights().clone())
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

fn wallis(light: &(impl Spectrum + ?Sized), m: usize) -> Result<Rule, Error> {
    let (mut lambda, mut weights) = (Vec::new(), [Vec::new(), Vec::new(), Vec::new()]);
    let measures = measures(light);
    for (c, n) in split(m).into_iter().enumerate() {
        let (rec, _) = measures[c].orthonormal(n).ok_or(Error::NoMass)?;
        let (t, w) = rec.gauss();
        for (t, w) in t.into_iter().zip(w) {
            lambda.push(to_lambda(t));
            for (row, weights) in weights.iter_mut().enumerate() {
                weights.push(if row == c { w } else { 0.0 });
            }
        }
    }
    Rule::new(lambda, weights)
}

fn meyer(light: &(impl Spectrum + ?Sized), m: usize) -> Result<Rule, Error> {
    let [.., sum] = measures(light);
    let (rec, _) = sum.orthonormal(m).ok_or(Error::NoMass)?;
    let (t, w) = rec.gauss();
    let lambda: Vec<f64> = t.into_iter().map(to_lambda).collect();
    let weights = [0, 1, 2].map(|c| {
        lambda.iter().zip(&w).map(|(&l, w)| w * xyz_bar(l)[c] / xyz_bar(l).iter().sum::<f64>()).collect()
    });
    Rule::new(lambda, weights)
}

fn borges(light: &(impl Spectrum + ?Sized), m: usize) -> Result<Rule, Error> {
    let [x, y, z, sum] = measures(light);
    let (rec, p) = sum.orthonormal(m).ok_or(Error::NoMass)?;
    let nodes = splits(m).into_iter().find_map(|r| shared_nodes(&rec, &p, [&x, &y, &z], r, sum.points()));
    let nodes = nodes.ok_or(Error::NoMass)?;
    let row = |w: &Measure| interpolatory(&rec, &p, w, &nodes);
    let weights = [row(&x)?, row(&y)?, row(&z)?];
    Rule::new(nodes.iter().map(|&t| to_lambda(t)).collect(), weights)
}

/// The ways of sharing `m` extra degrees among X, Y and Z, most balanced
/// first (Y, then X, favoured on ties): Borges's rules exist for some and
/// not others.
fn splits(m: usize) -> Vec<[usize; 3]> {
    let mut all: Vec<[usize; 3]> =
        (0..=m).flat_map(|rx| (0..=m - rx).map(move |ry| [rx, ry, m - rx - ry])).collect();
    let spread = |r: &[usize; 3]| r.iter().map(|&k| (3 * k).abs_diff(m).pow(2)).sum::<usize>();
    let order = |r: &[usize; 3]| (spread(r), std::cmp::Reverse(r[1]), std::cmp::Reverse(r[0]));
    all.sort_by_key(order);
    all.retain(|r| spread(r) <= 54); // no channel more than two degrees from an even share
    all
}

/// The roots of the monic node polynomial `ω = p_m + Σ_{j<m} α_j p_j`
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
fn interpolatory(rec: &Recurrence, p: &[Vec<f64>], w: &Measure, nodes: &[f64]) -> Result<Vec<f64>, Error> {
    let m = nodes.len();
    let mut values = vec![0.0; rec.n() + 1];
    let mut rows = vec![vec![0.0; m]; m];
    for (i, &t) in nodes.iter().enumerate() {
        rec.values_into(t, &mut values);
        (0..m).for_each(|k| rows[k][i] = values[k]);
    }
    let moments = (0..m).map(|k| w.integrate(&p[k])).collect();
    solve(rows, moments).ok_or(Error::NoMass)
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
