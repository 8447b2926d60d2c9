//! Spectra of RGB colours, each a [`SigmoidPolynomial`] `s(λ)` fitted to
//! the colour in an [`RgbSpace`] (Jakob and Hanika 2019, as pbrt-v4 and
//! Mitsuba 3 use them):
//!
//! - [`RgbAlbedo`]: a reflectance, `s(λ)`, in [0, 1], whose colour under
//!   the space's illuminant is the RGB it was made from;
//! - [`RgbUnbounded`]: `scale · s(λ)`, any non-negative colour (an
//!   emission or a scattering coefficient);
//! - [`RgbIlluminant`]: `scale · s(λ) · L(λ)`, a light of a colour, the
//!   space's illuminant `L` tinted.
//!
//! [`RgbAlbedo::new`] fits a linear sRGB colour (about 10 µs); a space's
//! [`albedo`](RgbSpace::albedo), [`unbounded`](RgbSpace::unbounded) and
//! [`light`](RgbSpace::light) look colours up in its table
//! ([`super::rgb_table`]); [`RgbUnbounded::new`] and [`RgbIlluminant::new`]
//! are sRGB's.
//!
//! ```
//! use speclab::{LinearRgb, Spectrum};
//! use speclab::color::{RgbAlbedo, upsample::RgbSpace};
//! let orange = LinearRgb::new(0.8, 0.35, 0.05);
//! let albedo = RgbAlbedo::new(orange)?;
//! assert!(albedo.eval(650.0) > albedo.eval(450.0));
//! assert!(RgbSpace::srgb().rgb_of(&albedo).distance(orange.into()) < 1e-4);
//! assert!(RgbAlbedo::new(LinearRgb::new(1.2, 0.0, 0.0)).is_err()); // not a reflectance
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::rgb::LinearRgb;
use crate::color::space::RgbSpace;
use crate::error::Error;
use crate::spectrum::observer::Y_BAR_INTEGRAL;
use crate::spectrum::{Pieces, SigmoidPolynomial, Spectrum, TabulatedSpectrum};

/// A reflectance from an RGB colour: a sigmoid polynomial, in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RgbAlbedo {
    pub(crate) poly: SigmoidPolynomial,
}

impl RgbAlbedo {
    /// The albedo of `poly`.
    #[must_use]
    pub const fn from_polynomial(poly: SigmoidPolynomial) -> Self {
        RgbAlbedo { poly }
    }

    /// Its sigmoid polynomial.
    #[must_use]
    pub const fn polynomial(&self) -> SigmoidPolynomial {
        self.poly
    }
}

impl Spectrum for RgbAlbedo {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.poly.eval(lambda)
    }

    /// Four lanes in `f32` at once ([`SigmoidPolynomial::eval_many_f32`]).
    #[inline(always)]
    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        self.poly.eval_many_f32(1.0, lambda, values);
    }

    /// As [`RgbAlbedo::eval_many_f32`]: a sigmoid needs no table.
    #[inline(always)]
    fn eval_many_nearest_f32(&self, lambda: &[f32], _nearest: &[u16], values: &mut [f32]) {
        self.poly.eval_many_f32(1.0, lambda, values);
    }

    fn pieces(&self) -> Option<Pieces<'_>> {
        self.poly.pieces()
    }

    /// Exact: the sigmoid polynomial's.
    fn max_value(&self) -> f64 {
        self.poly.max_value()
    }
}

/// Any non-negative colour: `scale · s(λ)` (pbrt-v4's
/// `RGBUnboundedSpectrum`: the colour over twice its largest component is
/// fitted as an albedo, then scaled back).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RgbUnbounded {
    pub(crate) scale: f64,
    pub(crate) poly: SigmoidPolynomial,
}

impl RgbUnbounded {
    /// `scale` times the sigmoid polynomial `poly`.
    #[must_use]
    pub const fn from_parts(scale: f64, poly: SigmoidPolynomial) -> Self {
        RgbUnbounded { scale, poly }
    }

    /// The scale.
    #[must_use]
    pub const fn scale(&self) -> f64 {
        self.scale
    }

    /// Its sigmoid polynomial.
    #[must_use]
    pub const fn polynomial(&self) -> SigmoidPolynomial {
        self.poly
    }
}

impl Spectrum for RgbUnbounded {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.scale * self.poly.eval(lambda)
    }

    /// Four lanes in `f32` at once, scaled.
    #[inline(always)]
    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        self.poly.eval_many_f32(to_f32(self.scale), lambda, values);
    }

    /// As [`RgbUnbounded::eval_many_f32`].
    #[inline(always)]
    fn eval_many_nearest_f32(&self, lambda: &[f32], _nearest: &[u16], values: &mut [f32]) {
        self.poly.eval_many_f32(to_f32(self.scale), lambda, values);
    }

    fn pieces(&self) -> Option<Pieces<'_>> {
        self.poly.pieces()
    }

    /// Exact: the scale times the sigmoid polynomial's.
    fn max_value(&self) -> f64 {
        self.scale * self.poly.max_value()
    }
}

/// A light of an RGB colour: `scale · s(λ) · L(λ)`, a colour space's
/// illuminant `L` tinted by an albedo (pbrt-v4's `RGBIlluminantSpectrum`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RgbIlluminant {
    pub(crate) scale: f64,
    pub(crate) poly: SigmoidPolynomial,
    illuminant: &'static TabulatedSpectrum,
}

