//! Three ways to estimate the XYZ of light × surface from n hero samples of
//! four wavelengths, written the way each kind of program would:
//!
//! - **speclab**: `HeroSample::<4>::exact(u)`, `sample`, `*`, `to_xyz`:
//!   exact interpolants (linear light, cubic reflectance and matching
//!   functions); and over dense tables as the README's first f32 loop
//!   writes it (`HeroSample::<4, f32>::new(u)`, the dense observer), with
//!   the tables held directly or as `Box<dyn Spectrum>`.
//! - **pbrt-style**: what pbrt-v4 does: PCG32, `SampleUniform`-style hero
//!   rotation in f32, five rounded lookups per wavelength into 1 nm f32
//!   tables (light, surface, x̄, ȳ, z̄), division by the pdf.
//! - **hand-tuned**: xorshift32, fixed-point hero rotation, branch-free
//!   lookups (light, surface, and one interleaved `{x̄, ȳ, z̄, 0}` row: three
//!   loads per wavelength), 4 × 4 independent accumulators.
//!
//! The 1 nm tables are sampled from speclab's own interpolants, so all three
//! estimate nearly the same integral; the peers trade exactness (a 1 nm
//! discretisation) for speed. Every kernel draws its own random numbers; the
//! speclab kernel uses the same xorshift32 as the hand-tuned one.

use speclab::SampledSpectrum;
use speclab::color::{LinearRgb, RgbAlbedo, RgbSpace, RgbTexel};
use speclab::sampling::Domain;
use speclab::spectrum::observer::xyz_bar;
use speclab::spectrum::{DenseSpectrum, Float, Wavelengths};
use speclab::{HeroSample, LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, Spectrum, TabulatedSpectrum, Xyz};

/// Table entries: one per nm from 380 to 730 inclusive.
pub const ENTRIES: usize = 351;

/// xorshift32 (Marsaglia 2003).
#[derive(Clone, Copy)]
pub struct XorShift32(pub u32);

impl XorShift32 {
    #[inline(always)]
    pub fn next(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x
    }
}

/// PCG32 (O'Neill 2014), pbrt-v4's `RNG`.
#[derive(Clone, Copy)]
pub struct Pcg32 {
    state: u64,
    inc: u64,
}

impl Pcg32 {
    pub fn new(seed: u64) -> Self {
        let mut r = Pcg32 { state: 0, inc: (0xda3e_39cb_94b9_5bdb << 1) | 1 };
        r.next();
        r.state = r.state.wrapping_add(seed);
        r.next();
        r
    }

    #[inline(always)]
    pub fn next(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(0x5851_f42d_4c95_7f2d).wrapping_add(self.inc);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        xorshifted.rotate_right((old >> 59) as u32)
    }

    /// A float in [0, 1), as pbrt's `Uniform<Float>`.
    #[inline(always)]
    pub fn uniform(&mut self) -> f32 {
        (self.next() as f32 * f32::from_bits(0x2f80_0000)).min(1.0 - f32::EPSILON / 2.0)
    }
}

/// 1 nm f32 tables sampled from speclab's interpolants.
pub struct Tables {
    pub light: Vec<f32>,
    pub surface: Vec<f32>,
    pub x: Vec<f32>,
    pub y: Vec<f32>,
    pub z: Vec<f32>,
    /// `{x̄, ȳ, z̄, 0}` per nm, 16-byte aligned rows.
    pub xyz0: Vec<[f32; 4]>,
}

impl Tables {
    pub fn new(light: &TabulatedSpectrum, surface: &TabulatedSpectrum) -> Self {
        let at = |i: usize| LAMBDA_MIN + i as f64;
        let sample = |f: &dyn Fn(f64) -> f64| (0..ENTRIES).map(|i| f(at(i)) as f32).collect::<Vec<_>>();
        let (x, y, z) = (sample(&|l| xyz_bar(l)[0]), sample(&|l| xyz_bar(l)[1]), sample(&|l| xyz_bar(l)[2]));
        let xyz0 = (0..ENTRIES).map(|i| [x[i], y[i], z[i], 0.0]).collect();
        Tables { light: sample(&|l| light.eval(l)), surface: sample(&|l| surface.eval(l)), x, y, z, xyz0 }
    }
}

