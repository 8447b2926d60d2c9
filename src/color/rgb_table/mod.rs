//! RGB to spectrum in one lookup: sigmoid-polynomial coefficients fitted
//! once on a grid of colours and interpolated (pbrt-v4's
//! `RGBToSpectrumTable`, Jakob and Hanika's table).
//!
//! For each of the three cases "red, green or blue is the largest
//! component", coefficients are kept at [`RESOLUTION`]³ colours: the
//! largest component `z` at nodes dense near 0 and 1 ([`node`]), the other
//! two as fractions of it on a regular grid. A lookup interpolates the
//! eight neighbouring coefficient triples trilinearly, in `f32`, with no
//! search and no allocation.
//!
//! **Data, not a start-up cost.** The built-in spaces' tables are fitted
//! once, by `cargo run --release -p speclab-tools --bin rgb-tables`, and
//! embedded at build time ([`RgbTable::SRGB`](crate::color::rgb_table::RgbTable::SRGB) and its siblings): nothing is
//! fitted when a program starts, and a colour of a built-in space is a
//! `const` ([`RgbTable::const_albedo`](crate::color::rgb_table::RgbTable::const_albedo)). A table is its file: one
//! versioned, checksummed layout (`speclab_tables::rgb_file`), `3 · 64³`
//! triples of `f32`, 9.4 MB per space, shared by every clone (an `Arc`, or
//! the program's own static data). A space the caller defines builds its
//! table on first use ([`RgbTable::fit`](crate::color::rgb_table::RgbTable::fit): seconds to a minute in a release
//! build), which [`RgbTable::save`](crate::color::rgb_table::RgbTable::save) keeps and [`RgbTable::load`](crate::color::rgb_table::RgbTable::load) reads
//! back, checked.
//!
//! ```
//! use speclab::color::{LinearRgb, RgbAlbedo, rgb_table::RgbTable, space::RgbSpace};
//! const ORANGE: RgbAlbedo = RgbTable::SRGB.const_albedo([0.8, 0.35, 0.05]).unwrap();
//! let looked_up = RgbSpace::srgb().albedo(LinearRgb::new(0.8, 0.35, 0.05))?;
//! assert_eq!(ORANGE, looked_up);
//! assert!(RgbSpace::srgb().rgb_of(&ORANGE).distance(LinearRgb::new(0.8, 0.35, 0.05)) < 1e-3);
//! // A coarse table of a space of one's own, saved and loaded back.
//! let coarse = RgbTable::fit(RgbSpace::srgb(), 8);
//! let path = std::env::temp_dir().join("speclab-doc-coarse.rgbt");
//! coarse.save(&path)?;
//! assert_eq!(RgbTable::load(&path)?, coarse);
//! # Ok::<(), speclab::Error>(())
//! ```

mod fit;
mod lookup;

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use speclab_tables::rgb_file;

use crate::color::RgbAlbedo;
use crate::color::rgb::LinearRgb;
use crate::color::rgb_spectra::Split;
use crate::color::upsample::Fit;
use crate::error::{Error, ReadError};
use crate::spectrum::SigmoidPolynomial;

use crate::spectrum::sigmoid::constant;
pub use lookup::node;

/// Nodes per axis of the built-in tables.
pub const RESOLUTION: usize = 64;

/// Sigmoid-polynomial coefficients on a grid of colours: a table file's
/// bytes (header, `f32` coefficients, checksum), checked when made.
#[derive(Clone)]
pub struct RgbTable {
    bytes: Bytes,
    /// Nodes per axis, the nodes, and how a colour finds its place.
    grid: lookup::Grid,
}

