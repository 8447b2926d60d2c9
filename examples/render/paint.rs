//! The two ways `render` paints its paths: spectral (what a hero-wavelength
//! renderer does with speclab) and grey (the same paths with one number per
//! surface, so the example can time the spectral work by difference).

use speclab::sampling::pdf::WavelengthPdf;
use speclab::spectrum::observer::Y_BAR_INTEGRAL;
use speclab::spectrum::{Float, Observer, RgbAlbedo};
use speclab::{HeroSample, SampledSpectrum, Spectrum, Xyz};

use crate::tracer::{Material, Paint};

/// Hero samples of four wavelengths in precision `T`, drawn from `pdf` and
/// weighted by `observer`; the light, the patches (`S`: exact tabulated or
/// dense) and the texture (RGB albedos) evaluated at them.
pub struct Spectral<'a, S, O, T> {
    pub light: S,
    pub patches: Vec<S>,
    pub texture: &'a [RgbAlbedo],
    pub observer: O,
    pub pdf: &'a (dyn WavelengthPdf + Sync),
    pub precision: std::marker::PhantomData<T>,
}

impl<S: Spectrum + Sync, O: Observer + Sync, T: Float> Paint for Spectral<'_, S, O, T> {
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

    fn zero(&self) -> Self::Value {
        SampledSpectrum::zero()
    }

    #[inline]
    fn scale(&self, v: Self::Value, s: f64) -> Self::Value {
        v * T::from_f64(s)
    }

    #[inline]
    fn emission(&self, h: &Self::Path) -> Self::Value {
        h.sample(&self.light)
    }

    #[inline]
    fn albedo(&self, h: &Self::Path, material: Material, texel: usize) -> Self::Value {
        match material {
            Material::Patch(i) => h.sample(&self.patches[i]),
            Material::Texture => h.sample(&self.texture[texel]),
        }
    }

    /// The throughput's luminance relative to a white path's: `y` over ∫ȳ,
    /// a weighted sum with the path's weights.
    #[inline]
    fn survival(&self, h: &Self::Path, beta: Self::Value) -> f64 {
        h.y(beta).to_f64() * (1.0 / Y_BAR_INTEGRAL)
    }

    #[inline]
    fn xyz(&self, h: &Self::Path, radiance: Self::Value) -> Xyz {
        h.to_xyz(radiance)
    }
}

/// One number per surface: its luminance factor under the light (patches)
/// or the luminance of its RGB (texels); radiance in units of the light's
/// white, so a grey image has the light's colour.
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

    fn zero(&self) -> f64 {
        0.0
    }

    fn scale(&self, v: f64, s: f64) -> f64 {
        v * s
    }

    fn emission(&self, _path: &()) -> f64 {
        1.0
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

    fn xyz(&self, _path: &(), radiance: f64) -> Xyz {
        self.white * radiance
    }
}
