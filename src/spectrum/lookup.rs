//! The hot path of evaluation: from a wavelength to its place in a table,
//! in a handful of instructions, and one of the crate's two places
//! allowed `unsafe`.
//!
//! - Equidistant tables ([`UniformLookup`]): the segment is one
//!   multiplication away, clamped into the table (NaN and ±∞ included) so
//!   that the conversion to an index is exact and the index in bounds;
//!   [`UniformLookup::row`] returns the segment's row and knot without
//!   bounds checks. **The invariant**, checked when the lookup is made
//!   (`UniformLookup::for_table`) and asserted where it is used: the table
//!   has one row per segment and one knot more. Its one `unsafe` block
//!   relies on it; the crate's other `unsafe` blocks, four, are in
//!   `spectrum/simd/x86.rs` (AVX loads and stores, and calls into AVX2
//!   code after the processor said it has it).
//! - The 1 nm grid of dense tables ([`nearest_nm`]): the nearest whole
//!   nanometre from 360 to 830 nm (the renderers' range, which holds the
//!   assignment's) as an index 0 to 470, or [`OUTSIDE`] (471) outside,
//!   where dense tables hold a zero. Computed
//!   once per wavelength when a sample is drawn; looking it up is then one
//!   load.

use speclab_tables::interp;

use crate::spectrum::{LAMBDA_MIN, WavelengthRange};

/// The dense grid's range: 360–830 nm.
pub(crate) const DENSE_RANGE: WavelengthRange = WavelengthRange::VISIBLE;

/// Whole nanometres of a dense table: 360 to 830.
pub(crate) const DENSE_VALUES: usize = 471;

/// Entries of a dense table: its 471 values, then zeros up to a power of
/// two, so that a lookup masks its index instead of comparing it.
pub(crate) const DENSE_ENTRIES: usize = 512;

/// The index of a wavelength outside 360–830 nm (or NaN) on the dense
/// grid: the zero entry.
pub(crate) const OUTSIDE: u16 = 471;

/// The index of 380 nm, where the assignment's range starts.
pub(crate) const ASSIGNMENT_OFFSET: u16 = (LAMBDA_MIN - DENSE_RANGE.min()) as u16;

/// The nearest whole nanometre to `lambda` as an index from 360 nm (0 to
/// 470), or [`OUTSIDE`] for a wavelength outside 360–830 nm or NaN.
#[inline(always)]
pub(crate) fn nearest_nm(lambda: f64) -> u16 {
    let x = lambda - DENSE_RANGE.min();
    // In range, x + ½ lies in [½, 470½]: its integer part is the nearest
    // whole nanometre (halves round up). NaN fails the test.
    if x >= 0.0 && lambda <= DENSE_RANGE.max() { (x + 0.5) as u16 } else { OUTSIDE }
}

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

    /// The lookup of a table of `rows` (one per segment) on the knots
    /// `lambda`, if the knots are equidistant and the rows one fewer.
    pub(crate) const fn for_table(lambda: &[f64], rows: usize) -> Option<UniformLookup> {
        match UniformLookup::of(lambda) {
            Some(lookup) if lookup.segments == rows => Some(lookup),
            _ => None,
        }
    }

    /// Segment `⌊(λ − λ₀)/step⌋` of `lambda`, clamped to the table: always
    /// below the number of segments. (The checked conversion of the cold
    /// paths; [`UniformLookup::row`] is the hot one.)
    #[inline]
    pub(crate) fn segment(&self, lambda: f64) -> usize {
        let x = (lambda - self.first) * self.inv_step;
        // `as` saturates (NaN becomes 0); the minimum keeps it in the table.
        (x as usize).min(self.segments - 1)
    }

    /// Segment `⌊(λ − λ₀)/step⌋` of `lambda`, clamped to the table, and its
    /// row of `rows` and knot of `knots`. Wavelengths outside the knots map
    /// to the end segments; callers zero them.
    ///
    /// # Panics
    /// If `rows` has fewer than one row per segment or `knots` no knot
    /// beyond the last segment (the lookup was made for another table).
    #[inline(always)]
    #[allow(unsafe_code)]
    pub(crate) fn row<R: Copy>(&self, rows: &[R], knots: &[f64], lambda: f64) -> (R, f64) {
        assert!(rows.len() >= self.segments && knots.len() > self.segments, "a lookup of another table");
        let x = (lambda - self.first) * self.inv_step;
        // Clamped into [0, top]: NaN and −∞ become 0, +∞ becomes top.
        let x = if x > 0.0 { x } else { 0.0 };
        let x = if x < self.top { x } else { self.top };
        // SAFETY (the crate's one invariant): x is finite and
        // 0 ≤ x ≤ top < segments ≤ i32::MAX (`of`), so the truncation is
        // exact in i32 (the signed conversion SSE2 has) and k < segments ≤
        // rows.len() < knots.len() (asserted above).
        unsafe {
            let k = x.to_int_unchecked::<i32>() as usize;
            (*rows.get_unchecked(k), *knots.get_unchecked(k))
        }
    }
}

/// The entry of index `i` (a [`nearest_nm`] index) of a dense table:
/// in bounds for any `i`.
#[inline(always)]
pub(crate) fn entry<R: Copy>(table: &[R; DENSE_ENTRIES], i: u16) -> R {
    const { assert!(DENSE_ENTRIES.is_power_of_two() && OUTSIDE as usize >= DENSE_VALUES) };
    table[usize::from(i) & (DENSE_ENTRIES - 1)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_nm_rounds_and_marks_the_outside() {
        assert_eq!(nearest_nm(360.0), 0);
        assert_eq!(nearest_nm(380.0), ASSIGNMENT_OFFSET);
        assert_eq!(nearest_nm(380.49), 20);
        assert_eq!(nearest_nm(380.5), 21);
        assert_eq!(nearest_nm(729.6), 370);
        assert_eq!(nearest_nm(829.6), 470);
        assert_eq!(nearest_nm(830.0), 470);
        for outside in [359.999, 830.001, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(nearest_nm(outside), OUTSIDE, "{outside}");
        }
    }

    #[test]
    fn rows_are_found_and_clamped() {
        let knots = [0.0, 1.0, 2.0, 3.0];
        let rows = ['a', 'b', 'c'];
        let lookup = UniformLookup::for_table(&knots, rows.len()).expect("equidistant");
        assert_eq!(lookup.row(&rows, &knots, 1.5), ('b', 1.0));
        assert_eq!(lookup.row(&rows, &knots, -5.0), ('a', 0.0));
        assert_eq!(lookup.row(&rows, &knots, 99.0), ('c', 2.0));
        assert_eq!(lookup.row(&rows, &knots, f64::NAN), ('a', 0.0));
        assert!(UniformLookup::for_table(&knots, 2).is_none());
        assert!(UniformLookup::for_table(&[0.0, 1.0, 3.0], 2).is_none());
    }

    #[test]
    #[should_panic(expected = "a lookup of another table")]
    fn a_shorter_table_is_refused() {
        let lookup = UniformLookup::of(&[0.0, 1.0, 2.0, 3.0]).expect("equidistant");
        let _ = lookup.row(&['a'], &[0.0, 1.0], 2.5);
    }
}
