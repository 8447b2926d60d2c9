//! A wavelength pdf that follows a light: `p(λ) ∝ L(λ)·Σ꜀ α꜀·c̄꜀(λ)` over
//! a range, 380–730 nm with the assignment's observer by default (or
//! `∝ S(λ)` alone, without the observer), tabulated exactly.
//!
//! Between consecutive breaks of the light and of the matching functions
//! every factor is one polynomial (a clamped segment contributes its bound),
//! so the density is one polynomial per piece, of degree at most 6. (A
//! light that is not piecewise polynomial, a blackbody or a sum with one,
//! is taken as the line through its values at the ends of each piece of at
//! most 5 nm: the density is then that line's, still exact for sampling
//! since `pdf` and `sample` use the same table.) Its
//! coefficients are exact products of the segments' polynomials, its
//! integral per piece is exact, and the CDF at the piece ends is their
//! running sum. Sampling finds the piece through a guide table (the piece
//! where each of `2 × pieces` equal slices of `[0, 1)` starts, then a step or
//! two forward) and inverts the piece's integral, a polynomial of degree at
//! most 7, by Halley's method from the trapezoid rule's guess, safeguarded by
//! bisection: about three iterations, no allocation, and the CDF of the
//! returned wavelength equals `u` to within 1e-12.
//!
//! The table is built when a [`super::pdf::LightPdf`] is made (about 8 µs
//! for a built-in light), for built-in and loaded lights alike.

use crate::spectrum::interp::{self, Coeffs};
use crate::spectrum::piecewise::View;
use crate::spectrum::{Interpolation, Role, Samples, Spectrum, StandardObserver, WavelengthRange, observer};

/// A spectrum's samples with their interpolant's polynomials and breaks,
/// computed as a `TabulatedSpectrum` computes them.
struct Table<'a> {
    samples: Samples<'a>,
    coeffs: Vec<Coeffs>,
    breaks: Vec<f64>,
}

impl<'a> Table<'a> {
    fn of(samples: Samples<'a>) -> Self {
        let (lambda, bounds) = (samples.lambda, samples.role.bounds());
        let coeffs = interp::coeffs(samples.interpolation, lambda, samples.values);
        let breaks = interp::breaks(lambda, &coeffs, bounds);
        Table { samples, coeffs, breaks }
    }

    fn view(&self) -> View<'_> {
        let bounds = self.samples.role.bounds();
        View { lambda: self.samples.lambda, coeffs: &self.coeffs, breaks: &self.breaks, bounds }
    }
}

/// Coefficients of the density on one piece, in `t = λ − start`.
pub(crate) type Poly = [f64; 7];

/// The tabulated density: piece ends, one polynomial per piece, the
/// unnormalised CDF at the ends, and the total.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PiecewisePdf {
    ends: Vec<f64>,
    polys: Vec<Poly>,
    cdf: Vec<f64>,
    /// `guide[i]`: the first piece whose CDF at its end exceeds
    /// `i/len·total`. Sampling starts there and steps forward: O(1).
    guide: Vec<u32>,
}

impl PiecewisePdf {
    /// The density ∝ `light·Σ alpha꜀·c̄꜀` (∝ `light` alone for `None`), or
    /// `None` if it integrates to zero (or to something not finite) over
    /// 380–730 nm, with the assignment's observer.
    pub(crate) fn new(light: &dyn Spectrum, alpha: Option<[f64; 3]>) -> Option<Self> {
        Self::new_over(light, alpha, StandardObserver::Assignment, WavelengthRange::ASSIGNMENT)
    }

