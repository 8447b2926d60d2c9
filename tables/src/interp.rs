//! Piecewise polynomials through tabulated samples.
//!
//! Segment `k` spans `[λₖ, λₖ₊₁]` and holds the coefficients `[c0, c1, c2, c3]`
//! of `p(t) = c0 + c1·t + c2·t² + c3·t³` in the local variable `t = λ − λₖ`
//! (nanometres). Linear interpolation uses the two end samples; the cubic uses
//! the four nearest samples, two on each side, with the stencil shifted
//! inwards at the ends of the table.
//!
//! Values are clamped to `bounds` (for example `[0, 1]` for a reflectance).
//! The *breaks* of a table are its wavelengths plus every point where a
//! segment's polynomial crosses a bound, so between two consecutive breaks the
//! clamped function is a single polynomial and can be integrated exactly.
//!
//! speclab's `TabulatedSpectrum` evaluates and integrates with these
//! functions, and [`crate::Codegen`] precomputes their tables for static
//! data. Every function takes any `f64` (NaN and infinities included) and
//! returns a value; none panics on a table of consistent lengths.
//!
//! ```
//! use speclab_tables::interp;
//! let (lambda, values) = ([400.0, 500.0], [1.0, 3.0]);
//! let c = interp::linear_coeffs(&lambda, &values);
//! let free = [f64::NEG_INFINITY, f64::INFINITY];
//! assert_eq!(interp::eval(&lambda, &c, free, 450.0), 2.0);
//! let brk = interp::breaks(&lambda, &c, free);
//! assert_eq!(interp::integral(&lambda, &c, &brk, free, 400.0, 500.0), 200.0);
//! ```

use crate::validate::Interpolation;

/// Coefficients of one segment, in `t = λ − λₖ`.
pub type Coeffs = [f64; 4];

/// The segment coefficients of `interpolation` through `(lambda, values)`.
pub fn coeffs(interpolation: Interpolation, lambda: &[f64], values: &[f64]) -> Vec<Coeffs> {
    match interpolation {
        Interpolation::Linear => linear_coeffs(lambda, values),
        Interpolation::Cubic => cubic_coeffs(lambda, values),
    }
}

/// Coefficients of the linear interpolant; needs at least 2 samples.
pub fn linear_coeffs(lambda: &[f64], values: &[f64]) -> Vec<Coeffs> {
    (0..lambda.len().min(values.len()).saturating_sub(1))
        .map(|k| {
            let slope = (values[k + 1] - values[k]) / (lambda[k + 1] - lambda[k]);
            [values[k], slope, 0.0, 0.0]
        })
        .collect()
}

/// Coefficients of the four-point piecewise cubic; needs at least 4 samples.
pub fn cubic_coeffs(lambda: &[f64], values: &[f64]) -> Vec<Coeffs> {
    let n = lambda.len().min(values.len());
    if n < 4 {
        return Vec::new();
    }
    (0..n - 1).map(|k| cubic_segment(lambda, values, k)).collect()
}

/// The first of the four samples the cubic of segment `k` goes through:
/// two on each side of the segment, shifted inwards at the ends.
#[inline]
pub fn stencil(k: usize, n: usize) -> usize {
    k.saturating_sub(1).min(n.saturating_sub(4))
}

/// The cubic of segment `k` (needs `k + 1 < n` and `n ≥ 4`), in `t = λ − λₖ`.
pub fn cubic_segment(lambda: &[f64], values: &[f64], k: usize) -> Coeffs {
    let s = stencil(k, lambda.len().min(values.len()));
    let u: [f64; 4] = std::array::from_fn(|j| lambda[s + j] - lambda[k]);
    let y: [f64; 4] = std::array::from_fn(|j| values[s + j]);
    newton_to_monomial(u, y)
}

/// The cubic through `(u[j], y[j])`, in monomial form.
fn newton_to_monomial(u: [f64; 4], y: [f64; 4]) -> Coeffs {
    // Divided differences: d[j] = y[u0..uj].
    let mut d = y;
    for level in 1..4 {
        for j in (level..4).rev() {
            d[j] = (d[j] - d[j - 1]) / (u[j] - u[j - level]);
        }
    }
    // Horner on the Newton form: p = d0 + (t−u0)(d1 + (t−u1)(d2 + (t−u2)d3)).
    let mut p = [d[3], 0.0, 0.0, 0.0];
    for j in (0..3).rev() {
        // p ← p·(t − u[j]) + d[j]
        let mut next = [0.0; 4];
        for i in 0..4 {
            if i + 1 < 4 {
                next[i + 1] += p[i];
            }
            next[i] -= u[j] * p[i];
        }
        next[0] += d[j];
        p = next;
    }
    p
}

