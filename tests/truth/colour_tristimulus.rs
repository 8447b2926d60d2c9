#![allow(clippy::excessive_precision)] // colour-science's expected values, digits as printed there

//! colour-science 0.4.7's tristimulus tests
//! (`colorimetry/tests/test_tristimulus_values.py`), reproduced through
//! speclab's public API: the input reflectance `SD_SAMPLE`
//! (`tests/data/colour_sd_sample.csv`, 340–830 nm every 5 nm), the
//! expected values and the tolerance (`assert_allclose` with
//! `atol = 1e-7` and numpy's default `rtol = 1e-7`) are colour's.
//!
//! How colour reads its inputs, and how these tests say the same: the
//! sample is interpolated by Sprague's formula (`spectrum::Sprague`) and
//! holds its end values outside; the CIE's 5 nm illuminant tables are
//! linear between samples (the crate's named lights) and hold their end
//! values outside (colour's constant extrapolation); illuminant A for
//! `sd_to_XYZ_ASTME308` is the CIE's formula at 1 nm.

use speclab::Xyz;
use speclab::colorimetry::Tristimulus;
use speclab::colorimetry::e308::Practice;
use speclab::data::lights;
use speclab::spectrum::{FnSpectrum, Spectrum, Sprague, StandardObserver, WavelengthRange};

/// numpy's `assert_allclose(actual, desired, atol=1e-7)`.
fn allclose(got: Xyz, expected: [f64; 3], what: &str) {
    for (g, e) in [got.x, got.y, got.z].into_iter().zip(expected) {
        assert!((g - e).abs() <= 1e-7 + 1e-7 * e.abs(), "{what}: {got:?} against {expected:?}");
    }
}

/// colour's `SD_SAMPLE` as a Sprague interpolant.
fn sample() -> Sprague {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/colour_sd_sample.csv");
    let text = std::fs::read_to_string(path).expect("test data");
    let values: Vec<f64> = text
        .lines()
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| l.split(',').nth(1).expect("two columns").parse().expect("a number"))
        .collect();
    assert_eq!(values.len(), 99);
    Sprague::new(340.0, 5.0, values).expect("the sample")
}

/// colour's `reshape_sd(SD_SAMPLE, SpectralShape(first, last, step))`:
/// the interpolant read at a new grid, a measurement of its own.
fn measured(first: f64, last: f64, step: f64) -> Sprague {
    let s = sample();
    let n = ((last - first) / step) as usize + 1;
    Sprague::new(first, step, (0..n).map(|i| s.eval(first + step * i as f64)).collect()).unwrap()
}

/// A 5 nm table read as colour reads it: linear, its ends held.
fn held(table: &speclab::TabulatedSpectrum) -> impl Spectrum + '_ {
    let (lo, hi) = (table.lambda()[0], *table.lambda().last().unwrap());
    FnSpectrum(move |lambda: f64| table.eval(lambda.clamp(lo, hi)))
}

/// CIE illuminant C (`tests/data/cie_illuminant_c.csv`, CIE 15:2004's
/// 5 nm table), loaded as a user loads a light.
fn illuminant_c() -> speclab::TabulatedSpectrum {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cie_illuminant_c.csv");
    speclab::io::Load::new(speclab::Role::Light).file(path).expect("illuminant C")
}

/// The CIE's formula for illuminant A (colour's `sd_CIE_standard_illuminant_A`).
fn a_formula() -> impl Spectrum {
    FnSpectrum(|l: f64| {
        let c2: f64 = 1.435e7;
        100.0 * (560.0 / l).powi(5) * ((c2 / (2848.0 * 560.0)).exp_m1() / (c2 / (2848.0 * l)).exp_m1())
    })
}

