//! Exact variances of one-sample estimates, for checking the estimators'
//! spread against theory.
//!
//! With `f = L·R·c̄` (per channel) and λ uniform on the range of width W, one
//! random sample `W·f(λ)` has variance `W·∫f² − (∫f)²`. One hero sample of
//! K wavelengths is `(W/K)·g(λ₀)` with `g(λ) = Σⱼ f(λ + jW/K)` (wrapped), and
//! since `g` has period `W/K` its second moment is `(W/K)·∫ g²` over one
//! period. Each integral is exact: between breaks `g²` is a polynomial of
//! degree ≤ 14, and 8-point Gauss–Legendre is exact to degree 15.
//!
//! ```
//! use speclab::{data, study::variance};
//! let one = variance::hero::<1>(&data::D65, &data::A1);
//! let four = variance::hero::<4>(&data::D65, &data::A1);
//! assert!(four.y < one.y / 4.0); // hero beats four independent wavelengths
//! ```

use crate::sampling::quadrature::{self, GAUSS_8};
use crate::sampling::reference;
use crate::spectrum::observer;
use crate::{LAMBDA_MIN, TabulatedSpectrum, WIDTH, Xyz};

/// Per-channel variance of one `HeroSample<K>` estimate of `light × surface`
/// (K = 1: one uniformly random wavelength).
#[must_use]
pub fn hero<const K: usize>(light: &TabulatedSpectrum, surface: &TabulatedSpectrum) -> Xyz {
    let period = WIDTH / K as f64;
    let g = |lambda: f64| {
        let mut sum = Xyz::ZERO;
        for j in 0..K {
            let mut x = lambda + j as f64 * period;
            if x > LAMBDA_MIN + WIDTH {
                x -= WIDTH;
            }
            sum += observer::xyz_bar(x) * (light.eval(x) * surface.eval(x));
        }
        sum
    };
    // Breaks of every factor, folded into the first period.
    let pieces = quadrature::pieces(
        [light, surface]
            .into_iter()
            .chain(observer::CMFS)
            .flat_map(|s| s.breaks().iter().copied())
            .filter(|b| (LAMBDA_MIN..=LAMBDA_MIN + WIDTH).contains(b))
            .map(|b| LAMBDA_MIN + (b - LAMBDA_MIN) % period)
            .chain([LAMBDA_MIN, LAMBDA_MIN + period]),
    );
    let [x2, y2, z2] = quadrature::integrate(&GAUSS_8, &pieces, |x| {
        let v = g(x);
        [v.x * v.x, v.y * v.y, v.z * v.z]
    });
    let second = Xyz::new(x2, y2, z2);
    let mean = reference::xyz(light, surface);
    let m2 = second * period;
    Xyz::new(m2.x - mean.x * mean.x, m2.y - mean.y * mean.y, m2.z - mean.z * mean.z)
}
