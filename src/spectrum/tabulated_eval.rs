//! Evaluating a tabulated spectrum at given wavelengths, the hot path of
//! every sample: one wavelength ([`TabulatedSpectrum::eval`]) or K at once
//! ([`TabulatedSpectrum::sample`]), four lanes to a vector.
//!
//! On an equidistant table (every built-in spectrum) each lane finds its
//! segment by one multiplication and a truncation to an integer
//! (`UniformLookup::row`); the four lanes' coefficients are gathered into
//! four `f64x4` vectors, and Horner's rule, the role's clamp and the
//! support (zero outside it, and for NaN) act on the four lanes at once,
//! without a branch. The operations and their order are those of one
//! lane at a time: the same bits (and the reference interpolant's value,
//! `interp::eval`, to rounding: it finds the segment by a search). The
//! clamp is `p > lo ? p : lo`, what SSE, AVX and NEON's maximum does. One
//! wavelength,
//! and the last few of a count that is not a multiple of four, take the
//! scalar rule (one lane is one chain of dependent steps, shorter in
//! scalar code). Tables that are not equidistant take a binary search per
//! wavelength, out of the way.
//!
//! ```
//! use speclab::data::lights::F11;
//! use speclab::sampling::HeroSample;
//! let h = HeroSample::<4, f64>::exact(0.3);
//! let four = F11.sample(&h);
//! let one_by_one: Vec<f64> = h.lambda().iter().map(|&l| F11.eval(l)).collect();
//! assert_eq!(four.values.to_vec(), one_by_one);
//! ```

use wide::{CmpGe, f64x4};

use super::TabulatedSpectrum;
use crate::spectrum::float::Float;
use crate::spectrum::interp;
use crate::spectrum::lookup::UniformLookup;
use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};
use crate::spectrum::validate::Interpolation;

impl TabulatedSpectrum {
    /// The value at `lambda` nm: the clamped interpolant inside the support,
    /// zero outside it and for NaN.
    ///
    /// On an equidistant table (every built-in spectrum) the segment is one
    /// multiplication away: no search, no call, no branch. Other tables take
    /// a binary search, out of the way of the common case. Either way the
    /// value is the reference interpolant's: the same segment polynomial at
    /// the same `t = λ − λₖ`.
    #[inline(always)]
    #[must_use]
    pub fn eval(&self, lambda: f64) -> f64 {
        self.eval_lanes(&[lambda])[0]
    }

    /// The spectrum's values at K wavelengths (a hero sample's, a fixed
    /// rule's, or a `[T; K]`), evaluated side by side in `f64` (the exact
    /// interpolant at each wavelength) and rounded to `T`.
    #[inline(always)]
    #[must_use]
    pub fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        let at = at.lambda();
        let values: [f64; K] = self.eval_lanes(&std::array::from_fn(|j| at[j].to_f64()));
        SampledSpectrum::new(std::array::from_fn(|j| T::from_f64(values[j])))
    }

    /// [`TabulatedSpectrum::eval`] at K wavelengths at once: four lanes
    /// per vector ([`TabulatedSpectrum::eval4`]), the rest one at a time.
    #[inline(always)]
    pub(crate) fn eval_lanes<const K: usize>(&self, lambda: &[f64; K]) -> [f64; K] {
        let Some(lookup) = self.lookup else {
            return self.eval_by_search(lambda);
        };
        let mut v = [0.0; K];
        let (v4, v_rest) = v.as_chunks_mut::<4>();
        let (l4, l_rest) = lambda.as_chunks::<4>();
        for (v, l) in v4.iter_mut().zip(l4) {
            *v = self.eval4(lookup, l);
        }
        for (v, &l) in v_rest.iter_mut().zip(l_rest) {
            *v = self.eval_at(lookup, l);
        }
        v
    }

    /// Four wavelengths side by side: each lane's segment found by its own
    /// index (an integer position in the table), the four segments'
    /// coefficients gathered into four vectors, and Horner's rule, the
    /// clamp and the support applied to all four lanes at once. The same
    /// operations in the same order as [`TabulatedSpectrum::eval_at`]: the
    /// same bits.
    #[inline(always)]
    pub(super) fn eval4(&self, lookup: UniformLookup, lambda: &[f64; 4]) -> [f64; 4] {
        let ([first, last], [lo, hi]) = (self.ends, self.bounds);
        let row = |j: usize| lookup.row(&self.coeffs, &self.lambda, lambda[j]);
        let (r0, r1, r2, r3) = (row(0), row(1), row(2), row(3));
        let c = |i: usize| f64x4::new([r0.0[i], r1.0[i], r2.0[i], r3.0[i]]);
        let l = f64x4::new(*lambda);
        let t = l - f64x4::new([r0.1, r1.1, r2.1, r3.1]);
        // A linear segment's c2 and c3 are 0: the same value, sooner.
        let p = if self.is_linear() { c(0) + t * c(1) } else { c(0) + t * (c(1) + t * (c(2) + t * c(3))) };
        // `p > lo ? p : lo`, then `p < hi ? p : hi`, as eval_at.
        let p = p.fast_max(f64x4::splat(lo)).fast_min(f64x4::splat(hi));
        let inside = ((l - f64x4::splat(first)) * (f64x4::splat(last) - l)).cmp_ge(f64x4::ZERO);
        (p & inside).to_array()
    }

    /// [`TabulatedSpectrum::eval`] at each of `lambda`, into `values` (as
    /// many as the shorter has).
    #[inline(always)]
    pub(super) fn eval_into(&self, lambda: &[f64], values: &mut [f64]) {
        let n = lambda.len().min(values.len());
        let (l4, l_rest) = lambda[..n].as_chunks::<4>();
        let (v4, v_rest) = values[..n].as_chunks_mut::<4>();
        for (v, l) in v4.iter_mut().zip(l4) {
            *v = self.eval_lanes(l);
        }
        for (v, &l) in v_rest.iter_mut().zip(l_rest) {
            *v = self.eval_lanes(&[l])[0];
        }
    }

    /// The value at `l` on an equidistant table, one lane: the scalar rule
    /// (what one wavelength, or a count's last few, takes).
    #[inline(always)]
    pub(super) fn eval_at(&self, lookup: UniformLookup, l: f64) -> f64 {
        let ([first, last], [lo, hi]) = (self.ends, self.bounds);
        let (c, knot) = lookup.row(&self.coeffs, &self.lambda, l);
        let t = l - knot;
        let p = if self.is_linear() { c[0] + t * c[1] } else { interp::segment_value(c, t) };
        let p = if p > lo { p } else { lo };
        let p = if p < hi { p } else { hi };
        // first ≤ λ ≤ last in one comparison (each difference has an exact
        // sign; NaN compares false).
        if (l - first) * (last - l) >= 0.0 { p } else { 0.0 }
    }

    /// [`TabulatedSpectrum::eval_lanes`] for a table that is not
    /// equidistant: a binary search per wavelength.
    #[cold]
    #[inline(never)]
    fn eval_by_search<const K: usize>(&self, lambda: &[f64; K]) -> [f64; K] {
        lambda.map(|l| interp::eval(&self.lambda, &self.coeffs, self.bounds, l))
    }

    /// Whether the segments are linear (their c2 and c3 zero).
    #[inline(always)]
    fn is_linear(&self) -> bool {
        self.interpolation == Interpolation::Linear
    }
}
