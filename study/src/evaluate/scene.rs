//! What is looked at: lights and surfaces with the names they have in
//! tables, chosen by built-in name or loaded from files.
//!
//! ```
//! use speclab_study::evaluate::scene::{Choice, builtin_surfaces};
//! use speclab::Role;
//! let d65 = Choice::Name("d65".into()).resolve(Role::Light)?;
//! assert_eq!(d65.name, "D65");
//! assert_eq!(Choice::Name("led-b3".into()).resolve(Role::Light)?.name, "LED-B3");
//! assert_eq!(Choice::Name("D5000".into()).resolve(Role::Light)?.name, "D5000");
//! assert_eq!(Choice::Name("au".into()).resolve(Role::Reflectance)?.name, "Au");
//! assert_eq!(builtin_surfaces().len(), 6);
//! let err = Choice::Name("F13".into()).resolve(Role::Light).unwrap_err();
//! assert!(err.to_string().starts_with("expected a built-in light or D and a temperature (D5000) (nearest: F11, F1 or F3"));
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::collections::HashMap;
use std::fmt;
use std::path::PathBuf;
use std::str::FromStr;
use std::sync::{Arc, Mutex, OnceLock};

use crate::sampling::choice::{ChosenPdf, PdfKind};
use speclab::color::Xyz;
use speclab::io::Load;
use speclab::sampling::fitted::FittedRules;
use speclab::sampling::{PreparedLight, reference};
use speclab::spectrum::data::{Light, Patch, SURFACE_NAMES, lights, surface_named};
use speclab::spectrum::{Product, Role, Spectrum, TabulatedSpectrum};

use crate::StudyError;
use crate::published::rules::Family;
use speclab::sampling::rule::Rule;

/// A spectrum with the name it has in tables, and, used as a light, what
/// the study prepares for it once: its exact reference weights (for the
/// grid of the first reflectance it meets), its wavelength pdfs, its
/// fitted rules, its white and its published rules, made on first use and
/// shared by its clones.
#[derive(Clone)]
pub struct Named {
    /// Name, e.g. `D65`, or a file's stem.
    pub name: String,
    /// The spectrum.
    pub spectrum: TabulatedSpectrum,
    prepared: Arc<Prepared>,
}

/// What is prepared for a light: its exact weights for one grid, each pdf
/// that follows it (by [`PdfKind`]'s place) and its fitted rules.
#[derive(Default)]
struct Prepared {
    weights: OnceLock<Option<PreparedLight<TabulatedSpectrum>>>,
    pdfs: [OnceLock<ChosenPdf>; PdfKind::ALL.len()],
    rules: OnceLock<FittedRules>,
    white: OnceLock<Xyz>,
    /// Published rules by family and M (`None`: no such rule for the light).
    published: Mutex<HashMap<(Family, usize), Option<Rule>>>,
}

impl Named {
    /// `spectrum`, called `name`.
    #[must_use]
    pub fn new(name: impl Into<String>, spectrum: TabulatedSpectrum) -> Self {
        Named { name: name.into(), spectrum, prepared: Arc::default() }
    }

    /// The exact XYZ of this light × `surface`: a dot product with the
    /// light's weights when `surface` is a reflectance on the grid they
    /// were prepared for (the first reflectance's the light met), else
    /// [`reference::xyz`]. Exact either way.
    #[must_use]
    pub fn exact(&self, surface: &TabulatedSpectrum) -> Xyz {
        let weights = self.prepared.weights.get_or_init(|| {
            let grid = (surface.role() == Role::Reflectance).then(|| surface.lambda());
            grid.and_then(|g| PreparedLight::for_grid(self.spectrum.clone(), g, surface.interpolation()).ok())
        });
        match weights {
            Some(w) if w.fits(surface) => w.xyz(surface),
            _ => reference::xyz(&self.spectrum, surface),
        }
    }

