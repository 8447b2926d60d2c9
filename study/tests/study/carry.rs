//! The ways of carrying colour along a path (`speclab_study::carry`) are what
//! they say: each method against the per-sample calls it stands for, and a
//! one-bounce path against the exact colour.

use speclab::color::LinearRgb;
use speclab::color::RgbSpace;
use speclab::data::{lights, patches};
use speclab::sampling::pdf::{LightPdf, Uniform};
use speclab::sampling::{HeroSample, reference, rule::Rule};
use speclab::spectrum::observer::Y_BAR_INTEGRAL;
use speclab::spectrum::{AssignmentObserver, DenseObserver, SampledSpectrum};
use speclab::{TabulatedSpectrum, Xyz};
use speclab_study::carry::{Carry, Fitted, Hero, Rgb};

fn close(a: Xyz, b: Xyz, tolerance: f64) -> bool {
    (a - b).to_array().iter().all(|d| d.abs() <= tolerance * b.y.abs().max(1e-300))
}

/// Hero: the path's wavelengths are the pdf's hero sample, a vertex is the
/// spectra sampled there, the luminance is `y` over ∫ȳ and the roulette's
/// survival the largest value.
#[test]
fn hero_is_the_per_sample_calls() {
    let f11 = LightPdf::light(&lights::F11).expect("a bright light");
    let lights = vec![&lights::F11, &lights::A];
    let hero = Hero::new(lights, vec![&patches::G4, &patches::A1], AssignmentObserver, &f11)
        .expect("within the observer");
    for u in [0.0, 0.3, 0.77] {
        let path = hero.path(u);
        assert_eq!(path, HeroSample::<4>::from_pdf_with(u, &f11, &AssignmentObserver).unwrap());
        assert_eq!(hero.one(), SampledSpectrum::splat(1.0));
        let beta = hero.albedo(&path, 1) * hero.scale(hero.one(), 0.5);
        assert_eq!(beta, path.sample(&patches::A1) * 0.5);
        assert_eq!(hero.emitted(&path, 1, beta), path.to_xyz(beta * path.sample(&lights::A)));
        assert_ne!(hero.emitted(&path, 0, beta), hero.emitted(&path, 1, beta));
        assert_eq!(hero.luminance(&path, beta), path.y(beta) * (1.0 / Y_BAR_INTEGRAL));
        // Russian roulette's survival: the largest value over the wavelengths.
        assert_eq!(hero.max_component(&path, beta), beta.max_value());
        assert!(beta.max_value() > 0.0 && beta.max_value() < 0.5);
    }
    // In f32, the same wavelengths to rounding.
    let single = Hero::new(vec![&lights::F11], vec![&patches::G4], DenseObserver::new(), Uniform::ASSIGNMENT)
        .expect("within the observer")
        .precision::<f32>();
    let path = single.path(0.25);
    assert_eq!(
        path,
        HeroSample::<4, f32>::from_pdf_with(0.25, &Uniform::ASSIGNMENT, &DenseObserver::new()).unwrap()
    );
    assert_eq!(single.one(), SampledSpectrum::<4, f32>::splat(1.0));
}

/// A white path's luminance averages 1: for uniform hero wavelengths,
/// `y(1)/∫ȳ` is an unbiased estimate of 1 (the mean over 4,096 jittered
/// paths within 1e-3).
#[test]
fn a_white_path_has_luminance_one_on_average() {
    let hero = Hero::new(vec![&lights::D65], vec![&patches::A1], AssignmentObserver, Uniform::ASSIGNMENT)
        .expect("within the observer");
    let n = 4096;
    let mean =
        (0..n).map(|i| hero.luminance(&hero.path((i as f64 + 0.5) / n as f64), hero.one())).sum::<f64>()
            / n as f64;
    assert!((mean - 1.0).abs() < 1e-3, "{mean}");
}

