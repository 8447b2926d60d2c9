//! Exact reference weights: the XYZ of a fixed light times any reflectance
//! tabulated on a given grid, as a dot product with the reflectance's
//! samples.
//!
//! The interpolants are linear in their samples. On segment k the cubic is
//! `R(λ) = Σⱼ r₍ₛ₊ⱼ₎·ℓⱼ(λ)`, with `ℓⱼ` the Lagrange basis of the segment's
//! four-sample stencil starting at s (linear: two samples). So
//!
//! `∫ L·R·c̄ dλ = Σₖ Σⱼ r₍ₛ₊ⱼ₎·Wₖⱼ`, with `Wₖⱼ = ∫ over segment k of L·c̄·ℓⱼ`,
//!
//! and summing the segments that share a sample gives one weight per
//! sample and channel. Each `Wₖⱼ` is integrated exactly (Gauss–Legendre
//! between the breaks of L and c̄; degree 1 + 3 + 3 = 7). Where the
//! reflectance's clamp acts on a segment, R is not `Σ r·ℓ` there: that
//! segment's term is replaced by its exact integral ([`segment_exact`]).
//!
//! For reflectances given as raw samples, two tests tell when a segment's
//! cubic provably stays in `[0, 1]`. Exactly ([`Weights::hull`]): its
//! Bernstein coefficients are linear in the samples, and the cubic lies in
//! their convex hull. Faster, on equidistant grids ([`Weights::margins`]):
//! the inner Bernstein coefficients differ from the linear interpolation at
//! ⅓ and ⅔ by a combination of the stencil's two second divided
//! differences, so `min(yₖ, yₖ₊₁) − Cₖ·S ≥ 0` and `max(yₖ, yₖ₊₁) + Cₖ·S ≤ 1`,
//! with S the larger |difference|, clear segment k.
//!
//! `sampling::PreparedLight` computes them once for a light and applies
//! them. Any piecewise polynomial light has them: the light enters only
//! through its value and its breaks.

use std::borrow::Cow;

use crate::spectrum::integrate;
use crate::spectrum::interface::Spectrum;
use crate::spectrum::interp::{self, Coeffs};
use crate::spectrum::observer;
use crate::spectrum::piecewise::pieces_into;
use crate::spectrum::quadrature::{self, integrate};
use crate::spectrum::validate::Interpolation;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};

/// Exact weights of one light for reflectances on one grid.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Weights {
    /// The reflectances' wavelengths, nm.
    pub(crate) grid: Vec<f64>,
    /// The reflectances' interpolation.
    pub(crate) cubic: bool,
    /// The integration range: 380–730 nm ∩ the light's and the grid's support.
    pub(crate) range: [f64; 2],
    /// One weight per sample, as three columns (x̄, ȳ, z̄), for sums four
    /// samples at a time.
    pub(crate) columns: [Vec<f64>; 3],
    /// Per segment, per stencil sample (4; linear uses 2), per channel.
    pub(crate) segments: Vec<[[f64; 3]; 4]>,
    /// Per segment: the stencil vectors giving the cubic's inner Bernstein
    /// coefficients b₁ and b₂ (b₀ and b₃ are the segment's samples).
    pub(crate) hull: Vec<[[f64; 4]; 2]>,
    /// Per segment: the |coefficient sum| turning the stencil's two second
    /// divided differences into a bound on the inner Bernstein coefficients'
    /// distance from the linear interpolation (0 for linear grids).
    pub(crate) margins: Vec<f64>,
    /// The grid's step if it is equidistant ([`Weights::step`]), found once.
    pub(crate) step: Option<f64>,
    /// The largest margin of the middle segments (all but the first and the
    /// last), found once.
    pub(crate) middle_margin: f64,
}

impl Weights {
    /// The reflectances' wavelengths, nm.
    #[must_use]
    pub(crate) fn grid(&self) -> &[f64] {
        &self.grid
    }

    /// The reflectances' interpolation.
    #[must_use]
    pub(crate) fn interpolation(&self) -> Interpolation {
        if self.cubic { Interpolation::Cubic } else { Interpolation::Linear }
    }

    /// The integration range, nm.
    pub(crate) fn range(&self) -> [f64; 2] {
        self.range
    }

