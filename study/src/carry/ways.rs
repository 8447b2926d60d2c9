//! The three ways of carrying colour: [`Hero`], [`Fitted`], [`Rgb`].

use std::marker::PhantomData;

use crate::StudyError;
use crate::carry::Carry;
use speclab::color::space::RgbSpace;
use speclab::color::{LinearRgb, Xyz};
use speclab::error::Error;
use speclab::sampling::pdf::WavelengthPdf;
use speclab::sampling::reference;
use speclab::sampling::rule::Rule;
use speclab::sampling::{Domain, Emission, FixedWavelengths, HeroSample};
use speclab::spectrum::observer::Y_BAR_INTEGRAL;
use speclab::spectrum::{Float, Observer, SampledSpectrum, Spectrum};

/// Hero wavelengths (K = 4) drawn per path from `pdf` and weighted by
/// `observer`; the lights and surfaces evaluated at them at every vertex,
/// in precision `T` (`f64` unless [`Hero::precision`] says otherwise).
#[derive(Clone, Debug)]
pub struct Hero<L, S, O, P, T = f64> {
    /// The lights, numbered in order.
    pub lights: Vec<L>,
    /// The surfaces' albedos, numbered in order.
    pub surfaces: Vec<S>,
    /// The density the wavelengths are drawn from and the observer the
    /// weights come from (`DenseObserver` for the fast path,
    /// `AssignmentObserver` for the exact one), checked together.
    pub domain: Domain<P, O>,
    precision: PhantomData<T>,
}

impl<L, S, O: Observer, P: WavelengthPdf> Hero<L, S, O, P, f64> {
    /// Hero wavelengths from `pdf`, weighted by `observer`, in `f64`; an
    /// error if the pdf draws where the observer has no data.
    pub fn new(lights: Vec<L>, surfaces: Vec<S>, observer: O, pdf: P) -> Result<Self, Error> {
        Ok(Hero { lights, surfaces, domain: Domain::new(pdf, observer)?, precision: PhantomData })
    }
}

impl<L, S, O, P, T> Hero<L, S, O, P, T> {
    /// The same, with per-sample values in precision `U` (`f32` for a
    /// renderer computing in single precision).
    #[must_use]
    pub fn precision<U: Float>(self) -> Hero<L, S, O, P, U> {
        let Hero { lights, surfaces, domain, .. } = self;
        Hero { lights, surfaces, domain, precision: PhantomData }
    }
}

impl<L: Spectrum, S: Spectrum, O: Observer, P: WavelengthPdf, T: Float> Carry for Hero<L, S, O, P, T> {
    /// The wavelengths and their weights: one value per path.
    type Path = HeroSample<4, T>;
    type Value = SampledSpectrum<4, T>;

    #[inline]
    fn path(&self, u: f64) -> Self::Path {
        self.domain.hero_by_cdf(T::from_f64(u))
    }

    fn one(&self) -> Self::Value {
        SampledSpectrum::splat(T::ONE)
    }

    #[inline]
    fn scale(&self, v: Self::Value, s: f64) -> Self::Value {
        v * T::from_f64(s)
    }

    #[inline]
    fn emitted(&self, h: &Self::Path, light: usize, beta: Self::Value) -> Xyz {
        self.lights.get(light).map_or(Xyz::ZERO, |l| h.to_xyz(beta * h.sample(l)))
    }

    #[inline]
    fn albedo(&self, h: &Self::Path, surface: usize) -> Self::Value {
        self.surfaces.get(surface).map_or(SampledSpectrum::zero(), |s| h.sample(s))
    }

    /// `y(β)` over ∫ȳ ([`Y_BAR_INTEGRAL`]): for a white β, an estimate of 1.
    #[inline]
    fn luminance(&self, h: &Self::Path, beta: Self::Value) -> f64 {
        h.y(beta).to_f64() * (1.0 / Y_BAR_INTEGRAL)
    }

    #[inline]
    fn max_component(&self, _h: &Self::Path, beta: Self::Value) -> f64 {
        beta.max_value().to_f64()
    }
}

/// Rules fitted to the scene's lights, one per light at the same M
/// wavelengths (`Rule::fit_each`), in `CAP` lanes (CAP ≥ M: the lanes
/// beyond M weigh nothing; [`with_lanes`](speclab::sampling::with_lanes) picks CAP
/// from M); every surface evaluated at the wavelengths once, and each
/// light's emission folded into its own rule's XYZ weights.
#[derive(Clone, Debug)]
pub struct Fitted<const CAP: usize, T: Float = f64> {
    /// The luminance weights (the first light's rule's).
    pub y: SampledSpectrum<CAP, T>,
    /// Each light's emission times its rule's weights.
    pub lights: Vec<Emission<CAP, T>>,
    /// Each surface's values at the wavelengths.
    pub surfaces: Vec<SampledSpectrum<CAP, T>>,
}

