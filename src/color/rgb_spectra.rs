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
//! use speclab::{LinearSrgb, Spectrum};
//! use speclab::color::{RgbAlbedo, upsample::RgbSpace};
//! let orange = LinearSrgb::new(0.8, 0.35, 0.05);
//! let albedo = RgbAlbedo::new(orange)?;
//! assert!(albedo.eval(650.0) > albedo.eval(450.0));
//! assert!(RgbSpace::srgb().rgb_of(&albedo).distance(orange.into()) < 1e-4);
//! assert!(RgbAlbedo::new(LinearSrgb::new(1.2, 0.0, 0.0)).is_err()); // not a reflectance
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::space::RgbSpace;
use crate::color::srgb::LinearSrgb;
use crate::error::Error;
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
}

impl Spectrum for RgbUnbounded {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.scale * self.poly.eval(lambda)
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
    pub fn new(rgb: LinearSrgb) -> Result<Self, Error> {
        RgbSpace::srgb().fit_albedo(rgb)
    }
}

impl RgbUnbounded {
    /// Any linear sRGB colour as a non-negative spectrum:
    /// [`RgbSpace::srgb`]'s [`unbounded`](RgbSpace::unbounded) (negative
    /// and NaN components are taken as 0: outside the gamut, there is no
    /// spectrum). The first call builds sRGB's table.
    #[must_use]
    pub fn new(rgb: LinearSrgb) -> Self {
        RgbSpace::srgb().unbounded(rgb)
    }
}

impl RgbIlluminant {
    /// A light of linear sRGB colour `rgb`: [`RgbSpace::srgb`]'s
    /// [`light`](RgbSpace::light), the CIE's D65 tinted, normalised so that
    /// (1, 1, 1) has the luminance of a constant spectrum of 1 (`Y = ∫ȳ`).
    /// The first call builds sRGB's table.
    #[must_use]
    pub fn new(rgb: LinearSrgb) -> Self {
        RgbSpace::srgb().light(rgb)
    }
}

crate::spectrum::scaled::scale_by_mul!(RgbAlbedo, RgbUnbounded, RgbIlluminant);