/// Where the bytes live: the program's static data, or shared on the heap.
#[derive(Clone)]
enum Bytes {
    Static(&'static [u8]),
    Shared(Arc<[u8]>),
}

/// sRGB's table file, once in the program (a static array: a `const`, or
/// a static reference to the bytes, could be copied into every place that
/// uses it).
static SRGB_FILE: [u8; include_bytes!("../../../data/rgb/srgb.rgbt").len()] =
    *include_bytes!("../../../data/rgb/srgb.rgbt");

impl RgbTable {
    /// Linear sRGB's table ([`RgbSpace::srgb`](crate::color::RgbSpace::srgb)'s), embedded at build time
    /// (`data/rgb/srgb.rgbt`).
    pub const SRGB: &RgbTable = &RgbTable::embedded(&SRGB_FILE);
    /// Display P3's table ([`RgbSpace::display_p3`](crate::color::RgbSpace::display_p3)'s), from
    /// `speclab-wide-gamut` (feature `wide-gamut`, on by default).
    #[cfg(feature = "wide-gamut")]
    pub const DISPLAY_P3: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::DISPLAY_P3);
    /// Rec.2020's table ([`RgbSpace::rec2020`](crate::color::RgbSpace::rec2020)'s), as [`RgbTable::DISPLAY_P3`](crate::color::rgb_table::RgbTable::DISPLAY_P3).
    #[cfg(feature = "wide-gamut")]
    pub const REC2020: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::REC2020);
    /// ACES2065-1's table ([`RgbSpace::aces2065_1`](crate::color::RgbSpace::aces2065_1)'s), as [`RgbTable::DISPLAY_P3`](crate::color::rgb_table::RgbTable::DISPLAY_P3).
    #[cfg(feature = "wide-gamut")]
    pub const ACES2065_1: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::ACES2065_1);
    /// ACEScg's table ([`RgbSpace::acescg`](crate::color::RgbSpace::acescg)'s), as [`RgbTable::DISPLAY_P3`](crate::color::rgb_table::RgbTable::DISPLAY_P3).
    #[cfg(feature = "wide-gamut")]
    pub const ACESCG: &RgbTable = &RgbTable::embedded(&speclab_wide_gamut::ACESCG);

    /// A table built into the program (checked by the build script).
    const fn embedded(bytes: &'static [u8]) -> RgbTable {
        let n = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]) as usize;
        RgbTable::with_bytes(Bytes::Static(bytes), n)
    }

    /// The table of checked `bytes` of `n` nodes per axis, with its grid.
    const fn with_bytes(bytes: Bytes, n: usize) -> RgbTable {
        RgbTable { bytes, grid: lookup::Grid::new(n) }
    }

    /// A table fitted by `fit` for the space named `name`, `n` nodes per
    /// axis (clamped into 2 to 256): what [`RgbTable::fit`](crate::color::rgb_table::RgbTable::fit) makes.
    pub(crate) fn fitted(fit: &Fit, name: &str, n: usize) -> RgbTable {
        let n = n.clamp(2, rgb_file::MAX_RESOLUTION as usize);
        let header = rgb_file::Header { resolution: n as u32, matrix: fit.to_rgb, name: name.into() };
        let mut bytes = rgb_file::encode_header(&header);
        for triple in fit::coefficients(fit, n) {
            bytes.extend(triple.iter().flat_map(|v| v.to_le_bytes()));
        }
        rgb_file::finish(&mut bytes);
        RgbTable::with_bytes(Bytes::Shared(bytes.into()), n)
    }

    /// The table in `bytes`, a table file's contents, checked (magic,
    /// version, length, checksum, finite numbers); `origin` names it in
    /// the error.
    pub fn from_bytes(bytes: &[u8], origin: &str) -> Result<RgbTable, Error> {
        let header = rgb_file::parse(bytes, origin).map_err(Error::TableFile)?;
        Ok(RgbTable::with_bytes(Bytes::Shared(bytes.into()), header.resolution as usize))
    }

    /// The table in the file at `path`, checked as [`RgbTable::from_bytes`](crate::color::rgb_table::RgbTable::from_bytes).
    pub fn load(path: impl AsRef<Path>) -> Result<RgbTable, Error> {
        let path = path.as_ref();
        let bytes = std::fs::read(path)
            .map_err(|source| Error::Read(ReadError::Io { path: path.to_path_buf(), source }))?;
        RgbTable::from_bytes(&bytes, &path.display().to_string())
    }

    /// Writes the table to `path` in the table file format.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<(), Error> {
        let path = path.as_ref();
        std::fs::write(path, self.as_bytes())
            .map_err(|source| Error::Read(ReadError::Io { path: path.to_path_buf(), source }))
    }

    /// The table's file, as bytes.
    #[must_use]
    pub fn as_bytes(&self) -> &[u8] {
        match &self.bytes {
            Bytes::Static(b) => b,
            Bytes::Shared(b) => b,
        }
    }

    /// Nodes per axis.
    #[must_use]
    pub const fn resolution(&self) -> usize {
        self.grid.n
    }

    /// What the file says of itself: the space's name and the XYZ → RGB
    /// matrix the table was fitted for.
    #[must_use]
    pub fn header(&self) -> rgb_file::Header {
        let unreadable = || rgb_file::Header {
            resolution: self.grid.n as u32,
            matrix: [[0.0; 3]; 3],
            name: String::new(),
        };
        rgb_file::read_header(self.as_bytes()).unwrap_or_else(unreadable)
    }

    /// The albedo of `rgb` (each component in [0, 1]; otherwise an
    /// [`Error::Albedo`]), interpolated from the table. Greys are the
    /// constants of their value, black and white 0 and 1 exactly.
    #[inline]
    pub fn albedo(&self, rgb: impl Into<LinearRgb>) -> Result<RgbAlbedo, Error> {
        Ok(RgbAlbedo::from_polynomial(self.lookup(albedo_components(rgb.into())?)))
    }

    /// [`RgbTable::albedo`](crate::color::rgb_table::RgbTable::albedo) at compile time, for a table built into the
    /// program ([`RgbTable::SRGB`](crate::color::rgb_table::RgbTable::SRGB) and its siblings): `None` for a
    /// component outside [0, 1], or for a table loaded or fitted at run
    /// time. The same coefficients as at run time, to the bit.
    #[must_use]
    pub const fn const_albedo(&self, rgb: [f32; 3]) -> Option<RgbAlbedo> {
        let Bytes::Static(bytes) = &self.bytes else { return None };
        let mut i = 0;
        while i < 3 {
            if !(rgb[i] >= 0.0 && rgb[i] <= 1.0) {
                return None;
            }
            i += 1;
        }
        let poly = if rgb[0] == rgb[1] && rgb[1] == rgb[2] {
            constant(rgb[0] as f64)
        } else if let Some(place) = self.grid.locate(rgb) {
            let c = self.grid.interpolate(bytes, place);
            SigmoidPolynomial::new([c[0] as f64, c[1] as f64, c[2] as f64])
        } else {
            SigmoidPolynomial::BLACK
        };
        Some(RgbAlbedo::from_polynomial(poly))
    }

    /// `rgb` (negatives and NaN as 0) as `(scale, polynomial)`: the scale
    /// by `split`'s rule, and the looked-up polynomial of the colour over
    /// it.
    pub(crate) fn split(&self, rgb: LinearRgb, split: Split) -> (f64, SigmoidPolynomial) {
        let rgb = rgb.map(|v| if v > 0.0 { v } else { 0.0 });
        let largest = rgb.max_component();
        if !(largest > 0.0 && largest.is_finite()) {
            return (0.0, SigmoidPolynomial::BLACK);
        }
        let scale = match split {
            Split::Twice => 2.0 * largest,
            Split::UpToOne => largest.max(1.0),
        };
        (scale, self.lookup((rgb / scale).to_array()))
    }

    /// The interpolated polynomial of `rgb` in [0, 1]³.
    #[inline(always)]
    fn lookup(&self, rgb: [f64; 3]) -> SigmoidPolynomial {
        if rgb[0] == rgb[1] && rgb[1] == rgb[2] {
            return constant(rgb[0]);
        }
        // Components below f32's smallest normal number are black.
        let Some(place) = self.grid.locate(rgb.map(|v| v as f32)) else { return SigmoidPolynomial::BLACK };
        SigmoidPolynomial::new(self.grid.interpolate_lanes(self.as_bytes(), place).map(f64::from))
    }
}

impl PartialEq for RgbTable {
    fn eq(&self, other: &Self) -> bool {
        self.as_bytes() == other.as_bytes()
    }
}

impl fmt::Debug for RgbTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.bytes {
            Bytes::Static(_) => "built in",
            Bytes::Shared(_) => "shared",
        };
        f.debug_struct("RgbTable")
            .field("resolution", &self.grid.n)
            .field("bytes", &self.as_bytes().len())
            .field("kind", &kind)
            .finish()
    }
}

/// An albedo's components, each in [0, 1] (otherwise an [`Error::Albedo`]).
#[inline]
pub(crate) fn albedo_components(rgb: LinearRgb) -> Result<[f64; 3], Error> {
    let c = rgb.to_array();
    if c.iter().all(|v| (0.0..=1.0).contains(v)) { Ok(c) } else { Err(Error::Albedo { rgb: c }) }
}
