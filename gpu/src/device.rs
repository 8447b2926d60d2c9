//! A device to run speclab's WGSL on, and one compute kernel run over
//! arrays of numbers: what the tests and the examples use.
//!
//! [`Gpu::new`] takes the first Vulkan adapter (a GPU's driver, or Mesa's
//! lavapipe on the CPU); without one it is an error that says what to
//! install, never a silent skip.

use std::fmt;

use crate::data::{Uploaded, group_layout};

/// What went wrong on the way to a result.
#[derive(Debug)]
pub enum GpuError {
    /// No Vulkan adapter: the message says what to install.
    NoAdapter(String),
    /// The device refused, or a shader failed to compile or validate.
    Device(String),
    /// Reading the results back failed.
    ReadBack(String),
}

impl fmt::Display for GpuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GpuError::NoAdapter(why) => write!(
                f,
                "no Vulkan adapter ({why}): install a GPU's Vulkan driver, or Mesa's lavapipe \
                 on the CPU (Debian and Ubuntu: `apt-get install mesa-vulkan-drivers`)"
            ),
            GpuError::Device(why) => write!(f, "the GPU device refused: {why}"),
            GpuError::ReadBack(why) => write!(f, "reading results back from the GPU failed: {why}"),
        }
    }
}

impl std::error::Error for GpuError {}

/// A device and its queue.
#[derive(Debug)]
pub struct Gpu {
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// Which adapter: name, driver, device type.
    pub adapter: wgpu::AdapterInfo,
}

impl Gpu {
    /// The first Vulkan adapter's device (a real GPU before a CPU one).
    pub fn new() -> Result<Gpu, GpuError> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            flags: wgpu::InstanceFlags::empty(),
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let options = wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        };
        let adapter = pollster::block_on(instance.request_adapter(&options))
            .map_err(|e| GpuError::NoAdapter(e.to_string()))?;
        let descriptor = wgpu::DeviceDescriptor { label: Some("speclab-gpu"), ..Default::default() };
        let (device, queue) = pollster::block_on(adapter.request_device(&descriptor))
            .map_err(|e| GpuError::Device(e.to_string()))?;
        Ok(Gpu { device, queue, adapter: adapter.get_info() })
    }

    /// Runs the entry point `main` of `wgsl` (which declares
    /// `@group(1) @binding(0) var<storage, read> input: array<u32>` and
    /// `@group(1) @binding(1) var<storage, read_write> output: array<u32>`,
    /// or the same arrays of `f32`) on `invocations` invocations in
    /// workgroups of 64, with `data` as group 0, and returns `output`'s
    /// `output_words` words. A shader error, a dispatch or buffer beyond the
    /// device's limits, or memory running out is an `Err`, not a panic.
    pub fn run(
        &self,
        wgsl: &str,
        data: &Uploaded,
        input: &[u32],
        output_words: usize,
        invocations: u32,
    ) -> Result<Vec<u32>, GpuError> {
        let limits = self.device.limits();
        let groups = invocations.div_ceil(64);
        if groups > limits.max_compute_workgroups_per_dimension {
            return Err(GpuError::Device(format!(
                "{invocations} invocations need {groups} workgroups of 64, over the device's {}",
                limits.max_compute_workgroups_per_dimension
            )));
        }
        let bytes = |words: usize| {
            (words.max(1) as u64)
                .checked_mul(4)
                .filter(|&b| b <= limits.max_storage_buffer_binding_size)
                .ok_or_else(|| GpuError::Device(format!("{words} words exceed a storage buffer binding")))
        };
        let (input_size, size) = (bytes(input.len())?, bytes(output_words)?);
        let device = &self.device;
        // Every error of the call is caught here, not by wgpu's handler (which panics).
        let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let staging = self.submit(wgsl, data, input, (input_size, size), groups);
        let errors = [memory, validation].map(|scope| pollster::block_on(scope.pop()));
        if let Some(e) = errors.into_iter().flatten().next() {
            return Err(GpuError::Device(e.to_string()));
        }
        self.read_back(&staging, output_words)
    }

    /// Builds the kernel and its buffers, dispatches `groups` workgroups
    /// and copies the output to a mappable buffer, returned.
    fn submit(
        &self,
        wgsl: &str,
        data: &Uploaded,
        input: &[u32],
        sizes: (u64, u64),
        groups: u32,
    ) -> wgpu::Buffer {
        let device = &self.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("speclab kernel"),
            source: wgpu::ShaderSource::Wgsl(wgsl.into()),
        });
        let io = group_layout(device, "io", &[true, false]);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("speclab kernel"),
            bind_group_layouts: &[Some(&data.layout), Some(&io)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("speclab kernel"),
            layout: Some(&layout),
            module: &module,
            entry_point: Some("main"),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        });
        let mut words: Vec<u8> = input.iter().flat_map(|x| x.to_le_bytes()).collect();
        words.resize(sizes.0 as usize, 0);
        let input = storage(device, &words, false);
        let output = storage(device, &vec![0; sizes.1 as usize], true);
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("io"),
            layout: &io,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: input.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: output.as_entire_binding() },
            ],
        });
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("read back"),
            size: sizes.1,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &data.group, &[]);
            pass.set_bind_group(1, &group, &[]);
            pass.dispatch_workgroups(groups, 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output, 0, &staging, 0, sizes.1);
        self.queue.submit([encoder.finish()]);
        staging
    }

    /// `words` words of the mappable buffer `staging`, once the queue is done.
    fn read_back(&self, staging: &wgpu::Buffer, words: usize) -> Result<Vec<u32>, GpuError> {
        let slice = staging.slice(..);
        let (send, receive) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = send.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::ReadBack(e.to_string()))?;
        receive
            .recv()
            .map_err(|e| GpuError::ReadBack(e.to_string()))?
            .map_err(|e| GpuError::ReadBack(e.to_string()))?;
        let view = slice.get_mapped_range().map_err(|e| GpuError::ReadBack(e.to_string()))?;
        let out =
            view.chunks_exact(4).take(words).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
        drop(view);
        staging.unmap();
        Ok(out)
    }
}

/// A storage buffer holding `bytes` (read-write and copyable where `writable`).
fn storage(device: &wgpu::Device, bytes: &[u8], writable: bool) -> wgpu::Buffer {
    use wgpu::util::DeviceExt;
    let usage = if writable {
        wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC
    } else {
        wgpu::BufferUsages::STORAGE
    };
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: None, contents: bytes, usage })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_adapter_says_what_to_install() {
        let message = GpuError::NoAdapter("none found".into()).to_string();
        assert!(message.contains("apt-get install mesa-vulkan-drivers"), "{message}");
        assert!(message.contains("none found"), "{message}");
        assert!(GpuError::Device("x".into()).to_string().contains("refused: x"));
        assert!(GpuError::ReadBack("y".into()).to_string().contains("failed: y"));
    }
}
