//! The file format of an RGB-to-spectrum table (speclab's `RgbTable`):
//! one versioned, checksummed binary layout, shared by the tables
//! embedded at build time, the ones a program saves, and the ones it
//! loads, so all three are checked by the same code with the same
//! messages.
//!
//! Version 1, every number little-endian:
//!
//! | offset | bytes | field |
//! |---:|---:|---|
//! | 0 | 8 | magic, `SPCLBRGB` |
//! | 8 | 4 | version, `u32` = 1 |
//! | 12 | 4 | resolution `n`, `u32`, 2 to 256 |
//! | 16 | 4 | node placement of the largest component, `u32` = 1 (see speclab's `rgb_table`) |
//! | 20 | 4 | reserved, 0 |
//! | 24 | 72 | the space's XYZ → RGB matrix the table was fitted for, 9 `f64`, row by row |
//! | 96 | 32 | the space's name, UTF-8, padded with zeros |
//! | 128 | 36 n³ | coefficients `[c₀, c₁, c₂]` as `f32`, `[case][z][y][x]` |
//! | end − 8 | 8 | FNV-1a (64-bit) of every byte before it |
//!
//! ```
//! use speclab_tables::rgb_file::{Header, HEADER_LEN, encode_header, finish, parse};
//! let header = Header { resolution: 2, matrix: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], name: "tiny".into() };
//! let mut bytes = encode_header(&header);
//! bytes.extend(std::iter::repeat_n(0u8, 36 * 8)); // 3 cases × 2³ nodes × 3 coefficients × 4 bytes
//! finish(&mut bytes);
//! assert_eq!(parse(&bytes, "tiny.rgbt")?, header);
//! bytes[HEADER_LEN] ^= 1; // one flipped bit
//! assert!(parse(&bytes, "tiny.rgbt").unwrap_err().to_string().contains("checksum"));
//! # Ok::<(), speclab_tables::rgb_file::FileError>(())
//! ```

use std::fmt;

/// The first eight bytes of every table file.
pub const MAGIC: [u8; 8] = *b"SPCLBRGB";
/// The version this code reads and writes.
pub const VERSION: u32 = 1;
/// The node placement this version knows: speclab's `rgb_table` nodes.
pub const GRID: u32 = 1;
/// Bytes before the coefficients.
pub const HEADER_LEN: usize = 128;
/// Bytes of the checksum after them.
pub const CHECKSUM_LEN: usize = 8;
/// The largest resolution a file may declare (3 × 256³ colours: 604 MB).
pub const MAX_RESOLUTION: u32 = 256;

/// What a table file says of itself.
#[derive(Clone, Debug, PartialEq)]
pub struct Header {
    /// Nodes per axis.
    pub resolution: u32,
    /// The XYZ → RGB matrix of the space the table was fitted for.
    pub matrix: [[f64; 3]; 3],
    /// The space's name (at most 32 bytes of UTF-8).
    pub name: String,
}

impl Header {
    /// Coefficient triples: three cases of `n³` colours.
    #[must_use]
    pub fn triples(&self) -> usize {
        3 * (self.resolution as usize).pow(3)
    }

    /// The length of the whole file.
    #[must_use]
    pub fn file_len(&self) -> usize {
        HEADER_LEN + 12 * self.triples() + CHECKSUM_LEN
    }
}

/// What is wrong with a table file; its message names the file.
#[derive(Clone, Debug, PartialEq)]
pub struct FileError {
    /// The file (or `<bytes>`).
    pub origin: String,
    /// What was expected and what was found.
    pub kind: FileErrorKind,
}