/// The wavelengths plus every crossing of a finite bound, sorted.
pub fn breaks(lambda: &[f64], coeffs: &[Coeffs], bounds: [f64; 2]) -> Vec<f64> {
    let mut out = Vec::with_capacity(lambda.len());
    for (k, c) in coeffs.iter().enumerate().take(lambda.len().saturating_sub(1)) {
        out.push(lambda[k]);
        let (crossings, count) = crossings(*c, bounds, lambda[k + 1] - lambda[k]);
        out.extend(crossings[..count].iter().map(|t| lambda[k] + t));
    }
    out.extend(lambda.last());
    out.dedup();
    out
}

/// The points in `(0, h)` where segment `c` meets a finite bound, sorted
/// (at most three per bound), without allocating.
pub fn crossings(c: Coeffs, bounds: [f64; 2], h: f64) -> ([f64; 6], usize) {
    let mut out = [0.0; 6];
    let mut count = 0;
    for level in bounds.into_iter().filter(|b| b.is_finite()) {
        let (roots, n) = roots_in(c, level, h);
        out[count..count + n].copy_from_slice(&roots[..n]);
        count += n;
    }
    out[..count].sort_by(f64::total_cmp);
    (out, count)
}

/// Points in `(0, h)` where `p(t) = level`, found by bisection on the
/// monotone pieces between the critical points of `p` (at most three).
pub fn roots_in(c: Coeffs, level: f64, h: f64) -> ([f64; 3], usize) {
    let f = |t: f64| segment_value(c, t) - level;
    // The ends and the critical points (roots of c1 + 2·c2·t + 3·c3·t²).
    let mut knots = [0.0, h, h, h];
    let (a, b, cc) = (3.0 * c[3], 2.0 * c[2], c[1]);
    if a != 0.0 {
        let disc = b * b - 4.0 * a * cc;
        if disc >= 0.0 {
            let r = disc.sqrt();
            knots[1] = (-b - r) / (2.0 * a);
            knots[2] = (-b + r) / (2.0 * a);
        }
    } else if b != 0.0 {
        knots[1] = -cc / b;
    }
    for t in &mut knots {
        if !(0.0..=h).contains(t) {
            *t = h;
        }
    }
    knots.sort_by(f64::total_cmp);
    let (mut roots, mut count) = ([0.0; 3], 0);
    for w in knots.windows(2) {
        let (mut lo, mut hi) = (w[0], w[1]);
        if f(lo) * f(hi) >= 0.0 {
            continue;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if f(lo) * f(mid) <= 0.0 { hi = mid } else { lo = mid }
        }
        let t = 0.5 * (lo + hi);
        // A root at an end is a knot, already a break.
        if t > 1e-9 * h && t < h * (1.0 - 1e-9) && count < 3 {
            roots[count] = t;
            count += 1;
        }
    }
    (roots, count)
}

/// `p(t)` by Horner's rule, unclamped.
#[inline]
pub const fn segment_value(c: Coeffs, t: f64) -> f64 {
    c[0] + t * (c[1] + t * (c[2] + t * c[3]))
}

/// The largest value of the polynomial `c` (in `t`) over `[a, b]`: at an
/// end, or where its derivative `c₁ + 2c₂t + 3c₃t²` vanishes inside.
#[must_use]
pub fn segment_max(c: Coeffs, a: f64, b: f64) -> f64 {
    let mut best = segment_value(c, a).max(segment_value(c, b));
    let [_, c1, c2, c3] = c;
    let (qa, qb, qc) = (3.0 * c3, 2.0 * c2, c1);
    let mut at = |t: f64| {
        if t > a && t < b {
            best = best.max(segment_value(c, t));
        }
    };
    if qa == 0.0 {
        if qb != 0.0 {
            at(-qc / qb);
        }
    } else {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc >= 0.0 {
            let root = disc.sqrt();
            at((-qb - root) / (2.0 * qa));
            at((-qb + root) / (2.0 * qa));
        }
    }
    best
}

/// `x` limited to `[lo, hi]`; NaN stays NaN.
#[inline]
pub const fn clamp(x: f64, bounds: [f64; 2]) -> f64 {
    if x < bounds[0] {
        bounds[0]
    } else if x > bounds[1] {
        bounds[1]
    } else {
        x
    }
}

/// Index `k` of the segment with `λₖ ≤ x`, for `x` inside the table.
#[inline]
pub const fn segment_of(lambda: &[f64], x: f64) -> usize {
    let (mut lo, mut hi) = (0, lambda.len().saturating_sub(1));
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if lambda[mid] <= x { lo = mid } else { hi = mid }
    }
    lo
}

/// The clamped interpolant at `x`; zero outside `[λ₀, λₙ₋₁]` and for NaN.
pub const fn eval(lambda: &[f64], coeffs: &[Coeffs], bounds: [f64; 2], x: f64) -> f64 {
    let n = lambda.len();
    if n < 2 || coeffs.len() + 1 != n || !(x >= lambda[0] && x <= lambda[n - 1]) {
        return 0.0;
    }
    let k = segment_of(lambda, x);
    clamp(segment_value(coeffs[k], x - lambda[k]), bounds)
}

