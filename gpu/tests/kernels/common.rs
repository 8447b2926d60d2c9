//! The harness: one device and sRGB's data for every test, a kernel that
//! maps `IN` input words to `OUT` output words per item, and ULP
//! distances.

use std::sync::OnceLock;

use speclab::color::RgbSpace;
use speclab::data::{lights, patches};
use speclab::spectrum::DenseObserver;
use speclab_gpu::{Data, Gpu, Uploaded};

/// The device and group 0: the CIE 1931 observer; spectra 0: sRGB's
/// illuminant (D65), 1: CIE A, 2: ColorChecker G4; sRGB's table.
pub struct Setup {
    pub gpu: Gpu,
    pub data: Uploaded,
}

/// The shared setup; a test without a Vulkan adapter fails with the
/// message saying what to install.
pub fn setup() -> &'static Setup {
    static SETUP: OnceLock<Setup> = OnceLock::new();
    SETUP.get_or_init(|| {
        let gpu = Gpu::new().unwrap_or_else(|e| panic!("speclab-gpu's tests need a Vulkan adapter: {e}"));
        eprintln!("adapter: {} ({:?}, {})", gpu.adapter.name, gpu.adapter.device_type, gpu.adapter.driver);
        let space = RgbSpace::srgb();
        let spectra: [&dyn speclab::Spectrum; 3] = [space.illuminant(), &lights::CIE_A, &patches::G4];
        let data = Data::new(DenseObserver::CIE_1931, space, &spectra)
            .upload(&gpu.device)
            .unwrap_or_else(|e| panic!("{e}"));
        Setup { gpu, data }
    })
}

/// Runs `body` (WGSL, with `item` the item and `input`/`output` arrays of
/// `u32`) over `items` items of `IN` input words each, returning `OUT`
/// words per item.
pub fn map<const IN: usize, const OUT: usize>(body: &str, input: &[[u32; IN]]) -> Vec<[u32; OUT]> {
    let s = setup();
    let kernel = format!(
        "{}\n@group(1) @binding(0) var<storage, read> input: array<u32>;
@group(1) @binding(1) var<storage, read_write> output: array<u32>;
var<private> item: u32;
fn inf(k: u32) -> f32 {{ return bitcast<f32>(input[{IN}u * ITEM + k]); }}
fn outf(k: u32, v: f32) {{ output[{OUT}u * ITEM + k] = bitcast<u32>(v); }}
fn outu(k: u32, v: u32) {{ output[{OUT}u * ITEM + k] = v; }}
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {{
    if (id.x >= {n}u) {{ return; }}
    item = id.x;
{body}
}}",
        speclab_gpu::source(RgbSpace::srgb()),
        n = input.len(),
    )
    .replace("ITEM", "item");
    let words: Vec<u32> = input.iter().flatten().copied().collect();
    let out = s.gpu.run(&kernel, &s.data, &words, OUT * input.len(), input.len() as u32);
    let out = out.unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(out.len(), OUT * input.len(), "the output's words");
    out.chunks_exact(OUT).map(|c| std::array::from_fn(|k| c[k])).collect()
}

/// The distance in units in the last place between two `f32`s (0 for
/// equal values, ±0 alike; the count of floats between them otherwise).
pub fn ulps(a: f32, b: f32) -> u64 {
    let ordered = |x: f32| {
        let bits = x.to_bits() as i64;
        if bits & 0x8000_0000 != 0 { 0x8000_0000 - bits } else { bits + 0x8000_0000 }
    };
    if a.is_nan() || b.is_nan() {
        return if a.is_nan() && b.is_nan() { 0 } else { u64::MAX };
    }
    ordered(a).abs_diff(ordered(b))
}

/// The largest ULP distance over pairs, and the pair where it is.
pub fn worst(pairs: impl IntoIterator<Item = (f32, f32)>) -> (u64, f32, f32) {
    pairs
        .into_iter()
        .map(|(a, b)| (ulps(a, b), a, b))
        .fold((0, 0.0, 0.0), |w, p| if p.0 > w.0 { p } else { w })
}

/// `n` numbers in [0, 1): a stratified sweep, then the edges and numbers
/// outside [0, 1) whose part modulo 1 is exact in `f32`.
pub fn unit_inputs(n: usize) -> Vec<f32> {
    let mut u: Vec<f32> = (0..n).map(|i| (i as f32 + 0.5) / n as f32).collect();
    let one_below = f32::from_bits(1.0f32.to_bits() - 1);
    u.extend([0.0, f32::MIN_POSITIVE, 1e-30, 1e-7, 0.25, 0.5, 0.75, one_below, 0.999_999]);
    // Outside [0, 1): taken modulo 1 (these exactly), NaN and ∞ as 0.
    u.extend([1.0, 1.25, 2.5, -0.25, -3.75, f32::NAN, f32::INFINITY, f32::NEG_INFINITY]);
    u
}

/// A fixed-seed generator of numbers in [0, 1) (xorshift64*), for inputs.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let v = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (v >> 40) as f32 / (1u64 << 24) as f32
    }
}