/// The ways a table file can be wrong.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum FileErrorKind {
    /// Not a table file: the first bytes are not [`MAGIC`].
    Magic,
    /// A version this code does not read.
    Version(u32),
    /// A resolution outside 2 to [`MAX_RESOLUTION`].
    Resolution(u32),
    /// A node placement this version does not know, or reserved bytes set.
    Grid(u32),
    /// A name that is not UTF-8.
    Name,
    /// A length other than the header's resolution implies.
    Length {
        /// Bytes the header implies.
        expected: usize,
        /// Bytes found.
        found: usize,
    },
    /// The checksum does not match the contents: a damaged file.
    Checksum {
        /// The checksum stored.
        stored: u64,
        /// The checksum of the contents.
        computed: u64,
    },
    /// A coefficient or a matrix entry that is NaN or infinite.
    NonFinite {
        /// Its byte offset.
        offset: usize,
    },
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.origin)?;
        match &self.kind {
            FileErrorKind::Magic => {
                write!(f, "expected an RGB table file (starting \"SPCLBRGB\"), found other bytes")
            }
            FileErrorKind::Version(v) => {
                write!(f, "expected table format version {VERSION}, found version {v}")
            }
            FileErrorKind::Resolution(n) => {
                write!(f, "expected a resolution from 2 to {MAX_RESOLUTION}, found {n}")
            }
            FileErrorKind::Grid(g) => {
                write!(f, "expected node placement {GRID} and zero reserved bytes, found {g}")
            }
            FileErrorKind::Name => write!(f, "expected a UTF-8 space name, found other bytes"),
            FileErrorKind::Length { expected, found } => {
                write!(f, "expected {expected} bytes for its resolution, found {found}")
            }
            FileErrorKind::Checksum { stored, computed } => write!(
                f,
                "expected checksum {stored:#018x} (stored), found {computed:#018x}: the file is damaged"
            ),
            FileErrorKind::NonFinite { offset } => {
                write!(f, "expected finite numbers, found NaN or infinity at byte {offset}")
            }
        }
    }
}

impl std::error::Error for FileError {}

/// FNV-1a, 64 bits.
#[must_use]
pub fn checksum(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

/// The header's bytes, [`HEADER_LEN`] of them (a name longer than 32
/// bytes is cut at a character boundary).
#[must_use]
pub fn encode_header(header: &Header) -> Vec<u8> {
    let mut out = Vec::with_capacity(header.file_len());
    out.extend(MAGIC);
    for word in [VERSION, header.resolution, GRID, 0] {
        out.extend(word.to_le_bytes());
    }
    out.extend(header.matrix.iter().flatten().flat_map(|v| v.to_le_bytes()));
    let mut end = header.name.len().min(32);
    while !header.name.is_char_boundary(end) {
        end -= 1;
    }
    out.extend(&header.name.as_bytes()[..end]);
    out.resize(HEADER_LEN, 0);
    out
}

/// Appends the checksum of `bytes` to them.
pub fn finish(bytes: &mut Vec<u8>) {
    let sum = checksum(bytes);
    bytes.extend(sum.to_le_bytes());
}

/// Checks a whole file and returns its header: magic, version,
/// resolution, node placement, length, checksum, and every number finite.
/// `origin` names the file in the error.
pub fn parse(bytes: &[u8], origin: &str) -> Result<Header, FileError> {
    let fail = |kind| FileError { origin: origin.to_string(), kind };
    if bytes.len() < 8 || bytes[..8] != MAGIC {
        return Err(fail(FileErrorKind::Magic));
    }
    if bytes.len() < HEADER_LEN {
        let expected = HEADER_LEN + CHECKSUM_LEN;
        return Err(fail(FileErrorKind::Length { expected, found: bytes.len() }));
    }
    let word = |at: usize| u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    if word(8) != VERSION {
        return Err(fail(FileErrorKind::Version(word(8))));
    }
    let resolution = word(12);
    if !(2..=MAX_RESOLUTION).contains(&resolution) {
        return Err(fail(FileErrorKind::Resolution(resolution)));
    }
    if word(16) != GRID || word(20) != 0 {
        return Err(fail(FileErrorKind::Grid(word(16).max(word(20)))));
    }
    let header = read_header(bytes).ok_or_else(|| fail(FileErrorKind::Name))?;
    if bytes.len() != header.file_len() {
        return Err(fail(FileErrorKind::Length { expected: header.file_len(), found: bytes.len() }));
    }
    let (body, tail) = bytes.split_at(bytes.len() - CHECKSUM_LEN);
    let stored = u64::from_le_bytes(std::array::from_fn(|i| tail[i]));
    let computed = checksum(body);
    if stored != computed {
        return Err(fail(FileErrorKind::Checksum { stored, computed }));
    }
    if let Some(r) = header.matrix.iter().flatten().position(|v| !v.is_finite()) {
        return Err(fail(FileErrorKind::NonFinite { offset: 24 + 8 * r }));
    }
    let floats = body[HEADER_LEN..].chunks_exact(4);
    if let Some(i) = floats.map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])).position(|v| !v.is_finite())
    {
        return Err(fail(FileErrorKind::NonFinite { offset: HEADER_LEN + 4 * i }));
    }
    Ok(header)
}

