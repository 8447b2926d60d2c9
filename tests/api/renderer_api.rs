//! The per-sample API as a path tracer uses it: sampled-spectrum
//! arithmetic, wavelengths and pdfs from the renderer's own sampler, pbrt's
//! `TerminateSecondary`, and luminance alone.
//!
//! Statistical checks follow `study/tests/study/unbiased.rs`: `TRIALS` independent
//! estimates of `N` samples each per cell, and the mean within `Z_MAX`
//! standard errors of the exact reference on every channel of every cell
//! (54 checks; a correct estimator fails one at 4.5σ with probability
//! below 1e-3; the seeds are fixed).

use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};
use speclab::data::{Light, Patch};
use speclab::sampling::reference;
use speclab::spectrum::DenseSpectrum;
use speclab::{Error, HeroSample, LAMBDA_MIN, LAMBDA_WIDTH, SampledSpectrum, TabulatedSpectrum, Xyz, data};

const TRIALS: usize = 2000;
const N: usize = 8;
const Z_MAX: f64 = 4.5;

/// Every cell's mean of `TRIALS` estimates, each the mean of `N` draws of
/// `sample`, lies within `Z_MAX` standard errors of the reference.
fn unbiased(name: &str, sample: impl Fn(&TabulatedSpectrum, &TabulatedSpectrum, &mut StdRng) -> Xyz) {
    unbiased_for(name, reference::xyz, sample);
}

/// [`unbiased`] against the exact value `exact` gives for each cell.
fn unbiased_for(
    name: &str,
    exact: impl Fn(&TabulatedSpectrum, &TabulatedSpectrum) -> Xyz,
    sample: impl Fn(&TabulatedSpectrum, &TabulatedSpectrum, &mut StdRng) -> Xyz,
) {
    let mut worst = 0.0f64;
    for (c, (light, patch)) in Light::APPENDIX.iter().flat_map(|l| Patch::ALL.map(|p| (*l, p))).enumerate() {
        let (l, s) = (light.spectrum(), patch.spectrum());
        let exact = exact(l, s).to_array();
        let mut rng = StdRng::seed_from_u64(0x7E57 + c as u64);
        let estimates: Vec<[f64; 3]> = (0..TRIALS)
            .map(|_| ((0..N).map(|_| sample(l, s, &mut rng)).sum::<Xyz>() / N as f64).to_array())
            .collect();
        for ch in 0..3 {
            let mean = estimates.iter().map(|e| e[ch]).sum::<f64>() / TRIALS as f64;
            let var = estimates.iter().map(|e| (e[ch] - mean).powi(2)).sum::<f64>() / (TRIALS - 1) as f64;
            let z = (mean - exact[ch]) / (var / TRIALS as f64).sqrt();
            worst = worst.max(z.abs());
            assert!(z.abs() < Z_MAX, "{name}: {light:?} {patch:?} channel {ch}: z = {z:.2}");
        }
    }
    eprintln!("{name}: largest |z| over 54 checks: {worst:.2}");
}

/// Hero samples in f32 are unbiased like f64 ones: weighted by the exact
/// observer over the exact spectra (evaluated in f64, rounded), against the
/// reference; and as the README's f32 loop draws them (`new`: the dense
/// observer) over f32 dense tables, against the exact integral of what
/// they look up, every table a step at the nearest whole nanometre.
#[test]
fn f32_hero_is_unbiased() {
    unbiased("f32 hero, exact spectra", |l, s, rng| {
        let h = HeroSample::<4, f32>::exact(rng.random::<f32>());
        h.to_xyz(l.sample(&h) * s.sample(&h))
    });
    let dense = |t: &TabulatedSpectrum| DenseSpectrum::new(t);
    unbiased_for(
        "f32 hero, f32 dense tables",
        |l, s| steps_integral(&dense(l), &dense(s)),
        |l, s, rng| {
            let h = HeroSample::<4, f32>::new(rng.random::<f32>());
            h.to_xyz(dense(l).sample(&h) * dense(s).sample(&h))
        },
    );
}

