//! The table's lookup: where a colour falls (a `const fn`), and the
//! eight coefficient triples around it interpolated, the same arithmetic
//! at compile time (`RgbTable::const_albedo`, from the file's bytes) and
//! at run time (from the decoded tiles), in `f32`, with no search and no
//! allocation.
//!
//! The largest component `z` has its nodes at `g(k/(n − 1))`, `g` the
//! smoothstep `3t² − 2t³` taken twice (pbrt-v4's placement: dense near 0
//! and 1, where the fits change fastest). Its interval is read from a
//! table of guesses keyed by the exponent and first mantissa bits of the
//! distance to the nearer end (`z` or `1 − z`), put right by one
//! comparison on each side: no search, no square root, the same at
//! compile time and at run time. The other two components are fractions
//! of `z` on a regular grid. Eight coefficient triples are interpolated
//! trilinearly, linearly in `z` between its nodes: four lanes at a time
//! at run time, the same operations in the same order, so the same bits.

use speclab_tables::rgb_file::{HEADER_LEN, VERSION_COMPACT, compact};
use wide::f32x4;

/// The node `k` of `n` of the largest component, in `f32` (computed in
/// `f64`, then rounded: the fits are made at exactly these values).
#[must_use]
pub const fn node(k: usize, n: usize) -> f32 {
    if n < 2 || k >= n {
        return if k == 0 { 0.0 } else { 1.0 };
    }
    let t = k as f64 / (n - 1) as f64;
    let s = t * t * (3.0 - 2.0 * t);
    (s * s * (3.0 - 2.0 * s)) as f32
}

/// The most nodes a table has per axis.
pub(crate) const MAX_NODES: usize = speclab_tables::rgb_file::MAX_RESOLUTION as usize;

/// The `n` nodes of the largest component, computed once per table.
pub(crate) const fn nodes(n: usize) -> [f32; MAX_NODES] {
    let mut out = [0.0; MAX_NODES];
    let mut k = 0;
    while k < n {
        out[k] = node(k, n);
        k += 1;
    }
    out
}

/// The interval `k` of `z` in (0, 1], `nodes[k] ≤ z < nodes[k + 1]` (the
/// last interval closed), found by walking the nodes: what the guesses
/// are made of (and [`Grid::interval`] is tested against).
pub(crate) const fn interval_walked(z: f32, nodes: &[f32; MAX_NODES], n: usize) -> usize {
    let mut k = 0;
    while k < n - 2 && z >= nodes[k + 1] {
        k += 1;
    }
    k
}

/// Mantissa bits in a key: a key's cell is at most 1/128 of its value
/// wide, narrower than the nodes' relative spacing below ½ (at least 1/57
/// at 256 nodes), so a cell holds at most one node.
const KEY_BITS: u32 = 7;
/// The biased exponent of 2⁻³⁰: distances below it share the first key
/// (the first node above 0 is above it up to 256 nodes).
const LOW_EXPONENT: u32 = 97;
/// Keys: 30 binary orders of magnitude of 128 cells.
pub(crate) const KEYS: usize = ((127 - LOW_EXPONENT) << KEY_BITS) as usize;

/// The key of a distance `d` in [0, ½]: its exponent and first mantissa
/// bits, from 2⁻³⁰ up.
#[inline(always)]
const fn key(d: f32) -> usize {
    let bits = d.to_bits() >> (23 - KEY_BITS);
    let low = LOW_EXPONENT << KEY_BITS;
    if bits < low {
        0
    } else if (bits - low) as usize >= KEYS {
        KEYS - 1
    } else {
        (bits - low) as usize
    }
}

/// For each key, the interval of the smallest distance in its cell (by
/// walking the nodes): the guess of the interval of any distance in it,
/// at most one low. Computed once per table.
pub(crate) const fn guesses(nodes: &[f32; MAX_NODES], n: usize) -> [u8; KEYS] {
    let mut out = [0; KEYS];
    let mut c = 1;
    while c < KEYS {
        let d = f32::from_bits(((c as u32) + (LOW_EXPONENT << KEY_BITS)) << (23 - KEY_BITS));
        out[c] = interval_walked(d, nodes, n) as u8;
        c += 1;
    }
    out
}

