//! The comparison grid: every light × surface by every method.
//!
//! This is the computation behind `examples/grid.rs`, kept in the library so
//! that tests and other programs get the same numbers. Paths may be deeper
//! than one bounce ([`GridOptions::depth`]): every method, the reference
//! included, then works on light × surface^depth. Cell `c` (in row-major
//! order over lights, then surfaces) draws its random methods from
//! `derive_seed(seed, 2c)` (random) and `derive_seed(seed, 2c + 1)` (hero).
//!
//! ```
//! use speclab_study::experiments::grid::GridOptions;
//! use speclab_study::evaluate::scene::{builtin_lights, builtin_surfaces};
//! let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
//! let rows = GridOptions::default().rows(&lights, &surfaces)?;
//! assert_eq!(rows.len(), 18 * 6);
//! assert_eq!(rows[5].light.name, "A");
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::{Method, derive_seed};
use crate::evaluate::scene::{Depth, Named};
use crate::sampling::choice::Sampling;
use speclab::color::Xyz;

/// What a grid run computes: its counts, seed and sampling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridOptions {
    /// Samples n for random and hero.
    pub n: NonZeroUsize,
    /// Buckets M for the regular methods, and wavelengths of the fitted rule.
    pub m: NonZeroUsize,
    /// Base seed.
    pub seed: u64,
    /// The random and hero methods' pdf and strata.
    pub sampling: Sampling,
    /// Surfaces per path (1: light × surface).
    pub depth: Depth,
}

impl Default for GridOptions {
    /// n = 100, M = 16, seed 1, uniform and independent wavelengths, depth 1.
    fn default() -> Self {
        GridOptions {
            n: NonZeroUsize::new(100).unwrap_or(NonZeroUsize::MIN),
            m: NonZeroUsize::new(16).unwrap_or(NonZeroUsize::MIN),
            seed: 1,
            sampling: Sampling::DEFAULT,
            depth: Depth::ONE,
        }
    }
}

/// One cell of the grid under one method.
#[derive(Clone, Debug, PartialEq)]
pub struct GridRow<'a> {
    /// The light.
    pub light: &'a Named,
    /// The surface.
    pub surface: &'a Named,
    /// The method.
    pub method: Method,
    /// n, M, or 0 for the reference.
    pub samples: usize,
    /// The result.
    pub xyz: Xyz,
}

impl GridOptions {
    /// All rows: for each light, each surface, each method in
    /// [`Method::ALL`] (random and hero drawing as [`GridOptions::sampling`] says).
    pub fn rows<'a>(
        &self,
        lights: &'a [Named],
        surfaces: &'a [Named],
    ) -> Result<Vec<GridRow<'a>>, StudyError> {
        self.rows_of(lights, surfaces, &Method::ALL)
    }

    /// [`GridOptions::rows`] for `methods` (a method's seed stream is its
    /// cell's, as in [`Method::ALL`]; the fixed ones take M).
    pub fn rows_of<'a>(
        &self,
        lights: &'a [Named],
        surfaces: &'a [Named],
        methods: &[Method],
    ) -> Result<Vec<GridRow<'a>>, StudyError> {
        let mut rows = Vec::with_capacity(lights.len() * surfaces.len() * methods.len());
        let methods: Vec<Method> = methods.iter().map(|m| m.with_sampling(self.sampling)).collect();
        let mut cell = 0u64;
        for light in lights {
            let prepared: Vec<_> = methods
                .iter()
                .map(|m| m.prepare(light).map(|p| p.at_depth(self.depth)))
                .collect::<Result<_, _>>()?;
            for surface in surfaces {
                for (&method, prepared) in methods.iter().zip(&prepared) {
                    let (samples, seed) = match method {
                        Method::Hero { k: 1, .. } => (self.n, derive_seed(self.seed, 2 * cell)),
                        Method::Hero { .. } => (self.n, derive_seed(self.seed, 2 * cell + 1)),
                        _ => (self.m, 0),
                    };
                    let xyz = prepared.xyz(&surface.spectrum, samples, seed)?;
                    let samples = method.reported_samples(samples);
                    rows.push(GridRow { light, surface, method, samples, xyz });
                }
                cell += 1;
            }
        }
        Ok(rows)
    }
}