    /// The weights as three columns, x̄, ȳ and z̄, one weight per sample.
    pub(crate) fn columns(&self) -> &[Vec<f64>; 3] {
        &self.columns
    }

    /// Segment `k`'s weights per stencil sample, and where its stencil starts.
    pub(crate) fn segment(&self, k: usize) -> (&[[f64; 3]], usize) {
        let (s, width) = stencil(self.cubic, k, self.grid.len());
        (&self.segments[k][..width], s)
    }

    /// Segment `k`'s Bernstein stencil vectors (cubic grids).
    pub(crate) fn hull(&self) -> &[[[f64; 4]; 2]] {
        &self.hull
    }

    /// Per segment, the margin `Cₖ` of `min(yₖ, yₖ₊₁) − Cₖ·S ≥ 0`, with S
    /// the larger |second divided difference| of the segment's stencil.
    pub(crate) fn margins(&self) -> &[f64] {
        &self.margins
    }

    /// The largest of [`Weights::margins`] but the first and the last (0
    /// for fewer than three segments).
    pub(crate) fn middle_margin(&self) -> f64 {
        self.middle_margin
    }

    /// For an equidistant grid of step h, the step (margins divided by
    /// `2h²` apply to plain second differences `y₀ − 2y₁ + y₂`, which are
    /// `2h²·[x₀, x₁, x₂]y`). `None` for other grids.
    pub(crate) fn step(&self) -> Option<f64> {
        self.step
    }
}

/// The step of `grid` (two samples at least) if its samples are equally
/// spaced (to 1e-9 of the step), else `None`.
pub(crate) fn equidistant_step(grid: &[f64]) -> Option<f64> {
    let h = (grid[grid.len() - 1] - grid[0]) / (grid.len() - 1) as f64;
    grid.windows(2).all(|w| ((w[1] - w[0]) - h).abs() <= 1e-9 * h).then_some(h)
}

/// The stencil of segment `k` of `n` samples: first sample and width.
pub(crate) fn stencil(cubic: bool, k: usize, n: usize) -> (usize, usize) {
    if cubic { (speclab_tables::interp::stencil(k, n), 4) } else { (k, 2) }
}

impl Weights {
    /// The weights of `light` for reflectances interpolated by
    /// `interpolation` on `grid` (strictly increasing, enough samples):
    /// exact for a piecewise polynomial light, by quadrature for others
    /// (as `integrate.rs` integrates them).
    pub(crate) fn compute(light: &dyn Spectrum, grid: &[f64], interpolation: Interpolation) -> Self {
        let (breaks, rule) = light_rule(light);
        let cmf = &observer::views();
        let cubic = interpolation == Interpolation::Cubic;
        let n = grid.len();
        let range = [LAMBDA_MIN.max(grid[0]), LAMBDA_MAX.min(grid[n - 1])];
        let breaks = [&breaks[..], cmf[0].breaks, cmf[1].breaks, cmf[2].breaks];
        let mut scratch = Vec::new();
        let segments: Vec<[[f64; 3]; 4]> = (0..n - 1)
            .map(|k| {
                let (s, width) = stencil(cubic, k, n);
                let nodes = &grid[s..s + width];
                if !pieces_into(&mut scratch, grid[k], grid[k + 1], range, breaks) {
                    return [[0.0; 3]; 4];
                }
                let flat: [f64; 12] = integrate(rule, &scratch, |x| {
                    let (basis, l) = (lagrange(nodes, x), light.eval(x));
                    let c = [cmf[0].eval(x), cmf[1].eval(x), cmf[2].eval(x)].map(|c| c * l);
                    std::array::from_fn(|i| c[i % 3] * basis[i / 3])
                });
                std::array::from_fn(|j| std::array::from_fn(|c| flat[3 * j + c]))
            })
            .collect();
        let mut samples = vec![[0.0; 3]; n];
        for (k, w) in segments.iter().enumerate() {
            let (s, width) = stencil(cubic, k, n);
            for (j, wj) in w.iter().enumerate().take(width) {
                for c in 0..3 {
                    samples[s + j][c] += wj[c];
                }
            }
        }
        let hull: Vec<[[f64; 4]; 2]> = (0..n - 1).map(|k| bernstein(grid, k, cubic)).collect();
        let margins = if cubic { margins(grid, &hull) } else { vec![0.0; n - 1] };
        let middle = margins.get(1..margins.len().saturating_sub(1)).unwrap_or(&[]);
        let middle_margin = middle.iter().fold(0.0, |a: f64, &b| a.max(b));
        let step = equidistant_step(grid);
        let columns = std::array::from_fn(|c| samples.iter().map(|w| w[c]).collect());
        Weights { grid: grid.to_vec(), cubic, range, columns, segments, hull, margins, step, middle_margin }
    }
}

