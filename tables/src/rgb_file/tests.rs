use super::*;
use proptest::prelude::*;

proptest! {
    /// Any bytes, and a good file with any byte changed or cut
    /// anywhere: an error or the file, never a panic; a changed good
    /// file is always an error.
    #[test]
    fn parse_never_panics(bytes in proptest::collection::vec(any::<u8>(), 0..600), at in 0usize..424, bit in 0u8..8, cut in 0usize..424) {
        let _ = parse(&bytes, "x");
        let mut changed = tiny();
        changed[at] ^= 1 << bit;
        prop_assert!(parse(&changed, "x").is_err());
        prop_assert!(parse(&tiny()[..cut], "x").is_err());
    }
}

proptest! {
    /// A compact file with any bytes changed and its checksum redone
    /// (so that the checks past it see them): an error or a file, and
    /// decoded slab by slab and corner by corner whether checked or
    /// not, never a panic.
    #[test]
    fn compact_files_never_panic(changes in proptest::collection::vec((any::<usize>(), any::<u8>()), 1..6), cut in any::<usize>()) {
        let mut bytes = tiny_compact();
        let body = bytes.len() - CHECKSUM_LEN;
        for (at, value) in changes {
            bytes[at % body] = value;
        }
        bytes.truncate(body);
        finish(&mut bytes);
        // Checked or not (an embedded table trusts its build script).
        let _ = parse(&bytes, "x");
        let (layout, decoder) = (compact::Layout::read(&bytes), compact::Decoder::new(&bytes));
        for case in 0..3 {
            let _ = decoder.tile(&bytes, case, 0, 0);
            let _ = compact::corners(&bytes, &layout, case, 1, 1, 1);
        }
        let cut = cut % bytes.len();
        prop_assert!(parse(&bytes[..cut], "x").is_err());
    }
}

proptest! {
    /// Bytes no check has seen (an embedded table trusts its build
    /// script's check): decoded slabs and corners are wrong numbers,
    /// never a panic.
    #[test]
    fn unchecked_bytes_never_panic(mut bytes in proptest::collection::vec(any::<u8>(), 0..3000), n in 2u32..12) {
        bytes.resize(bytes.len().max(200), 7);
        bytes[8..12].copy_from_slice(&2u32.to_le_bytes());
        bytes[12..16].copy_from_slice(&n.to_le_bytes());
        let (layout, decoder) = (compact::Layout::read(&bytes), compact::Decoder::new(&bytes));
        for case in 0..3 {
            let _ = decoder.tile(&bytes, case, 0, 0);
            let _ = compact::corners(&bytes, &layout, case, 0, 0, 0);
        }
    }
}

/// A compact file of three nodes per axis.
fn tiny_compact() -> Vec<u8> {
    let header = Header { version: 2, resolution: 3, matrix: [[1.0, 0.0, 0.0]; 3], name: "tiny".into() };
    let c: Vec<[f32; 3]> =
        (0..81).map(|i| [-(i as f32) * 7.0, 3.0 * i as f32, 0.5 - i as f32 * 0.1]).collect();
    compact::encode(&header, quantize::Quantizer::DEFAULT, 3, &c)
}

fn tiny() -> Vec<u8> {
    let matrix = [[1.1, -0.3, 0.2], [0.25, 0.9, 1e-3], [0.07, -0.2, 1.05]];
    let header = Header { version: 1, resolution: 2, matrix, name: "tiny".into() };
    let mut bytes = encode_header(&header);
    bytes.extend((0..72).flat_map(|i| (i as f32).to_le_bytes()));
    finish(&mut bytes);
    bytes
}

