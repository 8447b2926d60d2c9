//! The exact reference: XYZ of light × surface by exact integration, for
//! any spectra.
//!
//! Between two consecutive breaks every factor is a polynomial (a light is
//! linear, a reflectance and the matching functions cubic), so a
//! Gauss–Legendre rule with enough points is exact on each piece, up to
//! rounding; all arithmetic is f64. This reproduces Appendix 2 (see
//! `tests/appendix2.rs`). Spectra that are not piecewise polynomial
//! (blackbody, RGB-derived, closures) are integrated by quadrature on the
//! same pieces (see `spectrum::Spectrum`).
//!
//! **One range for everything**: the integrals run over 380–730 nm (W =
//! 350 nm). The perfect white ([`white`]) uses the same range as every
//! colour, even for lights tabulated to 780 nm, so a white patch of
//! reflectance 1 has exactly the white's XYZ, and every sampler (which
//! draws within 380–730 nm) is unbiased for both.
//!
//! For a renderer's paths, [`ExactPaths`] gives each path's exact colour
//! as a sum over fixed nodes.
//!
//! **Speed**: integration piece by piece takes a few microseconds for a
//! patch. For many reflectances under one light, prepare the light once
//! ([`PreparedLight`], about 20 µs): each XYZ is then a dot product with
//! the reflectance's samples, about 50 ns for a patch, and as exact.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::reference};
//! let rgb = reference::xyz(&lights::D65, &patches::A1).to_linear_srgb();
//! assert!((rgb.g - 82.44).abs() < 0.05); // Appendix 2: 80.79, 82.44, 80.84
//! let scaled = lights::D65.scaled(2.0)?;
//! let (once, twice) = (reference::xyz(&lights::D65, &patches::A1), reference::xyz(&scaled, &patches::A1));
//! assert!((twice.y - 2.0 * once.y).abs() < 1e-12 * twice.y);
//! # Ok::<(), speclab::Error>(())
//! ```

pub use crate::sampling::paths::ExactPaths;

use crate::color::Xyz;
#[cfg(doc)]
use crate::sampling::PreparedLight;
use crate::spectrum::{Spectrum, integrate};

/// XYZ of `light × surface`, integrated piece by piece: exact for
/// piecewise polynomials. For many surfaces under one light,
/// [`PreparedLight`] is faster.
#[must_use]
pub fn xyz(light: &(impl Spectrum + ?Sized), surface: &(impl Spectrum + ?Sized)) -> Xyz {
    xyz_of_product(&[&light as &dyn Spectrum, &surface])
}

/// XYZ of the perfect white (reflectance 1 over 380–730 nm) under `light`.
#[must_use]
pub fn white(light: &(impl Spectrum + ?Sized)) -> Xyz {
    Xyz::from(integrate::white(&light))
}

/// XYZ of the product of `factors` over 380–730 nm, integrated piece by
/// piece: exact for any number of piecewise polynomial factors (a path's
/// light and several reflectances).
#[must_use]
pub fn xyz_of_product(factors: &[&dyn Spectrum]) -> Xyz {
    Xyz::from(integrate::xyz_of_product(factors))
}
