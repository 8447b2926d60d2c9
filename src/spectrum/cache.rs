//! What a spectrum keeps of the work done on it: a [`Cache`], the one
//! place a light's precomputed data lives.
//!
//! Used as a light, a spectrum's exact reference weights for reflectances
//! on a grid (see `weights.rs` and `sampling::PreparedLight`) take about
//! 20 µs to compute and make every later exact XYZ a dot product; its
//! wavelength pdfs (`sampling::choice`) are tabulated in about 7 µs; the
//! normal equations of its fitted rules (`sampling::fitted`) take tens of
//! milliseconds. A spectrum that holds a `Cache` and returns it from
//! [`Spectrum::cache`](super::Spectrum::cache) keeps each of them, computed
//! on first use: tables do, and so can a renderer's own light type. A
//! cache is part of no spectrum's value: a clone starts empty, and
//! equality ignores it.
//!
//! ```
//! use speclab::spectrum::{Cache, FnSpectrum, Spectrum};
//! use speclab::{data::patches, sampling::reference};
//! struct Lamp(Cache); // a renderer's light, keeping its weights
//! impl Spectrum for Lamp {
//!     fn eval(&self, lambda: f64) -> f64 { if lambda < 600.0 { 1.0 } else { 2.0 } }
//!     fn pieces(&self) -> Option<speclab::spectrum::Pieces<'_>> {
//!         Some(speclab::spectrum::Pieces { breaks: vec![600.0].into(), degree: 0 })
//!     }
//!     fn cache(&self) -> Option<&Cache> { Some(&self.0) }
//! }
//! let lamp = Lamp(Cache::default());
//! let fast = reference::xyz(&lamp, &patches::G4); // computes and keeps the weights
//! let slow = reference::xyz_of_product(&[&lamp, &patches::G4]);
//! assert!((fast.y - slow.y).abs() < 1e-12 * slow.y);
//! ```

use std::any::{Any, TypeId};
use std::sync::{Arc, Mutex, OnceLock};

use crate::spectrum::validate::Interpolation;

/// Where a spectrum keeps what is computed from it once.
#[derive(Default)]
pub struct Cache {
    weights: OnceLock<Weights>,
    /// What the floors above keep, by type and key.
    derived: Mutex<Vec<Derived>>,
}

/// One value kept for a floor above: its type, a key, the value.
type Derived = (TypeId, u64, Arc<dyn Any + Send + Sync>);

impl Clone for Cache {
    /// An empty cache: what is kept belongs to the value that computed it.
    fn clone(&self) -> Self {
        Cache::default()
    }
}

impl PartialEq for Cache {
    /// Always equal: a cache is not part of a spectrum's value.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for Cache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let derived = self.derived.lock().map_or(0, |d| d.len());
        f.debug_struct("Cache")
            .field("weights", &self.weights.get().map(|w| w.grid().len()))
            .field("derived", &derived)
            .finish()
    }
}

impl Cache {
    /// An empty cache (also `Cache::default()`).
    #[must_use]
    pub const fn new() -> Cache {
        Cache { weights: OnceLock::new(), derived: Mutex::new(Vec::new()) }
    }

    /// The value of type `T` kept under `key`, or `make`'s, kept now (an
    /// error from `make` is returned and nothing kept). `make` runs outside
    /// the lock; if two threads race, the first value kept wins.
    pub(crate) fn derived<T: Any + Send + Sync, E>(
        &self,
        key: u64,
        make: impl FnOnce() -> Result<T, E>,
    ) -> Result<Arc<T>, E> {
        let id = TypeId::of::<T>();
        let find = |d: &[Derived]| {
            d.iter()
                .find(|(t, k, _)| *t == id && *k == key)
                .and_then(|(_, _, v)| Arc::clone(v).downcast::<T>().ok())
        };
        if let Some(kept) = self.derived.lock().ok().and_then(|d| find(&d)) {
            return Ok(kept);
        }
        let made = Arc::new(make()?);
        let Ok(mut derived) = self.derived.lock() else { return Ok(made) };
        if let Some(kept) = find(&derived) {
            return Ok(kept);
        }
        derived.push((id, key, Arc::clone(&made) as Arc<dyn Any + Send + Sync>));
        Ok(made)
    }

    /// The kept weights, computing them with `compute` if none are kept.
    pub(crate) fn weights(&self, compute: impl FnOnce() -> Weights) -> &Weights {
        self.weights.get_or_init(compute)
    }
}

/// Exact weights of one light for reflectances on one grid.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Weights {
    /// The reflectances' wavelengths, nm.
    pub(crate) grid: Vec<f64>,
    /// The reflectances' interpolation.
    pub(crate) cubic: bool,
    /// The integration range: 380–730 nm ∩ the light's and the grid's support.
    pub(crate) range: [f64; 2],
    /// Per sample, per channel.
    pub(crate) samples: Vec<[f64; 3]>,
    /// Per segment, per stencil sample (4; linear uses 2), per channel.
    pub(crate) segments: Vec<[[f64; 3]; 4]>,
    /// Per segment: the stencil vectors giving the cubic's inner Bernstein
    /// coefficients b₁ and b₂ (b₀ and b₃ are the segment's samples).
    pub(crate) hull: Vec<[[f64; 4]; 2]>,
    /// Per segment: the |coefficient sum| turning the stencil's two second
    /// divided differences into a bound on the inner Bernstein coefficients'
    /// distance from the linear interpolation (0 for linear grids).
    pub(crate) margins: Vec<f64>,
    /// The grid's step if it is equidistant ([`Weights::step`]), found once.
    pub(crate) step: Option<f64>,
    /// The largest margin of the middle segments (all but the first and the
    /// last), found once.
    pub(crate) middle_margin: f64,
}

