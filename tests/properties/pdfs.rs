//! Wavelength pdfs: each integrates to 1, `sample` inverts the CDF, no
//! wavelength is drawn where the density is zero, a dark light is a clear
//! error, and the spread of estimates under a pdf matches the exact variance.

use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};
use speclab::data::Light;
use speclab::io::Load;
use speclab::sampling::pdf::{LightPdf, Uniform, Visible, WavelengthPdf};
use speclab::spectrum::AssignmentObserver;
use speclab::{Error, HeroSample, Role, TabulatedSpectrum};

/// Every density, named, for the built-in lights.
fn pdfs() -> Vec<(String, Box<dyn WavelengthPdf>)> {
    let mut out: Vec<(String, Box<dyn WavelengthPdf>)> = vec![
        ("uniform".into(), Box::new(Uniform::ASSIGNMENT)),
        ("visible".into(), Box::new(Visible::ASSIGNMENT)),
    ];
    for light in Light::APPENDIX {
        let l = light.spectrum();
        out.push((format!("light {light:?}"), Box::new(LightPdf::light(l).expect("bright"))));
        out.push((format!("balanced {light:?}"), Box::new(LightPdf::balanced(l).expect("bright"))));
        out.push((format!("spectrum {light:?}"), Box::new(LightPdf::spectrum(l).expect("bright"))));
    }
    let g4 = speclab::data::patches::G4.clone();
    out.push(("spectrum G4".into(), Box::new(LightPdf::spectrum(&g4).expect("a reflectance"))));
    out
}

/// A spectrum's own pdf is proportional to it: `pdf(λ)/S(λ)` is one
/// constant over the range (for a table, a patch and a blackbody, which is
/// tabulated through its values at the ends of each piece of at most 5 nm:
/// there the ratio holds at those ends).
#[test]
fn a_spectrums_pdf_is_proportional_to_it() {
    let sun = speclab::spectrum::Blackbody::new(5778.0).expect("a temperature");
    let spectra: [(&dyn speclab::Spectrum, &[f64]); 3] = [
        (&speclab::data::lights::F11, &[400.0, 545.0, 611.0, 707.5]),
        (&speclab::data::patches::J4, &[380.0, 455.0, 600.0, 730.0]),
        (&sun, &[380.0, 450.0, 600.0, 730.0]),
    ];
    for (s, at) in spectra {
        let p = LightPdf::spectrum(&s).expect("bright");
        let ratio = p.pdf(at[0]) / s.eval(at[0]);
        for &l in at {
            assert!((p.pdf(l) / s.eval(l) - ratio).abs() < 1e-9 * ratio, "{l} nm");
        }
    }
}

/// `∫ pdf` over 380–730 nm by 16-point Gauss–Legendre on 0.25 nm pieces
/// (exact for the polynomial pieces, and far finer than needed for sech²).
fn integral(p: &dyn WavelengthPdf) -> f64 {
    const NODES: [(f64, f64); 8] = [
        (0.095_012_509_837_637_44, 0.189_450_610_455_068_5),
        (0.281_603_550_779_258_9, 0.182_603_415_044_923_6),
        (0.458_016_777_657_227_4, 0.169_156_519_395_002_5),
        (0.617_876_244_402_643_8, 0.149_595_988_816_576_7),
        (0.755_404_408_355_003, 0.124_628_971_255_533_9),
        (0.865_631_202_387_831_7, 0.095_158_511_682_492_78),
        (0.944_575_023_073_232_6, 0.062_253_523_938_647_89),
        (0.989_400_934_991_649_9, 0.027_152_459_411_754_09),
    ];
    let (mut sum, h) = (0.0, 0.25);
    for i in 0..1400 {
        let mid = 380.0 + (f64::from(i) + 0.5) * h;
        for (x, w) in NODES {
            sum += w * 0.5 * h * (p.pdf(mid - 0.5 * h * x) + p.pdf(mid + 0.5 * h * x));
        }
    }
    sum
}

#[test]
fn each_integrates_to_one() {
    for (name, p) in pdfs() {
        let total = integral(p.as_ref());
        assert!((total - 1.0).abs() < 1e-12, "{name}: ∫pdf = {total}");
        assert_eq!(p.cdf(380.0), Some(0.0), "{name}");
        assert!((p.cdf(730.0).unwrap() - 1.0).abs() < 1e-15, "{name}");
        assert_eq!((p.pdf(379.0), p.pdf(731.0), p.pdf(f64::NAN)), (0.0, 0.0, 0.0), "{name}");
    }
}

#[test]
fn sample_inverts_the_cdf() {
    let mut rng = StdRng::seed_from_u64(9);
    for (name, p) in pdfs() {
        let mut worst = 0.0f64;
        for i in 0..20_000 {
            let u = if i < 3 { [0.0, 0.5, 1.0 - 1e-16][i] } else { rng.random::<f64>() };
            let lambda = p.sample(u);
            assert!((380.0..=730.0).contains(&lambda), "{name}: u = {u} gave {lambda}");
            worst = worst.max((p.cdf(lambda).unwrap() - u).abs());
        }
        assert!(worst < 1e-12, "{name}: |CDF(sample(u)) − u| up to {worst:e}");
    }
}

