//! What the fuzz target `spectral_exr` runs on arbitrary bytes (and the
//! tests replay on the hand-made files and damaged copies of them): read
//! them as a spectral OpenEXR image and, if that succeeds, develop it.
//! The only failure is a panic.

use std::io::Cursor;

use speclab::film::{Develop, Kind, Sensor};
use speclab::spectrum::{Constant, StandardObserver};

/// Reads `data` (at most 2²⁴ values: the fuzzer's memory is 2 GB); a
/// success is developed by the CIE 1931 observer (under a
/// constant light if reflective), and its pixels looked at.
pub fn spectral_exr(data: &[u8]) {
    let Ok(file) = speclab_exr::read_limited(Cursor::new(data), 1 << 24) else { return };
    let light = Constant::new(1.0);
    let develop = Develop::new(Sensor::observer(StandardObserver::Cie1931));
    let develop = if file.image.kind() == Kind::Reflective { develop.light(&light) } else { develop };
    let xyz = develop.xyz(&file.image).expect("a read image of its kind develops");
    let (width, height) = file.image.size();
    assert_eq!(xyz.len(), width * height);
    assert!(file.image.pixel(width, 0).is_none());
}