    /// [`PiecewisePdf::new`] over `range` with `observer` (a CIE 1 nm
    /// table: lines between nanometres, so a piece per nanometre).
    pub(crate) fn new_over(
        light: &dyn Spectrum,
        alpha: Option<[f64; 3]>,
        observer: StandardObserver,
        range: WavelengthRange,
    ) -> Option<Self> {
        match observer.table() {
            None => Self::with_cmfs(light, alpha, observer::views(), range),
            Some((first, step, rows)) => {
                let lambda: Vec<f64> = (0..rows.len()).map(|i| first + step * i as f64).collect();
                let values: [Vec<f64>; 3] = std::array::from_fn(|c| rows.iter().map(|r| r[c]).collect());
                let tables: [Table<'_>; 3] = std::array::from_fn(|c| {
                    Table::of(Samples {
                        lambda: &lambda,
                        values: &values[c],
                        interpolation: Interpolation::Linear,
                        role: Role::Observer,
                    })
                });
                Self::with_cmfs(light, alpha, tables.each_ref().map(Table::view), range)
            }
        }
    }

    fn with_cmfs(
        light: &dyn Spectrum,
        alpha: Option<[f64; 3]>,
        cmf: [View<'_>; 3],
        range: WavelengthRange,
    ) -> Option<Self> {
        let (a, b) = (range.min(), range.max());
        let pieces = light.pieces();
        let mut ends: Vec<f64> = cmf.iter().flat_map(|v| v.breaks.iter().copied()).chain([a, b]).collect();
        if let Some(p) = &pieces {
            ends.extend(p.breaks.iter().copied());
        }
        ends.retain(|&x| x >= a && x <= b);
        ends.sort_by(f64::total_cmp);
        ends.dedup();
        let table = light.samples().map(Table::of);
        let view = table.as_ref().map(Table::view);
        let degree = pieces.map(|p| p.degree);
        let polys: Vec<Poly> = ends
            .windows(2)
            .map(|w| {
                let l = match &view {
                    Some(v) => piece_poly(v, w[0], w[1]),
                    None => spectrum_piece(light, w[0], w[1], degree),
                };
                let c = match alpha {
                    Some(alpha) => (0..3).fold([0.0; 4], |acc, i| {
                        let p = piece_poly(&cmf[i], w[0], w[1]);
                        std::array::from_fn(|j| acc[j] + alpha[i] * p[j])
                    }),
                    None => [1.0, 0.0, 0.0, 0.0],
                };
                product(l, c)
            })
            .collect();
        let mut cdf = Vec::with_capacity(ends.len());
        cdf.push(0.0);
        for (p, w) in polys.iter().zip(ends.windows(2)) {
            cdf.push(cdf[cdf.len() - 1] + primitive(p, w[1] - w[0]));
        }
        let total = cdf[cdf.len() - 1];
        let bright = total.is_finite() && total > 0.0 && cdf.windows(2).all(|c| c[1] >= c[0]);
        let guide = guide(&cdf, 2 * polys.len());
        bright.then_some(PiecewisePdf { ends, polys, cdf, guide })
    }

    fn total(&self) -> f64 {
        self.cdf[self.cdf.len() - 1]
    }

    /// The piece containing `lambda`, if inside the support.
    fn piece(&self, lambda: f64) -> Option<usize> {
        let (first, last) = (self.ends[0], self.ends[self.ends.len() - 1]);
        if !(lambda >= first && lambda <= last) {
            return None;
        }
        Some(self.ends.partition_point(|&x| x <= lambda).saturating_sub(1).min(self.polys.len() - 1))
    }

    /// The density at `lambda`, 1/nm; zero outside the range ∩ the light.
    pub(crate) fn pdf(&self, lambda: f64) -> f64 {
        self.piece(lambda)
            .map_or(0.0, |k| (value(&self.polys[k], lambda - self.ends[k]) / self.total()).max(0.0))
    }

    /// The first piece's start to the last one's end: where it draws.
    pub(crate) fn support(&self) -> WavelengthRange {
        let (first, last) = (self.ends.first().copied(), self.ends.last().copied());
        match (first, last) {
            (Some(a), Some(b)) => WavelengthRange::new(a, b).unwrap_or(WavelengthRange::VISIBLE),
            _ => WavelengthRange::VISIBLE,
        }
    }

    /// The CDF at `lambda`.
    pub(crate) fn cdf(&self, lambda: f64) -> f64 {
        match self.piece(lambda) {
            Some(k) => (self.cdf[k] + primitive(&self.polys[k], lambda - self.ends[k])) / self.total(),
            None if lambda >= self.ends[self.ends.len() - 1] => 1.0,
            None => 0.0,
        }
    }

    /// The wavelength whose CDF is `u` (clamped into `[0, 1)`; NaN acts as 0),
    /// never one where the density is zero on a whole piece.
    pub(crate) fn sample(&self, u: f64) -> f64 {
        self.sample_with_pdf(u).0
    }

    /// [`PiecewisePdf::sample`] and the density there, from the same piece.
    pub(crate) fn sample_with_pdf(&self, u: f64) -> (f64, f64) {
        let u = crate::sampling::analytic_pdf::unit(u);
        let total = self.total();
        let target = u * total;
        // The first piece whose CDF at its end exceeds the target has mass:
        // start where the guide points and step forward.
        let last = self.polys.len() - 1;
        let slot = ((u * self.guide.len() as f64) as usize).min(self.guide.len() - 1);
        let mut k = (self.guide[slot] as usize).min(last);
        while k < last && self.cdf[k + 1] <= target {
            k += 1;
        }
        let (p, h) = (&self.polys[k], self.ends[k + 1] - self.ends[k]);
        let t = invert(p, target - self.cdf[k], h, self.cdf[k + 1] - self.cdf[k]);
        (self.ends[k] + t, (value(p, t) / total).max(0.0))
    }
}

