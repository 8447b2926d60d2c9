//! RGB working spaces: linear RGB defined by three primaries and a white
//! point (their CIE 1931 xy chromaticities), and the illuminant whose
//! spectrum an RGB colour's spectrum is made under.
//!
//! Each space's RGB → XYZ matrix is *derived* from its chromaticities
//! (SMPTE RP 177's normalised primary matrix: the white has Y = 1 and is
//! `(1, 1, 1)`), never typed in; the tests hold each against the matrix or
//! the luminance coefficients its standard publishes. The five built-in
//! spaces:
//!
//! | space | primaries | white | illuminant |
//! |---|---|---|---|
//! | [`RgbSpace::srgb`] | IEC 61966-2-1 (Rec. 709) | D65 | CIE D65 |
//! | [`RgbSpace::display_p3`] | SMPTE EG 432-1 (P3) | D65 | CIE D65 |
//! | [`RgbSpace::rec2020`] | ITU-R BT.2020 | D65 | CIE D65 |
//! | [`RgbSpace::aces2065_1`] | SMPTE ST 2065-1 (AP0) | ACES (≈ D60) | CIE daylight at 6000 K |
//! | [`RgbSpace::acescg`] | ACES S-2014-004 (AP1) | ACES (≈ D60) | CIE daylight at 6000 K |
//!
//! **Which sRGB matrix.** [`RgbSpace::srgb`] is the renderer's: derived from
//! IEC 61966-2-1's primaries and D65, as pbrt-v4's and Mitsuba 3's sRGB are;
//! it agrees with the standard's published four-decimal matrix to its
//! rounding. [`crate::Xyz::to_linear_srgb`] is the assignment's: Appendix 1
//! part D's matrix as printed, which Appendix 2's numbers use. They differ
//! by up to 5e-4.
//!
//! **Spectra of RGB colours** in a space ([`RgbSpace::albedo`],
//! [`RgbSpace::unbounded`], [`RgbSpace::light`], defined with the table
//! and the fit in `space_spectra.rs`) are made under the space's
//! illuminant ([`RgbSpace::illuminant`]): an albedo's colour under it is
//! the RGB it was made from. Integrals run over 380–730 nm like every
//! colour here, where the illuminant's white is not exactly the published
//! white point (D65's chromaticity over 380–730 nm is off by about 1e-4):
//! the fit balances each channel so that the perfect reflector is
//! `(1, 1, 1)` exactly.
//!
//! ```
//! use speclab::color::{LinearRgb, space::RgbSpace};
//! let (acescg, rec2020) = (RgbSpace::acescg(), RgbSpace::rec2020());
//! let texel = LinearRgb::new(0.6, 0.3, 0.1); // an ACEScg texture's colour
//! let xyz = acescg.xyz(texel);
//! let shown = rec2020.rgb(xyz); // on a Rec.2020 display (same XYZ, a different white: no adaptation)
//! assert!((rec2020.xyz(shown) - xyz).to_array().iter().all(|d| d.abs() < 1e-12));
//! assert!((acescg.xyz(LinearRgb::splat(1.0)).y - 1.0).abs() < 1e-12); // white has Y = 1
//! ```
//!
//! A scene as a pbrt-v4 user writes one: textures in ACEScg, a blackbody
//! emitter in absolute units, hero wavelengths in f32, XYZ normalised so
//! that a constant 1 is `Y = 1`, shown on a Rec.2020 display.
//!
//! ```
//! use speclab::color::{LinearRgb, space::RgbSpace};
//! use speclab::spectrum::{Blackbody, DenseSpectrum};
//! use speclab::{SampledSpectrum, Spectrum, Xyz, sampling::Domain};
//! let acescg = RgbSpace::acescg();
//! // A texel's reflectance, fitted for this colour alone (about 10 µs);
//! // `acescg.albedo(rgb)` looks it up in the space's embedded table instead.
//! let texel = acescg.fit_albedo(LinearRgb::new(0.5, 0.25, 0.1))?;
//! let lamp = Blackbody::absolute(3200.0)?; // W·sr⁻¹·m⁻²·nm⁻¹
//! let (light, wall) = (DenseSpectrum::new(&lamp), DenseSpectrum::new(&texel));
//! let domain = Domain::VISIBLE; // pbrt-v4's: 360–830 nm, its visible pdf, CIE 1931 at 1 nm
//! let mut pixel = Xyz::ZERO;
//! for i in 0..256_u16 {
//!     let path = domain.hero::<4, f32>((f32::from(i) + 0.5) / 256.0);
//!     let beta: SampledSpectrum<4, f32> = path.sample(&wall);
//!     pixel += path.to_xyz(beta * path.sample(&light));
//! }
//! let pixel = domain.normalized(pixel / 256.0); // Y of a constant 1 is 1
//! let exact = domain.normalized(domain.reference(&[&lamp, &texel])?);
//! assert!((pixel.y - exact.y).abs() < 0.01 * exact.y);
//! let display = RgbSpace::rec2020().rgb(pixel / pixel.y); // on a Rec.2020 display, exposed to Y = 1
//! assert!(display.r > display.g && display.g > display.b); // a warm wall under a warm lamp
//! # Ok::<(), speclab::Error>(())
//! ```

