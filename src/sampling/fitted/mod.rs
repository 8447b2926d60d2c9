//! Wavelength rules fitted to a scene's lights: M wavelengths and a 3 × M
//! weight matrix, `XYZ꜀ ≈ Σᵢ w꜀ᵢ·v(λᵢ)`, where `v` is the path's spectral
//! value (light × reflectances) at `λᵢ`.
//!
//! Equidistant buckets put their M wavelengths everywhere alike, and under
//! F11 they straddle its three narrow lines. A fitted rule puts them where
//! the lights need them: Meyer's 1988 idea of choosing rendering wavelengths
//! by quadrature, fitted per scene. [`Rule::fit`] chooses the
//! wavelengths and weights that reproduce, by weighted least squares, the
//! exact XYZ of each light times each reflectance of a smooth prior
//! (`prior.rs`; `moments.rs` for what the fit needs of the reflectances,
//! `problem.rs` for the weighting and the anchors, `search.rs` for the
//! search); [`FittedRules::with_surfaces`] fits over a scene's own
//! materials instead. The weights apply to the product, so one rule serves every
//! intensity of its lights and every path through the scene.
//!
//! The rule reproduces the perfect white under each of its lights, and the
//! prior's mean reflectance, to [`ANCHOR_TOLERANCE`] (relative). In a
//! release build a fit takes about 85 ms the first time in a process (the
//! prior's moments, computed once) and 10–20 ms after, for M ≤ 16 and one
//! to three lights; it is deterministic.
//!
//! The fit is a [`Rule`] (M chosen at run time); a renderer takes it as a
//! `Copy` value, [`Rule::wavelengths`] (a `FixedWavelengths<M, T>`),
//! evaluates its spectra there as a `SampledSpectrum<M, T>` and converts
//! with the weights: no allocation per sample.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{reference, rule::Rule};
//! let rule = Rule::fit(&[&lights::F11], 10)?;
//! let at = rule.wavelengths::<10, f64>()?;
//! let (le, albedo) = (lights::F11.sample(&at), patches::G4.sample(&at));
//! let fitted = at.to_xyz(le * albedo);
//! let exact = reference::xyz(&lights::F11, &patches::G4);
//! assert!((fitted.y - exact.y).abs() < 0.01 * exact.y);
//! assert!(Rule::fit(&[&lights::F11], 0).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

mod moments;
mod problem;
mod search;

pub use moments::{MAX_REFLECTANCE, MAX_SURFACES};

use std::sync::{Arc, OnceLock};

use crate::error::Error;
use crate::sampling::fitted::moments::{CANDIDATES, Grid};
use crate::sampling::fitted::problem::Problem;
use crate::sampling::rule::{MAX_M, Rule, check_m};
use crate::spectrum::{Spectrum, StandardObserver, WavelengthRange};

/// How closely a rule reproduces the XYZ of the perfect white under each of
/// its lights and of the prior's mean reflectance, relative (tested).
pub const ANCHOR_TOLERANCE: f64 = 1e-3;

/// The lights of a list, as the fit takes them.
fn as_dyn<S: Spectrum>(lights: &[S]) -> Vec<&dyn Spectrum> {
    lights.iter().map(|l| l as &dyn Spectrum).collect()
}

/// The rules of a problem's groups at `m` (clamped into 1 ..= MAX_M): one
/// per group, at the same wavelengths, as many as the reflectances tell
/// apart up to `m` (see [`FittedRules::rule`]).
fn fit(problem: &Problem, m: usize) -> Vec<Rule> {
    let (nodes, weights) = problem.fit(m.clamp(1, MAX_M.min(CANDIDATES)));
    let lambda: Vec<f64> = nodes.iter().map(|&j| problem.grid.lambda(j)).collect();
    weights.into_iter().map(|w| Rule::fitted(lambda.clone(), w)).collect()
}

