//! What a caller can get wrong comes back as an error, not a panic.

use speclab::color::RgbSpace;

use crate::common::setup;

#[test]
fn a_broken_kernel_or_a_dispatch_past_the_limits_is_an_error() {
    let s = setup();
    let broken = speclab_gpu::source(RgbSpace::srgb())
        + "@compute @workgroup_size(64) fn main() { let x: u32 = 1.5; }";
    let e = s.gpu.run(&broken, &s.data, &[], 1, 1).expect_err("a type error");
    assert!(e.to_string().contains("refused"), "{e}");
    let kernel = speclab_gpu::source(RgbSpace::srgb())
        + "@group(1) @binding(0) var<storage, read> input: array<u32>;
@group(1) @binding(1) var<storage, read_write> output: array<u32>;
@compute @workgroup_size(64) fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if (id.x < arrayLength(&output)) { output[id.x] = input[0] + id.x; }
}";
    let e = s.gpu.run(&kernel, &s.data, &[7], 1, u32::MAX).expect_err("too many workgroups");
    assert!(e.to_string().contains("workgroups"), "{e}");
    let e = s.gpu.run(&kernel, &s.data, &[7], usize::MAX / 2, 1).expect_err("too large an output");
    assert!(e.to_string().contains("exceed"), "{e}");
    // And the same kernel, within the limits, runs: at the most workgroups
    // a dimension takes too, one invocation more is refused.
    assert_eq!(s.gpu.run(&kernel, &s.data, &[7], 3, 3).expect("it runs"), [7, 8, 9]);
    let most = s.gpu.device.limits().max_compute_workgroups_per_dimension * 64;
    assert_eq!(s.gpu.run(&kernel, &s.data, &[7], 3, most).expect("the most workgroups"), [7, 8, 9]);
    assert!(s.gpu.run(&kernel, &s.data, &[7], 3, most + 1).is_err());
}

/// A buffer of exactly the device's storage binding limit uploads; one
/// word more is an error.
#[test]
fn data_at_the_binding_limit_uploads_and_past_it_is_an_error() {
    let s = setup();
    let limit = s.gpu.device.limits().max_storage_buffer_binding_size as usize;
    let data = |floats: usize| speclab_gpu::Data {
        observer: vec![[0.0; 4]; 471],
        spectra: vec![0.0; floats],
        rgb_table: vec![0.0; 3],
        rgb_nodes: vec![0.0, 1.0, 1.0],
    };
    assert!(data(limit / 4).upload(&s.gpu.device).is_ok());
    let e = data(limit / 4 + 1).upload(&s.gpu.device).expect_err("past the limit");
    assert!(e.to_string().contains("over the device's"), "{e}");
}
