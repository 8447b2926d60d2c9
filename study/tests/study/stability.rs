//! Each method tested exactly where it fails. Every test states what it pins
//! down and why; the figures in comments come from the test's own output
//! (`cargo test --release -p speclab-study --test study stability -- --nocapture`).

use std::num::NonZeroUsize;

use speclab::Xyz;
use speclab::data::{Light, Patch};
use speclab::sampling::buckets::BucketRule as Rule;
use speclab::sampling::reference;
use speclab::sampling::rule::Rule as Buckets;
use speclab_study::evaluate::Named;
use speclab_study::evaluate::method::{Method, derive_seed};
use speclab_study::{evaluate::perceptual, evaluate::trials, evaluate::variance};

fn nz(n: usize) -> NonZeroUsize {
    NonZeroUsize::new(n).expect("non-zero")
}

fn de00_regular(light: Light, patch: Patch, m: usize, rule: Rule) -> f64 {
    let (l, s) = (light.spectrum(), patch.spectrum());
    let estimate = Buckets::buckets(m, rule).expect("1 ≤ M ≤ 64").xyz(l, s);
    perceptual::delta_e00(estimate, reference::xyz(l, s), reference::white(l))
}

/// Spiky light, centre buckets. F11's emission lines (545 and 611 nm) are
/// hit or missed depending on where the centres fall, so the error is not
/// monotone in M. At M = 16 the centres land at 545.6 and 610.9 nm, on both
/// lines: Y is 59–71 % too high for every patch, against 24–58 % at M = 8.
/// In ΔE00 (which compresses large lightness errors) G4 is worse at M = 16
/// (8.3 vs 5.4), and every patch's ΔE00 rises again 15–19 times as M goes
/// from 8 to 45 (asserted: at least 10).
#[test]
fn centre_buckets_are_not_monotone_under_f11() {
    let l = Light::F11.spectrum();
    for patch in Patch::ALL {
        let exact = reference::xyz(l, patch.spectrum()).y;
        let y_error = |m| {
            (Buckets::buckets(m, Rule::Center).expect("M").xyz(l, patch.spectrum()).y - exact).abs() / exact
        };
        let (e8, e16) = (y_error(8), y_error(16));
        eprintln!("F11 {patch:?}: centre |ΔY|/Y at M = 8: {e8:.3}, M = 16: {e16:.3}");
        assert!(e16 > e8, "{patch:?}: M = 16 ({e16}) should be worse than M = 8 ({e8})");
        let de: Vec<f64> = (8..=45).map(|m| de00_regular(Light::F11, patch, m, Rule::Center)).collect();
        let rises = de.windows(2).filter(|w| w[1] > w[0]).count();
        eprintln!("F11 {patch:?}: centre ΔE00 rises {rises} times over M = 8..45");
        assert!(rises >= 10, "{patch:?}: ΔE00 rises only {rises} times over M = 8..45");
    }
    assert!(
        de00_regular(Light::F11, Patch::G4, 16, Rule::Center)
            > de00_regular(Light::F11, Patch::G4, 8, Rule::Center)
    );
}

/// Spiky light, box buckets. Box averages keep each line's energy, so from
/// M = 16 up the error stays bounded: at most ΔE00 5.53 (A1, M = 18),
/// under `BOX_BOUND`, while centre sampling still reaches ΔE00 ≥ 10 for
/// every patch somewhere in the same range.
#[test]
fn box_buckets_stay_bounded_under_f11() {
    const BOX_BOUND: f64 = 6.0;
    for patch in Patch::ALL {
        let worst = |rule| (16..=64).map(|m| de00_regular(Light::F11, patch, m, rule)).fold(0.0, f64::max);
        let (boxed, centre) = (worst(Rule::BoxAverage), worst(Rule::Center));
        eprintln!("F11 {patch:?}: worst ΔE00 over M = 16..64: box {boxed:.2}, centre {centre:.2}");
        assert!(boxed < BOX_BOUND, "{patch:?}: box ΔE00 {boxed}");
        assert!(centre >= 10.0, "{patch:?}: centre ΔE00 only {centre}");
    }
}

/// Tiny counts: one sample, one bucket. Every cell and method is finite.
#[test]
fn tiny_counts_are_finite() {
    for light in Light::APPENDIX {
        for patch in Patch::ALL {
            for method in Method::ALL {
                for seed in 0..20 {
                    let xyz = method.xyz(light.spectrum(), patch.spectrum(), nz(1), seed).expect("n = 1");
                    assert!(xyz.is_finite(), "{light:?} {patch:?} {method:?}: {xyz:?}");
                    assert!(xyz.to_linear_srgb().to_array().iter().all(|c| c.is_finite()));
                }
            }
        }
    }
}

/// Sample mean and standard deviation, and the standard error of s/σ from
/// the sample kurtosis κ: SE ≈ √((κ − 1) / 4T).
fn spread(values: &[f64], sigma: f64) -> (f64, f64) {
    let t = values.len() as f64;
    let mean = values.iter().sum::<f64>() / t;
    let m2 = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / t;
    let m4 = values.iter().map(|v| (v - mean).powi(4)).sum::<f64>() / t;
    let s = (m2 * t / (t - 1.0)).sqrt();
    (s / sigma, ((m4 / (m2 * m2) - 1.0) / (4.0 * t)).sqrt())
}