/// For `slots` equal slices of `[0, 1)`, the first piece whose CDF at its
/// end exceeds the slice's start.
fn guide(cdf: &[f64], slots: usize) -> Vec<u32> {
    let total = cdf[cdf.len() - 1];
    (0..slots.max(1))
        .map(|i| {
            let target = i as f64 / slots.max(1) as f64 * total;
            cdf[1..].partition_point(|&c| c <= target).min(cdf.len() - 2) as u32
        })
        .collect()
}

/// The polynomial of `v` on `[a, b]` (inside one of its segments) in
/// `t = λ − a`, with the clamp applied: a piece below or above the bounds is
/// the bound.
fn piece_poly(v: &View, a: f64, b: f64) -> Coeffs {
    let n = v.lambda.len();
    let mid = 0.5 * (a + b);
    if !(mid >= v.lambda[0] && mid <= v.lambda[n - 1]) {
        return [0.0; 4];
    }
    let k = interp::segment_of(v.lambda, mid).min(v.coeffs.len() - 1);
    let raw = interp::segment_value(v.coeffs[k], mid - v.lambda[k]);
    if raw < v.bounds[0] {
        return [v.bounds[0], 0.0, 0.0, 0.0];
    }
    if raw > v.bounds[1] {
        return [v.bounds[1], 0.0, 0.0, 0.0];
    }
    shift(v.coeffs[k], a - v.lambda[k])
}

/// `s` on `[a, b]` as a cubic in `t = λ − a`: the polynomial through four
/// values inside the piece when `s` is a polynomial of `degree` ≤ 3 there
/// (exact, to rounding), else the line through its values at the ends
/// (non-negative where `s` is).
fn spectrum_piece(s: &dyn Spectrum, a: f64, b: f64, degree: Option<usize>) -> Coeffs {
    let h = b - a;
    match degree {
        Some(d) if d <= 3 => {
            let t = [0.125, 0.375, 0.625, 0.875].map(|f| f * h);
            let y = t.map(|t| s.eval(a + t));
            // The cubic through (t, y), via the interpolant of the tables'
            // own four-point stencil (k = 0 of a four-knot table).
            let c = interp::cubic_segment(&t, &y, 0);
            shift(c, -t[0])
        }
        _ => {
            let (ya, yb) = (s.eval(a).max(0.0), s.eval(b).max(0.0));
            [ya, (yb - ya) / h, 0.0, 0.0]
        }
    }
}

