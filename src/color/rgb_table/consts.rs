//! Colours at compile time: an embedded table's albedos, unbounded colours
//! and lights as `const` items, the same values as the run-time calls give
//! (to the bit), from the same [`LinearRgb`].
//!
//! ```
//! use speclab::color::{LinearRgb, RgbAlbedo, RgbIlluminant, RgbSpace, RgbUnbounded, rgb_table::RgbTable};
//! const PAINT: RgbAlbedo = RgbTable::SRGB.const_albedo(LinearRgb::new(0.8, 0.35, 0.05)).unwrap();
//! const GLOW: RgbUnbounded = RgbTable::SRGB.const_unbounded(LinearRgb::new(4.0, 1.0, 0.5)).unwrap();
//! const LAMP: RgbIlluminant = RgbTable::SRGB.const_light(LinearRgb::new(1.0, 0.8, 0.6)).unwrap();
//! let srgb = RgbSpace::srgb();
//! assert_eq!(PAINT, srgb.albedo(LinearRgb::new(0.8, 0.35, 0.05))?);
//! assert_eq!(GLOW, srgb.unbounded(LinearRgb::new(4.0, 1.0, 0.5)));
//! assert_eq!(LAMP, srgb.light(LinearRgb::new(1.0, 0.8, 0.6)));
//! # Ok::<(), speclab::Error>(())
//! ```
//!
//! Each colour decodes its eight corners in the compiler (a few hundred
//! thousand evaluation steps: about eight colours per `const` item before
//! rustc's `long_running_const_eval` lint).

use super::{RgbTable, Source};
use crate::color::rgb::LinearRgb;
use crate::color::rgb_spectra::{RgbAlbedo, RgbIlluminant, RgbUnbounded, Split};
use crate::spectrum::SigmoidPolynomial;
use crate::spectrum::TabulatedSpectrum;
use crate::spectrum::observer::Y_BAR_INTEGRAL;
use crate::spectrum::sigmoid::constant;

impl RgbTable {
    /// [`RgbTable::albedo`] at compile time, for a table embedded in the
    /// program ([`RgbTable::SRGB`] and its siblings, [`crate::rgb_table!`]):
    /// `None` for a component outside [0, 1], or for a table loaded or
    /// fitted at run time.
    #[must_use]
    pub const fn const_albedo(&self, rgb: LinearRgb) -> Option<RgbAlbedo> {
        let c = rgb.to_array();
        if !(in_unit(c[0]) && in_unit(c[1]) && in_unit(c[2])) {
            return None;
        }
        match self.const_lookup(c) {
            Some(poly) => Some(RgbAlbedo::from_polynomial(poly)),
            None => None,
        }
    }

    /// [`RgbSpace::unbounded`](crate::color::RgbSpace::unbounded) at
    /// compile time (pbrt-v4's rule: twice the largest component as the
    /// scale; negative and NaN components as 0): `None` for a table loaded
    /// or fitted at run time.
    #[must_use]
    pub const fn const_unbounded(&self, rgb: LinearRgb) -> Option<RgbUnbounded> {
        match self.const_split(rgb, Split::Twice) {
            Some((scale, poly)) => Some(RgbUnbounded::from_parts(scale, poly)),
            None => None,
        }
    }

    /// [`RgbSpace::unbounded_up_to_one`](crate::color::RgbSpace::unbounded_up_to_one)
    /// at compile time: `None` for a table loaded or fitted at run time.
    #[must_use]
    pub const fn const_unbounded_up_to_one(&self, rgb: LinearRgb) -> Option<RgbUnbounded> {
        match self.const_split(rgb, Split::UpToOne) {
            Some((scale, poly)) => Some(RgbUnbounded::from_parts(scale, poly)),
            None => None,
        }
    }

    /// [`RgbSpace::light`](crate::color::RgbSpace::light) at compile
    /// time: the tint times the space's illuminant, `(1, 1, 1)` as bright
    /// as a constant 1. `None` but for the tables of the spaces under the
    /// CIE's D65 ([`RgbTable::SRGB`], [`RgbTable::DISPLAY_P3`],
    /// [`RgbTable::REC2020`]): the ACES spaces' daylight is made at run time.
    #[must_use]
    pub const fn const_light(&self, rgb: LinearRgb) -> Option<RgbIlluminant> {
        let Some((illuminant, white_y)) = self.light else { return None };
        match self.const_split(rgb, Split::Twice) {
            Some((scale, poly)) => {
                Some(RgbIlluminant::from_parts(scale * Y_BAR_INTEGRAL / white_y, poly, illuminant))
            }
            None => None,
        }
    }

