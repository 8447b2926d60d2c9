//! What the tracer adds to the core's ways of carrying colour: the scene's
//! albedos as one list of one type ([`Albedo`]: a measured spectrum or a
//! texel's RGB), [`Grey`], one number per surface with no colour work,
//! the baseline colour's share of the time is measured against, and
//! [`Prefilter`], Ward's spectral prefiltering as a way to carry colour.

use crate::carry::Carry;
use speclab::Xyz;
use speclab::color::{LinearRgb, RgbAlbedo, RgbSpace};
use speclab::sampling::reference;

use crate::published::prefilter::{Prefiltered, Space};
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
    /// An RGB colour (in [0, 1]³) in a space, looked up in the space's
    /// table at every sample, as a texture is read at each hit.
    Lookup(LinearRgb, &'static RgbSpace),
}

impl<S> Albedo<S> {
    /// The albedo of a [`Albedo::Lookup`] (black for a colour outside the
    /// cube, which `Lookup`s are not made with).
    #[inline]
    fn looked_up(rgb: LinearRgb, space: &RgbSpace) -> RgbAlbedo {
        space.albedo(rgb).unwrap_or(RgbAlbedo::from_polynomial(speclab::spectrum::SigmoidPolynomial::BLACK))
    }

    /// The colour `rgb` in `space` converted once: the [`Albedo::Texel`]
    /// of what a [`Albedo::Lookup`] of it looks up at each hit.
    pub fn converted(rgb: LinearRgb, space: &RgbSpace) -> Self {
        Albedo::Texel(Self::looked_up(rgb, space))
    }
}