/// The header's resolution, matrix and name, read without checking the
/// rest (for bytes [`parse`] has checked): `None` for fewer than
/// [`HEADER_LEN`] bytes or a name that is not UTF-8.
#[must_use]
pub fn read_header(bytes: &[u8]) -> Option<Header> {
    let head = bytes.first_chunk::<HEADER_LEN>()?;
    let resolution = u32::from_le_bytes([head[12], head[13], head[14], head[15]]);
    let f64_at = |at: usize| f64::from_le_bytes(std::array::from_fn(|i| head[at + i]));
    let matrix = std::array::from_fn(|r| std::array::from_fn(|c| f64_at(24 + 8 * (3 * r + c))));
    let name = &head[96..];
    let len = name.iter().position(|&b| b == 0).unwrap_or(32);
    let name = std::str::from_utf8(&name[..len]).ok()?.to_string();
    Some(Header { resolution, matrix, name })
}

/// Reads and checks the table file at `path` (for build scripts, which
/// embed it): its header, or a message naming the file.
pub fn check_file(path: &std::path::Path) -> Result<Header, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    parse(&bytes, &path.display().to_string()).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
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

    fn tiny() -> Vec<u8> {
        let matrix = [[1.1, -0.3, 0.2], [0.25, 0.9, 1e-3], [0.07, -0.2, 1.05]];
        let header = Header { resolution: 2, matrix, name: "tiny".into() };
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
        cases.push((good[..64].to_vec(), "expected 136 bytes for its resolution, found 64"));
        cases.push((MAGIC.to_vec(), "expected 136 bytes for its resolution, found 8"));
        cases.push((good[..HEADER_LEN].to_vec(), "expected 424 bytes for its resolution, found 128"));
        cases.push((with(8, 2), "expected table format version 1, found version 2"));
        cases.push((with(12, 1), "expected a resolution from 2 to 256, found 1"));
        cases.push((with(12, 257), "found 257"));
        cases.push((with(16, 0), "expected node placement 1 and zero reserved bytes, found 0"));
        cases.push((with(20, 5), "found 5"));
        cases.push((with(12, 3), "expected 1108 bytes for its resolution, found 424"));
        cases.push((good[..good.len() - 1].to_vec(), "expected 424 bytes"));
        let mut flipped = good.clone();
        flipped[200] ^= 4;
        cases.push((flipped, "the file is damaged"));
        for (bytes, message) in cases {
            let e = parse(&bytes, "t.rgbt").unwrap_err().to_string();
            assert!(e.starts_with("t.rgbt: ") && e.contains(message), "{e} (wanted {message})");
        }
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
        let long = Header { resolution: 2, matrix: [[0.0; 3]; 3], name: format!("a{}", "é".repeat(20)) };
        assert_eq!(encode_header(&long).len(), HEADER_LEN);
        let mut bytes = encode_header(&long);
        bytes.extend([0u8; 288]);
        finish(&mut bytes);
        assert_eq!(parse(&bytes, "t").unwrap().name, format!("a{}", "é".repeat(15)));
    }
}
