//! The ways of computing a colour, behind one call.
//!
//! | method | wavelengths | `samples` means |
//! |---|---|---|
//! | `reference` | exact integration | (ignored; reported as 0) |
//! | `random` | n × 1 wavelength (hero sampling of width 1) | n |
//! | `hero` | n × K (hero + K − 1 rotations; K = 4 by default) | n |
//! | `regular-center` | M bucket centers | M |
//! | `regular-box` | M bucket means | M |
//! | `fitted` | M wavelengths fitted to the light ([`Rule::fit`]) | M |
//! | `astm`, `borges`, `meyer`, `wallis` | a published rule of M wavelengths for the light ([`Family`]) | M |
//! | `prefilter-xyz`, `-srgb`, `-sharp` | three numbers per surface under the light ([`Space`]) | (ignored; reported as 3) |
//!
//! The published rules and prefiltering ([`crate::published`]) are not in
//! [`Method::ALL`] (the grid's default columns): [`Method::PUBLISHED`]
//! lists them, and names parse from either list.
//! Random and hero are one method, of width 1 or K, and draw their
//! wavelengths as their [`Sampling`] says (a pdf and a strata; uniform and
//! independent by default, as the assignment), through the one dispatch
//! of a chosen pdf ([`ChosenPdf`]).
//! They draw from `StdRng::seed_from_u64(seed)`, so a seed fixes the
//! result. Use [`derive_seed`] to give independent runs their own seeds.
//! Buckets take any M from 1 to [`MAX_M`] at run time
//! ([`Rule::buckets`]), with the same numbers as `RegularSpectrum<M>`;
//! fitted rules any M up to [`MAX_M`], fitted to the light once and kept by
//! it ([`FittedRules`]); the light keeps its pdf tables too.
//!
//! Every method estimates a path of any [`Depth`]: light × surface^depth.
//! Random and hero sample the product at their wavelengths; buckets
//! multiply the surface's bucket values `depth` times, as a renderer that
//! buckets each spectrum once would; a fitted rule weights the product at
//! its wavelengths; the reference integrates the product exactly.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::data::{lights, patches};
//! use speclab_study::evaluate::method::Method;
//! let n = NonZeroUsize::new(100).unwrap();
//! let a = Method::HERO.xyz(&lights::A, &patches::E2, n, 7)?;
//! assert_eq!(a, Method::HERO.xyz(&lights::A, &patches::E2, n, 7)?);
//! assert_eq!("regular-box".parse::<Method>()?, Method::BOX);
//! assert_eq!(Method::HERO.evaluations(n), 400);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::fmt;
use std::num::NonZeroUsize;
use std::str::FromStr;

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use crate::sampling::choice::{ChosenPdf, Sampling};
use crate::sampling::estimate::{self, USUAL_K};
use speclab::color::Xyz;
use speclab::error::Error;
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::fitted::FittedRules;
use speclab::sampling::pdf::WavelengthPdf;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::spectrum::{Spectrum, TabulatedSpectrum};

use crate::StudyError;
use crate::evaluate::scene::{Depth, MAX_DEPTH, Named};
use crate::published::prefilter::{Prefiltered, Space};
use crate::published::rules::Family;

/// How wavelengths are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// Exact integration of the interpolants.
    Reference,
    /// n hero samples of `k` wavelengths each (`HeroSample<k>`, k from 1 to
    /// [`estimate::MAX_WIDTH`]); `k = 1` is the assignment's random sampling.
    Hero {
        /// Wavelengths per sample.
        k: usize,
        /// Their pdf and strata.
        sampling: Sampling,
    },
    /// M buckets (`RegularSpectrum<M, B>`; [`Rule::buckets`] at run time).
    Buckets {
        /// Center samples or box means.
        rule: BucketRule,
    },
    /// M wavelengths and weights fitted to the light ([`Rule::fit`]).
    Fitted,
    /// A published rule of M wavelengths built for the light, its weights
    /// including the light ([`Family::rule`]).
    Published {
        /// ASTM, Borges, Meyer or Wallis.
        family: Family,
    },
    /// Spectral prefiltering: three numbers per surface ([`Prefiltered`]).
    Prefiltered {
        /// The space the numbers are kept in.
        space: Space,
    },
}

impl Method {
    /// Random sampling as the assignment has it: one wavelength per
    /// sample, uniform, independent.
    pub const RANDOM: Method = Method::Hero { k: 1, sampling: Sampling::DEFAULT };

    /// Hero sampling of the usual width, [`USUAL_K`], uniform, independent.
    pub const HERO: Method = Method::Hero { k: USUAL_K, sampling: Sampling::DEFAULT };

    /// Center buckets.
    pub const CENTER: Method = Method::Buckets { rule: BucketRule::Center };

    /// Box buckets.
    pub const BOX: Method = Method::Buckets { rule: BucketRule::BoxAverage };

