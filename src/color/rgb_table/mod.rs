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
//! embedded at build time, compact ([`RgbTable::SRGB`] and its siblings,
//! `speclab_tables::rgb_file` version 2: each node rounded to what its
//! spectrum needs, predicted from its neighbours and Huffman-coded;
//! 1.5–2.6 MB per space). A lookup decodes the tile of 9 × 9 × 64 nodes
//! it needs the first time (about 1 ms), and keeps it (62 KB):
//! nothing is fitted when a program starts, and a colour of a built-in
//! space is a `const` ([`RgbTable::const_albedo`], which decodes the
//! colour's corners at compile time, to the run-time lookup's bits). A
//! table is its file, shared by every clone (an `Arc`, or the program's
//! own static data). A space the caller defines fits its table on first
//! use ([`RgbTable::fit`]: seconds to a minute in a release build), which
//! [`RgbTable::save`] keeps and [`RgbTable::load`] reads back, checked, or
//! a downstream crate embeds ([`crate::rgb_table!`]).
//!
//! ```
//! use speclab::color::{LinearRgb, RgbAlbedo, rgb_table::RgbTable, space::RgbSpace};
//! const ORANGE: RgbAlbedo = RgbTable::SRGB.const_albedo(LinearRgb::new(0.8, 0.35, 0.05)).unwrap();
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

mod builtin;
mod consts;
pub(crate) use builtin::BuiltInTable;
mod fit;
mod lookup;
mod tiles;

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use speclab_tables::rgb_file::{self, Header, VERSION_COMPACT, VERSION_F32, compact};

use crate::color::RgbAlbedo;
use crate::color::rgb::LinearRgb;
use crate::color::rgb_spectra::Split;
use crate::color::upsample::Fit;
use crate::error::{Error, ReadError};
use crate::spectrum::SigmoidPolynomial;

use crate::spectrum::sigmoid::constant;
pub use lookup::node;
/// How a compact table rounds its nodes (`speclab_tables::rgb_file::quantize`).
pub use speclab_tables::rgb_file::quantize::Quantizer;
pub use tiles::TileCache;

/// Nodes per axis of the built-in tables.
pub const RESOLUTION: usize = 64;

/// Sigmoid-polynomial coefficients on a grid of colours: a checked table
/// file's bytes (version 2, compact, or version 1, `f32`) and its tiles,
/// decoded as colours need them.
#[derive(Clone)]
pub struct RgbTable {
    source: Source,
    /// Nodes per axis, the nodes, and how a colour finds its place.
    grid: lookup::Grid,
    /// The illuminant a built-in table's lights tint and its `∫ L·ȳ`, for
    /// [`RgbTable::const_light`].
    light: Option<(&'static crate::TabulatedSpectrum, f64)>,
}

/// Where the bytes and their tiles live: the program's static data, or
/// shared on the heap.
#[derive(Clone)]
enum Source {
    Static { bytes: &'static [u8], tiles: &'static TileCache },
    Shared(Arc<(Box<[u8]>, TileCache)>),
}

impl RgbTable {
    /// The table of the table file `bytes`, embedded in the program with
    /// its tiles' cache: what [`crate::rgb_table!`] and the built-in tables
    /// use. The bytes must be a file `speclab_tables::rgb_file::parse`
    /// accepts (a build script checks it with `check_file`): other bytes
    /// give wrong colours, never a panic.
    #[must_use]
    pub const fn embedded(bytes: &'static [u8], tiles: &'static TileCache) -> RgbTable {
        let n = compact::word(bytes, 12) as usize;
        let n = if n < 2 {
            2
        } else if n > lookup::MAX_NODES {
            lookup::MAX_NODES
        } else {
            n
        };
        RgbTable { source: Source::Static { bytes, tiles }, grid: lookup::Grid::new(n), light: None }
    }

    /// The table of a checked file's `bytes` on the heap.
    fn shared(bytes: Box<[u8]>, n: usize) -> RgbTable {
        RgbTable {
            source: Source::Shared(Arc::new((bytes, TileCache::new()))),
            grid: lookup::Grid::new(n),
            light: None,
        }
    }

    /// A table fitted by `fit` for the space named `name`, `n` nodes per
    /// axis (clamped into 2 to 256), its coefficients as fitted (version
    /// 1): what [`RgbTable::fit`] makes.
    pub(crate) fn fitted(fit: &Fit, name: &str, n: usize) -> RgbTable {
        let n = n.clamp(2, rgb_file::MAX_RESOLUTION as usize);
        let header =
            Header { version: VERSION_F32, resolution: n as u32, matrix: fit.to_rgb, name: name.into() };
        let mut bytes = rgb_file::encode_header(&header);
        for triple in fit::coefficients(fit, n) {
            bytes.extend(triple.iter().flat_map(|v| v.to_le_bytes()));
        }
        rgb_file::finish(&mut bytes);
        RgbTable::shared(bytes.into(), n)
    }

    /// The table in `bytes`, a table file's contents (version 1 or 2),
    /// checked whole (magic, version, lengths, checksum, codes, every
    /// number finite: a compact file decoded once, about 0.1 s); `origin`
    /// names it in the error.
    pub fn from_bytes(bytes: &[u8], origin: &str) -> Result<RgbTable, Error> {
        let header = rgb_file::parse(bytes, origin).map_err(Error::TableFile)?;
        Ok(RgbTable::shared(bytes.into(), header.resolution as usize))
    }

