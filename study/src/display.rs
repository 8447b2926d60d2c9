//! From a colour's numbers to the pixel a screen shows, in three
//! small steps that renderers and the study's pictures share.
//!
//! 1. **Exposure** ([`Exposure`]): scale linear sRGB so that the perfect
//!    white under the light has Y = 1 ([`Exposure::for_white`]), so that
//!    it just fits the display with its own colour
//!    ([`Exposure::fit_white`]: brightest channel 1), or by a given factor
//!    ([`Exposure::new`]).
//! 2. **Gamut mapping** ([`GamutMap`]): bring a colour with a component
//!    below 0 or above 1 into the display cube [0, 1]³, either per channel
//!    ([`clip`]) or keeping hue and luminance and reducing chroma toward the
//!    grey of the same luminance until the colour fits ([`reduce_chroma`]).
//! 3. **Encoding** ([`EncodedSrgb`]): the IEC 61966-2-1 transfer function
//!    ([`srgb::encode`]), then quantisation to 8 bits ([`Srgb8`]).
//!
//! [`PixelPipeline`] runs the three for one pixel. Gamut mapping is for pixels
//! only: the numbers the study prints stay unclamped [`LinearRgb`], with
//! their negatives. Units: linear sRGB is relative to the display white
//! `(1, 1, 1)`, encoded values are fractions of full scale. Every function
//! here takes any `f64` (NaN, infinities, negatives) and gives a defined
//! pixel; none allocates.
//!
//! ```
//! use speclab_study::display::{PixelPipeline, Exposure, GamutMap, Srgb8};
//! use speclab::{data, sampling::reference};
//! let white = reference::white(&data::lights::D65);
//! let g4 = reference::xyz(&data::lights::D65, &data::patches::G4).to_linear_srgb(); // red; green < 0
//! let display = PixelPipeline::new(Exposure::for_white(white), GamutMap::Chroma);
//! let Srgb8 { r, g, b } = display.pixel(g4);
//! assert_eq!(g, 0); // on the gamut's edge: desaturated just enough
//! assert!(r > b && b > 0);
//! assert_eq!(display.pixel(white.to_linear_srgb()), Srgb8::new(255, 255, 255));
//! ```
//!
//! Linear and encoded sRGB are different types, so an encoded value cannot
//! be measured, mixed or encoded again as if it were linear:
//!
//! ```compile_fail
//! use speclab_study::display::EncodedSrgb;
//! use speclab::LinearRgb;
//! let linear = LinearRgb::new(0.2, 0.4, 0.6);
//! let encoded = EncodedSrgb::encode(linear);
//! let _ = linear.distance(encoded); // expected `LinearRgb`, found `EncodedSrgb`
//! ```
//!
//! Decoding first says what is meant, and compiles:
//!
//! ```
//! # use speclab::LinearRgb;
//! # use speclab_study::display::EncodedSrgb;
//! let linear = LinearRgb::new(0.2, 0.4, 0.6);
//! let encoded = EncodedSrgb::encode(linear);
//! assert!(linear.distance(encoded.decode()) < 1e-12);
//! ```

use speclab::color::srgb::{self, SRGB_TO_XYZ};
use speclab::{LinearRgb, Xyz, named_choices};

/// A positive factor that linear colours are multiplied by before display.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Exposure {
    factor: f64,
}

impl Exposure {
    /// No scaling.
    pub const ONE: Exposure = Exposure { factor: 1.0 };

    /// Scales by `factor`. A factor that is negative, zero, NaN or infinite
    /// gives factor 0 (every colour displays black).
    #[must_use]
    pub fn new(factor: f64) -> Exposure {
        Exposure { factor: if factor.is_finite() && factor > 0.0 { factor } else { 0.0 } }
    }

    /// Puts `white` (the perfect white under the light, in the units of the
    /// colours to display) at Y = 1: factor `1 / white.y`. A white whose Y
    /// is not positive, or so small that `1 / Y` overflows, gives factor 0.
    #[must_use]
    pub fn for_white(white: Xyz) -> Exposure {
        Exposure::new(1.0 / white.y)
    }

