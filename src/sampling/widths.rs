//! From a rule size chosen at run time to compile-time lanes.
//!
//! Per-sample values have a size known at compile time
//! (`SampledSpectrum<M, T>`), so that they live in registers; a scene's
//! fitted rule has a size M chosen at run time (by a plan, a budget, a
//! command line). [`with_lanes`] bridges the two: it calls back with the
//! smallest compiled width (4, 8, 12, 16, 24, 32 or 64) that holds M, each width
//! monomorphised once. The lanes beyond M weigh nothing
//! ([`Rule::wavelengths`](crate::sampling::rule::Rule::wavelengths) pads
//! them), so they change no colour.
//!
//! ```
//! use speclab::sampling::{AtWidth, with_lanes};
//! use speclab::data::{lights, patches};
//! use speclab::sampling::rule::Rule;
//!
//! /// The colour of G4 under F11 by a rule of `self.0`'s size.
//! struct Colour<'a>(&'a Rule);
//! impl AtWidth for Colour<'_> {
//!     type Output = Result<speclab::Xyz, speclab::Error>;
//!     fn call<const CAP: usize>(self) -> Self::Output {
//!         let at = self.0.wavelengths::<CAP, f32>()?;
//!         Ok(at.to_xyz(at.sample(&lights::F11) * at.sample(&patches::G4)))
//!     }
//! }
//! let m = 10; // chosen at run time
//! let rule = Rule::fit(&[&lights::F11], m)?;
//! let xyz = with_lanes(m, Colour(&rule))??; // runs with CAP = 12
//! assert!((xyz.y - rule.xyz(&lights::F11, &patches::G4).y).abs() < 1e-4 * xyz.y);
//! assert!(with_lanes(65, Colour(&rule)).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::sampling::rule::MAX_M;

/// The compiled widths, smallest first: multiples of four (a 128-bit
/// register of `f32`) up to 16, then 24, 32 and [`MAX_M`].
#[cfg(test)]
const WIDTHS: [usize; 7] = [4, 8, 12, 16, 24, 32, MAX_M];

/// Something done at a compile-time width: a callback for [`with_lanes`].
pub trait AtWidth {
    /// What it returns.
    type Output;

    /// Does it with `CAP` lanes.
    fn call<const CAP: usize>(self) -> Self::Output;
}

/// Calls `f` with the smallest compiled width (4, 8, 12, 16, 24, 32 or
/// 64) that holds `m`
/// wavelengths. An [`Error::Count`] unless `1 ≤ m ≤` [`MAX_M`].
pub fn with_lanes<F: AtWidth>(m: usize, f: F) -> Result<F::Output, Error> {
    macro_rules! widths {
        ($($cap:literal)*) => {
            $(if m <= $cap {
                return Ok(f.call::<$cap>());
            })*
        };
    }
    if m == 0 {
        return Err(Error::Count { what: "a rule size", found: m, min: 1, max: MAX_M });
    }
    widths!(4 8 12 16 24 32 64);
    Err(Error::Count { what: "a rule size", found: m, min: 1, max: MAX_M })
}

#[cfg(test)]
mod tests {
    use super::{AtWidth, WIDTHS, with_lanes};

    /// Reports the width it ran with.
    struct Width;
    impl AtWidth for Width {
        type Output = usize;
        fn call<const CAP: usize>(self) -> usize {
            CAP
        }
    }

    /// Every size gets the smallest width that holds it; 0 and 65 none.
    #[test]
    fn each_size_gets_the_smallest_width_that_holds_it() {
        for m in 1..=64 {
            let expected = WIDTHS.into_iter().find(|&w| w >= m);
            assert_eq!(with_lanes(m, Width).ok(), expected, "m = {m}");
        }
        assert!(with_lanes(0, Width).is_err() && with_lanes(65, Width).is_err());
        assert_eq!(WIDTHS.last(), Some(&64));
    }
}
