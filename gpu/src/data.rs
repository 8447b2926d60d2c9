//! The data a shader reads, bind group 0, and its upload.
//!
//! | binding | WGSL | holds | from |
//! |---|---|---|---|
//! | 0 | `speclab_observer: array<vec4<f32>>` | `[x̄, ȳ, z̄, 1]` at 360, 361, …, 830 nm (471 rows, 7,536 bytes) | `DenseObserver::rows::<f32>()` |
//! | 1 | `speclab_spectra: array<f32>` | dense spectra: spectrum `s` at `360 + i` nm at `s·471 + i` (1,884 bytes each) | `DenseSpectrum::values::<f32>()` of each spectrum given |
//! | 2 | `speclab_rgb_table: array<f32>` | one RGB table's coefficients, node `[case][z][y][x]` at `3·(((case·n + z)·n + y)·n + x)` (9,437,184 bytes at n = 64) | `RgbTable::coefficients()` (the compact table decoded once, on the CPU) |
//! | 3 | `speclab_rgb_nodes: array<f32>` | the table's `n` nodes of the largest component, then the `n − 1` reciprocals of their spacing | `rgb_table::node` |
//!
//! All little-endian `f32`, read-only storage buffers.
//!
//! ```no_run
//! use speclab::{color::RgbSpace, data::lights, spectrum::DenseObserver};
//! # fn main() -> Result<(), speclab_gpu::GpuError> {
//! let gpu = speclab_gpu::Gpu::new()?;
//! let space = RgbSpace::srgb();
//! // Spectrum 0: the space's illuminant (for its lights); 1: CIE A.
//! let data = speclab_gpu::Data::new(DenseObserver::CIE_1931, space, &[space.illuminant(), &lights::CIE_A]);
//! let uploaded = data.upload(&gpu.device)?; // buffers, bind group layout, bind group
//! # let _ = uploaded;
//! # Ok(())
//! # }
//! ```

use speclab::Spectrum;
use speclab::color::RgbSpace;
use speclab::color::rgb_table::node;
use speclab::spectrum::{DenseObserver, DenseSpectrum};
use wgpu::util::DeviceExt;

use crate::GpuError;

/// The four buffers' contents (see the module).
#[derive(Clone, Debug, PartialEq)]
pub struct Data {
    /// Binding 0: `[x̄, ȳ, z̄, 1]` per nanometre.
    pub observer: Vec<[f32; 4]>,
    /// Binding 1: the dense spectra, 471 values each.
    pub spectra: Vec<f32>,
    /// Binding 2: the RGB table's coefficients.
    pub rgb_table: Vec<f32>,
    /// Binding 3: the nodes, then the reciprocals of their spacing.
    pub rgb_nodes: Vec<f32>,
}

/// The buffers on the device, their layout and bind group (group 0).
#[derive(Debug)]
pub struct Uploaded {
    /// Bindings 0 to 3, in order.
    pub buffers: [wgpu::Buffer; 4],
    /// The layout of group 0.
    pub layout: wgpu::BindGroupLayout,
    /// Group 0, to set with `pass.set_bind_group(0, &uploaded.group, &[])`.
    pub group: wgpu::BindGroup,
}

impl Data {
    /// `observer`'s rows, `spectra` at every whole nanometre from 360 to
    /// 830 nm (spectrum `s` is index `s` in the shader), and `space`'s
    /// RGB table decoded.
    #[must_use]
    pub fn new(observer: DenseObserver, space: &RgbSpace, spectra: &[&dyn Spectrum]) -> Data {
        let table = space.table();
        let n = table.resolution();
        let nodes: Vec<f32> = (0..n).map(|k| node(k, n)).collect();
        let reciprocals = nodes.windows(2).map(|w| 1.0 / (w[1] - w[0]));
        Data {
            observer: observer.rows::<f32>().to_vec(),
            spectra: spectra.iter().flat_map(|s| *DenseSpectrum::new(*s).values::<f32>()).collect(),
            rgb_table: table.coefficients().into_iter().flatten().collect(),
            rgb_nodes: nodes.iter().copied().chain(reciprocals).collect(),
        }
    }

    /// The four buffers' bytes, in binding order (at least 4 bytes each:
    /// WebGPU binds no empty buffer).
    #[must_use]
    pub fn bytes(&self) -> [Vec<u8>; 4] {
        let observer: Vec<f32> = self.observer.iter().flatten().copied().collect();
        [&observer[..], &self.spectra, &self.rgb_table, &self.rgb_nodes].map(|v| {
            let mut b: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
            if b.is_empty() {
                b.extend([0; 4]);
            }
            b
        })
    }

    /// The buffers on `device`, with group 0's layout and bind group: a
    /// [`GpuError::Device`] for a buffer over the device's storage binding
    /// limit (a table of more than about 150 nodes per axis at the default
    /// 128 MiB) or memory running out.
    pub fn upload(&self, device: &wgpu::Device) -> Result<Uploaded, GpuError> {
        let limit = device.limits().max_storage_buffer_binding_size;
        let bytes = self.bytes();
        if let Some(b) = bytes.iter().find(|b| b.len() as u64 > limit) {
            return Err(GpuError::Device(format!(
                "a buffer of {} bytes, over the device's {limit}",
                b.len()
            )));
        }
        let scope = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let uploaded = self.create(device, &bytes);
        match pollster::block_on(scope.pop()) {
            Some(e) => Err(GpuError::Device(e.to_string())),
            None => Ok(uploaded),
        }
    }

    /// The buffers of `bytes`, the layout and the bind group.
    fn create(&self, device: &wgpu::Device, bytes: &[Vec<u8>; 4]) -> Uploaded {
        let labels = ["speclab_observer", "speclab_spectra", "speclab_rgb_table", "speclab_rgb_nodes"];
        let buffers = std::array::from_fn(|i| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(labels[i]),
                contents: &bytes[i],
                usage: wgpu::BufferUsages::STORAGE,
            })
        });
        let layout = group_layout(device, "speclab", &[true; 4]);
        let entries: Vec<wgpu::BindGroupEntry> = buffers
            .iter()
            .enumerate()
            .map(|(i, b)| wgpu::BindGroupEntry { binding: i as u32, resource: b.as_entire_binding() })
            .collect();
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("speclab"),
            layout: &layout,
            entries: &entries,
        });
        Uploaded { buffers, layout, group }
    }
}

/// A compute bind group layout of storage buffers, binding `i` read-only
/// where `read_only[i]` (at most the device's storage buffers per stage).
#[must_use]
pub(crate) fn group_layout(device: &wgpu::Device, label: &str, read_only: &[bool]) -> wgpu::BindGroupLayout {
    let entries: Vec<wgpu::BindGroupLayoutEntry> = read_only
        .iter()
        .enumerate()
        .map(|(i, &read_only)| wgpu::BindGroupLayoutEntry {
            binding: i as u32,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        })
        .collect();
    device
        .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some(label), entries: &entries })
}