/// `test_sd_to_XYZ_integration` (lines 795–847), five of its six cases.
/// The sixth sums over 340–830 nm at 5 nm with the CIE 1931 observer held
/// at its 360 nm value below 360 nm; the CIE defines no observer there,
/// and `Tristimulus` refuses a range outside the observer's data.
#[test]
fn integration() {
    let c = illuminant_c();
    let a_5nm = crate::cie_5nm(&lights::CIE_A);
    let (sd, a, c, fl2) = (sample(), held(&a_5nm), held(&c), held(&lights::F2));
    let (t1931, t1964) = (Tristimulus::CIE_1931, Tristimulus::CIE_1964);
    allclose(t1931.relative(&a, &sd).unwrap(), [14.46341147, 10.85819624, 2.04695585], "A, 2°");
    allclose(t1964.relative(&c, &sd).unwrap(), [10.77002699, 9.44876636, 6.62415290], "C, 10°");
    allclose(t1964.relative(&fl2, &sd).unwrap(), [11.57540576, 9.98608874, 3.95242590], "FL2, 10°");
    // colour's k = 683: 683·Σ S·R·c̄·Δλ / 100.
    let k683 = t1964.absolute(&fl2, &sd) * (683.0 / 100.0);
    allclose(k683, [1223.7509261493, 1055.7284645912, 417.8501342332], "FL2, 10°, k = 683");
    let coarse = t1964.over(WavelengthRange::new(400.0, 700.0).unwrap()).unwrap().with_step(20.0).unwrap();
    allclose(coarse.relative(&fl2, &sd).unwrap(), [11.98232967, 10.13543929, 3.66442524], "FL2, 10°, 20 nm");
}

/// `test_sd_to_XYZ_tristimulus_weighting_factors_ASTME308` (lines 875–947):
/// E2022 weights at the measured interval over 360–830 nm, adjusted to the
/// measured range.
#[test]
fn weighting_factors() {
    let c = illuminant_c();
    let a_5nm = crate::cie_5nm(&lights::CIE_A);
    let (a, c, fl2) = (held(&a_5nm), held(&c), held(&lights::F2));
    let (o1931, o1964) = (StandardObserver::Cie1931, StandardObserver::Cie1964);
    let w = Practice::WEIGHTS;
    let sd = measured(340.0, 830.0, 5.0);
    allclose(w.relative(&sd, &a, o1931).unwrap(), [14.46341867, 10.85820227, 2.04697034], "A, 2°");
    allclose(w.relative(&sd, &c, o1964).unwrap(), [10.77005571, 9.44877491, 6.62428210], "C, 10°");
    allclose(w.relative(&sd, &fl2, o1964).unwrap(), [11.57542759, 9.98605604, 3.95273304], "FL2, 10°");
    for (step, expected) in [
        (5.0, [14.38153638, 10.74503131, 2.01613844]),
        (10.0, [14.38257202, 10.74568178, 2.01588427]),
        (20.0, [14.38329645, 10.74603515, 2.01561113]),
    ] {
        let xyz = w.relative(&measured(400.0, 700.0, step), &a, o1964).unwrap();
        allclose(xyz, expected, &format!("A, 10°, 400–700 nm every {step} nm"));
    }
    let k1 = w.absolute(&measured(400.0, 700.0, 20.0), &a, o1964).unwrap();
    allclose(k1, [1636.74881983, 1222.84626486, 229.36669308], "A, 10°, 20 nm, k = 1");
}

/// One `sd_to_XYZ_ASTME308` case: the sample read on `first..=last` every
/// `step` nm, under the formula's A with the CIE 1931 observer.
struct Case {
    grid: (f64, f64, f64),
    practice: Practice,
    /// colour's `k = 1`: the sums over 100.
    k1: bool,
    expected: [f64; 3],
}

const E308: Practice = Practice::E308;
const FULL_RANGE: Practice = Practice { practice_range: false, ..Practice::E308 };
const WEIGHTS_5: Practice = Practice { omit_5nm: false, ..Practice::E308 };
const WEIGHTS_20: Practice = Practice { interpolate_20nm: false, ..Practice::E308 };
const FULL_WEIGHTS: Practice = Practice::WEIGHTS;

fn case(grid: (f64, f64, f64), practice: Practice, expected: [f64; 3]) -> Case {
    Case { grid, practice, k1: false, expected }
}

