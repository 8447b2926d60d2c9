//! The spectra of a space's colours: a colour looked up in the space's
//! table ([`RgbSpace::albedo`], [`RgbSpace::unbounded`],
//! [`RgbSpace::light`]) or fitted alone ([`RgbSpace::fit_albedo`]), a
//! table fitted for a space ([`RgbTable::fit`]), the colour of a
//! reflectance under the space's illuminant ([`RgbSpace::albedo_xyz`],
//! [`RgbSpace::rgb_of`]), and sRGB's shorthands (`RgbAlbedo::new`,
//! `RgbUnbounded::new`, `RgbIlluminant::new`). Here, above the space, its
//! table, the fit and the spectra's types, so that none of those four
//! imports another in a circle.
//!
//! ```
//! use speclab::LinearRgb;
//! use speclab::color::{RgbAlbedo, RgbSpace};
//! let space = RgbSpace::srgb();
//! let orange = LinearRgb::new(0.8, 0.35, 0.05);
//! let looked_up = space.albedo(orange)?; // the embedded table
//! let fitted = RgbAlbedo::new(orange)?; // fitted for this colour alone
//! assert!(space.rgb_of(&looked_up).distance(orange) < 2e-3);
//! assert!(space.rgb_of(&fitted).distance(orange) < 1e-4);
//! let lamp = space.light(LinearRgb::new(1.0, 0.9, 0.7)); // a warm light, D65 tinted
//! let shown = space.rgb(speclab::sampling::reference::white(&lamp));
//! assert!(shown.r > shown.g && shown.g > shown.b);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::rgb::LinearRgb;
use crate::color::rgb_spectra::{RgbAlbedo, RgbIlluminant, RgbUnbounded, Split};
use crate::color::rgb_table::{RgbTable, albedo_components};
use crate::color::space::RgbSpace;
use crate::color::xyz::Xyz;
use crate::error::Error;
use crate::spectrum::Spectrum;
use crate::spectrum::observer::Y_BAR_INTEGRAL;

/// The spectra of a space's colours, looked up in its table.
///
/// **Conventions.** pbrt-v4 scales an unbounded colour by twice its
/// largest component ([`RgbSpace::unbounded`]): the albedo looked up is
/// the colour at half brightness, where every chromaticity a reflectance
/// has is reached. A renderer that takes a colour in [0, 1]³ as its own
/// albedo and scales only brighter ones uses
/// [`RgbSpace::unbounded_up_to_one`]: the same spectrum as
/// [`RgbSpace::albedo`] inside the cube. A light given as an RGB colour in
/// the space is [`RgbSpace::light`] (pbrt-v4's `RGBIlluminantSpectrum`:
/// the tint times the space's illuminant, so that `(1, 1, 1)` is the
/// space's white); a renderer that multiplies by a light spectrum of its
/// own takes the tint alone, [`RgbSpace::unbounded`], or it counts the
/// illuminant twice.
impl RgbSpace {
    /// The reflectance whose colour under the space's illuminant is `rgb`
    /// (each component in [0, 1]; otherwise an [`Error::Albedo`]), fitted
    /// for this colour alone: about 10 µs. The closest a sigmoid
    /// polynomial comes, for a colour no reflectance has (outside the
    /// object colours of the illuminant: much of ACES2065-1's cube).
    pub fn fit_albedo(&self, rgb: impl Into<LinearRgb>) -> Result<RgbAlbedo, Error> {
        let c = albedo_components(rgb.into())?;
        Ok(RgbAlbedo::from_polynomial(self.fit.fit(c)))
    }

    /// The reflectance whose colour under the space's illuminant is `rgb`
    /// (each component in [0, 1]; otherwise an [`Error::Albedo`]), looked
    /// up in the space's [`table`](RgbSpace::table).
    #[inline]
    pub fn albedo(&self, rgb: impl Into<LinearRgb>) -> Result<RgbAlbedo, Error> {
        self.table().albedo(rgb.into())
    }

    /// The reflectance of any colour a texture holds, and what was done to
    /// its components outside [0, 1]: each clamped into [0, 1] (NaN as 0),
    /// then looked up as [`RgbSpace::albedo`] (one type for every texel;
    /// no `Result`).
    ///
    /// ```
    /// use speclab::color::{Clamp, LinearRgb, RgbSpace};
    /// let srgb = RgbSpace::srgb();
    /// let (albedo, clamped) = srgb.reflectance(LinearRgb::new(1.2, 0.5, -0.1));
    /// assert_eq!(clamped, [Clamp::Above, Clamp::Inside, Clamp::Below]);
    /// assert_eq!(albedo, srgb.albedo(LinearRgb::new(1.0, 0.5, 0.0))?);
    /// # Ok::<(), speclab::Error>(())
    /// ```
    #[inline]
    pub fn reflectance(&self, rgb: impl Into<LinearRgb>) -> (RgbAlbedo, [Clamp; 3]) {
        reflectance_in(self.table(), rgb.into())
    }

    /// The colour of a reflectance under the space's illuminant, white
    /// `Y = 1`: `∫ L·R·c̄ / ∫ L·ȳ`, integrated as the exact reference
    /// integrates.
    #[must_use]
    pub fn albedo_xyz(&self, albedo: &dyn Spectrum) -> Xyz {
        self.fit.albedo_xyz(albedo)
    }

