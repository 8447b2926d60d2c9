//! The comparison grid: every light × surface by every method.
//!
//! This is the computation behind `examples/grid.rs`, kept in the library so
//! that tests and other programs get the same numbers. Cell `c` (in row-major
//! order over lights, then surfaces) draws its random methods from
//! `derive_seed(seed, 2c)` (random) and `derive_seed(seed, 2c + 1)` (hero).
//!
//! ```
//! use speclab::grid::{Grid, builtin_lights, builtin_surfaces};
//! let rows = Grid::default().rows(&builtin_lights(), &builtin_surfaces())?;
//! assert_eq!(rows.len(), 18 * 5);
//! # Ok::<(), speclab::Error>(())
//! ```

use std::num::NonZeroUsize;

use crate::data::{Light, Patch};
use crate::method::{Method, derive_seed};
use crate::{Error, TabulatedSpectrum, Xyz};

/// A spectrum with the name it has in tables.
#[derive(Clone, Copy, Debug)]
pub struct Named<'a> {
    /// Name, e.g. `D65`.
    pub name: &'a str,
    /// The spectrum.
    pub spectrum: &'a TabulatedSpectrum,
}

/// The three appendix lights, named.
#[must_use]
pub fn builtin_lights() -> Vec<Named<'static>> {
    Light::ALL.map(|l| Named { name: l.name(), spectrum: l.spectrum() }).to_vec()
}

/// The six appendix patches, named.
#[must_use]
pub fn builtin_surfaces() -> Vec<Named<'static>> {
    Patch::ALL.map(|p| Named { name: p.name(), spectrum: p.spectrum() }).to_vec()
}

/// Settings of a grid run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grid {
    /// Samples n for random and hero.
    pub n: NonZeroUsize,
    /// Buckets M for the regular methods.
    pub m: NonZeroUsize,
    /// Base seed.
    pub seed: u64,
}

impl Default for Grid {
    /// n = 100, M = 16, seed 1.
    fn default() -> Self {
        Grid {
            n: NonZeroUsize::new(100).unwrap_or(NonZeroUsize::MIN),
            m: NonZeroUsize::new(16).unwrap_or(NonZeroUsize::MIN),
            seed: 1,
        }
    }
}

/// One cell of the grid under one method.
#[derive(Clone, Debug, PartialEq)]
pub struct Row<'a> {
    /// The light's name.
    pub light: &'a str,
    /// The surface's name.
    pub surface: &'a str,
    /// The method.
    pub method: Method,
    /// n, M, or 0 for the reference.
    pub samples: usize,
    /// The result.
    pub xyz: Xyz,
}

impl Grid {
    /// All rows: for each light, each surface, each method in [`Method::ALL`].
    pub fn rows<'a>(&self, lights: &[Named<'a>], surfaces: &[Named<'a>]) -> Result<Vec<Row<'a>>, Error> {
        let mut rows = Vec::with_capacity(lights.len() * surfaces.len() * Method::ALL.len());
        let mut cell = 0u64;
        for light in lights {
            for surface in surfaces {
                for method in Method::ALL {
                    let (samples, seed) = match method {
                        Method::Random => (self.n, derive_seed(self.seed, 2 * cell)),
                        Method::Hero => (self.n, derive_seed(self.seed, 2 * cell + 1)),
                        _ => (self.m, 0),
                    };
                    let xyz = method.xyz(light.spectrum, surface.spectrum, samples, seed)?;
                    let samples = method.reported_samples(samples);
                    rows.push(Row { light: light.name, surface: surface.name, method, samples, xyz });
                }
                cell += 1;
            }
        }
        Ok(rows)
    }
}