impl Rule {
    /// The rule of `m` wavelengths fitted to `lights` (one to a few; the
    /// scene's: any slice of spectra, `&[&dyn Spectrum]` for lights of
    /// mixed kinds). An [`Error::Count`] unless `1 ≤ m ≤` [`MAX_M`]; an
    /// [`Error::NoMass`] for no lights or one whose white is not positive
    /// in X, Y and Z. To fit several M to the same lights, build
    /// [`FittedRules`] once.
    pub fn fit<S: Spectrum>(lights: &[S], m: usize) -> Result<Rule, Error> {
        check_m("a fitted wavelength count", m)?;
        Ok(fit(&Problem::new(&as_dyn(lights), Grid::ASSIGNMENT)?, m).swap_remove(0))
    }

    /// [`Rule::fit`] over `range` with `observer`: the rule's wavelengths
    /// anywhere on the range's whole nanometres, its weights reproducing
    /// that observer's XYZ over it (a renderer's 360–830 nm with the CIE
    /// 1931 observer). The prior is the same formulas read over the range.
    /// An [`Error::RangeOutside`] for a range beyond the observer's data, an
    /// [`Error::OffGrid`] for ends off whole nanometres; otherwise
    /// errors as `fit`'s.
    ///
    /// ```
    /// use speclab::data::lights;
    /// use speclab::sampling::{reference, rule::Rule};
    /// use speclab::spectrum::{FnSpectrum, StandardObserver, WavelengthRange};
    /// let (cie, visible) = (StandardObserver::Cie1931, WavelengthRange::VISIBLE);
    /// let red = FnSpectrum(|l: f64| 0.5 + 0.4 * ((l - 600.0) / 40.0).tanh()); // defined over 360–830 nm
    /// let rule = Rule::fit_over(&[&lights::E], 8, cie, visible)?;
    /// let exact = reference::xyz_over(cie, visible, &[&lights::E, &red])?;
    /// let fitted = rule.xyz_of_product(&[&lights::E, &red]);
    /// assert!(rule.lambda().iter().all(|&l| visible.contains(l)));
    /// assert!((fitted.y / exact.y - 1.0).abs() < 0.01);
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn fit_over<S: Spectrum>(
        lights: &[S],
        m: usize,
        observer: StandardObserver,
        range: WavelengthRange,
    ) -> Result<Rule, Error> {
        check_m("a fitted wavelength count", m)?;
        Ok(fit(&Problem::new(&as_dyn(lights), Grid::new(observer, range)?)?, m).swap_remove(0))
    }

    /// One rule per light, all at the same `m` wavelengths, each with
    /// weights of its own for its light: the wavelengths chosen for the
    /// lights together, the weights for each apart. A renderer that knows
    /// which light each contribution came from (next-event estimation
    /// does) carries one set of `m` values per path and converts each
    /// light's contribution with that light's weights
    /// ([`FixedWavelengths::emission`](crate::sampling::FixedWavelengths::emission)):
    /// more accurate than one rule serving every light whenever the lights
    /// differ (F11 and A in one scene: ΔE00 over the six patches at
    /// M = 10 at most 0.34 with each light's weights, 1.6 with one
    /// rule for both; measured by `tests/properties/fitted.rs`). Errors as [`Rule::fit`].
    ///
    /// ```
    /// use speclab::data::{lights, patches};
    /// use speclab::sampling::{reference, rule::Rule};
    /// let rules = Rule::fit_each(&[&lights::F11, &lights::A], 10)?;
    /// assert_eq!(rules[0].lambda(), rules[1].lambda());
    /// let one = Rule::fit(&[&lights::F11, &lights::A], 10)?; // one rule for both
    /// let at = rules[0].wavelengths::<10, f64>()?;
    /// let albedo = patches::G4.sample(&at); // the same values for every light
    /// let own = rules[1].wavelengths::<10, f64>()?.emission(&lights::A).xyz(albedo);
    /// let shared = one.wavelengths::<10, f64>()?.emission(&lights::A).xyz(albedo);
    /// let exact = reference::xyz(&lights::A, &patches::G4);
    /// assert!((own.x - exact.x).abs() < (shared.x - exact.x).abs());
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn fit_each<S: Spectrum>(lights: &[S], m: usize) -> Result<Vec<Rule>, Error> {
        check_m("a fitted wavelength count", m)?;
        Ok(fit(&Problem::each(&as_dyn(lights), Grid::ASSIGNMENT)?, m))
    }
}