use std::sync::{Arc, OnceLock};

use crate::color::matrix::{Matrix, inverse, mul};
use crate::color::rgb::LinearRgb;
use crate::color::rgb_table::{BuiltInTable, RESOLUTION, RgbTable};
use crate::color::xyz::Xyz;
use crate::error::Error;
use crate::spectrum::TabulatedSpectrum;
use crate::spectrum::data::lights;

/// A chromaticity, CIE 1931 `[x, y]`.
pub type Chromaticity = [f64; 2];

/// A linear RGB space: primaries, white point and illuminant, the matrices
/// derived from them, and what turning its colours into spectra needs.
#[derive(Clone, Debug)]
pub struct RgbSpace {
    name: &'static str,
    primaries: [Chromaticity; 3],
    white: Chromaticity,
    to_xyz: Matrix,
    to_rgb: Matrix,
    /// What the spectra of its colours are fitted with.
    pub(crate) fit: crate::color::upsample::Fit,
    /// Its table of fitted colours, given or built on first use and
    /// shared by every clone.
    table: Arc<OnceLock<RgbTable>>,
    /// A built-in space's table, until another is given.
    pub(crate) built_in: Option<BuiltInTable>,
}

impl RgbSpace {
    /// The space of these primaries (red, green, blue) and white point,
    /// whose colours' spectra are made under `illuminant` (a light whose
    /// colour is the white point's, or near it). An [`Error::Primaries`]
    /// unless every chromaticity is finite with a non-zero y (the white's
    /// positive), and the primaries span a space (a triangle of non-zero
    /// area).
    pub fn new(
        name: &'static str,
        primaries: [Chromaticity; 3],
        white: Chromaticity,
        illuminant: &'static TabulatedSpectrum,
    ) -> Result<RgbSpace, Error> {
        let to_xyz = normalised_primary_matrix(primaries, white).ok_or(Error::Primaries)?;
        let to_rgb = inverse(&to_xyz);
        let fit = crate::color::upsample::Fit::new(illuminant, &to_rgb);
        Ok(RgbSpace { name, primaries, white, to_xyz, to_rgb, fit, table: Arc::default(), built_in: None })
    }

    /// The space's name (`sRGB`, `Display P3`, `Rec.2020`, `ACES2065-1`,
    /// `ACEScg`, or a new space's own).
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// The primaries' chromaticities: red, green, blue.
    #[must_use]
    pub fn primaries(&self) -> [Chromaticity; 3] {
        self.primaries
    }

    /// The white point's chromaticity.
    #[must_use]
    pub fn white_point(&self) -> Chromaticity {
        self.white
    }

    /// The white point's XYZ, `Y = 1`: `(1, 1, 1)` in the space.
    #[must_use]
    pub fn white(&self) -> Xyz {
        Xyz::from(mul(&self.to_xyz, [1.0; 3]))
    }

    /// The matrix taking linear RGB to XYZ (columns: the primaries' XYZ,
    /// scaled so that the white has `Y = 1`).
    #[must_use]
    pub fn to_xyz_matrix(&self) -> &Matrix {
        &self.to_xyz
    }

    /// The matrix taking XYZ to linear RGB: the inverse.
    #[must_use]
    pub fn to_rgb_matrix(&self) -> &Matrix {
        &self.to_rgb
    }

    /// XYZ of linear `rgb` (the white `(1, 1, 1)` has `Y = 1`).
    #[must_use]
    pub fn xyz(&self, rgb: impl Into<LinearRgb>) -> Xyz {
        Xyz::from(mul(&self.to_xyz, rgb.into().to_array()))
    }

    /// Linear RGB of `xyz`, unclamped (a negative component is outside
    /// the space's gamut).
    #[must_use]
    pub fn rgb(&self, xyz: Xyz) -> LinearRgb {
        LinearRgb::from(mul(&self.to_rgb, xyz.to_array()))
    }

