//! Decoding: a block (a `const fn`, for lookups at compile time), a
//! slab of blocks (run time), the eight corners of a cell, every node.

use super::{BlockState, Layout, MAX_BITS};
use crate::rgb_file::bits::BitReader;
use crate::rgb_file::huffman;
use crate::rgb_file::quantize::Node;

/// Decodes block `id`'s nodes up to (not including) node `upto` into
/// `state`: the block's bits left unread, or `None` for bits that are no
/// code, or that run past the block. The `const` form, for lookups at
/// compile time; [`Decoder`] decodes the same at run time, faster.
#[must_use]
pub const fn decode_block(
    bytes: &[u8],
    layout: &Layout,
    id: usize,
    upto: usize,
    state: &mut BlockState,
) -> Option<usize> {
    let (start, end) = layout.block_bytes(bytes, id);
    let mut reader = BitReader::new(bytes, start, end);
    let [dz, dy, dx] = layout.dims(id);
    *state = BlockState::new([dz, dy, dx]);
    let mut vertex = true;
    let mut i = 0;
    while i < upto && i < dz * dy * dx {
        let p = BlockState::padded(i / (dx * dy), i / dx % dy, i % dx);
        let mut j = 0;
        while j < 3 {
            let Some(s) = huffman::decode(&mut reader, bytes, layout.tables[state.table(p, j)]) else {
                return None;
            };
            if !take(state, p, j, s, &mut reader, &mut vertex) {
                return None;
            }
            j += 1;
        }
        i += 1;
    }
    if reader.overrun { None } else { Some(reader.remaining()) }
}

/// Component `j` of the node kept at `p`, from its symbol `s` and the bits
/// after it: the difference added to the prediction (and, for the first
/// component, the form flipped if the symbol says so). `false` for a
/// symbol past the longest difference.
#[inline(always)]
const fn take(
    state: &mut BlockState,
    p: usize,
    j: usize,
    s: usize,
    reader: &mut BitReader,
    vertex: &mut bool,
) -> bool {
    let mut s = s;
    if j == 0 {
        *vertex ^= s & 1 == 1;
        state.vertex[p] = *vertex;
        s >>= 1;
    }
    let len = (s as u32).div_ceil(2);
    if len > MAX_BITS {
        return false;
    }
    let r = if s == 0 { 0 } else { ((1u64 << (len - 1)) | reader.bits(len - 1)) as i64 };
    let r = if s.is_multiple_of(2) { r.wrapping_neg() } else { r };
    state.k[p][j] = state.predict(p, j).wrapping_add(r);
    state.length[p][j] = len as u8;
    true
}

/// A compact file's decoder at run time: its layout and a lookup table per
/// stored code ([`huffman::Lut`]), made once per file.
#[derive(Clone, Debug)]
pub struct Decoder {
    /// The file's layout.
    pub layout: Layout,
    luts: Vec<huffman::Lut>,
}

impl Decoder {
    /// The decoder of the compact file `bytes`.
    #[must_use]
    pub fn new(bytes: &[u8]) -> Decoder {
        let layout = Layout::read(bytes);
        Decoder { layout, luts: layout.tables.iter().map(|&at| huffman::Lut::new(bytes, at)).collect() }
    }

