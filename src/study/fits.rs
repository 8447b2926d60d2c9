//! Fitted rules for the study, kept per set of lights: the fit's problem is
//! built once per set (tens of milliseconds), and each M's rule once per
//! problem, however many surfaces, trials and counts ask.
//!
//! ```
//! use speclab::{data::lights, study::fits};
//! let f11 = fits::for_lights(&[&lights::F11])?;
//! let ten = f11.rule(10)?;
//! assert_eq!(ten.m(), 10);
//! assert!(std::ptr::eq(ten, f11.rule(10)?)); // fitted once
//! # Ok::<(), speclab::Error>(())
//! ```

use std::sync::{Arc, Mutex, OnceLock};

use crate::error::Error;
use crate::sampling::fitted::FitProblem;
use crate::sampling::rule::{MAX_M, Rule, check_m};
use crate::spectrum::{Spectrum, TabulatedSpectrum};

/// One set of lights' problem and its rules by M.
pub struct Fits {
    problem: FitProblem,
    rules: [OnceLock<Rule>; MAX_M],
}

impl std::fmt::Debug for Fits {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let fitted: Vec<usize> = (1..=MAX_M).filter(|&m| self.rules[m - 1].get().is_some()).collect();
        f.debug_struct("Fits").field("fitted", &fitted).finish_non_exhaustive()
    }
}

impl Fits {
    /// The rule of `m` wavelengths, fitted on first use; an
    /// [`Error::Count`] unless `1 ≤ m ≤` [`MAX_M`].
    pub fn rule(&self, m: usize) -> Result<&Rule, Error> {
        check_m("a fitted wavelength count", m)?;
        Ok(self.rules[m - 1].get_or_init(|| self.problem.rule(m)))
    }
}

/// The lights' identity: every wavelength and value, bit for bit.
fn key(lights: &[&TabulatedSpectrum]) -> Vec<u64> {
    let mut key = Vec::new();
    for l in lights {
        key.push(l.lambda().len() as u64);
        key.extend(l.lambda().iter().chain(l.values()).map(|v| v.to_bits()));
    }
    key
}

/// The fits for `lights` (a scene's set), from the process's cache (the
/// last eight sets asked for); an error as [`Rule::fit`]'s.
pub fn for_lights(lights: &[&TabulatedSpectrum]) -> Result<Arc<Fits>, Error> {
    static CACHE: Mutex<Vec<(Vec<u64>, Arc<Fits>)>> = Mutex::new(Vec::new());
    let key = key(lights);
    let found = CACHE.lock().ok().and_then(|c| c.iter().find(|(k, _)| *k == key).map(|(_, f)| Arc::clone(f)));
    if let Some(fits) = found {
        return Ok(fits);
    }
    let spectra: Vec<&dyn Spectrum> = lights.iter().map(|&l| l as &dyn Spectrum).collect();
    let fits =
        Arc::new(Fits { problem: FitProblem::new(&spectra)?, rules: [const { OnceLock::new() }; MAX_M] });
    if let Ok(mut cache) = CACHE.lock() {
        if cache.len() == 8 {
            cache.remove(0);
        }
        cache.push((key, Arc::clone(&fits)));
    }
    Ok(fits)
}
