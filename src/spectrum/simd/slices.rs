//! The exact reference's sums over a batch of reflectances' samples (a
//! count known at run time): [`Sums::each`], for each reflectance three
//! columns of weights against its samples, and the smallest and largest
//! sample and the largest second difference (what proves that no cubic
//! segment leaves [0, 1]), handed to the caller's closure.
//! [`PreparedLight::batch`](crate::sampling::PreparedLight::batch) runs
//! its checks there.
//!
//! Two forms, chosen once per batch by [`Sums::detect`]: four samples per
//! `wide::f64x4` (two SSE2 registers on a default x86-64 build), and on
//! x86-64 processors with AVX2 and FMA one register and fused
//! multiply-adds ([`super::x86`]). The spread has the same bits in both;
//! the sums differ in the last bits (fused, summed in another order).
//!
//! ```
//! // (crate-private; the public face is PreparedLight::batch)
//! use speclab::{data::{lights, patches}, sampling::{PreparedLight, reference}};
//! let a = PreparedLight::for_grid(&lights::A, patches::G4.lambda(), patches::G4.interpolation())?;
//! let mut out = [speclab::Xyz::ZERO; 1];
//! a.batch(patches::G4.values(), &mut out)?;
//! let exact = reference::xyz(&lights::A, &patches::G4);
//! assert!((out[0].y - exact.y).abs() <= 1e-12 * exact.y);
//! # Ok::<(), speclab::Error>(())
//! ```

use wide::f64x4;

use super::column_sums;
use super::spread::{Spread, each_run, finish_spread, for_each_window, shifted};

/// Which instructions a batch's sums use.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Sums {
    /// `wide`'s four lanes, on any processor.
    Portable,
    /// AVX2 and FMA, where the processor has them.
    #[cfg(target_arch = "x86_64")]
    Avx2(super::x86::Avx2Fma),
}

impl Sums {
    /// The fastest form this processor runs.
    #[inline]
    pub(crate) fn detect() -> Sums {
        #[cfg(target_arch = "x86_64")]
        if let Some(avx2) = super::x86::Avx2Fma::detect() {
            return Sums::Avx2(avx2);
        }
        Sums::Portable
    }

    /// For each run `y` of `n` samples of `r` (the `i`th reflectance),
    /// `Σᵢ wᵢ·yᵢ` per channel and the smallest and largest sample and the
    /// largest |y₀ − 2y₁ + y₂| (see [`dot_spread`]), handed to
    /// `f(i, y, sums, spread)`; stops at `f`'s first error. The weight
    /// columns are `n` long, the grid's. The whole loop runs in the chosen
    /// form, so that the sums are inlined into it and `f` with them.
    #[inline(always)]
    pub(crate) fn each<E>(
        self,
        columns: &[Vec<f64>; 3],
        r: &[f64],
        n: usize,
        f: impl FnMut(usize, &[f64], [f64; 3], Spread) -> Result<(), E>,
    ) -> Result<(), E> {
        debug_assert!(columns.iter().all(|c| c.len() == n), "samples and weights of one grid");
        match self {
            Sums::Portable => each_run(r, n, |y| dot_spread(columns, y), f),
            #[cfg(target_arch = "x86_64")]
            Sums::Avx2(avx2) => avx2.each(columns, r, n, f),
        }
    }
}

/// In passes over the samples, four per vector (`wide`'s `f64x4`):
///
/// - `Σᵢ wᵢ·yᵢ` per channel, from the weights' columns: the one weighted
///   sum, [`column_sums`] (columns shorter than `y` leave its last samples
///   out of the sums and the spread alike, so the caller passes both of
///   the grid's length);
/// - the smallest and largest sample (over whole vectors and the last
///   four samples) and, in a further pass, the
///   largest |y₀ − 2y₁ + y₂| (over windows of six, [`for_each_window`]).
///   With every middle segment's margin C, `lo − C·second ≥ 0` and
///   `hi + C·second ≤ 1` clear them all: a segment's inner Bernstein
///   coefficients lie within C·second of its linear interpolation, itself
///   within [lo, hi]. (NaN slips through here; the caller checks the sum.)
#[inline(always)]
pub(crate) fn dot_spread(columns: &[Vec<f64>; 3], y: &[f64]) -> ([f64; 3], Spread) {
    let n = y.len().min(columns[0].len()).min(columns[1].len()).min(columns[2].len());
    let y = &y[..n];
    let sum = column_sums(columns.each_ref().map(|c| &c[..n]), y);
    let first = f64x4::splat(y.first().copied().unwrap_or(0.0));
    let (mut lo, mut hi, mut second) = (first, first, f64x4::ZERO);
    for yk in y.as_chunks::<4>().0 {
        let a = f64x4::new(*yk);
        (lo, hi) = (lo.fast_min(a), hi.fast_max(a));
    }
    if let Some(last) = y.last_chunk::<4>() {
        let a = f64x4::new(*last);
        (lo, hi) = (lo.fast_min(a), hi.fast_max(a));
    }
    for_each_window(y, |six| {
        let [a, b, c] = shifted(six).map(f64x4::new);
        second = second.fast_max((a - b - b + c).abs());
    });
    (sum, finish_spread(y, [lo, hi, second].map(f64x4::to_array)))
}

