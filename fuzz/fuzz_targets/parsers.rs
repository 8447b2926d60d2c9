//! Every run-time parser on arbitrary bytes: brace notation, two-column
//! text, JSON, the format-detecting loader for each role, and evaluation of
//! whatever loads (`tests/api/fuzz_body.rs`, which the API tests replay). The only failure is a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "../../tests/api/fuzz_body.rs"]
mod body;

fuzz_target!(|data: &[u8]| body::parsers(data));
