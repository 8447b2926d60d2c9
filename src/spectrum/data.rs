//! The built-in spectra, static data generated at build time from `data/`
//! (provenance, units, step and range of every set in `data/SOURCES.md`;
//! each static's documentation repeats its file's header).
//!
//! `build.rs` reads every file with `speclab_tables::Codegen`, the build
//! helper users get too, validates it for its kind and emits the samples
//! plus precomputed segment coefficients. Grouped so that a light cannot be
//! passed where an index of refraction is meant:
//!
//! - [`lights`]: the assignment's `A`, `D65`, `F11` (Appendix 1, as
//!   printed: Appendix 2 depends on them) and the CIE's: `CIE_A`,
//!   `CIE_D65`, `D50`, `D55`, `D75`, `E`, `F1`–`F12` (the assignment's
//!   `F11` is the CIE's FL11, value for value), `FL3_1`–`FL3_15`,
//!   `HP1`–`HP5`, `LED_B1`–`LED_B5`, `LED_BH1`, `LED_RGB1`, `LED_V1`,
//!   `LED_V2`; by name ([`Light`], [`lights::named`]), and CIE daylight at
//!   any temperature ([`lights::daylight`]).
//! - [`patches`], ColorChecker SG (10 nm, cubic, 380–730 nm): `E2`, `F4`,
//!   `G4`, `H4`, `J4`, `A1`; also by name, [`Patch`].
//! - [`conductors`]: η and k of `AG`, `AL`, `AU`, `CR`, `CU`, `CUZN`,
//!   `MGO`, `NI`, `PT`, `TI`, `TIO2`, `W` ([`Conductor`]s; their
//!   normal-incidence reflectance is a surface).
//! - [`glasses`]: SCHOTT `N_BK7`, `N_BAF10`, `N_FK51A`, `N_LASF9`, `N_SF5`,
//!   `N_SF10`, `N_SF11` ([`Sellmeier`] formulas; pbrt-v4's seven glasses).
//! - [`daylight`]: the CIE daylight components `S0`, `S1`, `S2`.
//! - [`cie1931`], the 2° matching functions (5 nm, cubic, 380–780 nm):
//!   `X_BAR`, `Y_BAR`, `Z_BAR`.
//!
//! What a program does not use costs nothing at run time: the tables are
//! `static` data.
//!
//! ```
//! use speclab::data::{conductors, lights, patches, Light, Patch};
//! use speclab::Spectrum;
//! assert_eq!(lights::F11.eval(545.0), 72.84);
//! assert_eq!("f11".parse::<Light>()?.spectrum(), &lights::F11);
//! assert_eq!("LED-B3".parse::<Light>()?.spectrum(), &lights::LED_B3);
//! assert_eq!(Patch::A1.to_string(), "A1");
//! assert!(patches::A1.eval(555.0) > 0.8);
//! let d5000 = lights::named("D5000")?; // CIE daylight at 5000 K (nominal)
//! assert!((d5000.eval(560.0) - 100.0).abs() < 1e-9);
//! assert!(conductors::AU.reflectance().eval(700.0) > 0.95);
//! # Ok::<(), speclab::Error>(())
//! ```
//!
//! [`Conductor`]: crate::spectrum::Conductor
//! [`Sellmeier`]: crate::spectrum::Sellmeier

use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

use crate::error::Error;
use crate::spectrum::TabulatedSpectrum;

mod generated {
    include!(concat!(env!("OUT_DIR"), "/data.rs"));
}

/// Every built-in light (relative spectral power; see `data/SOURCES.md`),
/// the list of them, and CIE daylight at any temperature.
pub mod lights {
    pub use super::generated::lights::*;

    use crate::error::Error;
    use crate::spectrum::{PlanckConstants, Role, TabulatedSpectrum};