#[cfg(test)]
mod tests {
    use super::{Spread, Sums, dot_spread};

    /// Both forms give what a scalar walk gives, for every length from 1
    /// to 40 (whole vectors, tails, every remainder over four) and
    /// samples that put the extremes and the largest second difference
    /// (of either sign) anywhere: the spread to the bit, the sums within
    /// rounding.
    #[test]
    fn four_lanes_agree_with_one_at_a_time() {
        for n in 1..=40 {
            // Five saw-tooth patterns, then one peak at each position (its
            // largest |second difference| is a negative one, below the peak).
            // Sixteenths: exact in binary, so the windows' a − b − b + c and
            // the scalar a − 2b + c agree to the bit.
            for shift in 0..5 + n {
                let y: Vec<f64> = if shift < 5 {
                    (0..n).map(|i| ((i * 7 + shift * 3) % 11) as f64 / 16.0).collect()
                } else {
                    (0..n).map(|i| if i == shift - 5 { 0.875 } else { 0.125 }).collect()
                };
                let lo = y.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = y.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                let second = y.windows(3).map(|w| (w[0] - 2.0 * w[1] + w[2]).abs()).fold(0.0, f64::max);
                let columns: [Vec<f64>; 3] =
                    std::array::from_fn(|c| (0..n).map(|i| 1.0 + (i * (c + 2)) as f64).collect());
                let by_hand: [f64; 3] =
                    std::array::from_fn(|c| columns[c].iter().zip(&y).map(|(w, v)| w * v).sum());
                let mut detected = None;
                let each = Sums::detect().each(&columns, &y, n, |i, run, sums, spread| {
                    detected = Some((i, run.len(), sums, spread));
                    Ok::<(), ()>(())
                });
                assert_eq!(each, Ok(()));
                let Some((0, len, sums, spread)) = detected else { panic!("one run, the 0th") };
                assert_eq!(len, n);
                for (sums, spread) in [dot_spread(&columns, &y), (sums, spread)] {
                    assert_eq!(spread, Spread { lo, hi, second }, "n = {n}, shift {shift}");
                    for c in 0..3 {
                        assert!((sums[c] - by_hand[c]).abs() <= 1e-12 * by_hand[c].abs().max(1.0), "n = {n}");
                    }
                }
            }
        }
    }

    /// Both forms hand every run to the closure in order, with its index
    /// and its own samples, and stop at the closure's first error.
    #[test]
    fn each_walks_every_run_and_stops_at_the_first_error() {
        let n = 7;
        let columns: [Vec<f64>; 3] = std::array::from_fn(|c| (0..n).map(|i| (i + c) as f64).collect());
        let r: Vec<f64> = (0..3 * n).map(|i| (i % 5) as f64 / 8.0).collect();
        for sums in [Sums::Portable, Sums::detect()] {
            let mut seen = Vec::new();
            let all = sums.each(&columns, &r, n, |i, y, got, _| {
                assert_eq!(y, &r[i * n..(i + 1) * n], "run {i}");
                seen.push((i, got));
                Ok::<(), usize>(())
            });
            assert_eq!(all, Ok(()));
            let want: Vec<_> = (0..3).map(|i| (i, dot_spread(&columns, &r[i * n..(i + 1) * n]).0)).collect();
            assert_eq!(seen.iter().map(|s| s.0).collect::<Vec<_>>(), [0, 1, 2]);
            for ((_, got), (_, want)) in seen.iter().zip(&want) {
                for c in 0..3 {
                    assert!((got[c] - want[c]).abs() <= 1e-12 * want[c].abs().max(1.0));
                }
            }
            let mut calls = 0;
            let stopped = sums.each(&columns, &r, n, |i, _, _, _| {
                calls += 1;
                if i == 1 { Err(i) } else { Ok(()) }
            });
            assert_eq!((stopped, calls), (Err(1), 2));
        }
    }
}
