//! The ways of computing a colour, behind one call.
//!
//! | method | wavelengths | `samples` means |
//! |---|---|---|
//! | `reference` | exact integration | (ignored; reported as 0) |
//! | `random` | n × 1 wavelength | n |
//! | `hero` | n × K (hero + K − 1 rotations; K = 4 by default) | n |
//! | `regular-center` | M bucket centers | M |
//! | `regular-box` | M bucket means | M |
//! | `fitted` | M wavelengths fitted to the light ([`Rule::fit`]) | M |
//!
//! Random and hero draw their wavelengths as their [`Sampling`] says (a pdf
//! and a strata; uniform and independent by default, as the assignment).
//! They draw from `StdRng::seed_from_u64(seed)`, so a seed fixes the
//! result. Use [`derive_seed`] to give independent runs their own seeds.
//! Buckets take any M from 1 to [`MAX_M`] at run time
//! ([`Rule::buckets`]), with the same numbers as `RegularSpectrum<M>`;
//! fitted rules any M up to [`MAX_M`], fitted to the prepared light once per
//! process ([`crate::study::fits`]).
//!
//! Every method estimates a path of any [`Depth`]: light × surface^depth.
//! Random and hero sample the product at their wavelengths; buckets
//! multiply the surface's bucket values `depth` times, as a renderer that
//! buckets each spectrum once would; a fitted rule weights the product at
//! its wavelengths; the reference integrates the product exactly.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::{data::{lights, patches}, study::method::Method};
//! let n = NonZeroUsize::new(100).unwrap();
//! let a = Method::HERO.xyz(&lights::A, &patches::E2, n, 7)?;
//! assert_eq!(a, Method::HERO.xyz(&lights::A, &patches::E2, n, 7)?);
//! assert_eq!("regular-box".parse::<Method>()?, Method::BOX);
//! assert_eq!(Method::HERO.evaluations(n), 400);
//! # Ok::<(), speclab::study::StudyError>(())
//! ```

use std::fmt;
use std::num::NonZeroUsize;
use std::str::FromStr;

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use crate::color::Xyz;
use crate::error::Error;
use crate::sampling::buckets::BucketRule;
use crate::sampling::hero::{self, USUAL_K};
use crate::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
use crate::sampling::reference;
use crate::sampling::rule::{MAX_M, Rule};
use crate::spectrum::{Spectrum, TabulatedSpectrum};
use crate::study::error::StudyError;
use crate::study::fits::{self, Fits};
use crate::study::sampling::{Pdf, Sampling};
use crate::study::scene::Depth;

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
    /// n hero samples of `k` wavelengths (`HeroSample<k>`, k from 1 to
    /// [`hero::MAX_WIDTH`]).
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
}

impl Method {
    /// Random sampling as the assignment has it: uniform, independent.
    pub const RANDOM: Method = Method::Random { sampling: Sampling::DEFAULT };

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

    /// True for the methods with a fixed set of M wavelengths (buckets and
    /// fitted rules): deterministic and biased.
    #[must_use]
    pub fn is_fixed(self) -> bool {
        matches!(self, Method::Buckets { .. } | Method::Fitted)
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

    /// The counts a sequence studies: powers of two up to `max_n` for
    /// random and hero, every M up to [`MAX_M`] for buckets and fitted
    /// rules, none for the reference.
    #[must_use]
    pub fn counts(self, max_n: usize) -> Vec<usize> {
        match self {
            Method::Random { .. } | Method::Hero { .. } => {
                std::iter::successors(Some(1usize), |&n| n.checked_mul(2))
                    .take_while(|&n| n <= max_n)
                    .collect()
            }
            Method::Buckets { .. } | Method::Fitted => (1..=MAX_M).collect(),
            Method::Reference => Vec::new(),
        }
    }

    /// This method ready for `light` at depth 1: its pdf table built once,
    /// or its fitted rules found (see [`Prepared::xyz`]).
    pub fn prepare(self, light: &TabulatedSpectrum) -> Result<Prepared<'_>, StudyError> {
        let table = match self.sampling() {
            Some(s) => s.pdf.table(light)?,
            None => None,
        };
        let fits = if self == Method::Fitted { Some(fits::for_lights(&[light])?) } else { None };
        Ok(Prepared { method: self, light, table, fits, depth: Depth::ONE })
    }

    /// XYZ of `light × surface` by this method with `samples` samples or
    /// buckets. Errors for a hero width or bucket count that is not compiled
    /// (1 to [`hero::MAX_WIDTH`], 1 to [`MAX_M`]), and for a pdf that cannot
    /// follow the light.
    pub fn xyz(
        self,
        light: &TabulatedSpectrum,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        seed: u64,
    ) -> Result<Xyz, StudyError> {
        self.prepare(light)?.xyz(surface, samples, seed)
    }
}

impl fmt::Display for Method {
    /// The name used in tables and CSV: `reference`, `random`, `hero` (any
    /// K; the sampling has columns of its own), `regular-center`,
    /// `regular-box`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Method::Reference => "reference",
            Method::Random { .. } => "random",
            Method::Hero { .. } => "hero",
            Method::Buckets { rule: BucketRule::Center } => "regular-center",
            Method::Buckets { rule: BucketRule::BoxAverage } => "regular-box",
            Method::Fitted => "fitted",
        })
    }
}

