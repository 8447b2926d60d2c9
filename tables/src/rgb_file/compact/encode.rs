//! Encoding: each block's nodes to symbols, the codes chosen from their
//! counts, the file assembled.

use super::block::symbol;
use super::{ALPHABET, BLOCK_MAX, BlockState, Layout, MAX_BITS, TABLES};
use crate::rgb_file::bits::BitWriter;
use crate::rgb_file::huffman::Code;
use crate::rgb_file::quantize::{Node, Quantizer};

/// A node's symbols as the encoder sends them: per component, the code,
/// the symbol, and the bits after it (value, count).
type Sent = [(usize, usize, u64, u32); 3];

/// The symbols of every node of block `id`, in order.
fn block_symbols(layout: &Layout, nodes: &[Node], id: usize) -> Vec<Sent> {
    let (n, b, d) = (layout.n, layout.block, layout.dims(id));
    let p = layout.per_axis;
    let (case, z0, y0, x0) = (id / (p * p * p), id / (p * p) % p * b, id / p % p * b, id % p * b);
    let mut state = BlockState::new(d);
    let mut vertex = true;
    let mut out = Vec::with_capacity(d[0] * d[1] * d[2]);
    for i in 0..d[0] * d[1] * d[2] {
        let (z, y, x) = (z0 + i / (d[1] * d[2]), y0 + i / d[2] % d[1], x0 + i % d[2]);
        let node = nodes[((case * n + z) * n + y) * n + x];
        let p = state.place(i);
        let mut sent = [(0, 0, 0, 0); 3];
        for (j, slot) in sent.iter_mut().enumerate() {
            let (s, len, rest) = symbol(node.k[j].wrapping_sub(state.predict(p, j)));
            let flip = usize::from(j == 0 && node.vertex != vertex);
            *slot = (state.table(p, j), if j == 0 { 2 * s + flip } else { s }, rest, len.saturating_sub(1));
            state.k[p][j] = node.k[j];
            state.length[p][j] = len as u8;
        }
        vertex = node.vertex;
        out.push(sent);
    }
    out
}

/// The compact file of a table of `n` nodes per axis whose coefficients,
/// `[case][z][y][x]`, are `coefficients`: every node rounded by
/// `quantizer` ([`Quantizer::node`]), then [`encode_nodes`].
///
/// # Panics
/// As [`encode_nodes`].
#[must_use]
pub fn encode(
    header: &crate::rgb_file::Header,
    quantizer: Quantizer,
    n: usize,
    coefficients: &[[f32; 3]],
) -> Vec<u8> {
    let nodes: Vec<Node> = coefficients.iter().map(|&c| quantizer.node(c)).collect();
    encode_nodes(header, quantizer, n, &nodes)
}

/// The compact file of a table of `n` nodes per axis whose rounded nodes,
/// `[case][z][y][x]`, are `nodes` (rounded by `quantizer`), in blocks of
/// `min(8, n)`. The header's version is set to 2.
///
/// # Panics
/// If `nodes` does not hold `3n³` nodes, or a difference needs more than
/// [`MAX_BITS`] bits (a node of finite coefficients never does).
#[must_use]
pub fn encode_nodes(
    header: &crate::rgb_file::Header,
    quantizer: Quantizer,
    n: usize,
    nodes: &[Node],
) -> Vec<u8> {
    assert_eq!(nodes.len(), 3 * n * n * n, "3n³ nodes");
    let block = n.min(BLOCK_MAX);
    let per_axis = n.div_ceil(block);
    let layout = Layout { n, quantizer, block, per_axis, tables: [0; TABLES], offsets: 0, stream: 0 };
    let sent: Vec<Vec<Sent>> = (0..layout.blocks()).map(|id| block_symbols(&layout, nodes, id)).collect();
    let mut counts = vec![vec![0u64; 2 * ALPHABET]; TABLES];
    for &(t, s, _, len) in sent.iter().flatten().flatten() {
        assert!(len < MAX_BITS, "a difference of {} bits", len + 1);
        counts[t][s] += 1;
    }
    let codes: Vec<Code> = counts.iter().map(|c| Code::from_counts(c)).collect();
    let (mut stream, mut offsets) = (BitWriter::default(), vec![0u32]);
    for block in &sent {
        for &(t, s, rest, len) in block.iter().flatten() {
            codes[t].write(&mut stream, s);
            stream.put(rest, len);
        }
        stream.align();
        offsets.push(stream.len() as u32);
    }
    let tables: Vec<u8> = codes.iter().flat_map(Code::to_bytes).collect();
    let mut header = header.clone();
    header.version = 2;
    let mut out = crate::rgb_file::encode_header(&header);
    let q = quantizer;
    let params = [q.float.mantissa, q.float.low_exponent as u32, q.vertex_bits, block as u32];
    let sizes = [tables.len() as u32, layout.blocks() as u32, stream.len() as u32, 0];
    out.extend(params.iter().chain(&sizes).flat_map(|w| w.to_le_bytes()));
    out.extend(tables);
    out.extend(offsets.iter().flat_map(|w| w.to_le_bytes()));
    out.extend(stream.finish());
    crate::rgb_file::finish(&mut out);
    out
}
