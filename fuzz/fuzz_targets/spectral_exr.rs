//! The spectral OpenEXR reader on arbitrary bytes, and developing what it
//! reads (`exr/tests/support/fuzz_body.rs`, which the reader's tests replay on
//! the hand-made files and damaged copies). The only failure is a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "../../exr/tests/support/fuzz_body.rs"]
mod body;

fuzz_target!(|data: &[u8]| body::spectral_exr(data));