/// The exact XYZ of light × surface × observer where all three are the f32
/// steps a dense lookup reads: `Σᵢ Lᵢ·Rᵢ·c̄ᵢ·wᵢ` over the whole nanometres,
/// each step 1 nm wide inside 380–730 nm and half that at the two ends.
fn steps_integral(light: &DenseSpectrum, surface: &DenseSpectrum) -> Xyz {
    let cmf = speclab::spectrum::observer::CMFS.map(DenseSpectrum::new);
    let (l, s) = (light.values::<f32>(), surface.values::<f32>());
    let mut sum = [0.0; 3];
    for i in 0..l.len() {
        let w = if i == 0 || i == l.len() - 1 { 0.5 } else { 1.0 };
        let v = f64::from(l[i]) * f64::from(s[i]) * w;
        for (c, total) in sum.iter_mut().enumerate() {
            *total += f64::from(cmf[c].values::<f32>()[i]) * v;
        }
    }
    Xyz::from(sum)
}

/// The same draw in f32 and in f64 gives the same estimate to f32's
/// rounding: of the values, and of the wavelengths (an f32 wavelength near
/// 700 nm is within 3e-5 nm, where F11 changes by up to 0.17 of itself per
/// nm: 5e-6 relative).
#[test]
fn f32_and_f64_agree() {
    for u in [0.0_f32, 0.123, 0.5, 0.987] {
        let (single, double) = (HeroSample::<4, f32>::new(u), HeroSample::<4, f64>::new(f64::from(u)));
        let (l, s) = (&data::lights::F11, &data::patches::G4);
        let (a, b) = (
            single.to_xyz(l.sample(&single) * s.sample(&single)),
            double.to_xyz(l.sample(&double) * s.sample(&double)),
        );
        for (x, y) in a.to_array().iter().zip(b.to_array()) {
            assert!((x - y).abs() <= 2e-5 * y.abs(), "u = {u}: {a:?} against {b:?}");
        }
    }
}

/// Keeping only the hero (dispersion) stays unbiased: its pdf is divided
/// by K, so its lone term carries the weight of all four.
#[test]
fn terminate_secondary_is_unbiased() {
    unbiased("terminated hero", |l, s, rng| {
        let mut h = HeroSample::<4>::exact(rng.random());
        h.terminate_secondary();
        h.to_xyz(l.sample(&h) * s.sample(&h))
    });
}

#[test]
fn terminate_secondary_keeps_the_hero_alone() {
    let mut h = HeroSample::<4>::new(0.1);
    assert!(!h.secondary_terminated());
    h.terminate_secondary();
    assert!(h.secondary_terminated());
    assert_eq!(h.pdf(), [1.0 / (4.0 * LAMBDA_WIDTH), 0.0, 0.0, 0.0]);
    assert_eq!(h.inv_pdf(), [4.0 * LAMBDA_WIDTH, 0.0, 0.0, 0.0]);
    let once = h;
    h.terminate_secondary();
    assert_eq!(h, once, "terminating twice changes nothing");
    let v = data::lights::D65.sample(&h) * data::patches::A1.sample(&h);
    let alone = HeroSample::<1>::new(0.1);
    let single = alone.to_xyz(data::lights::D65.sample(&alone) * data::patches::A1.sample(&alone));
    let terminated = h.to_xyz(v);
    assert!(
        (terminated - single).to_array().iter().all(|d| d.abs() < 1e-12 * single.y),
        "the hero alone is a K = 1 sample"
    );
    assert!(HeroSample::<1>::new(0.3).secondary_terminated(), "K = 1 has no secondaries");
}

/// An observer of the caller's own that leaves the fourth column at 0
/// (not the documented 1) still gives the sample its pdf, and
/// `terminate_secondary` still works.
#[test]
fn an_observer_of_ones_own_keeps_the_pdf() {
    use speclab::spectrum::{AssignmentObserver, Float, Observer, Wavelengths};
    struct ZeroFourth;
    impl Observer for ZeroFourth {
        fn xyz_bar_at<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> [[T; 4]; K] {
            AssignmentObserver.xyz_bar_at(at).map(|[x, y, z, _]| [x, y, z, T::ZERO])
        }
        fn data_range(&self) -> speclab::spectrum::WavelengthRange {
            AssignmentObserver.data_range()
        }
        fn y_integral(&self, range: speclab::spectrum::WavelengthRange) -> f64 {
            AssignmentObserver.y_integral(range)
        }
    }
    let mut own = HeroSample::<4>::with_observer(0.1, &ZeroFourth).unwrap();
    let exact = HeroSample::<4>::exact(0.1);
    assert_eq!(own.pdf(), exact.pdf());
    let v = data::lights::D65.sample(&own);
    assert_eq!(own.to_xyz(v), exact.to_xyz(v));
    own.terminate_secondary();
    assert!(own.secondary_terminated());
    assert_eq!(own.pdf(), [1.0 / (4.0 * LAMBDA_WIDTH), 0.0, 0.0, 0.0]);
}

