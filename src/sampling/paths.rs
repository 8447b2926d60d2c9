//! The exact colour of many paths through one scene: [`ExactPaths`].
//!
//! A path of a path tracer that meets surfaces R₁ … R_k and, at some of
//! them, sees a light L (by next-event estimation or directly) carries
//! `Σⱼ cⱼ · L·R₁⋯Rⱼ` over wavelength, with scalar factors cⱼ (geometry,
//! Russian roulette; c₀ for the light seen directly). Its exact XYZ is
//! `∫ L·(c₀ + R₁·(c₁ + R₂·(c₂ + …)))·c̄ dλ` over 380–730 nm. Between the
//! breaks of every spectrum of the scene and of the observer, that
//! integrand is one polynomial of known degree, so one Gauss–Legendre rule
//! per piece integrates it exactly; the spectra are evaluated at the rule's
//! nodes once, and each path is then a sum over the nodes, with no
//! allocation: a renderer's ground truth, path by path, with the same
//! random numbers as its estimate.
//!
//! Exact (to rounding) for piecewise polynomial spectra and paths of up to
//! the `max_depth` given (a rule of at most 32 points per piece: degree 63);
//! spectra that are not polynomial (sigmoid textures, blackbodies) are
//! integrated by quadrature on pieces of at most 5 nm, within about 1e-12.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::reference::{self, ExactPaths};
//! let scene = ExactPaths::new(&[&lights::F11, &patches::G4, &patches::A1], 4);
//! // F11 seen directly (c₀ = 1), then off G4 (c₁ = 0.5) and G4·A1 (c₂ = 0.25).
//! let xyz = scene.xyz(0, &[1, 2], &[1.0, 0.5, 0.25])?;
//! let by_parts = reference::white(&lights::F11)
//!     + reference::xyz(&lights::F11, &patches::G4) * 0.5
//!     + reference::xyz_of_product(&[&lights::F11, &patches::G4, &patches::A1]) * 0.25;
//! assert!((xyz.y - by_parts.y).abs() < 1e-12 * by_parts.y);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::Error;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, Spectrum, integrate, observer, quadrature};

/// A scene's spectra at the nodes of a quadrature exact for its paths.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactPaths {
    /// Per node: its quadrature weight times x̄, ȳ, z̄ there (three rows).
    weights: [Vec<f64>; 3],
    /// Per spectrum of the scene, its value at every node.
    values: Vec<Vec<f64>>,
}

impl ExactPaths {
    /// The scene of `spectra` (lights and surfaces; a path names them by
    /// their place in this list), exact for paths of up to `max_depth`
    /// surfaces (any `max_depth` is taken: past the degree the largest
    /// Gauss rule integrates exactly, that rule).
    #[must_use]
    pub fn new(spectra: &[&dyn Spectrum], max_depth: usize) -> Self {
        let mut breaks: Vec<f64> = observer::CMFS.iter().flat_map(|c| c.breaks().iter().copied()).collect();
        let (mut degree, mut smooth) = (0, false);
        for s in spectra {
            match s.pieces() {
                Some(p) => {
                    breaks.extend(p.breaks.iter().copied());
                    degree = degree.max(p.degree);
                }
                None => smooth = true,
            }
        }
        let inside = breaks.into_iter().filter(|&x| x > LAMBDA_MIN && x < LAMBDA_MAX);
        let pieces = quadrature::pieces(inside.chain([LAMBDA_MIN, LAMBDA_MAX]));
        let extra = if smooth { integrate::SMOOTH_EXTRA } else { 0 };
        // Saturating: past the largest rule's degree, the largest rule.
        let rule = quadrature::for_degree(
            degree.saturating_mul(max_depth.saturating_add(1)).saturating_add(3 + extra),
        );
        let mut nodes = Vec::with_capacity(rule.len() * pieces.len());
        let mut weights = [Vec::new(), Vec::new(), Vec::new()];
        for w in pieces.windows(2) {
            let (half, middle) = (0.5 * (w[1] - w[0]), 0.5 * (w[1] + w[0]));
            for &(x, wt) in rule {
                let lambda = middle + half * x;
                let cmf = observer::xyz_bar(lambda);
                nodes.push(lambda);
                (0..3).for_each(|c| weights[c].push(half * wt * cmf[c]));
            }
        }
        let values = spectra
            .iter()
            .map(|s| {
                let mut v = vec![0.0; nodes.len()];
                s.eval_many(&nodes, &mut v);
                v
            })
            .collect();
        ExactPaths { weights, values }
    }

    /// The number of nodes each path is summed over.
    #[must_use]
    pub fn nodes(&self) -> usize {
        self.weights[0].len()
    }

    /// The exact XYZ of a path: `Σⱼ cⱼ ∫ L·R₁⋯Rⱼ·c̄` with `L` the scene's
    /// spectrum `light`, `Rᵢ` its spectrum `surfaces[i − 1]` and `cⱼ =
    /// coefficients[j]` (`c₀`: the light alone; a missing coefficient is 0,
    /// one beyond the surfaces ignored). An [`Error::Count`] for an index
    /// outside the scene.
    pub fn xyz(&self, light: usize, surfaces: &[usize], coefficients: &[f64]) -> Result<Xyz, Error> {
        let n = self.values.len();
        let outside = std::iter::once(&light).chain(surfaces).find(|&&i| i >= n);
        if let Some(&found) = outside {
            return Err(Error::Count {
                what: "a spectrum of the scene",
                found,
                min: 0,
                max: n.saturating_sub(1),
            });
        }
        let depth = surfaces.len().min(coefficients.len().saturating_sub(1));
        let mut sum = [0.0; 3];
        for (q, &l) in self.values[light].iter().enumerate() {
            // c₀ + R₁·(c₁ + R₂·(c₂ + …)), from the deepest surface out.
            let mut t = coefficients.get(depth).copied().unwrap_or(0.0);
            for j in (0..depth).rev() {
                t = coefficients[j] + self.values[surfaces[j]][q] * t;
            }
            let v = l * t;
            (0..3).for_each(|c| sum[c] += self.weights[c][q] * v);
        }
        Ok(Xyz::of_sums(sum))
    }
}
