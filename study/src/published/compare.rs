//! Each candidate rule against the exact colour over lights × surfaces:
//! the worst and mean ΔE00 (relative to each light's white), how many
//! pairs exceed 1, and each light's worst, at one path depth.
//!
//! A path of depth d is light × surface^d. A fitted rule weights the
//! whole product at its wavelengths; a published rule's weights include
//! its light, so it weights the surfaces' product alone; prefiltering
//! multiplies the surfaces' three numbers.
//!
//! ```
//! use speclab_study::evaluate::scene::{self, Depth};
//! use speclab_study::published::{compare::{self, Candidate}, prefilter::Space};
//! let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let rows = compare::table(&lights, &surfaces, &[Candidate::Prefiltered(Space::Sharp)], Depth::ONE)?;
//! assert!(rows[0].worst < 1e-6 && rows[0].pairs == 18); // exact at one bounce
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::fmt;

use rayon::prelude::*;

use speclab::color::Xyz;
use speclab::sampling::fitted::FittedRules;
use speclab::sampling::reference;
use speclab::sampling::rule::Rule;
use speclab::spectrum::{Spectrum, TabulatedSpectrum};

use crate::StudyError;
use crate::evaluate::perceptual;
use crate::evaluate::scene::{Depth, MAX_DEPTH, Named};
use crate::published::measured;
use crate::published::minimax::minimax;
use crate::published::prefilter::{Prefiltered, Space};
use crate::published::rules::{Family, astm_interval};

/// Lawson steps of `oracle-minimax`.
const MINIMAX_STEPS: usize = 100;

/// A way of computing a colour with few numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Candidate {
    /// speclab's rule of M wavelengths fitted to the light.
    Fitted(usize),
    /// The same fit over measured surfaces instead of the generated prior:
    /// the Munsell chips of [`measured::prior`], none of them near a
    /// held-apart surface.
    FittedMunsell(usize),
    /// The rule of M wavelengths fitted to the light over the very
    /// surfaces it is judged on (`FittedRules::with_surfaces`): a reference
    /// point, not a method (it has seen the answers) and not a lower bound
    /// (it minimises squares, not the worst case).
    Oracle(usize),
    /// The oracle's wavelengths with weights that minimise the worst ΔE00
    /// over the same surfaces at depth 1 ([`minimax`]): a reference point,
    /// not a method.
    OracleMinimax(usize),
    /// A published rule of M wavelengths.
    Published(Family, usize),
    /// Spectral prefiltering in a space (three numbers).
    Prefiltered(Space),
}

impl Candidate {
    /// Its wavelength count (`None` for prefiltering: three numbers per
    /// surface, no wavelengths).
    pub fn m(self) -> Option<usize> {
        match self {
            Candidate::Fitted(m)
            | Candidate::FittedMunsell(m)
            | Candidate::Oracle(m)
            | Candidate::OracleMinimax(m)
            | Candidate::Published(_, m) => Some(m),
            Candidate::Prefiltered(_) => None,
        }
    }

    /// Its colour of light × `surface`^depth, ready for one light; `fits`
    /// keeps the light's rules fitted over surfaces, once built.
    fn prepare(
        self,
        light: &Named,
        surfaces: &[Named],
        fits: &mut SurfaceFits,
    ) -> Result<Prepared, StudyError> {
        Ok(match self {
            Candidate::Fitted(m) => Prepared::Fitted(light.rules()?.rule(m)?.clone()),
            Candidate::FittedMunsell(m) => {
                let rules = match &fits.measured {
                    Some(rules) => rules.clone(),
                    None => fits.measured.insert(over(light, &as_dyn(measured::prior()?))?).clone(),
                };
                Prepared::Fitted(rules.rule(m)?.clone())
            }
            Candidate::Oracle(m) | Candidate::OracleMinimax(m) => {
                let own = as_dyn(surfaces);
                let rules = match &fits.oracle {
                    Some(rules) => rules.clone(),
                    None => fits.oracle.insert(over(light, &own)?).clone(),
                };
                let rule = rules.rule(m)?.clone();
                match self {
                    Candidate::OracleMinimax(_) => {
                        Prepared::Fitted(minimax(&light.spectrum, &rule, &own, MINIMAX_STEPS)?)
                    }
                    _ => Prepared::Fitted(rule),
                }
            }
            Candidate::Published(family, m) => Prepared::Published(light.published(family, m)?),
            Candidate::Prefiltered(space) => Prepared::Prefiltered(Prefiltered::new(space, light.white())?),
        })
    }
}

/// One light's rules fitted over surfaces: over the judged ones (the
/// oracle's) and over the measured prior.
#[derive(Default)]
struct SurfaceFits {
    oracle: Option<FittedRules>,
    measured: Option<FittedRules>,
}

