//! The exact reference's sums over a batch of reflectances' samples in
//! AVX2 with fused multiply-adds, chosen at run time on x86-64 processors
//! that have both (most made since 2013, though some low-end ones sold
//! later lack AVX; `wide`, which the portable forms use, picks its
//! instructions at compile time, so a default build gets SSE2 from it).
//!
//! [`Avx2Fma::detect`] asks the processor once and keeps the answer (a
//! build with `-C target-feature=+avx2,+fma`, or `target-cpu=native` on
//! such a processor, skips the question). The token is the proof a kernel
//! needs: only `detect` makes one, so a kernel cannot run where the
//! instructions are missing.
//!
//! [`Avx2Fma::each`] is [`super::slices`]'s loop over a batch, four `f64`
//! per instruction, the caller's closure compiled into it. A batch is
//! worth a call: it reads its samples from memory written long before,
//! and the call is made once. The per-sample sums of a few
//! values (`RegularSpectrum`, fixed wavelengths) stay in `wide`'s portable
//! form: there a call per sum measured slower (17 ns against 6 for
//! `RegularSpectrum<16>`'s multiply and sum, because a 32-byte load of
//! values that SSE2 code has just stored 16 bytes at a time waits for the
//! stores to reach the cache).
//!
//! ```
//! // (crate-private; the public face is PreparedLight::batch)
//! use speclab::{data::{lights, patches}, sampling::PreparedLight};
//! let d65 = PreparedLight::for_grid(&lights::D65, patches::G4.lambda(), patches::G4.interpolation())?;
//! let mut out = [speclab::Xyz::ZERO; 1];
//! d65.batch(patches::G4.values(), &mut out)?;
//! assert!(out[0].y > 0.0);
//! # Ok::<(), speclab::Error>(())
//! ```

// The one place besides `lookup.rs` that needs `unsafe`: loads from
// arrays into registers, and calls into functions compiled for AVX2 and
// FMA, made only with the token that proves the processor has them.
#![allow(unsafe_code)]

use std::arch::x86_64::{
    __m256d, _mm_add_pd, _mm_add_sd, _mm_cvtsd_f64, _mm_unpackhi_pd, _mm256_add_pd, _mm256_andnot_pd,
    _mm256_castpd256_pd128, _mm256_extractf128_pd, _mm256_fmadd_pd, _mm256_loadu_pd, _mm256_max_pd,
    _mm256_min_pd, _mm256_set1_pd, _mm256_setzero_pd, _mm256_storeu_pd, _mm256_sub_pd,
};
use std::sync::atomic::{AtomicU8, Ordering};

use super::spread::{Spread, each_run, finish_spread, for_each_window};

/// Proof that this processor has AVX2 and FMA (see [`Avx2Fma::detect`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2Fma(());

/// What the processor answered: not yet asked, no, yes.
static ANSWER: AtomicU8 = AtomicU8::new(UNASKED);
const UNASKED: u8 = 0;
const NO: u8 = 1;
const YES: u8 = 2;

impl Avx2Fma {
    /// The token, where the processor has AVX2 and FMA: one relaxed load
    /// after the first call.
    #[inline]
    pub(crate) fn detect() -> Option<Avx2Fma> {
        if cfg!(all(target_feature = "avx2", target_feature = "fma")) {
            return Some(Avx2Fma(()));
        }
        let yes = match ANSWER.load(Ordering::Relaxed) {
            YES => true,
            NO => false,
            _ => ask(),
        };
        yes.then_some(Avx2Fma(()))
    }

    /// See [`super::slices::Sums::each`].
    #[inline]
    pub(crate) fn each<E, F>(self, columns: &[Vec<f64>; 3], r: &[f64], n: usize, f: F) -> Result<(), E>
    where
        F: FnMut(usize, &[f64], [f64; 3], Spread) -> Result<(), E>,
    {
        // SAFETY: `self` exists only where the processor has AVX2 and FMA.
        unsafe { each(columns, r, n, f) }
    }
}

/// [`dot_spread`] on each run of `n` samples of `r`, and `f` on what it
/// gives: the loop compiled for AVX2 and FMA too, so that both are
/// inlined into it (one call per reflectance measured 12 % more
/// instructions).
#[target_feature(enable = "avx2,fma")]
fn each<E, F>(columns: &[Vec<f64>; 3], r: &[f64], n: usize, f: F) -> Result<(), E>
where
    F: FnMut(usize, &[f64], [f64; 3], Spread) -> Result<(), E>,
{
    each_run(r, n, |y| dot_spread(columns, y), f)
}

