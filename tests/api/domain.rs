//! A renderer's domain, named once: every normalisation path gives a
//! constant 1 the luminance 1 (hero draws in `f32` and `f64`, fixed rules,
//! buckets, the exact reference), a density reaching past its observer's
//! data is refused, a sample rebuilds from its hero wavelength, and any
//! texel colour becomes one reflectance with a report.

use speclab::color::{Clamp, LinearRgb, RgbSpace};
use speclab::sampling::pdf::{Uniform, Visible, WavelengthPdf};
use speclab::sampling::{Domain, VisibleBand, rule::Rule};
use speclab::spectrum::Float;
use speclab::spectrum::{AssignmentObserver, Constant, DenseObserver, Observer, StandardObserver};
use speclab::{BoxAverage, Center, Error, HeroSample, RegularSpectrum, SampledSpectrum, Xyz, data::lights};

/// The normalised Y of a constant 1 from `n` stratified hero samples.
fn hero_white<P: WavelengthPdf, O: Observer, T: Float>(domain: &Domain<P, O>, n: u32) -> f64 {
    let one = Constant::new(1.0);
    let sum: Xyz = (0..n)
        .map(|i| {
            let h = domain.hero::<4, T>(T::from_f64((f64::from(i) + 0.5) / f64::from(n)));
            h.to_xyz(h.sample(&one))
        })
        .sum();
    domain.normalized(sum / f64::from(n)).y
}

/// Stratified over 2²⁰ draws a hero estimate of `∫ȳ` has no noise left
/// to speak of (its error is the strata's, about 1e-8): the divisor is
/// the right one to 1e-6 for every built-in domain, in both precisions.
#[test]
fn a_constant_1_has_y_1_through_every_domain() {
    let n = 1 << 20;
    for (name, y) in [
        ("VISIBLE f64", hero_white::<_, _, f64>(&Domain::VISIBLE, n)),
        ("VISIBLE f32", hero_white::<_, _, f32>(&Domain::VISIBLE, n)),
        ("UNIFORM_VISIBLE f32", hero_white::<_, _, f32>(&Domain::UNIFORM_VISIBLE, n)),
        ("ASSIGNMENT f64", hero_white::<_, _, f64>(&Domain::ASSIGNMENT, n)),
        ("ASSIGNMENT_EXACT f64", hero_white::<_, _, f64>(&Domain::ASSIGNMENT_EXACT, n)),
    ] {
        assert!((y - 1.0).abs() < 1e-6, "{name}: {y}");
    }
    // The exact reference, over the same range with the same observer.
    for domain in [Domain::VISIBLE, Domain::new(Visible::VISIBLE, DenseObserver::CIE_1964).unwrap()] {
        let y = domain.normalized(domain.reference(&[&Constant::new(1.0)]).unwrap()).y;
        assert!((y - 1.0).abs() < 1e-12, "{y}");
    }
}

/// Fixed wavelengths and buckets normalise by their own weights: exactly.
#[test]
fn fixed_rules_and_buckets_normalise_by_their_own_weights() {
    let one = Constant::new(1.0);
    let rule = Rule::fit(&[&lights::F11], 10).unwrap();
    let at32 = rule.wavelengths::<10, f32>().unwrap();
    let at64 = rule.wavelengths::<10, f64>().unwrap();
    assert!((at32.to_normalized_xyz(at32.sample(&one)).y - 1.0).abs() < 1e-6);
    assert!((at64.to_normalized_xyz(at64.sample(&one)).y - 1.0).abs() < 1e-12);
    assert!((at32.luminance(SampledSpectrum::splat(1.0)) - 1.0).abs() < 1e-6);
    let centre = RegularSpectrum::<16, Center<VisibleBand>, f32>::center(&one);
    let boxed = RegularSpectrum::<8, BoxAverage>::box_average(&one);
    assert!((centre.to_normalized_xyz().y - 1.0).abs() < 1e-6);
    assert!((boxed.to_normalized_xyz().y - 1.0).abs() < 1e-12);
}

