//! Hero wavelengths: uniform (fixed point, bit for bit) and pbrt-v4's
//! visible density (an `atanh` in `f32` against the CPU's in `f64`).

use speclab::sampling::Domain;
use speclab::sampling::pdf::{Visible, WavelengthPdf};
use speclab::spectrum::Wavelengths;

use crate::common::{map, ulps, unit_inputs, worst};

/// λ, nearest index and 1/pdf of four wavelengths: 12 words per item.
const HERO_OUT: &str = "
    for (var j = 0u; j < 4u; j++) {
        outf(j, h.lambda[j]);
        outu(4u + j, h.nearest[j]);
        outf(8u + j, h.inv_pdf[j]);
    }";

#[test]
fn uniform_hero_wavelengths_are_the_cpus_bit_for_bit() {
    let u = unit_inputs(20_000);
    let input: Vec<[u32; 1]> = u.iter().map(|v| [v.to_bits()]).collect();
    for (domain, offset, width) in [(Domain::UNIFORM_VISIBLE, 0, 470), (Domain::ASSIGNMENT, 20, 350)] {
        let body = format!("    let h = speclab_hero_uniform(inf(0u), {offset}u, {width}u);{HERO_OUT}");
        let gpu = map::<1, 12>(&body, &input);
        for (&u, g) in u.iter().zip(&gpu) {
            let h = domain.hero::<4, f32>(u);
            let lambda = h.lambda().map(f32::to_bits);
            let nearest = h.nearest_nm().map(u32::from);
            let inv_pdf = h.inv_pdf().map(f32::to_bits);
            assert_eq!(g[..4], lambda, "λ at u = {u:e} over {width} nm");
            assert_eq!(g[4..8], nearest, "nearest nm at u = {u:e}");
            assert_eq!(g[8..], inv_pdf, "1/pdf at u = {u:e}");
        }
    }
}

#[test]
fn visible_hero_wavelengths_are_within_a_few_ulp() {
    let u = unit_inputs(20_000);
    let input: Vec<[u32; 1]> = u.iter().map(|v| [v.to_bits()]).collect();
    let body = format!("    let h = speclab_hero_visible(inf(0u));{HERO_OUT}");
    // (u outside [0, 1) included: the GPU takes it modulo 1 as the CPU does.)
    let gpu = map::<1, 12>(&body, &input);
    let (mut lambdas, mut over, mut moved) = (vec![], 0.0f64, 0);
    for (&u, g) in u.iter().zip(&gpu) {
        let h = Domain::VISIBLE.hero::<4, f32>(u);
        for j in 0..4 {
            lambdas.push((f32::from_bits(g[j]), h.lambda()[j]));
            let (a, b) = (f32::from_bits(g[8 + j]), h.inv_pdf()[j]);
            over = over.max(ulps(a, b) as f64 / pdf_ulps(b));
            moved += usize::from(g[4 + j] != u32::from(h.nearest_nm()[j]));
        }
    }
    let l = worst(lambdas.iter().copied());
    eprintln!(
        "visible hero: λ {} ULP ({} vs {}), 1/pdf at most {over:.3} of its bound; nearest nm differs at {moved} of {}",
        l.0,
        l.1,
        l.2,
        lambdas.len()
    );
    assert!(l.0 <= LAMBDA_ULPS, "λ {l:?}");
    assert!(over <= 1.0, "1/pdf at {over} of its bound");
    // A wavelength within a few ULP of a half nanometre may round the other way.
    assert!(moved * 1000 <= lambdas.len(), "{moved} nearest indices differ");
}

/// λ = 538 + atanh(y)/a in `f32`: y = t₀ + u(t₁ − t₀) and the rotation
/// u + j/4 rounded in `f32` (the CPU's in `f64`) move y by about 2ε,
/// which atanh's slope 1/(1 − y²) (up to 17) turns into 2.9e-4 nm at most
/// (4.7 ULP of λ from 512 nm up), and the GPU's atanh (a log) adds up to
/// 3 ULP of its value (up to 2.1, 1e-4 nm): 16 ULP.
const LAMBDA_ULPS: u64 = 16;

/// The ULP a density (or its reciprocal) may differ by where it is
/// `pdf`: `tanh` in `f32` within 16 ULP (WGSL inherits it from exp's
/// 3 + 2|2x| ULP, |x| ≤ 2.1, and a quotient), then 1 − y², which
/// amplifies y's relative error by 2y²/(1 − y²) (up to 32 at 830 nm).
fn pdf_ulps(pdf: f32) -> f64 {
    // y² from the density: pdf = norm·(1 − y²), or its reciprocal.
    let pdf = f64::from(pdf);
    let pdf = if pdf > 1.0 { 1.0 / pdf } else { pdf };
    let [t0, t1] = Visible::VISIBLE.tanh_ends();
    let norm = Visible::SLOPE / (t1 - t0);
    let y2 = (1.0 - pdf / norm).max(0.0);
    16.0 * (1.0 + 2.0 * y2 / (1.0 - y2).max(1e-9))
}

#[test]
fn the_visible_pdf_is_within_a_few_ulp() {
    let lambda: Vec<f32> =
        (0..=47_000).map(|i| 360.0 + i as f32 * 0.01).chain([359.99, 830.01, 538.0]).collect();
    let input: Vec<[u32; 1]> = lambda.iter().map(|v| [v.to_bits()]).collect();
    let gpu = map::<1, 1>("    outf(0u, speclab_visible_pdf(inf(0u)));", &input);
    let (mut worst_ulp, mut over) = (0, 0.0f64);
    for (&l, g) in lambda.iter().zip(&gpu) {
        let (a, b) = (f32::from_bits(g[0]), Visible::VISIBLE.pdf(f64::from(l)) as f32);
        worst_ulp = worst_ulp.max(ulps(a, b));
        if b > 0.0 {
            over = over.max(ulps(a, b) as f64 / pdf_ulps(b));
        } else {
            assert_eq!(a, 0.0, "outside 360–830 nm at {l}");
        }
    }
    eprintln!("visible pdf: {worst_ulp} ULP; at most {over:.3} of its bound");
    assert!(over <= 1.0, "{worst_ulp} ULP, {over} of the bound");
}
