//! The fast exact reference (a light's weights dotted with a reflectance's
//! samples, exact integration where a clamp acts) equals integration piece
//! by piece, `reference::xyz_of_product`, to 1e-12 relative: for every
//! built-in cell, for reflectances whose cubic overshoots [0, 1], for lights
//! prepared at run time, and through the batch.

use proptest::prelude::*;
use speclab::data::{Light, Patch};
use speclab::sampling::{PreparedLight, reference};
use speclab::{Error, Interpolation, Role, TabulatedSpectrum, Xyz};

/// Rounding only: the two routes sum the same exact integrals differently.
const ROUNDING: f64 = 1e-12;

fn close(fast: Xyz, slow: Xyz, scale: f64) -> bool {
    (fast - slow).to_array().iter().all(|d| d.abs() <= ROUNDING * scale)
}

fn grid() -> Vec<f64> {
    grid_every(10.0)
}

fn reflectance(values: Vec<f64>) -> TabulatedSpectrum {
    TabulatedSpectrum::new(grid(), values, Role::Reflectance).expect("valid")
}

#[test]
fn builtin_cells_equal_piecewise_integration() {
    for light in Light::APPENDIX {
        for patch in Patch::ALL {
            let (l, s) = (light.spectrum(), patch.spectrum());
            let (fast, slow) = (reference::xyz(l, s), reference::xyz_of_product(&[l, s]));
            for (f, w) in fast.to_array().iter().zip(slow.to_array()) {
                assert!((f - w).abs() <= ROUNDING * w.abs(), "{light:?} × {patch:?}: {fast:?} vs {slow:?}");
            }
        }
    }
}

/// Samples alternating 1, 0.02, 0.02: the cubic overshoots 1 and dips below
/// 0 in many segments; those are integrated exactly.
#[test]
fn clamped_segments_are_integrated_exactly() {
    let values: Vec<f64> = (0..36).map(|i| if i % 3 == 0 { 1.0 } else { 0.02 }).collect();
    let s = reflectance(values.clone());
    for light in Light::APPENDIX {
        let l = light.spectrum();
        let white = reference::white(l).y;
        let slow = reference::xyz_of_product(&[l, &s]);
        assert!(close(reference::xyz(l, &s), slow, white), "{light:?}");
        let prepared = PreparedLight::for_grid(l, &grid(), Interpolation::Cubic).expect("valid grid");
        assert!(close(prepared.xyz_samples(&values).expect("in range"), slow, white), "{light:?} raw");
        // Ignoring the clamp would be wrong: the weights alone differ.
        let unclamped: Xyz = {
            let flat = reflectance(values.iter().map(|v| v * 0.5 + 0.25).collect());
            (reference::xyz(l, &flat) - reference::xyz(l, &reflectance(vec![0.25; 36]))) * 2.0
        };
        assert!(!close(unclamped, slow, white), "the clamp matters here");
    }
}

/// The same on a fine grid (0.5 nm, 701 samples): the screen that decides
/// which segments might overshoot scales with the grid's step, and a step
/// below 1 nm must not let an overshoot through.
#[test]
fn clamped_segments_on_a_fine_grid() {
    let fine: Vec<f64> = (0..701).map(|i| 380.0 + 0.5 * f64::from(i)).collect();
    let values: Vec<f64> = (0..701).map(|i| if i % 3 == 0 { 1.0 } else { 0.02 }).collect();
    let s = TabulatedSpectrum::new(fine.clone(), values.clone(), Role::Reflectance).expect("valid");
    for light in Light::APPENDIX {
        let l = light.spectrum();
        let white = reference::white(l).y;
        let slow = reference::xyz_of_product(&[l, &s]);
        let prepared = PreparedLight::for_grid(l, &fine, Interpolation::Cubic).expect("valid grid");
        assert!(close(prepared.xyz_samples(&values).expect("in range"), slow, white), "{light:?}");
    }
}

