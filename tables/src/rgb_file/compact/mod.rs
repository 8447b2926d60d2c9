//! Version 2 of the table file, compact: each node rounded
//! ([`quantize`](super::quantize)), predicted from its neighbours, and the
//! difference stored in a Huffman code chosen by the neighbours' own.
//!
//! The nodes go in blocks of `B³` (8³ in the built-in tables), each coded
//! on its own, so that a lookup at compile time decodes the few blocks
//! around its colour and a program decodes a tile of blocks when a colour
//! first needs it. Within a block, in `z, y, x` order:
//!
//! - the node's three integers are predicted by Lorenzo's rule, the sum of
//!   the seven decoded neighbours below it with alternating signs (exact
//!   for a trilinear field; neighbours outside the block count as 0);
//! - each difference is sent as a symbol, its bit length and sign, in the
//!   canonical Huffman code of its component and of a context, the mean
//!   bit length of the differences to the left, below and behind (16
//!   contexts); then its bits below the leading one;
//! - whether the node's form differs from the last node's rides on the
//!   first component's symbol.
//!
//! | offset | bytes | field |
//! |---:|---:|---|
//! | 0 | 128 | the common header, version 2 ([`super`]) |
//! | 128 | 16 | mantissa bits, low exponent (`i32`), vertex bits, block side `B` (each `u32`) |
//! | 144 | 16 | code tables' length, blocks, stream length, reserved 0 (each `u32`) |
//! | 160 | `T` | 48 stored codes ([`huffman`]): component 0's 16 contexts, then 1's, then 2's |
//! | 160 + `T` | `4(b + 1)` | each block's first byte in the stream, and the stream's length |
//! | … | `S` | the blocks' bits, each starting on a byte, `[case][bz][by][bx]` |
//! | end − 8 | 8 | FNV-1a of every byte before it |
//!
//! ```
//! use speclab_tables::rgb_file::{Header, compact, quantize::Quantizer};
//! let header = Header { version: 2, resolution: 4, matrix: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], name: "tiny".into() };
//! let c: Vec<[f32; 3]> = (0..3 * 64).map(|i| [-(i as f32), 2.0 * i as f32, -0.5]).collect();
//! let bytes = compact::encode(&header, Quantizer::DEFAULT, 4, &c);
//! let tile = compact::Decoder::new(&bytes).tile(&bytes, 2, 0, 0); // case 2: z, y and x from 0 to 3
//! assert_eq!(tile.len(), 5 * 5 * 4); // 4 + 1 places for z and y
//! assert_eq!(tile[5 * 4 + 1], Quantizer::DEFAULT.coefficients(Quantizer::DEFAULT.node(c[2 * 64 + 16 + 1])));
//! ```

mod block;
mod check;
mod decode;
mod encode;

pub use block::BlockState;
pub(crate) use check::check;
pub use decode::{Decoder, coefficients, corners, decode_block, decode_nodes};
pub use encode::{encode, encode_nodes};

use crate::rgb_file::HEADER_LEN;
use crate::rgb_file::huffman;
use crate::rgb_file::quantize::{Minifloat, Quantizer};

/// The largest block side.
pub const BLOCK_MAX: usize = 8;
/// Contexts per component.
pub const CONTEXTS: usize = 16;
/// The longest difference, in bits.
pub const MAX_BITS: u32 = 40;
/// Symbols of components 1 and 2: zero, then each length with each sign;
/// component 0 has twice as many (the form's flip).
pub const ALPHABET: usize = 2 * MAX_BITS as usize + 1;
/// Stored codes: three components of [`CONTEXTS`] each.
pub const TABLES: usize = 3 * CONTEXTS;
/// Where the stored codes start.
pub const BODY_START: usize = HEADER_LEN + 32;

/// Where the parts of a compact file are, read from its bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// Nodes per axis.
    pub n: usize,
    /// How the nodes were rounded.
    pub quantizer: Quantizer,
    /// The block side.
    pub block: usize,
    /// Blocks per axis.
    pub per_axis: usize,
    /// Where each stored code starts.
    pub tables: [usize; TABLES],
    /// Where the blocks' offsets start.
    pub offsets: usize,
    /// Where the stream starts.
    pub stream: usize,
}

/// `v` within `[low, high]`.
const fn clamp(v: usize, low: usize, high: usize) -> usize {
    if v < low {
        low
    } else if v > high {
        high
    } else {
        v
    }
}

/// The little-endian `u32` at byte `at` (0 past the end).
pub const fn word(bytes: &[u8], at: usize) -> u32 {
    if at + 4 > bytes.len() {
        return 0;
    }
    u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
}

impl Layout {
    /// The layout of a compact file ([`super::parse`] checks that every
    /// part fits). Of other bytes, a layout whose every number is in range
    /// (clamped), so that decoding them gives wrong numbers, never a panic.
    #[must_use]
    pub const fn read(bytes: &[u8]) -> Layout {
        let n = clamp(word(bytes, 12) as usize, 2, super::MAX_RESOLUTION as usize);
        let mantissa = clamp(word(bytes, 128) as usize, 1, 23) as u32;
        let low = word(bytes, 132) as i32;
        let float = Minifloat { mantissa, low_exponent: if low < -60 || low > 0 { 0 } else { low } };
        let quantizer = Quantizer { float, vertex_bits: clamp(word(bytes, 136) as usize, 4, 24) as u32 };
        let block = clamp(word(bytes, 140) as usize, 1, if n < BLOCK_MAX { n } else { BLOCK_MAX });
        let mut tables = [0; TABLES];
        let mut at = BODY_START;
        let mut t = 0;
        while t < TABLES {
            tables[t] = at;
            at += match huffman::stored_len(bytes, at) {
                Some(len) => len,
                None => 0,
            };
            t += 1;
        }
        let per_axis = n.div_ceil(block);
        let offsets = BODY_START + word(bytes, 144) as usize;
        let stream = offsets + 4 * (3 * per_axis * per_axis * per_axis + 1);
        Layout { n, quantizer, block, per_axis, tables, offsets, stream }
    }

    /// Blocks in the file.
    #[must_use]
    pub const fn blocks(&self) -> usize {
        3 * self.per_axis * self.per_axis * self.per_axis
    }

    /// The block of node `(case, z, y, x)` and the node's index in it.
    #[must_use]
    pub const fn block_of(&self, case: usize, z: usize, y: usize, x: usize) -> (usize, usize) {
        let (b, p) = (self.block, self.per_axis);
        let id = ((case * p + z / b) * p + y / b) * p + x / b;
        let d = self.dims(id);
        (id, ((z % b) * d[1] + y % b) * d[2] + x % b)
    }

    /// The sides `[z, y, x]` of block `id` (shorter at the far ends).
    #[must_use]
    pub const fn dims(&self, id: usize) -> [usize; 3] {
        let p = self.per_axis;
        [self.side(id / (p * p) % p), self.side(id / p % p), self.side(id % p)]
    }

    /// The side of the `i`th block along an axis.
    const fn side(&self, i: usize) -> usize {
        if (i + 1) * self.block > self.n { self.n - i * self.block } else { self.block }
    }

    /// Block `id`'s bytes in the file: `[start, end)`.
    #[must_use]
    pub const fn block_bytes(&self, bytes: &[u8], id: usize) -> (usize, usize) {
        let start = self.stream + word(bytes, self.offsets + 4 * id) as usize;
        (start, self.stream + word(bytes, self.offsets + 4 * id + 4) as usize)
    }
}

#[cfg(test)]
mod tests;
