// speclab's per-sample arithmetic in WGSL (functions; the constants before
// them are generated from the Rust crate's data by `speclab_gpu::source`).
// Every function mirrors a Rust function and is tested against it.

// ---- data (bind group 0, `speclab_gpu::Data`) -------------------------

// The observer: [x̄, ȳ, z̄, 1] at 360, 361, …, 830 nm (471 rows).
@group(0) @binding(0) var<storage, read> speclab_observer: array<vec4<f32>>;
// Dense spectra: spectrum s at 360 + i nm is speclab_spectra[s * 471 + i].
@group(0) @binding(1) var<storage, read> speclab_spectra: array<f32>;
// One RGB table's coefficients: node [case][z][y][x] at 3 × (((case·n + z)·n + y)·n + x).
@group(0) @binding(2) var<storage, read> speclab_rgb_table: array<f32>;
// The table's n nodes of the largest component, then the n − 1 reciprocals of their spacing.
@group(0) @binding(3) var<storage, read> speclab_rgb_nodes: array<f32>;

// ---- hero wavelengths ---------------------------------------------------

// K = 4 wavelengths (nm), their nearest whole nanometre's index from 360 nm
// (471 outside 360–830 nm) and their reciprocal densities (nm).
struct SpeclabHero {
    lambda: vec4<f32>,
    nearest: vec4<u32>,
    inv_pdf: vec4<f32>,
}

// floor(u · width · 2¹⁶) for u in [0, 1), exactly (a 33-bit product in two
// words): the position of a uniform hero wavelength in 2⁻¹⁶ nm.
fn speclab_fixed_position(u: f32, width: u32) -> u32 {
    let bits = bitcast<u32>(u);
    var e = (bits >> 23u) & 0xffu;
    var m = bits & 0x7fffffu;
    if (e == 0u) {
        e = 1u;
    } else {
        m = m | 0x800000u;
    }
    // u = m · 2^(e − 150); the product m · width · 2^(e − 134).
    let s = 134u - e;
    let a = (m >> 16u) * width;
    let b = (m & 0xffffu) * width;
    let lo = ((a & 0xffffu) << 16u) + b;
    let hi = (a >> 16u) + select(0u, 1u, lo < b);
    if (s >= 33u) {
        return 0u;
    }
    if (s == 32u) {
        return hi;
    }
    return (hi << (32u - s)) | (lo >> s);
}

// u modulo 1, in [0, 1): u itself for u in [0, 1) (exactly as the CPU's
// `fract`), 0 for 1, NaN and infinities; other values within an ulp of it.
fn speclab_unit(u: f32) -> f32 {
    let f = u - floor(u);
    return select(0.0, f, f >= 0.0 && f < 1.0);
}

// Four wavelengths uniform over [360 + offset, 360 + offset + width] nm
// (whole nanometres within 360–830), from the renderer's number u (taken
// modulo 1): the hero at u and three rotations by a quarter, in fixed
// point (speclab's `Domain::hero` for a uniform density, bit for bit for
// u in [0, 1]).
fn speclab_hero_uniform(u: f32, offset: u32, width: u32) -> SpeclabHero {
    let period = width << 16u;
    let p0 = min(speclab_fixed_position(speclab_unit(u), width), period - 1u);
    let start = SPECLAB_DENSE_START + offset;
    let round = 0x8000u + (offset << 16u);
    var h: SpeclabHero;
    for (var j = 0u; j < 4u; j++) {
        var p = p0 + period / 4u * j;
        if (p >= period) {
            p = p - period;
        }
        h.lambda[j] = f32(start + (p >> 16u)) + f32(p & 0xffffu) * (1.0 / 65536.0);
        h.nearest[j] = (p + round) >> 16u;
        h.inv_pdf[j] = f32(width);
    }
    return h;
}

// The nearest whole nanometre's index from 360 nm, 471 outside 360–830 nm.
fn speclab_nearest(lambda: f32) -> u32 {
    let x = lambda - f32(SPECLAB_DENSE_START);
    if (x >= 0.0 && lambda <= f32(SPECLAB_DENSE_START + SPECLAB_DENSE_COUNT - 1u)) {
        return u32(x + 0.5);
    }
    return SPECLAB_DENSE_COUNT;
}

