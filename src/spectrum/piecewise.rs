//! A piecewise polynomial's tables, borrowed: what exact integration needs
//! of a spectrum (a light, a reflectance, a matching function).
//!
//! Between two consecutive *breaks* (the samples, plus the points where the
//! interpolant meets a clamp bound) the clamped function is one polynomial,
//! so a product of such functions is a polynomial there too, and Gauss–
//! Legendre quadrature ([`super::quadrature`]) integrates it exactly.
//! Internal: users reach it through [`super::TabulatedSpectrum`].

use crate::spectrum::interp::{self, Coeffs};

/// A piecewise polynomial's tables, borrowed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct View<'a> {
    /// The knots, nm.
    pub(crate) lambda: &'a [f64],
    /// One polynomial per segment, in `t = λ − λₖ`.
    pub(crate) coeffs: &'a [Coeffs],
    /// Knots and clamp crossings, sorted.
    pub(crate) breaks: &'a [f64],
    /// The clamp interval.
    pub(crate) bounds: [f64; 2],
}

impl View<'_> {
    /// The clamped interpolant at `x`; zero outside the knots.
    pub(crate) fn eval(&self, x: f64) -> f64 {
        interp::eval(self.lambda, self.coeffs, self.bounds, x)
    }
}

/// The breaks (sorted) strictly inside `(a, b)`.
fn breaks_in(breaks: &[f64], a: f64, b: f64) -> &[f64] {
    let from = breaks.partition_point(|&x| x <= a);
    let to = breaks.partition_point(|&x| x < b);
    &breaks[from..to.max(from)]
}

/// Fills `out` with the sorted ends of the pieces of `[a, b] ∩ range`
/// (the interval's ends and every one of `breaks` inside; each sorted).
/// False if the overlap is empty.
pub(crate) fn pieces_into(out: &mut Vec<f64>, a: f64, b: f64, range: [f64; 2], breaks: [&[f64]; 4]) -> bool {
    let (a, b) = (a.max(range[0]), b.min(range[1]));
    out.clear();
    if a >= b {
        return false;
    }
    out.extend([a, b]);
    for b_ in breaks {
        out.extend_from_slice(breaks_in(b_, a, b));
    }
    out.sort_by(f64::total_cmp);
    out.dedup();
    true
}
