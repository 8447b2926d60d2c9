//! Bits, most significant first: a writer for the encoder and a `const`
//! reader for the decoder, which reads zeros past the end and says so.
//!
//! ```
//! use speclab_tables::rgb_file::bits::{BitReader, BitWriter};
//! let mut w = BitWriter::default();
//! w.put(0b101, 3);
//! w.put(0x3ff, 10);
//! let bytes = w.finish();
//! let mut r = BitReader::new(&bytes, 0, bytes.len());
//! assert_eq!((r.bits(3), r.bits(10)), (0b101, 0x3ff));
//! assert!(!r.overrun);
//! ```

/// Writes bits, most significant first, into bytes.
#[derive(Clone, Debug, Default)]
pub struct BitWriter {
    bytes: Vec<u8>,
    /// Bits used of the last byte (0 to 7; 0 when it is full or absent).
    used: u32,
}

impl BitWriter {
    /// Appends the low `count` bits of `value` (at most 64).
    pub fn put(&mut self, value: u64, count: u32) {
        for i in (0..count).rev() {
            let bit = ((value >> i) & 1) as u8;
            if self.used == 0 {
                self.bytes.push(0);
            }
            let last = self.bytes.len() - 1;
            self.bytes[last] |= bit << (7 - self.used);
            self.used = (self.used + 1) % 8;
        }
    }

    /// Pads the last byte with zeros: what follows starts on a byte.
    pub fn align(&mut self) {
        self.used = 0;
    }

    /// Bytes written so far (the last one perhaps partly).
    #[must_use]
    pub fn len(&self) -> usize {
        self.bytes.len()
    }

    /// Whether nothing is written.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.bytes.is_empty()
    }

    /// The bytes, the last one padded with zeros.
    #[must_use]
    pub fn finish(self) -> Vec<u8> {
        self.bytes
    }
}

/// Reads bits, most significant first, from `bytes[start..end]` through a
/// 64-bit buffer; past the end it reads zeros and sets `overrun`.
#[derive(Clone, Copy, Debug)]
pub struct BitReader<'a> {
    bytes: &'a [u8],
    /// The next byte to load.
    next: usize,
    /// The first byte past the readable ones.
    end: usize,
    /// Loaded bits, the next one highest.
    buffer: u64,
    /// How many bits of `buffer` are loaded.
    loaded: u32,
    /// Readable bits not yet read.
    left: usize,
    /// Whether a read went past the end.
    pub overrun: bool,
}

impl<'a> BitReader<'a> {
    /// A reader of `bytes[start..end]` (clamped to the slice).
    #[must_use]
    pub const fn new(bytes: &'a [u8], start: usize, end: usize) -> BitReader<'a> {
        let end = if end < bytes.len() { end } else { bytes.len() };
        let left = 8 * end.saturating_sub(start);
        BitReader { bytes, next: start, end, buffer: 0, loaded: 0, left, overrun: false }
    }

    /// The next `count` bits (at most 56) without reading them.
    #[inline(always)]
    pub const fn peek(&mut self, count: u32) -> u64 {
        while self.loaded <= 56 {
            let byte = if self.next < self.end { self.bytes[self.next] } else { 0 };
            self.buffer |= (byte as u64) << (56 - self.loaded);
            self.next += 1;
            self.loaded += 8;
        }
        if count == 0 { 0 } else { self.buffer >> (64 - count) }
    }

    /// Reads `count` bits (at most 56) that were peeked.
    #[inline(always)]
    pub const fn skip(&mut self, count: u32) {
        self.buffer = if count >= 64 { 0 } else { self.buffer << count };
        self.loaded -= count;
        if count as usize > self.left {
            self.overrun = true;
            self.left = 0;
        } else {
            self.left -= count as usize;
        }
    }

    /// The next bit.
    #[inline(always)]
    pub const fn bit(&mut self) -> u32 {
        self.bits(1) as u32
    }

    /// The next `count` bits (at most 56) as a number.
    #[inline(always)]
    pub const fn bits(&mut self, count: u32) -> u64 {
        let v = self.peek(count);
        self.skip(count);
        v
    }

    /// Bits left before the end.
    #[must_use]
    pub const fn remaining(&self) -> usize {
        self.left
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_come_back_in_order_and_zeros_past_the_end() {
        let mut w = BitWriter::default();
        assert!(w.is_empty());
        for (v, n) in [(1, 1), (0, 2), (0xabcd, 16), (u64::MAX, 56), (0xff, 8), (5, 3)] {
            w.put(v, n);
        }
        w.align();
        w.put(1, 1);
        assert_eq!(w.len(), 12);
        let bytes = w.finish();
        let mut r = BitReader::new(&bytes, 0, bytes.len());
        let read: Vec<u64> = [1, 2, 16, 56, 8, 3].iter().map(|&n| r.bits(n)).collect();
        assert_eq!(read, [1, 0, 0xabcd, (1 << 56) - 1, 0xff, 5]);
        assert_eq!(r.remaining(), 10, "the padding of the eleventh byte and the twelfth");
        assert_eq!(r.bits(2), 0);
        assert_eq!(BitReader::new(&bytes, 11, 12).bit(), 1);
        let mut short = BitReader::new(&bytes, 11, 99);
        assert_eq!(short.bits(9), 0x100);
        assert!(short.overrun);
    }

    /// A writer with bits in it is not empty, and `bit` reads zeros as
    /// well as ones.
    #[test]
    fn single_bits_and_emptiness() {
        let mut w = BitWriter::default();
        w.put(0b0110, 4);
        assert!(!w.is_empty());
        let bytes = w.finish();
        let mut r = BitReader::new(&bytes, 0, bytes.len());
        assert_eq!([r.bit(), r.bit(), r.bit(), r.bit()], [0, 1, 1, 0]);
    }
}