    /// pbrt-v4's names for the CIE illuminants it ships, each with the
    /// built-in light it names: what a scene ported from pbrt-v4 types.
    /// (`D65`, `A` and `F11` are the assignment's tables, which Appendix 2
    /// uses; pbrt-v4's `stdillum-D65` and `stdillum-A` are the CIE's,
    /// `CIE-D65` and `CIE-A` here.)
    pub const ALIASES: [(&str, &str); 15] = [
        ("stdillum-A", "CIE-A"),
        ("stdillum-D50", "D50"),
        ("stdillum-D65", "CIE-D65"),
        ("stdillum-F1", "F1"),
        ("stdillum-F2", "F2"),
        ("stdillum-F3", "F3"),
        ("stdillum-F4", "F4"),
        ("stdillum-F5", "F5"),
        ("stdillum-F6", "F6"),
        ("stdillum-F7", "F7"),
        ("stdillum-F8", "F8"),
        ("stdillum-F9", "F9"),
        ("stdillum-F10", "F10"),
        ("stdillum-F11", "F11"),
        ("stdillum-F12", "F12"),
    ];

    /// The light named `name` (any case): a built-in one ([`NAMES`]; `A`,
    /// `D65` and `F11` are the assignment's tables, `CIE-A` and `CIE-D65`
    /// the CIE's), pbrt-v4's name for one ([`ALIASES`], e.g.
    /// `stdillum-D65`), or `D` and a temperature in kelvin for CIE
    /// daylight ([`daylight`]), e.g. `D5000`. An [`Error::UnknownName`]
    /// names the nearest names.
    pub fn named(name: &str) -> Result<std::borrow::Cow<'static, TabulatedSpectrum>, Error> {
        let alias = ALIASES.iter().find(|(a, _)| a.eq_ignore_ascii_case(name)).map_or(name, |&(_, n)| n);
        if let Some(light) = super::find(&ALL, alias) {
            return Ok(std::borrow::Cow::Borrowed(light));
        }
        let kelvin = name.strip_prefix(['D', 'd']).and_then(|t| t.parse::<f64>().ok());
        match kelvin {
            Some(kelvin) if kelvin >= 1000.0 => daylight(kelvin).map(std::borrow::Cow::Owned),
            _ => Err(super::unknown("a built-in light or D and a temperature (D5000)", &NAMES, name)),
        }
    }

    /// CIE daylight at the nominal correlated colour temperature `kelvin`
    /// (4000–25000 K): `S₀ + M₁·S₁ + M₂·S₂` (CIE 015:2018, 4.1.2), at the
    /// temperature `kelvin · 1.4388/1.4380` (the nominal temperatures of
    /// the D illuminants predate the current c₂: `daylight(6500.0)` is
    /// D65's formula), M₁ and M₂ rounded to three decimals as the CIE
    /// computes them. Tabulated every 5 nm from 300 to 830 nm, linear
    /// between; 100 at 560 nm. It reproduces the CIE's D50, D55, D65 and
    /// D75 tables to their rounding (`tests/truth/named.rs`).
    pub fn daylight(kelvin: f64) -> Result<TabulatedSpectrum, Error> {
        daylight_with(kelvin, PlanckConstants::CIE)
    }

    /// [`daylight`] on the temperature scale of `constants`' c₂: at
    /// `kelvin · c₂/1.4380e-2` (with [`PlanckConstants::CIE`], `daylight`).
    pub fn daylight_with(kelvin: f64, constants: PlanckConstants) -> Result<TabulatedSpectrum, Error> {
        if !(4000.0..=25000.0).contains(&kelvin) {
            return Err(Error::Daylight { kelvin });
        }
        let [x, y] = daylight_xy(kelvin * constants.c2 / 1.4380e-2)?;
        let m = 0.0241 + 0.2562 * x - 0.7341 * y;
        let round = |v: f64| (v * 1000.0).round() / 1000.0;
        let (m1, m2) =
            (round((-1.3515 - 1.7703 * x + 5.9114 * y) / m), round((0.0300 - 31.4424 * x + 30.0717 * y) / m));
        let [s0, s1, s2] = [&super::daylight::S0, &super::daylight::S1, &super::daylight::S2];
        let values =
            s0.values().iter().zip(s1.values()).zip(s2.values()).map(|((a, b), c)| a + m1 * b + m2 * c);
        TabulatedSpectrum::new(s0.lambda().to_vec(), values.collect(), Role::Light)
    }

    /// The chromaticity `[x, y]` of CIE daylight at the correlated colour
    /// temperature `cct` K on the current scale (CIE 015:2018, eqs. 4.7–4.9:
    /// the daylight locus), 4000–25000 K (to 25014 K, so that every nominal
    /// temperature [`daylight`] takes has one).
    ///
    /// ```
    /// // The locus near D65 (whose tabulated spectrum has xy 0.31272, 0.32903).
    /// let [x, y] = speclab::data::lights::daylight_xy(6504.0)?;
    /// assert!((x - 0.312_71).abs() < 1e-5 && (y - 0.329_12).abs() < 1e-5);
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn daylight_xy(cct: f64) -> Result<[f64; 2], Error> {
        if !(4000.0..=25000.0 * 1.4388 / 1.4380).contains(&cct) {
            return Err(Error::Daylight { kelvin: cct });
        }
        let x = if cct <= 7000.0 {
            -4.6070e9 / cct.powi(3) + 2.9678e6 / cct.powi(2) + 0.09911e3 / cct + 0.244063
        } else {
            -2.0064e9 / cct.powi(3) + 1.9018e6 / cct.powi(2) + 0.24748e3 / cct + 0.237040
        };
        Ok([x, -3.000 * x * x + 2.870 * x - 0.275])
    }
}

