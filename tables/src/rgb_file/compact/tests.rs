//! The compact format on small made-up tables: encoding and decoding agree
//! node for node, slab for slab and corner for corner; decoding the nodes
//! and encoding them again gives the same bytes; and every part of a file
//! that is wrong is named.

use super::*;
use crate::rgb_file::quantize::Node;
use crate::rgb_file::{FileErrorKind, Header, finish, parse};

/// A smooth field of coefficients over `n³` nodes per case, with both
/// forms (bumps whose vertex lies inside, ramps whose vertex lies far),
/// black at `z = 0` and large saturated values.
fn table(n: usize) -> Vec<[f32; 3]> {
    let mut out = Vec::new();
    for case in 0..3 {
        for z in 0..n {
            for y in 0..n {
                for x in 0..n {
                    let (fz, fy, fx) = [z, y, x].map(|v| v as f64 / (n - 1) as f64).into();
                    let c = if z == 0 {
                        [0.0, 0.0, -1e4]
                    } else if (x + y + case) % 5 == 0 {
                        [1e-3 * fx, 30.0 * fy - 10.0, -12.0 + fz]
                    } else {
                        let a = -(20.0 + 3000.0 * fz * fz * fx) * if case == 1 { -1.0 } else { 1.0 };
                        [a, -2.0 * a * (0.2 + 0.5 * fy), -5.0 + 40.0 * fx * fz]
                    };
                    out.push(c.map(|v| v as f32));
                }
            }
        }
    }
    out
}

fn header(n: usize) -> Header {
    Header {
        version: 2,
        resolution: n as u32,
        matrix: [[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, -0.2, 1.0]],
        name: "made up".into(),
    }
}

/// Node for node, slab for slab, corner for corner, at sizes that fill
/// blocks and that do not.
#[test]
fn decoding_gives_the_rounded_nodes() {
    let q = Quantizer::DEFAULT;
    for n in [2, 5, 8, 9, 17] {
        let c = table(n);
        let bytes = encode(&header(n), q, n, &c);
        assert_eq!(parse(&bytes, "t").map(|h| h.version), Ok(2), "n = {n}");
        let nodes: Vec<Node> = c.iter().map(|&c| q.node(c)).collect();
        assert!(nodes.iter().any(|n| n.vertex) && nodes.iter().any(|n| !n.vertex));
        assert_eq!(decode_nodes(&bytes), nodes, "n = {n}");
        let (layout, decoder) = (Layout::read(&bytes), Decoder::new(&bytes));
        let b = n.min(BLOCK_MAX);
        // The run-time decoder and the `const` one, block by block.
        let (mut fast, mut slow) = (BlockState::new([0; 3]), BlockState::new([0; 3]));
        for id in 0..layout.blocks() {
            let nodes = layout.dims(id).iter().product();
            let left = decoder.block(&bytes, id, nodes, &mut fast);
            assert_eq!(left, decode_block(&bytes, &layout, id, nodes, &mut slow), "n {n} block {id}");
            assert!((0..nodes).all(|i| fast.node(i) == slow.node(i)), "n {n} block {id}");
        }
        for case in 0..3 {
            for (tz, ty) in
                (0..(n - 1).div_ceil(b)).flat_map(|tz| (0..(n - 1).div_ceil(b)).map(move |ty| (tz, ty)))
            {
                let tile = decoder.tile(&bytes, case, tz, ty);
                assert_eq!(tile.len(), (b + 1) * (b + 1) * n);
                for (i, got) in tile.iter().enumerate() {
                    let (z, y, x) = (tz * b + i / ((b + 1) * n), ty * b + i / n % (b + 1), i % n);
                    let inside = z <= (tz * b + b).min(n - 1) && y <= (ty * b + b).min(n - 1);
                    let want = if inside {
                        q.coefficients(nodes[((case * n + z) * n + y) * n + x])
                    } else {
                        [0.0; 3]
                    };
                    assert_eq!(*got, want, "n {n} tile {tz} {ty} node {z} {y} {x}");
                }
            }
            let last = n - 2;
            for (z, y, x) in [
                (0, 0, 0),
                (last, last, last),
                (b.min(last), 1.min(last), n / 2 - 1),
                ((n / 2).min(last), (b - 1).min(last), 0),
            ] {
                let corners = corners(&bytes, &layout, case, z, y, x);
                for (k, got) in corners.iter().enumerate() {
                    let at = ((case * n + z + k / 4) * n + y + k / 2 % 2) * n + x + k % 2;
                    assert_eq!(
                        *got,
                        q.coefficients(nodes[at]),
                        "n {n} case {case} corner {k} of {z} {y} {x}"
                    );
                }
            }
        }
    }
}

