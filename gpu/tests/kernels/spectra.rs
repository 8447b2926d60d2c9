//! Spectra at a hero sample's wavelengths: dense tables (bit for bit),
//! the sigmoid polynomial, RGB colours through the table, Planck's law.

use speclab::color::{LinearRgb, RgbSpace};
use speclab::data::{lights, patches};
use speclab::sampling::Domain;
use speclab::spectrum::{DenseSpectrum, SigmoidPolynomial, planck};
use speclab::{Spectrum, TabulatedSpectrum};

use crate::common::{Rng, map, ulps, unit_inputs, worst};

#[test]
fn dense_spectra_are_the_cpus_bit_for_bit() {
    let u = unit_inputs(10_000);
    let input: Vec<[u32; 1]> = u.iter().map(|v| [v.to_bits()]).collect();
    let body = "    let h = speclab_hero_uniform(inf(0u), 0u, 470u);
    for (var s = 0u; s < 3u; s++) {
        let v = speclab_dense(s, h.nearest);
        for (var j = 0u; j < 4u; j++) { outf(4u * s + j, v[j]); }
    }";
    let gpu = map::<1, 12>(body, &input);
    let spectra: [&TabulatedSpectrum; 3] = [RgbSpace::srgb().illuminant(), &lights::CIE_A, &patches::G4];
    let dense = spectra.map(DenseSpectrum::new);
    for (&u, g) in u.iter().zip(&gpu) {
        let h = Domain::UNIFORM_VISIBLE.hero::<4, f32>(u);
        for (s, d) in dense.iter().enumerate() {
            assert_eq!(g[4 * s..4 * s + 4], d.sample(&h).values.map(f32::to_bits), "spectrum {s} at u = {u}");
        }
    }
}

#[test]
fn interpolated_dense_spectra_are_within_a_few_ulp() {
    // Spectrum 1 is CIE A, tabulated at 1 nm and interpolated linearly.
    let lambda: Vec<f32> = (0..=47_000).map(|i| 360.0 + i as f32 * 0.01).chain([359.99, 830.01]).collect();
    let input: Vec<[u32; 1]> = lambda.iter().map(|v| [v.to_bits()]).collect();
    let gpu = map::<1, 1>("    outf(0u, speclab_dense_linear(1u, vec4<f32>(inf(0u))).x);", &input);
    let pairs = lambda.iter().zip(&gpu).map(|(&l, g)| {
        let mut cpu = [0.0f32];
        let inside = (360.0..=830.0).contains(&l);
        lights::CIE_A.eval_many_f32(&[l], &mut cpu);
        (f32::from_bits(g[0]), if inside { cpu[0] } else { 0.0 })
    });
    let (w, a, b) = worst(pairs);
    eprintln!("dense, interpolated: {w} ULP ({a} vs {b})");
    // One lerp in f32 (three roundings) against the f64 lerp rounded once.
    assert!(w <= 4, "{w} ULP: {a} vs {b}");
}

#[test]
fn the_sigmoid_polynomial_is_within_a_few_ulp() {
    let mut rng = Rng(7);
    // Coefficients as the tables hold them (up to ±23,000), and small ones.
    let items: Vec<[f32; 4]> = (0..20_000)
        .map(|i| {
            let size = if i % 2 == 0 { 30.0 } else { 23_000.0 };
            let c = [0, 1, 2].map(|_| (rng.next() - 0.5) * 2.0 * size);
            [c[0], c[1], c[2], 360.0 + 470.0 * rng.next()]
        })
        .collect();
    let input: Vec<[u32; 4]> = items.iter().map(|v| v.map(f32::to_bits)).collect();
    let body = "    let s = SpeclabRgbSpectrum(1.0, vec3<f32>(inf(0u), inf(1u), inf(2u)));
    outf(0u, speclab_rgb_eval(s, vec4<f32>(inf(3u))).x);";
    let gpu = map::<4, 1>(body, &input);
    let pairs = items.iter().zip(&gpu).map(|(v, g)| {
        let mut cpu = [0.0f32];
        SigmoidPolynomial::eval_many_f32_coefficients([v[0], v[1], v[2]], 1.0, &[v[3]], &mut cpu);
        (f32::from_bits(g[0]), cpu[0])
    });
    let (w, a, b) = worst(pairs);
    eprintln!("sigmoid polynomial: {w} ULP ({a} vs {b})");
    assert!(w <= 4, "{w} ULP: {a} vs {b}");
}