/// `p(t + d)` as a polynomial in `t` (a Taylor shift of a cubic).
fn shift(c: Coeffs, d: f64) -> Coeffs {
    [
        c[0] + d * (c[1] + d * (c[2] + d * c[3])),
        c[1] + d * (2.0 * c[2] + 3.0 * d * c[3]),
        c[2] + 3.0 * d * c[3],
        c[3],
    ]
}

/// The product of two cubics.
fn product(a: Coeffs, b: Coeffs) -> Poly {
    let mut out = [0.0; 7];
    for (i, ai) in a.iter().enumerate() {
        for (j, bj) in b.iter().enumerate() {
            out[i + j] += ai * bj;
        }
    }
    out
}

/// `p(t)` by Estrin's scheme: pairs, then pairs of pairs, so the chain of
/// dependent operations is 3 deep instead of Horner's 7 (sampling inverts
/// the CDF by iteration, and is bound by that latency).
fn value(p: &Poly, t: f64) -> f64 {
    let t2 = t * t;
    let t4 = t2 * t2;
    let (a, b, c) = (p[0] + p[1] * t, p[2] + p[3] * t, p[4] + p[5] * t);
    a + b * t2 + (c + p[6] * t2) * t4
}

/// `∫₀ᵗ p`.
fn primitive(p: &Poly, t: f64) -> f64 {
    primitive_of(&integrand(p), t)
}

/// `p`'s coefficients divided by their power plus one: `∫₀ᵗ p = t·q(t)`.
fn integrand(p: &Poly) -> Poly {
    let mut q = *p;
    for (i, c) in q.iter_mut().enumerate() {
        *c /= (i + 1) as f64;
    }
    q
}

/// `t·q(t)`, `∫₀ᵗ p` for `q = integrand(p)`.
fn primitive_of(q: &Poly, t: f64) -> f64 {
    t * value(q, t)
}

/// The `t` in `[0, h]` with `∫₀ᵗ p = rest`, for `p ≥ 0` of integral `mass`
/// over the piece: Halley's method from the trapezoid rule's answer, kept
/// inside a shrinking bracket (bisection when a step would leave it).
fn invert(p: &Poly, rest: f64, h: f64, mass: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, h);
    let (q, dp) = (integrand(p), derivative(p));
    let mut t = trapezoid_guess(p[0], value(p, h), rest, h, mass);
    for _ in 0..100 {
        let g = primitive_of(&q, t) - rest;
        if g.abs() <= 1e-14 * mass.max(f64::MIN_POSITIVE) {
            break;
        }
        if g > 0.0 {
            hi = t
        } else {
            lo = t
        }
        // g' = p(t), g'' = p'(t); Halley's step, or Newton's where its
        // denominator is not positive.
        let (slope, bend) = (value(p, t), value(&dp, t));
        let halley = 2.0 * slope * slope - g * bend;
        let step = if halley > 0.0 { 2.0 * g * slope / halley } else { g / slope };
        let next = t - step;
        t = if slope > 0.0 && next > lo && next < hi { next } else { 0.5 * (lo + hi) };
        if hi - lo <= 1e-15 * h {
            break;
        }
    }
    t
}

/// Where `∫₀ᵗ = rest` if the density were the line from `a = p(0)` to
/// `b = p(h)` (a quadratic CDF, solved in its stable form), clamped into
/// `[0, h]`; the uniform guess where that fails.
fn trapezoid_guess(a: f64, b: f64, rest: f64, h: f64, mass: f64) -> f64 {
    let k = (b - a) / h;
    let root = (a * a + 2.0 * k * rest).max(0.0).sqrt();
    let t = 2.0 * rest / (a + root);
    if t.is_finite() && t >= 0.0 {
        t.min(h)
    } else if mass > 0.0 {
        (h * rest / mass).clamp(0.0, h)
    } else {
        0.0
    }
}

/// `p'`, coefficients in `t` (degree one less, last coefficient 0).
fn derivative(p: &Poly) -> Poly {
    let mut d = [0.0; 7];
    for i in 1..p.len() {
        d[i - 1] = i as f64 * p[i];
    }
    d
}
