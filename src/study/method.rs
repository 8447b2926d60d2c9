//! The five ways of computing a colour, behind one call.
//!
//! | method | wavelengths | `samples` means |
//! |---|---|---|
//! | `reference` | exact integration | (ignored; reported as 0) |
//! | `random` | n × 1 wavelength | n |
//! | `hero` | n × K (hero + K − 1 rotations; K = 4 by default) | n |
//! | `regular-centre` | M bucket centres | M |
//! | `regular-box` | M bucket means | M |
//!
//! Random and hero draw their wavelengths as their [`Sampling`] says (a pdf
//! and a strata; uniform and independent by default, as the assignment).
//! They draw from `StdRng::seed_from_u64(seed)`, so a seed fixes the
//! result. Use [`derive_seed`] to give independent runs their own seeds.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::{data, study::method::Method};
//! let n = NonZeroUsize::new(100).unwrap();
//! let a = Method::HERO.xyz(&data::A, &data::E2, n, 7)?;
//! assert_eq!(a, Method::HERO.xyz(&data::A, &data::E2, n, 7)?);
//! assert_eq!(Method::from_name("regular-box"), Some(Method::RegularBox));
//! assert_eq!(Method::HERO.evaluations(n), 400);
//! # Ok::<(), speclab::Error>(())
//! ```

use std::num::NonZeroUsize;

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use crate::sampling::regular::{self, Rule};
use crate::sampling::{hero, reference};
use crate::study::sampling::{AnyPdf, Sampling};
use crate::{Error, TabulatedSpectrum, Xyz};

/// The usual hero width: four wavelengths per sample.
pub const HERO_K: usize = 4;

/// How wavelengths are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// Exact integration of the interpolants.
    Reference,
    /// n single wavelengths (`HeroSample<1>`).
    Random {
        /// Their pdf and strata.
        sampling: Sampling,
    },
    /// n hero samples of `k` wavelengths (`HeroSample<k>`, k in
    /// [`hero::WIDTHS`]).
    Hero {
        /// Wavelengths per sample.
        k: usize,
        /// Their pdf and strata.
        sampling: Sampling,
    },
    /// `RegularSpectrum<M, Centre>`.
    RegularCentre,
    /// `RegularSpectrum<M, BoxAverage>`.
    RegularBox,
}

impl Method {
    /// Random sampling as the assignment has it: uniform, independent.
    pub const RANDOM: Method = Method::Random { sampling: Sampling::DEFAULT };

    /// Hero sampling of the usual width, [`HERO_K`], uniform, independent.
    pub const HERO: Method = Method::Hero { k: HERO_K, sampling: Sampling::DEFAULT };

    /// The assignment's five methods, reference first.
    pub const ALL: [Method; 5] =
        [Method::Reference, Method::RANDOM, Method::HERO, Method::RegularCentre, Method::RegularBox];

    /// The name used in tables and CSV (`hero` for any K; the sampling has
    /// columns of its own).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Method::Reference => "reference",
            Method::Random { .. } => "random",
            Method::Hero { .. } => "hero",
            Method::RegularCentre => "regular-centre",
            Method::RegularBox => "regular-box",
        }
    }

    /// The method with this name, sampling uniform and independent.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The same method drawing wavelengths as `sampling` says (no change
    /// for the deterministic methods).
    #[must_use]
    pub fn with_sampling(self, sampling: Sampling) -> Method {
        match self {
            Method::Random { .. } => Method::Random { sampling },
            Method::Hero { k, .. } => Method::Hero { k, sampling },
            other => other,
        }
    }

    /// The sampling of a random method.
    #[must_use]
    pub fn sampling(self) -> Option<Sampling> {
        match self {
            Method::Random { sampling } | Method::Hero { sampling, .. } => Some(sampling),
            _ => None,
        }
    }

    /// True for the methods whose result depends on the seed.
    #[must_use]
    pub fn is_random(self) -> bool {
        self.sampling().is_some()
    }

    /// The sample count reported for a run with `samples`: 0 for the reference.
    #[must_use]
    pub fn reported_samples(self, samples: NonZeroUsize) -> usize {
        if self == Method::Reference { 0 } else { samples.get() }
    }

    /// Wavelengths evaluated per estimate with `samples` samples or buckets
    /// (0 for the reference).
    #[must_use]
    pub fn evaluations(self, samples: NonZeroUsize) -> usize {
        match self {
            Method::Hero { k, .. } => k.saturating_mul(samples.get()),
            _ => self.reported_samples(samples),
        }
    }

    /// This method ready for `light`: its pdf built once (see
    /// [`Prepared::xyz`]).
    pub fn prepare(self, light: &TabulatedSpectrum) -> Result<Prepared<'_>, Error> {
        let pdf = match self.sampling() {
            Some(s) => Some(s.pdf.build(light)?),
            None => None,
        };
        Ok(Prepared { method: self, light, pdf })
    }

    /// XYZ of `light × surface` by this method with `samples` samples or
    /// buckets. Errors for a hero width or bucket count that is not compiled
    /// ([`hero::WIDTHS`], 1 to [`regular::MAX_BUCKETS`]), and for a pdf that
    /// cannot follow the light.
    pub fn xyz(
        self,
        light: &TabulatedSpectrum,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        seed: u64,
    ) -> Result<Xyz, Error> {
        self.prepare(light)?.xyz(surface, samples, seed)
    }
}

/// A method with its pdf built for one light.
#[derive(Clone, Debug)]
pub struct Prepared<'a> {
    method: Method,
    light: &'a TabulatedSpectrum,
    pdf: Option<AnyPdf>,
}

impl Prepared<'_> {
    /// XYZ of the light × `surface` with `samples` samples or buckets, the
    /// random methods seeded with `seed`.
    pub fn xyz(&self, surface: &TabulatedSpectrum, samples: NonZeroUsize, seed: u64) -> Result<Xyz, Error> {
        self.xyz_with_rng(surface, samples, &mut StdRng::seed_from_u64(seed))
    }

    /// [`Prepared::xyz`] with the random methods drawing from `rng`.
    pub fn xyz_with_rng<R: Rng + ?Sized>(
        &self,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        rng: &mut R,
    ) -> Result<Xyz, Error> {
        let light = self.light;
        let pdf = self.pdf.as_ref().unwrap_or(&AnyPdf::Uniform);
        match self.method {
            Method::Reference => Ok(reference::xyz(light, surface)),
            Method::Random { sampling } => {
                Ok(hero::estimate_with::<1, _>(light, surface, samples, pdf, sampling.strata, rng))
            }
            Method::Hero { k, sampling } => {
                hero::estimate_dyn(k, light, surface, samples, pdf, sampling.strata, rng)
            }
            Method::RegularCentre => regular::xyz_dyn(samples.get(), Rule::Centre, light, surface),
            Method::RegularBox => regular::xyz_dyn(samples.get(), Rule::BoxAverage, light, surface),
        }
    }
}

/// A seed for stream `stream` of a run seeded with `base` (SplitMix64 of
/// both), so that cells and trials draw independent sequences.
#[must_use]
pub fn derive_seed(base: u64, stream: u64) -> u64 {
    let mut z = base ^ stream.wrapping_mul(0x9E37_79B9_7F4A_7C15).wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
