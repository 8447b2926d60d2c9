//! One range for everything: the perfect white used for CIELAB is
//! integrated over 380–730 nm like every colour, even for lights and an
//! observer tabulated to 780 nm. (A white integrated to 780 nm for D65 and
//! F11 would move ΔE00 by up to 0.03 and put a perfect white patch below
//! L* = 100.)

use speclab::color::lab as perceptual;
use speclab::data::Light;
use speclab::sampling::reference;
use speclab::spectrum::observer;
use speclab::{Role, TabulatedSpectrum, Xyz};

/// Reflectance 1 over exactly 380–730 nm (the cubic through ones is 1).
fn perfect_white() -> TabulatedSpectrum {
    TabulatedSpectrum::new(vec![380.0, 500.0, 600.0, 730.0], vec![1.0; 4], Role::Reflectance).expect("valid")
}

/// Midpoint sum of light × c̄ over [a, b] at 0.005 nm (every 5 nm knot is
/// a step edge), independent of the library's quadrature.
fn riemann(light: &TabulatedSpectrum, a: f64, b: f64) -> Xyz {
    let steps = ((b - a) / 0.005).round() as usize;
    let h = (b - a) / steps as f64;
    (0..steps)
        .map(|i| a + (i as f64 + 0.5) * h)
        .map(|l| Xyz::from(observer::xyz_bar(l)) * (light.eval(l) * h))
        .sum()
}

#[test]
fn white_is_the_perfect_reflector_over_the_range() {
    let one = perfect_white();
    for light in Light::APPENDIX {
        let l = light.spectrum();
        let (white, patch) = (reference::white(l), reference::xyz(l, &one));
        let gap = (white - patch).to_array().iter().map(|d| d.abs()).fold(0.0, f64::max);
        assert!(gap <= 1e-12 * white.y, "{light:?}: {white:?} vs {patch:?}");
        let lab = perceptual::lab(patch, white);
        assert!(
            (lab[0] - 100.0).abs() < 1e-9 && lab[1].abs() < 1e-9 && lab[2].abs() < 1e-9,
            "{light:?}: {lab:?}"
        );
    }
}

#[test]
fn white_stops_at_730_nm() {
    for light in [Light::D65, Light::F11] {
        let l = light.spectrum();
        let white = reference::white(l);
        let (inside, tail) = (riemann(l, 380.0, 730.0), riemann(l, 730.0, 780.0));
        let gap = (white.x - inside.x).abs();
        eprintln!(
            "{light:?}: |white − Σ 380–730| = {:.1e}, 730–780 nm adds {:.1e} (relative X)",
            gap / white.x,
            tail.x / white.x
        );
        assert!(tail.x > 0.0 && gap < 0.01 * tail.x, "{light:?}: 730–780 nm must not be counted");
    }
}