/// Each field's error, named by its message.
#[test]
fn every_field_is_checked() {
    let good = tiny();
    assert_eq!(parse(&good, "t").unwrap().name, "tiny");
    let mut cases: Vec<(Vec<u8>, &str)> = Vec::new();
    let with = |at: usize, value: u32| {
        let mut b = good.clone();
        b[at..at + 4].copy_from_slice(&value.to_le_bytes());
        b
    };
    cases.push((b"PNG\x0d\x0a\x1a\x0a....".to_vec(), "expected an RGB table file"));
    cases.push((good[..64].to_vec(), "expected 136 bytes for what its header declares, found 64"));
    cases.push((MAGIC.to_vec(), "expected 136 bytes for what its header declares, found 8"));
    cases.push((good[..HEADER_LEN].to_vec(), "expected 136 bytes for what its header declares, found 128"));
    cases.push((with(8, 3), "expected table format version 1 or 2, found version 3"));
    cases.push((with(12, 1), "expected a resolution from 2 to 256, found 1"));
    cases.push((with(12, 257), "found 257"));
    cases.push((with(16, 0), "expected node placement 1 and zero reserved bytes, found 0"));
    cases.push((with(20, 5), "found 5"));
    cases.push((with(12, 3), "expected 1108 bytes for what its header declares, found 424"));
    cases.push((good[..good.len() - 1].to_vec(), "expected 424 bytes"));
    let mut flipped = good.clone();
    flipped[200] ^= 4;
    cases.push((flipped, "the file is damaged"));
    for (bytes, message) in cases {
        let e = parse(&bytes, "t.rgbt").unwrap_err().to_string();
        assert!(e.starts_with("t.rgbt: ") && e.contains(message), "{e} (wanted {message})");
    }
}

/// A file of exactly a header and a checksum is long enough for the
/// header's own checks: what is wrong is its version, or its length.
#[test]
fn a_header_and_a_checksum_reach_the_header_checks() {
    let bytes = tiny()[..HEADER_LEN + CHECKSUM_LEN].to_vec();
    let kind = |bytes: &[u8]| parse(bytes, "t").unwrap_err().kind;
    assert_eq!(kind(&bytes), FileErrorKind::Length { expected: tiny().len(), found: bytes.len() });
    let mut version_3 = bytes.clone();
    version_3[8] = 3;
    assert_eq!(kind(&version_3), FileErrorKind::Version(3));
}

#[test]
fn files_are_read_and_named() {
    let path = std::env::temp_dir().join(format!("speclab-rgb-file-{}.rgbt", std::process::id()));
    std::fs::write(&path, tiny()).unwrap();
    assert_eq!(check_file(&path).unwrap().resolution, 2);
    std::fs::write(&path, &tiny()[..200]).unwrap();
    let e = check_file(&path).unwrap_err();
    assert!(e.starts_with(&path.display().to_string()) && e.contains("expected 424 bytes"), "{e}");
    std::fs::remove_file(&path).unwrap();
    assert!(check_file(&path).unwrap_err().contains("cannot read"));
}

#[test]
fn names_and_non_finite_numbers() {
    let mut bad = tiny();
    bad[96] = 0xff;
    let n = bad.len() - CHECKSUM_LEN;
    bad.truncate(n);
    finish(&mut bad);
    assert!(parse(&bad, "t").unwrap_err().to_string().contains("UTF-8"));
    let cases = [
        (HEADER_LEN + 8, f32::NAN.to_le_bytes().to_vec()),
        (24, f64::INFINITY.to_le_bytes().to_vec()),
        (40, f64::NAN.to_le_bytes().to_vec()),
    ];
    for (at, value) in cases {
        let mut bad = tiny();
        bad[at..at + value.len()].copy_from_slice(&value);
        bad.truncate(n);
        finish(&mut bad);
        let e = parse(&bad, "t").unwrap_err();
        assert_eq!(e.kind, FileErrorKind::NonFinite { offset: at }, "{e}");
    }
    // 41 bytes: cut at 32, inside an "é", so at 31.
    let long =
        Header { version: 1, resolution: 2, matrix: [[0.0; 3]; 3], name: format!("a{}", "é".repeat(20)) };
    assert_eq!(encode_header(&long).len(), HEADER_LEN);
    let mut bytes = encode_header(&long);
    bytes.extend([0u8; 288]);
    finish(&mut bytes);
    assert_eq!(parse(&bytes, "t").unwrap().name, format!("a{}", "é".repeat(15)));
}
