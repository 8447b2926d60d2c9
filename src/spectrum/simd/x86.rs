//! The exact reference's sums over a reflectance's samples in AVX2 with
//! fused multiply-adds, chosen at run time on x86-64 processors that have
//! both (every x86-64 of the last ten years; `wide`, which the portable
//! forms use, picks its instructions at compile time, so a default build
//! gets SSE2 from it).
//!
//! [`Avx2Fma::detect`] asks the processor once and keeps the answer (a
//! build with `-C target-feature=+avx2,+fma`, or `target-cpu=native` on
//! such a processor, skips the question). The token is the proof a kernel
//! needs: only `detect` makes one, so a kernel cannot run where the
//! instructions are missing.
//!
//! [`Avx2Fma::dot`] and [`Avx2Fma::spread`] are [`super::slices`]'s sums,
//! four `f64` per instruction. They are worth a call: a batch reads its
//! samples from memory written long before. The per-sample sums of a few
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

use super::slices::{finish_spread, next, shifted, window};

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

    /// See [`super::slices::Sums::dot`].
    #[inline]
    pub(crate) fn dot(self, columns: &[Vec<f64>; 3], y: &[f64]) -> [f64; 3] {
        // SAFETY: `self` exists only where the processor has AVX2 and FMA.
        unsafe { dot(columns, y) }
    }

    /// See [`super::slices::Sums::spread`].
    #[inline]
    pub(crate) fn spread(self, y: &[f64]) -> (f64, f64, f64) {
        // SAFETY: as above.
        unsafe { spread(y) }
    }
}

/// Asks the processor, once, and keeps the answer.
#[cold]
#[inline(never)]
fn ask() -> bool {
    let yes = std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma");
    ANSWER.store(if yes { YES } else { NO }, Ordering::Relaxed);
    yes
}

/// `Σᵢ wᵢ·yᵢ` per channel: two accumulators per channel (even and odd
/// vectors of four samples), the rest one at a time.
#[target_feature(enable = "avx2,fma")]
fn dot(columns: &[Vec<f64>; 3], y: &[f64]) -> [f64; 3] {
    let n = y.len().min(columns[0].len()).min(columns[1].len()).min(columns[2].len());
    let (y4, y_rest) = y[..n].as_chunks::<4>();
    let w = columns.each_ref().map(|c| c[..n].as_chunks::<4>());
    // Named accumulators, so that they stay in registers.
    let (mut even, mut odd) = ([_mm256_setzero_pd(); 3], [_mm256_setzero_pd(); 3]);
    let (pairs, last) = y4.as_chunks::<2>();
    for (p, [a, b]) in pairs.iter().enumerate() {
        let (a, b) = (load(a), load(b));
        for c in 0..3 {
            even[c] = _mm256_fmadd_pd(load(&w[c].0[2 * p]), a, even[c]);
            odd[c] = _mm256_fmadd_pd(load(&w[c].0[2 * p + 1]), b, odd[c]);
        }
    }
    if let [a] = last {
        let (a, k) = (load(a), y4.len() - 1);
        for c in 0..3 {
            even[c] = _mm256_fmadd_pd(load(&w[c].0[k]), a, even[c]);
        }
    }
    let mut sum = [0.0; 3];
    for c in 0..3 {
        sum[c] = lane_sum(_mm256_add_pd(even[c], odd[c]));
        for (i, &y) in y_rest.iter().enumerate() {
            sum[c] = w[c].1[i].mul_add(y, sum[c]);
        }
    }
    sum
}

/// The portable `spread`'s vectors in one register each (the same
/// minimum, maximum and absolute value, so the same bits).
#[target_feature(enable = "avx2,fma")]
fn spread(y: &[f64]) -> (f64, f64, f64) {
    let (mut lo, mut hi, mut second) = (_mm256_set1_pd(y[0]), _mm256_set1_pd(y[0]), _mm256_setzero_pd());
    let sign = _mm256_set1_pd(-0.0);
    let mut i = 0;
    while let Some(six) = window(y, i) {
        let [a, b, c] = shifted(six).map(|v| load(&v));
        lo = _mm256_min_pd(_mm256_min_pd(lo, a), c);
        hi = _mm256_max_pd(_mm256_max_pd(hi, a), c);
        let d = _mm256_add_pd(_mm256_sub_pd(_mm256_sub_pd(a, b), b), c);
        second = _mm256_max_pd(second, _mm256_andnot_pd(sign, d));
        i = next(i, y.len());
    }
    finish_spread(y, [to_array(lo), to_array(hi), to_array(second)])
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