// pbrt-v4's visible density at lambda (1/nm), 0 outside 360–830 nm.
fn speclab_visible_pdf(lambda: f32) -> f32 {
    if (!(lambda >= SPECLAB_VISIBLE_MIN && lambda <= SPECLAB_VISIBLE_MAX)) {
        return 0.0;
    }
    let y = tanh(SPECLAB_VISIBLE_SLOPE * (lambda - SPECLAB_VISIBLE_CENTER));
    return SPECLAB_VISIBLE_NORM * (1.0 - y * y);
}

// The wavelength of pbrt-v4's visible density at u (taken modulo 1) and
// its reciprocal density: (lambda, 1/pdf).
fn speclab_visible_sample(u: f32) -> vec2<f32> {
    let y = SPECLAB_VISIBLE_T0 + speclab_unit(u) * (SPECLAB_VISIBLE_T1 - SPECLAB_VISIBLE_T0);
    let lambda = clamp(SPECLAB_VISIBLE_CENTER + atanh(y) / SPECLAB_VISIBLE_SLOPE, SPECLAB_VISIBLE_MIN, SPECLAB_VISIBLE_MAX);
    return vec2<f32>(lambda, 1.0 / (SPECLAB_VISIBLE_NORM * (1.0 - y * y)));
}

// Four wavelengths of pbrt-v4's visible density: u and three rotations by a
// quarter in primary-sample space (speclab's `Domain::VISIBLE.hero`).
fn speclab_hero_visible(u: f32) -> SpeclabHero {
    var h: SpeclabHero;
    let u0 = speclab_unit(u);
    for (var j = 0u; j < 4u; j++) {
        var v = u0 + f32(j) * 0.25;
        if (v >= 1.0) {
            v = v - 1.0;
        }
        let drawn = speclab_visible_sample(v);
        h.lambda[j] = drawn.x;
        h.nearest[j] = speclab_nearest(drawn.x);
        h.inv_pdf[j] = drawn.y;
    }
    return h;
}

// ---- spectra at the four wavelengths -----------------------------------

// Dense spectrum s (speclab_spectra) at the wavelengths' nearest nanometres.
fn speclab_dense(s: u32, nearest: vec4<u32>) -> vec4<f32> {
    var v = vec4<f32>(0.0);
    for (var j = 0u; j < 4u; j++) {
        if (nearest[j] < SPECLAB_DENSE_COUNT) {
            v[j] = speclab_spectra[s * SPECLAB_DENSE_COUNT + nearest[j]];
        }
    }
    return v;
}

// Dense spectrum s interpolated linearly between whole nanometres at the
// wavelengths (0 outside 360–830 nm): a 1 nm table as speclab's
// `TabulatedSpectrum` evaluates it (the CPU in f64, here in f32).
fn speclab_dense_linear(s: u32, lambda: vec4<f32>) -> vec4<f32> {
    var v = vec4<f32>(0.0);
    let last = f32(SPECLAB_DENSE_COUNT - 1u);
    for (var j = 0u; j < 4u; j++) {
        let x = lambda[j] - f32(SPECLAB_DENSE_START);
        if (x >= 0.0 && x <= last) {
            let i = min(u32(x), SPECLAB_DENSE_COUNT - 2u);
            let f = x - f32(i);
            let a = speclab_spectra[s * SPECLAB_DENSE_COUNT + i];
            let b = speclab_spectra[s * SPECLAB_DENSE_COUNT + i + 1u];
            v[j] = a + f * (b - a);
        }
    }
    return v;
}

// ½ + x/(2√(1 + x²)) without cancellation (speclab's `sigmoid_f32`).
fn speclab_sigmoid(x: f32) -> f32 {
    let r = sqrt(1.0 + x * x);
    let t = 0.5 / (r * (r + abs(x)));
    return select(1.0 - t, t, x < 0.0);
}

// A sigmoid polynomial times a scale: an RGB colour's spectrum (scale 1 for
// an albedo, 0 for black; `speclab_rgb_*` make it).
struct SpeclabRgbSpectrum {
    scale: f32,
    c: vec3<f32>,
}

