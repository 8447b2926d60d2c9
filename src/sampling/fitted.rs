//! Wavelength rules fitted to a scene's lights: M wavelengths and a 3 × M
//! weight matrix, `XYZ꜀ ≈ Σᵢ w꜀ᵢ·v(λᵢ)`, where `v` is the path's spectral
//! value (light × reflectances) at `λᵢ`.
//!
//! Equidistant buckets put their M wavelengths everywhere alike, and under
//! F11 they straddle its three narrow lines. A fitted rule puts them where
//! the lights need them: Meyer's 1988 idea of choosing rendering wavelengths
//! by quadrature, fitted per scene. [`FittedRule::fit`] chooses the
//! wavelengths and weights that reproduce, by weighted least squares, the
//! exact XYZ of each light times each reflectance of a smooth prior
//! ([`super::prior`]; see `fit.rs` for the weighting, the anchors and the
//! search). The weights apply to the product, so one rule serves every
//! intensity of its lights and every path through the scene.
//!
//! The rule reproduces the perfect white under each of its lights, and the
//! prior's mean reflectance, to [`ANCHOR_TOLERANCE`] (relative). In a
//! release build a fit takes about 85 ms the first time in a process (the
//! prior's moments, computed once) and 10–20 ms after, for M ≤ 16 and one
//! to three lights; it is deterministic.
//!
//! A renderer evaluates its spectra at the rule's wavelengths, as a
//! `SampledSpectrum<M>` through [`FittedWavelengths<M>`], and converts with
//! the weights: no allocation per sample.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{fitted::FittedRule, reference};
//! use speclab::{SampledSpectrum, Spectrum};
//! let rule = FittedRule::fit(&[&lights::F11], 10)?;
//! let at = rule.wavelengths::<10>()?;
//! let (le, albedo) = (lights::F11.sample(&at), patches::G4.sample(&at));
//! let fitted = at.to_xyz(le * albedo);
//! let exact = reference::xyz(&lights::F11, &patches::G4);
//! assert!((fitted.y - exact.y).abs() < 0.01 * exact.y);
//! assert!(FittedRule::fit(&[&lights::F11], 0).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::Error;
use crate::sampling::fit::{CANDIDATES, Problem};
use crate::spectrum::{LAMBDA_MIN, SampledSpectrum, Spectrum, Wavelengths};

/// The most wavelengths a rule takes.
pub const MAX_NODES: usize = 64;

/// How closely a rule reproduces the XYZ of the perfect white under each of
/// its lights and of the prior's mean reflectance, relative (tested).
pub const ANCHOR_TOLERANCE: f64 = 1e-3;

/// The part of a fit that depends on the lights alone (the normal
/// equations over the prior): build it once to fit several M.
pub struct FitProblem(Problem);

impl std::fmt::Debug for FitProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FitProblem").finish_non_exhaustive()
    }
}

impl FitProblem {
    /// The problem for `lights`; an [`Error::DarkLight`] as in
    /// [`FittedRule::fit`].
    pub fn new(lights: &[&dyn Spectrum]) -> Result<Self, Error> {
        Problem::new(lights).map(FitProblem)
    }

    /// The rule of `m` wavelengths, `m` clamped into 1 ..= [`MAX_NODES`].
    #[must_use]
    pub fn rule(&self, m: usize) -> FittedRule {
        let (nodes, w) = self.0.fit(m.clamp(1, MAX_NODES));
        let lambda = nodes.iter().map(|&j| LAMBDA_MIN + j as f64).collect();
        let weights = (0..nodes.len()).map(|i| [w[0][i], w[1][i], w[2][i]]).collect();
        FittedRule { lambda, weights }
    }
}

/// M wavelengths and their XYZ weights, fitted to a set of lights.
#[derive(Clone, Debug, PartialEq)]
pub struct FittedRule {
    lambda: Vec<f64>,
    weights: Vec<[f64; 3]>,
}

impl FittedRule {
    /// The rule of `m` wavelengths for `lights` (one to a few; the scene's).
    /// An [`Error::NodeCount`] unless `1 ≤ m ≤` [`MAX_NODES`]; an
    /// [`Error::DarkLight`] for no lights or one whose white is not
    /// positive in X, Y and Z.
    pub fn fit(lights: &[&dyn Spectrum], m: usize) -> Result<Self, Error> {
        if !(1..=MAX_NODES.min(CANDIDATES)).contains(&m) {
            return Err(Error::NodeCount { m, max: MAX_NODES });
        }
        Ok(FitProblem::new(lights)?.rule(m))
    }

