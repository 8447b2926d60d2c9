//! naga (the WGSL front end wgpu uses) parses and validates the module
//! for every built-in space, with a renderer's entry point appended: no
//! device needed.

use speclab::color::RgbSpace;

#[test]
fn the_module_validates_for_every_space() {
    let entry = "
@group(1) @binding(0) var<storage, read_write> out: array<f32>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let h = speclab_hero_visible(f32(id.x) / 64.0);
    let u = speclab_hero_uniform(0.5, 0u, 470u);
    let s = speclab_rgb_light(vec3<f32>(2.0, 1.0, 0.5));
    let v = speclab_rgb_light_eval(s, h, 0u) + speclab_rgb_eval(speclab_rgb_albedo(vec3<f32>(0.2)), u.lambda)
        + speclab_dense(1u, h.nearest) + speclab_planck(h.lambda, 5000.0) * speclab_visible_pdf(500.0);
    let rgb = SPECLAB_XYZ_TO_SRGB * speclab_xyz(speclab_weights(h), v) / SPECLAB_Y_INTEGRAL;
    out[id.x] = rgb.x + speclab_rgb_unbounded(rgb).scale;
}";
    for space in RgbSpace::all() {
        let source = speclab_gpu::source(space) + entry;
        let module = naga::front::wgsl::parse_str(&source)
            .unwrap_or_else(|e| panic!("{}: {}", space.name(), e.emit_to_string(&source)));
        let mut validator = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        );
        if let Err(e) = validator.validate(&module) {
            panic!("{}: {}", space.name(), e.emit_to_string(&source));
        }
    }
}

#[test]
fn a_broken_module_is_refused() {
    let source = speclab_gpu::source(RgbSpace::srgb()) + "fn broken() -> f32 { return speclab_sigmoid(1u); }";
    let module = naga::front::wgsl::parse_str(&source).expect("it parses");
    let mut validator = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    );
    assert!(validator.validate(&module).is_err(), "a u32 passed for an f32 must not validate");
}