/// The light's breaks and the rule that integrates it times a cubic and a
/// matching function exactly on each piece (at least 5 points; for a light
/// that is not piecewise polynomial, [`integrate::SMOOTH_EXTRA`] degrees
/// more, on pieces of at most 5 nm between the observer's breaks).
fn light_rule(light: &dyn Spectrum) -> (Cow<'_, [f64]>, &'static quadrature::GaussRule) {
    let (breaks, degree) = match light.pieces() {
        Some(p) => (p.breaks, p.degree),
        None => (Cow::Borrowed(&[][..]), integrate::SMOOTH_EXTRA),
    };
    (breaks, quadrature::gauss(((degree + 6) / 2 + 1).max(5)))
}

/// The Lagrange basis through `nodes` (2 or 4 of them) at `x`; unused
/// entries 0.
fn lagrange(nodes: &[f64], x: f64) -> [f64; 4] {
    std::array::from_fn(|j| {
        if j >= nodes.len() {
            return 0.0;
        }
        let mut l = 1.0;
        for (m, &xm) in nodes.iter().enumerate() {
            if m != j {
                l *= (x - xm) / (nodes[j] - xm);
            }
        }
        l
    })
}

/// For the cubic of segment `k` of `grid`: the vectors β₁, β₂ with
/// `b₁ = β₁·y`, `b₂ = β₂·y` over the stencil samples `y` (Bernstein
/// coefficients on the segment: `b₁ = p(0) + h·p'(0)/3`,
/// `b₂ = p(h) − h·p'(h)/3`). Zero for linear grids (never used there).
fn bernstein(grid: &[f64], k: usize, cubic: bool) -> [[f64; 4]; 2] {
    if !cubic {
        return [[0.0; 4]; 2];
    }
    let (s, h) = (interp::stencil(k, grid.len()), grid[k + 1] - grid[k]);
    // The basis function ℓⱼ as a cubic in t = λ − λₖ, for each j.
    let basis: [interp::Coeffs; 4] = std::array::from_fn(|j| {
        let y: [f64; 4] = std::array::from_fn(|i| f64::from(u8::from(i == j)));
        interp::cubic_segment(&grid[s..s + 4], &y, k - s)
    });
    let b1 = basis.map(|c| c[0] + h * c[1] / 3.0);
    let b2 =
        basis.map(|c| interp::segment_value(c, h) - h * (c[1] + h * (2.0 * c[2] + 3.0 * h * c[3])) / 3.0);
    [b1, b2]
}

/// The coefficients of the second divided difference `[x₀, x₁, x₂]`.
fn divided_difference(x: [f64; 3]) -> [f64; 3] {
    [
        1.0 / ((x[0] - x[1]) * (x[0] - x[2])),
        1.0 / ((x[1] - x[0]) * (x[1] - x[2])),
        1.0 / ((x[2] - x[0]) * (x[2] - x[1])),
    ]
}

/// Per segment, the larger `|α| + |β|` of its two inner Bernstein
/// coefficients, where `b − (linear interpolation at ⅓ or ⅔) =
/// α·[x₀,x₁,x₂]y + β·[x₁,x₂,x₃]y` over the segment's stencil x₀..x₃. (A
/// functional on four nodes that vanishes on lines is such a combination;
/// α and β follow from its first and last coefficients, where only one of
/// the two differences has a term.)
fn margins(grid: &[f64], hull: &[[[f64; 4]; 2]]) -> Vec<f64> {
    let n = grid.len();
    hull.iter()
        .enumerate()
        .map(|(k, beta)| {
            let mut worst = 0.0f64;
            let s = interp::stencil(k, n);
            let (first, last) = (
                divided_difference([grid[s], grid[s + 1], grid[s + 2]]),
                divided_difference([grid[s + 1], grid[s + 2], grid[s + 3]]),
            );
            for (b, share) in beta.iter().zip([1.0 / 3.0, 2.0 / 3.0]) {
                // The linear interpolation at `share` of the segment, on the stencil.
                let mut gamma = *b;
                gamma[k - s] -= 1.0 - share;
                gamma[k + 1 - s] -= share;
                let (alpha, beta) = (gamma[0] / first[0], gamma[3] / last[2]);
                worst = worst.max(alpha.abs() + beta.abs());
            }
            worst
        })
        .collect()
}

