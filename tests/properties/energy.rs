//! Property tests: energy conservation for random reflectances in [0, 1]
//! and random non-negative lights.
//!
//! Where two exact integrals over different piece partitions are compared,
//! `ROUNDING` allows for f64 rounding only (1e-12 relative).

use proptest::prelude::*;
use speclab::sampling::reference;
use speclab::{BoxAverage, HeroSample, RegularSpectrum, Role, TabulatedSpectrum};

const ROUNDING: f64 = 1e-12;

/// A spectrum with `values` spread evenly over 380–730 nm.
fn spectrum(values: Vec<f64>, role: Role) -> TabulatedSpectrum {
    let step = 350.0 / (values.len() - 1) as f64;
    let lambda = (0..values.len()).map(|i| 380.0 + i as f64 * step).collect();
    TabulatedSpectrum::new(lambda, values, role).expect("valid samples")
}

fn reflectance() -> impl Strategy<Value = TabulatedSpectrum> {
    prop::collection::vec(0.0..=1.0f64, 4..40).prop_map(|v| spectrum(v, Role::Reflectance))
}

fn light() -> impl Strategy<Value = TabulatedSpectrum> {
    prop::collection::vec(prop_oneof![Just(0.0), 0.0..100.0f64], 2..80).prop_map(|v| spectrum(v, Role::Light))
}

proptest! {
    #[test]
    fn product_never_exceeds_light(l in light(), r in reflectance(), lambda in 370.0..740.0f64) {
        let rv = r.eval(lambda);
        prop_assert!((0.0..=1.0).contains(&rv), "reflectance {rv} at {lambda}");
        let h = HeroSample::<4>::new((lambda - 370.0) / 370.0);
        let (ls, product) = (l.sample(&h), l.sample(&h) * r.sample(&h));
        for j in 0..4 {
            prop_assert!(product.values[j] <= ls.values[j]);
        }
    }

    #[test]
    fn reference_y_at_most_white(l in light(), r in reflectance()) {
        let (y, white) = (reference::xyz(&l, &r).y, reference::white(&l).y);
        prop_assert!(y >= 0.0 && y <= white * (1.0 + ROUNDING), "{y} > {white}");
    }

    #[test]
    fn box_buckets_y_at_most_white(l in light(), r in reflectance()) {
        let lb = RegularSpectrum::<16, BoxAverage>::box_average(&l);
        let y = (lb * RegularSpectrum::box_average(&r)).to_xyz().y;
        let white = lb.to_xyz().y;
        prop_assert!(y <= white * (1.0 + ROUNDING), "{y} > {white}");
    }

    #[test]
    fn every_hero_sample_y_at_most_white(l in light(), r in reflectance(), u in 0.0..1.0f64) {
        let h = HeroSample::<4>::new(u);
        let y = h.to_xyz(l.sample(&h) * r.sample(&h)).y;
        let white = h.to_xyz(l.sample(&h)).y;
        prop_assert!(y >= 0.0 && y <= white, "{y} > {white}");
    }

    #[test]
    fn box_average_preserves_integral(l in light(), r in reflectance()) {
        for s in [&l, &r] {
            let buckets = RegularSpectrum::<16, BoxAverage>::box_average(s);
            let sum: f64 = buckets.values().iter().sum::<f64>() * 350.0 / 16.0;
            let exact = s.integral(380.0, 730.0);
            prop_assert!((sum - exact).abs() <= 1e-9 * exact.abs().max(1e-300), "{sum} vs {exact}");
        }
    }
}

#[test]
fn cubic_overshoot_is_clamped_to_one() {
    // The cubic through 0, 1, 1, 0 peaks at 1.125 between the middle samples.
    let r =
        TabulatedSpectrum::new(vec![400.0, 410.0, 420.0, 430.0], vec![0.0, 1.0, 1.0, 0.0], Role::Reflectance)
            .expect("valid");
    // Unclamped, by Lagrange at t = 1.5 steps: (−1·0 + 9·1 + 9·1 − 1·0)/16 = 9/8.
    assert_eq!(r.eval(415.0), 1.0);
    // The clamp is part of the exact integral too: the middle segment is
    // above 1 throughout, so its integral is exactly 10 nm × 1.
    assert!(r.integral(410.0, 420.0) == 10.0);
    assert!(r.eval(411.0) == 1.0 && r.eval(405.0) < 1.0);
}