/// `test_sd_to_XYZ_ASTME308_mi_1nm`, `_mi_5nm`, `_mi_10nm` and `_mi_20nm`
/// (lines 986–1331), every case.
#[test]
fn astm_e308() {
    let k1 = |grid, expected| Case { grid, practice: E308, k1: true, expected };
    let cases = [
        case((360.0, 830.0, 1.0), E308, [14.46372680, 10.85832950, 2.04663200]),
        case((360.0, 830.0, 1.0), FULL_RANGE, [14.46366018, 10.85827949, 2.04662258]),
        case((400.0, 700.0, 1.0), E308, [14.54173397, 10.88628632, 2.04965822]),
        case((400.0, 700.0, 1.0), FULL_RANGE, [14.54203076, 10.88636754, 2.04964877]),
        k1((400.0, 700.0, 1.0), [15.6898152997, 11.7457671769, 2.2114803420]),
        case((360.0, 830.0, 5.0), E308, [14.46372173, 10.85832502, 2.04664734]),
        case((360.0, 830.0, 5.0), FULL_RANGE, [14.46366388, 10.85828159, 2.04663915]),
        case((360.0, 830.0, 5.0), WEIGHTS_5, [14.46373399, 10.85833553, 2.0466465]),
        case((400.0, 700.0, 5.0), E308, [14.54025742, 10.88576251, 2.04950226]),
        case((400.0, 700.0, 5.0), FULL_RANGE, [14.54051517, 10.88583304, 2.04949406]),
        case((400.0, 700.0, 5.0), WEIGHTS_5, [14.54022093, 10.88575468, 2.04951057]),
        case(
            (360.0, 830.0, 5.0),
            Practice { omit_5nm: false, ..FULL_RANGE },
            [14.46366737, 10.85828552, 2.04663707],
        ),
        case(
            (400.0, 700.0, 5.0),
            Practice { omit_5nm: false, ..FULL_RANGE },
            [14.54051772, 10.88583590, 2.04950113],
        ),
        k1((400.0, 700.0, 5.0), [15.6882479013, 11.7452212708, 2.2113156963]),
        case((360.0, 830.0, 10.0), E308, [14.47779980, 10.86358645, 2.04751388]),
        case((360.0, 830.0, 10.0), FULL_RANGE, [14.47773312, 10.86353641, 2.04750445]),
        case((400.0, 700.0, 10.0), E308, [14.54137532, 10.88641727, 2.04931318]),
        case((400.0, 700.0, 10.0), FULL_RANGE, [14.54167211, 10.88649849, 2.04930374]),
        k1((400.0, 700.0, 10.0), [15.6894283333, 11.7459084705, 2.2111080639]),
        k1((401.0, 701.0, 10.0), [15.6713226093, 11.7392254489, 2.2117708792]),
        case((360.0, 820.0, 20.0), E308, [14.50187464, 10.87217124, 2.04918305]),
        case((360.0, 820.0, 20.0), FULL_RANGE, [14.50180785, 10.87212116, 2.04917361]),
        case((360.0, 820.0, 20.0), WEIGHTS_20, [14.50216194, 10.87236873, 2.04977256]),
        case((400.0, 700.0, 20.0), E308, [14.54114025, 10.88634755, 2.04916445]),
        case((400.0, 700.0, 20.0), FULL_RANGE, [14.54143704, 10.88642877, 2.04915501]),
        case((400.0, 700.0, 20.0), WEIGHTS_20, [14.54242562, 10.88694088, 2.04919645]),
        case((360.0, 820.0, 20.0), FULL_WEIGHTS, [14.50209515, 10.87231865, 2.04976312]),
        case((400.0, 700.0, 20.0), FULL_WEIGHTS, [14.54272240, 10.88702210, 2.04918701]),
        k1((400.0, 700.0, 20.0), [15.6891747040, 11.7458332427, 2.2109475945]),
        case((401.0, 701.0, 20.0), E308, [14.5220164311, 10.8790959535, 2.0490905325]),
    ];
    let a = a_formula();
    for Case { grid: (first, last, step), practice, k1, expected } in cases {
        let sd = measured(first, last, step);
        let o = StandardObserver::Cie1931;
        let xyz = match k1 {
            true => practice.absolute(&sd, &a, o).unwrap() * 0.01,
            false => practice.relative(&sd, &a, o).unwrap(),
        };
        allclose(xyz, expected, &format!("{first}–{last} nm every {step} nm, {practice:?}, k = 1: {k1}"));
    }
    // `test_raise_exception_sd_to_XYZ_ASTME308`: a 2 nm interval.
    assert!(E308.relative(&measured(360.0, 820.0, 2.0), &a, StandardObserver::Cie1931).is_err());
}
