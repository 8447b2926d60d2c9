//! What the batch's two forms of the sums share (`slices.rs`, portable;
//! `x86.rs`, AVX2): the loop over a batch's runs of samples, and the spread
//! of a run (its smallest and largest sample and largest second
//! difference), found over windows of six samples so that both forms take
//! the same values in the same order and agree to the bit. Below both
//! forms, so that neither imports the other's file back.
//!
//! ```
//! // (crate-private; the public face is PreparedLight::batch)
//! use speclab::{data::{lights, patches}, sampling::PreparedLight};
//! let a = PreparedLight::for_grid(&lights::A, patches::G4.lambda(), patches::G4.interpolation())?;
//! let mut out = [speclab::Xyz::ZERO; 2];
//! a.batch(&[patches::G4.values(), patches::G4.values()].concat(), &mut out)?;
//! assert_eq!(out[0], out[1]);
//! # Ok::<(), speclab::Error>(())
//! ```

/// `f(i, y, sums, spread)` for each run `y` of `n` samples of `r`, with
/// `walk(y)`'s sums and spread, stopping at `f`'s first error: the loop of
/// both forms (inlined into the AVX2 one, so that its walk and `f` are
/// compiled with it).
#[inline(always)]
pub(crate) fn each_run<E>(
    r: &[f64],
    n: usize,
    walk: impl Fn(&[f64]) -> ([f64; 3], Spread),
    mut f: impl FnMut(usize, &[f64], [f64; 3], Spread) -> Result<(), E>,
) -> Result<(), E> {
    for (i, y) in r.chunks_exact(n.max(1)).enumerate() {
        let (sums, spread) = walk(y);
        f(i, y, sums, spread)?;
    }
    Ok(())
}

/// A reflectance's smallest and largest sample and largest second
/// difference |y₀ − 2y₁ + y₂|.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Spread {
    /// The smallest sample.
    pub(crate) lo: f64,
    /// The largest sample.
    pub(crate) hi: f64,
    /// The largest |y₀ − 2y₁ + y₂|.
    pub(crate) second: f64,
}

/// `f` on windows of six samples whose second differences (from their
/// first, second and third four) are every second difference of `y`:
/// from 0, 4, 8, … as long as the window lies within two vectors of four
/// (no bounds to test per window; they cover the second differences
/// that start at 0 to 4⌊n/4⌋ − 5), then from n − 6 and, where n leaves 3
/// over four, from n − 7, which overlap them (the largest second
/// difference does not mind seeing one twice). Nothing for fewer than six
/// samples.
#[inline(always)]
pub(crate) fn for_each_window(y: &[f64], mut f: impl FnMut(&[f64; 6])) {
    let (y4, _) = y.as_chunks::<4>();
    for two in y4.windows(2) {
        if let Some(six) = two.as_flattened().first_chunk::<6>() {
            f(six);
        }
    }
    let n = y.len();
    let from = |back: usize| n.checked_sub(back).and_then(|i| y[i..].first_chunk::<6>());
    if n % 4 == 3
        && let Some(six) = from(7)
    {
        f(six);
    }
    if let Some(six) = from(6) {
        f(six);
    }
}

/// Six samples as three runs of four, from the first, second and third.
#[inline(always)]
pub(crate) fn shifted(six: &[f64; 6]) -> [[f64; 4]; 3] {
    std::array::from_fn(|o| std::array::from_fn(|l| six[o + l]))
}

/// The spread from the lanes of its vectors (`[lo, hi, second]`, four of
/// each), and where there were no windows (fewer than six samples)
/// from the samples one at a time.
#[inline(always)]
pub(crate) fn finish_spread(y: &[f64], [lo, hi, second]: [[f64; 4]; 3]) -> Spread {
    let n = y.len();
    let fold = |lanes: [f64; 4], keep: fn(f64, f64) -> bool| {
        lanes.into_iter().reduce(|m, v| if keep(v, m) { v } else { m }).unwrap_or(0.0)
    };
    let (mut lo, mut hi, mut second) =
        (fold(lo, |v, m| v < m), fold(hi, |v, m| v > m), fold(second, |v, m| v > m));
    let from = if n >= 6 { n } else { 0 };
    for j in from..n {
        lo = if y[j] < lo { y[j] } else { lo };
        hi = if y[j] > hi { y[j] } else { hi };
        if j + 2 < n {
            let d = (y[j] - 2.0 * y[j + 1] + y[j + 2]).abs();
            second = if d > second { d } else { second };
        }
    }
    Spread { lo, hi, second }
}
