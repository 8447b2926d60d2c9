use super::*;
use crate::data::lights;
use crate::sampling::pdf::{LightPdf, Uniform, Visible};
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, observer};

/// A "density" whose `sample` always answers `at`.
struct Stuck(f64);

impl WavelengthPdf for Stuck {
    fn sample(&self, _u: f64) -> f64 {
        self.0
    }
    fn pdf(&self, _lambda: f64) -> f64 {
        0.0
    }
    fn support(&self) -> WavelengthRange {
        WavelengthRange::ASSIGNMENT
    }
}

#[test]
fn bin_counts_and_degenerate_densities_are_errors() {
    assert!(matches!(
        BinnedPdf::new(&Uniform::ASSIGNMENT, 0),
        Err(Error::Count { found: 0, max: MAX_BINS, .. })
    ));
    assert!(matches!(BinnedPdf::new(&Uniform::ASSIGNMENT, MAX_BINS + 1), Err(Error::Count { .. })));
    assert_eq!(BinnedPdf::new(&Uniform::ASSIGNMENT, MAX_BINS).map(|p| p.len()).ok(), Some(MAX_BINS));
    let one = BinnedPdf::new(&Uniform::ASSIGNMENT, 1).unwrap();
    assert!(!one.is_empty() && (one.pdf(400.0) * LAMBDA_WIDTH - 1.0).abs() < 1e-12);
    assert!(matches!(BinnedPdf::new(&Stuck(500.0), 4), Err(Error::NoMass)));
    assert!(matches!(BinnedPdf::new(&Stuck(f64::NAN), 1), Err(Error::NoMass)));
}

/// The cuts are the source's quantiles: its CDF there is `i/bins`.
#[test]
fn knots_are_the_sources_quantiles() {
    let source = LightPdf::light(&lights::F11).unwrap();
    let binned = BinnedPdf::new(&source, 256).unwrap();
    assert_eq!(binned.knots().len(), 257);
    for (i, &knot) in binned.knots().iter().enumerate().take(256).skip(1) {
        let (got, want) = (source.cdf(knot).unwrap(), i as f64 / 256.0);
        assert!((got - want).abs() < 1e-12, "knot {i} at {knot} nm: {got}");
        assert!((binned.cdf(knot).unwrap() - want).abs() < 1e-12);
    }
    assert_eq!(
        (binned.cdf(379.0), binned.cdf(f64::NAN), binned.cdf(731.0)),
        (Some(0.0), Some(0.0), Some(1.0))
    );
    // Narrow bins on F11's lines, wide between them.
    assert!(binned.pdf(545.0) > 10.0 * binned.pdf(500.0));
}

/// Uniform cut into equal bins stays uniform.
#[test]
fn uniform_stays_uniform() {
    let binned = BinnedPdf::new(&Uniform::ASSIGNMENT, 7).unwrap();
    for i in 0..100 {
        let u = (i as f64 + 0.5) / 100.0;
        let (lambda, inv) = binned.sample_with_inv_pdf(u);
        assert!((lambda - (LAMBDA_MIN + u * LAMBDA_WIDTH)).abs() < 1e-9 && (inv - LAMBDA_WIDTH).abs() < 1e-9);
    }
    assert_eq!((binned.pdf(379.9), binned.pdf(730.1), binned.pdf(f64::NAN)), (0.0, 0.0, 0.0));
    assert_eq!(binned.support(), crate::spectrum::WavelengthRange::ASSIGNMENT);
    // Only a uniform density says so (a histogram of one is not drawn in
    // fixed point).
    assert!(Uniform::ASSIGNMENT.is_uniform() && !Visible::VISIBLE.is_uniform() && !binned.is_uniform());
}

#[test]
fn samples_invert_the_cdf_and_carry_their_bins_density() {
    let binned = BinnedPdf::new(&LightPdf::balanced(&lights::F11).unwrap(), 256).unwrap();
    for i in 0..10_000 {
        let u = (i as f64 + 0.5) / 10_000.0;
        let (lambda, inv) = binned.sample_with_inv_pdf(u);
        assert!((binned.cdf(lambda).unwrap() - u).abs() < 1e-12, "u = {u}");
        assert!(inv > 0.0 && (inv * binned.pdf(lambda) - 1.0).abs() < 1e-9, "u = {u}");
        assert_eq!(binned.sample(u), lambda);
    }
    let knots = binned.knots();
    assert_eq!((binned.sample(-1.0), binned.sample(f64::NAN)), (knots[0], knots[0]));
    assert_eq!(binned.sample(2.0), knots[256]);
    assert!(knots[0] >= LAMBDA_MIN && knots[256] <= LAMBDA_MAX);
}

/// The estimate of ∫ F11·ȳ with wavelengths from the binned light pdf
/// matches the exact integral within 4 standard errors, over independent
/// uniform numbers (a fixed-seed LCG).
#[test]
fn estimates_from_the_histogram_are_unbiased() {
    let binned = BinnedPdf::new(&LightPdf::light(&lights::F11).unwrap(), 64).unwrap();
    let f = |lambda: f64| lights::F11.eval(lambda) * observer::xyz_bar(lambda)[1];
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let n = 50_000;
    let values: Vec<f64> = (0..n)
        .map(|_| {
            state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            let (lambda, inv) = binned.sample_with_inv_pdf((state >> 11) as f64 / (1u64 << 53) as f64);
            f(lambda) * inv
        })
        .collect();
    let mean = values.iter().sum::<f64>() / n as f64;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    let exact = crate::sampling::reference::white(&lights::F11).y;
    let se = (var / n as f64).sqrt();
    assert!((mean - exact).abs() < 4.0 * se, "{mean} against {exact} (se {se})");
    // And the histogram follows the light: far below uniform sampling's spread.
    let uniform_var: f64 = (0..n)
        .map(|i| {
            let lambda = LAMBDA_MIN + LAMBDA_WIDTH * (i as f64 + 0.5) / n as f64;
            (f(lambda) * LAMBDA_WIDTH - exact).powi(2)
        })
        .sum::<f64>()
        / n as f64;
    assert!(var < 0.2 * uniform_var, "{var} against uniform {uniform_var}");
}

#[test]
fn visible_histogram_tracks_visible() {
    let binned = BinnedPdf::new(&Visible::ASSIGNMENT, 256).unwrap();
    for lambda in [400.0, 538.0, 700.0] {
        let (a, b) = (binned.pdf(lambda), Visible::ASSIGNMENT.pdf(lambda));
        assert!((a - b).abs() < 0.02 * b, "{lambda}: {a} against {b}");
    }
}

#[test]
fn the_range_ends_belong_to_the_end_bins() {
    let light = LightPdf::light(&lights::F11).unwrap();
    let binned = BinnedPdf::new(&light, 64).unwrap();
    let (first, last) = (binned.knots()[0], binned.knots()[64]);
    let width = |i: usize| binned.knots()[i + 1] - binned.knots()[i];
    // The last knot is in the last bin (not one past it), the first in the first.
    assert_eq!(binned.pdf(last), 1.0 / (64.0 * width(63)));
    assert_eq!(binned.pdf(first), 1.0 / (64.0 * width(0)));
    assert_eq!(binned.cdf(last), Some(1.0));
    assert_eq!(binned.cdf(first), Some(0.0));
    assert_eq!(binned.pdf(last + 1e-9), 0.0);
}
