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
//! **Speed**: for a tabulated light and surface (or any light with a
//! cache and reflectance with samples), the light keeps exact
//! weights for the surface's grid, computed on first use (about 20 µs),
//! after which each XYZ is a dot product with the reflectance's samples
//! ([`PreparedLight`]): about 50 ns for a patch. Built-in, cloned, scaled
//! and loaded lights all do so.
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
use crate::sampling::PreparedLight;
use crate::spectrum::{Role, Spectrum, integrate, weights};

/// XYZ of `light × surface`. For a light that keeps a [`Cache`] (tables
/// do) and a reflectance that interpolates samples
/// ([`Spectrum::samples`]), a dot product with the light's weights for the
/// surface's grid ([`PreparedLight`], kept by the light after the first
/// call); otherwise integration piece by piece. Both exact for piecewise
/// polynomials.
///
/// [`Cache`]: crate::spectrum::Cache
#[must_use]
pub fn xyz(light: &impl Spectrum, surface: &impl Spectrum) -> Xyz {
    if let Some(s) = surface.samples()
        && s.role == Role::Reflectance
        && let Some(weights) = weights::kept_for(light, s.lambda, s.interpolation)
        && let Ok(xyz) = PreparedLight::borrowed(light, weights).xyz_samples(s.values)
    {
        return xyz;
    }
    xyz_of_product(&[light as &dyn Spectrum, surface])
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
