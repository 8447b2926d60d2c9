//! The two ways `render` paints its paths: spectral (what a hero-wavelength
//! renderer does with speclab) and grey (the same paths with one number per
//! surface, so the example can time the spectral work by difference).

use speclab::sampling::pdf::WavelengthPdf;
use speclab::spectrum::observer::Y_BAR_INTEGRAL;
use speclab::spectrum::{Observer, RgbAlbedo};
use speclab::{HeroSample, SampledSpectrum, Spectrum, Xyz};

use crate::tracer::{Material, Paint};

/// Hero samples of four wavelengths, drawn from `pdf`; the light, the
/// patches (`S`: exact tabulated or dense) and the texture (RGB albedos)
/// evaluated at them; XYZ through `observer`.
pub struct Spectral<'a, S, O> {
    pub light: S,
    pub patches: Vec<S>,
    pub texture: &'a [RgbAlbedo],
    pub observer: O,
    pub pdf: &'a (dyn WavelengthPdf + Sync),
}

impl<S: Spectrum + Sync, O: Observer + Sync> Paint for Spectral<'_, S, O> {
    /// The wavelengths, and the luminance weights of their throughput.
    type Path = (HeroSample<4>, SampledSpectrum<4>);
    type Value = SampledSpectrum<4>;

    #[inline]
    fn path(&self, u: f64) -> Self::Path {
        let h = HeroSample::from_pdf(u, self.pdf);
        (h, h.y_weights() * (1.0 / Y_BAR_INTEGRAL))
    }

    fn one(&self) -> SampledSpectrum<4> {
        SampledSpectrum::splat(1.0)
    }

    fn zero(&self) -> SampledSpectrum<4> {
        SampledSpectrum::zero()
    }

    #[inline]
    fn emission(&self, (h, _): &Self::Path) -> SampledSpectrum<4> {
        h.sample(&self.light)
    }

    #[inline]
    fn albedo(&self, (h, _): &Self::Path, material: Material, texel: usize) -> SampledSpectrum<4> {
        match material {
            Material::Patch(i) => h.sample(&self.patches[i]),
            Material::Texture => h.sample(&self.texture[texel]),
        }
    }

    /// The throughput's luminance relative to a white path's: `y` over ∫ȳ,
    /// as a dot product with the path's weights.
    #[inline]
    fn survival(&self, (_, y_weights): &Self::Path, beta: SampledSpectrum<4>) -> f64 {
        beta.dot(y_weights)
    }

    #[inline]
    fn xyz(&self, (h, _): &Self::Path, radiance: SampledSpectrum<4>) -> Xyz {
        h.to_xyz_with(&self.observer, radiance)
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