    /// The table with the illuminant its lights tint and that
    /// illuminant's `∫ L·ȳ` over 380–730 nm (a built-in table's).
    pub(crate) const fn lit(mut self, illuminant: &'static TabulatedSpectrum, white_y: f64) -> RgbTable {
        self.light = Some((illuminant, white_y));
        self
    }

    /// [`RgbTable::split`] at compile time (the same arithmetic).
    const fn const_split(&self, rgb: LinearRgb, split: Split) -> Option<(f64, SigmoidPolynomial)> {
        let c = rgb.to_array();
        let c = [positive(c[0]), positive(c[1]), positive(c[2])];
        let largest = larger(larger(c[0], c[1]), c[2]);
        if !(largest > 0.0 && largest.is_finite()) {
            return if self.is_static() { Some((0.0, SigmoidPolynomial::BLACK)) } else { None };
        }
        let scale = match split {
            Split::Twice => 2.0 * largest,
            Split::UpToOne => larger(largest, 1.0),
        };
        match self.const_lookup([c[0] / scale, c[1] / scale, c[2] / scale]) {
            Some(poly) => Some((scale, poly)),
            None => None,
        }
    }

    /// The interpolated polynomial of `rgb` in [0, 1]³, from the embedded
    /// bytes: `None` for a table that is not embedded.
    const fn const_lookup(&self, rgb: [f64; 3]) -> Option<SigmoidPolynomial> {
        let Source::Static { bytes, .. } = &self.source else { return None };
        Some(if rgb[0] == rgb[1] && rgb[1] == rgb[2] {
            constant(rgb[0])
        } else if let Some(place) = self.grid.locate([rgb[0] as f32, rgb[1] as f32, rgb[2] as f32]) {
            let c = self.grid.interpolate(bytes, place);
            SigmoidPolynomial::new([c[0] as f64, c[1] as f64, c[2] as f64])
        } else {
            SigmoidPolynomial::BLACK
        })
    }

    const fn is_static(&self) -> bool {
        matches!(self.source, Source::Static { .. })
    }
}

const fn in_unit(v: f64) -> bool {
    v >= 0.0 && v <= 1.0
}

/// `v`, or 0 for a negative or NaN `v` (as [`RgbTable::split`] takes them).
const fn positive(v: f64) -> f64 {
    if v > 0.0 { v } else { 0.0 }
}

/// The larger of two numbers that are not NaN.
const fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::RgbSpace;

    /// The `const` normaliser is the one the D65 spaces' fits compute.
    #[test]
    fn d65_white_y_is_the_fits() {
        assert_eq!(RgbSpace::srgb().fit.white_y.to_bits(), super::super::builtin::D65_WHITE_Y.to_bits());
    }

    /// Every `const` path gives the run-time value to the bit, for colours
    /// inside, above and outside the cube (negative, NaN, ∞, black).
    #[test]
    fn const_colours_are_the_run_time_ones() {
        let srgb = RgbSpace::srgb();
        let colours = [
            [0.8, 0.35, 0.05],
            [4.0, 1.0, 0.5],
            [0.5, 0.5, 0.5],
            [1.0, 0.2, 3.0],
            [-1.0, 0.3, 0.2],
            [f64::NAN, 0.5, 0.25],
            [0.0; 3],
            [f64::INFINITY, 0.1, 0.1],
            [0.2, 0.9, 1.0],
        ];
        for c in colours.map(LinearRgb::from) {
            let table = RgbTable::SRGB;
            assert_eq!(table.const_unbounded(c), Some(srgb.unbounded(c)), "{c:?}");
            assert_eq!(table.const_unbounded_up_to_one(c), Some(srgb.unbounded_up_to_one(c)), "{c:?}");
            assert_eq!(table.const_light(c), Some(srgb.light(c)), "{c:?}");
            assert_eq!(table.const_albedo(c), srgb.albedo(c).ok(), "{c:?}");
        }
    }

    /// Tables not embedded have no `const` colours; tables without a
    /// `const` illuminant no `const` lights.
    #[test]
    fn only_embedded_tables_and_d65_lights() {
        let fitted = RgbTable::fit(RgbSpace::srgb(), 4);
        let c = LinearRgb::new(0.5, 0.2, 0.1);
        assert!(fitted.const_albedo(c).is_none() && fitted.const_unbounded(c).is_none());
        assert!(fitted.const_unbounded_up_to_one(LinearRgb::splat(0.0)).is_none());
        let mine = crate::rgb_table!("../../../data/rgb/srgb.rgbt");
        assert!(mine.const_light(c).is_none() && mine.const_unbounded(c).is_some());
        #[cfg(feature = "wide-gamut")]
        {
            assert!(RgbTable::ACESCG.const_light(c).is_none());
            assert_eq!(RgbTable::REC2020.const_light(c), Some(RgbSpace::rec2020().light(c)));
        }
    }
}