impl RgbIlluminant {
    /// `scale` times `poly` times `illuminant`.
    #[must_use]
    pub const fn from_parts(
        scale: f64,
        poly: SigmoidPolynomial,
        illuminant: &'static TabulatedSpectrum,
    ) -> Self {
        RgbIlluminant { scale, poly, illuminant }
    }

    /// The illuminant it tints.
    #[must_use]
    pub fn illuminant(&self) -> &'static TabulatedSpectrum {
        self.illuminant
    }

    /// The scale.
    #[must_use]
    pub const fn scale(&self) -> f64 {
        self.scale
    }

    /// Its sigmoid polynomial.
    #[must_use]
    pub const fn polynomial(&self) -> SigmoidPolynomial {
        self.poly
    }
}

impl Spectrum for RgbIlluminant {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.scale * self.poly.eval(lambda) * self.illuminant.eval(lambda)
    }

    /// The tint's lanes in `f32` times the illuminant's, eight wavelengths
    /// at a time (no allocation).
    fn eval_many_nearest_f32(&self, lambda: &[f32], nearest: &[u16], values: &mut [f32]) {
        let chunks = values.chunks_mut(8).zip(lambda.chunks(8)).zip(nearest.chunks(8));
        for ((v, l), n) in chunks {
            let mut light = [0.0f32; 8];
            let light = &mut light[..v.len()];
            self.illuminant.eval_many_nearest_f32(l, n, light);
            self.poly.eval_many_f32(to_f32(self.scale), l, v);
            v.iter_mut().zip(light.iter()).for_each(|(v, e)| *v *= e);
        }
    }

    /// A bound: the scale times the polynomial's maximum times the
    /// illuminant's.
    fn max_value(&self) -> f64 {
        self.scale * self.poly.max_value() * self.illuminant.max_value()
    }
}

impl RgbAlbedo {
    /// The reflectance whose colour under D65 is `rgb` (linear sRGB, each
    /// component in [0, 1]; otherwise an [`Error::Albedo`]), fitted: about
    /// 10 µs. [`RgbSpace::albedo`] does it in a lookup, in any space.
    pub fn new(rgb: LinearRgb) -> Result<Self, Error> {
        RgbSpace::srgb().fit_albedo(rgb)
    }
}

impl RgbUnbounded {
    /// Any linear sRGB colour as a non-negative spectrum:
    /// [`RgbSpace::srgb`]'s [`unbounded`](RgbSpace::unbounded) (negative
    /// and NaN components are taken as 0: outside the gamut, there is no
    /// spectrum). The first call builds sRGB's table.
    #[must_use]
    pub fn new(rgb: LinearRgb) -> Self {
        RgbSpace::srgb().unbounded(rgb)
    }
}

impl RgbIlluminant {
    /// A light of linear sRGB colour `rgb`: [`RgbSpace::srgb`]'s
    /// [`light`](RgbSpace::light), the CIE's D65 tinted, normalised so that
    /// (1, 1, 1) has the luminance of a constant spectrum of 1 (`Y = ∫ȳ`).
    /// The first call builds sRGB's table.
    #[must_use]
    pub fn new(rgb: LinearRgb) -> Self {
        RgbSpace::srgb().light(rgb)
    }
}

/// A scale in `f32`, at most `f32::MAX` (so a huge one times a value of 0
/// stays 0).
fn to_f32(scale: f64) -> f32 {
    scale.min(f64::from(f32::MAX)) as f32
}

/// How an unbounded colour is split into a scale and an albedo.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Split {
    /// Twice the largest component (pbrt-v4, Mitsuba's `SRGBEmitterSpectrum`).
    Twice,
    /// 1 while the largest component is at most 1, the largest beyond.
    UpToOne,
}

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
    /// Any colour as a non-negative spectrum, `scale · s(λ)`: twice the
    /// largest component times the albedo of the colour over that, looked
    /// up in the table (pbrt-v4's `RGBUnboundedSpectrum`). Negative and
    /// NaN components are taken as 0.
    #[must_use]
    pub fn unbounded(&self, rgb: impl Into<LinearRgb>) -> RgbUnbounded {
        let (scale, poly) = self.table().split(rgb.into(), Split::Twice);
        RgbUnbounded::from_parts(scale, poly)
    }

    /// Any colour as a non-negative spectrum, scaled "1 up to 1": a colour
    /// whose largest component is at most 1 is its albedo
    /// ([`RgbSpace::albedo`], scale 1), a brighter one its largest
    /// component times the albedo of the colour over that. Negative and
    /// NaN components are taken as 0.
    #[must_use]
    pub fn unbounded_up_to_one(&self, rgb: impl Into<LinearRgb>) -> RgbUnbounded {
        let (scale, poly) = self.table().split(rgb.into(), Split::UpToOne);
        RgbUnbounded::from_parts(scale, poly)
    }

    /// A light of colour `rgb`: [`RgbSpace::unbounded`]'s spectrum times
    /// the space's illuminant, normalised so that `(1, 1, 1)` has the
    /// luminance of a constant spectrum of 1 (pbrt-v4's
    /// `RGBIlluminantSpectrum`). A renderer that multiplies by its own
    /// light spectrum wants [`RgbSpace::unbounded`] instead.
    #[must_use]
    pub fn light(&self, rgb: impl Into<LinearRgb>) -> RgbIlluminant {
        let (scale, poly) = self.table().split(rgb.into(), Split::Twice);
        RgbIlluminant::from_parts(scale * Y_BAR_INTEGRAL / self.fit.white_y, poly, self.fit.illuminant)
    }
}

crate::spectrum::scaled::scale_by_mul!(RgbAlbedo, RgbUnbounded, RgbIlluminant);