/// No silent zero: a density that draws where the observer has no data is
/// an error, as a domain and as a single sample.
#[test]
fn densities_past_the_observers_data_are_refused() {
    let refused = Domain::new(Visible::VISIBLE, DenseObserver::ASSIGNMENT).unwrap_err();
    assert!(matches!(refused, Error::RangeOutside { range: [360.0, 830.0], .. }), "{refused:?}");
    assert!(Domain::new(Uniform::VISIBLE, AssignmentObserver).is_err());
    assert!(Domain::new(Uniform::VISIBLE, StandardObserver::Cie1931).is_ok());
    assert!(HeroSample::<4>::from_pdf_with(0.5, &Visible::VISIBLE, &DenseObserver::ASSIGNMENT).is_err());
    assert!(HeroSample::<4>::from_pdf_with(0.5, &Visible::VISIBLE, &DenseObserver::CIE_1931).is_ok());
    // A wavelength of the renderer's own beyond the observer's data.
    let own = Domain::ASSIGNMENT.wavelengths([500.0f32, 800.0], [0.01, 0.01]);
    assert!(matches!(own, Err(Error::SampleWavelength { index: 1, .. })), "{own:?}");
}

/// A sample rebuilt from its hero wavelength is the one drawn (to the
/// rounding of inverting the density), companions and weights included.
#[test]
fn a_sample_rebuilds_from_its_hero_wavelength() {
    for i in 0..1000 {
        let u = (f64::from(i) + 0.25) / 1000.0;
        for domain in [Domain::VISIBLE, Domain::new(Visible::VISIBLE, DenseObserver::CIE_1931).unwrap()] {
            let drawn = domain.hero::<4, f64>(u);
            let rebuilt = domain.hero_at::<4, f64>(drawn.lambda()[0]).unwrap();
            for (a, b) in drawn.lambda().iter().zip(rebuilt.lambda()) {
                assert!((a - b).abs() < 1e-9, "u = {u}: {:?} vs {:?}", drawn.lambda(), rebuilt.lambda());
            }
        }
        let drawn = Domain::UNIFORM_VISIBLE.hero::<4, f32>(u as f32);
        let rebuilt = Domain::UNIFORM_VISIBLE.hero_at::<4, f32>(drawn.lambda()[0]).unwrap();
        assert!((drawn.lambda()[2] - rebuilt.lambda()[2]).abs() < 1e-3, "u = {u}");
    }
    for outside in [350.0, 831.0, f64::NAN] {
        assert!(Domain::VISIBLE.hero_at::<4, f64>(outside).is_err(), "{outside}");
    }
}

/// Any texel colour: one reflectance, and a report per component.
#[test]
fn any_texel_colour_becomes_one_reflectance() {
    let srgb = RgbSpace::srgb();
    let cases = [
        ([0.2, 0.5, 0.7], [Clamp::Inside; 3], [0.2, 0.5, 0.7]),
        ([1.5, f64::NAN, -2.0], [Clamp::Above, Clamp::NotANumber, Clamp::Below], [1.0, 0.0, 0.0]),
        (
            [f64::INFINITY, f64::NEG_INFINITY, 1.0],
            [Clamp::Above, Clamp::Below, Clamp::Inside],
            [1.0, 0.0, 1.0],
        ),
    ];
    for (rgb, report, inside) in cases {
        let (albedo, clamped) = srgb.reflectance(LinearRgb::from(rgb));
        assert_eq!(clamped, report, "{rgb:?}");
        assert_eq!(albedo, srgb.albedo(LinearRgb::from(inside)).unwrap(), "{rgb:?}");
        let erased: &RgbSpace = srgb;
        assert_eq!(erased.reflectance(LinearRgb::from(rgb)), (albedo, clamped));
    }
}