    /// The largest exposure at which `white` shows unchanged: its brightest
    /// linear sRGB channel at 1. A neutral white lands at Y ≈ 1, as with
    /// [`Exposure::for_white`]; a coloured one (A's orange, F11's
    /// yellow-green) keeps its colour instead of reaching Y = 1, where only
    /// the display white fits. A white with no positive channel gives 0.
    #[must_use]
    pub fn fit_white(white: Xyz) -> Exposure {
        let brightest = white.to_linear_srgb().to_array().into_iter().fold(0.0, f64::max);
        Exposure::new(1.0 / brightest)
    }

    /// The factor.
    #[must_use]
    pub fn factor(self) -> f64 {
        self.factor
    }

    /// `rgb` times the factor (non-finite components stay non-finite; the
    /// gamut map handles them).
    #[inline]
    #[must_use]
    pub fn apply(self, rgb: LinearRgb) -> LinearRgb {
        rgb * self.factor
    }
}

/// How a colour outside the display cube [0, 1]³ is brought into it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum GamutMap {
    /// Per channel ([`clip`]): fast, but shifts hue and luminance.
    Clip,
    /// Keep hue and luminance, reduce chroma ([`reduce_chroma`]).
    #[default]
    Chroma,
}

named_choices!(GamutMap, "a gamut map": Clip => "clip", Chroma => "chroma");

impl GamutMap {
    /// `rgb` mapped into [0, 1]³.
    #[inline]
    #[must_use]
    pub fn apply(self, rgb: LinearRgb) -> LinearRgb {
        match self {
            GamutMap::Clip => clip(rgb),
            GamutMap::Chroma => reduce_chroma(rgb),
        }
    }
}

/// Each channel clamped to [0, 1]; NaN gives 0.
#[inline]
#[must_use]
pub fn clip(rgb: LinearRgb) -> LinearRgb {
    // The comparison is false for NaN, hence 0.
    let c = |v: f64| if v > 0.0 { v.min(1.0) } else { 0.0 };
    LinearRgb::new(c(rgb.r), c(rgb.g), c(rgb.b))
}

/// Luminance of the display white `(1, 1, 1)`: 0.99991 by the part D
/// matrix (the sum of [`SRGB_TO_XYZ`]'s middle row).
pub const WHITE_LUMINANCE: f64 = SRGB_TO_XYZ[1][0] + SRGB_TO_XYZ[1][1] + SRGB_TO_XYZ[1][2];

/// The colour of [0, 1]³ with the same luminance and hue as `rgb` and the
/// most chroma: `rgb` moved along the straight line toward the grey of its
/// luminance, `g·(1, 1, 1)` with `g = Y / Y_white`, just until every
/// channel lies in [0, 1]. Colours inside the cube are returned unchanged.
///
/// - **Luminance** `Y` ([`srgb::luminance`]) is kept, because the
///   luminance is linear and the grey has the same: to 1e-12 for components
///   up to 10³ in magnitude (rounding only).
/// - **Hue** is kept: a mixture of a colour and a grey lies on the straight
///   line from the white point through the colour, in the chromaticity
///   diagram and in linear RGB, so the direction from the grey is the
///   input's (to 1e-9 rad while the output is at least 1e-6 from the grey).
/// - Luminance outside the cube's range is clamped first: `Y ≤ 0` gives
///   black, `Y ≥ Y_white` gives white, the only colours of those
///   luminances inside the cube.
/// - A non-finite component has no hue: such a colour is [`clip`]ped.
#[must_use]
pub fn reduce_chroma(rgb: LinearRgb) -> LinearRgb {
    let c = rgb.to_array();
    if !c.iter().all(|v| v.is_finite()) {
        return clip(rgb);
    }
    if c.iter().all(|v| (0.0..=1.0).contains(v)) {
        return rgb;
    }
    let y = srgb::luminance(rgb);
    if y <= 0.0 {
        return LinearRgb::new(0.0, 0.0, 0.0);
    }
    if y >= WHITE_LUMINANCE {
        return LinearRgb::new(1.0, 1.0, 1.0);
    }
    let grey = y / WHITE_LUMINANCE;
    // The largest t in [0, 1] that keeps grey + t·(c − grey) in [0, 1]³.
    let t = c.iter().fold(1.0_f64, |t, &v| {
        let d = v - grey;
        if d > 0.0 {
            t.min((1.0 - grey) / d)
        } else if d < 0.0 {
            t.min(grey / -d)
        } else {
            t
        }
    });
    // Clamped only against rounding, by at most a few units in the last place.
    let mix = |v: f64| (grey + t * (v - grey)).clamp(0.0, 1.0);
    LinearRgb::new(mix(rgb.r), mix(rgb.g), mix(rgb.b))
}