/// Asks the processor, once, and keeps the answer.
#[cold]
#[inline(never)]
fn ask() -> bool {
    let yes = std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma");
    ANSWER.store(if yes { YES } else { NO }, Ordering::Relaxed);
    yes
}

/// The batch's sums and spread in AVX2 registers with fused multiply-adds
/// (the portable form is `slices.rs`'s, over [`column_sums`](super::column_sums)): two accumulators per channel (even and odd
/// vectors), named so that they stay in registers; the same minimum,
/// maximum and absolute value in the same order, so the same bits for the
/// spread.
#[inline]
#[target_feature(enable = "avx2,fma")]
fn dot_spread(columns: &[Vec<f64>; 3], y: &[f64]) -> ([f64; 3], Spread) {
    let n = y.len().min(columns[0].len()).min(columns[1].len()).min(columns[2].len());
    let y = &y[..n];
    let (y4, y_rest) = y.as_chunks::<4>();
    let w = columns.each_ref().map(|c| c[..n].as_chunks::<4>());
    let (mut even, mut odd) = ([_mm256_setzero_pd(); 3], [_mm256_setzero_pd(); 3]);
    let first = _mm256_set1_pd(y.first().copied().unwrap_or(0.0));
    let (mut lo, mut hi, mut second) = (first, first, _mm256_setzero_pd());
    let (pairs, last) = y4.as_chunks::<2>();
    for (p, [a, b]) in pairs.iter().enumerate() {
        let (k, a, b) = (2 * p, load(a), load(b));
        for c in 0..3 {
            even[c] = _mm256_fmadd_pd(load(&w[c].0[k]), a, even[c]);
            odd[c] = _mm256_fmadd_pd(load(&w[c].0[k + 1]), b, odd[c]);
        }
        lo = _mm256_min_pd(_mm256_min_pd(lo, a), b);
        hi = _mm256_max_pd(_mm256_max_pd(hi, a), b);
    }
    if let [a] = last {
        let (k, a) = (y4.len() - 1, load(a));
        for c in 0..3 {
            even[c] = _mm256_fmadd_pd(load(&w[c].0[k]), a, even[c]);
        }
        (lo, hi) = (_mm256_min_pd(lo, a), _mm256_max_pd(hi, a));
    }
    if let Some(a) = y.last_chunk::<4>() {
        let a = load(a);
        (lo, hi) = (_mm256_min_pd(lo, a), _mm256_max_pd(hi, a));
    }
    let sign = _mm256_set1_pd(-0.0);
    for_each_window(y, |six| {
        let [a, b, c] = [0, 1, 2].map(|from| {
            // SAFETY: four readable f64 from `six[from]`, `from + 4 ≤ 6`; an
            // unaligned load.
            unsafe { _mm256_loadu_pd(six[from..].as_ptr()) }
        });
        let d = _mm256_add_pd(_mm256_sub_pd(_mm256_sub_pd(a, b), b), c);
        second = _mm256_max_pd(second, _mm256_andnot_pd(sign, d));
    });
    let mut sum = [0.0; 3];
    for c in 0..3 {
        sum[c] = lane_sum(_mm256_add_pd(even[c], odd[c]));
        for (i, &y) in y_rest.iter().enumerate() {
            sum[c] = w[c].1[i].mul_add(y, sum[c]);
        }
    }
    (sum, finish_spread(y, [to_array(lo), to_array(hi), to_array(second)]))
}

/// Four `f64` in a register.
#[inline]
#[target_feature(enable = "avx2,fma")]
fn load(a: &[f64; 4]) -> __m256d {
    // SAFETY: `a` is four readable f64; an unaligned load.
    unsafe { _mm256_loadu_pd(a.as_ptr()) }
}

/// A register's four `f64`.
#[inline]
#[target_feature(enable = "avx2,fma")]
fn to_array(v: __m256d) -> [f64; 4] {
    let mut out = [0.0; 4];
    // SAFETY: `out` is four writable f64.
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), v) };
    out
}

/// The four lanes' sum, `(v₀ + v₂) + (v₁ + v₃)`.
#[inline]
#[target_feature(enable = "avx2,fma")]
fn lane_sum(v: __m256d) -> f64 {
    let pairs = _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
    _mm_cvtsd_f64(_mm_add_sd(pairs, _mm_unpackhi_pd(pairs, pairs)))
}

#[cfg(test)]
mod tests {
    use super::Avx2Fma;

    /// The token exists exactly where the processor says it has both, on
    /// the first call (which asks) and after (which reads the answer kept).
    #[test]
    fn the_token_follows_the_processor() {
        let has = std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma");
        assert_eq!(Avx2Fma::detect().is_some(), has);
        assert_eq!(Avx2Fma::detect().is_some(), has);
    }
}
