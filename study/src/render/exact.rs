//! The exact image: the same paths as a render (the same random numbers
//! for positions, directions and Russian roulette), each path's colour
//! integrated exactly over wavelength with `reference::ExactPaths`, so
//! that the difference between a render and its exact image is the
//! spectral error alone (a hero render's colour noise included).

use speclab::color::RgbAlbedo;
use speclab::sampling::reference::ExactPaths;
use speclab::spectrum::Spectrum;
use speclab::{TabulatedSpectrum, Xyz};

use crate::render::tracer::{MAX_DEPTH, Record};

/// The scene's spectra at the nodes of an exact quadrature: the lights,
/// then the six patches, then the 64 texels.
#[derive(Debug)]
pub struct ExactScene {
    paths: ExactPaths,
    lights: usize,
}

impl ExactScene {
    /// The quadrature for these lights, patches and texels.
    #[must_use]
    pub fn new(lights: &[TabulatedSpectrum], patches: &[TabulatedSpectrum], texture: &[RgbAlbedo]) -> Self {
        let mut spectra: Vec<&dyn Spectrum> = lights.iter().map(|l| l as &dyn Spectrum).collect();
        spectra.extend(patches.iter().map(|p| p as &dyn Spectrum));
        spectra.extend(texture.iter().map(|t| t as &dyn Spectrum));
        ExactScene { paths: ExactPaths::new(&spectra, MAX_DEPTH), lights: lights.len() }
    }

    /// The exact colour of a recorded path.
    #[must_use]
    pub fn xyz(&self, path: &PathRecord) -> Xyz {
        let index: [usize; MAX_DEPTH] = std::array::from_fn(|i| self.lights + path.surfaces[i]);
        let mut sum = Xyz::ZERO;
        for (light, factors) in path.factors.iter().enumerate().take(self.lights) {
            if factors[..=path.len].iter().any(|&c| c != 0.0) {
                sum += self.paths.xyz(light, &index[..path.len], &factors[..=path.len]).unwrap_or(Xyz::ZERO);
            }
        }
        sum
    }
}

/// What one path met: its surfaces (0–5 the patches, 6–69 the texels) and,
/// per light, the factor each prefix of them was seen with.
#[derive(Clone, Copy, Debug)]
pub struct PathRecord {
    surfaces: [usize; MAX_DEPTH],
    len: usize,
    factors: [[f64; MAX_DEPTH + 1]; 2],
}

impl Default for PathRecord {
    fn default() -> Self {
        Self::new()
    }
}

impl PathRecord {
    /// A path that has met nothing.
    #[must_use]
    pub fn new() -> Self {
        PathRecord { surfaces: [0; MAX_DEPTH], len: 0, factors: [[0.0; MAX_DEPTH + 1]; 2] }
    }
}

impl Record for PathRecord {
    fn surface(&mut self, surface: usize) {
        if self.len < MAX_DEPTH {
            self.surfaces[self.len] = surface;
            self.len += 1;
        }
    }

    fn light(&mut self, light: usize, depth: usize, factor: f64) {
        if let Some(c) = self.factors.get_mut(light).and_then(|f| f.get_mut(depth)) {
            *c += factor;
        }
    }
}
