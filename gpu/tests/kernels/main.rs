//! Each WGSL function against the Rust function it mirrors, in `f32`, on
//! at least 10,000 inputs with the edges, on the first Vulkan adapter
//! (lavapipe in CI). Each test prints its largest difference in ULP.

mod colour;
mod common;
mod errors;
mod hero;
mod spectra;
