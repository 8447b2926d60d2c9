//! No input through the public API panics: every call returns a value or an
//! error, as documented. Arbitrary text goes to every parser, arbitrary
//! floats (NaN, ±∞, negative, huge) to every constructor and evaluator.

use std::num::NonZeroUsize;

use proptest::prelude::*;
use rand::SeedableRng;
use speclab::io::{Format, Load};
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::reference;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::{BoxAverage, HeroSample, Interpolation, RegularSpectrum, Role, TabulatedSpectrum, data};
use speclab_tables::{brace, columns, json, read};

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(-0.0),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        any::<f64>(),
        -1e3..1e3f64,
        350.0..800.0f64,
    ]
}

fn role() -> impl Strategy<Value = Role> {
    prop_oneof![Just(Role::Light), Just(Role::Reflectance), Just(Role::Observer)]
}

/// Text that is often close to valid: pieces of the three grammars.
fn spectrum_text() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        Just("{".to_string()),
        Just("}".to_string()),
        Just(", ".to_string()),
        Just("\n".to_string()),
        Just("\"wavelengths\": [".to_string()),
        Just("\"values\": [".to_string()),
        Just("]".to_string()),
        Just("# c\n".to_string()),
        Just("\t".to_string()),
        "[0-9.eE+-]{1,8}",
        any::<f64>().prop_map(|x| x.to_string()),
        "\\PC{0,3}",
    ];
    prop::collection::vec(piece, 0..40).prop_map(|v| v.concat())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn parsers_never_panic(text in prop_oneof![spectrum_text(), "\\PC*", any::<String>()], role in role()) {
        let _ = brace::parse_samples(&text, "<string>");
        let _ = brace::parse_rows::<3>(&text, "<string>", 3);
        let _ = columns::parse_columns(&text, "<string>");
        let _ = json::parse_json(&text, "<string>");
        let _ = read::samples(&text, "<string>", role, role.interpolation(), None);
        for format in [Format::Brace, Format::Json, Format::Columns] {
            let _ = Load::new(role).with_format(format).text(&text, "<string>");
        }
        if let Ok(s) = Load::new(role).text(&text, "<string>") {
            // Whatever loads evaluates and integrates without panicking.
            prop_assert!(s.eval(555.0).is_finite());
            let _ = s.integral(380.0, 730.0);
        }
    }

    #[test]
    fn constructors_take_any_floats(
        lambda in prop::collection::vec(any_f64(), 0..12),
        values in prop::collection::vec(any_f64(), 0..12),
        role in role(),
        cubic in any::<bool>(),
    ) {
        let interpolation = if cubic { Interpolation::Cubic } else { Interpolation::Linear };
        if let Ok(s) = TabulatedSpectrum::with_interpolation(lambda.clone(), values.clone(), role, interpolation) {
            for x in [f64::NAN, f64::NEG_INFINITY, 0.0, 380.0, 555.5, 730.0, 1e300] {
                let _ = s.eval(x);
            }
            let _ = RegularSpectrum::<7, BoxAverage>::box_average(&s).to_xyz();
            let _ = RegularSpectrum::<7>::center(&s).to_xyz();
            let _ = reference::xyz(&data::lights::D65, &s);
            let _ = s.mean(555.0, 555.0);
        }
        let mut pdf = values.clone();
        pdf.resize(4, 1.0);
        let mut wavelengths = lambda.clone();
        wavelengths.resize(4, 500.0);
        let four = |v: &[f64]| [v[0], v[1], v[2], v[3]];
        if let Ok(h) = HeroSample::from_wavelengths_with(four(&wavelengths), four(&pdf), &speclab::spectrum::DenseObserver::ASSIGNMENT) {
            prop_assert!(h.to_xyz(data::lights::D65.sample(&h)).y.is_finite());
        }
    }

    #[test]
    fn evaluators_take_any_floats(x in any_f64(), u in any_f64()) {
        for s in [&data::lights::F11, &data::patches::G4, &data::cie1931::Z_BAR] {
            let v = s.eval(x);
            prop_assert!(v.is_finite() && v >= 0.0);
        }
        // Documented: only the fractional part of u counts; non-finite u acts as 0.
        let h = HeroSample::<4>::new(u);
        prop_assert!(h.lambda().iter().all(|l| (380.0..=730.0).contains(l)), "{:?}", h.lambda());
        prop_assert!(h.to_xyz(data::lights::F11.sample(&h) * data::patches::A1.sample(&h)).is_finite());
        let mut terminated = h;
        terminated.terminate_secondary();
        prop_assert!(terminated.to_xyz(data::lights::F11.sample(&h) * data::patches::A1.sample(&h)).is_finite());
    }

    #[test]
    fn bucket_counts_and_huge_values(m in any::<usize>(), scale in any_f64()) {
        let m = NonZeroUsize::new(m).unwrap_or(NonZeroUsize::MIN);
        for rule in BucketRule::ALL {
            let result = Rule::buckets(m.get(), rule).map(|b| b.xyz(&data::lights::A, &data::patches::E2));
            prop_assert_eq!(result.is_ok(), m.get() <= MAX_M);
            if let Ok(xyz) = result {
                prop_assert!(xyz.is_finite());
            }
        }
        if let Ok(light) = TabulatedSpectrum::new(vec![380.0, 730.0], vec![scale, scale], Role::Light) {
            let _ = RegularSpectrum::<3>::center(&light).to_xyz();
            let _ = crate::hero_mean::<2>(&light, &data::patches::A1, 1, &mut rand::rngs::StdRng::seed_from_u64(1));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Every pdf maps any number to a wavelength in 380–730 nm, and gives a
    /// finite, non-negative density and a CDF in [0, 1] at any wavelength.
    #[test]
    fn pdfs_take_any_numbers(u in any_f64(), lambda in any_f64(), n in 0..50usize) {
        use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
        let binned = speclab::sampling::binned::BinnedPdf::new(&LightPdf::light(&data::lights::F11).expect("bright"), 1 + n).expect("bins");
        let pdfs: [&dyn WavelengthPdf; 5] = [&Uniform::ASSIGNMENT, &Visible::ASSIGNMENT, &LightPdf::light(&data::lights::F11).expect("bright"), &LightPdf::balanced(&data::lights::A).expect("bright"), &binned];
        for p in pdfs {
            let l = p.sample(u);
            prop_assert!((380.0..=730.0).contains(&l), "{}", l);
            let (d, c) = (p.pdf(lambda), p.cdf(lambda).expect("the library's pdfs know their CDF"));
            prop_assert!(d.is_finite() && d >= 0.0 && (0.0..=1.0).contains(&c), "{} {}", d, c);
            let h = HeroSample::<4>::from_pdf_with(u, p, &speclab::spectrum::DenseObserver::ASSIGNMENT).expect("within 380–780 nm");
            prop_assert!(h.to_xyz(data::lights::D65.sample(&HeroSample::<4>::new(u))).is_finite());
        }
    }

    /// Preparing a light for any grid, and converting any slice, returns a
    /// value or an error.
    #[test]
    fn prepared_light_takes_anything(
        grid in prop::collection::vec(any_f64(), 0..12),
        samples in prop::collection::vec(any_f64(), 0..80),
        outputs in 0..4usize,
        cubic in any::<bool>(),
    ) {
        let interpolation = if cubic { Interpolation::Cubic } else { Interpolation::Linear };
        for light in [&data::lights::A, &data::lights::F11] {
            if let Ok(p) = speclab::sampling::PreparedLight::for_grid(light, &grid, interpolation) {
                let mut out = vec![speclab::Xyz::ZERO; outputs];
                if p.batch(&samples, &mut out).is_ok() {
                    prop_assert!(out.iter().all(|x| x.is_finite()));
                }
                let _ = p.xyz_samples(&samples);
                prop_assert!(p.xyz(&data::patches::G4).is_finite());
            }
        }
    }
}

#[test]
fn hero_u_outside_unit_interval_is_documented() {
    assert_eq!(HeroSample::<4>::new(1.25), HeroSample::<4>::new(0.25));
    assert_eq!(HeroSample::<4>::new(-0.25), HeroSample::<4>::new(0.75));
    assert_eq!(HeroSample::<4>::new(f64::NAN), HeroSample::<4>::new(0.0));
    assert_eq!(HeroSample::<4>::new(f64::INFINITY), HeroSample::<4>::new(0.0));
    assert_eq!(HeroSample::<1>::new(1.0), HeroSample::<1>::new(0.0));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Counts, depths, indices and roles a caller passes: a value or an
    /// error, never a panic (a power past the limit, an exact scene of any
    /// depth, a path naming spectra outside the scene, a conductor of any
    /// two tables).
    #[test]
    fn counts_indices_and_roles_take_anything(
        depth in any::<usize>(),
        light in any::<usize>(),
        surfaces in prop::collection::vec(any::<usize>(), 0..6),
        coefficients in prop::collection::vec(-2.0..2.0f64, 0..6),
        eta in 0..4usize,
        k in 0..4usize,
    ) {
        use speclab::spectrum::{Conductor, MAX_POWER, Product, Spectrum};
        let power = Product::power(&data::patches::G4, depth);
        prop_assert_eq!(power.is_ok(), depth <= MAX_POWER);
        let spectra: [&dyn Spectrum; 3] = [&data::lights::F11, &data::patches::G4, &data::patches::A1];
        let scene = reference::ExactPaths::new(&spectra, depth % 8);
        let path = scene.xyz(light % 5, &surfaces.iter().map(|s| s % 5).collect::<Vec<_>>(), &coefficients);
        let inside = light % 5 < 3 && surfaces.iter().all(|s| s % 5 < 3);
        prop_assert_eq!(path.is_ok(), inside);
        prop_assert!(path.map_or(true, |x| x.is_finite()));
        let au = &data::conductors::AU;
        let tables = [au.eta(), au.k(), &data::lights::A, &data::patches::G4];
        let made = Conductor::new(tables[eta], tables[k]);
        prop_assert_eq!(made.is_ok(), eta == 0 && k == 1);
    }
}