/// A table's grid, computed once per table: the nodes of the largest
/// component, the reciprocals of their intervals' widths, and the guesses
/// of an interval.
#[derive(Clone)]
pub(crate) struct Grid {
    /// Nodes per axis, 2 to [`MAX_NODES`].
    pub(crate) n: usize,
    /// `n − 1`, the last node's index.
    last: f32,
    /// The largest component's nodes (the first `n`).
    nodes: [f32; MAX_NODES],
    /// `1/(nodes[k + 1] − nodes[k])`, the first `n − 1`.
    inverse_widths: [f32; MAX_NODES],
    /// The guesses of an interval ([`Grid::interval`]).
    guesses: [u8; KEYS],
}

/// Where a colour falls in a table: its case, its first corner's node
/// `[z, y, x]`, and the fractions `[dx, dy, dz]` along the three axes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Place {
    pub(crate) case: usize,
    pub(crate) node: [usize; 3],
    d: [f32; 3],
}

impl Grid {
    /// The grid of a table of `n` nodes per axis, 2 to [`MAX_NODES`] (a
    /// checked table's).
    pub(crate) const fn new(n: usize) -> Grid {
        let nodes = nodes(n);
        let mut inverse_widths = [0.0; MAX_NODES];
        let mut k = 0;
        while k + 1 < n {
            inverse_widths[k] = 1.0 / (nodes[k + 1] - nodes[k]);
            k += 1;
        }
        Grid { n, last: (n - 1) as f32, nodes, inverse_widths, guesses: guesses(&nodes, n) }
    }

    /// The interval of `z` in (0, 1] ([`interval_walked`]'s) from the
    /// table of guesses: the distance to the nearer end, `z` or `1 − z`
    /// (exact), looked up, mirrored above ½ (the nodes are symmetric), and
    /// put right by one comparison on each side. No search, no branch, no
    /// square root: the same at compile time and at run time.
    #[inline(always)]
    pub(crate) const fn interval(&self, z: f32) -> usize {
        let last = self.n - 2;
        let upper = z > 0.5;
        // A guess is an interval, at most `last`.
        let low = self.guesses[key(if upper { 1.0 - z } else { z })] as usize;
        let guess = if upper { last - low } else { low };
        let up = (z >= self.nodes[guess + 1]) as usize;
        let k = (guess + up).saturating_sub((z < self.nodes[guess]) as usize);
        if k > last { last } else { k }
    }

    /// Where `rgb` (in [0, 1]³) falls: the case (which component is
    /// largest, the first of equals after red, as pbrt-v4 chooses), the
    /// largest component `z`'s interval, the other two as fractions of
    /// `z`. `None` for a colour whose largest component is below `f32`'s
    /// smallest normal number (black: `1/z` would overflow).
    #[inline(always)]
    pub(crate) const fn locate(&self, [r, g, b]: [f32; 3]) -> Option<Place> {
        let case = if r > g {
            if r > b { 0 } else { 2 }
        } else if g > b {
            1
        } else {
            2
        };
        let (z, x, y) = if case == 0 {
            (r, g, b)
        } else if case == 1 {
            (g, b, r)
        } else {
            (b, r, g)
        };
        if z < f32::MIN_POSITIVE {
            return None;
        }
        let k = self.interval(z);
        let scale = 1.0 / z;
        let (x, y) = (x * scale * self.last, y * scale * self.last);
        let (xi, yi) = (self.index(x), self.index(y));
        let dz = (z - self.nodes[k]) * self.inverse_widths[k];
        Some(Place { case, node: [k, yi as usize, xi as usize], d: [x - xi as f32, y - yi as f32, dz] })
    }

