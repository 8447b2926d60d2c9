//! A block's state: its nodes so far, with a border of zeros, what the
//! decoder and the encoder both predict and choose codes from.

use super::{BLOCK_MAX, CONTEXTS};
use crate::rgb_file::quantize::Node;

/// The side of a block's state: one more than the largest block, for a
/// border of zeros before each axis.
const SIDE: usize = BLOCK_MAX + 1;
/// Entries in a block's state.
const PADDED: usize = SIDE * SIDE * SIDE;

/// A block's decoded nodes (or, for the encoder, its nodes so far), with a
/// border of zeros before each axis, so that prediction and contexts read
/// neighbours outside the block as 0 without a branch.
#[derive(Clone, Debug)]
pub struct BlockState {
    /// Each node's integers.
    pub(super) k: [[i64; 3]; PADDED],
    /// Each node's form.
    pub(super) vertex: [bool; PADDED],
    /// The bit length of each node's differences.
    pub(super) length: [[u8; 3]; PADDED],
    /// The block's sides.
    dims: [usize; 3],
}

impl BlockState {
    /// An empty state for a block of sides `dims`.
    #[must_use]
    pub const fn new(dims: [usize; 3]) -> BlockState {
        BlockState { k: [[0; 3]; PADDED], vertex: [true; PADDED], length: [[0; 3]; PADDED], dims }
    }

    /// Where node `(z, y, x)` of the block is kept.
    #[inline(always)]
    pub(super) const fn padded(z: usize, y: usize, x: usize) -> usize {
        ((z + 1) * SIDE + y + 1) * SIDE + x + 1
    }

    /// Where node `i` (in `z, y, x` order) of the block is kept.
    #[inline(always)]
    pub(super) const fn place(&self, i: usize) -> usize {
        let [_, dy, dx] = self.dims;
        BlockState::padded(i / (dx * dy), i / dx % dy, i % dx)
    }

    /// Node `(z, y, x)`'s form and integers.
    #[inline(always)]
    #[must_use]
    pub const fn node_at(&self, z: usize, y: usize, x: usize) -> Node {
        let p = BlockState::padded(z, y, x);
        Node { vertex: self.vertex[p], k: self.k[p] }
    }

    /// Node `i`'s form and integers.
    #[must_use]
    pub const fn node(&self, i: usize) -> Node {
        let p = self.place(i);
        Node { vertex: self.vertex[p], k: self.k[p] }
    }

    /// Lorenzo's prediction of component `j` of the node kept at `p`: the
    /// seven neighbours below it, with alternating signs.
    #[inline(always)]
    pub(super) const fn predict(&self, p: usize, j: usize) -> i64 {
        let (x, y, z) = (1, SIDE, SIDE * SIDE);
        let k = &self.k;
        k[p - x][j]
            .wrapping_add(k[p - y][j])
            .wrapping_add(k[p - z][j])
            .wrapping_sub(k[p - x - y][j])
            .wrapping_sub(k[p - x - z][j])
            .wrapping_sub(k[p - y - z][j])
            .wrapping_add(k[p - x - y - z][j])
    }

    /// The code of component `j` of the node kept at `p`: its context,
    /// the mean bit length of the differences to the left, below and
    /// behind.
    #[inline(always)]
    pub(super) const fn table(&self, p: usize, j: usize) -> usize {
        let l = &self.length;
        let context =
            (l[p - 1][j] as usize + l[p - SIDE][j] as usize + l[p - SIDE * SIDE][j] as usize + 1) / 3;
        j * CONTEXTS + if context < CONTEXTS { context } else { CONTEXTS - 1 }
    }
}

/// The symbol of a difference (0; `2ℓ − 1` positive, `2ℓ` negative, `ℓ`
/// its bit length), its bit length, and its bits below the leading one.
pub(super) const fn symbol(r: i64) -> (usize, u32, u64) {
    if r == 0 {
        return (0, 0, 0);
    }
    let a = r.unsigned_abs();
    let len = 64 - a.leading_zeros();
    let sign = if r < 0 { 0 } else { 1 };
    (2 * len as usize - sign, len, a & !(1 << (len - 1)))
}
