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
//! use speclab::{data, variance};
//! let one = variance::hero::<1>(&data::D65, &data::A1);
//! let four = variance::hero::<4>(&data::D65, &data::A1);
//! assert!(four.y < one.y / 4.0); // hero beats four independent wavelengths
//! ```

use crate::data::{CIE_X, CIE_Y, CIE_Z};
use crate::{LAMBDA_MIN, TabulatedSpectrum, WIDTH, Xyz, observer, reference};

/// Gauss–Legendre on `[-1, 1]`, 8 points (exact to degree 15): (node, weight).
const GAUSS_8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

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
    let breaks = reference::sorted_unique(
        [light, surface, &CIE_X, &CIE_Y, &CIE_Z]
            .iter()
            .flat_map(|s| s.breaks().iter().copied())
            .filter(|b| (LAMBDA_MIN..=LAMBDA_MIN + WIDTH).contains(b))
            .map(|b| LAMBDA_MIN + (b - LAMBDA_MIN) % period)
            .chain([LAMBDA_MIN, LAMBDA_MIN + period]),
    );
    let mut second = Xyz::ZERO;
    for w in breaks.windows(2) {
        let (mid, half) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
        for (node, weight) in GAUSS_8 {
            for x in [mid - half * node, mid + half * node] {
                let v = g(x);
                second += Xyz::new(v.x * v.x, v.y * v.y, v.z * v.z) * (weight * half);
            }
        }
    }
    let mean = reference::xyz(light, surface);
    let m2 = second * period;
    Xyz::new(m2.x - mean.x * mean.x, m2.y - mean.y * mean.y, m2.z - mean.z * mean.z)
}
