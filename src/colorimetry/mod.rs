//! Colorimetry as a colour scientist computes it, on the CIE's 1 nm
//! observers: relative tristimulus values over a chosen range and step,
//! correlated colour temperature, and the loci behind it.
//!
//! - [`Tristimulus`]: `X, Y, Z` as sums over a grid of wavelengths
//!   (observer, range, step), absolute or relative (`Y = 100` for the
//!   perfect white under the light).
//! - [`astm`]: ASTM E308 weighting tables (E2022's construction) for any
//!   light, every 1 to 20 nm, over any range of whole nanometres, and
//!   their adjustment to a measured range; E2022's Lagrange coefficients
//!   ([`astm::lagrange_coefficients`]).
//! - [`e308`]: ASTM E308's practice for a reflectance measured every 1,
//!   5, 10 or 20 nm (given as a [`crate::spectrum::Sprague`] interpolant,
//!   the CIE's recommended interpolation of 5 nm tables).
//! - [`cct`]: the Planckian locus ([`cct::Planckian`]), CIE 1960 `u, v`,
//!   and `(T, Duv)` of a chromaticity by Ohno 2013, both ways; the daylight
//!   locus `y_D(x_D)` and the temperature along it nearest a chromaticity.
//! - Around them, on the floors below: the observers and ranges
//!   ([`crate::spectrum::StandardObserver`], [`crate::spectrum::WavelengthRange`]),
//!   Planck's constants by name ([`crate::spectrum::PlanckConstants`]),
//!   the daylight locus (`data::lights::daylight_xy`), xy ↔ XYZ
//!   ([`crate::Xyz::xy`], [`crate::Xyz::from_xy_luminance`]), Lab → XYZ
//!   ([`crate::color::lab::xyz_from_lab`]) and chromatic adaptation as
//!   matrices ([`crate::color::adaptation::Cat`]).
//!
//! Wavelengths in nm, temperatures in K. The renderer's sampled paths
//! (`HeroSample`, `RegularSpectrum`) are not this floor: they take any
//! `spectrum::Observer`, a `StandardObserver` among them. `docs/color.md`
//! puts ranges and observers on one page.
//!
//! ```
//! use speclab::colorimetry::{Tristimulus, cct::{Planckian, uv_from_xy}};
//! use speclab::data::lights;
//! let d65 = Tristimulus::CIE_1931.white(&lights::D65)?;
//! let (t, _) = Planckian::CIE.cct(uv_from_xy(d65.xy().unwrap()))?;
//! assert!((t - 6504.0).abs() < 2.0);
//! # Ok::<(), speclab::Error>(())
//! ```

pub mod astm;
pub mod cct;
pub mod e308;
mod tristimulus;

pub use tristimulus::Tristimulus;