/// A renderer's own wavelength distribution, p(λ) ∝ 1 + t over the range
/// (t = (λ − 380)/W), drawn by inverting its CDF and rotated in primary
/// sample space, is unbiased through `from_wavelengths`.
#[test]
fn own_distribution_through_from_wavelengths_is_unbiased() {
    let lambda_of = |u: f64| LAMBDA_MIN + LAMBDA_WIDTH * ((1.0 + 3.0 * u).sqrt() - 1.0);
    let pdf_of = |lambda: f64| (1.0 + (lambda - LAMBDA_MIN) / LAMBDA_WIDTH) / (1.5 * LAMBDA_WIDTH);
    unbiased("ramp pdf", |l, s, rng| {
        let u: f64 = rng.random();
        let lambda: [f64; 4] = std::array::from_fn(|j| lambda_of((u + j as f64 / 4.0).fract()));
        let h = HeroSample::from_wavelengths_with(
            lambda,
            lambda.map(pdf_of),
            &speclab::spectrum::DenseObserver::ASSIGNMENT,
        )
        .expect("valid");
        h.to_xyz(l.sample(&h) * s.sample(&h))
    });
}

#[test]
fn from_wavelengths_rejects_what_cannot_be_used() {
    assert!(
        HeroSample::from_wavelengths_with(
            [500.0, 600.0],
            [0.01, 0.0],
            &speclab::spectrum::DenseObserver::ASSIGNMENT
        )
        .is_ok(),
        "pdf 0 marks a dropped wavelength"
    );
    for (lambda, pdf) in [(f64::NAN, 0.01), (500.0, -0.01), (500.0, f64::INFINITY), (f64::INFINITY, 0.01)] {
        let err = HeroSample::from_wavelengths_with(
            [400.0, lambda],
            [0.01, pdf],
            &speclab::spectrum::DenseObserver::ASSIGNMENT,
        )
        .unwrap_err();
        assert!(matches!(err, Error::SampleWavelength { index: 1, .. }), "{err:?}");
    }
    let dropped = HeroSample::from_wavelengths_with(
        [500.0, 600.0],
        [0.0, 0.0],
        &speclab::spectrum::DenseObserver::ASSIGNMENT,
    )
    .expect("valid");
    assert_eq!(dropped.to_xyz(SampledSpectrum::splat(1.0)), Xyz::ZERO);
}

/// `y()` gives `to_xyz`'s Y and the dot product with `y_weights`, to
/// rounding, at any wavelengths and pdfs: uniform, light-following,
/// terminated.
#[test]
fn luminance_alone_equals_to_xyz_y() {
    let pdf = speclab::sampling::pdf::LightPdf::light(&data::lights::F11).expect("bright");
    for i in 0..1000 {
        let u = f64::from(i) / 1000.0;
        let mut drawn =
            HeroSample::<4>::from_pdf_with(u, &pdf, &speclab::spectrum::DenseObserver::ASSIGNMENT).unwrap();
        if i % 3 == 0 {
            drawn.terminate_secondary();
        }
        for h in [HeroSample::<4>::new(u), drawn] {
            let v = data::lights::F11.sample(&h) * data::patches::H4.sample(&h);
            let (y, xyz) = (h.y(v), h.to_xyz(v).y);
            assert!((y - xyz).abs() <= 1e-12 * xyz.abs(), "{h:?}: {y} vs {xyz}");
            let dotted = v.dot(&h.y_weights());
            assert!((dotted - y).abs() <= 1e-12 * y.abs(), "{h:?}: {dotted} vs {y}");
        }
    }
    // Normalised by ∫ȳ, a constant spectrum's luminance is the constant,
    // on average (the exact observer's weights average to ∫ȳ).
    let n = 4096;
    let domain = speclab::sampling::Domain::ASSIGNMENT_EXACT;
    let mean: f64 = (0..n)
        .map(|i| {
            let h = domain.hero::<4, f64>((f64::from(i) + 0.5) / f64::from(n));
            domain.luminance(&h, SampledSpectrum::splat(2.5))
        })
        .sum::<f64>()
        / f64::from(n);
    assert!((mean - 2.5).abs() < 1e-6, "{mean}");
}

