#![allow(clippy::excessive_precision)] // colour-science's expected values, digits as printed there

//! colour-science 0.4.7's own tests, reproduced through speclab's public
//! API: their inputs and expected values are published truth (the file and
//! test of each are named), held to colour's tolerance
//! (`TOLERANCE_ABSOLUTE_TESTS` = 1e-7) unless a test says why not.

use speclab::Xyz;
use speclab::color::adaptation::Cat;
use speclab::color::lab::{lab, xyz_from_lab};
use speclab::colorimetry::cct::{Planckian, uv_from_xy, xy_from_uv};
use speclab::data::lights::daylight_xy;
use speclab::spectrum::PlanckConstants;

/// colour's `TOLERANCE_ABSOLUTE_TESTS`.
const TOLERANCE: f64 = 1e-7;

fn close(got: &[f64], expected: &[f64], tolerance: f64, what: &str) {
    for (g, e) in got.iter().zip(expected) {
        assert!((g - e).abs() <= tolerance, "{what}: {got:?} against {expected:?}");
    }
}

/// The XYZ of a chromaticity at Y = 1 (colour's illuminant arguments).
fn white(xy: [f64; 2]) -> Xyz {
    Xyz::from_xy_luminance(xy, 1.0)
}

/// `models/tests/test_cie_lab.py`: `test_XYZ_to_Lab`, `test_Lab_to_XYZ`
/// (D65 at xy 0.3127, 0.3290 by default; illuminants A and D50 given).
#[test]
fn cie_lab_both_ways() {
    let d65 = [0.3127, 0.3290];
    let cases = [
        ([0.20654008, 0.12197225, 0.05136952], d65, [41.52787529, 52.63858304, 26.92317922]),
        ([0.14222010, 0.23042768, 0.10495772], d65, [55.11636304, -41.08791787, 30.91825778]),
        ([0.07818780, 0.06157201, 0.28099326], d65, [29.80565520, 20.01830466, -48.34913874]),
        ([0.20654008, 0.12197225, 0.05136952], [0.44757, 0.40745], [41.52787529, 38.48089305, -5.73295122]),
        ([0.20654008, 0.12197225, 0.05136952], [0.34570, 0.35850], [41.52787529, 51.19354174, 19.91843098]),
    ];
    for (xyz, xy, expected) in cases {
        close(&lab(Xyz::from(xyz), white(xy)), &expected, TOLERANCE, "XYZ_to_Lab");
        close(&xyz_from_lab(expected, white(xy)).to_array(), &xyz, TOLERANCE, "Lab_to_XYZ");
    }
}

/// `models/tests/test_cie_xyy.py`: `test_xyY_to_XYZ`, `test_XYZ_to_xy`.
#[test]
fn chromaticity_both_ways() {
    let cases = [
        ([0.54369557, 0.32107944, 0.12197225], [0.20654008, 0.12197225, 0.05136952]),
        ([0.29777735, 0.48246446, 0.23042768], [0.14222010, 0.23042768, 0.10495772]),
        ([0.18582823, 0.14633764, 0.06157201], [0.07818780, 0.06157201, 0.28099326]),
    ];
    for ([x, y, big_y], xyz) in cases {
        close(&Xyz::from_xy_luminance([x, y], big_y).to_array(), &xyz, TOLERANCE, "xyY_to_XYZ");
        close(&Xyz::from(xyz).xy().unwrap(), &[x, y], TOLERANCE, "XYZ_to_xy");
    }
    assert_eq!(Xyz::from_xy_luminance([0.34567, 0.3585], 0.0), Xyz::ZERO);
}

/// `adaptation/tests/test_vonkries.py`: `test_matrix_chromatic_adaptation_VonKries`
/// (CAT02 is colour's default transform), D65 to D50 and to A.
#[test]
fn chromatic_adaptation_matrices() {
    let (d65, d50, a) =
        ([0.95045593, 1.0, 1.08905775], [0.96429568, 1.0, 0.82510460], [1.09846607, 1.0, 0.35582280]);
    let cases = [
        (
            Cat::Cat02,
            d50,
            [
                [1.04257389, 0.03089108, -0.05281257],
                [0.02219345, 1.00185663, -0.02107375],
                [-0.00116488, -0.00342053, 0.76178907],
            ],
        ),
        (
            Cat::Cat02,
            a,
            [
                [1.17159793, 0.16088780, -0.16158366],
                [0.11462057, 0.96182051, -0.06497572],
                [-0.00413024, -0.00912739, 0.33871096],
            ],
        ),
        (
            Cat::Bradford,
            d50,
            [
                [1.04792979, 0.02294687, -0.05019227],
                [0.02962781, 0.99043443, -0.01707380],
                [-0.00924304, 0.01505519, 0.75187428],
            ],
        ),
        (
            Cat::VonKries,
            d50,
            [
                [1.01611856, 0.05535971, -0.05219186],
                [0.00608087, 0.99555604, -0.00122642],
                [0.0, 0.0, 0.75763163],
            ],
        ),
        (Cat::XyzScaling, d50, [[1.01456117, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.75763163]]),
    ];
    for (cat, to, expected) in cases {
        let m = cat.matrix(Xyz::from(d65), Xyz::from(to));
        for (row, e) in m.iter().zip(expected) {
            close(row, &e, TOLERANCE, &format!("{cat:?}"));
        }
    }
}

