//! Spectra of RGB colours, each a [`SigmoidPolynomial`] `s(λ)` fitted to
//! the colour in an [`RgbSpace`](super::RgbSpace) (Jakob and Hanika 2019, as pbrt-v4 and
//! Mitsuba 3 use them):
//!
//! - [`RgbAlbedo`]: a reflectance, `s(λ)`, in [0, 1], whose colour under
//!   the space's illuminant is the RGB it was made from;
//! - [`RgbUnbounded`]: `scale · s(λ)`, any non-negative colour (an
//!   emission or a scattering coefficient);
//! - [`RgbIlluminant`]: `scale · s(λ) · L(λ)`, a light of a colour, the
//!   space's illuminant `L` tinted.
//!
//! A space's [`albedo`](super::RgbSpace::albedo),
//! [`unbounded`](super::RgbSpace::unbounded) and
//! [`light`](super::RgbSpace::light) look colours up in its table
//! ([`super::rgb_table`]); [`RgbAlbedo::new`] fits a linear sRGB colour
//! (about 10 µs), and [`RgbUnbounded::new`] and [`RgbIlluminant::new`] look
//! up sRGB's (all in `space_spectra.rs`).
//!
//! ```
//! use speclab::{LinearRgb, Spectrum};
//! use speclab::color::{RgbAlbedo, RgbSpace};
//! let orange = LinearRgb::new(0.8, 0.35, 0.05);
//! let albedo = RgbAlbedo::new(orange)?;
//! assert!(albedo.eval(650.0) > albedo.eval(450.0));
//! assert!(RgbSpace::srgb().rgb_of(&albedo).distance(orange) < 1e-4);
//! assert!(RgbAlbedo::new(LinearRgb::new(1.2, 0.0, 0.0)).is_err()); // not a reflectance
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::spectrum::{Pieces, SigmoidPolynomial, Spectrum, TabulatedSpectrum};
use std::borrow::Cow;

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

    /// The illuminant's breaks: the tint is smooth.
    fn kinks(&self) -> Cow<'_, [f64]> {
        Cow::Borrowed(self.illuminant.breaks())
    }

    /// A bound: the scale times the polynomial's maximum times the
    /// illuminant's.
    fn max_value(&self) -> f64 {
        self.scale * self.poly.max_value() * self.illuminant.max_value()
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

crate::spectrum::scaled::scale_by_mul!(RgbAlbedo, RgbUnbounded, RgbIlluminant);