    /// [`RgbSpace::albedo_xyz`] as linear RGB, each channel balanced so
    /// that the perfect reflector is `(1, 1, 1)` exactly.
    #[must_use]
    pub fn rgb_of(&self, albedo: &dyn Spectrum) -> LinearRgb {
        self.fit.rgb(self.fit.albedo_xyz(albedo))
    }

    /// Any colour as a non-negative spectrum, `scale · s(λ)`: twice the
    /// largest component times the albedo of the colour over that, looked
    /// up in the table (pbrt-v4's `RGBUnboundedSpectrum`). Negative and
    /// NaN components are taken as 0.
    #[must_use]
    pub fn unbounded(&self, rgb: impl Into<LinearRgb>) -> RgbUnbounded {
        unbounded_in(self.table(), rgb.into(), Split::Twice)
    }

    /// Any colour as a non-negative spectrum, scaled "1 up to 1": a colour
    /// whose largest component is at most 1 is its albedo
    /// ([`RgbSpace::albedo`], scale 1), a brighter one its largest
    /// component times the albedo of the colour over that. Negative and
    /// NaN components are taken as 0.
    #[must_use]
    pub fn unbounded_up_to_one(&self, rgb: impl Into<LinearRgb>) -> RgbUnbounded {
        unbounded_in(self.table(), rgb.into(), Split::UpToOne)
    }

    /// A light of colour `rgb`: [`RgbSpace::unbounded`]'s spectrum times
    /// the space's illuminant, normalised so that `(1, 1, 1)` has the
    /// luminance of a constant spectrum of 1 (pbrt-v4's
    /// `RGBIlluminantSpectrum`). A renderer that multiplies by its own
    /// light spectrum wants [`RgbSpace::unbounded`] instead.
    #[must_use]
    pub fn light(&self, rgb: impl Into<LinearRgb>) -> RgbIlluminant {
        self.light_in(self.table(), rgb.into())
    }

    /// [`RgbSpace::light`] by `table` (the space's own, as the caller
    /// found it).
    pub(crate) fn light_in(&self, table: &RgbTable, rgb: LinearRgb) -> RgbIlluminant {
        let (scale, poly) = table.split(rgb, Split::Twice);
        RgbIlluminant::from_parts(scale * Y_BAR_INTEGRAL / self.fit.white_y, poly, self.fit.illuminant)
    }
}

/// [`RgbSpace::unbounded`] (`Split::Twice`) or
/// [`RgbSpace::unbounded_up_to_one`] by `table`.
pub(crate) fn unbounded_in(table: &RgbTable, rgb: LinearRgb, split: Split) -> RgbUnbounded {
    let (scale, poly) = table.split(rgb, split);
    RgbUnbounded::from_parts(scale, poly)
}

impl RgbTable {
    /// The table of `space` with `resolution` nodes per axis (2 to 256),
    /// fitted now, its coefficients as fitted (version 1, `f32`; 9.4 MB at
    /// the full [`RESOLUTION`](super::rgb_table::RESOLUTION); [`RgbTable::compact`] makes it 1.5–2.3 MB):
    /// seconds (sRGB) to a minute (ACES2065-1) in a release build, on up to
    /// three threads.
    #[must_use]
    pub fn fit(space: &RgbSpace, resolution: usize) -> RgbTable {
        RgbTable::fitted(&space.fit, space.name(), resolution)
    }
}

/// What [`RgbSpace::reflectance`] did with one component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clamp {
    /// In [0, 1]: taken as it is.
    Inside,
    /// Below 0 (or −∞): taken as 0.
    Below,
    /// Above 1 (or +∞): taken as 1.
    Above,
    /// NaN: taken as 0.
    NotANumber,
}

/// [`RgbSpace::reflectance`] by `table`.
pub(crate) fn reflectance_in(table: &RgbTable, rgb: LinearRgb) -> (RgbAlbedo, [Clamp; 3]) {
    let c = rgb.to_array();
    let clamp = c.map(|v| match v {
        v if v.is_nan() => Clamp::NotANumber,
        v if v < 0.0 => Clamp::Below,
        v if v > 1.0 => Clamp::Above,
        _ => Clamp::Inside,
    });
    let inside = LinearRgb::from(c.map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) }));
    let albedo = table.albedo(inside).unwrap_or_else(|_| unreachable!("components clamped into [0, 1]"));
    (albedo, clamp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::RgbSpace;

    /// Each component's report, and the albedo of the clamped colour.
    #[test]
    fn reflectance_reports_each_component() {
        let srgb = RgbSpace::srgb();
        let cases = [
            ([0.0, 1.0, 0.5], [Clamp::Inside; 3], [0.0, 1.0, 0.5]),
            ([-1e-9, 1.0 + 1e-9, f64::NAN], [Clamp::Below, Clamp::Above, Clamp::NotANumber], [0.0, 1.0, 0.0]),
            (
                [f64::INFINITY, f64::NEG_INFINITY, 0.25],
                [Clamp::Above, Clamp::Below, Clamp::Inside],
                [1.0, 0.0, 0.25],
            ),
        ];
        for (rgb, report, inside) in cases {
            let (albedo, clamped) = srgb.reflectance(LinearRgb::from(rgb));
            assert_eq!(clamped, report, "{rgb:?}");
            assert_eq!(albedo, srgb.albedo(LinearRgb::from(inside)).unwrap(), "{rgb:?}");
            assert_eq!((**srgb).reflectance(LinearRgb::from(rgb)), (albedo, clamped));
        }
    }
}