/// The exact `∫ L·clamp(p)·c̄` over segment `[knot, next]` ∩ `range`, where
/// `p` is the reflectance's polynomial `c` (in `t = λ − knot`), clamped to
/// `bounds`: pieces between the breaks of the light, the observer and the
/// clamp's crossings. `scratch` is reused between calls.
pub(crate) fn segment_exact(
    light: &dyn Spectrum,
    [knot, next]: [f64; 2],
    c: Coeffs,
    bounds: [f64; 2],
    range: [f64; 2],
    scratch: &mut Vec<f64>,
) -> [f64; 3] {
    let cmf = &observer::views();
    let (breaks, rule) = light_rule(light);
    let breaks = [&breaks[..], cmf[0].breaks, cmf[1].breaks, cmf[2].breaks];
    if !pieces_into(scratch, knot, next, range, breaks) {
        return [0.0; 3];
    }
    let (a, b) = (scratch[0], scratch[scratch.len() - 1]);
    let (crossings, count) = interp::crossings(c, bounds, next - knot);
    scratch.extend(crossings[..count].iter().map(|t| knot + t).filter(|&x| x > a && x < b));
    scratch.sort_by(f64::total_cmp);
    scratch.dedup();
    integrate(rule, scratch, |x| {
        let r = interp::clamp(interp::segment_value(c, x - knot), bounds);
        let lr = light.eval(x) * r;
        [cmf[0].eval(x) * lr, cmf[1].eval(x) * lr, cmf[2].eval(x) * lr]
    })
}

#[cfg(test)]
mod tests {
    use super::{Weights, equidistant_step};

    /// The step of an equally spaced grid, to 1e-9 of it; `None` for any
    /// other grid.
    #[test]
    fn the_step_of_an_equidistant_grid() {
        let grid = |h: f64, n: usize| (0..n).map(|i| 380.0 + h * i as f64).collect::<Vec<f64>>();
        assert_eq!(equidistant_step(&grid(10.0, 36)), Some(10.0));
        assert_eq!(equidistant_step(&grid(0.5, 701)), Some(0.5));
        assert_eq!(equidistant_step(&[400.0, 700.0]), Some(300.0));
        let mut uneven = grid(10.0, 36);
        uneven[17] += 1e-9; // 1e-10 of the step: within the tolerance
        assert_eq!(equidistant_step(&uneven).map(|h| (h - 10.0).abs() < 1e-12), Some(true));
        uneven[17] += 1e-6; // 1e-7 of the step: not equidistant
        assert_eq!(equidistant_step(&uneven), None);
        assert_eq!(equidistant_step(&[380.0, 390.0, 410.0]), None);
    }

    /// A light's weights keep their grid's step and the largest middle
    /// margin.
    #[test]
    fn weights_keep_the_step_and_the_middle_margin() {
        use crate::spectrum::{Interpolation, data::lights};
        let grid: Vec<f64> = (0..36).map(|i| 380.0 + 10.0 * f64::from(i)).collect();
        let w = Weights::compute(&lights::A, &grid, Interpolation::Cubic);
        assert_eq!(w.step(), Some(10.0));
        let m = w.margins();
        assert_eq!(w.middle_margin(), m[1..m.len() - 1].iter().fold(0.0, |a: f64, &b| a.max(b)));
        assert!(w.middle_margin() > 0.0 && m.len() == 35);
        let uneven = [380.0, 400.0, 450.0, 600.0, 730.0];
        assert_eq!(Weights::compute(&lights::A, &uneven, Interpolation::Cubic).step(), None);
    }
}