impl FromStr for Method {
    type Err = Error;
    /// The method with this name (any case), sampling uniform and independent.
    fn from_str(name: &str) -> Result<Method, Error> {
        let found = Method::ALL.into_iter().find(|m| m.to_string().eq_ignore_ascii_case(name));
        found.ok_or_else(|| Error::UnknownName {
            what: "a method",
            expected: &["reference", "random", "hero", "regular-center", "regular-box", "fitted"],
            found: name.to_string(),
        })
    }
}

/// A method with its pdf table built, or its rules found, for one light,
/// and the depth of the paths it estimates.
#[derive(Clone, Debug)]
pub struct Prepared<'a> {
    method: Method,
    light: &'a TabulatedSpectrum,
    table: Option<LightPdf>,
    fits: Option<std::sync::Arc<Fits>>,
    depth: Depth,
}

impl Prepared<'_> {
    /// The same, estimating paths of `depth` surfaces.
    #[must_use]
    pub fn at_depth(mut self, depth: Depth) -> Self {
        self.depth = depth;
        self
    }

    /// The fitted rule of `m` wavelengths, for a fitted method.
    pub fn rule(&self, m: usize) -> Result<Option<&Rule>, StudyError> {
        Ok(match &self.fits {
            Some(f) => Some(f.rule(m)?),
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

    /// [`Prepared::xyz`] with the random methods drawing from `rng`.
    pub fn xyz_with_rng<R: Rng + ?Sized>(
        &self,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        rng: &mut R,
    ) -> Result<Xyz, StudyError> {
        let light = self.light;
        // The estimate with the density's own type: no dynamic dispatch per
        // wavelength, so that timings are a renderer's.
        macro_rules! with_pdf {
            ($pdf:expr, |$p:ident| $estimate:expr) => {
                match ($pdf, &self.table) {
                    (Pdf::Uniform, _) => {
                        let $p = &Uniform;
                        $estimate
                    }
                    (Pdf::Visible, _) => {
                        let $p = &Visible;
                        $estimate
                    }
                    (_, Some($p)) => $estimate,
                    (_, None) => Err(Error::DarkLight),
                }
            };
        }
        if self.depth != Depth::ONE {
            return self.at_depth_with_rng(surface, samples, rng);
        }
        Ok(match self.method {
            Method::Reference => reference::xyz(light, surface),
            Method::Random { sampling } => with_pdf!(sampling.pdf, |pdf| hero::estimate_width(
                1,
                light,
                surface,
                samples,
                pdf,
                sampling.strata,
                rng
            ))?,
            Method::Hero { k, sampling } => with_pdf!(sampling.pdf, |pdf| hero::estimate_width(
                k,
                light,
                surface,
                samples,
                pdf,
                sampling.strata,
                rng
            ))?,
            Method::Buckets { rule } => Rule::buckets(samples.get(), rule)?.xyz(light, surface),
            Method::Fitted => self.fitted(samples.get())?.xyz_of_product(&[light, surface]),
        })
    }

    /// [`Prepared::xyz_with_rng`] for a path of [`Prepared::at_depth`]'s
    /// depth, more than one surface.
    fn at_depth_with_rng<R: Rng + ?Sized>(
        &self,
        surface: &TabulatedSpectrum,
        samples: NonZeroUsize,
        rng: &mut R,
    ) -> Result<Xyz, StudyError> {
        let (light, depth) = (self.light, self.depth);
        let path = depth.path(surface);
        let mut factors: Vec<&dyn Spectrum> = vec![light];
        factors.extend_from_slice(path.factors());
        Ok(match self.method {
            Method::Reference => depth.exact(light, surface),
            Method::Random { .. } | Method::Hero { .. } => {
                let (k, sampling) = match self.method {
                    Method::Hero { k, sampling } => (k, sampling),
                    _ => (1, self.method.sampling().unwrap_or_default()),
                };
                let pdf = self.pdf().ok_or(Error::DarkLight)?;
                hero::estimate_width(k, light, &path, samples, pdf, sampling.strata, rng)?
            }
            Method::Buckets { rule } => Rule::buckets(samples.get(), rule)?.xyz_of_product(&factors),
            Method::Fitted => self.fitted(samples.get())?.xyz_of_product(&factors),
        })
    }

    /// The fitted rule of `m` wavelengths (an error for other methods).
    fn fitted(&self, m: usize) -> Result<&Rule, StudyError> {
        let fitted = self.rule(m)?;
        fitted.ok_or(StudyError::Spectra(Error::Count {
            what: "a fitted wavelength count",
            found: m,
            min: 1,
            max: MAX_M,
        }))
    }

    /// The method's density for the light, if it draws wavelengths: for
    /// checking estimates against theory (`study::variance`).
    #[must_use]
    pub fn pdf(&self) -> Option<&dyn WavelengthPdf> {
        let pdf = self.method.sampling()?.pdf;
        match (pdf, &self.table) {
            (Pdf::Uniform, _) => Some(&Uniform),
            (Pdf::Visible, _) => Some(&Visible),
            (_, table) => table.as_ref().map(|t| t as &dyn WavelengthPdf),
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