/// The six ColorChecker SG patches of the appendix (reflectance, 0–1), in
/// Appendix 2's order, and the list of them.
pub mod patches {
    pub use super::generated::patches::*;

    use crate::error::Error;
    use crate::spectrum::TabulatedSpectrum;

    /// The patch named `name` (any case, [`NAMES`]).
    pub fn named(name: &str) -> Result<&'static TabulatedSpectrum, Error> {
        super::find(&ALL, name).ok_or_else(|| super::unknown("a built-in patch", &NAMES, name))
    }
}

/// Conductors' complex refractive indices `η + i·k` (refractiveindex.info
/// data; see `data/SOURCES.md`), and the list of them.
pub mod conductors {
    pub use super::generated::conductors::*;

    use crate::error::Error;
    use crate::spectrum::Conductor;

    /// The conductor named `name` (any case, [`NAMES`]).
    pub fn named(name: &str) -> Result<&'static Conductor<'static>, Error> {
        super::find(&ALL, name).ok_or_else(|| super::unknown("a built-in conductor", &NAMES, name))
    }
}

/// Dielectrics' refractive indices: pbrt-v4's seven glasses, as the
/// SCHOTT catalogue's Sellmeier formulas (pbrt-v4 calls them glass-BK7,
/// -BAF10, -FK51A, -LASF9, -F5, -F10, -F11; the last three are N-SF5,
/// N-SF10 and N-SF11), and the list of them.
pub mod glasses {
    pub use super::generated::glasses::*;

    use crate::error::Error;
    use crate::spectrum::Sellmeier;

    /// The glass named `name` (any case, [`NAMES`]: `N-BK7`, …).
    pub fn named(name: &str) -> Result<&'static Sellmeier, Error> {
        super::find(&ALL, name).ok_or_else(|| super::unknown("a built-in glass", &NAMES, name))
    }
}

/// The CIE daylight components S₀, S₁, S₂ (5 nm, 300–830 nm, linear).
pub mod daylight {
    pub use super::generated::daylight::*;
}

/// The CIE 1931 2° standard observer's matching functions x̄, ȳ, z̄.
pub mod cie1931 {
    pub use super::generated::cie1931::{CIE_X as X_BAR, CIE_Y as Y_BAR, CIE_Z as Z_BAR};
}

/// The CIE's standard observers at 1 nm, 360–830 nm, as `[x̄, ȳ, z̄]` rows
/// (`data/observers/`; read them through [`crate::spectrum::StandardObserver`]).
pub mod observers {
    pub use super::generated::observers::*;
}

