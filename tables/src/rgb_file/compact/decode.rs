//! Decoding: a block (a `const fn`, for lookups at compile time), a
//! slab of blocks (run time), the eight corners of a cell, every node.

use super::{BlockState, Layout, MAX_BITS};
use crate::rgb_file::bits::BitReader;
use crate::rgb_file::huffman;
use crate::rgb_file::quantize::Node;

/// Decodes block `id`'s nodes up to (not including) node `upto` into
/// `state`: the block's bits left unread, or `None` for bits that are no
/// code, or that run past the block.
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
            let Some(mut s) = huffman::decode(&mut reader, bytes, layout.tables[state.table(p, j)]) else {
                return None;
            };
            if j == 0 {
                vertex ^= s & 1 == 1;
                s >>= 1;
            }
            let len = (s as u32).div_ceil(2);
            if len > MAX_BITS {
                return None;
            }
            let r = if s == 0 { 0 } else { ((1u64 << (len - 1)) | reader.bits(len - 1)) as i64 };
            let r = if s % 2 == 0 { r.wrapping_neg() } else { r };
            state.k[p][j] = state.predict(p, j).wrapping_add(r);
            state.length[p][j] = len as u8;
            j += 1;
        }
        state.vertex[p] = vertex;
        i += 1;
    }
    if reader.overrun { None } else { Some(reader.remaining()) }
}

/// The coefficients of node `i` of a decoded block.
#[must_use]
pub const fn coefficients(layout: &Layout, state: &BlockState, i: usize) -> [f32; 3] {
    layout.quantizer.coefficients(state.node(i))
}

/// The coefficients of the slab `s` of case `case`: nodes `z` from `s·B`
/// to `min(s·B + B, n − 1)` (one past the blocks' own, so that every
/// interval of `z` lies in one slab), all `y` and `x`, `[z][y][x]`.
#[must_use]
pub fn decode_slab(bytes: &[u8], layout: &Layout, case: usize, s: usize) -> Vec<[f32; 3]> {
    let (n, b) = (layout.n, layout.block);
    let z0 = s * b;
    let z_end = (z0 + b).min(n - 1);
    let mut out = vec![[0.0; 3]; (z_end - z0 + 1) * n * n];
    let mut state = BlockState::new([0; 3]);
    for z in (z0..=z_end).step_by(b) {
        for (y, x) in (0..n).step_by(b).flat_map(|y| (0..n).step_by(b).map(move |x| (y, x))) {
            let (id, _) = layout.block_of(case, z, y, x);
            let d = layout.dims(id);
            // The next slab's first z only, when z is past this slab's blocks.
            let dz = if z > z0 { 1 } else { d[0] };
            let _ = decode_block(bytes, layout, id, dz * d[1] * d[2], &mut state);
            for i in 0..dz * d[1] * d[2] {
                let (bz, by, bx) = (i / (d[1] * d[2]), i / d[2] % d[1], i % d[2]);
                out[((z - z0 + bz) * n + y + by) * n + x + bx] = coefficients(layout, &state, i);
            }
        }
    }
    out
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
/// [`encode_nodes`] makes the same bytes of.
#[must_use]
pub fn decode_nodes(bytes: &[u8]) -> Vec<Node> {
    let layout = Layout::read(bytes);
    let n = layout.n;
    let mut out = vec![Node { vertex: true, k: [0; 3] }; 3 * n * n * n];
    let mut state = BlockState::new([0; 3]);
    for id in 0..layout.blocks() {
        let d = layout.dims(id);
        let _ = decode_block(bytes, &layout, id, d[0] * d[1] * d[2], &mut state);
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
