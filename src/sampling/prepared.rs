//! A light prepared for the exact XYZ of many reflectances: the reference
//! as a dot product with the reflectance's samples (see [`Weights`]).
//!
//! Preparing computes one weight per sample and channel for the
//! reflectances' grid (about 20 µs for a patch's 36 samples): keep the
//! prepared light, which owns (or borrows) its light, as long as the
//! light is used. Each XYZ is then exact and O(n): a
//! dot product, plus exact integration of the few segments where a
//! reflectance's clamp to [0, 1] acts. [`PreparedLight::batch`] converts a
//! slice of raw sample arrays into a slice of XYZ, without allocating per
//! spectrum; split the slices to use more threads.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::{PreparedLight, reference}};
//! let d65 = PreparedLight::for_grid(&lights::D65, patches::G4.lambda(), patches::G4.interpolation())?;
//! let fast = d65.xyz(&patches::G4);
//! let exact = reference::xyz_of_product(&[&lights::D65, &patches::G4]);
//! assert!((fast.y - exact.y).abs() <= 1e-12 * exact.y);
//! let mut out = [speclab::Xyz::ZERO; 2];
//! let samples: Vec<f64> = [patches::G4.values(), patches::A1.values()].concat();
//! d65.batch(&samples, &mut out)?;
//! assert!((out[0].y - exact.y).abs() <= 1e-12 * exact.y);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::{Error, Field, Invalid, SampleError};
use crate::spectrum::simd::slices::Sums;
use crate::spectrum::simd::spread::Spread;
use crate::spectrum::weights::{self, Weights};
use crate::spectrum::{Interpolation, Role, Spectrum, interp};
use crate::spectrum::{integrate, validate};

/// A light (of any spectrum type `L`, owned or borrowed: `&L` is a
/// spectrum too) with its exact weights for reflectances on one grid.
#[derive(Clone)]
pub struct PreparedLight<L: Spectrum> {
    light: L,
    weights: Weights,
}

impl<L: Spectrum> std::fmt::Debug for PreparedLight<L> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PreparedLight").field("grid", &self.weights.grid()).finish_non_exhaustive()
    }
}

impl<L: Spectrum> PreparedLight<L> {
    /// `light` prepared for reflectances sampled at `grid` (nm, strictly
    /// increasing) and interpolated by `interpolation`: its weights
    /// computed now (exactly for a piecewise polynomial light; about 20 µs
    /// for a patch's 36 samples).
    pub fn for_grid(light: L, grid: &[f64], interpolation: Interpolation) -> Result<Self, Error> {
        validate::validate(grid, &vec![0.0; grid.len()], Role::Reflectance, interpolation)?;
        let weights = Weights::compute(&light, grid, interpolation);
        Ok(PreparedLight { light, weights })
    }

    /// The light.
    #[must_use]
    pub fn light(&self) -> &L {
        &self.light
    }

    /// The reflectances' grid, nm.
    #[must_use]
    pub fn grid(&self) -> &[f64] {
        self.weights.grid()
    }

    /// The weights, as rows for x̄, ȳ and z̄, one per grid sample (nm):
    /// `XYZ꜀ = Σᵢ w꜀ᵢ·rᵢ` for every reflectance with samples `r` on the
    /// grid whose interpolant stays in `[0, 1]` (where it leaves it,
    /// [`PreparedLight::xyz_samples`] integrates the clamp exactly). On an
    /// equidistant grid they are the light's tristimulus weighting factors
    /// in the sense of ASTM E2022 (the Lagrange basis of the reflectance's
    /// interpolant integrated against light × observer), unnormalised and
    /// integrated exactly over the grid's span within 380–730 nm (a grid
    /// that ends short of 730 nm leaves the rest out, as the reference does
    /// for a reflectance tabulated that far).
    ///
    /// ```
    /// use speclab::{data::{lights, patches}, sampling::PreparedLight};
    /// let d65 = PreparedLight::for_grid(&lights::D65, patches::G4.lambda(), patches::G4.interpolation())?;
    /// let [_, wy, _] = d65.weights();
    /// let y: f64 = wy.iter().zip(patches::G4.values()).map(|(w, r)| w * r).sum();
    /// assert!((y - d65.xyz(&patches::G4).y).abs() <= 1e-12 * y);
    /// # Ok::<(), speclab::Error>(())
    /// ```
    #[must_use]
    pub fn weights(&self) -> &[Vec<f64>; 3] {
        self.weights.columns()
    }

