//! speclab on the GPU: the per-sample spectral arithmetic of a spectral
//! renderer in WGSL, its constants generated from speclab's own data, its
//! tables uploaded through `wgpu`, each function tested against the Rust
//! function it mirrors (`tests/`, on any Vulkan adapter: Mesa's lavapipe
//! in CI).
//!
//! What a WGSL renderer imports: [`source`]`(space)`, a module of
//! functions (`speclab_hero_uniform`, `speclab_hero_visible`,
//! `speclab_dense`, `speclab_rgb_albedo`, `speclab_rgb_unbounded`,
//! `speclab_rgb_light`, `speclab_rgb_eval`, `speclab_planck`,
//! `speclab_weights`, `speclab_xyz`, and matrices such as
//! `SPECLAB_XYZ_TO_SRGB`) to which it appends its own entry points; and
//! bind group 0, the observer, dense spectra and RGB table
//! ([`Data`], laid out in [`data`]). Units: nanometres, and the CPU
//! crate's (spectra as given; XYZ with `Y` of a constant 1 equal to
//! `SPECLAB_Y_INTEGRAL`, 106.857 over 360–830 nm). docs/gpu.md has the
//! differences from the CPU measured per function.
//!
//! ```no_run
//! use speclab::{color::RgbSpace, spectrum::DenseObserver};
//! # fn main() -> Result<(), speclab_gpu::GpuError> {
//! let gpu = speclab_gpu::Gpu::new()?; // a Vulkan adapter, or an error saying what to install
//! let space = RgbSpace::srgb();
//! let data = speclab_gpu::Data::new(DenseObserver::CIE_1931, space, &[space.illuminant()]).upload(&gpu.device)?;
//! let kernel = speclab_gpu::source(space) + "
//! @group(1) @binding(0) var<storage, read> input: array<f32>;
//! @group(1) @binding(1) var<storage, read_write> output: array<f32>;
//! @compute @workgroup_size(64)
//! fn main(@builtin(global_invocation_id) id: vec3<u32>) {
//!     if (id.x >= arrayLength(&output) / 3u) { return; }
//!     let h = speclab_hero_uniform(input[id.x], 0u, 470u);
//!     let red = speclab_rgb_albedo(vec3<f32>(0.8, 0.1, 0.05));
//!     let xyz = speclab_xyz(speclab_weights(h), speclab_rgb_eval(red, h.lambda) * speclab_dense(0u, h.nearest));
//!     output[3u * id.x] = xyz.x; output[3u * id.x + 1u] = xyz.y; output[3u * id.x + 2u] = xyz.z;
//! }";
//! let u: Vec<u32> = (0..1024).map(|i| ((i as f32 + 0.5) / 1024.0).to_bits()).collect();
//! let xyz = gpu.run(&kernel, &data, &u, 3 * 1024, 1024)?;
//! # let _ = xyz;
//! # Ok(())
//! # }
//! ```

pub mod data;
pub mod device;
pub mod shader;

pub use data::{Data, Uploaded};
pub use device::{Gpu, GpuError};
pub use shader::{DENSE_COUNT, FUNCTIONS, source};