/// Under A and F11, the light prepared for the cubic grid `lambda` gives
/// for samples `values` what piece-by-piece integration gives.
fn prepared_equals_integration(lambda: &[f64], values: &[f64], what: &str) {
    let s = TabulatedSpectrum::new(lambda.to_vec(), values.to_vec(), Role::Reflectance).expect("valid");
    for light in [Light::A, Light::F11] {
        let l = light.spectrum();
        let white = reference::white(l).y;
        let slow = reference::xyz_of_product(&[l, &s]);
        let prepared = PreparedLight::for_grid(l, lambda, Interpolation::Cubic).expect("valid grid");
        let fast = prepared.xyz_samples(values).expect("in range");
        assert!(close(fast, slow, white), "{what}, {light:?}: {fast:?} vs {slow:?}");
    }
}

/// 380–730 nm every `step` nm.
fn grid_every(step: f64) -> Vec<f64> {
    let n = (350.0 / step) as usize + 1;
    (0..n).map(|i| 380.0 + step * i as f64).collect()
}

/// A reflectance of 0.5 on `lambda` with `pattern` from sample `at`: its
/// samples and the spectrum.
fn grey_with(lambda: &[f64], at: usize, pattern: &[f64]) -> (Vec<f64>, TabulatedSpectrum) {
    let mut values = vec![0.5; lambda.len()];
    values[at..at + pattern.len()].copy_from_slice(pattern);
    let s = TabulatedSpectrum::new(lambda.to_vec(), values.clone(), Role::Reflectance).expect("valid");
    (values, s)
}

/// Overshoots that the samples do not show: a plateau of 0.99 between
/// 0.9s, whose cubic rises just above 1 (clamped: 1.0 exactly at the
/// plateau's middle), in the middle and at each end of a 10 nm and a
/// 0.5 nm grid. The screen that lets a spectrum skip the exact correction
/// must not pass these: every one is integrated exactly.
#[test]
fn small_overshoots_between_samples_are_caught() {
    for step in [10.0, 0.5] {
        let lambda = grid_every(step);
        let n = lambda.len();
        for at in [0, n / 2, n - 4] {
            let (values, s) = grey_with(&lambda, at, &[0.9, 0.99, 0.99, 0.9]);
            let middle = lambda[at + 1] + 0.5 * step;
            assert_eq!(s.eval(middle), 1.0, "step {step}, at {at}: the cubic overshoots 1");
            prepared_equals_integration(&lambda, &values, &format!("step {step}, at {at}"));
        }
    }
}

/// Overshoots inside an end segment (its cubic through the first or last
/// four samples, `a, a, b, c` from the end), on the 0.5 nm grid, where
/// each end's screen margin is what stands between them and a skipped
/// correction (on a 10 nm grid a wrong margin would come out larger).
#[test]
fn overshoots_in_the_end_segments_are_caught() {
    let step = 0.5;
    let lambda = grid_every(step);
    let n = lambda.len();
    for [a, b, c] in
        [[0.99, 0.8, 0.3], [0.99, 0.85, 0.5], [0.97, 0.6, 0.0], [0.999, 0.95, 0.8], [0.96, 0.5, 0.0]]
    {
        for first in [true, false] {
            let (at, end) = if first { (0, [a, a, b, c]) } else { (n - 4, [c, b, a, a]) };
            let (values, s) = grey_with(&lambda, at, &end);
            let segment = if first { lambda[0] } else { lambda[n - 2] };
            let clamped = (1..20).any(|i| s.eval(segment + step * f64::from(i) / 20.0) == 1.0);
            assert!(
                clamped,
                "{a}, {b}, {c} at the {} end: the cubic overshoots 1",
                if first { "first" } else { "last" }
            );
            prepared_equals_integration(&lambda, &values, &format!("{a}, {b}, {c}, first end {first}"));
        }
    }
}

/// Zigzags whose second differences exceed 1 (`lo, hi, lo` with hi − lo
/// above ½) around a plateau `hi, hi` whose cubic rises above 1, with
/// every sample well inside [0, 1]: the screen's margin grows with the
/// second difference, so none of these may skip the exact correction.
#[test]
fn zigzags_with_large_second_differences_are_caught() {
    let step = 10.0;
    let lambda = grid_every(step);
    for i in 0..10 {
        let lo = 0.05 + 0.005 * f64::from(i);
        let hi = 1.0 - lo;
        let (values, s) = grey_with(&lambda, 14, &[lo, hi, lo, hi, hi, lo, hi, lo]);
        assert_eq!(s.eval(lambda[17] + 0.5 * step), 1.0, "lo {lo}: the plateau's cubic overshoots 1");
        prepared_equals_integration(&lambda, &values, &format!("zigzag, lo {lo}"));
    }
}

