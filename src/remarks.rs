//! The assignment's three remarks as options: normalisation of the light,
//! gamut, and white balance.
//!
//! 1. **Normalisation.** The appendix lights have arbitrary scales (F11 is
//!    about 15× brighter than A and D65). [`Normalization::Power`] scales a
//!    light to mean spectral power 1 over 380–730 nm (equal radiant power);
//!    [`Normalization::Luminance`] scales it so the perfect white has
//!    Y = 100. `None` keeps Appendix 2 reproducible.
//! 2. **Gamut.** A linear sRGB with a negative component is out of gamut:
//!    see [`crate::LinearSrgb::in_gamut`].
//! 3. **White balance.** [`white_balance`] applies a Bradford (von Kries in
//!    Bradford's cone space) adaptation from the light's white to D65's
//!    before the conversion to sRGB, so a neutral patch looks neutral.
//!
//! ```
//! use speclab::{data, reference, remarks::{self, Normalization}};
//! let d65 = Normalization::Luminance.apply(&data::D65)?;
//! assert!((reference::white(&d65).y - 100.0).abs() < 1e-9);
//! let a1 = remarks::white_balance(reference::xyz(&data::A, &data::A1), &data::A);
//! let rgb = a1.to_linear_srgb();
//! assert!((rgb.r - rgb.b).abs() / rgb.g < 0.05); // near-neutral after adaptation
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::{Matrix, inverse, mul};
use crate::{Error, LAMBDA_MAX, LAMBDA_MIN, TabulatedSpectrum, WIDTH, Xyz, data, reference};

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

impl Normalization {
    /// All options, in CLI order.
    pub const ALL: [Normalization; 3] = [Normalization::None, Normalization::Power, Normalization::Luminance];

    /// The name used on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Normalization::None => "none",
            Normalization::Power => "power",
            Normalization::Luminance => "luminance",
        }
    }

    /// The option with this name.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Normalization> {
        Normalization::ALL.into_iter().find(|n| n.name() == name)
    }

    /// The factor that scales `light` as this option asks.
    #[must_use]
    pub fn factor(self, light: &TabulatedSpectrum) -> f64 {
        match self {
            Normalization::None => 1.0,
            Normalization::Power => WIDTH / light.integral(LAMBDA_MIN, LAMBDA_MAX),
            Normalization::Luminance => 100.0 / reference::white(light).y,
        }
    }

    /// `light` scaled by [`Normalization::factor`]; an error if the light is
    /// dark (zero power or luminance over the range).
    pub fn apply(self, light: &TabulatedSpectrum) -> Result<TabulatedSpectrum, Error> {
        light.scaled(self.factor(light))
    }
}

/// Bradford's cone response matrix (Lam 1985).
const BRADFORD: Matrix = [[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]];

/// `xyz` seen under `from_white`, adapted to `to_white` (Bradford).
#[must_use]
pub fn bradford(xyz: Xyz, from_white: Xyz, to_white: Xyz) -> Xyz {
    let (c, s, d) = (
        mul(&BRADFORD, xyz.to_array()),
        mul(&BRADFORD, from_white.to_array()),
        mul(&BRADFORD, to_white.to_array()),
    );
    let adapted = [0, 1, 2].map(|i| c[i] * d[i] / s[i]);
    let [x, y, z] = mul(&inverse(&BRADFORD), adapted);
    Xyz::new(x, y, z)
}

/// The white that [`white_balance`] adapts to: D65's perfect white, scaled
/// to the luminance of `light`'s.
#[must_use]
pub fn target_white(light: &TabulatedSpectrum) -> Xyz {
    let d65 = reference::white(&data::D65);
    d65 * (reference::white(light).y / d65.y)
}

/// `xyz` under `light`, white-balanced to D65 at the same luminance.
#[must_use]
pub fn white_balance(xyz: Xyz, light: &TabulatedSpectrum) -> Xyz {
    bradford(xyz, reference::white(light), target_white(light))
}