impl Weights {
    /// True if these are the weights for reflectances on `grid`
    /// interpolated by `interpolation`.
    pub(crate) fn fits(&self, grid: &[f64], interpolation: Interpolation) -> bool {
        self.grid == grid && self.interpolation() == interpolation
    }

    /// The reflectances' wavelengths, nm.
    #[must_use]
    pub(crate) fn grid(&self) -> &[f64] {
        &self.grid
    }

    /// The reflectances' interpolation.
    #[must_use]
    pub(crate) fn interpolation(&self) -> Interpolation {
        if self.cubic { Interpolation::Cubic } else { Interpolation::Linear }
    }

    /// The integration range, nm.
    pub(crate) fn range(&self) -> [f64; 2] {
        self.range
    }

    /// One weight per sample and channel.
    pub(crate) fn samples(&self) -> &[[f64; 3]] {
        &self.samples
    }

    /// Segment `k`'s weights per stencil sample, and where its stencil starts.
    pub(crate) fn segment(&self, k: usize) -> (&[[f64; 3]], usize) {
        let (s, width) = stencil(self.cubic, k, self.grid.len());
        (&self.segments[k][..width], s)
    }

    /// Segment `k`'s Bernstein stencil vectors (cubic grids).
    pub(crate) fn hull(&self) -> &[[[f64; 4]; 2]] {
        &self.hull
    }

    /// Per segment, the margin `Cₖ` of `min(yₖ, yₖ₊₁) − Cₖ·S ≥ 0`, with S
    /// the larger |second divided difference| of the segment's stencil.
    pub(crate) fn margins(&self) -> &[f64] {
        &self.margins
    }

    /// The largest of [`Weights::margins`] but the first and the last (0
    /// for fewer than three segments).
    pub(crate) fn middle_margin(&self) -> f64 {
        self.middle_margin
    }

    /// For an equidistant grid of step h, the step (margins divided by
    /// `2h²` apply to plain second differences `y₀ − 2y₁ + y₂`, which are
    /// `2h²·[x₀, x₁, x₂]y`). `None` for other grids.
    pub(crate) fn step(&self) -> Option<f64> {
        self.step
    }
}

/// The step of `grid` (two samples at least) if its samples are equally
/// spaced (to 1e-9 of the step), else `None`.
pub(crate) fn equidistant_step(grid: &[f64]) -> Option<f64> {
    let h = (grid[grid.len() - 1] - grid[0]) / (grid.len() - 1) as f64;
    grid.windows(2).all(|w| ((w[1] - w[0]) - h).abs() <= 1e-9 * h).then_some(h)
}

/// The stencil of segment `k` of `n` samples: first sample and width.
pub(crate) fn stencil(cubic: bool, k: usize, n: usize) -> (usize, usize) {
    if cubic { (speclab_tables::interp::stencil(k, n), 4) } else { (k, 2) }
}

#[cfg(test)]
mod tests {
    use super::equidistant_step;

    /// The step of an equally spaced grid, to 1e-9 of it; `None` for any
    /// other grid.
    #[test]
    fn the_step_of_an_equidistant_grid() {
        let grid = |h: f64, n: usize| (0..n).map(|i| 380.0 + h * i as f64).collect::<Vec<f64>>();
        assert_eq!(equidistant_step(&grid(10.0, 36)), Some(10.0));
        assert_eq!(equidistant_step(&grid(0.5, 701)), Some(0.5));
        assert_eq!(equidistant_step(&[400.0, 700.0]), Some(300.0));
        let mut uneven = grid(10.0, 36);
        uneven[17] += 1e-9; // 1e-10 of the step: within the tolerance
        assert_eq!(equidistant_step(&uneven).map(|h| (h - 10.0).abs() < 1e-12), Some(true));
        uneven[17] += 1e-6; // 1e-7 of the step: not equidistant
        assert_eq!(equidistant_step(&uneven), None);
        assert_eq!(equidistant_step(&[380.0, 390.0, 410.0]), None);
    }

    /// A light's weights keep their grid's step and the largest middle
    /// margin.
    #[test]
    fn weights_keep_the_step_and_the_middle_margin() {
        use crate::spectrum::{Interpolation, data::lights};
        let grid: Vec<f64> = (0..36).map(|i| 380.0 + 10.0 * f64::from(i)).collect();
        let w = super::Weights::compute(&lights::A, &grid, Interpolation::Cubic);
        assert_eq!(w.step(), Some(10.0));
        let m = w.margins();
        assert_eq!(w.middle_margin(), m[1..m.len() - 1].iter().fold(0.0, |a: f64, &b| a.max(b)));
        assert!(w.middle_margin() > 0.0 && m.len() == 35);
        let uneven = [380.0, 400.0, 450.0, 600.0, 730.0];
        assert_eq!(super::Weights::compute(&lights::A, &uneven, Interpolation::Cubic).step(), None);
    }
}
