//! The exact reference: XYZ of light × surface by exact integration.
//!
//! Between two consecutive breaks every factor is a polynomial of degree
//! ≤ 3, so the product with a matching function has degree ≤ 9 and 5-point
//! Gauss–Legendre on each piece is exact up to rounding. All arithmetic is
//! f64. This reproduces Appendix 2 (see `tests/appendix2.rs`).
//!
//! **One range for everything**: the integrals run over 380–730 nm (W =
//! 350 nm), intersected with the factors' supports. The perfect white
//! ([`white`]) uses the same range as every colour, even for lights
//! tabulated to 780 nm, so a white patch of reflectance 1 has exactly the
//! white's XYZ, and every sampler (which draws within 380–730 nm) is
//! unbiased for both.
//!
//! ```
//! use speclab::{data, sampling::reference};
//! let rgb = reference::xyz(&data::D65, &data::A1).to_linear_srgb();
//! assert!((rgb.g - 82.44).abs() < 0.05); // Appendix 2: 80.79, 82.44, 80.84
//! ```

use crate::sampling::quadrature::{self, GAUSS_5};
use crate::sampling::{PreparedLight, weights};
use crate::spectrum::observer;
use crate::{LAMBDA_MAX, LAMBDA_MIN, TabulatedSpectrum, Xyz};

/// XYZ of `light × surface`. For a built-in light (or a clone of one)
/// and a reflectance on the patches' 10 nm grid this is a dot product with
/// weights computed at build time ([`crate::sampling::PreparedLight`]);
/// otherwise exact integration piece by piece. Both are exact.
#[must_use]
pub fn xyz(light: &TabulatedSpectrum, surface: &TabulatedSpectrum) -> Xyz {
    match PreparedLight::builtin(light, surface) {
        Some(prepared) => prepared.xyz(surface),
        None => xyz_of_product(&[light, surface]),
    }
}

/// XYZ of the perfect white (reflectance 1 over 380–730 nm) under `light`.
#[must_use]
pub fn white(light: &TabulatedSpectrum) -> Xyz {
    let [x, y, z] = weights::white(&light.view(), &observer::views());
    Xyz::new(x, y, z)
}

/// XYZ of the product of `factors` over 380–730 nm and their common
/// support; zero if that is empty.
#[must_use]
pub fn xyz_of_product(factors: &[&TabulatedSpectrum]) -> Xyz {
    let a = factors.iter().map(|s| s.support().0).fold(LAMBDA_MIN, f64::max);
    let b = factors.iter().map(|s| s.support().1).fold(LAMBDA_MAX, f64::min);
    if a >= b {
        return Xyz::ZERO;
    }
    let pieces = quadrature::pieces(
        factors
            .iter()
            .copied()
            .chain(observer::CMFS)
            .flat_map(|s| s.breaks().iter().copied())
            .filter(|&x| x > a && x < b)
            .chain([a, b]),
    );
    let [x, y, z] = quadrature::integrate(&GAUSS_5, &pieces, |lambda| {
        let f: f64 = factors.iter().map(|s| s.eval(lambda)).product();
        (observer::xyz_bar(lambda) * f).to_array()
    });
    Xyz::new(x, y, z)
}
