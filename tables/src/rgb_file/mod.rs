//! The file format of an RGB-to-spectrum table (speclab's `RgbTable`):
//! one versioned, checksummed binary layout, shared by the tables
//! embedded at build time, the ones a program saves, and the ones it
//! loads, so all three are checked by the same code with the same
//! messages.
//!
//! Every version starts with the same 128 bytes, every number
//! little-endian:
//!
//! | offset | bytes | field |
//! |---:|---:|---|
//! | 0 | 8 | magic, `SPCLBRGB` |
//! | 8 | 4 | version, `u32`: 1 or 2 |
//! | 12 | 4 | resolution `n`, `u32`, 2 to 256 |
//! | 16 | 4 | node placement of the largest component, `u32` = 1 (see speclab's `rgb_table`) |
//! | 20 | 4 | reserved, 0 |
//! | 24 | 72 | the space's XYZ → RGB matrix the table was fitted for, 9 `f64`, row by row |
//! | 96 | 32 | the space's name, UTF-8, padded with zeros |
//!
//! and ends with 8 bytes, the FNV-1a (64-bit) checksum of every byte
//! before them. Between them:
//!
//! - **version 1**, the coefficients as they were fitted: `[c₀, c₁, c₂]`
//!   as `f32`, `[case][z][y][x]`, 36 n³ bytes (9.4 MB at n = 64);
//! - **version 2**, compact ([`compact`]): each node rounded
//!   ([`quantize`]), predicted from its neighbours, and Huffman-coded, in
//!   blocks that decode on their own (1.4–2.3 MB at n = 64).
//!
//! ```
//! use speclab_tables::rgb_file::{Header, HEADER_LEN, encode_header, finish, parse};
//! let header = Header { version: 1, resolution: 2, matrix: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], name: "tiny".into() };
//! let mut bytes = encode_header(&header);
//! bytes.extend(std::iter::repeat_n(0u8, 36 * 8)); // 3 cases × 2³ nodes × 3 coefficients × 4 bytes
//! finish(&mut bytes);
//! assert_eq!(parse(&bytes, "tiny.rgbt")?, header);
//! bytes[HEADER_LEN] ^= 1; // one flipped bit
//! assert!(parse(&bytes, "tiny.rgbt").unwrap_err().to_string().contains("checksum"));
//! # Ok::<(), speclab_tables::rgb_file::FileError>(())
//! ```

pub mod bits;
pub mod compact;
pub mod huffman;
pub mod quantize;

use std::fmt;

