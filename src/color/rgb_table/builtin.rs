//! The built-in spaces' tables, embedded: each its compact file and its
//! tiles' cache, as `static`s, so that a program links a table only where
//! it names it ([`RgbTable::SRGB`] and its siblings); and
//! [`crate::rgb_table!`], which embeds a table of the caller's own the
//! same way.

use super::{RgbTable, TileCache};
use crate::spectrum::data::lights;

/// `∫ D65·ȳ` over 380–730 nm (the CIE's 1 nm D65, read as lines, and the
/// assignment's observer, exactly): what the D65 spaces' lights are
/// normalised by, as their fits compute it at run time (a test holds the
/// two equal to the bit; it is a `const` here so that lights can be).
pub(crate) const D65_WHITE_Y: f64 = 10566.542938675018;

/// sRGB's compact table file, once in the program (a static array: a
/// `const`, or a static reference to the bytes, could be copied into every
/// place that uses it).
static SRGB_FILE: [u8; include_bytes!("../../../data/rgb/srgb.rgbt").len()] =
    *include_bytes!("../../../data/rgb/srgb.rgbt");
static SRGB_TILES: TileCache = TileCache::new();

#[cfg(feature = "wide-gamut")]
static DISPLAY_P3_TILES: TileCache = TileCache::new();
#[cfg(feature = "wide-gamut")]
static REC2020_TILES: TileCache = TileCache::new();
#[cfg(feature = "wide-gamut")]
static ACES2065_1_TILES: TileCache = TileCache::new();
#[cfg(feature = "wide-gamut")]
static ACESCG_TILES: TileCache = TileCache::new();

impl RgbTable {
    /// Linear sRGB's table ([`RgbSpace::srgb`](crate::color::RgbSpace::srgb)'s), embedded at build time
    /// (`data/rgb/srgb.rgbt`, 1.5 MB).
    pub const SRGB: &RgbTable =
        &RgbTable::embedded(&SRGB_FILE, &SRGB_TILES).lit(&lights::CIE_D65, D65_WHITE_Y);
    /// Display P3's table ([`RgbSpace::display_p3`](crate::color::RgbSpace::display_p3)'s), from
    /// `speclab-wide-gamut` (feature `wide-gamut`, on by default).
    #[cfg(feature = "wide-gamut")]
    pub const DISPLAY_P3: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::DISPLAY_P3, &DISPLAY_P3_TILES)
        .lit(&lights::CIE_D65, D65_WHITE_Y);
    /// Rec.2020's table ([`RgbSpace::rec2020`](crate::color::RgbSpace::rec2020)'s), as [`RgbTable::DISPLAY_P3`].
    #[cfg(feature = "wide-gamut")]
    pub const REC2020: &RgbTable =
        &RgbTable::embedded(&speclab_wide_gamut::REC2020, &REC2020_TILES).lit(&lights::CIE_D65, D65_WHITE_Y);
    /// ACES2065-1's table ([`RgbSpace::aces2065_1`](crate::color::RgbSpace::aces2065_1)'s), as [`RgbTable::DISPLAY_P3`].
    #[cfg(feature = "wide-gamut")]
    pub const ACES2065_1: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::ACES2065_1, &ACES2065_1_TILES);
    /// ACEScg's table ([`RgbSpace::acescg`](crate::color::RgbSpace::acescg)'s), as [`RgbTable::DISPLAY_P3`].
    #[cfg(feature = "wide-gamut")]
    pub const ACESCG: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::ACESCG, &ACESCG_TILES);
}

/// A table file embedded in the program, as a `&'static RgbTable`: the
/// file's bytes and its tiles' cache as `static`s, so that it is in the
/// program once, its first lookup decodes one tile (about 1 ms) and its
/// colours can be `const`s. The path is `include_bytes!`'s; check the
/// file in the build script (`speclab_tables::rgb_file::check_file`),
/// since the table trusts its bytes (other bytes give wrong colours, never
/// a panic).
///
/// ```
/// use speclab::color::{LinearRgb, RgbAlbedo, rgb_table::RgbTable};
/// const MINE: &RgbTable = speclab::rgb_table!(concat!(env!("CARGO_MANIFEST_DIR"), "/data/rgb/srgb.rgbt"));
/// const RED: RgbAlbedo = MINE.const_albedo(LinearRgb::new(0.8, 0.1, 0.05)).unwrap();
/// assert_eq!(MINE.albedo(LinearRgb::new(0.8, 0.1, 0.05))?, RED);
/// # Ok::<(), speclab::Error>(())
/// ```
#[macro_export]
macro_rules! rgb_table {
    ($path:expr) => {{
        static FILE: [u8; include_bytes!($path).len()] = *include_bytes!($path);
        static TILES: $crate::color::rgb_table::TileCache = $crate::color::rgb_table::TileCache::new();
        &$crate::color::rgb_table::RgbTable::embedded(&FILE, &TILES)
    }};
}

/// Which built-in table a built-in space has, for a space reached through
/// `&RgbSpace` (whose [`RgbSpace::table`](crate::color::RgbSpace::table)
/// then names all five, so a program that calls it links them all).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BuiltInTable {
    Srgb,
    DisplayP3,
    Rec2020,
    Aces2065_1,
    AcesCg,
}

impl BuiltInTable {
    /// The table, if the program has it (the wide-gamut spaces' with the
    /// feature `wide-gamut`).
    pub(crate) fn table(self) -> Option<&'static RgbTable> {
        match self {
            BuiltInTable::Srgb => Some(RgbTable::SRGB),
            #[cfg(feature = "wide-gamut")]
            BuiltInTable::DisplayP3 => Some(RgbTable::DISPLAY_P3),
            #[cfg(feature = "wide-gamut")]
            BuiltInTable::Rec2020 => Some(RgbTable::REC2020),
            #[cfg(feature = "wide-gamut")]
            BuiltInTable::Aces2065_1 => Some(RgbTable::ACES2065_1),
            #[cfg(feature = "wide-gamut")]
            BuiltInTable::AcesCg => Some(RgbTable::ACESCG),
            #[cfg(not(feature = "wide-gamut"))]
            _ => None,
        }
    }
}
