//! Reflectances outside the fitted rules' prior, named, for judging rules
//! on surfaces they were not fitted to (the prior is in
//! `sampling::prior`; the six appendix patches are not in it either).
//!
//! - [`colorchecker`]: the 24 ColorChecker Classic colours, upsampled from
//!   their published 8-bit sRGB values by [`RgbAlbedo`] (the sigmoid
//!   quadratics of RGB textures: the family of half the prior, not its
//!   members), tabulated every nm.
//! - [`edges`]: seven piecewise-linear reflectances with 20–40 nm edges,
//!   bands and a notch: a family absent from the prior (kinks, flat tops,
//!   features as narrow as F11's line spacing), harsher than pigments.
//!
//! ```
//! use speclab_study::evaluate::shapes;
//! assert_eq!(shapes::colorchecker()?.len(), 24);
//! assert_eq!(shapes::edges()?[3].name, "notch-550");
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use crate::StudyError;
use crate::display::Srgb8;
use crate::evaluate::scene::Named;
use speclab::color::RgbAlbedo;
use speclab::spectrum::{Interpolation, Role, Spectrum, TabulatedSpectrum};

/// The ColorChecker Classic's colours, 8-bit sRGB, in chart order.
const COLORCHECKER: [(&str, u32); 24] = [
    ("dark-skin", 0x73_52_44),
    ("light-skin", 0xC2_96_82),
    ("blue-sky", 0x62_7A_9D),
    ("foliage", 0x57_6C_43),
    ("blue-flower", 0x85_80_B1),
    ("bluish-green", 0x67_BD_AA),
    ("orange", 0xD6_7E_2C),
    ("purplish-blue", 0x50_5B_A6),
    ("moderate-red", 0xC1_5A_63),
    ("purple", 0x5E_3C_6C),
    ("yellow-green", 0x9D_BC_40),
    ("orange-yellow", 0xE0_A3_2E),
    ("blue", 0x38_3D_96),
    ("green", 0x46_94_49),
    ("red", 0xAF_36_3C),
    ("yellow", 0xE7_C7_1F),
    ("magenta", 0xBB_56_95),
    ("cyan", 0x08_85_A1),
    ("white", 0xF3_F3_F2),
    ("neutral-8", 0xC8_C8_C8),
    ("neutral-6.5", 0xA0_A0_A0),
    ("neutral-5", 0x7A_7A_79),
    ("neutral-3.5", 0x55_55_55),
    ("black", 0x34_34_34),
];

/// The 24 ColorChecker colours as reflectances (see the module overview).
pub fn colorchecker() -> Result<Vec<Named>, StudyError> {
    COLORCHECKER
        .iter()
        .map(|&(name, hex)| {
            let [_, r, g, b] = hex.to_be_bytes();
            let albedo = RgbAlbedo::new(Srgb8::new(r, g, b).to_encoded().decode())?;
            let lambda: Vec<f64> = (380..=730).map(f64::from).collect();
            let values = lambda.iter().map(|&l| albedo.eval(l)).collect();
            Ok(Named::new(name, TabulatedSpectrum::new(lambda, values, Role::Reflectance)?))
        })
        .collect()
}

/// The seven edge shapes: `(name, [(nm, reflectance)])`, linear between.
const EDGES: [(&str, &[(f64, f64)]); 7] = [
    ("step-up-500", &[(380.0, 0.05), (480.0, 0.05), (520.0, 0.85), (730.0, 0.85)]),
    ("step-down-600", &[(380.0, 0.85), (580.0, 0.85), (620.0, 0.05), (730.0, 0.05)]),
    ("band-450", &[(380.0, 0.05), (420.0, 0.05), (440.0, 0.8), (460.0, 0.8), (480.0, 0.05), (730.0, 0.05)]),
    ("notch-550", &[(380.0, 0.8), (520.0, 0.8), (540.0, 0.1), (560.0, 0.1), (580.0, 0.8), (730.0, 0.8)]),
    ("band-620", &[(380.0, 0.05), (590.0, 0.05), (610.0, 0.85), (630.0, 0.85), (650.0, 0.05), (730.0, 0.05)]),
    ("ramp", &[(380.0, 0.1), (730.0, 0.9)]),
    ("dark-grey", &[(380.0, 0.03), (730.0, 0.03)]),
];

/// The seven edge shapes as reflectances (see the module overview).
pub fn edges() -> Result<Vec<Named>, StudyError> {
    EDGES
        .iter()
        .map(|&(name, points)| {
            let (lambda, values) = points.iter().copied().unzip();
            let s = TabulatedSpectrum::with_interpolation(
                lambda,
                values,
                Role::Reflectance,
                Interpolation::Linear,
            )?;
            Ok(Named::new(name, s))
        })
        .collect()
}