/// A light prepared at run time (a loaded, non-uniform one here) gives the
/// same as integration, and so does a surface off the light's grid.
#[test]
fn runtime_light_and_other_grids() {
    let lamp = TabulatedSpectrum::new(
        vec![380.0, 400.0, 451.5, 500.0, 545.0, 546.0, 600.0, 650.0, 730.0],
        vec![0.5, 0.8, 1.5, 1.0, 1.0, 20.0, 2.0, 1.2, 0.7],
        Role::Light,
    )
    .expect("valid");
    let prepared = PreparedLight::for_grid(&lamp, &grid(), Interpolation::Cubic).expect("valid grid");
    let white = reference::white(&lamp).y;
    for patch in Patch::ALL {
        let s = patch.spectrum();
        assert!(prepared.fits(s));
        assert!(close(prepared.xyz(s), reference::xyz_of_product(&[&lamp, s]), white), "{patch:?}");
    }
    let coarse =
        TabulatedSpectrum::new(vec![380.0, 500.0, 600.0, 730.0], vec![0.2, 0.4, 0.6, 0.8], Role::Reflectance)
            .expect("valid");
    assert!(!prepared.fits(&coarse));
    assert!(close(prepared.xyz(&coarse), reference::xyz_of_product(&[&lamp, &coarse]), white));
    let linear = PreparedLight::for_grid(&lamp, &grid(), Interpolation::Linear).expect("valid grid");
    let s = TabulatedSpectrum::with_interpolation(
        grid(),
        Patch::G4.spectrum().values().to_vec(),
        Role::Reflectance,
        Interpolation::Linear,
    )
    .expect("valid");
    assert!(linear.fits(&s));
    assert!(close(linear.xyz(&s), reference::xyz_of_product(&[&lamp, &s]), white), "linear reflectances");
}

#[test]
fn batch_errors_name_the_index() {
    let d65 =
        PreparedLight::for_grid(Light::D65.spectrum(), &grid(), Interpolation::Cubic).expect("valid grid");
    let mut out = [Xyz::ZERO; 2];
    let err = d65.batch(&[0.5; 71], &mut out).unwrap_err();
    assert_eq!(err.to_string(), "values: expected 72 values, one per wavelength, found 71");
    let mut bad = vec![0.5; 72];
    bad[40] = 1.5;
    assert_eq!(
        d65.batch(&bad, &mut out).unwrap_err().to_string(),
        "values[40]: expected a value in [0, 1], found 1.5"
    );
    bad[40] = f64::NAN;
    assert!(matches!(d65.batch(&bad, &mut out), Err(Error::Sample(_))));
    assert!(
        PreparedLight::for_grid(Light::D65.spectrum(), &[380.0, 370.0, 400.0, 500.0], Interpolation::Cubic)
            .is_err()
    );
}

proptest! {
    /// Any reflectance on the grid, extremes included, through the batch.
    #[test]
    fn batch_equals_integration(
        values in prop::collection::vec(prop_oneof![Just(0.0), Just(1.0), 0.0..=1.0f64], 72),
        light in 0..3usize,
    ) {
        let l = Light::APPENDIX[light].spectrum();
        let prepared = PreparedLight::for_grid(l, &grid(), Interpolation::Cubic).expect("valid grid");
        let mut out = [Xyz::ZERO; 2];
        prepared.batch(&values, &mut out).expect("in range");
        let white = reference::white(l).y;
        for (chunk, got) in values.chunks(36).zip(out) {
            let slow = reference::xyz_of_product(&[l, &reflectance(chunk.to_vec())]);
            prop_assert!(close(got, slow, white), "{:?} vs {:?}", got, slow);
        }
    }
}
