//! The hot path of evaluation: from a wavelength to its segment of an
//! equidistant table, and the segment's row, in a handful of instructions.
//!
//! [`UniformLookup`] holds what a lookup needs (first knot, `1/step`, the last
//! segment) and guarantees, by construction, that every index it produces
//! is a valid segment of the table it was made for. That guarantee is what
//! lets [`UniformLookup::segment`] convert and index without checks: the coordinate
//! is clamped into `[0, last segment]` first (NaN and ±∞ included), so the
//! conversion is exact and the index in bounds.

use speclab_tables::interp;

/// An equidistant table's geometry, for O(1) segment lookup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct UniformLookup {
    first: f64,
    inv_step: f64,
    /// The last segment's index, as f64 (the clamp bound).
    top: f64,
    /// Number of segments; `top + 1`.
    segments: usize,
}

impl UniformLookup {
    /// The lookup of `lambda` if it is equidistant (to 1e-9 of a step) with at
    /// least two knots, else `None`.
    pub(crate) const fn of(lambda: &[f64]) -> Option<UniformLookup> {
        let inv_step = interp::uniform_inv_step(lambda);
        if inv_step > 0.0 && lambda.len() >= 2 && lambda.len() <= i32::MAX as usize {
            let segments = lambda.len() - 1;
            Some(UniformLookup { first: lambda[0], inv_step, top: (segments - 1) as f64, segments })
        } else {
            None
        }
    }

    /// Number of segments this lookup indexes.
    #[inline(always)]
    pub(crate) const fn segments(&self) -> usize {
        self.segments
    }

    /// The segment of `lambda`: `⌊(λ − λ₀)/step⌋`, clamped to the table, so
    /// always `< self.segments()`. Wavelengths outside the support map to the
    /// end segments; callers zero them.
    #[inline(always)]
    pub(crate) fn segment(&self, lambda: f64) -> usize {
        let x = (lambda - self.first) * self.inv_step;
        // Clamped into [0, top]: NaN and −∞ become 0, +∞ becomes top.
        let x = if x > 0.0 { x } else { 0.0 };
        let x = if x < self.top { x } else { self.top };
        // SAFETY: x is finite and 0 ≤ x ≤ top < segments ≤ i32::MAX (checked
        // in `of`), so the truncation is representable in i32 (the signed
        // conversion is the one SSE2 has, also packed).
        (unsafe { x.to_int_unchecked::<i32>() }) as usize
    }
}
