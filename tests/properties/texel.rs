//! Texels: a texture's colours converted once into 12 bytes each. Their
//! rounding against the spectra they came from, on 4,000 random colours of
//! each built-in space (albedos, and unbounded colours up to 8): the
//! colour under the space's illuminant, the reflectance over 360–830 nm,
//! the `f32` lanes against the `f64` value. Regression snapshot; prints
//! the figures (`cargo test --test properties texel -- --nocapture`).

use rand::{RngExt, SeedableRng, rngs::StdRng};
use speclab::color::difference::delta_e00;
use speclab::color::{LinearRgb, RgbSpace, RgbTexel};
use speclab::{HeroSample, Spectrum};
use static_assertions::const_assert_eq;

const_assert_eq!(std::mem::size_of::<RgbTexel>(), 12);

/// The rounding of a texel moves its colour by ΔE00 ≤ 0.025 (0.002 on
/// average; measured 0.0074–0.0207 and 0.0011–0.0018) and its reflectance
/// by ≤ 0.01 (measured at most 0.006); unbounded colours keep their scale
/// to `f32`.
#[test]
fn texels_stay_close_to_their_spectra() {
    let mut rng = StdRng::seed_from_u64(11);
    for space in RgbSpace::all() {
        let (mut worst, mut mean, mut reflectance) = (0f64, 0f64, 0f64);
        let count = 4000;
        for _ in 0..count {
            let rgb = LinearRgb::new(rng.random(), rng.random(), rng.random());
            let albedo = space.albedo(rgb).unwrap();
            let texel = RgbTexel::from(albedo);
            let de = delta_e00(space.albedo_xyz(&texel), space.albedo_xyz(&albedo), space.white());
            (worst, mean) = (worst.max(de), mean + de / f64::from(count));
            for lambda in (360..=830).step_by(2) {
                let l = f64::from(lambda);
                reflectance = reflectance.max((texel.eval(l) - albedo.eval(l)).abs());
            }
            let bright = space.unbounded(rgb * 8.0);
            let texel = RgbTexel::from(bright);
            assert_eq!(texel.scale(), f64::from(bright.scale() as f32));
            assert!((texel.eval(555.0) - bright.eval(555.0)).abs() <= 0.15 * bright.scale(), "{rgb:?}");
        }
        println!(
            "{}: texel ΔE00 mean {mean:.4}, worst {worst:.4}; reflectance {reflectance:.4}",
            space.name()
        );
        assert!(
            worst < 0.025 && mean < 0.002 && reflectance < 0.01,
            "{}: {worst} {mean} {reflectance}",
            space.name()
        );
    }
}

/// Black and white stay exact; a light's texel is its tint; the `f32`
/// lanes of a hero sample follow the `f64` value.
#[test]
fn texels_keep_black_white_and_lanes() {
    let space = RgbSpace::srgb();
    for (grey, value) in [(0.0, 0.0), (1.0, 1.0)] {
        let texel = RgbTexel::from(space.albedo(LinearRgb::splat(grey)).unwrap());
        assert_eq!((texel.eval(400.0), texel.eval(700.0)), (value, value));
    }
    let light = space.light(LinearRgb::new(1.0, 0.5, 0.2));
    let texel = RgbTexel::from(light);
    assert_eq!(texel.scale(), f64::from(light.scale() as f32));
    let tint = space.unbounded(LinearRgb::new(1.0, 0.5, 0.2));
    assert_eq!(texel.polynomial(), RgbTexel::from(tint).polynomial());
    for i in 0..100 {
        let h = HeroSample::<4, f32>::new((i as f32 + 0.5) / 100.0);
        for (v, l) in h.sample(&texel).values.iter().zip(h.lambda()) {
            let exact = texel.eval(f64::from(*l));
            assert!((f64::from(*v) - exact).abs() <= 1e-5 * exact.max(1e-3), "{l}: {v} against {exact}");
        }
    }
}