/// Fitted: every surface at the rules' wavelengths once, each light's
/// emission in its own rule's weights, lanes beyond M weighing nothing.
#[test]
fn fitted_is_the_rules_weights() {
    let scene: [&TabulatedSpectrum; 2] = [&lights::F11, &lights::A];
    let rules = Rule::fit_each(&scene, 10).expect("bright lights");
    let surfaces = [&patches::G4, &patches::J4];
    let twelve = Fitted::<12>::new(&rules, &scene, &surfaces).expect("fits in 12 lanes");
    let sixteen = Fitted::<16>::new(&rules, &scene, &surfaces).expect("fits in 16 lanes");
    assert!(Fitted::<8>::new(&rules, &scene, &surfaces).is_err(), "10 wavelengths in 8 lanes");
    assert!(Fitted::<12>::new(&[], &scene, &surfaces).is_err(), "no rule");
    let at = rules[1].wavelengths::<12, f64>().expect("12 lanes");
    assert_eq!(twelve.albedo(&(), 1), at.sample(&patches::J4));
    assert_eq!(twelve.one(), SampledSpectrum::splat(1.0));
    let beta = twelve.scale(twelve.albedo(&(), 0), 2.0);
    assert_eq!(beta, at.sample(&patches::G4) * 2.0);
    let a = twelve.emitted(&(), 1, beta);
    assert!(close(a, at.to_xyz(beta * at.sample(&lights::A)), 1e-12), "{a:?}");
    let sixteen_beta = sixteen.scale(sixteen.albedo(&(), 0), 2.0);
    assert!(close(sixteen.emitted(&(), 1, sixteen_beta), a, 1e-12), "padding lanes weigh nothing");
    let exact = reference::xyz(&lights::F11, &patches::G4);
    assert!(close(twelve.emitted(&(), 0, twelve.albedo(&(), 0)), exact, 0.01));
    let y = rules[0].wavelengths::<12, f64>().expect("12 lanes").y_weights();
    assert_eq!(twelve.luminance(&(), beta), beta.dot(&y) * (1.0 / Y_BAR_INTEGRAL));
    assert_ne!(twelve.luminance(&(), beta), twelve.luminance(&(), twelve.one()));
    assert_eq!(twelve.max_component(&(), beta), beta.max_value());
    assert!(beta.max_value() > 0.0 && beta.max_value() < 2.0);
}

/// Rgb: lights as their white's colour, surfaces as their albedo's, a
/// vertex a product of triples, luminance the triple's Y.
#[test]
fn rgb_is_triples() {
    let rgb = Rgb::new(&[&lights::D65, &lights::A], &[&patches::G4, &patches::A1]);
    let space = RgbSpace::srgb();
    assert_eq!(rgb.lights[1], space.rgb(reference::white(&lights::A)).map(|c| c.max(0.0)));
    assert_eq!(rgb.surfaces[0], space.rgb_of(&patches::G4).map(|c| c.clamp(0.0, 1.0)));
    assert_eq!(rgb.one(), LinearRgb::splat(1.0));
    let beta = rgb.scale(rgb.albedo(&(), 0), 0.5);
    assert_eq!(beta, rgb.surfaces[0] * 0.5);
    assert_eq!(rgb.emitted(&(), 1, beta), space.xyz(beta * rgb.lights[1]));
    assert!((rgb.luminance(&(), rgb.one()) - 1.0).abs() < 1e-12);
    assert_eq!(rgb.luminance(&(), beta), space.xyz(beta).y);
    assert_eq!(rgb.max_component(&(), beta), beta.max_component());
    assert!(beta.max_component() > 0.0 && beta.max_component() < 0.5);
}

/// Indices past the scene give nothing (no panic), and a fitted way needs
/// one rule per light, all at the same wavelengths.
#[test]
fn indices_past_the_scene_give_nothing() {
    let (light, surface) = (&lights::F11, &patches::G4);
    let hero = Hero::new(vec![light], vec![surface], DenseObserver::new(), Uniform::ASSIGNMENT)
        .expect("within the observer");
    let path = hero.path(0.3);
    assert_eq!(hero.emitted(&path, 1, hero.one()), Xyz::ZERO);
    assert_eq!(hero.albedo(&path, 7), SampledSpectrum::zero());
    let rule = Rule::fit_each(&[light], 10).expect("fits");
    let fitted = Fitted::<12>::new(&rule, &[light], &[surface]).expect("one rule per light");
    assert_eq!(fitted.emitted(&(), 2, fitted.one()), Xyz::ZERO);
    assert_eq!(fitted.albedo(&(), 1), SampledSpectrum::zero());
    assert!(fitted.emitted(&(), 0, fitted.one()).y > 0.0);
    assert!(Fitted::<12>::new(&rule, &[light, &lights::A], &[surface]).is_err());
    let other = Rule::fit(&[&lights::A], 10).expect("fits");
    let mixed = [rule[0].clone(), other];
    assert_ne!(mixed[0].lambda(), mixed[1].lambda());
    let err = Fitted::<12>::new(&mixed, &[light, &lights::A], &[surface]).err();
    assert!(matches!(err, Some(speclab_study::StudyError::RulesDiffer { index: 1 })), "{err:?}");
    let rgb = Rgb::new(&[light], &[surface]);
    assert_eq!(rgb.emitted(&(), 3, rgb.one()), Xyz::ZERO);
    assert_eq!(rgb.albedo(&(), 3), LinearRgb::default());
}