/// The rules fitted to a scene's lights, each M fitted on first use and
/// kept: the part of a fit that depends on the lights alone (the normal
/// equations over the prior or the scene's surfaces, tens of
/// milliseconds) is built once, so that
/// asking again (another M, another surface, another trial) costs a
/// lookup. Clones share what is kept.
///
/// ```
/// use speclab::data::lights;
/// use speclab::sampling::{fitted::FittedRules, rule::Rule};
/// let f11 = FittedRules::of(&lights::F11)?;
/// assert_eq!(f11.rule(10)?.m(), 10);
/// assert!(std::ptr::eq(f11.rule(10)?, f11.clone().rule(10)?)); // kept, and shared
/// assert_eq!(f11.rule(6)?, &Rule::fit(&[&lights::F11], 6)?);
/// # Ok::<(), speclab::Error>(())
/// ```
#[derive(Clone)]
pub struct FittedRules(Arc<Fits>);

impl std::fmt::Debug for FittedRules {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let fitted: Vec<usize> = (1..=MAX_M).filter(|&m| self.0.rules[m - 1].get().is_some()).collect();
        f.debug_struct("FittedRules").field("fitted", &fitted).finish_non_exhaustive()
    }
}

/// A fit problem and its rules by M.
struct Fits {
    problem: Problem,
    rules: [OnceLock<Rule>; MAX_M],
}

impl FittedRules {
    /// The rules of `lights` (any slice of spectra); an [`Error::NoMass`]
    /// as in [`Rule::fit`].
    pub fn new<S: Spectrum>(lights: &[S]) -> Result<Self, Error> {
        Ok(Self::of_problem(Problem::new(&as_dyn(lights), Grid::ASSIGNMENT)?))
    }

    /// The rules of `lights` over `range` with `observer`, as
    /// [`Rule::fit_over`] fits them (its errors).
    pub fn new_over<S: Spectrum>(
        lights: &[S],
        observer: StandardObserver,
        range: WavelengthRange,
    ) -> Result<Self, Error> {
        Ok(Self::of_problem(Problem::new(&as_dyn(lights), Grid::new(observer, range)?)?))
    }

    fn of_problem(problem: Problem) -> Self {
        FittedRules(Arc::new(Fits { problem, rules: [const { OnceLock::new() }; MAX_M] }))
    }

    /// The rules of `lights` fitted over a scene's own `surfaces` instead of
    /// the built-in prior: each surface alone and products of two to four
    /// of them (paths of several bounces), drawn as the prior's are, with
    /// the perfect white and the surfaces' mean as anchors. A renderer that
    /// knows its materials gets a rule fitted to them; a study gets a
    /// reference point, the fit over the very set it then judges (not a
    /// lower bound: least squares, not the worst case). Building it
    /// takes about 40 ms for a few surfaces and 0.45 s for [`MAX_SURFACES`]
    /// (release build).
    ///
    /// An [`Error::Count`] for no surfaces or more than [`MAX_SURFACES`],
    /// an [`Error::Surface`] for a value that is not finite, an
    /// [`Error::NoMass`] as in [`Rule::fit`].
    ///
    /// ```
    /// use speclab::data::{lights, patches};
    /// use speclab::sampling::{fitted::FittedRules, reference};
    /// use speclab::spectrum::Spectrum;
    /// let six: Vec<&dyn Spectrum> = patches::ALL.iter().map(|&(_, p)| p as &dyn Spectrum).collect();
    /// let own = FittedRules::with_surfaces(&[&lights::F11], &six)?;
    /// let prior = FittedRules::of(&lights::F11)?;
    /// let error = |rules: &FittedRules| -> Result<f64, speclab::Error> {
    ///     let rule = rules.rule(4)?;
    ///     Ok(six.iter().map(|&p| {
    ///         let (got, want) = (rule.xyz_of_product(&[&lights::F11, p]), reference::xyz(&lights::F11, p));
    ///         (got.y - want.y).abs() / want.y
    ///     }).fold(0.0, f64::max))
    /// };
    /// assert!(error(&own)? < error(&prior)?); // fitted to these six, it serves them better
    /// assert!(FittedRules::with_surfaces(&[&lights::F11], &[] as &[&dyn Spectrum]).is_err());
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn with_surfaces<S: Spectrum, R: Spectrum>(lights: &[S], surfaces: &[R]) -> Result<Self, Error> {
        Ok(Self::of_problem(Problem::over(&as_dyn(lights), &as_dyn(surfaces), Grid::ASSIGNMENT)?))
    }