/// speclab's per-sample path over exact spectra, K wavelengths in
/// precision `T`: the mean XYZ of `n` hero samples.
#[inline(never)]
pub fn speclab_hero<const K: usize, T: Float>(
    light: &TabulatedSpectrum,
    surface: &TabulatedSpectrum,
    n: usize,
    rng: &mut XorShift32,
) -> Xyz {
    let mut sum = Xyz::ZERO;
    for _ in 0..n {
        let h = HeroSample::<K, T>::exact(T::from_f64(f64::from(rng.next()) * (1.0 / 4_294_967_296.0)));
        sum += h.to_xyz(light.sample(&h) * surface.sample(&h));
    }
    sum / n as f64
}

/// speclab's per-sample path over dense tables (light, surface and
/// observer at every whole nm, looked up at the nearest), K = 4 in
/// precision `T`, as the README's first f32 loop writes it (uniform over
/// 360–830 nm, the CIE 1931 1 nm observer, `Domain::UNIFORM_VISIBLE`): the mean XYZ
/// of `n` hero samples. `S` is how the renderer holds its materials (the
/// table itself, or `Box<dyn Spectrum>`).
#[inline(never)]
pub fn speclab_dense_hero<T: Float, L: Spectrum, S: Spectrum>(
    light: &L,
    surface: &S,
    n: usize,
    rng: &mut XorShift32,
) -> Xyz {
    let mut sum = Xyz::ZERO;
    for _ in 0..n {
        let u = T::from_f64(f64::from(rng.next()) * (1.0 / 4_294_967_296.0));
        let h = Domain::UNIFORM_VISIBLE.hero::<4, T>(u);
        sum += h.to_xyz(light.sample(&h) * surface.sample(&h));
    }
    sum / n as f64
}

/// [`speclab_dense_hero`] with the surface a texture's colour looked up at
/// each hit (`space.albedo(rgb)`, as pbrt-v4 builds an
/// `RGBAlbedoSpectrum` at each shading point), `f32`.
#[inline(never)]
pub fn speclab_texel_hero(
    space: &RgbSpace,
    light: &DenseSpectrum,
    texels: &[LinearRgb],
    n: usize,
    rng: &mut XorShift32,
) -> Xyz {
    texel_loop(light, n, rng, |i| space.albedo(texels[i % texels.len()]).expect("texels are albedos"))
}

/// [`speclab_texel_hero`] with the texture's colours converted once, when
/// it was loaded (an `RgbAlbedo` per texel, as Mitsuba 3's `bitmap`
/// texture stores coefficients): at each hit, the texel's albedo is read,
/// then sampled.
#[inline(never)]
pub fn speclab_converted_texel_hero(
    light: &DenseSpectrum,
    texels: &[RgbAlbedo],
    n: usize,
    rng: &mut XorShift32,
) -> Xyz {
    texel_loop(light, n, rng, |i| texels[i % texels.len()])
}

/// [`speclab_converted_texel_hero`] with each texel in 12 bytes (an
/// `RgbTexel`, decoded at each hit).
#[inline(never)]
pub fn speclab_texel_12_hero(
    light: &DenseSpectrum,
    texels: &[RgbTexel],
    n: usize,
    rng: &mut XorShift32,
) -> Xyz {
    texel_loop(light, n, rng, |i| texels[i % texels.len()])
}

/// The texel kernels' loop: `n` f32 hero samples of the light times the
/// albedo of hit `i`.
#[inline(always)]
fn texel_loop<S: Spectrum>(
    light: &DenseSpectrum,
    n: usize,
    rng: &mut XorShift32,
    albedo: impl Fn(usize) -> S,
) -> Xyz {
    let mut sum = Xyz::ZERO;
    for i in 0..n {
        let u = f64::from(rng.next()) * (1.0 / 4_294_967_296.0);
        let h = HeroSample::<4, f32>::new(u as f32);
        sum += h.to_xyz(light.sample(&h) * albedo(i).sample(&h));
    }
    sum / n as f64
}

