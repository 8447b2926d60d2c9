//! Nothing the public API returns from finite, validated input is NaN or
//! infinite. Lights and reflectances with values anywhere from 0 and
//! subnormals up to the validation limit go through every computation;
//! values past the limit are refused where they are written.

use proptest::prelude::*;
use rand::SeedableRng;
use rand::rngs::StdRng;
use speclab::sampling::reference;
use speclab::spectrum::validate::MAX_VALUE;
use speclab::{BoxAverage, Center, Error, RegularSpectrum, Role, TabulatedSpectrum, Xyz};

/// Light power across the scales that matter: zero, subnormal, tiny,
/// ordinary, huge up to the limit.
fn power() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(f64::MIN_POSITIVE / 4.0),
        Just(MAX_VALUE),
        1e-300..1e-290f64,
        0.0..100.0f64,
        1e90..MAX_VALUE,
    ]
}

/// `values` spread evenly over 380–730 nm.
fn spectrum(values: Vec<f64>, role: Role) -> Result<TabulatedSpectrum, Error> {
    let step = 350.0 / (values.len() - 1) as f64;
    TabulatedSpectrum::new((0..values.len()).map(|i| 380.0 + i as f64 * step).collect(), values, role)
}

fn finite(x: Xyz) -> bool {
    x.is_finite() && x.to_linear_srgb().to_array().iter().all(|c| c.is_finite())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn validated_input_gives_finite_results(
        light in prop::collection::vec(power(), 2..40),
        surface in prop::collection::vec(0.0..=1.0f64, 4..40),
        seed in any::<u64>(),
    ) {
        let l = spectrum(light, Role::Light).expect("within the limits");
        let s = spectrum(surface, Role::Reflectance).expect("within the limits");
        prop_assert!(finite(reference::xyz(&l, &s)) && finite(reference::white(&l)));
        let mut rng = StdRng::seed_from_u64(seed);
        prop_assert!(finite(crate::hero_mean::<1>(&l, &s, 3, &mut rng)));
        prop_assert!(finite(crate::hero_mean::<4>(&l, &s, 3, &mut rng)));
        let centre = RegularSpectrum::<16, Center>::center(&l) * RegularSpectrum::center(&s);
        let boxed = RegularSpectrum::<16, BoxAverage>::box_average(&l) * RegularSpectrum::box_average(&s);
        prop_assert!(finite(centre.to_xyz()) && finite(boxed.to_xyz()));
        prop_assert!(l.integral(380.0, 730.0).is_finite() && l.mean(380.0, 730.0).is_finite());
        colour(&l, &s)?;
    }

    #[test]
    fn values_past_the_limit_are_refused(value in MAX_VALUE * 1.000_001..f64::MAX) {
        let err = spectrum(vec![1.0, value, 1.0], Role::Light).unwrap_err();
        prop_assert!(err.to_string().starts_with("values[1]: expected a value of magnitude at most 1e100"), "{}", err);
    }
}

/// The colour floor's and the exact variances' numbers on the same input:
/// Lab relative to the white, ΔE00 against itself, one sample's variance.
fn colour(l: &TabulatedSpectrum, s: &TabulatedSpectrum) -> Result<(), TestCaseError> {
    use speclab::color::{difference::delta_e00, lab::lab};
    use speclab::sampling::variance;
    let (exact, white) = (reference::xyz(l, s), reference::white(l));
    let lab = lab(exact, white);
    prop_assert!(lab.iter().all(|c| c.is_finite()), "{lab:?}");
    prop_assert!(delta_e00(exact, exact, white) == 0.0 || !white.to_array().iter().any(|&w| w > 0.0));
    prop_assert!(variance::hero::<1>(l, s).is_finite() && variance::hero::<4>(l, s).is_finite());
    Ok(())
}

/// The case the property above found: a light rising from subnormal power
/// makes the white's Z 1.3e-310 while one box bucket puts 1e99 there; the
/// ratio overflowed and CIEDE2000 returned NaN.
#[test]
fn nearly_zero_white_component() {
    use speclab::color::difference as perceptual;
    use speclab::sampling::buckets::BucketRule;
    use speclab::sampling::rule::Rule;
    let l = spectrum(vec![0.0, 0.0, 0.0, 5.562_684_646_268_003e-309, 1e100], Role::Light).expect("valid");
    let s = spectrum(vec![0.0, 0.0, 0.0, 0.516_878_024_304_750_5], Role::Reflectance).expect("valid");
    let (exact, white) = (reference::xyz(&l, &s), reference::white(&l));
    assert!(white.z > 0.0 && white.z < 1e-300, "{white:?}");
    let boxed = Rule::buckets(1, BucketRule::BoxAverage).expect("M = 1").xyz(&l, &s);
    assert!(boxed.z / white.z == f64::INFINITY, "the ratio overflows");
    let de = perceptual::delta_e00(boxed, exact, white);
    assert!(de.is_finite() && de > 50.0, "finite and far off: {de}");
}