impl<const CAP: usize, T: Float> Fitted<CAP, T> {
    /// The scene's spectra at the rules' wavelengths (`rules[i]` for light
    /// `i`, all at the same wavelengths, as `Rule::fit_each` makes them).
    /// An [`Error::NoMass`] for no rules; an [`Error::Count`] for a number
    /// of rules other than the number of lights, or a rule larger than
    /// `CAP`; a [`StudyError::RulesDiffer`] for a rule at other wavelengths
    /// than the first's.
    pub fn new(
        rules: &[Rule],
        lights: &[impl Spectrum],
        surfaces: &[impl Spectrum],
    ) -> Result<Self, StudyError> {
        if rules.len() != lights.len() && !rules.is_empty() {
            let (found, n) = (rules.len(), lights.len());
            return Err(Error::Count { what: "rules, one per light", found, min: n, max: n }.into());
        }
        if let Some(index) = rules.iter().position(|r| r.lambda() != rules[0].lambda()) {
            return Err(StudyError::RulesDiffer { index });
        }
        let each: Vec<FixedWavelengths<CAP, T>> =
            rules.iter().map(Rule::wavelengths).collect::<Result<_, _>>()?;
        let at = each.first().ok_or(Error::NoMass)?;
        Ok(Fitted {
            y: at.y_weights(),
            lights: each.iter().zip(lights).map(|(w, l)| w.emission(l)).collect(),
            surfaces: surfaces.iter().map(|s| at.sample(s)).collect(),
        })
    }
}

impl<const CAP: usize, T: Float> Carry for Fitted<CAP, T> {
    /// Nothing per path: the wavelengths are the rules'.
    type Path = ();
    type Value = SampledSpectrum<CAP, T>;

    fn path(&self, _u: f64) {}

    fn one(&self) -> Self::Value {
        SampledSpectrum::splat(T::ONE)
    }

    #[inline]
    fn scale(&self, v: Self::Value, s: f64) -> Self::Value {
        v * T::from_f64(s)
    }

    #[inline]
    fn emitted(&self, _path: &(), light: usize, beta: Self::Value) -> Xyz {
        self.lights.get(light).map_or(Xyz::ZERO, |l| l.xyz(beta))
    }

    #[inline]
    fn albedo(&self, _path: &(), surface: usize) -> Self::Value {
        self.surfaces.get(surface).copied().unwrap_or_else(SampledSpectrum::zero)
    }

    /// `β·w_Y` with the first rule's weights, over ∫ȳ ([`Y_BAR_INTEGRAL`]).
    /// A fitted rule's luminance weights need not sum to ∫ȳ (under F11 at
    /// M = 10 they sum to about 77): a white β then reads below 1.
    #[inline]
    fn luminance(&self, _path: &(), beta: Self::Value) -> f64 {
        beta.dot(&self.y).to_f64() * (1.0 / Y_BAR_INTEGRAL)
    }

    /// Over every lane: the lanes beyond the rule's size repeat its last
    /// wavelength, so they add no larger value.
    #[inline]
    fn max_component(&self, _path: &(), beta: Self::Value) -> f64 {
        beta.max_value().to_f64()
    }
}

/// Linear RGB triples: a renderer without spectra.
#[derive(Clone, Debug)]
pub struct Rgb {
    /// Each light's colour.
    pub lights: Vec<LinearRgb>,
    /// Each surface's albedo.
    pub surfaces: Vec<LinearRgb>,
    /// The space the triples are in.
    pub space: &'static RgbSpace,
}

impl Rgb {
    /// [`Rgb::in_space`] in linear sRGB.
    pub fn new(lights: &[impl Spectrum], surfaces: &[impl Spectrum]) -> Self {
        Rgb::in_space(RgbSpace::srgb(), lights, surfaces)
    }

    /// Each light as its colour in `space` (its white's XYZ, in the light's
    /// own units, negatives clipped), each surface as its albedo under the
    /// space's illuminant clipped to [0, 1] (an RGB renderer's materials
    /// hold nothing else; unclipped, the products of out-of-gamut surfaces'
    /// negative components along a path go negative).
    pub fn in_space(space: &'static RgbSpace, lights: &[impl Spectrum], surfaces: &[impl Spectrum]) -> Self {
        Rgb {
            lights: lights.iter().map(|l| space.rgb(reference::white(l)).map(|c| c.max(0.0))).collect(),
            surfaces: surfaces.iter().map(|s| space.rgb_of(s).map(|c| c.clamp(0.0, 1.0))).collect(),
            space,
        }
    }
}

impl Carry for Rgb {
    type Path = ();
    type Value = LinearRgb;

    fn path(&self, _u: f64) {}

    fn one(&self) -> LinearRgb {
        LinearRgb::splat(1.0)
    }

    #[inline]
    fn scale(&self, v: LinearRgb, s: f64) -> LinearRgb {
        v * s
    }

    #[inline]
    fn emitted(&self, _path: &(), light: usize, beta: LinearRgb) -> Xyz {
        self.lights.get(light).map_or(Xyz::ZERO, |&l| self.space.xyz(beta * l))
    }

    #[inline]
    fn albedo(&self, _path: &(), surface: usize) -> LinearRgb {
        self.surfaces.get(surface).copied().unwrap_or_default()
    }

    /// The throughput's Y (a white β has Y = 1).
    #[inline]
    fn luminance(&self, _path: &(), beta: LinearRgb) -> f64 {
        self.space.xyz(beta).y
    }

    #[inline]
    fn max_component(&self, _path: &(), beta: LinearRgb) -> f64 {
        beta.max_component()
    }
}