/// pbrt-v4's `DenselySampledSpectrum` lookup: the entry at the rounded
/// wavelength, 0 outside the table.
#[inline(always)]
fn dense(table: &[f32], lambda: f32) -> f32 {
    let offset = lambda.round() as i32 - LAMBDA_MIN as i32;
    if offset < 0 || offset as usize >= table.len() { 0.0 } else { table[offset as usize] }
}

/// The pbrt-style kernel: the mean XYZ of `n` hero samples.
#[inline(never)]
pub fn pbrt_hero(t: &Tables, n: usize, rng: &mut Pcg32) -> [f32; 3] {
    const N: usize = 4;
    let (min, max) = (LAMBDA_MIN as f32, LAMBDA_MAX as f32);
    let mut sum = [0.0f32; 3];
    for _ in 0..n {
        // SampledWavelengths::SampleUniform
        let u = rng.uniform();
        let mut lambda = [0.0f32; N];
        lambda[0] = (1.0 - u) * min + u * max;
        let delta = (max - min) / N as f32;
        for i in 1..N {
            lambda[i] = lambda[i - 1] + delta;
            if lambda[i] > max {
                lambda[i] = min + (lambda[i] - max);
            }
        }
        let pdf = 1.0 / (max - min);
        // L = light · surface; XYZ = average over wavelengths of c̄·L / pdf
        for &l in &lambda {
            let v = dense(&t.light, l) * dense(&t.surface, l) / pdf;
            sum[0] += dense(&t.x, l) * v;
            sum[1] += dense(&t.y, l) * v;
            sum[2] += dense(&t.z, l) * v;
        }
    }
    let scale = 1.0 / (N * n) as f32;
    sum.map(|s| s * scale)
}

/// The hand-tuned kernel: the mean XYZ of `n` hero samples.
#[inline(never)]
pub fn hand_tuned_hero(t: &Tables, n: usize, rng: &mut XorShift32) -> [f32; 3] {
    // Positions in 1/256 nm over [0, 350 nm); a quarter turn is 87.5 nm.
    const PERIOD: u32 = 350 << 8;
    const QUARTER: u32 = PERIOD / 4;
    let (light, surface, xyz0) = (&t.light[..ENTRIES], &t.surface[..ENTRIES], &t.xyz0[..ENTRIES]);
    let mut acc = [[0.0f32; 4]; 4];
    for _ in 0..n {
        let p0 = ((u64::from(rng.next()) * u64::from(PERIOD)) >> 32) as u32;
        for (j, a) in acc.iter_mut().enumerate() {
            let p = p0 + j as u32 * QUARTER;
            let p = if p >= PERIOD { p - PERIOD } else { p };
            // Round to the nearest nm; index 350 (730 nm) exists.
            let i = ((p + 128) >> 8) as usize;
            let v = light[i] * surface[i];
            let c = xyz0[i];
            for ch in 0..4 {
                a[ch] += c[ch] * v;
            }
        }
    }
    let scale = (LAMBDA_WIDTH as f32) / (4 * n) as f32;
    let s = |ch: usize| (acc[0][ch] + acc[1][ch] + acc[2][ch] + acc[3][ch]) * scale;
    [s(0), s(1), s(2)]
}

/// A renderer's own list of materials of mixed kinds, as the docs
/// recommend for the hot loop: an enum whose `sample` dispatches to each
/// kind's own.
pub enum Material {
    /// A measured reflectance as a dense table.
    Table(DenseSpectrum),
    /// A texture's colour.
    Rgb(RgbAlbedo),
}

impl Spectrum for Material {
    fn eval(&self, lambda: f64) -> f64 {
        match self {
            Material::Table(s) => s.eval(lambda),
            Material::Rgb(s) => s.eval(lambda),
        }
    }

    #[inline(always)]
    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        match self {
            Material::Table(s) => s.sample(at),
            Material::Rgb(s) => s.sample(at),
        }
    }
}
