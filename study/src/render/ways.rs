//! What the tracer adds to the core's ways of carrying colour: the scene's
//! albedos as one list of one type ([`Albedo`]: a measured spectrum or a
//! texel's RGB), and [`Grey`], one number per surface with no colour work,
//! the baseline colour's share of the time is measured against.

use speclab::Xyz;
use speclab::carry::Carry;
use speclab::color::RgbAlbedo;
use speclab::spectrum::{Float, Pieces, SampledSpectrum, Samples, Spectrum, Wavelengths};

/// A surface's albedo: a measured reflectance (`S`: tabulated or dense) or
/// a texel's RGB colour as a spectrum. Sampling dispatches to the kind's
/// own `sample`, so a dense table keeps its one-load lookup.
#[derive(Clone, Debug)]
pub enum Albedo<S> {
    /// A reflectance, tabulated or dense.
    Measured(S),
    /// An RGB texel's spectrum.
    Texel(RgbAlbedo),
}

impl<S: Spectrum> Spectrum for Albedo<S> {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        match self {
            Albedo::Measured(s) => s.eval(lambda),
            Albedo::Texel(t) => t.eval(lambda),
        }
    }

    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        match self {
            Albedo::Measured(s) => s.eval_many(lambda, values),
            Albedo::Texel(t) => t.eval_many(lambda, values),
        }
    }

    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        match self {
            Albedo::Measured(s) => s.eval_many_f32(lambda, values),
            Albedo::Texel(t) => t.eval_many_f32(lambda, values),
        }
    }

    #[inline]
    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        match self {
            Albedo::Measured(s) => s.sample(at),
            Albedo::Texel(t) => t.sample(at),
        }
    }

    fn pieces(&self) -> Option<Pieces<'_>> {
        match self {
            Albedo::Measured(s) => s.pieces(),
            Albedo::Texel(t) => t.pieces(),
        }
    }

    fn samples(&self) -> Option<Samples<'_>> {
        match self {
            Albedo::Measured(s) => s.samples(),
            Albedo::Texel(t) => t.samples(),
        }
    }
}

/// One number per surface: its luminance factor under the lights (patches)
/// or the luminance of its RGB (texels); radiance in units of the lights'
/// white, so a grey image has the lights' colour.
#[derive(Clone, Debug)]
pub struct Grey {
    /// Per surface (the patches, then the texels).
    pub surfaces: Vec<f64>,
    /// The lights' white, summed.
    pub white: Xyz,
}

impl Carry for Grey {
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
    fn albedo(&self, _path: &(), surface: usize) -> f64 {
        self.surfaces[surface]
    }

    fn luminance(&self, _path: &(), beta: f64) -> f64 {
        beta
    }

    fn max_component(&self, _path: &(), beta: f64) -> f64 {
        beta
    }
}
