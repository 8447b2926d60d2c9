//! A table's coefficients as the run-time lookup reads them: tiles of
//! nodes, each decoded from the table file the first time a colour needs
//! it and kept for the table's life, shared by its clones.
//!
//! Tile `(tz, ty)` of a case holds the nodes `z` from `tz·B` to
//! `min(tz·B + B, n − 1)` and `y` from `ty·B` to `min(ty·B + B, n − 1)`
//! (`B = min(8, n)`, the compact file's block side), every `x`, as `f32`
//! triples `[z][y][x]` with `B + 1` places for `z` and for `y`, and one
//! more `f32`: the cell of nodes `[k, k + 1] × [j, j + 1]` lies in tile
//! `(k / B, j / B)`, and the lookup reads four lanes from each corner's
//! triple. A built-in table's tile decodes in about 0.8 ms (release;
//! about 5 ms unoptimised), a version-1 file's is copied.

use std::sync::OnceLock;

use speclab_tables::rgb_file::{HEADER_LEN, VERSION_COMPACT, compact};

/// The most tiles a case has along an axis: `⌈(256 − 1)/8⌉`.
pub(crate) const MAX_TILES: usize = 32;

/// A decoded tile, once.
type Tile = OnceLock<Box<[f32]>>;

/// Places for tiles: 3 cases × [`MAX_TILES`]² (72 KB), allocated at the
/// first lookup so that a `static` cache stays a few bytes in the program.
const SLOTS: usize = 3 * MAX_TILES * MAX_TILES;

/// Where a table keeps its decoded tiles: one per case and tile, each
/// decoded once. A built-in table's is a `static`; [`crate::rgb_table!`]
/// makes one for a table embedded by a downstream crate.
#[derive(Debug)]
pub struct TileCache {
    /// Case `c`'s tile `(tz, ty)` at `(c·MAX_TILES + tz)·MAX_TILES + ty`.
    tiles: OnceLock<Box<[Tile]>>,
    /// A compact file's decoder (its codes' lookup tables), made once.
    decoder: OnceLock<compact::Decoder>,
}

impl Default for TileCache {
    fn default() -> Self {
        TileCache::new()
    }
}

impl TileCache {
    /// An empty cache.
    #[must_use]
    pub const fn new() -> TileCache {
        TileCache { tiles: OnceLock::new(), decoder: OnceLock::new() }
    }

    /// Tile `[tz, ty]` of case `case` of the checked table file `bytes`
    /// (`n` nodes per axis), decoded now if it is not yet. An empty tile
    /// for an index past the table's (which a lookup never asks for).
    #[inline]
    pub(crate) fn get(&self, bytes: &[u8], n: usize, case: usize, [tz, ty]: [usize; 2]) -> &[f32] {
        if case >= 3 || tz >= MAX_TILES || ty >= MAX_TILES {
            return &[];
        }
        let slots = self.tiles.get_or_init(|| (0..SLOTS).map(|_| OnceLock::new()).collect());
        match slots.get((case * MAX_TILES + tz) * MAX_TILES + ty) {
            Some(cell) => cell.get_or_init(|| self.decode(bytes, n, case, tz, ty)),
            None => &[],
        }
    }

    /// How many tiles are decoded.
    pub(crate) fn decoded(&self) -> usize {
        self.tiles.get().map_or(0, |slots| slots.iter().filter(|t| t.get().is_some()).count())
    }

    /// Tile `(tz, ty)` of case `case`, decoded (version 2) or copied
    /// (version 1).
    fn decode(&self, bytes: &[u8], n: usize, case: usize, tz: usize, ty: usize) -> Box<[f32]> {
        let triples = if compact::word(bytes, 8) == VERSION_COMPACT {
            self.decoder.get_or_init(|| compact::Decoder::new(bytes)).tile(bytes, case, tz, ty)
        } else {
            f32_tile(bytes, n, case, tz, ty)
        };
        let mut out: Vec<f32> = triples.into_iter().flatten().collect();
        out.push(0.0);
        out.into_boxed_slice()
    }
}

/// The side of a tile's blocks, `min(8, n)`.
pub(crate) const fn block(n: usize) -> usize {
    if n < compact::BLOCK_MAX { n } else { compact::BLOCK_MAX }
}

/// Tiles per case along `z` and along `y`: `⌈(n − 1)/B⌉`.
pub(crate) const fn count(n: usize) -> usize {
    (n - 1).div_ceil(block(n))
}

/// Tile `(tz, ty)` of case `case` of a version-1 file, copied.
fn f32_tile(bytes: &[u8], n: usize, case: usize, tz: usize, ty: usize) -> Vec<[f32; 3]> {
    let b = block(n);
    let mut out = vec![[0.0; 3]; (b + 1) * (b + 1) * n];
    let triple = |i: usize| {
        let at = HEADER_LEN + 12 * i;
        let f = |k: usize| {
            bytes
                .get(at + 4 * k..at + 4 * k + 4)
                .map_or(0.0, |b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        };
        [f(0), f(1), f(2)]
    };
    for z in tz * b..=(tz * b + b).min(n - 1) {
        for y in ty * b..=(ty * b + b).min(n - 1) {
            for x in 0..n {
                out[((z - tz * b) * (b + 1) + y - ty * b) * n + x] = triple(((case * n + z) * n + y) * n + x);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cache is under a kilobyte until a lookup allocates its slots (a
    /// built-in table's `static` is in every program naming its space),
    /// and an index past the slots reads an empty tile.
    #[test]
    fn a_cache_is_small_until_used() {
        assert!(std::mem::size_of::<TileCache>() <= 1024, "{}", std::mem::size_of::<TileCache>());
        let cache = TileCache::new();
        assert_eq!(cache.decoded(), 0);
        assert!(cache.get(&[], 64, 3, [0, 0]).is_empty());
        assert!(cache.get(&[], 64, 0, [MAX_TILES, 0]).is_empty());
        assert!(cache.get(&[], 64, 0, [0, MAX_TILES]).is_empty());
        assert_eq!(cache.decoded(), 0);
    }

    /// A lookup decodes its colour's tile, once: the count says so.
    #[test]
    fn a_lookup_decodes_one_tile_once() {
        use crate::color::rgb_table::RgbTable;
        let table = RgbTable::from_bytes(RgbTable::SRGB.as_bytes(), "sRGB's bytes").expect("a table");
        assert_eq!(table.decoded_tiles(), (0, 192));
        table.albedo([0.6, 0.3, 0.2]).expect("an albedo");
        table.albedo([0.6, 0.3, 0.21]).expect("an albedo");
        assert_eq!(table.decoded_tiles(), (1, 192));
        // A dark red with much blue: case 0, the first tile along z, a later
        // one along y, whose slot is not the first's; its coefficients are
        // the compile-time lookup's (which reads the file, not the tiles).
        let rgb = crate::color::LinearRgb::new(0.004, 0.0008, 0.0032);
        assert_eq!(table.albedo(rgb).ok(), RgbTable::SRGB.const_albedo(rgb));
    }
}