/// `temperature/tests/test_ohno2013.py`: `test_uv_to_CCT_Ohno2013`,
/// `test_CCT_to_uv_Ohno2013`, `test_XYZ_to_CCT_Ohno2013`,
/// `test_CCT_to_XYZ_Ohno2013` (the 1931 observer over 360–780 nm at 1 nm,
/// c₂ = 1.4388e-2 m·K: `Planckian::CIE`). `CCT_to_XYZ` is held to 1e-6 there.
#[test]
fn cct_by_ohno_2013() {
    let p = Planckian::CIE;
    let to_cct = [
        ([0.1978, 0.3122], [6507.474788799616363, 0.003223346337596]),
        ([0.4328, 0.2883], [1041.678320000468375, -0.067378053475797]),
        ([0.2927, 0.2722], [2444.971818951082696, -0.084370641205118]),
    ];
    for (uv, expected) in to_cct {
        let (t, duv) = p.cct(uv).unwrap();
        close(&[t, duv], &expected, TOLERANCE, "uv_to_CCT_Ohno2013");
    }
    let to_uv = [
        ([6507.47380460, 0.00322335], [0.19779997, 0.31219997]),
        ([1041.68315360, -0.06737802], [0.43279885, 0.28830013]),
        ([2452.15316417, -0.08437064], [0.29247364, 0.27215157]),
    ];
    for ([t, duv], expected) in to_uv {
        close(&p.uv_at(t, duv).unwrap(), &expected, TOLERANCE, "CCT_to_uv_Ohno2013");
    }
    let d65 = Xyz::new(95.04, 100.0, 108.88);
    let (t, duv) = p.cct(uv_from_xy(d65.xy().unwrap())).unwrap();
    close(&[t, duv], &[6503.30711709, 0.00321729], TOLERANCE, "XYZ_to_CCT_Ohno2013");
    let back = Xyz::from_xy_luminance(xy_from_uv(p.uv_at(6503.30711709, 0.00321729).unwrap()), 1.0);
    close(&back.to_array(), &[0.9504, 1.0, 1.0888], 1e-6, "CCT_to_XYZ_Ohno2013");
}

/// `temperature/tests/test_cie_d.py`: `test_CCT_to_xy_CIE_D`.
#[test]
fn daylight_locus() {
    let cases = [
        (4000.0, [0.382343625000000, 0.383766261015578]),
        (7000.0, [0.305357431486880, 0.321646345474552]),
        (25000.0, [0.24985367, 0.254799464210944]),
    ];
    for (cct, xy) in cases {
        close(&daylight_xy(cct).unwrap(), &xy, TOLERANCE, "CCT_to_xy_CIE_D");
    }
}

/// `colorimetry/tests/test_blackbody.py`: `test_planck_law`, its table
/// `DATA_PLANCK_LAW` (`tests/data/colour_planck_law.csv`; 1 nm to 32 µm,
/// 1667 K to 1e19 K). colour holds it to 1e-7 absolute on values up to
/// 1e36 W·sr⁻¹·m⁻³, which only its own order of operations meets; here
/// each value within 1e-13 relative (a few rounding steps).
#[test]
fn planck_law() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/colour_planck_law.csv");
    let text = std::fs::read_to_string(path).expect("test data");
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("kelvin"))
        .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
        .collect();
    assert_eq!(rows.len(), 80);
    for row in rows {
        let (kelvin, nm, expected) = (row[0], row[1], row[2]);
        let got = PlanckConstants::CIE.radiance(nm, kelvin) * 1e9;
        assert!(
            (got - expected).abs() <= 1e-13 * expected,
            "{nm} nm, {kelvin} K: {got:e} against {expected:e}"
        );
    }
}

