//! Four lanes at a time: the per-sample arithmetic in SIMD registers
//! (`wide`'s `f32x4`, one 128-bit register, and `f64x4`, two SSE2 or one
//! AVX register), written once for both precisions through
//! [`Float`]'s sealed vector type.
//!
//! - [`zip`] and [`map`]: a point-wise operation over `[T; N]`, four
//!   values per instruction; a count that is not a multiple of four pads
//!   its last vector (the padding lanes are computed and dropped), so a
//!   count of 10 costs three vectors, not a scalar tail.
//! - [`weighted_sum`]: `Σⱼ rowⱼ·vⱼ` over rows `[w_X, w_Y, w_Z, w₀]`, one
//!   fused multiply-add per wavelength into a vector whose lanes are the
//!   channels: the XYZ of a sample with no horizontal sums. Four
//!   interleaved accumulators for counts of eight and more, so that the
//!   additions do not wait on each other. Drawn wavelengths sum this way.
//! - [`column_sums`]: the same sums from the weights as three columns
//!   (`w_X`, `w_Y`, `w_Z` of every wavelength), three multiply-adds per
//!   four wavelengths and one horizontal sum per channel (in `f32` the
//!   three at once: a transpose and three vector additions): half the
//!   work of the rows at M = 16. Fixed wavelengths and `RegularSpectrum`
//!   sum this way.
//! - [`slices`]: the exact reference's sums over a run-time count of
//!   samples, in AVX2 where the processor has it (`x86.rs`, chosen at run
//!   time).
//!
//! Where the build enables FMA (`-C target-cpu=native` on a processor
//! that has it) a multiply-add is fused, and otherwise a multiply and an
//! add: the two round differently in the last bit.
//!
//! ```
//! // (crate-private; the public face is SampledSpectrum's arithmetic)
//! use speclab::SampledSpectrum;
//! let a = SampledSpectrum::new([1.0_f32, 2.0, 3.0, 4.0, 5.0]);
//! assert_eq!((a * a).values, [1.0, 4.0, 9.0, 16.0, 25.0]);
//! ```

use crate::spectrum::float::Float;
use crate::spectrum::float::sealed::Vector;

pub(crate) mod slices;
pub(crate) mod spread;
#[cfg(target_arch = "x86_64")]
mod x86;

/// `f(a, b)` lane by lane over `N` values, four per vector.
#[inline(always)]
pub(crate) fn zip<T: Float, const N: usize>(
    a: &[T; N],
    b: &[T; N],
    f: impl Fn(T::V4, T::V4) -> T::V4,
) -> [T; N] {
    let mut out = [T::ZERO; N];
    let (a4, a_rest) = a.as_chunks::<4>();
    let (b4, b_rest) = b.as_chunks::<4>();
    let (out4, out_rest) = out.as_chunks_mut::<4>();
    for ((o, a), b) in out4.iter_mut().zip(a4).zip(b4) {
        *o = T::array(f(T::v4(*a), T::v4(*b)));
    }
    if !out_rest.is_empty() {
        let r = T::array(f(T::v4(padded(a_rest)), T::v4(padded(b_rest))));
        out_rest.copy_from_slice(&r[..out_rest.len()]);
    }
    out
}

/// `f(a)` lane by lane over `N` values, four per vector.
#[inline(always)]
pub(crate) fn map<T: Float, const N: usize>(a: &[T; N], f: impl Fn(T::V4) -> T::V4) -> [T; N] {
    zip(a, a, |a, _| f(a))
}

/// Up to four values in a vector's array, the rest 0.
#[inline(always)]
fn padded<T: Float>(rest: &[T]) -> [T; 4] {
    let mut p = [T::ZERO; 4];
    p[..rest.len()].copy_from_slice(rest);
    p
}

