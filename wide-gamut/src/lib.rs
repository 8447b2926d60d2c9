//! # speclab-wide-gamut: the tables of speclab's wide-gamut RGB spaces
//!
//! Data only (static arrays, so that each table is in the program once,
//! and only in a program that turns that space's colours into spectra):
//! the RGB-to-spectrum tables (Jakob and Hanika's sigmoid polynomials at
//! 3 × 64³ colours) of four of [speclab](https://docs.rs/speclab)'s
//! built-in spaces, each a compact table file (version 2 of
//! `speclab_tables::rgb_file`: every node rounded to what its spectrum
//! needs, predicted from its neighbours and Huffman-coded; 1.6–2.6 MB),
//! fitted by speclab's `rgb-tables` program and checked by this crate's
//! build script. speclab reads them through its default feature
//! `wide-gamut` (without it, those spaces fit their tables on first use);
//! sRGB's lives in speclab itself.
//!
//! ```
//! assert_eq!(&speclab_wide_gamut::ACESCG[..8], b"SPCLBRGB");
//! assert_eq!(speclab_wide_gamut::ACESCG[8], 2); // version 2: compact
//! let total: usize = [&speclab_wide_gamut::DISPLAY_P3[..], &speclab_wide_gamut::REC2020,
//!     &speclab_wide_gamut::ACES2065_1, &speclab_wide_gamut::ACESCG].iter().map(|t| t.len()).sum();
//! assert!(total < 9_000_000);
//! ```

#![no_std]

/// Display P3's table file.
pub static DISPLAY_P3: [u8; include_bytes!("../data/display-p3.rgbt").len()] =
    *include_bytes!("../data/display-p3.rgbt");
/// Rec.2020's table file.
pub static REC2020: [u8; include_bytes!("../data/rec2020.rgbt").len()] =
    *include_bytes!("../data/rec2020.rgbt");
/// ACES2065-1's table file.
pub static ACES2065_1: [u8; include_bytes!("../data/aces2065-1.rgbt").len()] =
    *include_bytes!("../data/aces2065-1.rgbt");
/// ACEScg's table file.
pub static ACESCG: [u8; include_bytes!("../data/acescg.rgbt").len()] = *include_bytes!("../data/acescg.rgbt");