    /// The tile `[tz, ty]` of `place` and its first corner's index in it
    /// (tiles of 8 `z` and 8 `y` with a place more for each; one tile
    /// below 8 nodes).
    #[inline(always)]
    pub(crate) const fn in_tile(&self, place: Place) -> ([usize; 2], usize) {
        let [k, y, x] = place.node;
        let n = self.n;
        if n >= 8 {
            ([k >> 3, y >> 3], (((k & 7) * 9 + (y & 7)) * n) + x)
        } else {
            ([0, 0], (k * (n + 1) + y) * n + x)
        }
    }

    /// `floor(v)` of `v ≥ 0`, at most `n − 2`.
    #[inline(always)]
    const fn index(&self, v: f32) -> u32 {
        let (i, top) = (v as u32, self.n as u32 - 2);
        if i > top { top } else { i }
    }

    /// The coefficients at `place` in the checked table file `bytes`:
    /// its eight corners read (version 1) or decoded (version 2), then
    /// interpolated trilinearly, linearly in `z` between its nodes.
    #[inline(always)]
    pub(crate) const fn interpolate(&self, bytes: &[u8], place: Place) -> [f32; 3] {
        let [k, y, x] = place.node;
        let c = if compact::word(bytes, 8) == VERSION_COMPACT {
            compact::corners(bytes, &compact::Layout::read(bytes), place.case, k, y, x)
        } else {
            let n = self.n;
            let at = ((place.case * n + k) * n + y) * n + x;
            let (r, s) = (n, n * n);
            [
                triple(bytes, at),
                triple(bytes, at + 1),
                triple(bytes, at + r),
                triple(bytes, at + r + 1),
                triple(bytes, at + s),
                triple(bytes, at + s + 1),
                triple(bytes, at + s + r),
                triple(bytes, at + s + r + 1),
            ]
        };
        let [dx, dy, dz] = place.d;
        let low = lerp(lerp(c[0], c[1], dx), lerp(c[2], c[3], dx), dy);
        let high = lerp(lerp(c[4], c[5], dx), lerp(c[6], c[7], dx), dy);
        lerp(low, high, dz)
    }

    /// [`Grid::interpolate`] at run time, from the place's decoded tile
    /// ([`Grid::in_tile`]): the same operations in the same order on four
    /// lanes at once (each corner's triple and the next float, which is
    /// dropped), so the same bits, and faster: one bounds check per two
    /// corners.
    #[inline(always)]
    pub(crate) fn interpolate_lanes(&self, tile: &[f32], at: usize, place: Place) -> [f32; 3] {
        let n = self.n;
        let rows = if n >= 8 { 9 } else { n + 1 };
        let [dx, dy, dz] = place.d.map(f32x4::splat);
        let (at, row, slice) = (3 * at, 3 * n, 3 * rows * n);
        let pair = |at: usize| {
            let f = tile.get(at..).and_then(<[f32]>::first_chunk::<7>).copied().unwrap_or([0.0; 7]);
            (f32x4::from([f[0], f[1], f[2], f[3]]), f32x4::from([f[3], f[4], f[5], f[6]]))
        };
        let lerp = |a: f32x4, b: f32x4, t: f32x4| a + t * (b - a);
        let plane = |at: usize| {
            let ((a, b), (c, d)) = (pair(at), pair(at + row));
            lerp(lerp(a, b, dx), lerp(c, d, dx), dy)
        };
        let c = lerp(plane(at), plane(at + slice), dz).to_array();
        [c[0], c[1], c[2]]
    }
}

/// `a + t(b − a)`, each component.
#[inline(always)]
const fn lerp(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
}