/// Decoded nodes encode to the very bytes they came from.
#[test]
fn decode_then_encode_gives_the_same_bytes() {
    for n in [3, 8, 12] {
        let bytes = encode(&header(n), Quantizer::DEFAULT, n, &table(n));
        assert_eq!(encode_nodes(&header(n), Quantizer::DEFAULT, n, &decode_nodes(&bytes)), bytes);
    }
}

/// `bytes` with the 32-bit word at `at` set to `value`, checksum redone.
fn with_word(bytes: &[u8], at: usize, value: u32) -> Vec<u8> {
    let mut b = bytes[..bytes.len() - 8].to_vec();
    b[at..at + 4].copy_from_slice(&value.to_le_bytes());
    finish(&mut b);
    b
}

/// Each part of a compact file, wrong, is an error that names it.
#[test]
fn wrong_parts_are_named() {
    let n = 9;
    let good = encode(&header(n), Quantizer::DEFAULT, n, &table(n));
    let layout = Layout::read(&good);
    let kind = |bytes: &[u8]| parse(bytes, "t").unwrap_err().kind;
    let param =
        |name| move |k: FileErrorKind| matches!(k, FileErrorKind::Parameter { name: m, .. } if m == name);
    assert!(param("mantissa bits")(kind(&with_word(&good, 128, 0))));
    assert!(param("mantissa bits")(kind(&with_word(&good, 128, 24))));
    assert!(param("low exponent")(kind(&with_word(&good, 132, 1))));
    assert!(param("vertex bits")(kind(&with_word(&good, 136, 3))));
    assert!(param("block side")(kind(&with_word(&good, 140, 4))));
    assert!(param("reserved")(kind(&with_word(&good, 156, 1))));
    assert!(param("block count")(kind(&with_word(&good, 148, 7))));
    assert!(matches!(kind(&with_word(&good, 152, 1)), FileErrorKind::Length { .. }));
    // A code with three one-bit codes.
    let over = with_word(&good, layout.tables[5], 3);
    assert_eq!(kind(&over), FileErrorKind::Code { table: 5 });
    // Offsets that fall back, and a stream cut short of its last block.
    let blocks = layout.blocks();
    let falling = with_word(&good, layout.offsets + 4 * 3, 1_000_000);
    assert_eq!(kind(&falling), FileErrorKind::Block { block: 3 });
    let first = with_word(&good, layout.offsets, 1);
    assert_eq!(kind(&first), FileErrorKind::Block { block: 0 });
    // A block's bits changed: it no longer decodes within its bytes, or
    // decodes to other numbers (which the checksum alone would catch).
    let (start, end) = layout.block_bytes(&good, blocks - 1);
    let mut flipped = good[..good.len() - 8].to_vec();
    flipped[start] ^= 0xff;
    flipped[end - 1] ^= 0x0f;
    finish(&mut flipped);
    assert!(parse(&flipped, "t").is_err() || decode_nodes(&flipped) != decode_nodes(&good));
    let e = parse(&good[..good.len() - 20], "cut.rgbt").unwrap_err();
    assert!(e.to_string().starts_with("cut.rgbt: expected"), "{e}");
}

