#![allow(clippy::excessive_precision)] // colour-science's values, digits as printed there

//! colour-science 0.4.7's tests of the pieces speclab lacked, reproduced
//! through the public API within colour's own tolerance (`assert_allclose`:
//! `|actual − expected| ≤ atol + 1e-7·|expected|`, atol 1e-7 unless
//! stated): CIEDE2000 for textiles (`test_delta_e.py`), the daylight locus
//! and CCT along it (`test_illuminants.py`, `test_cie_d.py`,
//! `test__init__.py`), ASTM E2022's Lagrange coefficients
//! (`test_tristimulus_values.py`), XYZ → sRGB by IEC 61966-2-1's printed
//! matrix (`models/rgb/tests/test_common.py`), the CIE 2015 observers
//! (`test_tristimulus_values.py`), and Ohno 2013 on both of its branches
//! and at both ends of its table: points colour's own tests leave out,
//! with colour's `uv_to_CCT_Ohno2013` as the second computation (run
//! values, 12 significant digits or more).

use speclab::Xyz;
use speclab::color::adaptation::Cat;
use speclab::color::difference::{Parametric, ciede2000, ciede2000_with};
use speclab::color::srgb::encode;
use speclab::colorimetry::astm::lagrange_coefficients;
use speclab::colorimetry::cct::{Planckian, daylight_cct, daylight_locus_y};
use speclab::data::lights::daylight_xy;
use speclab::spectrum::{Spectrum, Sprague, StandardObserver};

/// numpy's `assert_allclose` with `atol`.
fn close(got: &[f64], expected: &[f64], atol: f64, what: &str) {
    for (g, e) in got.iter().zip(expected) {
        assert!((g - e).abs() <= atol + 1e-7 * e.abs(), "{what}: {got:?} against {expected:?}");
    }
}

#[test]
fn ciede2000_for_textiles() {
    let pairs = [
        ([100.0, 21.57210357, 272.22819350], [50.0, 426.67945353, 72.39590835], 95.79205352),
        ([100.0, 21.57210357, 272.22819350], [50.0, 74.05216981, 276.45318193], 23.55420943),
        ([100.0, 21.57210357, 272.22819350], [50.0, 8.32281957, -73.58297716], 70.63213819),
        // The function's own example (its docstring).
        ([48.99183622, -0.10561667, 400.65619925], [50.65907324, -0.11671910, 402.82235718], 0.8412338),
    ];
    for (a, b, expected) in pairs {
        close(&[ciede2000_with(a, b, Parametric::TEXTILES)], &[expected], 1e-7, "textiles");
    }
    // A pair that differs in lightness alone: kL = 2 halves it.
    let (a, b) = ([40.0, 10.0, 10.0], [60.0, 10.0, 10.0]);
    assert!((2.0 * ciede2000_with(a, b, Parametric::TEXTILES) - ciede2000(a, b)).abs() < 1e-12);
}

#[test]
fn daylight_locus_and_cct_along_it() {
    for (x, y) in [(0.31270, 0.329105129999999), (0.34570, 0.358633529999999), (0.44758, 0.408571030799999)] {
        close(&[daylight_locus_y(x)], &[y], 1e-7, "y_D");
    }
    let points = [
        (4000.0, [0.382343625000000, 0.383766261015578]),
        (7000.0, [0.305357431486880, 0.321646345474552]),
        (25000.0, [0.24985367, 0.254799464210944]),
    ];
    for (t, xy) in points {
        close(&daylight_xy(t).unwrap(), &xy, 1e-7, "CCT_to_xy_CIE_D");
        close(&[daylight_cct(xy).unwrap()], &[t], 1e-7, "xy_to_CCT_CIE_D");
    }
    // `xy_to_CCT`'s default method (test__init__.py, atol 0.01).
    close(&[daylight_cct([0.31270, 0.32900]).unwrap()], &[6508.1175148], 0.01, "xy_to_CCT");
    assert!(daylight_cct([f64::NAN, 0.3]).is_err());
    // Past the locus' ends: the end itself.
    assert_eq!(daylight_cct([0.5, 0.45]).unwrap(), 4000.0);
    assert_eq!(daylight_cct([0.2, 0.2]).unwrap(), 25000.0);
}

