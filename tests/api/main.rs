//! The core's public API as its users write it: a renderer's per-sample
//! loop (no allocation on it), the types' sizes and traits, names in any
//! case, errors that name the place, a downstream build script, and the
//! fuzz target's saved inputs.

mod alloc;
mod build_data;
mod clients;
mod doc_pages;
mod domain;
mod fuzz_body;
mod fuzz_regressions;
mod imports;
mod input_errors;
mod materials;
mod names;
mod renderer_api;
mod types;
