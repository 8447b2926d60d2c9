//! Dense tables: any spectrum resampled every nanometre over 380–730 nm,
//! for evaluation in one lookup, as renderers do (pbrt-v4's
//! `DenselySampledSpectrum`, also 1 nm).
//!
//! A [`DenseSpectrum`] keeps, per nanometre, the value at its start and the
//! slope to the next: evaluation is one index, one 16-byte load and one
//! multiply-add: the line through the source's values at whole nanometres.
//! Outside 380–730 nm it is zero. [`DenseObserver`] is the same for x̄, ȳ,
//! z̄ together (one 48-byte row per nanometre), for
//! `HeroSample::to_xyz_with`. The grid is fixed (not a field), so when a
//! light, a surface and the observer are looked up at one wavelength, the
//! index is computed once.
//!
//! **Accuracy** (the largest |dense − source| over 380–730 nm, measured
//! every 0.01 nm, 1 nm step; `tests/dense.rs` holds these bounds): the
//! built-in lights are linear between 5 nm knots, so their dense tables
//! are the same lines (error 2e-16 of their peak: rounding); the patches
//! differ from their cubics by at most 1.9e-4 (A1 at 380.5 nm, where the
//! cubic's stencil is shifted), most by less than 8e-5 (reflectance, of
//! 1); the observer by 1.3e-4 (x̄), 9.6e-5 (ȳ) and 5.9e-4 (z̄, whose peak
//! is 1.78). Between its knots a dense table is a line: a spectrum with
//! features narrower than a step (an emission line off the whole
//! nanometres) loses their shape.
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, Spectrum};
//! use speclab::spectrum::{DenseObserver, DenseSpectrum};
//! let (light, surface) = (DenseSpectrum::new(&lights::F11), DenseSpectrum::new(&patches::H4));
//! assert!((light.eval(545.0) - lights::F11.eval(545.0)).abs() < 1e-12);
//! let observer = DenseObserver::new();
//! let h = HeroSample::<4>::new(0.3);
//! let dense = h.to_xyz_with(&observer, light.sample(&h) * surface.sample(&h));
//! let exact = h.to_xyz(lights::F11.sample(&h) * patches::H4.sample(&h));
//! assert!((dense.y - exact.y).abs() < 1e-3 * exact.y);
//! ```

use std::borrow::Cow;

use crate::spectrum::generic::{Pieces, Spectrum};
use crate::spectrum::observer::{self, Observer};
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};

/// Steps of 1 nm from 380 to 730 nm.
const STEPS: usize = 350;

/// The step of `lambda` (nm) and where in it: `k = ⌊λ − 380⌋` clamped to
/// the table (NaN and ±∞ included), `t = λ − 380 − k`, and whether λ is in
/// 380–730 nm. The grid is a constant, so that the light's, the surface's
/// and the observer's lookups at one wavelength are computed once.
#[inline(always)]
fn step_of(lambda: f64) -> (usize, f64, bool) {
    let x = lambda - LAMBDA_MIN;
    let c = if x > 0.0 { x } else { 0.0 };
    let c = if c < (STEPS - 1) as f64 { c } else { (STEPS - 1) as f64 };
    // SAFETY: c is finite and in [0, 349] (NaN compares false above).
    let k = unsafe { c.to_int_unchecked::<i32>() } as usize;
    (k, x - k as f64, (lambda - LAMBDA_MIN) * (LAMBDA_MAX - lambda) >= 0.0)
}

/// A spectrum resampled every nanometre over 380–730 nm: one lookup per
/// wavelength.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseSpectrum {
    /// Per step: the value at its start and the slope to the next knot.
    lines: Box<[[f64; 2]; STEPS]>,
}

impl DenseSpectrum {
    /// `s` at every whole nanometre from 380 to 730.
    #[must_use]
    pub fn new(s: &(impl Spectrum + ?Sized)) -> Self {
        let knots: Vec<f64> = (0..=STEPS).map(|i| LAMBDA_MIN + i as f64).collect();
        let mut values = vec![0.0; knots.len()];
        s.eval_many(&knots, &mut values);
        let lines = std::array::from_fn(|k| [values[k], values[k + 1] - values[k]]);
        DenseSpectrum { lines: Box::new(lines) }
    }
}

impl DenseSpectrum {
    /// The line of `lambda`'s step at `lambda`; zero outside the range.
    #[inline(always)]
    fn line(&self, lambda: f64) -> f64 {
        let (k, t, inside) = step_of(lambda);
        // SAFETY: k < STEPS, the array's length (`step_of`).
        let [a, b] = unsafe { *self.lines.get_unchecked(k) };
        if inside { a + b * t } else { 0.0 }
    }
}

impl Spectrum for DenseSpectrum {
    #[inline(always)]
    fn eval(&self, lambda: f64) -> f64 {
        let mut v = [0.0];
        self.eval_many(&[lambda], &mut v);
        v[0]
    }

    #[inline(always)]
    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = self.line(l);
        }
    }

    /// Lines between whole nanometres (zero outside 380–730 nm).
    fn pieces(&self) -> Option<Pieces<'_>> {
        static KNOTS: std::sync::OnceLock<Vec<f64>> = std::sync::OnceLock::new();
        let knots = KNOTS.get_or_init(|| (0..=STEPS).map(|i| LAMBDA_MIN + i as f64).collect());
        Some(Pieces { breaks: Cow::Borrowed(knots), degree: 1 })
    }
}

/// The CIE 1931 observer resampled every nanometre from 380 to 730: x̄, ȳ,
/// z̄ and their slopes in one row per step.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseObserver {
    /// Per step: `[x̄, ȳ, z̄, x̄', ȳ', z̄']` at its start.
    rows: Box<[[f64; 6]; STEPS]>,
}

impl Default for DenseObserver {
    fn default() -> Self {
        DenseObserver::new()
    }
}

impl DenseObserver {
    /// The observer at every whole nanometre, 380 to 730.
    #[must_use]
    pub fn new() -> Self {
        let at: Vec<[f64; 3]> = (0..=STEPS).map(|i| observer::xyz_bar(LAMBDA_MIN + i as f64)).collect();
        let rows = std::array::from_fn(|k| {
            let (a, b) = (at[k], at[k + 1]);
            [a[0], a[1], a[2], b[0] - a[0], b[1] - a[1], b[2] - a[2]]
        });
        DenseObserver { rows: Box::new(rows) }
    }
}

impl Observer for DenseObserver {
    #[inline(always)]
    fn xyz_bar_lanes<const K: usize>(&self, lambda: &[f64; K]) -> [[f64; 3]; K] {
        let mut out = [[0.0; 3]; K];
        for (out, &l) in out.iter_mut().zip(lambda) {
            let (k, t, inside) = step_of(l);
            // SAFETY: k < STEPS, the array's length (`step_of`).
            let r = unsafe { self.rows.get_unchecked(k) };
            let v = [r[0] + r[3] * t, r[1] + r[4] * t, r[2] + r[5] * t];
            *out = if inside { v } else { [0.0; 3] };
        }
        out
    }
}
