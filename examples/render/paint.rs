//! The ways `render` carries colour along its paths:
//!
//! - [`Hero`]: hero wavelengths (K = 4) drawn per path from a pdf, every
//!   spectrum evaluated at them per vertex, in `f64` or `f32`;
//! - [`Fitted`]: M wavelengths fitted once to all the scene's lights, with
//!   weights of its own for each light; every spectrum (texels included)
//!   evaluated at the wavelengths once, when the scene is built; a path
//!   carries M values, and each light's contribution is converted with its
//!   light's weights;
//! - [`Rgb`]: a renderer without spectra: every reflectance as its linear
//!   sRGB albedo under D65, texels as given, each light as its linear sRGB
//!   colour, channel by channel;
//! - [`Grey`]: one number per surface, no colour work (the timing baseline).

use speclab::color::RgbAlbedo;
use speclab::color::upsample::RgbSpace;
use speclab::sampling::pdf::WavelengthPdf;
use speclab::sampling::rule::Rule;
use speclab::sampling::{Emission, SampledWavelengths};
use speclab::spectrum::observer::Y_BAR_INTEGRAL;
use speclab::spectrum::{Float, Observer};
use speclab::{HeroSample, LinearSrgb, SampledSpectrum, Spectrum, Xyz};

use crate::tracer::{Material, Paint};

/// Hero samples of four wavelengths in precision `T`, drawn from `pdf` and
/// weighted by `observer`; the lights, the patches (`S`: exact tabulated
/// or dense) and the texture (RGB albedos) evaluated at them.
pub struct Hero<'a, S, O, T> {
    pub lights: Vec<S>,
    pub patches: Vec<S>,
    pub texture: &'a [RgbAlbedo],
    pub observer: O,
    pub pdf: &'a (dyn WavelengthPdf + Sync),
    pub precision: std::marker::PhantomData<T>,
}

impl<S: Spectrum + Sync, O: Observer + Sync, T: Float> Paint for Hero<'_, S, O, T> {
    /// The wavelengths and their weights: one value per path.
    type Path = HeroSample<4, T>;
    type Value = SampledSpectrum<4, T>;

    #[inline]
    fn path(&self, u: f64) -> Self::Path {
        HeroSample::from_pdf_with(T::from_f64(u), self.pdf, &self.observer)
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
        h.to_xyz(beta * h.sample(&self.lights[light]))
    }

    #[inline]
    fn albedo(&self, h: &Self::Path, material: Material, texel: usize) -> Self::Value {
        match material {
            Material::Patch(i) => h.sample(&self.patches[i]),
            Material::Texture => h.sample(&self.texture[texel]),
        }
    }

    /// The throughput's luminance relative to a white path's: `y` over ∫ȳ.
    #[inline]
    fn survival(&self, h: &Self::Path, beta: Self::Value) -> f64 {
        h.y(beta).to_f64() * (1.0 / Y_BAR_INTEGRAL)
    }
}

/// Rules fitted to the scene's lights, one per light at the same M
/// wavelengths (`Rule::fit_each`), in `CAP` lanes (the rest weigh
/// nothing); every spectrum of the scene evaluated at them once, and each
/// light's emission folded into its own rule's XYZ weights.
pub struct Fitted<const CAP: usize, T: Float> {
    /// The luminance weights for Russian roulette (the first light's).
    pub y: SampledSpectrum<CAP, T>,
    pub lights: Vec<Emission<CAP, T>>,
    pub patches: Vec<SampledSpectrum<CAP, T>>,
    pub texture: Vec<SampledSpectrum<CAP, T>>,
}

impl<const CAP: usize, T: Float> Fitted<CAP, T> {
    /// The scene's spectra at the rules' wavelengths (`rules[i]` for light
    /// `i`; one rule at least).
    pub fn new(
        rules: &[Rule],
        lights: &[impl Spectrum],
        patches: &[impl Spectrum],
        texture: &[RgbAlbedo],
    ) -> Result<Self, speclab::Error> {
        let each: Vec<SampledWavelengths<CAP, T>> =
            rules.iter().map(|r| r.wavelengths()).collect::<Result<_, _>>()?;
        let at = each.first().ok_or(speclab::Error::NoMass)?;
        Ok(Fitted {
            y: at.y_weights(),
            lights: each.iter().zip(lights).map(|(w, l)| w.emission(l)).collect(),
            patches: patches.iter().map(|p| at.sample(p)).collect(),
            texture: texture.iter().map(|t| at.sample(t)).collect(),
        })
    }
}

