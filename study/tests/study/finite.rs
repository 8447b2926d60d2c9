//! The study's numbers from finite, validated input are never NaN or
//! infinite: normalisation, white balance and the trials of every method,
//! on lights and reflectances with values from 0 and subnormals up to the
//! validation limit (the core's own numbers are checked in its
//! `tests/properties/finite.rs`).

use std::num::NonZeroUsize;

use proptest::prelude::*;
use speclab::sampling::reference;
use speclab::spectrum::validate::MAX_VALUE;
use speclab::{Error, Role, TabulatedSpectrum, Xyz};
use speclab_study::evaluate::Named;
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::trials;
use speclab_study::evaluate::viewing::{Normalization, Viewing};

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
    fn validated_input_gives_finite_study_numbers(
        light in prop::collection::vec(power(), 2..40),
        surface in prop::collection::vec(0.0..=1.0f64, 4..40),
        seed in any::<u64>(),
    ) {
        let l = spectrum(light, Role::Light).expect("within the limits");
        let s = spectrum(surface, Role::Reflectance).expect("within the limits");
        study(&l, &s, seed)?;
    }
}

/// The study's numbers: normalisation, white balance, trials.
fn study(l: &TabulatedSpectrum, s: &TabulatedSpectrum, seed: u64) -> Result<(), TestCaseError> {
    let (exact, white) = (reference::xyz(l, s), reference::white(l));
    for mode in Normalization::ALL {
        prop_assert!(!mode.factor(l).is_nan(), "{mode:?}");
        if let Ok(scaled) = mode.apply(l) {
            prop_assert!(finite(reference::white(&scaled)));
        }
    }
    let viewing = Viewing { white_balance: true, ..Viewing::default() };
    prop_assert!(finite(viewing.adapt(exact, l)) && finite(viewing.white(l)));
    let n = NonZeroUsize::new(2).expect("non-zero");
    let light = Named::new("light", l.clone());
    let dark = !white.to_array().iter().any(|&w| w > 0.0);
    for method in Method::ALL {
        let stats = match trials::method(&light, s, method, n, NonZeroUsize::new(5).expect("non-zero"), seed)
        {
            // A rule cannot be fitted to a light the observer does not see:
            // a clear error, which is what the fitted method must give.
            Err(e) if method == Method::FITTED && dark => {
                prop_assert!(e.to_string().contains("finite positive mass where the observer sees"), "{e}");
                continue;
            }
            other => other.map_err(|e| TestCaseError::fail(e.to_string()))?,
        };
        prop_assert!(stats.rms_de00.is_finite() && stats.p95_de00.is_finite(), "{method:?}: {stats:?}");
        prop_assert!(stats.bias.is_finite() && stats.sd.is_finite(), "{method:?}: {stats:?}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any hero width and any number of points: a width outside
    /// 1..=`MAX_WIDTH` is an error, never a panic; every strata gives `n`
    /// numbers in [0, 1) for any width.
    #[test]
    fn widths_and_strata_take_anything(n in 0..50usize, k in 0..6usize, seed in any::<u64>()) {
        use rand::SeedableRng;
        use speclab::data::{lights, patches};
        use speclab_study::sampling::estimate::{MAX_WIDTH, estimate_width};
        use speclab_study::sampling::strata::Strata;
        let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
        for width in [0, 1, 4, 5, MAX_WIDTH, MAX_WIDTH + 1, usize::MAX] {
            let (pdf, strata) = (speclab::sampling::pdf::Uniform::ASSIGNMENT, Strata::None);
            let result = estimate_width(width, &lights::A, &patches::J4, NonZeroUsize::MIN, &pdf, strata, &mut rng);
            prop_assert_eq!(result.is_ok(), (1..=MAX_WIDTH).contains(&width));
        }
        for strata in Strata::ALL {
            let points: Vec<f64> = strata.points(n, k, &mut rng).collect();
            prop_assert_eq!(points.len(), n);
            prop_assert!(points.iter().all(|u| (0.0..1.0).contains(u)));
        }
    }
}
