//! Paths deeper than one bounce: light × surface^depth. The exact
//! reference agrees with brute-force quadrature; every method estimates the
//! same product (hero without bias, buckets as the product of bucket
//! values, fitted rules at their wavelengths).

use std::num::NonZeroUsize;

use speclab::TabulatedSpectrum;
use speclab::data::{Light, Patch, lights, patches};
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::rule::Rule;
use speclab::spectrum::observer::xyz_bar;
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::scene::{Depth, MAX_DEPTH, Named};
use speclab_study::{StudyError, evaluate::trials};

/// `∫ L·Rᵈ·c̄` by 10-point Gauss–Legendre on every 0.05 nm: no knowledge of
/// the pieces, so kinks (clamps) cost it a little, far below 1e-9.
fn brute_force(light: &TabulatedSpectrum, surface: &TabulatedSpectrum, depth: usize) -> [f64; 3] {
    const NODES: [(f64, f64); 5] = [
        (0.148_874_338_981_631_2, 0.295_524_224_714_752_9),
        (0.433_395_394_129_247_2, 0.269_266_719_309_996_4),
        (0.679_409_568_299_024_4, 0.219_086_362_515_982),
        (0.865_063_366_688_984_5, 0.149_451_349_150_580_6),
        (0.973_906_528_517_171_7, 0.066_671_344_308_688_1),
    ];
    let (pieces, h) = (7000, 0.05);
    let mut sum = [0.0; 3];
    for i in 0..pieces {
        let mid = 380.0 + (f64::from(i) + 0.5) * h;
        for &(x, w) in &NODES {
            for lambda in [mid - 0.5 * h * x, mid + 0.5 * h * x] {
                let v = light.eval(lambda) * surface.eval(lambda).powi(depth as i32) * w * 0.5 * h;
                let c = xyz_bar(lambda);
                (0..3).for_each(|k| sum[k] += c[k] * v);
            }
        }
    }
    sum
}

#[test]
fn depth_references_agree_with_brute_force() {
    let mut worst = 0.0f64;
    for light in Light::APPENDIX.map(|l| l.spectrum()) {
        for surface in [Patch::G4, Patch::J4, Patch::A1].map(|p| p.spectrum()) {
            for d in 1..=MAX_DEPTH {
                let exact = Depth::new(d).unwrap().exact(light, surface).to_array();
                let brute = brute_force(light, surface, d);
                for (e, b) in exact.iter().zip(brute) {
                    let rel = (e - b).abs() / b.abs().max(1e-300);
                    worst = worst.max(rel);
                    assert!(rel < 1e-9, "depth {d}: {e} against {b}");
                }
            }
        }
    }
    eprintln!("worst relative difference {worst:e}");
}

/// Hero at depth 3 is unbiased: over 400 trials of n = 32, the mean XYZ is
/// within 4 standard errors of the exact product's.
#[test]
fn hero_at_depth_is_unbiased() {
    let (t, n) = (NonZeroUsize::new(400).unwrap(), NonZeroUsize::new(32).unwrap());
    let depth = Depth::new(3).unwrap();
    for (l, s) in [(&lights::F11, &patches::G4), (&lights::A, &patches::J4)] {
        let light = Named::new("light", l.clone());
        let stats = trials::method_at_depth(&light, s, depth, Method::HERO, n, t, 9).unwrap();
        let se = stats.sd.to_array().map(|sd| sd / (t.get() as f64).sqrt());
        for (bias, se) in stats.bias.to_array().iter().zip(se) {
            assert!(bias.abs() <= 4.0 * se + 1e-12, "bias {bias} against se {se}");
        }
        assert!(stats.sd.y > 0.0);
    }
}

/// Buckets at depth are the product of the bucketed spectra, as a renderer
/// that buckets each spectrum once computes it; the fitted rule evaluates
/// the product at its wavelengths; both are estimates of the same exact
/// product, and depth 1 is the assignment's light × surface.
#[test]
fn fixed_methods_at_depth() {
    let (l, s) = (&lights::D65, &patches::F4);
    let light = Named::from(Light::D65);
    let m = NonZeroUsize::new(16).unwrap();
    for d in 1..=MAX_DEPTH {
        let depth = Depth::new(d).unwrap();
        let boxed = Method::BOX.prepare(&light).unwrap().at_depth(depth).xyz(s, m, 0).unwrap();
        let b = Rule::buckets(16, BucketRule::BoxAverage).unwrap();
        let (lv, sv) = (b.values(l), b.values(s));
        let by_hand: Vec<f64> = lv.iter().zip(&sv).map(|(a, r)| a * r.powi(d as i32)).collect();
        let want = b.xyz_of_factors(&[&by_hand]);
        assert!((boxed - want).to_array().iter().all(|e| e.abs() <= 1e-12 * want.y), "depth {d}");
        let fitted = Method::FITTED.prepare(&light).unwrap().at_depth(depth).xyz(s, m, 0).unwrap();
        let exact = depth.exact(l, s);
        assert!((fitted.y - exact.y).abs() < 0.01 * exact.y, "depth {d}: {fitted:?} against {exact:?}");
    }
    let one = Method::Reference.prepare(&light).unwrap().at_depth(Depth::ONE).xyz(s, m, 0).unwrap();
    assert_eq!(one, light.exact(s));
    let integrated = speclab::sampling::reference::xyz(l, s); // piece by piece: the same to rounding
    assert!((one - integrated).to_array().iter().all(|e| e.abs() <= 1e-12 * integrated.y), "{one:?}");
    // Darker with every bounce.
    let y: Vec<f64> = (1..=MAX_DEPTH).map(|d| Depth::new(d).unwrap().exact(l, s).y).collect();
    assert!(y.windows(2).all(|w| w[1] < w[0]), "{y:?}");
}

#[test]
fn depths_outside_one_to_four_are_errors() {
    for bad in ["0", "5", "-1", "two", ""] {
        let err = bad.parse::<Depth>().unwrap_err();
        assert!(matches!(err, StudyError::Depth { .. }), "{bad}");
        assert_eq!(err.to_string(), format!("expected a path depth from 1 to 4, found {bad:?}"));
    }
    assert_eq!("4".parse::<Depth>().unwrap().get(), 4);
    assert_eq!(Depth::ALL.map(Depth::get), [1, 2, 3, 4]);
    assert!(Depth::new(0).is_err() && Depth::new(5).is_err());
    assert_eq!(Depth::default(), Depth::ONE);
    assert_eq!(Depth::new(3).unwrap().to_string(), "3");
}
