//! Checking a compact file read from outside: every part in range and
//! every block decoded.

use super::{
    ALPHABET, BLOCK_MAX, BODY_START, BlockState, CONTEXTS, Decoder, Layout, TABLES, coefficients, word,
};
use crate::rgb_file::FileErrorKind;
use crate::rgb_file::huffman;

/// Checks a compact file whose common header and checksum are checked:
/// its parameters, codes, offsets, and with `blocks`, every block decoded
/// within its bytes into finite coefficients.
pub(crate) fn check(bytes: &[u8], blocks: bool) -> Result<(), FileErrorKind> {
    let layout = check_layout(bytes)?;
    if !blocks {
        return Ok(());
    }
    let decoder = Decoder::new(bytes);
    let mut state = BlockState::new([0; 3]);
    for id in 0..layout.blocks() {
        let d = layout.dims(id);
        let nodes = d[0] * d[1] * d[2];
        let (start, _) = layout.block_bytes(bytes, id);
        // Every bit a code, and no byte left over.
        if decoder.block(bytes, id, nodes, &mut state).is_none_or(|left| left >= 8) {
            return Err(FileErrorKind::Block { block: id });
        }
        if (0..nodes).any(|i| coefficients(&layout, &state, i).iter().any(|v| !v.is_finite())) {
            return Err(FileErrorKind::NonFinite { offset: start });
        }
    }
    Ok(())
}

/// The parameters, lengths, codes and offsets of a compact file.
fn check_layout(bytes: &[u8]) -> Result<Layout, FileErrorKind> {
    let n = word(bytes, 12) as usize;
    let param =
        |name, value: i64, ok: bool| if ok { Ok(()) } else { Err(FileErrorKind::Parameter { name, value }) };
    let (m, low, vb, block) = (word(bytes, 128), word(bytes, 132) as i32, word(bytes, 136), word(bytes, 140));
    param("mantissa bits", m.into(), (1..=23).contains(&m))?;
    param("low exponent", low.into(), (-60..=0).contains(&low))?;
    param("vertex bits", vb.into(), (4..=24).contains(&vb))?;
    param("block side", block.into(), block as usize == n.min(BLOCK_MAX))?;
    param("reserved", word(bytes, 156).into(), word(bytes, 156) == 0)?;
    let layout = Layout::read(bytes);
    let tables_len = word(bytes, 144) as usize;
    let (blocks, stream_len) = (word(bytes, 148) as usize, word(bytes, 152) as usize);
    param("block count", blocks as i64, blocks == layout.blocks())?;
    let expected = BODY_START + tables_len + 4 * (blocks + 1) + stream_len + crate::rgb_file::CHECKSUM_LEN;
    if bytes.len() != expected {
        return Err(FileErrorKind::Length { expected, found: bytes.len() });
    }
    for (t, &at) in layout.tables.iter().enumerate() {
        let alphabet = if t < CONTEXTS { 2 * ALPHABET } else { ALPHABET };
        let fits = huffman::stored_len(bytes, at).is_some_and(|len| at + len <= BODY_START + tables_len);
        if !(fits && huffman::stored_is_valid(bytes, at, alphabet)) {
            return Err(FileErrorKind::Code { table: t });
        }
    }
    let last = layout.tables[TABLES - 1];
    if huffman::stored_len(bytes, last).map(|len| last + len) != Some(BODY_START + tables_len) {
        return Err(FileErrorKind::Code { table: TABLES - 1 });
    }
    let offset = |i: usize| word(bytes, layout.offsets + 4 * i) as usize;
    if let Some(id) = (0..blocks).find(|&i| offset(i) > offset(i + 1)) {
        return Err(FileErrorKind::Block { block: id });
    }
    if offset(0) != 0 || offset(blocks) != stream_len {
        return Err(FileErrorKind::Block { block: if offset(0) != 0 { 0 } else { blocks - 1 } });
    }
    Ok(layout)
}