/// Spread matches theory: the standard deviation of 4,000 one-sample
/// estimates matches the exact `√(W·∫f² − (∫f)²)` (and its hero analogue)
/// within 10 % wherever that is at least 4 standard errors of the sample
/// standard deviation. Single random wavelengths under F11 are heavy-tailed
/// (kurtosis up to about 30: a sample either hits a line or not), so there
/// s/σ has a standard error up to 4.2 % and 10 % would be a 2.4σ test; those
/// channels are held to 4 standard errors instead. Measured: worst
/// |s/σ − 1| is 0.051 under the 10 % bound, and 0.098 (F11 × G4, X) under
/// the 4 SE bound.
#[test]
fn spread_matches_theory() {
    const TRIALS: u64 = 4000;
    let mut worst = (0.0f64, 0.0f64, 0.0f64);
    for light in Light::APPENDIX {
        for patch in Patch::ALL {
            let (l, s) = (light.spectrum(), patch.spectrum());
            for (method, var) in
                [(Method::RANDOM, variance::hero::<1>(l, s)), (Method::HERO, variance::hero::<4>(l, s))]
            {
                let runs: Vec<Xyz> =
                    (0..TRIALS).map(|t| method.xyz(l, s, nz(1), derive_seed(11, t)).expect("xyz")).collect();
                for (c, sigma2) in var.to_array().into_iter().enumerate() {
                    let values: Vec<f64> = runs.iter().map(|x| x.to_array()[c]).collect();
                    let (ratio, se) = spread(&values, sigma2.sqrt());
                    let gap = (ratio - 1.0).abs();
                    if 4.0 * se <= 0.10 {
                        worst.0 = worst.0.max(gap);
                        assert!(gap < 0.10, "{light:?} {patch:?} {method:?} ch {c}: s/σ = {ratio:.3}");
                    } else {
                        worst.1 = worst.1.max(gap);
                        worst.2 = worst.2.max(se);
                        assert!(
                            gap < 4.0 * se,
                            "{light:?} {patch:?} {method:?} ch {c}: s/σ = {ratio:.3} ± {se:.3}"
                        );
                    }
                }
            }
        }
    }
    eprintln!(
        "worst |s/σ − 1|: {:.3} (10 % bound), {:.3} (4 SE bound; largest SE {:.3})",
        worst.0, worst.1, worst.2
    );
}

/// Hero pays off: at equal wavelength evaluations (one K = 4 sample against
/// four single wavelengths) hero's exact variance is lower in every channel
/// of every cell. Under A and D65 it is 0.2–51 % of random's; under F11 the
/// rotations often land between lines and the gain shrinks to 33–99 %
/// (F11 × J4, X: 0.993, almost none).
#[test]
fn hero_beats_random_at_equal_evaluations() {
    let mut f11_worst = 0.0f64;
    for light in Light::APPENDIX {
        for patch in Patch::ALL {
            let (l, s) = (light.spectrum(), patch.spectrum());
            let (one, four) = (variance::hero::<1>(l, s).to_array(), variance::hero::<4>(l, s).to_array());
            for c in 0..3 {
                let ratio = four[c] / (one[c] / 4.0);
                assert!(ratio < 1.0, "{light:?} {patch:?} channel {c}: hero/random = {ratio}");
                if light == Light::F11 {
                    f11_worst = f11_worst.max(ratio);
                } else {
                    assert!(ratio < 0.55, "{light:?} {patch:?} channel {c}: hero/random = {ratio}");
                }
            }
        }
    }
    eprintln!("F11: largest hero/random variance ratio {f11_worst:.3}");
    assert!(f11_worst > 0.9, "F11 leaves hero little gain somewhere");
}

/// Out of gamut: G4 under every light and J4 under D65 are out of gamut in
/// the reference (Appendix 2). At n = 100 over 2,000 trials, hero's gamut
/// flag agrees with the reference in at least 80 % of trials (worst: F11 ×
/// G4, 82 %), random's in at least 65 % (worst: F11 × G4, 69 %).
#[test]
fn gamut_flag_agrees_with_reference() {
    let cells =
        [(Light::A, Patch::G4), (Light::D65, Patch::G4), (Light::F11, Patch::G4), (Light::D65, Patch::J4)];
    for (light, patch) in cells {
        let (l, s) = (light.spectrum(), patch.spectrum());
        assert!(!reference::xyz(l, s).to_linear_srgb().in_gamut(), "{light:?} {patch:?}");
        for (method, bound) in [(Method::HERO, 0.80), (Method::RANDOM, 0.65)] {
            let stats = trials::method(&Named::from(light), s, method, nz(100), nz(2000), 5).expect("study");
            let agree = 1.0 - stats.false_in_gamut.expect("reference out of gamut");
            eprintln!(
                "{light:?} {patch:?} {method:?}: gamut flag agrees in {:.1} % of trials",
                100.0 * agree
            );
            assert!(agree >= bound, "{light:?} {patch:?} {method:?}: {agree}");
        }
    }
}