#[test]
fn astm_e2022_lagrange_coefficients() {
    let (inner, boundary) = lagrange_coefficients(10);
    let expected_inner = [
        [-0.0285, 0.9405, 0.1045, -0.0165],
        [-0.0480, 0.8640, 0.2160, -0.0320],
        [-0.0595, 0.7735, 0.3315, -0.0455],
        [-0.0640, 0.6720, 0.4480, -0.0560],
        [-0.0625, 0.5625, 0.5625, -0.0625],
        [-0.0560, 0.4480, 0.6720, -0.0640],
        [-0.0455, 0.3315, 0.7735, -0.0595],
        [-0.0320, 0.2160, 0.8640, -0.0480],
        [-0.0165, 0.1045, 0.9405, -0.0285],
    ];
    let expected_boundary = [
        [0.8550, 0.1900, -0.0450],
        [0.7200, 0.3600, -0.0800],
        [0.5950, 0.5100, -0.1050],
        [0.4800, 0.6400, -0.1200],
        [0.3750, 0.7500, -0.1250],
        [0.2800, 0.8400, -0.1200],
        [0.1950, 0.9100, -0.1050],
        [0.1200, 0.9600, -0.0800],
        [0.0550, 0.9900, -0.0450],
    ];
    assert_eq!((inner.len(), boundary.len()), (9, 9));
    for (got, e) in inner.iter().zip(&expected_inner) {
        close(got, e, 1e-7, "inner, 10");
    }
    for (got, e) in boundary.iter().zip(&expected_boundary) {
        close(got, e, 1e-7, "boundary, 10");
    }
    // Interval 20 (colour's run values): every other row is interval 10's.
    let (inner20, boundary20) = lagrange_coefficients(20);
    close(&inner20[0], &[-0.0154375, 0.9725625, 0.0511875, -0.0083125], 1e-7, "inner, 20");
    close(&boundary20[18], &[0.02625, 0.9975, -0.02375], 1e-7, "boundary, 20");
    for i in 0..9 {
        close(&inner20[2 * i + 1], &expected_inner[i], 1e-7, "inner, 20 at 10's");
    }
    assert!(lagrange_coefficients(1).0.is_empty() && lagrange_coefficients(0).1.is_empty());
}

/// `XYZ_to_sRGB` (printed matrix, whitepoint 0.3127, 0.329; CAT02 by
/// default, Bradford where the test names it), encoded.
#[test]
fn xyz_to_srgb_by_the_printed_matrix() {
    let d65 = Xyz::from_xy_luminance([0.3127, 0.329], 1.0);
    let cases = [
        (
            [0.20654008, 0.12197225, 0.05136952],
            [0.3127, 0.329],
            Cat::Cat02,
            [0.70573936, 0.19248266, 0.22354169],
        ),
        (
            [0.14222010, 0.23042768, 0.10495772],
            [0.3127, 0.329],
            Cat::Cat02,
            [0.25847003, 0.58276102, 0.29718877],
        ),
        (
            [0.07818780, 0.06157201, 0.28099326],
            [0.3457, 0.3585],
            Cat::Cat02,
            [0.09838967, 0.25404426, 0.65130925],
        ),
        ([0.0, 0.0, 0.0], [0.44757, 0.40745], Cat::Cat02, [0.0, 0.0, 0.0]),
        (
            [0.20654008, 0.12197225, 0.05136952],
            [0.44757, 0.40745],
            Cat::Bradford,
            [0.60873814, 0.23259548, 0.43714892],
        ),
    ];
    for (xyz, white, cat, expected) in cases {
        let [x, y, z] = xyz;
        let adapted = cat.adapt(Xyz::new(x, y, z), Xyz::from_xy_luminance(white, 1.0), d65);
        let rgb = adapted.to_linear_srgb_iec();
        close(&[encode(rgb.r), encode(rgb.g), encode(rgb.b)], &expected, 1e-7, "XYZ_to_sRGB");
    }
}

