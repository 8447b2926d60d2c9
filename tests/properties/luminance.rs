//! What the luminance weights of each kind of wavelengths sum to
//! (`Σⱼ w_Yⱼ`, the Y of a spectrum that is 1 everywhere), and that
//! `luminance` divides by `∫ȳ dλ` in the wavelengths' own precision: see
//! `sampling::wavelengths`.

use speclab::data::lights;
use speclab::sampling::regular::Bucketing;
use speclab::sampling::{reference, rule::Rule};
use speclab::spectrum::observer::{CMFS, Y_BAR_INTEGRAL};
use speclab::spectrum::{AssignmentObserver, Constant, DenseObserver, DenseSpectrum, Float, Observer};
use speclab::{BoxAverage, Center, FixedWavelengths, HeroSample, SampledSpectrum};

/// `Σⱼ w_Yⱼ` of fixed wavelengths.
fn y_sum<const M: usize, T: Float>(at: &FixedWavelengths<M, T>) -> f64 {
    at.weights().iter().map(|row| row[1].to_f64()).sum()
}

/// The mean of `Σⱼ w_Yⱼ` over `n` evenly spread hero samples weighted by
/// `observer` (n·K equidistant wavelengths: a midpoint sum).
fn drawn_mean(n: u32, observer: &impl Observer) -> f64 {
    let sum: f64 = (0..n)
        .map(|i| HeroSample::<4>::with_observer((f64::from(i) + 0.5) / f64::from(n), observer).unwrap())
        .map(|h| h.y(SampledSpectrum::splat(1.0)))
        .sum();
    sum / f64::from(n)
}

/// Drawn by the exact observer: on average `∫ȳ` (an evenly spread mean of
/// 65 536 wavelengths is a midpoint sum of the smooth ȳ, within 1e-8).
/// Drawn by the dense observer: on average the integral of its step
/// function, ȳ at the nearest whole nanometre (a trapezoid sum on the
/// 1 nm grid), which lies 6e-8 from `∫ȳ`.
#[test]
fn drawn_weights_average_to_the_integral_of_their_observer() {
    let exact = drawn_mean(16_384, &AssignmentObserver);
    assert!((exact / Y_BAR_INTEGRAL - 1.0).abs() < 1e-8, "{exact} vs {Y_BAR_INTEGRAL}");
    let y = DenseSpectrum::new(CMFS[1]);
    let v = y.values::<f64>();
    // Over 380–730 nm: entries 20 to 370 of the 360–830 nm grid.
    let v = &v[20..=370];
    let steps: f64 = v.iter().sum::<f64>() - 0.5 * (v[0] + v[350]);
    let dense = drawn_mean(16_384, &DenseObserver::new());
    // Equidistant points integrate a step function to within its total
    // variation times half their spacing.
    let variation: f64 = v.windows(2).map(|w| (w[1] - w[0]).abs()).sum();
    let spacing = 350.0 / (4.0 * 16_384.0);
    assert!((dense - steps).abs() <= variation * spacing / 2.0, "{dense} vs {steps}");
    assert!((steps / Y_BAR_INTEGRAL - 1.0).abs() < 1e-7, "{steps} vs {Y_BAR_INTEGRAL}");
}

/// Box buckets: exactly `∫ȳ` (their weights are ȳ's exact bucket
/// integrals). Centre buckets: the midpoint sum (M = 4: 2.3 % low;
/// M = 16: 4e-5 low; M = 32: 1e-4 high).
#[test]
fn bucket_weights_sum_to_the_integral_or_its_midpoint_sum() {
    fn check<const M: usize>(centre_error: f64) {
        let boxes = y_sum(&<BoxAverage as Bucketing<M>>::wavelengths::<f64>());
        let centres = y_sum(&<Center as Bucketing<M>>::wavelengths::<f64>());
        assert!((boxes / Y_BAR_INTEGRAL - 1.0).abs() < 1e-13, "M = {M}: {boxes}");
        let relative = centres / Y_BAR_INTEGRAL - 1.0;
        eprintln!("M = {M}: centre {relative:e}");
        assert!(relative.abs() < centre_error, "M = {M}: {relative:e}");
        let f32s = y_sum(&<BoxAverage as Bucketing<M>>::wavelengths::<f32>());
        assert!((f32s / Y_BAR_INTEGRAL - 1.0).abs() < 1e-6, "M = {M}: {f32s}");
    }
    check::<4>(3e-2);
    check::<16>(1e-4);
    check::<32>(2e-4);
}

/// A fitted rule reproduces light × reflectance: its weights times the
/// light sum to the light's Y (the rule's Y of a reflectance that is 1
/// everywhere), not to `∫ȳ`. Under F11 at M = 10 they sum to about 77 nm
/// (a regression snapshot), far from 106.86.
#[test]
fn fitted_weights_reproduce_the_light_not_the_observer() {
    let rule = Rule::fit(&[&lights::F11], 10).expect("a rule");
    let at = rule.wavelengths::<10, f64>().expect("M = 10");
    let white = reference::xyz(&lights::F11, &Constant::new(1.0)).y;
    let through = at.y(at.sample(&lights::F11));
    assert!((through / white - 1.0).abs() < 1e-3, "{through} vs {white}");
    let sum = y_sum(&at);
    eprintln!("F11, M = 10: Σ w_Y = {sum}");
    assert!((sum - 77.4).abs() < 1.0, "snapshot: {sum}");
}

/// Fixed wavelengths' `luminance` is `y` over their own white, in their
/// precision: a constant comes out as itself over box and centre
/// buckets; a domain's is `y / ∫ȳ` for drawn ones.
#[test]
fn luminance_is_y_over_the_integral_in_its_own_precision() {
    let constant = SampledSpectrum::<16, f32>::splat(2.5);
    for fixed in
        [<BoxAverage as Bucketing<16>>::wavelengths::<f32>(), <Center as Bucketing<16>>::wavelengths::<f32>()]
    {
        let l: f32 = fixed.luminance(constant);
        assert!((l - 2.5).abs() < 1e-5, "{l}");
    }
    let domain = speclab::sampling::Domain::ASSIGNMENT;
    let h = domain.hero::<4, f32>(0.3);
    let v = SampledSpectrum::new([0.2_f32, 0.4, 0.6, 0.8]);
    let expected = h.y(v) / domain.y_integral() as f32;
    assert!((domain.luminance(&h, v) - expected).abs() <= 1e-6 * expected);
    assert!((domain.y_integral() / Y_BAR_INTEGRAL - 1.0).abs() < 1e-6);
}