/// A lamp dark below 500 nm: its pdfs never draw there, every estimate is
/// finite, and no wavelength carries an infinite weight.
#[test]
fn zero_regions_are_never_drawn() {
    let lamp = Load::new(Role::Light)
        .text("380 0\n450 0\n500 0\n520 3\n600 1\n650 0\n700 2\n730 2", "lamp.txt")
        .expect("valid");
    let mut rng = StdRng::seed_from_u64(3);
    for p in [LightPdf::light(&lamp).expect("bright"), LightPdf::balanced(&lamp).expect("bright")] {
        for _ in 0..20_000 {
            let h = HeroSample::<4>::from_pdf_with(
                rng.random(),
                &p,
                &speclab::spectrum::DenseObserver::ASSIGNMENT,
            )
            .unwrap();
            for (&lambda, w) in h.lambda().iter().zip(h.inv_pdf()) {
                assert!(lambda > 500.0 && p.pdf(lambda) > 0.0, "drew {lambda} nm, density {}", p.pdf(lambda));
                assert!(w.is_finite() && w > 0.0);
            }
            let xyz = h.to_xyz(lamp.sample(&h) * speclab::data::patches::G4.sample(&h));
            assert!(xyz.is_finite());
        }
    }
}

#[test]
fn dark_lights_are_errors() {
    let dark = TabulatedSpectrum::new(vec![380.0, 730.0], vec![0.0, 0.0], Role::Light).expect("valid");
    // Power only beyond 730 nm, none within the range (a file like this is
    // refused when loaded: `tests/api/input_errors.rs`).
    let beyond =
        TabulatedSpectrum::new(vec![380.0, 730.0, 760.0, 780.0], vec![0.0, 0.0, 5.0, 5.0], Role::Light)
            .expect("valid samples");
    for light in [&dark, &beyond] {
        for result in [LightPdf::light(light), LightPdf::balanced(light)] {
            let err = result.expect_err("no power where the observer sees");
            assert!(matches!(err, Error::NoMass));
            assert_eq!(
                err.to_string(),
                "expected a light or density with finite positive mass where the observer sees (380-730 nm), found none"
            );
        }
    }
}

/// Standard error of the sample standard deviation relative to σ, from the
/// sample kurtosis: √((κ − 1)/4T).
fn spread(values: &[f64], sigma: f64) -> (f64, f64) {
    let t = values.len() as f64;
    let mean = values.iter().sum::<f64>() / t;
    let m2 = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / t;
    let m4 = values.iter().map(|v| (v - mean).powi(4)).sum::<f64>() / t;
    ((m2 * t / (t - 1.0)).sqrt() / sigma, ((m4 / (m2 * m2) - 1.0) / (4.0 * t)).sqrt())
}

/// Under non-uniform pdfs, the standard deviation of 4,000 one-sample
/// estimates matches the exact variance within 10 %, or within 4 standard
/// errors of the sample standard deviation where heavy tails make that
/// error large (as `study/tests/study/stability.rs` does for uniform sampling).
#[test]
fn spread_matches_exact_variance() {
    use speclab::data::Patch;
    use speclab::sampling::variance;
    const TRIALS: usize = 4000;
    let mut rng = StdRng::seed_from_u64(17);
    let mut worst = 0.0f64;
    for light in Light::APPENDIX {
        let l = light.spectrum();
        let (visible, following) = (Visible::ASSIGNMENT, LightPdf::light(l).expect("bright"));
        for patch in [Patch::G4, Patch::A1] {
            let s = patch.spectrum();
            let cases: [(&str, &dyn WavelengthPdf, usize); 4] = [
                ("visible", &visible, 1),
                ("visible", &visible, 4),
                ("light", &following, 1),
                ("light", &following, 4),
            ];
            for (name, p, k) in cases {
                let exact = if k == 1 {
                    variance::hero_with::<1>(l, s, p)
                } else {
                    variance::hero_with::<4>(l, s, p)
                };
                let runs: Vec<speclab::Xyz> = (0..TRIALS)
                    .map(|_| {
                        let u: f64 = rng.random();
                        if k == 1 {
                            let h = HeroSample::<1>::from_pdf_with(u, p, &AssignmentObserver).unwrap();
                            h.to_xyz(l.sample(&h) * s.sample(&h))
                        } else {
                            let h = HeroSample::<4>::from_pdf_with(u, p, &AssignmentObserver).unwrap();
                            h.to_xyz(l.sample(&h) * s.sample(&h))
                        }
                    })
                    .collect();
                for (c, var) in exact.to_array().into_iter().enumerate() {
                    let values: Vec<f64> = runs.iter().map(|x| x.to_array()[c]).collect();
                    let (ratio, se) = spread(&values, var.sqrt());
                    let bound = if 4.0 * se <= 0.10 { 0.10 } else { 4.0 * se };
                    worst = worst.max((ratio - 1.0).abs());
                    assert!(
                        (ratio - 1.0).abs() < bound,
                        "{light:?} {patch:?} {name} K={k} ch {c}: s/σ = {ratio:.3} ± {se:.3}"
                    );
                }
            }
        }
    }
    eprintln!("worst |s/σ − 1| under visible and light pdfs: {worst:.3}");
}

/// The exact variance under the uniform pdf is the closed form of uniform
/// sampling, `W·∫f² − (∫f)²` for K = 1, computed here independently.
#[test]
fn uniform_variance_is_the_closed_form() {
    use speclab::sampling::reference;
    use speclab::sampling::variance;
    use speclab::spectrum::observer::xyz_bar;
    let (l, s) = (&speclab::data::lights::D65, &speclab::data::patches::F4);
    // ∫ f² by a fine midpoint sum (f² is smooth between 5 nm knots).
    let h = 0.001;
    let second: f64 = (0..350_000)
        .map(|i| 380.0 + (f64::from(i) + 0.5) * h)
        .map(|x| (xyz_bar(x)[1] * l.eval(x) * s.eval(x)).powi(2) * h)
        .sum();
    let mean = reference::xyz(l, s).y;
    let closed = 350.0 * second - mean * mean;
    let exact = variance::hero::<1>(l, s).y;
    assert!((exact - closed).abs() < 1e-6 * closed, "{exact} vs {closed}");
}