    /// A fitted rule.
    pub const FITTED: Method = Method::Fitted;

    /// The assignment's five methods, reference first, and the fitted rule.
    pub const ALL: [Method; 6] =
        [Method::Reference, Method::RANDOM, Method::HERO, Method::CENTER, Method::BOX, Method::FITTED];

    /// The names of [`Method::ALL`], in its order.
    pub const NAMES: [&str; 6] = ["reference", "random", "hero", "regular-center", "regular-box", "fitted"];

    /// True for the published rules and spectral prefiltering
    /// ([`Method::PUBLISHED`]).
    #[must_use]
    pub fn is_published(self) -> bool {
        matches!(self, Method::Published { .. } | Method::Prefiltered { .. })
    }

    /// The published rules and spectral prefiltering, in that order.
    pub const PUBLISHED: [Method; 7] = [
        Method::Published { family: Family::Astm },
        Method::Published { family: Family::Borges },
        Method::Published { family: Family::Meyer },
        Method::Published { family: Family::Wallis },
        Method::Prefiltered { space: Space::Xyz },
        Method::Prefiltered { space: Space::Srgb },
        Method::Prefiltered { space: Space::Sharp },
    ];

    /// The names of [`Method::PUBLISHED`], in its order.
    pub const PUBLISHED_NAMES: [&str; 7] =
        ["astm", "borges", "meyer", "wallis", "prefilter-xyz", "prefilter-srgb", "prefilter-sharp"];

    /// Every name a method parses from: [`Method::NAMES`], then
    /// [`Method::PUBLISHED_NAMES`].
    pub const EVERY_NAME: [&str; 13] = [
        "reference",
        "random",
        "hero",
        "regular-center",
        "regular-box",
        "fitted",
        "astm",
        "borges",
        "meyer",
        "wallis",
        "prefilter-xyz",
        "prefilter-srgb",
        "prefilter-sharp",
    ];

    /// True for the deterministic, biased methods: a fixed set of M
    /// wavelengths (buckets, fitted and published rules) or prefiltering.
    #[must_use]
    pub fn is_fixed(self) -> bool {
        matches!(
            self,
            Method::Buckets { .. } | Method::Fitted | Method::Published { .. } | Method::Prefiltered { .. }
        )
    }

    /// The same method drawing wavelengths as `sampling` says (no change
    /// for the deterministic methods).
    #[must_use]
    pub fn with_sampling(self, sampling: Sampling) -> Method {
        match self {
            Method::Hero { k, .. } => Method::Hero { k, sampling },
            other => other,
        }
    }

    /// The sampling of a random method.
    #[must_use]
    pub fn sampling(self) -> Option<Sampling> {
        match self {
            Method::Hero { sampling, .. } => Some(sampling),
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
        match self {
            Method::Reference => 0,
            Method::Prefiltered { .. } => 3,
            _ => samples.get(),
        }
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

    /// The counts a sequence studies: powers of two up to `max_n` for
    /// random and hero, every M up to [`MAX_M`] for buckets and fitted
    /// rules (from the family's smallest for a published rule), one for
    /// prefiltering, none for the reference.
    #[must_use]
    pub fn counts(self, max_n: usize) -> Vec<usize> {
        match self {
            Method::Hero { .. } => std::iter::successors(Some(1usize), |&n| n.checked_mul(2))
                .take_while(|&n| n <= max_n)
                .collect(),
            Method::Buckets { .. } | Method::Fitted => (1..=MAX_M).collect(),
            Method::Published { family } => (family.min_m()..=MAX_M).collect(),
            Method::Prefiltered { .. } => vec![3],
            Method::Reference => Vec::new(),
        }
    }

    /// This method ready for `light` at depth 1: its pdf and its fitted
    /// rules at hand, prepared by the light once (see [`Estimator::xyz`]).
    pub fn prepare(self, light: &Named) -> Result<Estimator<'_>, StudyError> {
        let pdf = self.sampling().map(|s| light.pdf(s.pdf)).transpose()?;
        let rules = if self == Method::Fitted { Some(light.rules()?) } else { None };
        Ok(Estimator { method: self, light, pdf, rules, depth: Depth::ONE })
    }

    /// XYZ of `light × surface` by this method with `samples` samples or
    /// buckets. Errors for a hero width or a count out of range (1 to
    /// [`estimate::MAX_WIDTH`], 1 to [`MAX_M`]), and for a pdf that cannot
    /// follow the light.
    pub fn xyz(
        self,
        light: &TabulatedSpectrum,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        seed: u64,
    ) -> Result<Xyz, StudyError> {
        self.prepare(&Named::new("", light.clone()))?.xyz(surface, samples, seed)
    }
}

impl fmt::Display for Method {
    /// The name used in tables and CSV: `reference`, `random` (hero of
    /// width 1), `hero` (any other width; the sampling has columns of its
    /// own), `regular-center`, `regular-box`, `fitted`, and the
    /// [`Method::PUBLISHED_NAMES`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Method::Reference => Method::NAMES[0],
            Method::Hero { k: 1, .. } => Method::NAMES[1],
            Method::Hero { .. } => Method::NAMES[2],
            Method::Buckets { rule: BucketRule::Center } => Method::NAMES[3],
            Method::Buckets { rule: BucketRule::BoxAverage } => Method::NAMES[4],
            Method::Fitted => Method::NAMES[5],
            Method::Published { family } => return family.fmt(f),
            Method::Prefiltered { space } => return write!(f, "prefilter-{space}"),
        })
    }
}