/// Seventeen cameras' r, g, b response curves at 10 nm, 380–720 nm
/// (pbrt-v4's PhysLight data, `data/sensors/`; read them through
/// [`crate::film::Sensor::camera`]).
pub mod sensors {
    pub use super::generated::sensors::*;
}

pub(crate) use generated::XYZ_TO_SRGB;
pub(crate) use generated::cie1931::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA,
};

/// The entry of `list` named `name`, in any case: the one lookup by name
/// of every built-in list.
fn find<T: ?Sized>(list: &[(&str, &'static T)], name: &str) -> Option<&'static T> {
    list.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|&(_, t)| t)
}

/// An [`Error::UnknownName`] for `found` among `names`.
fn unknown(what: &'static str, names: &'static [&'static str], found: &str) -> Error {
    Error::UnknownName { what, expected: names, found: found.to_string() }
}

/// A built-in spectrum by its place in a generated list: a `Copy` handle
/// with a name and a static spectrum, one constant per name
/// (`Light::F11`, `Patch::G4`), `ALL` in the list's order, parsed from
/// its name in any case.
macro_rules! handle {
    ($ty:ident, $list:ident, $what:literal) => {
        impl $ty {
            /// The name, as on command lines (`A`, `CIE-D65`, `G4`).
            #[must_use]
            pub fn name(self) -> &'static str {
                $list::ALL[self.0].0
            }

            /// The spectrum.
            #[must_use]
            pub fn spectrum(self) -> &'static TabulatedSpectrum {
                $list::ALL[self.0].1
            }
        }

        impl fmt::Display for $ty {
            /// The name used on command lines, in tables and in CSV.
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(self.name())
            }
        }

        impl fmt::Debug for $ty {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!(stringify!($ty), "({})"), self.name())
            }
        }

        impl FromStr for $ty {
            type Err = Error;
            /// The built-in one of this name, in any case.
            fn from_str(s: &str) -> Result<Self, Error> {
                let found = $list::NAMES.iter().position(|n| n.eq_ignore_ascii_case(s));
                found.map($ty).ok_or_else(|| unknown($what, &$list::NAMES, s))
            }
        }
    };
}

/// A built-in light, by its place in [`lights::ALL`] (the appendix's
/// three first): `Light::F11`, `Light::CIE_D65`, `"led-b3".parse()`.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Light(usize);

handle!(Light, lights, "a built-in light");

impl Light {
    /// The assignment's three lights, in the order of Appendix 2's columns.
    pub const APPENDIX: [Light; 3] = [Light::A, Light::D65, Light::F11];
}

/// One of the six ColorChecker SG patches of the appendix, by its place in
/// [`patches::ALL`] (Appendix 2's row order): `Patch::G4`, `"a1".parse()`.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Patch(usize);

handle!(Patch, patches, "a built-in patch");

/// The names of the built-in surfaces: the patches, then the conductors.
pub const SURFACE_NAMES: [&str; patches::NAMES.len() + conductors::NAMES.len()] = surface_names();

const fn surface_names() -> [&'static str; patches::NAMES.len() + conductors::NAMES.len()] {
    let mut out = [""; patches::NAMES.len() + conductors::NAMES.len()];
    let p = patches::NAMES.len();
    let mut i = 0;
    while i < out.len() {
        out[i] = if i < p { patches::NAMES[i] } else { conductors::NAMES[i - p] };
        i += 1;
    }
    out
}

/// The surface named `name` (any case): a patch, or a conductor's
/// normal-incidence reflectance tabulated every nanometre
/// ([`NormalReflectance::tabulated`](crate::spectrum::NormalReflectance::tabulated)).
pub fn surface_named(name: &str) -> Result<Cow<'static, TabulatedSpectrum>, Error> {
    if let Some(patch) = find(&patches::ALL, name) {
        return Ok(Cow::Borrowed(patch));
    }
    match find(&conductors::ALL, name) {
        Some(c) => Ok(Cow::Owned(c.reflectance().tabulated())),
        None => Err(unknown("a built-in surface", &SURFACE_NAMES, name)),
    }
}
