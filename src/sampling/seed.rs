//! Seeds that fix a result: [`SplitMix64`], a tiny generator whose whole
//! sequence follows from one `u64`, and [`mix`], its finaliser, which
//! spreads any `u64` over all 64 bits (Steele, Lea and Flood 2014, "Fast
//! splittable pseudorandom number generators").
//!
//! The crate's one seeding helper: the fitted rules' reflectance prior
//! draws from it, and a program that gives each cell, trial or pixel a seed
//! of its own derives it with [`derive()`] (then seeds its own generator
//! with it), so that results do not depend on the order or the number of
//! threads the work runs on.
//!
//! ```
//! use speclab::sampling::seed::{SplitMix64, derive};
//! let mut a = SplitMix64::new(7);
//! let (x, y) = (a.next_u64(), a.next_f64());
//! let mut b = SplitMix64::new(7);
//! assert_eq!((x, y), (b.next_u64(), b.next_f64())); // the same sequence
//! assert!((0.0..1.0).contains(&y));
//! assert_ne!(derive(1, 0), derive(1, 1)); // streams of one run differ
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

/// SplitMix64: a 64-bit state advanced by [`GOLDEN`] and finalised by
/// [`mix`]. Small and fast, and its sequence is fixed by its seed on every
/// platform and in every version of this crate (not a cryptographic
/// generator).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// The generator seeded with `seed`.
    #[must_use]
    pub const fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    /// The next number, uniform on all of `u64`.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(GOLDEN);
        mix(self.state)
    }

    /// The next number, uniform on `[0, 1)` (53 bits).
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::{SplitMix64, derive, mix};

    /// Steele, Lea and Flood's SplitMix64 as Vigna's reference
    /// `splitmix64.c` outputs it: from state 0, and from 1234567.
    #[test]
    fn the_sequence_is_splitmix64s() {
        let mut zero = SplitMix64::new(0);
        let got = [zero.next_u64(), zero.next_u64(), zero.next_u64()];
        assert_eq!(got, [0xE220_A839_7B1D_CDAF, 0x6E78_9E6A_A1B9_65F4, 0x06C4_5D18_8009_454F]);
        let mut other = SplitMix64::new(1_234_567);
        assert_eq!(
            [other.next_u64(), other.next_u64()],
            [6_457_827_717_110_365_317, 3_203_168_211_198_807_973]
        );
        let mut f = SplitMix64::new(0);
        assert_eq!(f.next_f64(), (0xE220_A839_7B1D_CDAF_u64 >> 11) as f64 / (1u64 << 53) as f64);
    }

    /// A stream's seed is the finaliser of the base and the stream's
    /// golden-ratio multiple.
    #[test]
    fn derived_seeds_mix_base_and_stream() {
        let g = super::GOLDEN;
        assert_eq!(derive(7, 3), mix(7 ^ 3u64.wrapping_mul(g).wrapping_add(g)));
        assert_ne!(derive(7, 3), derive(7, 4));
        assert_ne!(derive(7, 3), derive(8, 3));
        assert_eq!(mix(0), 0);
    }
}
