//! Four small clients as a renderer writes them against the core's API:
//! the README's f32 loop, materials of mixed kinds in one list, a fitted
//! rule of a size chosen at run time, and an RGB-textured scene. Each
//! compiles against today's names (the CHANGELOG's migration table gives
//! the old ones) and lands near the exact colour.

use speclab::color::rgb_table::RgbTable;
use speclab::color::{RgbAlbedo, RgbSpace};
use speclab::data::{conductors, lights, patches};
use speclab::sampling::rule::Rule;
use speclab::sampling::{AtWidth, reference, with_lanes};
use speclab::spectrum::{DenseSpectrum, FnSpectrum};
use speclab::{HeroSample, LinearRgb, SampledSpectrum, Spectrum, Xyz};

/// `n` hero samples of one bounce (`surface` lit by `light`), in f32, the
/// renderer's numbers stratified over [0, 1/4).
fn one_bounce(light: &impl Spectrum, surface: &dyn Spectrum, n: u16) -> Xyz {
    let mut pixel = Xyz::ZERO;
    for i in 0..n {
        let path = HeroSample::<4, f32>::new((f32::from(i) + 0.5) / (4.0 * f32::from(n)));
        let beta: SampledSpectrum<4, f32> = path.sample(&surface);
        pixel += path.to_xyz(beta * path.sample(light));
    }
    pixel / f64::from(n)
}

/// The README's loop: dense tables, f32 hero samples, two bounces.
#[test]
fn the_readme_loop() {
    let light = DenseSpectrum::new(&lights::F11);
    let walls = [&patches::G4, &patches::A1].map(DenseSpectrum::new);
    let mut pixel = Xyz::ZERO;
    for i in 0..1024_u16 {
        let path = HeroSample::<4, f32>::new((f32::from(i) + 0.5) / 1024.0);
        let (le, mut beta, mut l) =
            (light.sample(&path), SampledSpectrum::splat(1.0), SampledSpectrum::zero());
        for wall in &walls {
            beta *= wall.sample(&path);
            l += beta * le * 0.5;
        }
        pixel += path.to_xyz(l);
    }
    let exact = (reference::xyz(&lights::F11, &patches::G4)
        + reference::xyz_of_product(&[&lights::F11, &patches::G4, &patches::A1]))
        * 0.5;
    assert!((pixel / 1024.0 - exact).to_array().iter().all(|d| d.abs() < 2e-3 * exact.y), "{pixel:?}");
}

/// Materials of four kinds in one list, each within 1 % of its exact
/// colour under D65.
#[test]
fn a_list_of_mixed_materials() -> Result<(), speclab::Error> {
    let gold = conductors::AU.reflectance();
    let materials: Vec<Box<dyn Spectrum + Send + Sync>> = vec![
        Box::new(DenseSpectrum::new(&patches::G4)),
        Box::new(RgbSpace::srgb().albedo(LinearRgb::new(0.1, 0.5, 0.2))?),
        Box::new(gold.tabulated()),
        Box::new(FnSpectrum(|l: f64| if l > 580.0 { 0.8 } else { 0.1 })),
    ];
    let light = DenseSpectrum::new(&lights::D65);
    for (i, m) in materials.iter().enumerate() {
        let (got, exact) = (one_bounce(&light, m.as_ref(), 512), reference::xyz(&lights::D65, m.as_ref()));
        assert!((got.y - exact.y).abs() < 0.01 * exact.y, "material {i}: {got:?} against {exact:?}");
    }
    Ok(())
}

/// A rule fitted to the scene's light, its size chosen at run time,
/// reaching compile-time lanes: within 1 % of the exact colour at M = 10
/// under F11, and refused at M = 0.
#[test]
fn a_fitted_rule_of_run_time_size() -> Result<(), speclab::Error> {
    struct Colour<'a>(&'a Rule);
    impl AtWidth for Colour<'_> {
        type Output = Result<Xyz, speclab::Error>;
        fn call<const CAP: usize>(self) -> Self::Output {
            let at = self.0.wavelengths::<CAP, f32>()?;
            Ok(at.to_xyz(at.sample(&lights::F11) * at.sample(&patches::H4)))
        }
    }
    let m = std::hint::black_box(10);
    let rule = Rule::fit(&[&lights::F11], m)?;
    let xyz = with_lanes(m, Colour(&rule))??;
    let exact = reference::xyz(&lights::F11, &patches::H4);
    assert!((xyz.y - exact.y).abs() < 0.01 * exact.y, "{xyz:?} against {exact:?}");
    assert!(with_lanes(0, Colour(&rule)).is_err());
    Ok(())
}

/// An RGB-textured scene: texels of an ACEScg texture looked up at each
/// hit, and a colour made at compile time, each a reflectance whose colour
/// under the space's illuminant is its RGB.
#[test]
fn an_rgb_textured_scene() -> Result<(), speclab::Error> {
    const RED: RgbAlbedo = match RgbTable::SRGB.const_albedo(LinearRgb::new(0.8, 0.1, 0.05)) {
        Some(a) => a,
        None => panic!("in [0, 1]"),
    };
    let acescg = RgbSpace::acescg();
    let texels = [[0.6, 0.3, 0.1], [0.1, 0.4, 0.2], [0.2, 0.2, 0.7]].map(|[r, g, b]| LinearRgb::new(r, g, b));
    for texel in texels {
        let albedo = acescg.albedo(texel)?;
        assert!(acescg.rgb_of(&albedo).distance(texel) < 0.01, "{texel:?}");
    }
    let red = RgbSpace::srgb().rgb_of(&RED);
    assert!(red.distance(LinearRgb::new(0.8, 0.1, 0.05)) < 0.01, "{red:?}");
    Ok(())
}
