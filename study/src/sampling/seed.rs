//! Seeds that fix a result: a program that gives each cell, trial or
//! pixel a seed of its own derives it with [`derive()`] from the run's
//! seed (then seeds its own generator with it), so that results do not
//! depend on the order or the number of threads the work runs on. [`mix`]
//! is SplitMix64's finaliser (Steele, Lea and Flood 2014), which spreads
//! any `u64` over all 64 bits.
//!
//! ```
//! use speclab_study::sampling::seed::{derive, mix};
//! assert_ne!(derive(1, 0), derive(1, 1)); // streams of one run differ
//! assert_ne!(derive(1, 0), derive(2, 0)); // and runs
//! assert_eq!(mix(0), 0);
//! ```

/// The golden-ratio increment of SplitMix64, `⌊2⁶⁴/φ⌋`.
pub const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

/// SplitMix64's finaliser: a bijection of `u64` that spreads every input
/// bit over the output.
#[must_use]
pub const fn mix(z: u64) -> u64 {
    let z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    let z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A seed for stream `stream` of a run seeded with `base`: distinct
/// streams of one run, and the same stream of distinct runs, get
/// unrelated seeds.
#[must_use]
pub const fn derive(base: u64, stream: u64) -> u64 {
    mix(base ^ stream.wrapping_mul(GOLDEN).wrapping_add(GOLDEN))
}

#[cfg(test)]
mod tests {
    use super::{derive, mix};

    /// A stream's seed is the finaliser of the base and the stream's
    /// golden-ratio multiple.
    #[test]
    fn derived_seeds_mix_base_and_stream() {
        let g = super::GOLDEN;
        assert_eq!(derive(7, 3), mix(7 ^ 3u64.wrapping_mul(g).wrapping_add(g)));
        assert_ne!(derive(7, 3), derive(7, 4));
        assert_ne!(derive(7, 3), derive(8, 3));
        assert_eq!(mix(0), 0);
        assert_eq!(mix(1), 0x5692_161D_100B_05E5);
    }
}
