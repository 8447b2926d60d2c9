//! Dense tables: any spectrum resampled at a fixed step over 380–730 nm
//! (1 nm by default), for evaluation in one lookup, as renderers do
//! (pbrt-v4's `DenselySampledSpectrum`).
//!
//! A [`DenseSpectrum`] keeps, per step, the value at its start and the slope
//! to the next: evaluation is one segment index, one 16-byte load and one
//! multiply-add: the line through the source's values at the steps. Outside
//! 380–730 nm it is zero. [`DenseObserver`] is the same for x̄, ȳ, z̄
//! together (one 48-byte row per step), for `HeroSample::to_xyz_with`.
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

use crate::error::Error;
use crate::spectrum::generic::{Pieces, Spectrum};
use crate::spectrum::lookup::UniformLookup;
use crate::spectrum::observer::{self, Observer};
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH};

/// A spectrum resampled at a fixed step over 380–730 nm: one lookup per
/// wavelength.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseSpectrum {
    lookup: UniformLookup,
    /// The knots, nm: 380, 380 + h, …, 730.
    knots: Vec<f64>,
    /// Per step: the value at its start and the slope to the next knot.
    lines: Vec<[f64; 2]>,
}

/// The smallest step [`DenseSpectrum::with_step`] takes, nm.
pub const MIN_STEP: f64 = 0.01;

impl DenseSpectrum {
    /// `s` at every whole nanometre from 380 to 730.
    #[must_use]
    pub fn new(s: &(impl Spectrum + ?Sized)) -> Self {
        Self::build(s, 350)
    }

    /// `s` every `step` nm (finite, at least [`MIN_STEP`] and at most 350;
    /// rounded to the nearest step that divides 350 nm).
    pub fn with_step(s: &(impl Spectrum + ?Sized), step: f64) -> Result<Self, Error> {
        if !(step.is_finite() && (MIN_STEP..=LAMBDA_WIDTH).contains(&step)) {
            return Err(Error::Step { step });
        }
        Ok(Self::build(s, (LAMBDA_WIDTH / step).round().max(1.0) as usize))
    }

    fn build(s: &(impl Spectrum + ?Sized), steps: usize) -> Self {
        let h = LAMBDA_WIDTH / steps as f64;
        let knots: Vec<f64> = (0..=steps).map(|i| LAMBDA_MIN + i as f64 * h).collect();
        let mut values = vec![0.0; knots.len()];
        s.eval_many(&knots, &mut values);
        let lines =
            values.windows(2).zip(knots.windows(2)).map(|(v, k)| [v[0], (v[1] - v[0]) / (k[1] - k[0])]);
        let lookup = UniformLookup::regular(LAMBDA_MIN, h, steps);
        DenseSpectrum { lookup, lines: lines.collect(), knots }
    }

    /// The step, nm.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.knots[1] - self.knots[0]
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
            let k = self.lookup.segment(l);
            let ([a, b], knot) = (self.lines[k], self.knots[k]);
            let inside = (l - LAMBDA_MIN) * (LAMBDA_MAX - l) >= 0.0;
            *v = if inside { a + b * (l - knot) } else { 0.0 };
        }
    }

    /// Lines between the knots (zero outside 380–730 nm).
    fn pieces(&self) -> Option<Pieces<'_>> {
        Some(Pieces { breaks: Cow::Borrowed(&self.knots), degree: 1 })
    }
}

/// The CIE 1931 observer resampled every nanometre from 380 to 730: x̄, ȳ,
/// z̄ and their slopes in one row per step.
#[derive(Clone, Debug, PartialEq)]
pub struct DenseObserver {
    lookup: UniformLookup,
    /// Per step: `[x̄, ȳ, z̄, x̄', ȳ', z̄']` at its start.
    rows: Vec<[f64; 6]>,
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
        let knots: Vec<f64> = (0..=350).map(|i| LAMBDA_MIN + f64::from(i)).collect();
        let at: Vec<[f64; 3]> = knots.iter().map(|&l| observer::xyz_bar(l)).collect();
        let rows = at
            .windows(2)
            .map(|w| std::array::from_fn(|i| if i < 3 { w[0][i] } else { w[1][i - 3] - w[0][i - 3] }));
        DenseObserver { lookup: UniformLookup::regular(LAMBDA_MIN, 1.0, 350), rows: rows.collect() }
    }
}

impl Observer for DenseObserver {
    #[inline(always)]
    fn xyz_bar_lanes<const K: usize>(&self, lambda: &[f64; K]) -> [[f64; 3]; K] {
        let mut out = [[0.0; 3]; K];
        for (out, &l) in out.iter_mut().zip(lambda) {
            let k = self.lookup.segment(l);
            let r = &self.rows[k];
            let t = l - (LAMBDA_MIN + k as f64);
            let inside = (l - LAMBDA_MIN) * (LAMBDA_MAX - l) >= 0.0;
            let v = [r[0] + r[3] * t, r[1] + r[4] * t, r[2] + r[5] * t];
            *out = if inside { v } else { [0.0; 3] };
        }
        out
    }
}