/// Colours on a 22³ grid through [0, 1] (components at 0 and 1, greys,
/// saturated corners) and random ones, scaled by `scale`.
fn colours(scale: f32) -> Vec<[f32; 3]> {
    let steps = 22;
    let grid = (0..steps * steps * steps).map(|i| {
        let c = [i % steps, (i / steps) % steps, i / (steps * steps)];
        c.map(|k| k as f32 / (steps - 1) as f32 * scale)
    });
    let mut rng = Rng(11);
    grid.chain((0..2_000).map(|_| [0, 1, 2].map(|_| rng.next() * scale))).collect()
}

/// The GPU's values of each colour's spectrum (`make` is the WGSL
/// function's name) at a hero sample per colour, against `cpu`'s (the
/// spectrum, its scale and its polynomial's coefficients): the largest
/// ULP distance and the largest difference over the polynomial's bound.
fn rgb_values(
    make: &str,
    scale: f32,
    cpu: impl Fn(LinearRgb) -> (Box<dyn Spectrum>, [f32; 3]),
) -> (u64, f64) {
    let rgb = colours(scale);
    let u: Vec<f32> = (0..rgb.len()).map(|i| (i as f32 + 0.5) / rgb.len() as f32).collect();
    let input: Vec<[u32; 4]> =
        rgb.iter().zip(&u).map(|(c, &u)| [c[0], c[1], c[2], u].map(f32::to_bits)).collect();
    let value = if make == "speclab_rgb_light" {
        "speclab_rgb_light_eval(s, h, 0u)"
    } else {
        "speclab_rgb_eval(s, h.lambda)"
    };
    let body = format!(
        "    let h = speclab_hero_uniform(inf(3u), 0u, 470u);
    let s = {make}(vec3<f32>(inf(0u), inf(1u), inf(2u)));
    let v = {value};
    for (var j = 0u; j < 4u; j++) {{ outf(j, v[j]); }}
    outf(4u, s.c.x); outf(5u, s.c.y); outf(6u, s.c.z);"
    );
    let gpu = map::<4, 7>(&body, &input);
    let (mut ulp, mut over) = (0, 0.0f64);
    for ((c, &u), g) in rgb.iter().zip(&u).zip(&gpu) {
        let h = Domain::UNIFORM_VISIBLE.hero::<4, f32>(u);
        let (spectrum, coefficients) = cpu(LinearRgb::new(c[0].into(), c[1].into(), c[2].into()));
        let values = h.sample(&spectrum).values;
        // The table's coefficients to the bit (greys and black are constants
        // computed, not looked up).
        let looked_up = !(c[0] == c[1] && c[1] == c[2]) && coefficients[2].is_finite();
        if looked_up {
            assert_eq!(g[4..7], coefficients.map(f32::to_bits), "coefficients of {c:?}");
        }
        for j in 0..4 {
            let (a, b) = (f32::from_bits(g[j]), values[j]);
            ulp = ulp.max(ulps(a, b));
            let bound = polynomial_bound(coefficients, h.lambda()[j]) * f64::from(b.abs()) + 4.0 * ulp_of(b);
            over = over.max(f64::from((a - b).abs()) / bound);
            if std::env::var("DEBUG_RGB").is_ok() && f64::from((a - b).abs()) > bound {
                eprintln!("{c:?} λ {} gpu {a} cpu {b}", h.lambda()[j]);
            }
        }
    }
    (ulp, over)
}