impl FromStr for Method {
    type Err = Error;
    /// The method with this name (any case), sampling uniform and independent.
    fn from_str(name: &str) -> Result<Method, Error> {
        let every = Method::ALL.iter().chain(&Method::PUBLISHED);
        let found = Method::EVERY_NAME.iter().zip(every).find(|(n, _)| n.eq_ignore_ascii_case(name));
        found.map(|(_, &m)| m).ok_or_else(|| Error::UnknownName {
            what: "a method",
            expected: &Method::EVERY_NAME,
            found: name.to_string(),
        })
    }
}

/// A method ready for one light (its pdf tabulated, its rules found, both
/// shared with the light's [`Named`]), and the depth of the paths it
/// estimates.
#[derive(Clone, Debug)]
pub struct Estimator<'a> {
    method: Method,
    light: &'a Named,
    pdf: Option<ChosenPdf>,
    rules: Option<FittedRules>,
    depth: Depth,
}

impl Estimator<'_> {
    /// The same, estimating paths of `depth` surfaces.
    #[must_use]
    pub fn at_depth(mut self, depth: Depth) -> Self {
        self.depth = depth;
        self
    }

    /// The fitted rule of `m` wavelengths, for a fitted method.
    pub fn rule(&self, m: usize) -> Result<Option<&Rule>, StudyError> {
        Ok(match &self.rules {
            Some(rules) => Some(rules.rule(m)?),
            None => None,
        })
    }

    /// XYZ of the light × `surface` with `samples` samples or buckets, the
    /// random methods seeded with `seed`.
    pub fn xyz(
        &self,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        seed: u64,
    ) -> Result<Xyz, StudyError> {
        self.xyz_with_rng(surface, samples, &mut StdRng::seed_from_u64(seed))
    }

    /// [`Estimator::xyz`] with the random methods drawing from `rng`: the
    /// one dispatch over the methods.
    pub fn xyz_with_rng<R: Rng + ?Sized>(
        &self,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        rng: &mut R,
    ) -> Result<Xyz, StudyError> {
        let (light, depth) = (&self.light.spectrum, self.depth);
        // The light, then the surface `depth` times: on the stack, so that
        // an estimate allocates nothing (what `study::cost` times).
        let s: &dyn Spectrum = surface;
        let mut factors = [s; 1 + MAX_DEPTH];
        factors[0] = light;
        let factors = &factors[..=depth.get()];
        let m = samples.get();
        Ok(match self.method {
            Method::Reference => self.light.exact_at(depth, surface),
            Method::Hero { k, sampling } => {
                let pdf = self.pdf.as_ref().ok_or(Error::NoMass)?;
                // At depth 1 the surface itself: no product in the loop.
                if depth == Depth::ONE {
                    estimate::estimate_width(k, light, surface, samples, pdf, sampling.strata, rng)?
                } else {
                    estimate::estimate_width(
                        k,
                        light,
                        &depth.path(surface),
                        samples,
                        pdf,
                        sampling.strata,
                        rng,
                    )?
                }
            }
            Method::Buckets { rule } => Rule::buckets(m, rule)?.xyz_of_product(factors),
            Method::Fitted => self.rule(m)?.ok_or(Error::NoMass)?.xyz_of_product(factors),
            // The rule's weights include the light: the surfaces alone.
            Method::Published { family } => self.light.published(family, m)?.xyz_of_product(&factors[1..]),
            Method::Prefiltered { space } => {
                Prefiltered::new(space, self.light.white())?.path_xyz(self.light.exact(surface), depth.get())
            }
        })
    }

    /// The method's density for the light, if it draws wavelengths: for
    /// checking estimates against theory (`study::variance`).
    #[must_use]
    pub fn pdf(&self) -> Option<&dyn WavelengthPdf> {
        self.pdf.as_ref().map(|p| p as &dyn WavelengthPdf)
    }
}

/// A seed for stream `stream` of a run seeded with `base`, so that cells
/// and trials draw independent sequences: the core's
/// [`crate::sampling::seed::derive`].
pub use crate::sampling::seed::derive as derive_seed;
