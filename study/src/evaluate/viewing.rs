//! The assignment's three remarks as options: normalisation of the light,
//! gamut, and white balance.
//!
//! 1. **Normalisation.** The appendix lights have arbitrary scales: F11's
//!    perfect white is about 29× A's and 16× D65's.
//!    [`Normalization::Power`] scales a light to mean spectral power 1 over
//!    380–730 nm (equal radiant power); [`Normalization::Luminance`] scales
//!    it so the perfect white has Y = 100. `None` keeps Appendix 2
//!    reproducible.
//! 2. **Gamut.** A linear sRGB with a negative component is out of gamut:
//!    see [`speclab::LinearRgb::in_gamut`].
//! 3. **White balance.** [`white_balance`] applies a Bradford adaptation
//!    ([`speclab::color::adaptation`]) from the light's white to D65's before
//!    the conversion to sRGB, so a neutral patch looks neutral.
//!
//! [`Viewing`] bundles the first and third, and says which white CIELAB is
//! taken relative to.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::reference};
//! use speclab_study::evaluate::viewing::{self, Normalization};
//! let d65 = Normalization::Luminance.apply(&lights::D65)?;
//! assert!((reference::white(&d65).y - 100.0).abs() < 1e-9);
//! let a1 = viewing::white_balance(reference::xyz(&lights::A, &patches::A1), &lights::A);
//! let rgb = a1.to_linear_srgb();
//! assert!((rgb.r - rgb.b).abs() / rgb.g < 0.05); // near-neutral after adaptation
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use crate::StudyError;
use speclab::color::Xyz;
use speclab::color::adaptation::Cat;
use speclab::named_choices;
use speclab::sampling::reference;
use speclab::spectrum::data::lights;
use speclab::spectrum::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, TabulatedSpectrum};

/// How a light is scaled before use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Normalization {
    /// As tabulated (reproduces Appendix 2).
    #[default]
    None,
    /// Mean spectral power 1 over 380–730 nm.
    Power,
    /// The perfect white under the light has Y = 100.
    Luminance,
}

named_choices!(Normalization, "a normalisation": None => "none", Power => "power", Luminance => "luminance");

impl Normalization {
    /// The factor that scales `light` as this option asks.
    #[must_use]
    pub fn factor(self, light: &TabulatedSpectrum) -> f64 {
        match self {
            Normalization::None => 1.0,
            Normalization::Power => LAMBDA_WIDTH / light.integral(LAMBDA_MIN, LAMBDA_MAX),
            Normalization::Luminance => 100.0 / reference::white(light).y,
        }
    }

    /// `light` scaled by [`Normalization::factor`]; an error if the light is
    /// dark (zero power or luminance over the range).
    pub fn apply(self, light: &TabulatedSpectrum) -> Result<TabulatedSpectrum, StudyError> {
        Ok(light.scaled(self.factor(light))?)
    }
}

/// The white that [`white_balance`] adapts to: D65's perfect white, scaled
/// to the luminance of `light`'s.
#[must_use]
pub fn target_white(light: &TabulatedSpectrum) -> Xyz {
    let d65 = reference::white(&lights::D65);
    d65 * (reference::white(light).y / d65.y)
}

/// `xyz` under `light`, white-balanced to D65 at the same luminance.
#[must_use]
pub fn white_balance(xyz: Xyz, light: &TabulatedSpectrum) -> Xyz {
    Cat::Bradford.adapt(xyz, reference::white(light), target_white(light))
}

/// How colours are viewed: the light's normalisation, and whether colours
/// are white-balanced to D65.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Viewing {
    /// How each light is scaled first.
    pub normalize: Normalization,
    /// Whether colours are Bradford-adapted to D65's white.
    pub white_balance: bool,
}

impl Viewing {
    /// `light` scaled as [`Viewing::normalize`] asks.
    pub fn light(&self, light: &TabulatedSpectrum) -> Result<TabulatedSpectrum, StudyError> {
        self.normalize.apply(light)
    }

    /// `xyz` under `light` (already normalised), white-balanced if asked.
    #[must_use]
    pub fn adapt(&self, xyz: Xyz, light: &TabulatedSpectrum) -> Xyz {
        if self.white_balance { white_balance(xyz, light) } else { xyz }
    }

    /// The white that colours under `light` end up relative to, for CIELAB:
    /// the light's own perfect white, or the D65 white it is balanced to.
    #[must_use]
    pub fn white(&self, light: &TabulatedSpectrum) -> Xyz {
        if self.white_balance { target_white(light) } else { reference::white(light) }
    }
}