/// The first eight bytes of every table file.
pub const MAGIC: [u8; 8] = *b"SPCLBRGB";
/// The version of the coefficients as fitted, in `f32`.
pub const VERSION_F32: u32 = 1;
/// The version of compact tables ([`compact`]).
pub const VERSION_COMPACT: u32 = 2;
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
    /// The format version: [`VERSION_F32`] or [`VERSION_COMPACT`].
    pub version: u32,
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

    /// The length of the whole file in version 1.
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
    /// A length other than the header implies.
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
        /// Its byte offset (for a compact file, the offset of its block).
        offset: usize,
    },
    /// A compact file's coding parameter outside what this code reads.
    Parameter {
        /// Which: `mantissa bits`, `low exponent`, `vertex bits`, `block side`, `reserved`.
        name: &'static str,
        /// Its value.
        value: i64,
    },
    /// A compact file's stored code that is no prefix code of its symbols.
    Code {
        /// Which of the 48 codes.
        table: usize,
    },
    /// A compact file's block whose bits are no codes, or run past its
    /// bytes, or whose offset does not follow the last one's.
    Block {
        /// Which block.
        block: usize,
    },
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.origin)?;
        match &self.kind {
            FileErrorKind::Magic => {
                write!(f, "expected an RGB table file (starting \"SPCLBRGB\"), found other bytes")
            }
            FileErrorKind::Version(v) => write!(
                f,
                "expected table format version {VERSION_F32} or {VERSION_COMPACT}, found version {v}"
            ),
            FileErrorKind::Resolution(n) => {
                write!(f, "expected a resolution from 2 to {MAX_RESOLUTION}, found {n}")
            }
            FileErrorKind::Grid(g) => {
                write!(f, "expected node placement {GRID} and zero reserved bytes, found {g}")
            }
            FileErrorKind::Name => write!(f, "expected a UTF-8 space name, found other bytes"),
            FileErrorKind::Length { expected, found } => {
                write!(f, "expected {expected} bytes for what its header declares, found {found}")
            }
            FileErrorKind::Checksum { stored, computed } => write!(
                f,
                "expected checksum {stored:#018x} (stored), found {computed:#018x}: the file is damaged"
            ),
            FileErrorKind::NonFinite { offset } => {
                write!(f, "expected finite numbers, found NaN or infinity at byte {offset}")
            }
            FileErrorKind::Parameter { name, value } => {
                write!(f, "expected a compact table's {name} in range, found {value}")
            }
            FileErrorKind::Code { table } => {
                write!(f, "expected a prefix code in stored code {table}, found an over-full one")
            }
            FileErrorKind::Block { block } => {
                write!(f, "expected block {block} to decode within its bytes, found other bits")
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
    let mut out = Vec::with_capacity(HEADER_LEN);
    out.extend(MAGIC);
    for word in [header.version, header.resolution, GRID, 0] {
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
/// resolution, node placement, length, checksum, and every number finite
/// (for a compact file, every block decoded and each node's coefficients
/// finite: about 0.1 s in a release build). `origin` names the file in the
/// error.
pub fn parse(bytes: &[u8], origin: &str) -> Result<Header, FileError> {
    parse_to(bytes, origin, Depth::Blocks)
}

/// [`parse`] without decoding a compact file's blocks: its parameters,
/// codes and offsets checked, the checksum standing for the blocks' bits.
/// What a build script needs of a file it embeds (milliseconds, where
/// decoding every block of four tables in an unoptimised build script
/// takes a second); the crate's tests decode the built-in files whole.
pub fn parse_structure(bytes: &[u8], origin: &str) -> Result<Header, FileError> {
    parse_to(bytes, origin, Depth::Structure)
}

/// How far [`parse_to`] checks a compact file.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Depth {
    Structure,
    Blocks,
}

fn parse_to(bytes: &[u8], origin: &str, depth: Depth) -> Result<Header, FileError> {
    let fail = |kind| FileError { origin: origin.to_string(), kind };
    let header = parse_header(bytes).map_err(fail)?;
    if header.version == VERSION_F32 && bytes.len() != header.file_len() {
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
    if header.version == VERSION_COMPACT {
        compact::check(bytes, depth == Depth::Blocks).map_err(fail)?;
        return Ok(header);
    }
    let floats = body[HEADER_LEN..].chunks_exact(4);
    if let Some(i) = floats.map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])).position(|v| !v.is_finite())
    {
        return Err(fail(FileErrorKind::NonFinite { offset: HEADER_LEN + 4 * i }));
    }
    Ok(header)
}

/// The common header's checks: magic, version, resolution, node
/// placement, name, and room for the checksum.
fn parse_header(bytes: &[u8]) -> Result<Header, FileErrorKind> {
    if bytes.len() < 8 || bytes[..8] != MAGIC {
        return Err(FileErrorKind::Magic);
    }
    if bytes.len() < HEADER_LEN + CHECKSUM_LEN {
        return Err(FileErrorKind::Length { expected: HEADER_LEN + CHECKSUM_LEN, found: bytes.len() });
    }
    let word = |at: usize| compact::word(bytes, at);
    if word(8) != VERSION_F32 && word(8) != VERSION_COMPACT {
        return Err(FileErrorKind::Version(word(8)));
    }
    let resolution = word(12);
    if !(2..=MAX_RESOLUTION).contains(&resolution) {
        return Err(FileErrorKind::Resolution(resolution));
    }
    if word(16) != GRID || word(20) != 0 {
        return Err(FileErrorKind::Grid(word(16).max(word(20))));
    }
    read_header(bytes).ok_or(FileErrorKind::Name)
}

/// The header's version, resolution, matrix and name, read without
/// checking the rest (for bytes [`parse`] has checked): `None` for fewer
/// than [`HEADER_LEN`] bytes or a name that is not UTF-8.
#[must_use]
pub fn read_header(bytes: &[u8]) -> Option<Header> {
    let head = bytes.first_chunk::<HEADER_LEN>()?;
    let (version, resolution) = (compact::word(head, 8), compact::word(head, 12));
    let f64_at = |at: usize| f64::from_le_bytes(std::array::from_fn(|i| head[at + i]));
    let matrix = std::array::from_fn(|r| std::array::from_fn(|c| f64_at(24 + 8 * (3 * r + c))));
    let name = &head[96..];
    let len = name.iter().position(|&b| b == 0).unwrap_or(32);
    let name = std::str::from_utf8(&name[..len]).ok()?.to_string();
    Some(Header { version, resolution, matrix, name })
}

/// Reads the table file at `path` and checks its structure
/// ([`parse_structure`]: for build scripts, which embed it): its header,
/// or a message naming the file.
pub fn check_file(path: &std::path::Path) -> Result<Header, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
    parse_structure(&bytes, &path.display().to_string()).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests;