/// sRGB encoded by the IEC 61966-2-1 transfer function: what a display
/// expects, each component in [0, 1]. A different type from
/// [`LinearRgb`], so the two cannot be mixed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EncodedSrgb {
    /// Red, encoded.
    pub r: f64,
    /// Green, encoded.
    pub g: f64,
    /// Blue, encoded.
    pub b: f64,
}

impl EncodedSrgb {
    /// Encodes each channel with [`srgb::encode`] (components outside
    /// [0, 1] are clamped first; NaN gives 0). Map the gamut before, to
    /// choose how.
    #[inline]
    #[must_use]
    pub fn encode(rgb: LinearRgb) -> EncodedSrgb {
        EncodedSrgb { r: srgb::encode(rgb.r), g: srgb::encode(rgb.g), b: srgb::encode(rgb.b) }
    }

    /// Back to linear with [`srgb::decode`] (clamped to [0, 1]; NaN gives 0).
    #[inline]
    #[must_use]
    pub fn decode(self) -> LinearRgb {
        LinearRgb::new(srgb::decode(self.r), srgb::decode(self.g), srgb::decode(self.b))
    }

    /// Quantised to 8 bits per channel by [`srgb::to_8bit`].
    #[inline]
    #[must_use]
    pub fn to_8bit(self) -> Srgb8 {
        Srgb8::new(srgb::to_8bit(self.r), srgb::to_8bit(self.g), srgb::to_8bit(self.b))
    }
}

/// An encoded sRGB pixel, 8 bits per channel (0 to 255).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Srgb8 {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
}

impl Srgb8 {
    /// From components.
    #[must_use]
    pub const fn new(r: u8, g: u8, b: u8) -> Srgb8 {
        Srgb8 { r, g, b }
    }

    /// `[r, g, b]`.
    #[must_use]
    pub const fn to_array(self) -> [u8; 3] {
        [self.r, self.g, self.b]
    }

    /// The encoded value this code stands for, `code / 255`.
    #[must_use]
    pub fn to_encoded(self) -> EncodedSrgb {
        let v = |c: u8| f64::from(c) / 255.0;
        EncodedSrgb { r: v(self.r), g: v(self.g), b: v(self.b) }
    }
}

/// The whole pipeline for one pixel: exposure, gamut map, encoding, 8 bits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelPipeline {
    /// How linear colours are scaled first.
    pub exposure: Exposure,
    /// How colours outside [0, 1]³ are brought in.
    pub gamut: GamutMap,
}

impl PixelPipeline {
    /// From its two choices.
    #[must_use]
    pub const fn new(exposure: Exposure, gamut: GamutMap) -> PixelPipeline {
        PixelPipeline { exposure, gamut }
    }

    /// The pixel showing `rgb`.
    #[inline]
    #[must_use]
    pub fn pixel(&self, rgb: LinearRgb) -> Srgb8 {
        EncodedSrgb::encode(self.gamut.apply(self.exposure.apply(rgb))).to_8bit()
    }
}
