//! Canonical Huffman codes, at most [`MAX_LEN`] bits: built from symbol
//! counts by the encoder, stored as the number of codes of each length and
//! the symbols in code order, and decoded one bit at a time by a `const fn`
//! (Mark Adler's `puff` way: no table to build, the same at compile time
//! and at run time).
//!
//! ```
//! use speclab_tables::rgb_file::{bits::{BitReader, BitWriter}, huffman::Code};
//! let code = Code::from_counts(&[50, 20, 20, 9, 1]);
//! let mut w = BitWriter::default();
//! for s in [0, 4, 2, 0] { code.write(&mut w, s); }
//! let bytes = w.finish();
//! let stored = code.to_bytes();
//! let mut r = BitReader::new(&bytes, 0, bytes.len());
//! let read: Vec<_> = (0..4).map(|_| speclab_tables::rgb_file::huffman::decode(&mut r, &stored, 0)).collect();
//! assert_eq!(read, [Some(0), Some(4), Some(2), Some(0)]);
//! ```

use crate::rgb_file::bits::{BitReader, BitWriter};

/// The longest code.
pub const MAX_LEN: usize = 15;

/// A canonical code: each symbol's length (0 for a symbol never used).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Code {
    lengths: Vec<u8>,
    /// Each symbol's code, canonically: by length, then by value.
    codes: Vec<u32>,
}

impl Code {
    /// The optimal code of at most [`MAX_LEN`] bits for symbols seen
    /// `counts[s]` times (Huffman's, with the counts halved until it fits).
    /// A lone symbol gets one bit.
    #[must_use]
    pub fn from_counts(counts: &[u64]) -> Code {
        let mut counts = counts.to_vec();
        loop {
            let lengths = huffman_lengths(&counts);
            if lengths.iter().all(|&l| usize::from(l) <= MAX_LEN) {
                return Code::canonical(lengths);
            }
            // Rounded up: a used symbol stays used, an unused one unused.
            for c in &mut counts {
                *c = c.div_ceil(2);
            }
        }
    }

    /// Each symbol's length.
    #[must_use]
    pub fn lengths(&self) -> &[u8] {
        &self.lengths
    }

    /// How many codes of each length, 1 to [`MAX_LEN`].
    fn counts(&self) -> [u8; MAX_LEN + 1] {
        let mut n = [0u8; MAX_LEN + 1];
        for &l in &self.lengths {
            n[usize::from(l)] += 1;
        }
        n[0] = 0;
        n
    }

    /// The stored form: [`MAX_LEN`] counts (lengths 1, 2, …), then the
    /// used symbols by length, then by value, one byte each.
    #[must_use]
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = self.counts()[1..].to_vec();
        for len in 1..=MAX_LEN as u8 {
            out.extend((0..self.lengths.len()).filter(|&s| self.lengths[s] == len).map(|s| s as u8));
        }
        out
    }

    /// Writes symbol `s`'s code (nothing for a symbol without one).
    pub fn write(&self, out: &mut BitWriter, s: usize) {
        out.put(u64::from(self.codes[s]), u32::from(self.lengths[s]));
    }

    /// The canonical codes of these lengths: each length's first code
    /// follows the last of the length before, shifted; within a length,
    /// codes rise with the symbol.
    fn canonical(lengths: Vec<u8>) -> Code {
        let mut next = [0u32; MAX_LEN + 1];
        let mut count = [0u32; MAX_LEN + 1];
        for &l in &lengths {
            count[usize::from(l)] += 1;
        }
        count[0] = 0;
        // The first code of each length from 2 on (length 1's is 0).
        for l in 1..MAX_LEN {
            next[l + 1] = (next[l] + count[l]) << 1;
        }
        let codes = lengths
            .iter()
            .map(|&l| {
                let l = usize::from(l);
                next[l] += 1;
                next[l] - 1
            })
            .collect();
        Code { lengths, codes }
    }
}

/// Huffman's lengths for `counts` (0 for unused symbols; 1 for a lone one).
fn huffman_lengths(counts: &[u64]) -> Vec<u8> {
    let mut lengths = vec![0u8; counts.len()];
    // Each tree: its weight and its symbols.
    let mut trees: Vec<(u64, Vec<usize>)> =
        (0..counts.len()).filter(|&s| counts[s] > 0).map(|s| (counts[s], vec![s])).collect();
    if trees.len() == 1 {
        lengths[trees[0].1[0]] = 1;
    }
    while trees.len() > 1 {
        trees.sort_by(|a, b| b.0.cmp(&a.0).then(b.1[0].cmp(&a.1[0])));
        let (wa, a) = trees.pop().unwrap_or_default();
        let (wb, b) = trees.pop().unwrap_or_default();
        for &s in a.iter().chain(&b) {
            lengths[s] = lengths[s].saturating_add(1);
        }
        trees.push((wa + wb, [a, b].concat()));
    }
    lengths
}