    /// The rules of one light: [`FittedRules::new`]`(&[light])`.
    pub fn of(light: &(impl Spectrum + ?Sized)) -> Result<Self, Error> {
        Self::new(&[&light as &dyn Spectrum])
    }

    /// The rule of `m` wavelengths, fitted on first use: for rules over the
    /// prior, the same rule as [`Rule::fit`]`(lights, m)`. An
    /// [`Error::Count`] unless `1 ≤ m ≤` [`MAX_M`]. The rule has fewer
    /// wavelengths where the reflectances tell apart fewer (`m()` says how
    /// many): a handful of surfaces given to
    /// [`with_surfaces`](FittedRules::with_surfaces) (one grey tells apart
    /// one), or the prior at M near 64 under a light dark over much of the
    /// range (F11: 59 at M = 64).
    pub fn rule(&self, m: usize) -> Result<&Rule, Error> {
        check_m("a fitted wavelength count", m)?;
        Ok(self.0.rules[m - 1].get_or_init(|| fit(&self.0.problem, m).swap_remove(0)))
    }
}

#[cfg(test)]
mod tests {
    use super::{ANCHOR_TOLERANCE, FittedRules};
    use crate::data::Light;
    use crate::sampling::prior::PriorMean;
    use crate::sampling::reference;

    /// Each M is kept in its own place: asking for 6 and 10 keeps 6 and 10,
    /// and the last place holds M = 64 (under F11 the prior tells apart 59
    /// wavelengths there: regression snapshot).
    #[test]
    fn rules_are_kept_by_m() {
        let rules = FittedRules::of(&crate::spectrum::data::lights::F11).unwrap();
        rules.rule(6).unwrap();
        rules.rule(10).unwrap();
        assert!(format!("{rules:?}").contains("fitted: [6, 10]"), "{rules:?}");
        assert_eq!(rules.rule(64).unwrap().m(), 59);
        assert!(format!("{rules:?}").contains("fitted: [6, 10, 64]"), "{rules:?}");
    }

    /// A grey, alone, tells apart one wavelength (every row is the light
    /// times a constant): a rule of one however many are asked for, which
    /// reproduces the grey.
    #[test]
    fn surfaces_tell_apart_as_many_wavelengths_as_they_span() {
        use crate::sampling::reference;
        use crate::spectrum::{Constant, Spectrum, data::lights};
        let grey = Constant::new(0.5);
        let rules = FittedRules::with_surfaces(&[&lights::F11], &[&grey as &dyn Spectrum]).unwrap();
        let rule = rules.rule(10).unwrap();
        assert_eq!(rule.m(), 1);
        let (got, want) = (rule.xyz_of_product(&[&lights::F11, &grey]), reference::xyz(&lights::F11, &grey));
        assert!((got.y - want.y).abs() < 1e-6 * want.y, "{got:?} {want:?}");
    }

    /// Each rule reproduces its anchors to [`ANCHOR_TOLERANCE`]: the
    /// perfect white under its light, and the prior's mean reflectance.
    #[test]
    fn anchors_are_reproduced() {
        let mut worst = 0.0f64;
        for light in Light::APPENDIX.map(|l| l.spectrum()) {
            let rules = FittedRules::of(light).unwrap();
            for m in [6, 10, 16, 32] {
                let rule = rules.rule(m).unwrap();
                for (got, want) in [
                    (rule.xyz_of_product(&[light]), reference::white(light)),
                    (
                        rule.xyz_of_product(&[light, &PriorMean]),
                        reference::xyz_of_product(&[light, &PriorMean]),
                    ),
                ] {
                    let (g, w) = (got.to_array(), want.to_array());
                    let scale = w.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    worst =
                        worst.max(g.iter().zip(w).map(|(a, b)| (a - b).abs() / scale).fold(0.0, f64::max));
                }
            }
        }
        assert!(worst <= ANCHOR_TOLERANCE, "{worst}");
    }
}