/// The coefficient triple number `i` of a version-1 file (zeros past the
/// end, which a checked table never reaches): one bounds check for twelve
/// bytes.
#[inline(always)]
const fn triple(bytes: &[u8], i: usize) -> [f32; 3] {
    let at = HEADER_LEN + 12 * i;
    if at > bytes.len() {
        return [0.0; 3];
    }
    let Some(b) = bytes.split_at(at).1.first_chunk::<12>() else { return [0.0; 3] };
    [
        f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
        f32::from_le_bytes([b[4], b[5], b[6], b[7]]),
        f32::from_le_bytes([b[8], b[9], b[10], b[11]]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interval by the guesses is the interval by walking on every
    /// node, the floats next to it on each side, and a sweep of 100,000
    /// values, from 2 nodes to 256.
    #[test]
    fn the_interval_by_guesses_is_the_interval_by_walking() {
        for n in [2, 3, 8, 64, 256] {
            let mut zs: Vec<f32> = (0..100_000).map(|i| (i as f32 + 0.5) / 100_000.0).collect();
            for k in 1..n {
                let z = node(k, n);
                zs.extend([z, f32::from_bits(z.to_bits() - 1), f32::from_bits(z.to_bits() + 1).min(1.0)]);
            }
            let (all, grid) = (nodes(n), Grid::new(n));
            for z in zs {
                let k = grid.interval(z);
                assert_eq!(k, interval_walked(z, &all, n), "z = {z:e}, n = {n}");
                assert!(node(k, n) <= z && (z < node(k + 1, n) || k == n - 2), "z = {z:e}: {k}");
            }
        }
    }

    /// The case of a colour with equal components is pbrt-v4's (the first
    /// of equals after red: green for red = green, blue for blue equal to
    /// the largest), read back from the place's offset; a largest
    /// component at `f32`'s smallest normal number has a place, below it
    /// none (black).
    #[test]
    fn ties_take_pbrt_v4s_case_and_the_smallest_normal_has_a_place() {
        let grid = Grid::new(64);
        let case = |rgb: [f32; 3]| grid.locate(rgb).map(|p| p.case);
        assert_eq!(case([0.5, 0.5, 0.2]), Some(1));
        assert_eq!(case([0.6, 0.5, 0.6]), Some(2));
        assert_eq!(case([0.2, 0.7, 0.7]), Some(2));
        assert_eq!(case([0.7, 0.2, 0.3]), Some(0));
        let tiny = f32::MIN_POSITIVE;
        assert_eq!(case([tiny, 0.0, 0.0]), Some(0));
        assert_eq!(case([f32::from_bits(tiny.to_bits() - 1), 0.0, 0.0]), None);
    }

    /// A component equal to the largest is at the far end of the last
    /// interval (pbrt-v4's `min(x, res − 2)`, then a fraction of 1), not
    /// at the start of an interval past the table's edge.
    #[test]
    fn a_component_equal_to_the_largest_ends_the_last_interval() {
        let grid = Grid::new(64);
        let place = grid.locate([0.5, 0.5, 0.2]).expect("a place");
        let [_, y, x] = place.node;
        assert_eq!((x, y), (25, 62), "green is largest: x is blue, y red");
        assert_eq!(place.d[1], 1.0);
        assert!((place.d[0] - 0.2).abs() < 1e-5, "{:?}", place.d);
    }

    /// The nodes of pbrt-v4's placement, rising from 0 to 1, symmetric.
    #[test]
    fn nodes_rise_from_zero_to_one_symmetrically() {
        let n = 64;
        assert_eq!((node(0, n), node(n - 1, n)), (0.0, 1.0));
        assert!((1..n).all(|k| node(k, n) > node(k - 1, n)));
        assert!((0..n).all(|k| (node(k, n) + node(n - 1 - k, n) - 1.0).abs() < 1e-7));
        let s = |t: f64| t * t * (3.0 - 2.0 * t);
        assert_eq!(node(7, n), s(s(7.0 / 63.0)) as f32);
        assert_eq!(nodes(n)[..n], (0..n).map(|k| node(k, n)).collect::<Vec<_>>()[..]);
    }

    /// Keys rise with the distance, cover 2⁻³⁰ to ½, and each cell holds
    /// at most one node at 256 nodes (the densest table).
    #[test]
    fn keys_cover_the_distances() {
        assert_eq!((key(0.0), key(1e-12), key(0.5)), (0, 0, KEYS - 128));
        assert!(key(2f32.powi(-30)) == 0 && key(2f32.powi(-29)) == 128);
        let all = nodes(256);
        let keys: Vec<usize> = all[1..128].iter().map(|&z| key(z)).collect();
        assert!(keys.windows(2).all(|w| w[0] < w[1]), "two nodes share a key: {keys:?}");
    }
}
