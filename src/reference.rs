//! The exact reference: XYZ of light × surface by exact integration.
//!
//! Between two consecutive *breaks* (sample wavelengths of any factor, plus
//! the points where an interpolant meets its clamp bound) every factor is a
//! polynomial of degree ≤ 3, so the product with a matching function has
//! degree ≤ 9 and 5-point Gauss–Legendre on each piece is exact up to
//! rounding. All arithmetic is f64. This reproduces Appendix 2 (see
//! `tests/appendix2.rs`).
//!
//! The range is the common support of the factors and the matching
//! functions: 380–730 nm for the appendix data.
//!
//! ```
//! use speclab::{data, reference};
//! let rgb = reference::xyz(&data::D65, &data::A1).to_linear_srgb();
//! assert!((rgb.g - 82.44).abs() < 0.05); // Appendix 2: 80.79, 82.44, 80.84
//! ```

use crate::data::{CIE_X, CIE_Y, CIE_Z};
use crate::{TabulatedSpectrum, Xyz, observer};

/// Gauss–Legendre nodes and weights on `[-1, 1]`, 5 points (exact to degree 9).
const GAUSS_5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// XYZ of `light × surface` over their common support with the observer.
#[must_use]
pub fn xyz(light: &TabulatedSpectrum, surface: &TabulatedSpectrum) -> Xyz {
    xyz_of_product(&[light, surface])
}

/// XYZ of the perfect white (reflectance 1) under `light`.
#[must_use]
pub fn white(light: &TabulatedSpectrum) -> Xyz {
    xyz_of_product(&[light])
}

/// XYZ of the product of `factors`, over their common support with x̄ȳz̄.
#[must_use]
pub fn xyz_of_product(factors: &[&TabulatedSpectrum]) -> Xyz {
    let cmfs = [&CIE_X, &CIE_Y, &CIE_Z];
    let all = || factors.iter().copied().chain(cmfs);
    let a = all().map(|s| s.support().0).fold(f64::NEG_INFINITY, f64::max);
    let b = all().map(|s| s.support().1).fold(f64::INFINITY, f64::min);
    if a >= b || a.is_nan() || b.is_nan() {
        return Xyz::ZERO;
    }
    let breaks = sorted_unique(
        all().flat_map(|s| s.breaks().iter().copied()).filter(|&x| x > a && x < b).chain([a, b]),
    );
    let mut sum = Xyz::ZERO;
    for w in breaks.windows(2) {
        let (mid, half) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
        for (node, weight) in GAUSS_5 {
            let lambda = mid + half * node;
            let f: f64 = factors.iter().map(|s| s.eval(lambda)).product();
            sum += observer::xyz_bar(lambda) * (f * weight * half);
        }
    }
    sum
}

/// `points` sorted, without repeats: the ends of the pieces to integrate.
pub(crate) fn sorted_unique(points: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = points.collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}