    /// The number of wavelengths, M.
    #[must_use]
    pub fn m(&self) -> usize {
        self.lambda.len()
    }

    /// The wavelengths, nm, increasing.
    #[must_use]
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }

    /// Per wavelength, its `[X, Y, Z]` weights, nm.
    #[must_use]
    pub fn weights(&self) -> &[[f64; 3]] {
        &self.weights
    }

    /// `Σᵢ wᵢ·vᵢ` for the values `v` at the rule's wavelengths (missing
    /// values count as 0, extra ones are ignored).
    #[must_use]
    pub fn xyz_of_values(&self, values: &[f64]) -> Xyz {
        weighted_sum(&self.weights, values)
    }

    /// `s` at the rule's wavelengths, into `out` (as many as the shorter
    /// has): what a renderer stores per spectrum.
    pub fn values_into(&self, s: &(impl Spectrum + ?Sized), out: &mut [f64]) {
        for (v, &l) in out.iter_mut().zip(&self.lambda) {
            *v = s.eval(l);
        }
    }

    /// The XYZ of the point-wise product of `factors`, each the values of a
    /// spectrum at the rule's wavelengths ([`FittedRule::values_into`]), as
    /// `Buckets::xyz_of_product` for buckets. Missing values count as 0. No
    /// allocation.
    #[must_use]
    pub fn xyz_of_factors(&self, factors: &[&[f64]]) -> Xyz {
        let mut product = [0.0; MAX_NODES];
        let product = &mut product[..self.m()];
        product.fill(1.0);
        for f in factors {
            let (known, missing) = product.split_at_mut(f.len().min(product.len()));
            known.iter_mut().zip(*f).for_each(|(p, v)| *p *= v);
            missing.fill(0.0);
        }
        self.xyz_of_values(product)
    }

    /// The XYZ of the product of `factors` (a light and a path's
    /// reflectances), evaluated at the rule's wavelengths. No allocation.
    #[must_use]
    pub fn xyz_of_product(&self, factors: &[&dyn Spectrum]) -> Xyz {
        let mut values = [0.0; MAX_NODES];
        for (v, &l) in values.iter_mut().zip(&self.lambda) {
            *v = factors.iter().map(|f| f.eval(l)).product();
        }
        self.xyz_of_values(&values[..self.m()])
    }

    /// The rule as a `Copy` value of compile-time size M, for a renderer's
    /// inner loop; an [`Error::RuleSize`] unless `M` is the rule's M.
    pub fn wavelengths<const M: usize>(&self) -> Result<FittedWavelengths<M>, Error> {
        if M != self.m() {
            return Err(Error::RuleSize { rule: self.m(), asked: M });
        }
        Ok(FittedWavelengths {
            lambda: std::array::from_fn(|i| self.lambda[i]),
            weights: std::array::from_fn(|i| self.weights[i]),
        })
    }
}

/// A fitted rule of M wavelengths as a `Copy` value: spectra sample at it
/// (`spectrum.sample(&at)`) and [`FittedWavelengths::to_xyz`] converts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FittedWavelengths<const M: usize> {
    lambda: [f64; M],
    weights: [[f64; 3]; M],
}

impl<const M: usize> Wavelengths<M> for FittedWavelengths<M> {
    #[inline]
    fn lambda(&self) -> &[f64; M] {
        &self.lambda
    }
}

impl<const M: usize> FittedWavelengths<M> {
    /// `Σᵢ wᵢ·vᵢ`: the XYZ of a spectrum with values `v` at the rule's
    /// wavelengths.
    #[inline]
    #[must_use]
    pub fn to_xyz(&self, v: SampledSpectrum<M>) -> Xyz {
        weighted_sum(&self.weights, &v.values)
    }
}

/// `Σᵢ wᵢ·vᵢ` per channel, in four interleaved partial sums (the additions
/// do not wait on each other); missing values count as 0.
#[inline]
fn weighted_sum(weights: &[[f64; 3]], values: &[f64]) -> Xyz {
    let mut acc = [[0.0; 3]; 4];
    for (i, (w, v)) in weights.iter().zip(values).enumerate() {
        let a = &mut acc[i % 4];
        *a = [a[0] + w[0] * v, a[1] + w[1] * v, a[2] + w[2] * v];
    }
    let sum = std::array::from_fn(|c| (acc[0][c] + acc[2][c]) + (acc[1][c] + acc[3][c]));
    Xyz::from(sum)
}