/// The length in bytes of the stored code at `at` in `bytes` (its counts
/// and symbols), or `None` if they do not fit in `bytes`.
#[must_use]
pub const fn stored_len(bytes: &[u8], at: usize) -> Option<usize> {
    if at + MAX_LEN > bytes.len() {
        return None;
    }
    let mut used = 0;
    let mut l = 0;
    while l < MAX_LEN {
        used += bytes[at + l] as usize;
        l += 1;
    }
    if at + MAX_LEN + used > bytes.len() { None } else { Some(MAX_LEN + used) }
}

/// Whether the stored code at `at` is a prefix code over an alphabet of
/// `alphabet` symbols: no length over-subscribed, every symbol in the
/// alphabet (its length checked by [`stored_len`] first).
#[must_use]
pub fn stored_is_valid(bytes: &[u8], at: usize, alphabet: usize) -> bool {
    let mut left: i64 = 1;
    let mut used = 0;
    for l in 0..MAX_LEN {
        left = 2 * left - i64::from(bytes[at + l]);
        used += usize::from(bytes[at + l]);
        if left < 0 {
            return false;
        }
    }
    bytes[at + MAX_LEN..at + MAX_LEN + used].iter().all(|&s| usize::from(s) < alphabet)
}

/// The next symbol, by the stored code at `at` in `bytes`: `None` for bits
/// that are no code of it (an incomplete code). The next [`MAX_LEN`] bits
/// are peeked at once and compared with each length's first code.
#[inline(always)]
#[must_use]
pub const fn decode(reader: &mut BitReader, bytes: &[u8], at: usize) -> Option<usize> {
    if at + MAX_LEN > bytes.len() {
        return None;
    }
    let peeked = reader.peek(MAX_LEN as u32) as i32;
    let (mut first, mut index) = (0i32, 0usize);
    let mut len = 1;
    while len <= MAX_LEN {
        let code = peeked >> (MAX_LEN - len);
        let count = bytes[at + len - 1] as i32;
        if code - first < count {
            reader.skip(len as u32);
            let symbol = at + MAX_LEN + index + (code - first) as usize;
            return if symbol < bytes.len() { Some(bytes[symbol] as usize) } else { None };
        }
        index += count as usize;
        first = (first + count) << 1;
        len += 1;
    }
    None
}

/// Bits a [`Lut`] looks up at once.
pub const LUT_BITS: u32 = 10;

/// A stored code as a table for decoding at run time: for each next
/// [`LUT_BITS`] bits, the symbol and its length when the code is that
/// short; longer codes go bit by bit ([`decode`]). The same symbols as
/// [`decode`], about three times faster.
#[derive(Clone, Debug)]
pub struct Lut {
    /// `symbol << 4 | length`, length 0 for a longer code.
    entries: Box<[u16]>,
}

impl Lut {
    /// The table of the stored code at `at` in `bytes` (checked).
    #[must_use]
    pub fn new(bytes: &[u8], at: usize) -> Lut {
        let mut entries = vec![0u16; 1 << LUT_BITS].into_boxed_slice();
        let (mut first, mut index) = (0usize, 0usize);
        for len in 1..=LUT_BITS as usize {
            let count = usize::from(bytes.get(at + len - 1).copied().unwrap_or(0));
            for rank in 0..count {
                let symbol = u16::from(bytes.get(at + MAX_LEN + index + rank).copied().unwrap_or(0));
                let spread = LUT_BITS as usize - len;
                let start = ((first + rank) << spread).min(entries.len());
                let end = ((first + rank + 1) << spread).min(entries.len());
                entries[start..end].fill(symbol << 4 | len as u16);
            }
            index += count;
            first = (first + count) << 1;
        }
        Lut { entries }
    }