    /// The exact XYZ of this light × `surface`^`depth`: at depth 1
    /// [`Named::exact`], deeper [`Depth::exact`].
    #[must_use]
    pub fn exact_at(&self, depth: Depth, surface: &TabulatedSpectrum) -> Xyz {
        if depth == Depth::ONE { self.exact(surface) } else { depth.exact(&self.spectrum, surface) }
    }

    /// The density `kind` for this light, tabulated on first use; an
    /// error for a light the observer cannot see.
    pub fn pdf(&self, kind: PdfKind) -> Result<ChosenPdf, StudyError> {
        let index = PdfKind::ALL.iter().position(|&k| k == kind).unwrap_or(0);
        kept(&self.prepared.pdfs[index], || kind.for_light(&self.spectrum))
    }

    /// The exact XYZ of the perfect white under this light, computed once.
    #[must_use]
    pub fn white(&self) -> Xyz {
        *self.prepared.white.get_or_init(|| reference::white(&self.spectrum))
    }

    /// The published rule of `family` and `m` wavelengths for this light,
    /// built on first use ([`Family::rule`]).
    pub fn published(&self, family: Family, m: usize) -> Result<Rule, StudyError> {
        let key = (family, m);
        let known = self.prepared.published.lock().map(|c| c.get(&key).cloned()).unwrap_or(None);
        let rule = match known {
            Some(rule) => rule,
            None => {
                let made = match family.rule(&self.spectrum, m) {
                    Ok(rule) => Some(rule),
                    Err(StudyError::NoRule { .. }) => None,
                    Err(e) => return Err(e),
                };
                if let Ok(mut cache) = self.prepared.published.lock() {
                    cache.insert(key, made.clone());
                }
                made
            }
        };
        rule.ok_or_else(|| StudyError::NoRule { family: family.to_string(), m })
    }

    /// The rules fitted to this light alone, each M fitted on first use.
    pub fn rules(&self) -> Result<FittedRules, StudyError> {
        kept(&self.prepared.rules, || FittedRules::of(&self.spectrum))
    }
}

/// The value `cell` keeps, or `make`'s, kept now (an error is returned and
/// nothing kept).
fn kept<T: Clone>(
    cell: &OnceLock<T>,
    make: impl FnOnce() -> Result<T, speclab::Error>,
) -> Result<T, StudyError> {
    if let Some(value) = cell.get() {
        return Ok(value.clone());
    }
    let made = make()?;
    Ok(cell.get_or_init(|| made).clone())
}

impl From<Light> for Named {
    /// A built-in light, by its name.
    fn from(light: Light) -> Self {
        Named::new(light.name(), light.spectrum().clone())
    }
}

impl From<Patch> for Named {
    /// A built-in patch, by its name.
    fn from(patch: Patch) -> Self {
        Named::new(patch.name(), patch.spectrum().clone())
    }
}

impl PartialEq for Named {
    /// The same name and spectrum (what is prepared follows from them).
    fn eq(&self, other: &Self) -> bool {
        (&self.name, &self.spectrum) == (&other.name, &other.spectrum)
    }
}

impl fmt::Debug for Named {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Named")
            .field("name", &self.name)
            .field("spectrum", &self.spectrum)
            .finish_non_exhaustive()
    }
}

/// A spectrum chosen on a command line: a built-in name or a file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Choice {
    /// A built-in spectrum by name, any case: a light of
    /// `data::lights::NAMES` or `D` and a temperature, a surface of
    /// `data::SURFACE_NAMES`.
    Name(String),
    /// A file in any format [`Load`] reads.
    File(PathBuf),
}

impl Choice {
    /// The spectrum, named as tables show it (a file by its stem). Names are
    /// looked up among the built-in lights for [`Role::Light`] and among the
    /// surfaces otherwise.
    pub fn resolve(&self, role: Role) -> Result<Named, StudyError> {
        match self {
            Choice::Name(name) => Ok(match role {
                Role::Light => Named::new(canonical(name, &lights::NAMES), lights::named(name)?.into_owned()),
                _ => Named::new(canonical(name, &SURFACE_NAMES), surface_named(name)?.into_owned()),
            }),
            Choice::File(path) => {
                let spectrum = Load::new(role).file(path)?;
                let name =
                    path.file_stem().map_or_else(|| "file".into(), |s| s.to_string_lossy().into_owned());
                Ok(Named::new(name, spectrum))
            }
        }
    }
}