/// The relative difference two evaluations of `scale·s(x)`, x = c₂ +
/// t(c₁ + t·c₀), may show when one reassociates (WGSL allows it; the
/// GPU's compiler does): x moves by up to 8ε(|c₂| + |t·c₁| + t²|c₀|)
/// where the coefficients cancel, and s by s'(x)/s(x) times that.
fn polynomial_bound([c0, c1, c2]: [f32; 3], lambda: f32) -> f64 {
    let t = f64::from((lambda - 380.0) * (1.0 / 350.0));
    let (c0, c1, c2) = (f64::from(c0), f64::from(c1), f64::from(c2));
    let x = c2 + t * (c1 + t * c0);
    let dx = 8.0 * f64::from(f32::EPSILON) / 2.0 * (c2.abs() + (t * c1).abs() + (t * t * c0).abs());
    let s = 0.5 + x / (2.0 * (1.0 + x * x).sqrt());
    let slope = 1.0 / (2.0 * (1.0 + x * x).powf(1.5));
    slope / s.max(f64::MIN_POSITIVE) * dx + 8.0 * f64::from(f32::EPSILON)
}

/// One unit in the last place of `v`.
fn ulp_of(v: f32) -> f64 {
    let v = v.abs();
    f64::from(f32::from_bits(v.to_bits() + 1) - v)
}

#[test]
fn rgb_albedos_are_within_the_polynomials_bound() {
    let space = RgbSpace::srgb();
    let (ulp, over) = rgb_values("speclab_rgb_albedo", 1.0, |c| {
        let a = space.albedo(c).expect("in [0, 1]");
        (Box::new(a), a.polynomial().coefficients().map(|v| v as f32))
    });
    eprintln!("RGB albedo: {ulp} ULP; at most {over:.3} of the polynomial's bound");
    assert!(over <= 1.0, "{ulp} ULP, {over} of the bound");
}

#[test]
fn rgb_unbounded_colours_and_lights_are_within_the_polynomials_bound() {
    let space = RgbSpace::srgb();
    let (ulp, over) = rgb_values("speclab_rgb_unbounded", 10.0, |c| {
        let s = space.unbounded(c);
        (Box::new(s), s.polynomial().coefficients().map(|v| v as f32))
    });
    eprintln!("RGB unbounded: {ulp} ULP; at most {over:.3} of the polynomial's bound");
    assert!(over <= 1.0, "{ulp} ULP, {over} of the bound");
    let (ulp, over) = rgb_values("speclab_rgb_light", 10.0, |c| {
        let s = space.light(c);
        (Box::new(s), s.polynomial().coefficients().map(|v| v as f32))
    });
    eprintln!("RGB light: {ulp} ULP; at most {over:.3} of the polynomial's bound");
    assert!(over <= 1.0, "{ulp} ULP, {over} of the bound");
}

#[test]
fn greys_are_within_eight_ulp_down_to_the_darkest() {
    // 10,000 greys from 1e-8 to 1 − 1e-7, logarithmically, and both ways.
    let greys: Vec<f32> = (0..5_000)
        .map(|i| 10f32.powf(-8.0 + 8.0 * i as f32 / 4_999.0))
        .flat_map(|v| [v, 1.0 - v.max(1.2e-7)])
        .collect();
    let input: Vec<[u32; 2]> = greys.iter().map(|&v| [v.to_bits(), 0.37f32.to_bits()]).collect();
    let body = "    let h = speclab_hero_uniform(inf(1u), 0u, 470u);
    outf(0u, speclab_rgb_eval(speclab_rgb_albedo(vec3<f32>(inf(0u))), h.lambda).x);";
    let gpu = map::<2, 1>(body, &input);
    let h = Domain::UNIFORM_VISIBLE.hero::<4, f32>(0.37);
    let space = RgbSpace::srgb();
    let pairs = greys.iter().zip(&gpu).map(|(&v, g)| {
        let grey = space.albedo(LinearRgb::new(v.into(), v.into(), v.into())).expect("in [0, 1]");
        (f32::from_bits(g[0]), h.sample(&grey).values[0])
    });
    let (w, a, b) = worst(pairs.collect::<Vec<_>>());
    eprintln!("greys: {w} ULP ({a} vs {b})");
    // c₂ = (v − ½)/√(v(1 − v)) in f32 (three roundings and a square root,
    // up to 3 ULP; the CPU's is f64, rounded once), and a dark grey's value
    // ≈ 1/(4c₂²) doubles c₂'s relative error: 8 ULP.
    assert!(w <= 8, "{w} ULP: {a} vs {b}");
}