impl<S: Spectrum> Spectrum for Albedo<S> {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        match self {
            Albedo::Measured(s) => s.eval(lambda),
            Albedo::Texel(t) => t.eval(lambda),
            Albedo::Lookup(rgb, space) => Self::looked_up(*rgb, space).eval(lambda),
        }
    }

    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        match self {
            Albedo::Measured(s) => s.eval_many(lambda, values),
            Albedo::Texel(t) => t.eval_many(lambda, values),
            Albedo::Lookup(rgb, space) => Self::looked_up(*rgb, space).eval_many(lambda, values),
        }
    }

    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        match self {
            Albedo::Measured(s) => s.eval_many_f32(lambda, values),
            Albedo::Texel(t) => t.eval_many_f32(lambda, values),
            Albedo::Lookup(rgb, space) => Self::looked_up(*rgb, space).eval_many_f32(lambda, values),
        }
    }

    #[inline]
    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        match self {
            Albedo::Measured(s) => s.sample(at),
            Albedo::Texel(t) => t.sample(at),
            Albedo::Lookup(rgb, space) => Self::looked_up(*rgb, space).sample(at),
        }
    }

    fn pieces(&self) -> Option<Pieces<'_>> {
        match self {
            Albedo::Measured(s) => s.pieces(),
            Albedo::Texel(t) => t.pieces(),
            Albedo::Lookup(..) => None,
        }
    }

    fn samples(&self) -> Option<Samples<'_>> {
        match self {
            Albedo::Measured(s) => s.samples(),
            Albedo::Texel(t) => t.samples(),
            Albedo::Lookup(..) => None,
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

/// Spectral prefiltering (Ward and Eydelberg-Vileshin 2002) as a way to
/// carry colour: three numbers per surface, each surface prefiltered once
/// under the scene's lights together (their sum), each light's own colour
/// in the space; exact for one bounce under one light, an approximation
/// from the second bounce on. RGB's cost per vertex.
#[derive(Clone, Debug)]
pub struct Prefilter {
    /// The space's conversions and the lights' summed colour.
    space: Prefiltered,
    /// Each light's colour in the space.
    lights: Vec<LinearRgb>,
    /// Each surface's three numbers.
    surfaces: Vec<LinearRgb>,
    /// Y per unit of each channel of a throughput, for a white path's Y = 1.
    luminance: [f64; 3],
}

impl Prefilter {
    /// The lights and surfaces (exact XYZ of each light, and of their sum
    /// times each surface) prefiltered in `space`. An error if the lights'
    /// summed colour has a zero channel there.
    pub fn new(
        space: Space,
        lights: &[impl Spectrum],
        surfaces: &[impl Spectrum],
    ) -> Result<Self, speclab::Error> {
        let white: Xyz = lights.iter().map(reference::white).sum();
        let space = Prefiltered::new(space, white)?;
        let under_all = |s: &dyn Spectrum| lights.iter().map(|l| reference::xyz(l, s)).sum::<Xyz>();
        let surfaces = surfaces.iter().map(|s| LinearRgb::from(space.surface(under_all(s)))).collect();
        let lights = lights.iter().map(|l| LinearRgb::from(space.in_space(reference::white(l)))).collect();
        let l0 = space.light();
        let luminance = [0, 1, 2].map(|c| {
            let mut unit = [0.0; 3];
            unit[c] = l0[c];
            space.to_xyz(unit).y / white.y
        });
        Ok(Prefilter { space, lights, surfaces, luminance })
    }
}

impl Carry for Prefilter {
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
        self.lights.get(light).map_or(Xyz::ZERO, |&l| self.space.to_xyz((beta * l).to_array()))
    }

    #[inline]
    fn albedo(&self, _path: &(), surface: usize) -> LinearRgb {
        self.surfaces.get(surface).copied().unwrap_or_default()
    }

    /// The throughput's Y relative to a white path's under the lights' sum.
    #[inline]
    fn luminance(&self, _path: &(), beta: LinearRgb) -> f64 {
        let b = beta.to_array();
        (0..3).map(|c| self.luminance[c] * b[c]).sum()
    }

    #[inline]
    fn max_component(&self, _path: &(), beta: LinearRgb) -> f64 {
        beta.max_component()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use speclab::data::{lights, patches};

    #[test]
    fn prefiltering_carries_one_bounce_exactly_and_a_white_path_at_one() {
        let carry = Prefilter::new(Space::Sharp, &[&lights::F11], &[&patches::G4, &patches::A1]).unwrap();
        let beta = carry.albedo(&(), 0);
        let (ours, exact) = (carry.emitted(&(), 0, beta), reference::xyz(&lights::F11, &patches::G4));
        assert!((ours.y - exact.y).abs() < 1e-9 * exact.y && (ours.x - exact.x).abs() < 1e-9 * exact.x);
        assert!((carry.luminance(&(), carry.one()) - 1.0).abs() < 1e-12);
        let half = carry.scale(carry.one(), 0.5);
        assert!((carry.luminance(&(), half) - 0.5).abs() < 1e-12);
        // Russian roulette reads the largest channel: G4's, then half of it.
        let g4 = beta.to_array().into_iter().fold(f64::MIN, f64::max);
        assert!(g4 > 0.05 && g4 < 1.0 && carry.max_component(&(), beta) == g4, "{beta:?}");
        assert_eq!(carry.max_component(&(), carry.scale(beta, 0.5)), 0.5 * g4);
        let two = Prefilter::new(Space::Xyz, &[&lights::F11, &lights::A], &[&patches::G4]).unwrap();
        let white = reference::white(&lights::A);
        assert!((two.emitted(&(), 1, two.one()).y - white.y).abs() < 1e-9 * white.y);
    }

    /// A light or surface index past the scene gives nothing, as the other
    /// ways of carrying colour do.
    #[test]
    fn indices_past_the_scene_give_nothing() {
        let carry = Prefilter::new(Space::Sharp, &[&lights::F11], &[&patches::G4]).unwrap();
        assert_eq!(carry.emitted(&(), 1, carry.one()), Xyz::ZERO);
        assert_eq!(carry.albedo(&(), 1), LinearRgb::default());
        assert!(carry.emitted(&(), 0, carry.one()).y > 0.0);
    }
}
