//! [`SplitMix64`], a tiny generator whose whole sequence follows from one
//! `u64` (Steele, Lea and Flood 2014, "Fast splittable pseudorandom number
//! generators"): what the fitted rules' reflectance prior is drawn from,
//! so that the prior, and every rule fitted over it, is the same on every
//! platform and in every version. Private: a program seeds its own
//! generator.

/// The golden-ratio increment of SplitMix64, `⌊2⁶⁴/φ⌋`.
const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

/// SplitMix64's finaliser: a bijection of `u64` that spreads every input
/// bit over the output.
const fn mix(z: u64) -> u64 {
    let z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    let z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
/// SplitMix64: a 64-bit state advanced by [`GOLDEN`] and finalised by
/// [`mix`]. Small and fast, and its sequence is fixed by its seed on every
/// platform and in every version of this crate (not a cryptographic
/// generator).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// The generator seeded with `seed`.
    #[must_use]
    pub(crate) const fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    /// The next number, uniform on all of `u64`.
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(GOLDEN);
        mix(self.state)
    }

    /// The next number, uniform on `[0, 1)` (53 bits).
    pub(crate) fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::{SplitMix64, mix};

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

    /// The finaliser fixes 0.
    #[test]
    fn mix_fixes_zero() {
        assert_eq!(mix(0), 0);
    }
}