/// `name` as the list writes it (`led-b3` is `LED-B3`), or as given (a
/// daylight temperature, upper-cased: `D5000`).
fn canonical(name: &str, names: &[&str]) -> String {
    names.iter().find(|n| n.eq_ignore_ascii_case(name)).map_or_else(|| name.to_uppercase(), |n| n.to_string())
}

/// Every built-in light, named (`data::lights::ALL`).
#[must_use]
pub fn every_light() -> Vec<Named> {
    Light::ALL.map(Named::from).to_vec()
}

/// The three appendix lights, named.
#[must_use]
pub fn builtin_lights() -> Vec<Named> {
    Light::APPENDIX.map(Named::from).to_vec()
}

/// The six appendix patches, named.
#[must_use]
pub fn builtin_surfaces() -> Vec<Named> {
    Patch::ALL.map(Named::from).to_vec()
}

/// The deepest path the study follows.
pub const MAX_DEPTH: usize = 4;

/// How many surfaces a path meets before the eye: its value is light ×
/// surface^depth (the same surface at every bounce, the worst case for
/// narrowing). 1 is the assignment's light × surface.
///
/// ```
/// use speclab_study::evaluate::scene::Depth;
/// let two: Depth = "2".parse()?;
/// assert_eq!((two.get(), Depth::ONE.get()), (2, 1));
/// assert!("5".parse::<Depth>().is_err() && Depth::new(0).is_err());
/// # Ok::<(), speclab_study::StudyError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Depth(usize);

impl Depth {
    /// One bounce: light × surface.
    pub const ONE: Depth = Depth(1);

    /// Every depth, 1 to [`MAX_DEPTH`].
    pub const ALL: [Depth; MAX_DEPTH] = [Depth(1), Depth(2), Depth(3), Depth(4)];

    /// `depth` surfaces; a [`StudyError::Depth`] outside 1 ..= [`MAX_DEPTH`].
    pub fn new(depth: usize) -> Result<Depth, StudyError> {
        if (1..=MAX_DEPTH).contains(&depth) {
            Ok(Depth(depth))
        } else {
            Err(StudyError::Depth { found: depth.to_string(), max: MAX_DEPTH })
        }
    }

    /// The number of surfaces.
    #[must_use]
    pub fn get(self) -> usize {
        self.0
    }

    /// The surface `depth` times, as one spectrum.
    #[must_use]
    pub fn path<'a>(self, surface: &'a TabulatedSpectrum) -> Product<'a> {
        Product::new(vec![surface as &dyn Spectrum; self.0])
    }

    /// The exact XYZ of light × surface^depth (at depth 1, exactly
    /// [`reference::xyz`]).
    #[must_use]
    pub fn exact(self, light: &impl Spectrum, surface: &impl Spectrum) -> Xyz {
        if self == Depth::ONE {
            return reference::xyz(light, surface);
        }
        let mut factors: Vec<&dyn Spectrum> = vec![light];
        factors.extend(std::iter::repeat_n(surface as &dyn Spectrum, self.0));
        reference::xyz_of_product(&factors)
    }
}

impl Default for Depth {
    fn default() -> Self {
        Depth::ONE
    }
}

impl fmt::Display for Depth {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl FromStr for Depth {
    type Err = StudyError;
    fn from_str(s: &str) -> Result<Depth, StudyError> {
        let bad = || StudyError::Depth { found: s.to_string(), max: MAX_DEPTH };
        s.trim().parse::<usize>().map_err(|_| bad()).and_then(|d| Depth::new(d).map_err(|_| bad()))
    }
}