/// `∫ p(t) dt` from `t0` to `t1`.
const fn segment_integral(c: Coeffs, t0: f64, t1: f64) -> f64 {
    primitive(c, t1) - primitive(c, t0)
}

/// `∫₀ᵗ p`, by Horner's rule.
#[inline(always)]
pub const fn primitive(c: Coeffs, t: f64) -> f64 {
    t * (c[0] + t * (c[1] / 2.0 + t * (c[2] / 3.0 + t * c[3] / 4.0)))
}

/// Exact integral of the clamped interpolant over `[a, b]` (zero outside
/// the table). `brk` must be the table's [`breaks`].
pub const fn integral(
    lambda: &[f64],
    coeffs: &[Coeffs],
    brk: &[f64],
    bounds: [f64; 2],
    a: f64,
    b: f64,
) -> f64 {
    if lambda.len() < 2 || coeffs.len() + 1 != lambda.len() || a >= b || a.is_nan() || b.is_nan() {
        return 0.0;
    }
    let mut sum = 0.0;
    let mut i = 0;
    while i + 1 < brk.len() {
        let x0 = if brk[i] > a { brk[i] } else { a };
        let x1 = if brk[i + 1] < b { brk[i + 1] } else { b };
        if x0 < x1 {
            let mid = 0.5 * (x0 + x1);
            let k = segment_of(lambda, mid);
            let c = coeffs[k];
            let raw = segment_value(c, mid - lambda[k]);
            sum += if raw < bounds[0] {
                bounds[0] * (x1 - x0)
            } else if raw > bounds[1] {
                bounds[1] * (x1 - x0)
            } else {
                segment_integral(c, x0 - lambda[k], x1 - lambda[k])
            };
        }
        i += 1;
    }
    sum
}

/// The exact integral from the first knot to every knot (`prefix[0] = 0`),
/// in one pass over the breaks. `brk` must be the table's [`breaks`].
pub fn prefix(lambda: &[f64], coeffs: &[Coeffs], brk: &[f64], bounds: [f64; 2]) -> Vec<f64> {
    let mut out = vec![0.0; lambda.len()];
    let (mut sum, mut k) = (0.0, 0);
    for w in brk.windows(2) {
        let mid = 0.5 * (w[0] + w[1]);
        while k + 2 < lambda.len() && lambda[k + 1] <= mid {
            k += 1;
        }
        let Some(&c) = coeffs.get(k) else { break };
        sum += piece_integral(c, lambda[k], w[0], w[1], bounds);
        if w[1] == lambda[k + 1] {
            out[k + 1] = sum;
        }
    }
    out
}

/// The integral over one piece `[x0, x1]` of segment `c` starting at `knot`,
/// where the clamped polynomial is either the polynomial or a bound.
fn piece_integral(c: Coeffs, knot: f64, x0: f64, x1: f64, bounds: [f64; 2]) -> f64 {
    let raw = segment_value(c, 0.5 * (x0 + x1) - knot);
    if raw < bounds[0] {
        bounds[0] * (x1 - x0)
    } else if raw > bounds[1] {
        bounds[1] * (x1 - x0)
    } else {
        segment_integral(c, x0 - knot, x1 - knot)
    }
}

/// For every segment, whether its clamp never acts: no break inside it and
/// its polynomial within the bounds. On such a segment the clamped function
/// is the polynomial, and its integral is the polynomial's primitive.
pub fn clean(lambda: &[f64], coeffs: &[Coeffs], brk: &[f64], bounds: [f64; 2]) -> Vec<bool> {
    let mut out: Vec<bool> = coeffs
        .iter()
        .zip(lambda.windows(2))
        .map(|(&c, w)| {
            let mid = segment_value(c, 0.5 * (w[1] - w[0]));
            mid >= bounds[0] && mid <= bounds[1]
        })
        .collect();
    let mut k = 0;
    for &b in brk {
        while k + 1 < lambda.len() && lambda[k + 1] <= b {
            k += 1;
        }
        if b > lambda[k] && k < out.len() {
            out[k] = false;
        }
    }
    out
}

/// `1 / step` if the wavelengths are equidistant (to 1e-9 of a step), else 0.
pub const fn uniform_inv_step(lambda: &[f64]) -> f64 {
    let n = lambda.len();
    if n < 2 {
        return 0.0;
    }
    let step = (lambda[n - 1] - lambda[0]) / (n - 1) as f64;
    let mut k = 0;
    while k < n {
        let d = lambda[k] - (lambda[0] + k as f64 * step);
        if d.abs() > 1e-9 * step {
            return 0.0;
        }
        k += 1;
    }
    1.0 / step
}
