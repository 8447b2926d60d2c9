//! The five built-in spaces, each its own type, so that a program links a
//! space's RGB table only where it turns that space's colours into
//! spectra.
//!
//! [`RgbSpace::srgb`] and its siblings return a `&'static BuiltIn<S>`: it
//! derefs to the [`RgbSpace`] (name, primaries, white, matrices, the fit),
//! which never names a table, and its own [`albedo`](BuiltIn::albedo),
//! [`unbounded`](BuiltIn::unbounded), [`unbounded_up_to_one`](BuiltIn::unbounded_up_to_one) and
//! [`light`](BuiltIn::light) look colours up in that space's table alone
//! (1.5–2.6 MB of compact data each). The same calls through a
//! `&RgbSpace` (a space chosen at run time) work too, and link the five.
//!
//! ```
//! use speclab::LinearRgb;
//! use speclab::color::{RgbSpace, BuiltIn, builtin::AcesCg};
//! let acescg: &BuiltIn<AcesCg> = RgbSpace::acescg();
//! let matrix = acescg.to_xyz_matrix(); // no table in the program for this
//! let albedo = acescg.albedo(LinearRgb::new(0.5, 0.25, 0.1))?; // ACEScg's table, and no other
//! let erased: &RgbSpace = acescg; // a space chosen at run time
//! assert_eq!(erased.albedo(LinearRgb::new(0.5, 0.25, 0.1))?, albedo);
//! assert!(matrix[1][1] > 0.0);
//! # Ok::<(), speclab::Error>(())
//! ```

use std::marker::PhantomData;
use std::ops::Deref;
use std::sync::OnceLock;

use crate::color::rgb::LinearRgb;
use crate::color::rgb_spectra::{RgbAlbedo, RgbIlluminant, RgbUnbounded, Split};
use crate::color::rgb_table::{BuiltInTable, RgbTable};
use crate::color::space::{ACES, D65, RgbSpace, aces_d60, standard};
use crate::color::space_spectra::{Clamp, reflectance_in, unbounded_in};
use crate::error::Error;
use crate::spectrum::data::lights;

/// A built-in space as a type: the [`RgbSpace`] it derefs to, and the
/// spectra of its colours from its own table ([`Table`]).
#[derive(Debug)]
pub struct BuiltIn<S> {
    space: RgbSpace,
    which: PhantomData<S>,
}

impl<S> Clone for BuiltIn<S> {
    fn clone(&self) -> Self {
        BuiltIn { space: self.space.clone(), which: PhantomData }
    }
}

impl<S> Deref for BuiltIn<S> {
    type Target = RgbSpace;

    fn deref(&self) -> &RgbSpace {
        &self.space
    }
}

/// How a built-in space finds its table: each marker type names its own.
pub trait Table: sealed::Sealed {
    /// The table of `space` (this marker's space).
    fn table(space: &RgbSpace) -> &RgbTable;
}

mod sealed {
    pub trait Sealed {}
}

/// Declares a marker type and its table.
macro_rules! marker {
    ($(#[$doc:meta])* $name:ident, $table:ident, $feature:meta) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug)]
        pub struct $name;
        impl sealed::Sealed for $name {}
        impl Table for $name {
            #[inline(always)]
            fn table(space: &RgbSpace) -> &RgbTable {
                #[cfg($feature)]
                let table = {
                    let _ = space;
                    RgbTable::$table
                };
                // Without the tables' crate, fitted on first use.
                #[cfg(not($feature))]
                let table = space.fitted_table();
                table
            }
        }
    };
}

marker!(
    /// Linear sRGB ([`RgbSpace::srgb`]).
    Srgb, SRGB, all()
);
marker!(
    /// Display P3 ([`RgbSpace::display_p3`]).
    DisplayP3, DISPLAY_P3, feature = "wide-gamut"
);
marker!(
    /// ITU-R BT.2020 ([`RgbSpace::rec2020`]).
    Rec2020, REC2020, feature = "wide-gamut"
);
marker!(
    /// ACES2065-1 ([`RgbSpace::aces2065_1`]).
    Aces2065, ACES2065_1, feature = "wide-gamut"
);
marker!(
    /// ACEScg ([`RgbSpace::acescg`]).
    AcesCg, ACESCG, feature = "wide-gamut"
);

impl<S: Table> BuiltIn<S> {
    /// The space's table ([`RgbSpace::table`]'s, without naming the others).
    #[must_use]
    #[inline]
    pub fn table(&self) -> &RgbTable {
        S::table(&self.space)
    }

    /// [`RgbSpace::albedo`], by this space's table alone.
    #[inline]
    pub fn albedo(&self, rgb: impl Into<LinearRgb>) -> Result<RgbAlbedo, Error> {
        self.table().albedo(rgb)
    }

    /// [`RgbSpace::reflectance`], by this space's table alone.
    #[inline]
    pub fn reflectance(&self, rgb: impl Into<LinearRgb>) -> (RgbAlbedo, [Clamp; 3]) {
        reflectance_in(self.table(), rgb.into())
    }

    /// [`RgbSpace::unbounded`], by this space's table alone.
    #[must_use]
    pub fn unbounded(&self, rgb: impl Into<LinearRgb>) -> RgbUnbounded {
        unbounded_in(self.table(), rgb.into(), Split::Twice)
    }

    /// [`RgbSpace::unbounded_up_to_one`], by this space's table alone.
    #[must_use]
    pub fn unbounded_up_to_one(&self, rgb: impl Into<LinearRgb>) -> RgbUnbounded {
        unbounded_in(self.table(), rgb.into(), Split::UpToOne)
    }

    /// [`RgbSpace::light`], by this space's table alone.
    #[must_use]
    pub fn light(&self, rgb: impl Into<LinearRgb>) -> RgbIlluminant {
        self.space.light_in(self.table(), rgb.into())
    }

    /// [`RgbSpace::with_table`]: the space (erased) with `table` instead.
    pub fn with_table(self, table: RgbTable) -> Result<RgbSpace, Error> {
        self.space.with_table(table)
    }
}

/// A built-in space, made once.
fn built_in<S>(
    cell: &'static OnceLock<BuiltIn<S>>,
    make: impl FnOnce() -> RgbSpace,
    table: BuiltInTable,
) -> &'static BuiltIn<S> {
    cell.get_or_init(|| {
        let mut space = make();
        space.built_in = Some(table);
        BuiltIn { space, which: PhantomData }
    })
}