/// A block whose bits are no codes: the structure passes (the checksum
/// stands for the bits, as a build script trusts), the whole check names
/// the block.
#[test]
fn structure_alone_does_not_decode_blocks() {
    let n = 9;
    let good = encode(&header(n), Quantizer::DEFAULT, n, &table(n));
    let layout = Layout::read(&good);
    let (start, end) = layout.block_bytes(&good, 2);
    let mut bad = good[..good.len() - 8].to_vec();
    bad[start..end].fill(0xff);
    finish(&mut bad);
    assert!(crate::rgb_file::parse_structure(&bad, "t").is_ok());
    assert_eq!(parse(&bad, "t").unwrap_err().kind, FileErrorKind::Block { block: 2 });
    assert!(crate::rgb_file::parse_structure(&good[1..], "t").is_err());
}

/// The longest differences, [`MAX_BITS`] bits of either sign, the form's
/// flip riding on the first component's: the top symbols of each alphabet,
/// which the file's codes hold and its check accepts.
#[test]
fn the_longest_differences_fit_the_alphabets() {
    let n = 2;
    let big = (1i64 << MAX_BITS) - 1;
    let zero = Node { vertex: true, k: [0; 3] };
    let mut nodes = vec![zero; 3 * n * n * n];
    // Down by `big` from the prediction 0, then back up by it.
    nodes[0] = Node { vertex: false, k: [-big; 3] };
    let bytes = encode_nodes(&header(n), Quantizer::DEFAULT, n, &nodes);
    assert_eq!(crate::rgb_file::parse_structure(&bytes, "t").map(|h| h.version), Ok(2));
    assert_eq!(decode_nodes(&bytes), nodes);
    // Only `v` (with `a` = 0 the coefficients stay finite): the whole check.
    nodes[0] = Node { vertex: true, k: [0, -big, 0] };
    let bytes = encode_nodes(&header(n), Quantizer::DEFAULT, n, &nodes);
    assert_eq!(parse(&bytes, "t").map(|h| h.version), Ok(2));
    assert_eq!(decode_nodes(&bytes), nodes);
}

/// `word` reads a word that ends the bytes, and 0 for one past them.
#[test]
fn words_up_to_the_last_byte() {
    assert_eq!(word(&[1, 2, 3, 4], 0), 0x0403_0201);
    assert_eq!(word(&[0, 1, 2, 3, 4], 1), 0x0403_0201);
    assert_eq!(word(&[1, 2, 3, 4], 1), 0);
}

/// The layout of bytes no check has seen: each number clamped into the
/// range the decoder handles, in range ones kept.
#[test]
fn layouts_clamp_what_they_read() {
    let read = |words: &[(usize, i64)]| {
        let mut bytes = vec![0u8; 200];
        for &(at, value) in words {
            bytes[at..at + 4].copy_from_slice(&(value as u32).to_le_bytes());
        }
        Layout::read(&bytes)
    };
    // Resolution 2 to 256; block side 1 to min(n, 8).
    for (n, block, want) in
        [(0, 0, (2, 1)), (1, 9, (2, 2)), (3, 8, (3, 3)), (5, 4, (5, 4)), (300, 9, (256, 8))]
    {
        let l = read(&[(12, n), (140, block)]);
        assert_eq!((l.n, l.block), want, "n {n}, block {block}");
        assert_eq!(l.per_axis, want.0.div_ceil(want.1));
    }
    // Mantissa bits 1 to 23; vertex bits 4 to 24.
    for (m, vb, want) in
        [(0, 3, (1, 4)), (1, 4, (1, 4)), (12, 16, (12, 16)), (23, 24, (23, 24)), (24, 25, (23, 24))]
    {
        let q = read(&[(12, 4), (128, m), (136, vb)]).quantizer;
        assert_eq!((q.float.mantissa, q.vertex_bits), want, "mantissa {m}, vertex bits {vb}");
    }
    // Low exponent −60 to 0, 0 outside.
    for (low, want) in [(-61, 0), (-60, -60), (-8, -8), (0, 0), (1, 0), (i64::from(i32::MIN), 0)] {
        let q = read(&[(12, 4), (128, 12), (132, low)]).quantizer;
        assert_eq!(q.float.low_exponent, want, "low exponent {low}");
    }
}