    /// The table in the file at `path`, checked as [`RgbTable::from_bytes`].
    pub fn load(path: impl AsRef<Path>) -> Result<RgbTable, Error> {
        let path = path.as_ref();
        let bytes = std::fs::read(path)
            .map_err(|source| Error::Read(ReadError::Io { path: path.to_path_buf(), source }))?;
        RgbTable::from_bytes(&bytes, &path.display().to_string())
    }

    /// Writes the table to `path` as its file (the version it has).
    pub fn save(&self, path: impl AsRef<Path>) -> Result<(), Error> {
        let path = path.as_ref();
        std::fs::write(path, self.as_bytes())
            .map_err(|source| Error::Read(ReadError::Io { path: path.to_path_buf(), source }))
    }

    /// The table made compact (version 2) with the built-in tables'
    /// rounding ([`Quantizer::DEFAULT`]): [`RgbTable::compact_with`].
    #[must_use]
    pub fn compact(&self) -> RgbTable {
        self.compact_with(Quantizer::DEFAULT)
    }

    /// The table made compact (version 2) with `quantizer`'s rounding
    /// (`speclab_tables::rgb_file::compact`): itself if it is compact with
    /// that rounding, else its coefficients as the lookup reads them,
    /// rounded and coded. The same coefficients give the same bytes.
    #[must_use]
    pub fn compact_with(&self, quantizer: Quantizer) -> RgbTable {
        if self.quantizer() == Some(quantizer) {
            return self.clone();
        }
        let n = self.grid.n;
        let bytes = compact::encode(&self.header(), quantizer, n, &self.coefficients());
        RgbTable::shared(bytes.into(), n)
    }

    /// The rounding of a compact table (`None` for version 1).
    #[must_use]
    pub fn quantizer(&self) -> Option<Quantizer> {
        let bytes = self.as_bytes();
        (compact::word(bytes, 8) == VERSION_COMPACT).then(|| compact::Layout::read(bytes).quantizer)
    }

    /// Every node's coefficients as the lookup reads them, `[case][z][y][x]`.
    #[must_use]
    pub fn coefficients(&self) -> Vec<[f32; 3]> {
        let n = self.grid.n;
        let (b, count) = (tiles::block(n), tiles::count(n));
        let mut out = vec![[0.0; 3]; 3 * n * n * n];
        for (case, tz, ty) in
            (0..3).flat_map(|c| (0..count).flat_map(move |z| (0..count).map(move |y| (c, z, y))))
        {
            let tile = self.tile(case, [tz, ty]);
            for (z, y) in
                (tz * b..(tz * b + b).min(n)).flat_map(|z| (ty * b..(ty * b + b).min(n)).map(move |y| (z, y)))
            {
                let from = 3 * (((z - tz * b) * (b + 1) + y - ty * b) * n);
                let row = tile[from..from + 3 * n].chunks_exact(3).map(|c| [c[0], c[1], c[2]]);
                let to = ((case * n + z) * n + y) * n;
                out[to..to + n].iter_mut().zip(row).for_each(|(o, c)| *o = c);
            }
        }
        out
    }

    /// The table's file, as bytes.
    #[must_use]
    pub fn as_bytes(&self) -> &[u8] {
        match &self.source {
            Source::Static { bytes, .. } => bytes,
            Source::Shared(shared) => &shared.0,
        }
    }

    /// Tile `[tz, ty]` of case `case` (decoded now if it is not yet).
    #[inline(always)]
    fn tile(&self, case: usize, tile: [usize; 2]) -> &[f32] {
        match &self.source {
            Source::Static { bytes, tiles } => tiles.get(bytes, self.grid.n, case, tile),
            Source::Shared(shared) => shared.1.get(&shared.0, self.grid.n, case, tile),
        }
    }

    /// How many of the table's tiles are decoded, of how many (three
    /// cases of `⌈(n − 1)/8⌉²`): what the table costs in memory now,
    /// 62 KB a tile at 64 nodes per axis.
    #[must_use]
    pub fn decoded_tiles(&self) -> (usize, usize) {
        let cache = match &self.source {
            Source::Static { tiles, .. } => *tiles,
            Source::Shared(shared) => &shared.1,
        };
        (cache.decoded(), 3 * tiles::count(self.grid.n).pow(2))
    }

    /// Nodes per axis.
    #[must_use]
    pub const fn resolution(&self) -> usize {
        self.grid.n
    }

    /// What the file says of itself: its version, the space's name and the
    /// XYZ → RGB matrix the table was fitted for.
    #[must_use]
    pub fn header(&self) -> Header {
        let unreadable = || Header {
            version: 0,
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
        let (tile, at) = self.grid.in_tile(place);
        let c = self.grid.interpolate_lanes(self.tile(place.case, tile), at, place);
        SigmoidPolynomial::new(c.map(f64::from))
    }
}

impl PartialEq for RgbTable {
    fn eq(&self, other: &Self) -> bool {
        self.as_bytes() == other.as_bytes()
    }
}

impl fmt::Debug for RgbTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.source {
            Source::Static { .. } => "built in",
            Source::Shared(_) => "shared",
        };
        f.debug_struct("RgbTable")
            .field("resolution", &self.grid.n)
            .field("version", &compact::word(self.as_bytes(), 8))
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