impl RgbSpace {
    /// Linear sRGB: IEC 61966-2-1's primaries (those of ITU-R BT.709) and
    /// D65 (0.3127, 0.3290), spectra under the CIE's D65.
    #[must_use]
    pub fn srgb() -> &'static BuiltIn<Srgb> {
        static SPACE: OnceLock<BuiltIn<Srgb>> = OnceLock::new();
        let make = || standard("sRGB", [[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]], D65, &lights::CIE_D65);
        built_in(&SPACE, make, BuiltInTable::Srgb)
    }

    /// Display P3: the P3 primaries of SMPTE EG 432-1 with D65, as Apple's
    /// displays use them; spectra under the CIE's D65.
    #[must_use]
    pub fn display_p3() -> &'static BuiltIn<DisplayP3> {
        static SPACE: OnceLock<BuiltIn<DisplayP3>> = OnceLock::new();
        let primaries = [[0.680, 0.320], [0.265, 0.690], [0.150, 0.060]];
        built_in(&SPACE, || standard("Display P3", primaries, D65, &lights::CIE_D65), BuiltInTable::DisplayP3)
    }

    /// ITU-R BT.2020 (Rec. 2020): spectral primaries at 630, 532 and
    /// 467 nm, D65; spectra under the CIE's D65.
    #[must_use]
    pub fn rec2020() -> &'static BuiltIn<Rec2020> {
        static SPACE: OnceLock<BuiltIn<Rec2020>> = OnceLock::new();
        let primaries = [[0.708, 0.292], [0.170, 0.797], [0.131, 0.046]];
        built_in(&SPACE, || standard("Rec.2020", primaries, D65, &lights::CIE_D65), BuiltInTable::Rec2020)
    }

    /// ACES2065-1 (SMPTE ST 2065-1): the AP0 primaries, which enclose every
    /// colour (two are not colours), and the ACES white (0.32168, 0.33767);
    /// spectra under CIE daylight at 6000 K, whose chromaticity the ACES
    /// white is (TB-2018-001).
    #[must_use]
    pub fn aces2065_1() -> &'static BuiltIn<Aces2065> {
        static SPACE: OnceLock<BuiltIn<Aces2065>> = OnceLock::new();
        let primaries = [[0.7347, 0.2653], [0.0, 1.0], [0.0001, -0.0770]];
        built_in(&SPACE, || standard("ACES2065-1", primaries, ACES, aces_d60()), BuiltInTable::Aces2065_1)
    }

    /// ACEScg (ACES S-2014-004): the AP1 primaries, a working space for
    /// rendering, and the ACES white; spectra under CIE daylight at 6000 K.
    #[must_use]
    pub fn acescg() -> &'static BuiltIn<AcesCg> {
        static SPACE: OnceLock<BuiltIn<AcesCg>> = OnceLock::new();
        let primaries = [[0.713, 0.293], [0.165, 0.830], [0.128, 0.044]];
        built_in(&SPACE, || standard("ACEScg", primaries, ACES, aces_d60()), BuiltInTable::AcesCg)
    }

    /// The five built-in spaces, erased: their spectra link all five
    /// tables ([`RgbSpace::table`]).
    #[must_use]
    pub fn all() -> [&'static RgbSpace; 5] {
        [&**Self::srgb(), Self::display_p3(), Self::rec2020(), Self::aces2065_1(), Self::acescg()]
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
    /// [`RgbSpace::srgb`]'s [`unbounded`](BuiltIn::unbounded) (negative
    /// and NaN components are taken as 0: outside the gamut, there is no
    /// spectrum), looked up in sRGB's embedded table.
    #[must_use]
    pub fn new(rgb: LinearRgb) -> Self {
        RgbSpace::srgb().unbounded(rgb)
    }
}

impl RgbIlluminant {
    /// A light of linear sRGB colour `rgb`: [`RgbSpace::srgb`]'s
    /// [`light`](BuiltIn::light), the CIE's D65 tinted, normalised so that
    /// (1, 1, 1) has the luminance of a constant spectrum of 1 (`Y = ∫ȳ`),
    /// looked up in sRGB's embedded table.
    #[must_use]
    pub fn new(rgb: LinearRgb) -> Self {
        RgbSpace::srgb().light(rgb)
    }
}
