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
//! **One range for the study**: [`xyz`], [`white`] and [`xyz_of_product`]
//! run over 380–730 nm (W = 350 nm) with the assignment's observer;
//! [`xyz_over`] takes another range and observer (360–830 nm and the CIE's
//! 1 nm tables, for a renderer's). The perfect white ([`white`]) uses the same range as every
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
use crate::error::Error;
#[cfg(doc)]
use crate::sampling::PreparedLight;
use crate::spectrum::{Spectrum, StandardObserver, WavelengthRange, integrate};

/// XYZ of `light × surface`, integrated piece by piece: exact for
/// piecewise polynomials. For many surfaces under one light,
/// [`PreparedLight`] is faster.
#[must_use]
pub fn xyz(light: &(impl Spectrum + ?Sized), surface: &(impl Spectrum + ?Sized)) -> Xyz {
    xyz_of_product(&[&light as &dyn Spectrum, &surface])
}

/// XYZ of the product of `factors` over `range` with `observer`, exact as
/// [`xyz_of_product`] (which is this over 380–730 nm with the assignment's
/// observer); an error if the observer's data do not cover the range.
///
/// ```
/// use speclab::{data::{lights, patches}, sampling::reference, Spectrum};
/// use speclab::spectrum::{StandardObserver, WavelengthRange};
/// let wide = reference::xyz_over(StandardObserver::Cie1931, WavelengthRange::VISIBLE, &[&lights::D65, &patches::G4])?;
/// let narrow = reference::xyz(&lights::D65, &patches::G4);
/// assert!((wide.y / narrow.y - 1.0).abs() < 1e-3); // G4 is zero beyond 730 nm, D65 beyond 780 nm
/// assert!(reference::xyz_over(StandardObserver::Assignment, WavelengthRange::VISIBLE, &[&lights::D65]).is_err());
/// # Ok::<(), speclab::Error>(())
/// ```
pub fn xyz_over(
    observer: StandardObserver,
    range: WavelengthRange,
    factors: &[&dyn Spectrum],
) -> Result<Xyz, Error> {
    integrate::xyz_of_product_with(observer, range, factors).map(Xyz::from)
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
