//! A table's coefficients as the run-time lookup reads them: slabs of the
//! largest component `z`, each decoded from the table file the first time
//! a colour needs it and kept for the table's life, shared by its clones.
//!
//! Slab `s` of a case holds the nodes `z` from `s·B` to
//! `min(s·B + B, n − 1)` (`B = min(8, n)`, the compact file's block side),
//! every `y` and `x`, as `f32` triples `[z][y][x]`, and one more `f32`: the
//! interval `[k, k + 1]` of `z` lies in slab `k / B`, and the lookup reads
//! four lanes from each corner's triple. A compact file's slab decodes in
//! about 4 ms (release; 14 ms unoptimised), a version-1 file's is copied.

use std::sync::OnceLock;

use speclab_tables::rgb_file::{HEADER_LEN, VERSION_COMPACT, compact};

/// The most slabs a case has: `⌈(256 − 1)/8⌉`.
pub(crate) const MAX_SLABS: usize = 32;

/// Where a table keeps its decoded slabs: one per case and slab, each
/// decoded once. A built-in table's is a `static`; [`crate::rgb_table!`]
/// makes one for a table embedded by a downstream crate.
#[derive(Debug)]
pub struct SlabCache {
    slabs: [[OnceLock<Box<[f32]>>; MAX_SLABS]; 3],
}

impl Default for SlabCache {
    fn default() -> Self {
        SlabCache::new()
    }
}

impl SlabCache {
    /// An empty cache.
    #[must_use]
    pub const fn new() -> SlabCache {
        SlabCache { slabs: [const { [const { OnceLock::new() }; MAX_SLABS] }; 3] }
    }

    /// Slab `s` of case `case` of the checked table file `bytes` (`n`
    /// nodes per axis), decoded now if it is not yet. An empty slab for an
    /// index past the table's (which a lookup never asks for).
    #[inline]
    pub(crate) fn get(&self, bytes: &[u8], n: usize, case: usize, s: usize) -> &[f32] {
        match self.slabs.get(case).and_then(|slabs| slabs.get(s)) {
            Some(cell) => cell.get_or_init(|| decode(bytes, n, case, s)),
            None => &[],
        }
    }

    /// Slab `s` of case `case` if it is decoded.
    pub(crate) fn decoded(&self, case: usize, s: usize) -> Option<&[f32]> {
        self.slabs.get(case)?.get(s)?.get().map(|b| &b[..])
    }
}

/// The side of a slab's blocks, `min(8, n)`.
pub(crate) const fn block(n: usize) -> usize {
    if n < compact::BLOCK_MAX { n } else { compact::BLOCK_MAX }
}

/// Slabs per case: `⌈(n − 1)/B⌉`.
pub(crate) const fn count(n: usize) -> usize {
    (n - 1).div_ceil(block(n))
}

/// The first and last `z` of slab `s`.
pub(crate) const fn z_range(n: usize, s: usize) -> (usize, usize) {
    let b = block(n);
    let last = s * b + b;
    (s * b, if last < n - 1 { last } else { n - 1 })
}

/// Slab `s` of case `case`, decoded (version 2) or copied (version 1).
fn decode(bytes: &[u8], n: usize, case: usize, s: usize) -> Box<[f32]> {
    let (z0, z1) = z_range(n, s);
    let triples = if compact::word(bytes, 8) == VERSION_COMPACT {
        compact::decode_slab(bytes, &compact::Layout::read(bytes), case, s)
    } else {
        let start = HEADER_LEN + 12 * (case * n + z0) * n * n;
        let end = (start + 12 * (z1 - z0 + 1) * n * n).min(bytes.len());
        let floats = bytes.get(start..end).unwrap_or_default().chunks_exact(4);
        let floats: Vec<f32> = floats.map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
        floats.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
    };
    let mut out: Vec<f32> = triples.into_iter().flatten().collect();
    out.push(0.0);
    out.into_boxed_slice()
}