/// `Σⱼ rowsⱼ·vⱼ`: each row scaled by its value and summed, lanes kept
/// apart (for rows `[w_X, w_Y, w_Z, w₀]`, the lanes of the result are X,
/// Y, Z and `Σ w₀·v`). Four accumulators, summed as `(a₀ + a₂) + (a₁ + a₃)`.
#[inline(always)]
pub(crate) fn weighted_sum<T: Float, const K: usize>(rows: &[[T; 4]; K], v: &[T; K]) -> [T; 4] {
    // −0 is the additive identity (x + −0 = x for every x, +0 included),
    // so the unused accumulators of a short sum fold away.
    let mut acc = [T::splat(T::from_f64(-0.0)); 4];
    for (j, (row, &v)) in rows.iter().zip(v).enumerate() {
        let lane = if K >= 8 { j % 4 } else { j % 2 };
        acc[lane] = T::v4(*row).mul_add(T::splat(v), acc[lane]);
    }
    T::array((acc[0] + acc[2]) + (acc[1] + acc[3]))
}

/// `[Σⱼ c₀ⱼ·vⱼ, Σⱼ c₁ⱼ·vⱼ, Σⱼ c₂ⱼ·vⱼ]`: three columns of weights against
/// the values `v` (the fixed kinds' X, Y and Z), four values per vector, a
/// count that is not a multiple of four padded with zeros; per column,
/// four partial sums added as `(a₀ + a₂) + (a₁ + a₃)`. Over the shortest
/// of the four slices (missing values count as 0): compile-time counts
/// (`RegularSpectrum`, `FixedWavelengths`, unrolled when inlined), a
/// rule's run-time count, and the exact reference's batch all sum here.
#[inline(always)]
pub(crate) fn column_sums<T: Float>(columns: [&[T]; 3], v: &[T]) -> [T; 3] {
    let n = columns.iter().fold(v.len(), |n, c| n.min(c.len()));
    let mut acc = [T::splat(T::from_f64(-0.0)); 3];
    let (v4, v_rest) = v[..n].as_chunks::<4>();
    let w = columns.map(|c| c[..n].as_chunks::<4>());
    for (k, vk) in v4.iter().enumerate() {
        let vk = T::v4(*vk);
        for c in 0..3 {
            acc[c] = T::v4(w[c].0[k]).mul_add(vk, acc[c]);
        }
    }
    if !v_rest.is_empty() {
        let vk = T::v4(padded(v_rest));
        for c in 0..3 {
            acc[c] = T::v4(padded(w[c].1)).mul_add(vk, acc[c]);
        }
    }
    T::sums3(acc)
}