// scale · sigmoid(c₀t² + c₁t + c₂), t = (λ − 380)/350, at four wavelengths
// (speclab's `SigmoidPolynomial::eval_many_f32`).
fn speclab_rgb_eval(s: SpeclabRgbSpectrum, lambda: vec4<f32>) -> vec4<f32> {
    var v: vec4<f32>;
    for (var j = 0u; j < 4u; j++) {
        let t = (lambda[j] - SPECLAB_SIGMOID_LAMBDA0) * (1.0 / SPECLAB_SIGMOID_WIDTH);
        v[j] = s.scale * speclab_sigmoid(s.c.z + t * (s.c.y + t * s.c.x));
    }
    return v;
}

// An RGB light (speclab's `RgbIlluminant`): its tint times the space's
// illuminant, dense spectrum `illuminant` (interpolated, as the CPU's).
fn speclab_rgb_light_eval(s: SpeclabRgbSpectrum, h: SpeclabHero, illuminant: u32) -> vec4<f32> {
    return speclab_rgb_eval(s, h.lambda) * speclab_dense_linear(illuminant, h.lambda);
}

// The interval k of z in the table's nodes: nodes[k] ≤ z < nodes[k + 1], the
// last closed.
fn speclab_rgb_interval(z: f32, n: u32) -> u32 {
    var lo = 0u;
    var hi = n - 2u;
    while (lo < hi) {
        let mid = (lo + hi + 1u) / 2u;
        if (z >= speclab_rgb_nodes[mid]) {
            lo = mid;
        } else {
            hi = mid - 1u;
        }
    }
    return lo;
}

fn speclab_rgb_corner(i: u32) -> vec3<f32> {
    return vec3<f32>(speclab_rgb_table[3u * i], speclab_rgb_table[3u * i + 1u], speclab_rgb_table[3u * i + 2u]);
}

fn speclab_lerp3(a: vec3<f32>, b: vec3<f32>, t: f32) -> vec3<f32> {
    return a + t * (b - a);
}

// The table's polynomial of rgb in [0, 1]³ (speclab's `RgbTable::albedo`):
// greys the constants of their value, black and white 0 and 1 exactly.
fn speclab_rgb_albedo(rgb: vec3<f32>) -> SpeclabRgbSpectrum {
    // The uploaded table's resolution: n nodes and n − 1 reciprocals.
    let n = (arrayLength(&speclab_rgb_nodes) + 1u) / 2u;
    if (rgb.x == rgb.y && rgb.y == rgb.z) {
        let v = rgb.x;
        if (v <= 0.0) {
            return SpeclabRgbSpectrum(0.0, vec3<f32>(0.0));
        }
        if (v >= 1.0) {
            return SpeclabRgbSpectrum(1.0, vec3<f32>(0.0, 0.0, SPECLAB_SIGMOID_HUGE));
        }
        // (2v − 1)/√(1 − (2v − 1)²), without its cancellation for small v.
        return SpeclabRgbSpectrum(1.0, vec3<f32>(0.0, 0.0, (v - 0.5) / sqrt(v * (1.0 - v))));
    }
    var case_ = 2u;
    var zxy = vec3<f32>(rgb.z, rgb.x, rgb.y);
    if (rgb.x > rgb.y) {
        if (rgb.x > rgb.z) {
            case_ = 0u;
            zxy = vec3<f32>(rgb.x, rgb.y, rgb.z);
        }
    } else if (rgb.y > rgb.z) {
        case_ = 1u;
        zxy = vec3<f32>(rgb.y, rgb.z, rgb.x);
    }
    let z = zxy.x;
    if (z < 1.17549435e-38) {
        return SpeclabRgbSpectrum(0.0, vec3<f32>(0.0));
    }
    let k = speclab_rgb_interval(z, n);
    let scale = 1.0 / z;
    let last = f32(n - 1u);
    let x = zxy.y * scale * last;
    let y = zxy.z * scale * last;
    let xi = min(u32(x), n - 2u);
    let yi = min(u32(y), n - 2u);
    let dx = x - f32(xi);
    let dy = y - f32(yi);
    let dz = (z - speclab_rgb_nodes[k]) * speclab_rgb_nodes[n + k];
    let at = ((case_ * n + k) * n + yi) * n + xi;
    let row = n;
    let slice = n * n;
    let low = speclab_lerp3(
        speclab_lerp3(speclab_rgb_corner(at), speclab_rgb_corner(at + 1u), dx),
        speclab_lerp3(speclab_rgb_corner(at + row), speclab_rgb_corner(at + row + 1u), dx), dy);
    let high = speclab_lerp3(
        speclab_lerp3(speclab_rgb_corner(at + slice), speclab_rgb_corner(at + slice + 1u), dx),
        speclab_lerp3(speclab_rgb_corner(at + slice + row), speclab_rgb_corner(at + slice + row + 1u), dx), dy);
    return SpeclabRgbSpectrum(1.0, speclab_lerp3(low, high, dz));
}