    /// The samples of `surface`, if it is a reflectance interpolating
    /// samples on this light's grid, with its interpolation.
    fn samples_of<'s>(&self, surface: &'s (impl Spectrum + ?Sized)) -> Option<&'s [f64]> {
        let s = surface.samples()?;
        let fits = s.role == Role::Reflectance
            && s.interpolation == self.weights.interpolation()
            && s.lambda == self.weights.grid();
        fits.then_some(s.values)
    }

    /// True if `surface` is a reflectance on this light's grid, with its
    /// interpolation.
    #[must_use]
    pub fn fits(&self, surface: &(impl Spectrum + ?Sized)) -> bool {
        self.samples_of(surface).is_some()
    }

    /// The exact XYZ of the light times `surface`: equal to
    /// [`crate::sampling::reference::xyz`] (to rounding), in O(samples) when
    /// `surface` [fits](PreparedLight::fits), by exact integration otherwise.
    #[must_use]
    pub fn xyz(&self, surface: &(impl Spectrum + ?Sized)) -> Xyz {
        match self.samples_of(surface).map(|r| self.xyz_samples(r)) {
            Some(Ok(xyz)) => xyz,
            _ => Xyz::from(integrate::xyz_of_product(&[&self.light, &surface])),
        }
    }

    /// The exact XYZ of the light times the reflectance with samples `r` on
    /// this light's grid (each in `[0, 1]`), interpolated like the grid's.
    pub fn xyz_samples(&self, r: &[f64]) -> Result<Xyz, Error> {
        let mut out = [Xyz::ZERO];
        self.batch(r, &mut out)?;
        Ok(out[0])
    }

    /// The exact XYZ of each reflectance in `r`: consecutive runs of
    /// `grid.len()` samples, each in `[0, 1]`, one per element of `out`.
    /// Errors name the offending index in `r`. Allocates nothing per
    /// spectrum (one scratch buffer, only if some cubic overshoots [0, 1]).
    pub fn batch(&self, r: &[f64], out: &mut [Xyz]) -> Result<(), Error> {
        let n = self.weights.grid().len();
        if r.len() != out.len() * n {
            let problem = Invalid::Lengths { lambda: out.len() * n, values: r.len() };
            return Err(
                SampleError { index: r.len().min(out.len() * n), field: Field::Value, problem }.into()
            );
        }
        let mut scratch = Vec::new();
        let cubic = self.weights.interpolation() == Interpolation::Cubic;
        let margins = self.weights.margins();
        // On an equidistant grid, margins for plain second differences: the
        // middle segments' largest, and each end segment's own.
        let scale = self.weights.step().filter(|_| cubic && n >= 5).map(|h| 1.0 / (2.0 * h * h));
        let middle = scale.map(|s| s * self.weights.middle_margin());
        let w = self.weights.columns();
        let sums = Sums::detect();
        sums.each(w, r, n, |i, y, mut sum, Spread { lo, hi, second }| {
            let clear = match (scale, middle) {
                (Some(scale), Some(middle)) => {
                    let ends = end_clear(y, 0, 0, margins[0] * scale)
                        & end_clear(y, n - 2, n - 4, margins[n - 2] * scale);
                    (lo - middle * second >= 0.0) & (hi + middle * second <= 1.0) & ends
                }
                _ => !cubic && y.iter().all(|v| (0.0..=1.0).contains(v)),
            };
            // NaN anywhere makes the sum NaN.
            if !clear || sum.iter().any(|s| s.is_nan()) {
                if let Some(e) = invalid_sample(r, i * n, n) {
                    return Err(e);
                }
                if cubic {
                    self.correct_overshoots(&mut sum, y, &mut scratch);
                }
            }
            if let Some(o) = out.get_mut(i) {
                *o = Xyz::of_sums(sum);
            }
            Ok(())
        })
    }

    /// Replaces the weighted term of every segment of `y` whose cubic the
    /// clamp to `[0, 1]` acts on by its exact integral. The Bernstein hull
    /// clears almost every segment in a few operations.
    #[cold]
    #[inline(never)]
    fn correct_overshoots(&self, sum: &mut [f64; 3], y: &[f64], scratch: &mut Vec<f64>) {
        let grid = self.weights.grid();
        for (k, beta) in self.weights.hull().iter().enumerate() {
            let s = interp::stencil(k, y.len());
            let ys = [y[s], y[s + 1], y[s + 2], y[s + 3]];
            let b1 = beta[0][0] * ys[0] + beta[0][1] * ys[1] + beta[0][2] * ys[2] + beta[0][3] * ys[3];
            let b2 = beta[1][0] * ys[0] + beta[1][1] * ys[1] + beta[1][2] * ys[2] + beta[1][3] * ys[3];
            if (0.0..=1.0).contains(&b1) && (0.0..=1.0).contains(&b2) {
                continue;
            }
            let c = interp::cubic_segment(grid, y, k);
            let (_, crossings) = interp::crossings(c, [0.0, 1.0], grid[k + 1] - grid[k]);
            let mid = interp::segment_value(c, 0.5 * (grid[k + 1] - grid[k]));
            if crossings > 0 || !(0.0..=1.0).contains(&mid) {
                self.correct(sum, y, k, c, [0.0, 1.0], scratch);
            }
        }
    }

    /// `sum` with segment `k`'s weighted term replaced by its exact integral
    /// for the clamped polynomial `c`.
    fn correct(
        &self,
        sum: &mut [f64; 3],
        y: &[f64],
        k: usize,
        c: interp::Coeffs,
        bounds: [f64; 2],
        scratch: &mut Vec<f64>,
    ) {
        let (w, s) = self.weights.segment(k);
        for (j, wj) in w.iter().enumerate() {
            for ch in 0..3 {
                sum[ch] -= wj[ch] * y[s + j];
            }
        }
        let grid = self.weights.grid();
        let exact = weights::segment_exact(
            &self.light,
            [grid[k], grid[k + 1]],
            c,
            bounds,
            self.weights.range(),
            scratch,
        );
        for ch in 0..3 {
            sum[ch] += exact[ch];
        }
    }
}