impl<const CAP: usize, T: Float> Paint for Fitted<CAP, T> {
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
        self.lights[light].xyz(beta)
    }

    #[inline]
    fn albedo(&self, _path: &(), material: Material, texel: usize) -> Self::Value {
        match material {
            Material::Patch(i) => self.patches[i],
            Material::Texture => self.texture[texel],
        }
    }

    /// The luminance with the first rule's weights, over ∫ȳ.
    #[inline]
    fn survival(&self, _path: &(), beta: Self::Value) -> f64 {
        beta.dot(&self.y).to_f64() * (1.0 / Y_BAR_INTEGRAL)
    }
}

/// Linear sRGB triples: a renderer without spectra.
pub struct Rgb {
    pub lights: Vec<LinearSrgb>,
    pub patches: Vec<LinearSrgb>,
    pub texture: Vec<LinearSrgb>,
    pub space: &'static RgbSpace,
}

impl Rgb {
    /// Each light as its linear sRGB colour (its white's XYZ, in the
    /// light's own units, negatives clipped), each reflectance as its
    /// linear sRGB albedo under D65 clipped to [0, 1] (an RGB renderer's
    /// materials and textures hold nothing else; unclipped, the products of
    /// out-of-gamut patches' negative components along a path go negative),
    /// the texels as given.
    pub fn new(lights: &[impl Spectrum], patches: &[impl Spectrum], texture: &[LinearSrgb]) -> Self {
        let space = RgbSpace::srgb();
        let white = |l: &dyn Spectrum| space.rgb(speclab::sampling::reference::white(l)).map(|c| c.max(0.0));
        Rgb {
            lights: lights.iter().map(|l| white(l)).collect(),
            patches: patches.iter().map(|p| space.rgb_of(p).map(|c| c.clamp(0.0, 1.0))).collect(),
            texture: texture.to_vec(),
            space,
        }
    }
}

impl Paint for Rgb {
    type Path = ();
    type Value = LinearSrgb;

    fn path(&self, _u: f64) {}

    fn one(&self) -> LinearSrgb {
        LinearSrgb::new(1.0, 1.0, 1.0)
    }

    #[inline]
    fn scale(&self, v: LinearSrgb, s: f64) -> LinearSrgb {
        v * s
    }

    #[inline]
    fn emitted(&self, _path: &(), light: usize, beta: LinearSrgb) -> Xyz {
        self.space.xyz(beta * self.lights[light])
    }

    #[inline]
    fn albedo(&self, _path: &(), material: Material, texel: usize) -> LinearSrgb {
        match material {
            Material::Patch(i) => self.patches[i],
            Material::Texture => self.texture[texel],
        }
    }

    /// The throughput's luminance (white Y = 1).
    #[inline]
    fn survival(&self, _path: &(), beta: LinearSrgb) -> f64 {
        self.space.xyz(beta).y
    }
}

/// One number per surface: its luminance factor under the lights (patches)
/// or the luminance of its RGB (texels); radiance in units of the lights'
/// white, so a grey image has the lights' colour.
pub struct Grey {
    pub patches: Vec<f64>,
    pub texture: Vec<f64>,
    pub white: Xyz,
}

impl Paint for Grey {
    type Path = ();
    type Value = f64;

    fn path(&self, _u: f64) {}

    fn one(&self) -> f64 {
        1.0
    }

    fn scale(&self, v: f64, s: f64) -> f64 {
        v * s
    }

    fn emitted(&self, _path: &(), _light: usize, beta: f64) -> Xyz {
        self.white * beta
    }

    #[inline]
    fn albedo(&self, _path: &(), material: Material, texel: usize) -> f64 {
        match material {
            Material::Patch(i) => self.patches[i],
            Material::Texture => self.texture[texel],
        }
    }

    fn survival(&self, _path: &(), beta: f64) -> f64 {
        beta
    }
}