/// Weight rows `[w_X, w_Y, w_Z, _]` as three columns (at compile time for
/// the buckets' tables, at run time for a rule's wavelengths).
pub(crate) const fn columns<T: Float, const M: usize>(rows: &[[T; 4]; M]) -> [[T; M]; 3] {
    let mut out = [[T::ZERO; M]; 3];
    let mut j = 0;
    while j < M {
        out[0][j] = rows[j][0];
        out[1][j] = rows[j][1];
        out[2][j] = rows[j][2];
        j += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{column_sums, map, weighted_sum, zip};
    use crate::spectrum::float::sealed::Sealed;

    /// Every count from 1 to 13, 16 and 21 (past four accumulators of
    /// four): whole vectors and padded tails give the scalar results
    /// (exact for +, −, ×, ÷; within rounding for the row and column sums).
    #[test]
    fn lanes_agree_with_scalars() {
        fn check<const N: usize>() {
            let a: [f64; N] = std::array::from_fn(|i| 0.5 + i as f64 * 0.618_034);
            let b: [f64; N] = std::array::from_fn(|i| 1.25 - (i as f64 * 0.3).sin());
            assert_eq!(zip(&a, &b, |x, y| x * y), std::array::from_fn(|i| a[i] * b[i]), "N = {N}");
            assert_eq!(zip(&a, &b, |x, y| x / y), std::array::from_fn(|i| a[i] / b[i]), "N = {N}");
            assert_eq!(map(&a, |x| x - f64::splat(2.0)), a.map(|v| v - 2.0), "N = {N}");
            let a32 = a.map(|v| v as f32);
            assert_eq!(zip(&a32, &a32, |x, y| x + y), a32.map(|v| v + v), "N = {N}");
            let rows: [[f64; 4]; N] = std::array::from_fn(|j| [a[j], b[j], a[j] * b[j], 1.0 / a[j]]);
            let sum = weighted_sum(&rows, &b);
            for c in 0..4 {
                let scalar: f64 = (0..N).map(|j| rows[j][c] * b[j]).sum();
                assert!((sum[c] - scalar).abs() <= 1e-14 * scalar.abs().max(1.0), "N = {N}, lane {c}");
            }
            let columns = super::columns(&rows);
            let (sums, sums32) = (
                column_sums(columns.each_ref().map(|c| &c[..]), &b),
                column_sums(
                    super::columns(&rows.map(|r| r.map(|w| w as f32))).each_ref().map(|c| &c[..]),
                    &b.map(|v| v as f32),
                ),
            );
            for c in 0..3 {
                let scalar: f64 = (0..N).map(|j| rows[j][c] * b[j]).sum();
                assert!((sums[c] - scalar).abs() <= 1e-14 * scalar.abs().max(1.0), "N = {N}, column {c}");
                assert!(
                    (f64::from(sums32[c]) - scalar).abs() <= 1e-5 * scalar.abs().max(1.0),
                    "N = {N}, column {c}"
                );
            }
        }
        check::<1>();
        check::<2>();
        check::<3>();
        check::<4>();
        check::<5>();
        check::<6>();
        check::<7>();
        check::<8>();
        check::<9>();
        check::<10>();
        check::<11>();
        check::<12>();
        check::<13>();
        check::<16>();
        check::<21>();
    }

    /// The `f32` sums taken transposed add the same lanes in the same order
    /// as the scalar form: the same bits, on lanes spanning eight decades,
    /// where another order of the additions rounds differently (the order
    /// `(a₀ + a₁) + (a₂ + a₃)` fails this test).
    #[test]
    fn transposed_sums_are_the_scalar_sums() {
        let scalar = |a: wide::f32x4| {
            let [a0, a1, a2, a3] = a.to_array();
            (a0 + a2) + (a1 + a3)
        };
        for k in 0..200_u16 {
            let lane = |c: u16, i: u16| {
                f32::from(k * 7 + c * 3 + i).sin() * 10_f32.powi(i32::from((k + c + i) % 9) - 4)
            };
            let v = [0, 1, 2].map(|c| wide::f32x4::new([0, 1, 2, 3].map(|i| lane(c, i))));
            let want = v.map(scalar);
            assert_eq!(f32::sums3(v).map(f32::to_bits), want.map(f32::to_bits), "k = {k}");
        }
    }

    /// A run-time count sums in the compile-time order: four partial sums
    /// over chunks of four, `(a₀ + a₂) + (a₁ + a₃)`, for every count from 0
    /// to 13 (whole chunks, remainders), and values shorter than the
    /// weights count as 0 (to the bit where multiply and add are not
    /// fused).
    #[test]
    fn a_run_time_count_keeps_the_order() {
        let w: [Vec<f64>; 3] = [1.7, 2.9, 0.4].map(|s| (0..13).map(|i| 1.0 / (f64::from(i) + s)).collect());
        let v: Vec<f64> = (0..13).map(|i| (f64::from(i) * 0.618_034).fract() - 0.3).collect();
        let tolerance = if cfg!(target_feature = "fma") { 1e-15 } else { 0.0 };
        for n in 0..=13 {
            let expected = w.each_ref().map(|w| {
                let by_hand = (0..n).fold([0.0; 4], |mut acc, i| {
                    acc[i % 4] += w[i] * v[i];
                    acc
                });
                (by_hand[0] + by_hand[2]) + (by_hand[1] + by_hand[3])
            });
            let (short, full) = (w.each_ref().map(|w| &w[..n]), w.each_ref().map(|w| &w[..]));
            for got in [column_sums(short, &v[..n]), column_sums(full, &v[..n])] {
                let close = got.iter().zip(&expected).all(|(g, e)| (g - e).abs() <= tolerance);
                assert!(close, "n = {n}: {got:?} against {expected:?}");
            }
        }
        // Columns of unequal length: the shortest bounds every sum.
        let uneven = [&w[0][..5], &w[1][..], &w[2][..]];
        assert_eq!(column_sums(uneven, &v), column_sums(w.each_ref().map(|w| &w[..5]), &v[..5]));
    }
}