/// An end segment `k` (stencil from `s`) is clear: its samples' range,
/// widened by `margin` times its stencil's larger |second difference|,
/// stays in `[0, 1]`.
#[inline(always)]
fn end_clear(y: &[f64], k: usize, s: usize, margin: f64) -> bool {
    let second = |i: usize| (y[i] - 2.0 * y[i + 1] + y[i + 2]).abs();
    let (d0, d1) = (second(s), second(s + 1));
    let e = margin * if d0 > d1 { d0 } else { d1 };
    let (lo, hi) = if y[k] < y[k + 1] { (y[k], y[k + 1]) } else { (y[k + 1], y[k]) };
    (lo - e >= 0.0) & (hi + e <= 1.0)
}

/// The error for the first sample of `r[from..from + n]` that is not a
/// number in `[0, 1]`, if there is one.
fn invalid_sample(r: &[f64], from: usize, n: usize) -> Option<Error> {
    let index = (from..from + n).find(|&i| !(0.0..=1.0).contains(&r[i]))?;
    let value = r[index];
    let problem = if value.is_finite() {
        Invalid::OutOfRange { value, min: 0.0, max: 1.0 }
    } else {
        Invalid::NonFinite { value }
    };
    Some(SampleError { index, field: Field::Value, problem }.into())
}