    /// The illuminant the space's colours' spectra are made under.
    #[must_use]
    pub fn illuminant(&self) -> &'static TabulatedSpectrum {
        self.fit.illuminant
    }

    /// The space's table of sigmoid polynomials (`rgb_table::RESOLUTION`³
    /// colours per case): a built-in space's is embedded in the program
    /// (reached through `&RgbSpace`, any of the five: a program that calls
    /// this links them all; the typed [`BuiltIn`](crate::color::BuiltIn)'s own
    /// [`table`](crate::color::BuiltIn::table) links one); a space of the caller's own
    /// fits its table on first use (seconds to a minute in a release
    /// build: [`RgbTable::fit`]), shared by its clones, unless one was
    /// given ([`RgbSpace::with_table`]).
    #[must_use]
    #[inline]
    pub fn table(&self) -> &RgbTable {
        match self.built_in.and_then(BuiltInTable::table) {
            Some(table) => table,
            None => self.fitted_table(),
        }
    }

    /// The table given, or fitted now (made compact) and kept.
    pub(crate) fn fitted_table(&self) -> &RgbTable {
        self.table.get_or_init(|| RgbTable::fit(self, RESOLUTION).compact())
    }

    /// The space with `table` as its table (one saved by
    /// [`RgbTable::save`] and loaded back, one embedded by
    /// [`crate::rgb_table!`], or one a program ships): an
    /// [`Error::TableSpace`] unless the table was fitted for this space
    /// (its XYZ → RGB matrix, balanced to the white of the space's
    /// illuminant, within 1e-5 of the space's: an illuminant of the same
    /// white but another spectrum is not told apart, nor one tabulated
    /// anew to the same significant figures).
    pub fn with_table(mut self, table: RgbTable) -> Result<RgbSpace, Error> {
        if !self.fitted_for(&table) {
            return Err(Error::TableSpace { table: table.header().name, space: self.name });
        }
        self.table = Arc::new(OnceLock::from(table));
        self.built_in = None;
        Ok(self)
    }

    /// Whether `table` was fitted for this space: its matrix within
    /// [`FITTED_FOR`] of the space's balanced one.
    pub(crate) fn fitted_for(&self, table: &RgbTable) -> bool {
        let matrix = table.header().matrix;
        let mut same = matrix.iter().flatten().zip(self.fit.to_rgb.iter().flatten());
        same.all(|(a, b)| (a - b).abs() <= FITTED_FOR * b.abs().max(1.0))
    }
}

/// How far (relative) a table's balanced matrix may be from its space's.
/// Tables of one illuminant published to 6 significant figures at two
/// steps give whites a few 1e-7 apart (D65 at 5 nm, which the built-in
/// tables were fitted under, and at 1 nm: 6.0e-7); another white or other
/// primaries move the matrix by 1e-3 or more.
const FITTED_FOR: f64 = 1e-5;

/// D65's white point (CIE 15: 0.3127, 0.3290 to four decimals, as the
/// standards state it).
pub(crate) const D65: Chromaticity = [0.3127, 0.3290];
/// The ACES white point (SMPTE ST 2065-1).
pub(crate) const ACES: Chromaticity = [0.32168, 0.33767];

/// A built-in space (its chromaticities are valid).
pub(crate) fn standard(
    name: &'static str,
    primaries: [Chromaticity; 3],
    white: Chromaticity,
    illuminant: &'static TabulatedSpectrum,
) -> RgbSpace {
    RgbSpace::new(name, primaries, white, illuminant).unwrap_or_else(|_| unreachable!("{name}'s primaries"))
}

/// CIE daylight at 6000 K on the current c₂ scale (nominal 5996.7 K:
/// [`lights::daylight`] takes nominal temperatures), 5 nm.
pub(crate) fn aces_d60() -> &'static TabulatedSpectrum {
    static D60: OnceLock<TabulatedSpectrum> = OnceLock::new();
    D60.get_or_init(|| {
        lights::daylight(6000.0 * 1.4380 / 1.4388).unwrap_or_else(|_| unreachable!("6000 K is daylight"))
    })
}

/// The XYZ of chromaticity `[x, y]` with `Y = 1`.
fn xyz_of(c: Chromaticity) -> [f64; 3] {
    let [x, y] = c;
    [x / y, 1.0, (1.0 - x - y) / y]
}

/// SMPTE RP 177's normalised primary matrix: columns the primaries' XYZ
/// (`Y = 1`), each scaled so that their sum is the white's XYZ (`Y = 1`).
/// `None` for chromaticities that are not finite with a non-zero y (a
/// primary's y may be negative: ACES's AP0 blue is not a colour), a white
/// whose y is not positive, or primaries that do not span a space (their
/// triangle's area, `|det|` of the xy-chromaticity matrix, below 1e-9).
fn normalised_primary_matrix(primaries: [Chromaticity; 3], white: Chromaticity) -> Option<Matrix> {
    let valid = |c: Chromaticity| c.iter().all(|v| v.is_finite()) && c[1] != 0.0;
    if !(primaries.iter().all(|&p| valid(p)) && valid(white) && white[1] > 0.0) {
        return None;
    }
    let [[xr, yr], [xg, yg], [xb, yb]] = primaries;
    let area = (xg - xr) * (yb - yr) - (xb - xr) * (yg - yr);
    if area.abs() <= 1e-9 {
        return None;
    }
    let columns = primaries.map(xyz_of);
    let p: Matrix = std::array::from_fn(|r| std::array::from_fn(|c| columns[c][r]));
    let inv = inverse(&p);
    let s = mul(&inv, xyz_of(white));
    let m: Matrix = std::array::from_fn(|r| std::array::from_fn(|c| p[r][c] * s[c]));
    m.iter().flatten().all(|v| v.is_finite()).then_some(m)
}
