//! A measured prior for fitted rules: 1,269 matte Munsell chips, each
//! measured at 1 nm and averaged to 5 nm (`data/measured/munsell-matt.csv`,
//! source in `data/SOURCES.md`), instead of the library's generated
//! smooth prior.
//!
//! The held-apart sets are partly Munsell chips themselves (CIE TCS01–12
//! and NIST CQS VS1–15 are given by Munsell notation; every CQS sample
//! lies within 0.05 ΔE00 of one of these chips), so the prior drops every
//! chip within [`NEAR`] ΔE00 of a held-apart surface under
//! CIE A or D65 (relative to each light's white): a rule fitted over what
//! is left, `fitted-munsell` in [`compare`](super::compare), has not seen
//! the surfaces it is judged on, nor their neighbours.
//!
//! Units: reflectance 0–1 at 380, 385, …, 780 nm (integrated over
//! 380–730 nm, as everything else).
//!
//! ```
//! use speclab_study::published::measured;
//! assert_eq!(measured::munsell()?.len(), 1269);
//! let prior = measured::prior()?;
//! assert!(prior.len() > 1000 && prior.len() < 1269);
//! assert!(prior[0].name.starts_with("munsell/"));
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::sync::OnceLock;

use speclab::color::Xyz;
use speclab::data::lights;
use speclab::sampling::reference;
use speclab::spectrum::TabulatedSpectrum;

use crate::StudyError;
use crate::evaluate::perceptual;
use crate::evaluate::scene::Named;
use crate::published::held_apart;

/// How close (ΔE00, under A or D65) a chip may come to a held-apart
/// surface: a chip at this distance or closer is dropped from the prior.
pub const NEAR: f64 = 3.0;

/// The file, as read at compile time.
const MUNSELL: (&str, &str) =
    ("data/measured/munsell-matt.csv", include_str!("../../../data/measured/munsell-matt.csv"));

/// Every chip, named `munsell/<notation>` (e.g. `munsell/5R4/14`), in
/// the file's order.
pub fn munsell() -> Result<Vec<Named>, StudyError> {
    held_apart::parse("munsell", MUNSELL.0, MUNSELL.1)
}

/// The chips farther than [`NEAR`] from every held-apart surface under
/// both lights, read and screened once per process.
pub fn prior() -> Result<&'static [Named], StudyError> {
    static PRIOR: OnceLock<Vec<Named>> = OnceLock::new();
    if let Some(p) = PRIOR.get() {
        return Ok(p);
    }
    let (chips, screen) = (munsell()?, Screen::new(&held_apart::all()?));
    Ok(PRIOR.get_or_init(|| chips.into_iter().filter(|c| screen.nearest(c) > NEAR).collect()))
}

/// The smallest ΔE00 from `chip` to any of `others`, under A and under
/// D65 (relative to each light's white).
pub fn nearest(chip: &Named, others: &[Named]) -> f64 {
    Screen::new(others).nearest(chip)
}

/// Surfaces' colours under A and D65, with each light's white.
struct Screen(Vec<(&'static TabulatedSpectrum, Xyz, Vec<Xyz>)>);

impl Screen {
    fn new(others: &[Named]) -> Screen {
        let under = |light: &'static TabulatedSpectrum| {
            (
                light,
                reference::white(light),
                others.iter().map(|o| reference::xyz(light, &o.spectrum)).collect(),
            )
        };
        Screen(vec![under(&lights::A), under(&lights::D65)])
    }

    fn nearest(&self, chip: &Named) -> f64 {
        let distances = self.0.iter().flat_map(|(light, white, others)| {
            let xyz = reference::xyz(*light, &chip.spectrum);
            others.iter().map(move |&o| perceptual::delta_e00(xyz, o, *white))
        });
        distances.fold(f64::INFINITY, f64::min)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_file_holds_every_chip_as_published() {
        let all = munsell().unwrap();
        assert_eq!(all.len(), 1269);
        assert_eq!((all[0].name.as_str(), all[1268].name.as_str()), ("munsell/2.5R9/2", "munsell/10RP4/12"));
        // The first chip's values at 380, 385 and 780 nm, as distributed.
        let v = all[0].spectrum.values();
        assert_eq!((v.len(), v[0], v[1], v[80]), (81, 0.13734, 0.1673, 0.75638));
        assert!(all.iter().all(|c| c.spectrum.values().iter().all(|r| (0.0..=1.0).contains(r))));
    }

    #[test]
    fn the_prior_keeps_exactly_the_chips_far_from_every_held_apart_surface() {
        let (all, prior) = (munsell().unwrap(), prior().unwrap());
        let screen = Screen::new(&held_apart::all().unwrap());
        let kept: Vec<&str> = prior.iter().map(|c| c.name.as_str()).collect();
        let mut dropped = 0;
        for chip in &all {
            let far = screen.nearest(chip) > NEAR;
            assert_eq!(kept.contains(&chip.name.as_str()), far, "{}", chip.name);
            dropped += usize::from(!far);
        }
        // The chip 5R4/14 lies 0.04 ΔE00 from `cqs/vs1`: dropped.
        assert!(!kept.contains(&"munsell/5R4/14"));
        // 54 dropped (regression snapshot; an independent recomputation
        // in Python, cubic interpolation at 1 nm, drops the same 54).
        assert_eq!((dropped, kept.len()), (54, 1215));
    }

    #[test]
    fn a_surface_is_nearest_to_itself() {
        let held = held_apart::all().unwrap();
        assert_eq!(nearest(&held[3], &held), 0.0);
        assert!(nearest(&held[3], &held[4..5]) > 0.0);
    }
}