/// `colorimetry/tests/test_tristimulus_values.py`:
/// `test_tristimulus_weighting_factors_ASTME2022` and
/// `test_adjust_tristimulus_weighting_factors_ASTME308`
/// (`tests/data/astm_e308_weights.csv`). Illuminant A is the CIE's formula
/// at 1 nm (colour's `sd_CIE_standard_illuminant_A`); D65 the CIE's 5 nm
/// table, linear between, its 780 nm value held beyond (colour's
/// `reshape_sd`). The three-decimal tables are ASTM E308-15's, colour notes.
#[test]
fn astm_e308_weighting_tables() {
    use speclab::colorimetry::Tristimulus;
    use speclab::colorimetry::astm::Weights;
    use speclab::data::lights;
    use speclab::spectrum::{FnSpectrum, WavelengthRange};
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/astm_e308_weights.csv");
    let text = std::fs::read_to_string(path).expect("test data");
    let table = |name: &str| -> Vec<[f64; 3]> {
        text.lines()
            .filter(|l| l.split(',').next() == Some(name))
            .map(|l| {
                let v: Vec<f64> = l.split(',').skip(2).map(|x| x.parse().expect("a number")).collect();
                [v[0], v[1], v[2]]
            })
            .collect()
    };
    let a = FnSpectrum(|l: f64| {
        let c2: f64 = 1.435e7;
        100.0 * (560.0 / l).powi(5) * ((c2 / (2848.0 * 560.0)).exp_m1() / (c2 / (2848.0 * l)).exp_m1())
    });
    let d65_5nm = crate::cie_5nm(&lights::CIE_D65);
    let d65 = FnSpectrum(|l: f64| d65_5nm.eval(l.min(780.0)));
    let three_decimals = |w: &Weights, expected: &[[f64; 3]], what: &str| {
        assert_eq!(w.rows().len(), expected.len(), "{what}");
        for (row, e) in w.rows().iter().zip(expected) {
            close(&row.map(|v| (v * 1000.0).round() / 1000.0), e, TOLERANCE, what);
        }
    };
    let (o1931, o1964) = (Tristimulus::CIE_1931, Tristimulus::CIE_1964);
    let every = |t: Tristimulus, step| t.with_step(step).unwrap();
    three_decimals(
        &Weights::e2022(&a, every(o1964, 10.0)).unwrap(),
        &table("TWF_A_CIE_1964_10_10"),
        "A, 10°, 10 nm",
    );
    three_decimals(
        &Weights::e2022(&a, every(o1964, 20.0)).unwrap(),
        &table("TWF_A_CIE_1964_10_20"),
        "A, 10°, 20 nm",
    );
    let w = Weights::e2022(&d65, every(o1931, 20.0)).unwrap();
    three_decimals(&w, &table("TWF_D65_CIE_1931_2_20"), "D65, 2°, 20 nm");
    let k1 = Weights::e2022_unscaled(&d65, every(o1931, 20.0)).unwrap();
    for (row, e) in k1.rows().iter().zip(table("TWF_D65_CIE_1931_2_20_K1")) {
        close(row, &e, TOLERANCE, "D65, 2°, 20 nm, k = 1");
    }
    // The adjustment, applied (as colour's test does) to the three-decimal table.
    let printed: Vec<[f64; 3]> = table("TWF_D65_CIE_1931_2_20");
    let rounded = Weights::from_rows(360.0, 20, printed).unwrap();
    let trimmed = rounded.trimmed(WavelengthRange::new(400.0, 700.0).unwrap()).unwrap();
    for (row, e) in trimmed.rows().iter().zip(table("TWF_D65_CIE_1931_2_20_A")) {
        close(row, &e, TOLERANCE, "adjusted to 400–700 nm");
    }
}

/// `colorimetry/tests/test_illuminants.py`: `test_sd_CIE_illuminant_D_series`
/// (the formula at the nominal temperature times 1.4388/1.4380 against the
/// CIE's D50, D55, D65 and D75 tables, to 0.001).
#[test]
fn daylight_series() {
    use speclab::data::lights;
    for (table, nominal) in
        [(&lights::D50, 5000.0), (&lights::D55, 5500.0), (&lights::CIE_D65, 6500.0), (&lights::D75, 7500.0)]
    {
        let d = lights::daylight(nominal).unwrap();
        for (&l, &v) in table.lambda().iter().zip(table.values()) {
            assert!((d.eval(l) - v).abs() <= 0.001, "D{nominal} at {l} nm: {} against {v}", d.eval(l));
        }
    }
}