#[test]
fn sampled_spectrum_arithmetic() {
    type S = SampledSpectrum<4>;
    let (a, b) = (S::new([1.0, 2.0, 3.0, 4.0]), S::new([2.0, 0.0, -1.0, 0.5]));
    assert_eq!(a + b, S::new([3.0, 2.0, 2.0, 4.5]));
    assert_eq!(a - b, S::new([-1.0, 2.0, 4.0, 3.5]));
    assert_eq!(a * b, S::new([2.0, 0.0, -3.0, 2.0]));
    assert_eq!(a / S::splat(2.0), S::new([0.5, 1.0, 1.5, 2.0]));
    assert_eq!(a + 1.0, S::new([2.0, 3.0, 4.0, 5.0]));
    assert_eq!(a - 1.0, S::new([0.0, 1.0, 2.0, 3.0]));
    assert_eq!(a * 2.0, 2.0 * a);
    assert_eq!(a / 2.0, S::new([0.5, 1.0, 1.5, 2.0]));
    assert_eq!(-a, S::new([-1.0, -2.0, -3.0, -4.0]));
    let mut c = a;
    c += b;
    c -= b;
    c *= b;
    c /= 2.0;
    c += 1.0;
    c -= 0.5;
    c *= 2.0;
    c /= S::splat(4.0);
    assert_eq!(c, S::new([0.75, 0.25, -0.5, 0.75]));
    assert_eq!(a.average(), 2.5);
    assert_eq!(a.dot(&b), 2.0 + 0.0 - 3.0 + 2.0);
    assert_eq!(b.max_value(), 2.0);
    assert_eq!((a[0], a[3]), (1.0, 4.0));
    c[1] = 9.0;
    assert_eq!(c[1], 9.0);
    assert!(S::zero().is_black() && S::default().is_black() && !b.is_black());
    assert_eq!(S::default(), S::splat(0.0));
}

/// `safe_div` gives 0 wherever the divisor is 0 (so 0/0 is 0); plain `/`
/// follows IEEE.
#[test]
fn safe_division() {
    let n = SampledSpectrum::new([0.0_f64, 1.0, 6.0]);
    let d = SampledSpectrum::new([0.0, 0.0, 3.0]);
    assert_eq!(n.safe_div(d), SampledSpectrum::new([0.0, 0.0, 2.0]));
    let plain = n / d;
    assert!(plain[0].is_nan() && plain[1].is_infinite());
}

/// The pdf given is the pdf kept (up to the rounding of a reciprocal), and
/// a pdf whose reciprocal overflows is refused like ∞.
#[test]
fn pdf_round_trip() {
    let pdf = [0.004_f64, 1e-3, 0.0, 0.0123];
    let h = HeroSample::from_wavelengths_with(
        [400.0, 500.0, 600.0, 700.0],
        pdf,
        &speclab::spectrum::DenseObserver::ASSIGNMENT,
    )
    .expect("valid");
    for (got, want) in h.pdf().iter().zip(pdf) {
        assert!((got - want).abs() <= 1e-15 * want, "{got} vs {want}");
    }
    assert_eq!(h.inv_pdf()[2], 0.0);
    assert!(
        HeroSample::from_wavelengths_with([400.0], [1e-310], &speclab::spectrum::DenseObserver::ASSIGNMENT)
            .is_err()
    );
    assert_eq!(HeroSample::<2>::new(0.25).pdf(), [1.0 / LAMBDA_WIDTH; 2]);
}