    /// The next symbol ([`decode`]'s), the stored code at `at` in `bytes`
    /// being this table's.
    #[inline(always)]
    pub fn decode(&self, reader: &mut BitReader, bytes: &[u8], at: usize) -> Option<usize> {
        let entry = self.entries[reader.peek(LUT_BITS) as usize];
        if entry & 15 == 0 {
            return decode(reader, bytes, at);
        }
        reader.skip(u32::from(entry & 15));
        Some(usize::from(entry >> 4))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Codes from skewed and flat counts round trip through bits, never
    /// exceed the longest length, and satisfy Kraft's inequality.
    #[test]
    fn codes_round_trip_and_stay_short() {
        let skewed: Vec<u64> =
            (0..162).map(|i| if i % 7 == 3 { 0 } else { 1u64 << (40 - i / 4).max(0) }).collect();
        for counts in [skewed, vec![1; 40], vec![0, 0, 9, 0], vec![3, 1]] {
            let code = Code::from_counts(&counts);
            assert!(code.lengths().iter().all(|&l| usize::from(l) <= MAX_LEN));
            // A code for each used symbol, none for the others.
            assert_eq!(code.lengths().len(), counts.len());
            assert!(counts.iter().zip(code.lengths()).all(|(&c, &l)| (c > 0) == (l > 0)), "{code:?}");
            let used: Vec<usize> = (0..counts.len()).filter(|&s| counts[s] > 0).collect();
            // Huffman's codes are complete: Kraft's sum is 1 (½ for a lone symbol).
            let kraft: f64 =
                code.lengths().iter().filter(|&&l| l > 0).map(|&l| 0.5f64.powi(i32::from(l))).sum();
            assert_eq!(kraft, if used.len() == 1 { 0.5 } else { 1.0 }, "{code:?}");
            let stored = code.to_bytes();
            assert_eq!(stored_len(&stored, 0), Some(stored.len()));
            assert!(stored_is_valid(&stored, 0, counts.len()));
            let mut w = BitWriter::default();
            for &s in used.iter().chain(used.iter().rev()) {
                code.write(&mut w, s);
            }
            let bytes = w.finish();
            let mut r = BitReader::new(&bytes, 0, bytes.len());
            for &s in used.iter().chain(used.iter().rev()) {
                assert_eq!(decode(&mut r, &stored, 0), Some(s));
            }
            assert!(!r.overrun);
            let lut = Lut::new(&stored, 0);
            let mut r = BitReader::new(&bytes, 0, bytes.len());
            for &s in used.iter().chain(used.iter().rev()) {
                assert_eq!(lut.decode(&mut r, &stored, 0), Some(s));
            }
        }
    }

    /// A stored code that lies about its symbols is refused; bits outside
    /// an incomplete code decode to `None`.
    #[test]
    fn bad_codes_are_refused() {
        let mut over = vec![0u8; MAX_LEN];
        over[0] = 3; // three codes of one bit
        over.extend([0, 1, 2]);
        assert!(!stored_is_valid(&over, 0, 3));
        let code = Code::from_counts(&[5, 0, 0, 0]).to_bytes();
        assert!(stored_is_valid(&code, 0, 4) && !stored_is_valid(&code, 0, 0));
        assert_eq!(stored_len(&code, 0), Some(MAX_LEN + 1));
        assert_eq!(stored_len(&code[..MAX_LEN], 0), None);
        let ones = [0xffu8; 4];
        let mut r = BitReader::new(&ones, 0, 4);
        assert_eq!(decode(&mut r, &code, 0), None, "the lone symbol's code is 0");
    }

    /// Counts in powers of two get lengths of `log2(total / count)`.
    #[test]
    fn dyadic_counts_get_their_entropy_lengths() {
        assert_eq!(Code::from_counts(&[8, 4, 2, 1, 1]).lengths(), [1, 2, 3, 4, 4]);
        assert_eq!(Code::from_counts(&[0, 2, 0, 1, 1]).lengths(), [0, 1, 0, 2, 2]);
    }

    /// A code of no symbols (an unused context) is its counts alone, even
    /// as the last bytes; a stored code cut short, in its counts or in
    /// its symbols, decodes to `None` rather than reading past the bytes.
    #[test]
    fn empty_and_cut_codes() {
        let empty = Code::from_counts(&[0; 4]).to_bytes();
        assert_eq!(empty, [0; MAX_LEN]);
        assert_eq!(stored_len(&empty, 0), Some(MAX_LEN));
        let zeros = [0u8; 4];
        let lone = Code::from_counts(&[0, 0, 7]).to_bytes();
        assert_eq!(decode(&mut BitReader::new(&zeros, 0, 4), &lone, 0), Some(2));
        for cut in [&lone[..MAX_LEN], &lone[..5], &lone[..0]] {
            assert_eq!(decode(&mut BitReader::new(&zeros, 0, 4), cut, 0), None, "{} bytes", cut.len());
        }
    }
}