    /// [`decode_block`], the same nodes, at run time.
    #[must_use]
    pub fn block(&self, bytes: &[u8], id: usize, upto: usize, state: &mut BlockState) -> Option<usize> {
        let layout = &self.layout;
        let (start, end) = layout.block_bytes(bytes, id);
        let mut reader = BitReader::new(bytes, start, end);
        let [dz, dy, dx] = layout.dims(id);
        *state = BlockState::new([dz, dy, dx]);
        let (mut vertex, mut left) = (true, upto.min(dz * dy * dx));
        // Nested loops: no division per node.
        'nodes: for z in 0..dz {
            for y in 0..dy {
                for x in 0..dx {
                    if left == 0 {
                        break 'nodes;
                    }
                    left -= 1;
                    let p = BlockState::padded(z, y, x);
                    for j in 0..3 {
                        let t = state.table(p, j);
                        let s = self.luts[t].decode(&mut reader, bytes, layout.tables[t])?;
                        if !take(state, p, j, s, &mut reader, &mut vertex) {
                            return None;
                        }
                    }
                }
            }
        }
        if reader.overrun { None } else { Some(reader.remaining()) }
    }

    /// The coefficients of the tile `(tz, ty)` of case `case`: nodes `z`
    /// from `tz·B` to `min(tz·B + B, n − 1)` and `y` from `ty·B` to
    /// `min(ty·B + B, n − 1)` (one past the blocks' own, so that every
    /// cell lies in one tile), every `x`; `[z][y][x]` with `B + 1` places
    /// for `z` and for `y` (zeros where the table ends). The blocks of the
    /// tile, the next row's first `y` and the next slice's first `z`:
    /// about 16 blocks' worth of decoding.
    #[must_use]
    pub fn tile(&self, bytes: &[u8], case: usize, tz: usize, ty: usize) -> Vec<[f32; 3]> {
        let layout = &self.layout;
        let (n, b) = (layout.n, layout.block);
        let (z0, y0) = (tz * b, ty * b);
        let (z_end, y_end) = ((z0 + b).min(n - 1), (y0 + b).min(n - 1));
        let mut out = vec![[0.0; 3]; (b + 1) * (b + 1) * n];
        let mut state = BlockState::new([0; 3]);
        for (z, y) in (z0..=z_end).step_by(b).flat_map(|z| (y0..=y_end).step_by(b).map(move |y| (z, y))) {
            for x in (0..n).step_by(b) {
                let (id, _) = layout.block_of(case, z, y, x);
                let [dz, dy, dx] = layout.dims(id);
                // Past the tile's own blocks, the first z or y alone.
                let (dz, dy) = (if z > z0 { 1 } else { dz }, if y > y0 { 1 } else { dy });
                let last = ((dz - 1) * layout.dims(id)[1] + dy - 1) * dx + dx;
                let _ = self.block(bytes, id, last, &mut state);
                for (bz, by) in (0..dz).flat_map(|bz| (0..dy).map(move |by| (bz, by))) {
                    let row = ((z - z0 + bz) * (b + 1) + y - y0 + by) * n + x;
                    for (bx, out) in out[row..row + dx].iter_mut().enumerate() {
                        *out = layout.quantizer.coefficients(state.node_at(bz, by, bx));
                    }
                }
            }
        }
        out
    }
}

/// The coefficients of node `i` of a decoded block.
#[must_use]
pub const fn coefficients(layout: &Layout, state: &BlockState, i: usize) -> [f32; 3] {
    layout.quantizer.coefficients(state.node(i))
}

/// The coefficients of the eight nodes `(z + dz, y + dy, x + dx)`, each of
/// `dz, dy, dx` 0 or 1, in the order `[dz][dy][dx]`: the blocks they lie
/// in decoded as far as needed. For lookups at compile time.
#[must_use]
pub const fn corners(
    bytes: &[u8],
    layout: &Layout,
    case: usize,
    z: usize,
    y: usize,
    x: usize,
) -> [[f32; 3]; 8] {
    let mut place = [(0usize, 0usize); 8];
    let mut c = 0;
    while c < 8 {
        place[c] = layout.block_of(case, z + c / 4, y + c / 2 % 2, x + c % 2);
        c += 1;
    }
    let mut out = [[0.0; 3]; 8];
    let mut state = BlockState::new([0; 3]);
    let mut c = 0;
    while c < 8 {
        // The first corner of each block decodes it for all its corners.
        let (id, _) = place[c];
        let mut seen = false;
        let mut upto = 0;
        let mut e = 0;
        while e < 8 {
            seen |= e < c && place[e].0 == id;
            if place[e].0 == id && place[e].1 + 1 > upto {
                upto = place[e].1 + 1;
            }
            e += 1;
        }
        if !seen {
            let _ = decode_block(bytes, layout, id, upto, &mut state);
            let mut e = c;
            while e < 8 {
                if place[e].0 == id {
                    out[e] = coefficients(layout, &state, place[e].1);
                }
                e += 1;
            }
        }
        c += 1;
    }
    out
}

/// Every node of a checked compact file, `[case][z][y][x]`: what
/// [`encode_nodes`](super::encode_nodes) makes the same bytes of.
#[must_use]
pub fn decode_nodes(bytes: &[u8]) -> Vec<Node> {
    let decoder = Decoder::new(bytes);
    let layout = decoder.layout;
    let n = layout.n;
    let mut out = vec![Node { vertex: true, k: [0; 3] }; 3 * n * n * n];
    let mut state = BlockState::new([0; 3]);
    for id in 0..layout.blocks() {
        let d = layout.dims(id);
        let _ = decoder.block(bytes, id, d[0] * d[1] * d[2], &mut state);
        let p = layout.per_axis;
        let (case, z0, y0, x0) = (
            id / (p * p * p),
            id / (p * p) % p * layout.block,
            id / p % p * layout.block,
            id % p * layout.block,
        );
        for i in 0..d[0] * d[1] * d[2] {
            let (z, y, x) = (z0 + i / (d[1] * d[2]), y0 + i / d[2] % d[1], x0 + i % d[2]);
            out[((case * n + z) * n + y) * n + x] = state.node(i);
        }
    }
    out
}