#[test]
fn colours_that_are_not_finite_are_black() {
    let rgb = [[f32::INFINITY, 0.5, 0.2], [f32::NAN, 0.5, 0.2], [-1.0, -2.0, 0.0], [0.0; 3]];
    let input: Vec<[u32; 3]> = rgb.iter().map(|c| c.map(f32::to_bits)).collect();
    let body = "    let s = speclab_rgb_unbounded(vec3<f32>(inf(0u), inf(1u), inf(2u)));
    outf(0u, s.scale);";
    let gpu = map::<3, 1>(body, &input);
    let space = RgbSpace::srgb();
    for (c, g) in rgb.iter().zip(&gpu) {
        let cpu = space.unbounded(LinearRgb::new(c[0].into(), c[1].into(), c[2].into())).scale();
        // The CPU takes NaN as 0: (0, 0.5, 0.2) is not black there.
        let want = if c[0].is_nan() { None } else { Some(cpu as f32) };
        if let Some(want) = want {
            assert_eq!(f32::from_bits(g[0]), want, "{c:?}");
        }
    }
}

/// Whether the device fuses `a·b + c` (or runs `fma` unfused): either is
/// allowed by WGSL, and nothing else is. Printed: docs/gpu.md reads it.
#[test]
fn multiply_adds_are_fused_or_not_but_nothing_else() {
    let a = 1.0f32 + 2f32.powi(-12);
    let c = -(1.0f32 + 2f32.powi(-11));
    let body = "    let a = inf(0u); let c = inf(1u); outf(0u, a * a + c); outf(1u, fma(a, a, c));";
    let gpu = map::<2, 2>(body, &[[a.to_bits(), c.to_bits()]]);
    let (plain, fma) = (f32::from_bits(gpu[0][0]), f32::from_bits(gpu[0][1]));
    eprintln!("a·b + c: {plain:e}, fma: {fma:e} (fused: {:e}, unfused: 0)", 2f32.powi(-24));
    for v in [plain, fma] {
        assert!(v == 0.0 || v == 2f32.powi(-24), "{v:e}");
    }
}

#[test]
fn planck_is_within_its_exponential() {
    let mut rng = Rng(3);
    let items: Vec<[f32; 2]> =
        (0..20_000).map(|_| [360.0 + 470.0 * rng.next(), 1000.0 + 19_000.0 * rng.next()]).collect();
    let input: Vec<[u32; 2]> = items.iter().map(|v| v.map(f32::to_bits)).collect();
    let gpu = map::<2, 1>("    outf(0u, speclab_planck(vec4<f32>(inf(0u)), inf(1u)).x);", &input);
    let (mut worst_ulp, mut over) = (0, 0.0f64);
    for (v, g) in items.iter().zip(&gpu) {
        let (a, b) = (f32::from_bits(g[0]), planck(f64::from(v[0]), f64::from(v[1])) as f32);
        let w = ulps(a, b);
        worst_ulp = worst_ulp.max(w);
        over = over.max(w as f64 / planck_ulps(v[0], v[1]));
    }
    eprintln!("Planck: {worst_ulp} ULP; at most {over:.3} of the bound");
    assert!(over <= 1.0, "{worst_ulp} ULP, {over} of the bound");
}

/// The ULP Planck's law may differ by in `f32`: WGSL allows exp(x)
/// 3 + 2|x| ULP (x = c₂/(λT), 0.087 to 40 here), which e^x/(e^x − 1)
/// amplifies where the subtraction cancels (small x), and 8 ULP for the
/// powers, the quotient and the roundings of λ, T and the result.
fn planck_ulps(lambda: f32, kelvin: f32) -> f64 {
    let x = 1.438_776_877e7 / (f64::from(lambda) * f64::from(kelvin));
    (3.0 + 2.0 * x) * x.exp() / x.exp_m1() + 8.0
}