// Any colour as a non-negative spectrum: twice its largest component times
// the albedo of the colour over that (speclab's `RgbSpace::unbounded`;
// negative components as 0).
fn speclab_rgb_unbounded(rgb: vec3<f32>) -> SpeclabRgbSpectrum {
    let c = max(rgb, vec3<f32>(0.0));
    let largest = max(c.x, max(c.y, c.z));
    if (!(largest > 0.0 && largest <= 3.40282347e38)) {
        return SpeclabRgbSpectrum(0.0, vec3<f32>(0.0));
    }
    let scale = 2.0 * largest;
    var s = speclab_rgb_albedo(c / scale);
    s.scale = s.scale * scale;
    return s;
}

// A light of colour rgb (speclab's `RgbSpace::light`): the unbounded
// spectrum, its scale times the space's light factor; evaluate it with
// `speclab_rgb_light_eval` and the space's illuminant.
fn speclab_rgb_light(rgb: vec3<f32>) -> SpeclabRgbSpectrum {
    var s = speclab_rgb_unbounded(rgb);
    s.scale = s.scale * SPECLAB_RGB_LIGHT_FACTOR;
    return s;
}

// ---- Planck's law ----------------------------------------------------

// Spectral radiance of a blackbody at kelvin, W·sr⁻¹·m⁻²·nm⁻¹ (speclab's
// `planck`), at four wavelengths (nm; 0 at wavelengths that are not
// positive). In f32 the denominator overflows where c₂/(λT) is large: 0
// from c₂/(λT) = 50 (below about 800 K at 360 nm); tested from 1,000 K.
fn speclab_planck(lambda: vec4<f32>, kelvin: f32) -> vec4<f32> {
    var v: vec4<f32>;
    for (var j = 0u; j < 4u; j++) {
        let l = lambda[j];
        let l2 = l * l;
        let x = SPECLAB_PLANCK_C2_NM / (l * kelvin);
        v[j] = select(0.0, SPECLAB_PLANCK_C1_NM / (l2 * l2 * l * (exp(min(x, 50.0)) - 1.0)), l > 0.0 && x < 50.0);
    }
    return v;
}

// ---- the observer ------------------------------------------------------

// Each wavelength's weights [x̄, ȳ, z̄, 1] · (1/pdf)/4 (speclab's hero rows).
fn speclab_weights(h: SpeclabHero) -> array<vec4<f32>, 4> {
    var w: array<vec4<f32>, 4>;
    for (var j = 0u; j < 4u; j++) {
        var row = vec4<f32>(0.0, 0.0, 0.0, 1.0);
        if (h.nearest[j] < SPECLAB_DENSE_COUNT) {
            row = speclab_observer[h.nearest[j]];
        }
        let s = h.inv_pdf[j] * 0.25;
        w[j] = vec4<f32>(row.xyz * s, s);
    }
    return w;
}

// XYZ of the values v at the sample's wavelengths: Σⱼ wⱼ·vⱼ, summed in
// speclab's order ((w₀v₀ + w₂v₂) + (w₁v₁ + w₃v₃)).
fn speclab_xyz(w: array<vec4<f32>, 4>, v: vec4<f32>) -> vec3<f32> {
    let even = w[2].xyz * v[2] + w[0].xyz * v[0];
    let odd = w[3].xyz * v[3] + w[1].xyz * v[1];
    return even + odd;
}