/// `light`'s rules fitted over `surfaces`.
fn over(light: &Named, surfaces: &[&dyn Spectrum]) -> Result<FittedRules, StudyError> {
    Ok(FittedRules::with_surfaces(&[&light.spectrum], surfaces)?)
}

/// The named spectra as trait objects.
fn as_dyn(named: &[Named]) -> Vec<&dyn Spectrum> {
    named.iter().map(|s| &s.spectrum as &dyn Spectrum).collect()
}

impl fmt::Display for Candidate {
    /// `fitted`, `fitted-munsell`, `oracle`, `oracle-minimax`, `astm` (with its interval: `astm-10nm`), `borges`,
    /// `meyer`, `wallis`, `prefilter-xyz` / `-srgb` / `-sharp`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Candidate::Fitted(_) => f.write_str("fitted"),
            Candidate::FittedMunsell(_) => f.write_str("fitted-munsell"),
            Candidate::Oracle(_) => f.write_str("oracle"),
            Candidate::OracleMinimax(_) => f.write_str("oracle-minimax"),
            Candidate::Published(Family::Astm, m) => write!(f, "astm-{}nm", astm_interval(*m)),
            Candidate::Published(family, _) => family.fmt(f),
            Candidate::Prefiltered(space) => write!(f, "prefilter-{space}"),
        }
    }
}

/// A candidate ready for one light.
enum Prepared {
    Fitted(Rule),
    Published(Rule),
    Prefiltered(Prefiltered),
}

impl Prepared {
    fn xyz(&self, light: &Named, surface: &TabulatedSpectrum, depth: Depth) -> Xyz {
        let s: &dyn Spectrum = surface;
        let mut factors = [s; 1 + MAX_DEPTH];
        factors[0] = &light.spectrum;
        let factors = &factors[..=depth.get()];
        match self {
            Prepared::Fitted(rule) => rule.xyz_of_product(factors),
            Prepared::Published(rule) => rule.xyz_of_product(&factors[1..]),
            Prepared::Prefiltered(p) => p.path_xyz(light.exact(surface), depth.get()),
        }
    }
}

/// One candidate over every pair.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The candidate.
    pub candidate: Candidate,
    /// The path depth.
    pub depth: usize,
    /// The largest ΔE00 over the pairs (NaN for none).
    pub worst: f64,
    /// The mean ΔE00 (NaN for none).
    pub mean: f64,
    /// Pairs with ΔE00 above 1.
    pub above_one: usize,
    /// Pairs evaluated (lights where the candidate exists × surfaces).
    pub pairs: usize,
    /// Each light's worst ΔE00, in the lights' order (NaN where the
    /// candidate does not exist for the light: a Borges rule without real
    /// nodes).
    pub per_light: Vec<f64>,
}

/// Each candidate over `lights` × `surfaces` at `depth` (an error for an
/// empty scene; a light no candidate can see is an error too).
pub fn table(
    lights: &[Named],
    surfaces: &[Named],
    candidates: &[Candidate],
    depth: Depth,
) -> Result<Vec<Row>, StudyError> {
    if lights.is_empty() || surfaces.is_empty() {
        return Err(StudyError::EmptyScene);
    }
    let per_light: Vec<Vec<Option<Vec<f64>>>> = lights
        .par_iter()
        .map(|light| {
            let white = reference::white(&light.spectrum);
            let exact: Vec<Xyz> = surfaces.iter().map(|s| light.exact_at(depth, &s.spectrum)).collect();
            let mut fits = SurfaceFits::default();
            candidates
                .iter()
                .map(|c| match c.prepare(light, surfaces, &mut fits) {
                    Ok(p) => Ok(Some(
                        surfaces
                            .iter()
                            .zip(&exact)
                            .map(|(s, &e)| perceptual::delta_e00(p.xyz(light, &s.spectrum, depth), e, white))
                            .collect(),
                    )),
                    Err(StudyError::NoRule { .. }) => Ok(None),
                    Err(e) => Err(e),
                })
                .collect::<Result<Vec<_>, StudyError>>()
        })
        .collect::<Result<_, _>>()?;
    Ok(candidates
        .iter()
        .enumerate()
        .map(|(i, &candidate)| {
            let all: Vec<f64> = per_light.iter().filter_map(|l| l[i].as_ref()).flatten().copied().collect();
            let worst_of =
                |l: &Option<Vec<f64>>| l.as_ref().map_or(f64::NAN, |d| d.iter().copied().fold(0.0, f64::max));
            Row {
                candidate,
                depth: depth.get(),
                worst: all.iter().copied().fold(f64::NAN, f64::max),
                mean: all.iter().sum::<f64>() / all.len() as f64,
                above_one: all.iter().filter(|&&d| d > 1.0).count(),
                pairs: all.len(),
                per_light: per_light.iter().map(|l| worst_of(&l[i])).collect(),
            }
        })
        .collect())
}
