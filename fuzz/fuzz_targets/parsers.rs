//! Every run-time parser on arbitrary bytes: brace notation, two-column
//! text, JSON, the format-detecting loader for each role, and evaluation of
//! whatever loads (`speclab::fuzzing::parsers`). The only failure is a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| speclab::fuzzing::parsers(data));
