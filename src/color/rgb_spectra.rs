//! Spectra of RGB colours, each a [`SigmoidPolynomial`] `s(λ)` fitted to
//! the colour by [`RgbSpace`] (Jakob and Hanika 2019, as pbrt-v4 and
//! Mitsuba 3 use them):
//!
//! - [`RgbAlbedo`]: a reflectance, `s(λ)`, in [0, 1], whose colour under
//!   D65 is the linear sRGB it was made from;
//! - [`RgbUnbounded`]: `scale · s(λ)`, any non-negative colour (an
//!   emission or a scattering coefficient);
//! - [`RgbIlluminant`]: `scale · s(λ) · D65(λ)`, a light of a colour, the
//!   colour space's illuminant tinted.
//!
//! A fit takes about 10 µs; [`super::rgb_table`] gives an albedo in one
//! lookup.
//!
//! ```
//! use speclab::{LinearSrgb, Spectrum};
//! use speclab::color::{RgbAlbedo, upsample::RgbSpace};
//! let orange = LinearSrgb::new(0.8, 0.35, 0.05);
//! let albedo = RgbAlbedo::new(orange)?;
//! assert!(albedo.eval(650.0) > albedo.eval(450.0));
//! assert!(RgbSpace::srgb().rgb_of(&albedo).distance(orange) < 1e-4);
//! assert!(RgbAlbedo::new(LinearSrgb::new(1.2, 0.0, 0.0)).is_err()); // not a reflectance
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::srgb::LinearSrgb;
use crate::color::upsample::RgbSpace;
use crate::error::Error;
use crate::spectrum::data::lights;
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

    fn pieces(&self) -> Option<Pieces<'_>> {
        self.poly.pieces()
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
}

/// A light of an RGB colour: `scale · s(λ) · D65(λ)`, the colour space's
/// illuminant (the tabulated D65, normalised so that its white has Y = 1)
/// tinted by an albedo (pbrt-v4's `RGBIlluminantSpectrum`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RgbIlluminant {
    pub(crate) scale: f64,
    pub(crate) poly: SigmoidPolynomial,
}

impl RgbIlluminant {
    /// `scale` times `poly` times the normalised D65.
    #[must_use]
    pub const fn from_parts(scale: f64, poly: SigmoidPolynomial) -> Self {
        RgbIlluminant { scale, poly }
    }

    /// The illuminant it tints: D65 as tabulated in `data/`.
    #[must_use]
    pub fn illuminant() -> &'static TabulatedSpectrum {
        &lights::D65
    }
}

impl Spectrum for RgbIlluminant {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.scale * self.poly.eval(lambda) * lights::D65.eval(lambda)
    }
}

impl RgbAlbedo {
    /// The reflectance whose colour under D65 is `rgb` (linear sRGB, each
    /// component in [0, 1]; otherwise an [`Error::Albedo`]). About 10 µs;
    /// `color::rgb_table` does it in a lookup.
    pub fn new(rgb: LinearSrgb) -> Result<Self, Error> {
        let c = rgb.to_array();
        if !c.iter().all(|v| (0.0..=1.0).contains(v)) {
            return Err(Error::Albedo { rgb: c });
        }
        Ok(RgbAlbedo::from_polynomial(RgbSpace::srgb().fit(c)))
    }
}

impl RgbUnbounded {
    /// Any colour as a non-negative spectrum: twice the largest component
    /// times the albedo of the colour over that (negative and NaN
    /// components are taken as 0: outside the gamut, there is no spectrum).
    #[must_use]
    pub fn new(rgb: LinearSrgb) -> Self {
        let (scale, poly) = RgbSpace::srgb().split(rgb);
        RgbUnbounded::from_parts(scale, poly)
    }
}

impl RgbIlluminant {
    /// A light of colour `rgb`: [`RgbUnbounded`]'s spectrum times D65,
    /// normalised so that (1, 1, 1) has the luminance of a constant
    /// spectrum of 1 (`Y = ∫ȳ`).
    #[must_use]
    pub fn new(rgb: LinearSrgb) -> Self {
        let space = RgbSpace::srgb();
        let (scale, poly) = space.split(rgb);
        RgbIlluminant::from_parts(scale * Y_BAR_INTEGRAL / space.white_y, poly)
    }
}