/// The CIE 2015 observers' tables where colour's test reads them (480 nm
/// a row; 641.5 nm by Sprague's interpolant, colour's default), and the
/// white of D65 and A under each (colour's 1 nm sums over 390–830 nm,
/// run values, as xy).
#[test]
fn cie_2015_observers() {
    let o2 = StandardObserver::Cie2015_2;
    close(&o2.xyz_bar(480.0), &[0.08182895, 0.17880480, 0.75523790], 1e-7, "2°, 480 nm");
    close(
        &StandardObserver::Cie2015_10.xyz_bar(480.0),
        &[0.0759312, 0.2682271, 0.7516389],
        1e-7,
        "10°, 480 nm",
    );
    let (first, step, rows) = o2.table().unwrap();
    let column = |c: usize| Sprague::new(first, step, rows.iter().map(|r| r[c]).collect()).unwrap();
    let at = [0, 1, 2].map(|c| column(c).eval(641.5));
    close(&at, &[0.44575583, 0.18184213, 0.0], 1e-7, "2°, 641.5 nm (Sprague)");
    assert_eq!(o2.xyz_bar(389.5), [0.0; 3], "no data below 390 nm");
    assert_eq!(o2.data_range().min(), 390.0);
    let sums = |o: StandardObserver, light: &speclab::TabulatedSpectrum| {
        let (first, _, rows) = o.table().unwrap();
        let mut xyz = [0.0; 3];
        for (i, row) in rows.iter().enumerate().skip(30) {
            let s = light.eval(first + i as f64);
            (0..3).for_each(|c| xyz[c] += s * row[c]);
        }
        Xyz::new(xyz[0], xyz[1], xyz[2]).xy().unwrap()
    };
    use speclab::data::lights::{CIE_A, CIE_D65};
    let expected = [
        (o2, &CIE_D65, [0.31345244945499906, 0.33080182783040235]),
        (o2, &CIE_A, [0.45275876977750484, 0.4087995845814157]),
        (StandardObserver::Cie2015_10, &CIE_D65, [0.3137862796412001, 0.33127476288336694]),
        (StandardObserver::Cie2015_10, &CIE_A, [0.4529287385656466, 0.40520434705333586]),
    ];
    for (o, light, xy) in expected {
        close(&sums(o, light), &xy, 1e-10, o.name());
    }
    assert_eq!(StandardObserver::named("CIE 2015 10°").unwrap(), StandardObserver::Cie2015_10);
    assert_eq!(StandardObserver::named("2015 2 deg").unwrap(), StandardObserver::Cie2015_2);
    for (name, o) in [
        ("CIE 2015 2°", StandardObserver::Cie2015_2),
        ("2015 2°", StandardObserver::Cie2015_2),
        ("2015 10deg", StandardObserver::Cie2015_10),
    ] {
        assert_eq!(StandardObserver::named(name).unwrap(), o, "{name}");
    }
    // Each observer's 1 nm table leads back to it.
    for o in StandardObserver::ALL {
        assert_eq!(StandardObserver::of_dense(&o.dense()), o, "{}", o.name());
    }
}

/// Ohno 2013 where colour's tests do not go: 12 points on the triangular
/// branch (|Duv| < 0.002) from 1005 to 99000 K, points either side of the
/// 0.002 switch, and the table's ends (the nearest entry its first or
/// last, the interval clamped to the last but one). Each `(u, v)` and
/// colour's `(T, Duv)` for it.
#[test]
fn ohno_2013_both_branches_and_both_ends() {
    let points: [([f64; 2], [f64; 2]); 21] = [
        ([0.446795936323, 0.35473058922], [1005.00053763, 7.82002690493e-09]),
        ([0.44576370774, 0.356325113404], [1010.00052598, 0.00150000797186]),
        ([0.425657669417, 0.354977855141], [1100.0002827, -0.00149999059696]),
        ([0.357924830315, 0.361330616963], [1499.99998707, 0.00100002127438]),
        ([0.305088027055, 0.358568052766], [2000.00072138, -0.000499961945236]),
        ([0.255951285367, 0.349521049525], [2856.00233973, 3.97738914845e-08]),
        ([0.224031585547, 0.335951890049], [3999.99579268, 0.00190003352307]),
        ([0.199132648602, 0.31127249807], [6504.03659643, 0.00160001252898]),
        ([0.192032147562, 0.292444079699], [10000.073876, -0.00189999627965]),
        ([0.182454393444, 0.27421896669], [25000.0322249, 0.000500000263451]),
        ([0.182059440161, 0.267326842922], [60000.0376446, -0.000999999989462]),
        ([0.179498700937, 0.266216192474], [98999.9397301, 0.00120000000014]),
        // Either side of the switch at |Duv| = 0.002, at 1200 K.
        ([0.4060259977196355, 0.35984453332288324], [1200.0000820343625, 0.0019000123993591891]),
        ([0.4060397462665816, 0.3600440602069287], [1200.0007649563308, 0.002100021110775785]),
        ([0.405751026780713, 0.35585399564197506], [1200.0007522928813, -0.002100021034088684]),
        // The table's ends.
        ([0.4479628837635949, 0.3546296248084429], [999.9999999999978, -6.770326844116008e-17]),
        ([0.4480492448082198, 0.35562588871422857], [999.9997226148172, 0.0009999999978819532]),
        ([0.4478027467610388, 0.3541416293324473], [1000.5004680954515, -0.0004999942361150879]),
        ([0.18065515488983033, 0.2658948188326904], [99999.99999999677, 0.0]),
        ([0.18162419536135851, 0.26564791689964723], [100000.00533853652, -0.0010000000000003196]),
        ([0.18017063785227572, 0.26601828235156766], [99999.48901575473, 0.0005000000000043781]),
    ];
    for (uv, [t, duv]) in points {
        let (got_t, got_duv) = Planckian::CIE.cct(uv).unwrap();
        // The 12-digit points carry their inputs' rounding: 1e-11 in u, v
        // moves T by up to 1e-5 K at 99000 K; atol 1e-7 + rtol 1e-7 is
        // colour's tolerance (0.01 K at 100000 K).
        close(&[got_t], &[t], 1e-7, &format!("T at {uv:?}"));
        close(&[got_duv], &[duv], 1e-7, &format!("Duv at {uv:?}"));
    }
}