/// A path's exact colour (`reference::ExactPaths`: one Gauss rule per
/// piece, the scene's spectra at its nodes) against brute force: Simpson's
/// rule every 0.0005 nm over 380–730 nm of the path's spectrum, within
/// 1e-9 relative on every channel, for paths of one to four surfaces
/// (tabulated patches and an RGB texture's sigmoid) under F11 and A.
#[test]
fn exact_paths_are_brute_force_quadrature() {
    use speclab::LinearRgb;
    use speclab::color::RgbAlbedo;
    use speclab::sampling::reference::ExactPaths;
    use speclab::spectrum::Spectrum;
    let texel = RgbAlbedo::new(LinearRgb::new(0.7, 0.3, 0.1)).expect("an albedo");
    let spectra: [&dyn Spectrum; 6] = [
        &data::lights::F11,
        &data::lights::A,
        &data::patches::G4,
        &data::patches::A1,
        &data::patches::J4,
        &texel,
    ];
    let scene = ExactPaths::new(&spectra, 4);
    let paths: [(usize, &[usize], &[f64]); 4] = [
        (0, &[2], &[0.0, 1.0]),
        (0, &[3, 5], &[1.0, 0.3, 0.7]),
        (1, &[5, 4, 2], &[0.0, 0.5, 0.25, 2.0]),
        (0, &[2, 2, 3, 5], &[0.1, 0.2, 0.3, 0.4, 0.5]),
    ];
    for (light, surfaces, c) in paths {
        let exact = scene.xyz(light, surfaces, c).expect("in the scene").to_array();
        let f = |lambda: f64| {
            let mut t = c[surfaces.len()];
            for j in (0..surfaces.len()).rev() {
                t = c[j] + spectra[surfaces[j]].eval(lambda) * t;
            }
            let cmf = speclab::spectrum::observer::xyz_bar(lambda);
            cmf.map(|v| v * spectra[light].eval(lambda) * t)
        };
        let (n, h) = (700_000, 350.0 / 700_000.0);
        let mut brute = [0.0; 3];
        for i in 0..=n {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            let v = f(380.0 + f64::from(i) * h);
            (0..3).for_each(|ch| brute[ch] += w * v[ch] * h / 3.0);
        }
        for ch in 0..3 {
            assert!(
                (exact[ch] - brute[ch]).abs() <= 1e-9 * brute[ch].abs(),
                "{surfaces:?} {ch}: {exact:?} {brute:?}"
            );
        }
    }
    assert!(scene.xyz(6, &[], &[1.0]).is_err() && scene.xyz(0, &[9], &[1.0, 1.0]).is_err());
    // At least 70 pieces (F11's 5 nm lines over 380–730 nm), each with a
    // rule exact for degree 1 + 4·3 + 3 = 16 (the light, four cubics, the
    // observer): 9 nodes or more per piece.
    assert!(scene.nodes() >= 70 * 9, "{} nodes", scene.nodes());
}

/// A light folded into the weights (`FixedWavelengths::emission`) gives
/// what multiplying by the light and converting gives, for hero samples
/// and for a fitted rule's wavelengths, in f64 and f32.
#[test]
fn emission_is_the_light_folded_into_the_weights() {
    use speclab::sampling::rule::Rule;
    let (light, surface) = (&data::lights::F11, &data::patches::G4);
    for u in [0.0, 0.3, 0.77] {
        let h = HeroSample::<4>::new(u);
        let beta = surface.sample(&h) * 0.7;
        let (folded, direct) = (h.emission(light).xyz(beta), h.to_xyz(beta * light.sample(&h)));
        assert!(
            (folded - direct).to_array().iter().all(|d| d.abs() <= 1e-12 * direct.y),
            "{folded:?} {direct:?}"
        );
        assert!(folded.y > 0.0);
    }
    let at = Rule::fit(&[light], 10).expect("a rule").wavelengths::<10, f32>().expect("M = 10");
    let beta = surface.sample(&at);
    let (folded, direct) = (at.emission(light).xyz(beta), at.to_xyz(beta * light.sample(&at)));
    assert!((folded - direct).to_array().iter().all(|d| d.abs() <= 1e-5 * direct.y), "{folded:?} {direct:?}");
    assert!((direct.y - reference::xyz(light, surface).y).abs() < 0.02 * direct.y);
}
