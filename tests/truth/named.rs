//! The named spectra against their publications (published truth, in
//! `tests/data/`): every CIE illuminant's chromaticity, computed the way
//! the CIE computed it; every glass's catalogue n_d and Abbe number; the
//! conductors' η and k at their source's rows; the daylight formula
//! against the tabulated D illuminants; and the lookups by name.

use speclab::data::{Light, conductors, glasses, lights};
use speclab::spectrum::Spectrum;

/// Rows of a CSV file of `tests/data/`, without comments and header.
fn rows(file: &str) -> Vec<Vec<String>> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(file);
    let text = std::fs::read_to_string(&path).expect("test data");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// `v` rounded half up to `digits` decimals, as text.
fn rounded(v: f64, digits: usize) -> String {
    let scale = 10f64.powi(digits as i32);
    format!("{:.*}", digits, (v * scale + 0.5).floor() / scale)
}

/// The CIE's procedure (CIE 15:2004, 7.3): X, Y, Z summed at 5 nm from 380
/// to 780 nm, the light's tabulated values times the 1931 observer's 5 nm
/// table (`tests/data/cie1931_2deg_5nm.csv`, six decimals).
fn chromaticity(light: &dyn Spectrum) -> (f64, f64) {
    let mut xyz = [0.0; 3];
    for row in rows("cie1931_2deg_5nm.csv") {
        let nm: f64 = row[0].parse().expect("nm");
        if (380.0..=780.0).contains(&nm) {
            let s = light.eval(nm);
            for c in 0..3 {
                xyz[c] += s * row[c + 1].parse::<f64>().expect("cmf");
            }
        }
    }
    let sum = xyz[0] + xyz[1] + xyz[2];
    (xyz[0] / sum, xyz[1] / sum)
}

/// Each CIE illuminant's published (x, y) to the published digits, but
/// FL3.13's x (published 0.3830; its spectrum, the CIE's data set value
/// for value, gives 0.38305 by every procedure).
#[test]
fn illuminants_have_their_published_chromaticities() {
    let mut checked = 0;
    for row in rows("chromaticity_cie1931.csv") {
        let name = match row[0].as_str() {
            "A" => "CIE-A".to_string(),
            "D65" => "CIE-D65".to_string(),
            fl if fl.starts_with("FL") && !fl.contains('.') => fl.replacen("FL", "F", 1),
            other => other.to_string(),
        };
        let light: Light = name.parse().unwrap_or_else(|e| panic!("{name}: {e}"));
        let (x, y) = chromaticity(light.spectrum());
        let digits = row[1].len() - 2;
        let (got_x, got_y) = (rounded(x, digits), rounded(y, digits));
        if name == "FL3.13" {
            assert_eq!((got_x.as_str(), got_y.as_str()), ("0.3831", row[2].as_str()), "{x} {y}");
        } else {
            assert_eq!((got_x, got_y), (row[1].clone(), row[2].clone()), "{name}: {x} {y}");
        }
        checked += 1;
    }
    assert_eq!(checked, 46);
}

/// The assignment's lights against the CIE's (`data/SOURCES.md`): A is the
/// CIE's divided by 216.12 (within 0.05 %), D65 divided by 117.812 (within
/// 0.08 % over 380–730 nm); F11 is the CIE's FL11 (its published
/// chromaticity, above).
#[test]
fn the_assignment_lights_are_the_cie_tables_rescaled() {
    for (appendix, cie, scale, within) in
        [(&lights::A, &lights::CIE_A, 216.12, 5e-4), (&lights::D65, &lights::CIE_D65, 117.812, 8e-4)]
    {
        for nm in (380..=730).step_by(5) {
            let (a, c) = (appendix.eval(f64::from(nm)), cie.eval(f64::from(nm)) / scale);
            assert!((a - c).abs() <= within * c, "{nm} nm: {a} against {c}");
        }
    }
}

/// Each glass's n_d (587.5618 nm) and Abbe number to the catalogue's
/// digits, or (fused silica, diamond) its index at spectral lines to the
/// published digits; every glass has rows.
#[test]
fn glasses_have_their_catalogue_index_and_abbe_number() {
    let (rows, lines) = (rows("glasses.csv"), rows("glass-lines.csv"));
    for (name, _) in glasses::ALL {
        assert!(rows.iter().chain(&lines).any(|r| r[0] == *name), "{name} has published figures");
    }
    for row in lines {
        let (_, glass) = glasses::ALL.iter().find(|(n, _)| *n == row[0]).expect("a glass of the list");
        let digits = row[2].split('.').nth(1).map_or(0, str::len);
        let n = glass.eval(row[1].parse().expect("nm"));
        assert_eq!(rounded(n, digits), row[2], "{} at {} nm: {n}", row[0], row[1]);
    }
    for row in rows {
        let (_, glass) = glasses::ALL.iter().find(|(n, _)| *n == row[0]).expect("a glass of the list");
        let (d, f, c) = (glass.eval(587.5618), glass.eval(486.1327), glass.eval(656.2725));
        assert_eq!(rounded(d, 5), row[1], "{}: n_d {d}", row[0]);
        assert_eq!(rounded((d - 1.0) / (f - c), 2), row[2], "{}: v_d", row[0]);
    }
}

/// Each conductor at three of its source's rows: η, k as written there
/// (MgO's source is a formula: its table holds it to 6 decimals), and the
/// normal-incidence reflectance from them (6 decimals).
#[test]
fn conductors_are_their_sources() {
    let rows = rows("conductors.csv");
    assert_eq!(rows.len(), 3 * conductors::ALL.len());
    for row in rows {
        let (_, c) = conductors::ALL.iter().find(|(n, _)| *n == row[0]).expect("a conductor of the list");
        let nm: f64 = row[3].parse().expect("nm");
        let (eta, k): (f64, f64) = (row[4].parse().expect("η"), row[5].parse().expect("k"));
        let rounding = if row[0] == "MgO" { 5e-7 } else { 0.0 };
        assert!((c.eta().eval(nm) - eta).abs() <= rounding, "{} at {nm} nm", row[0]);
        assert_eq!(c.k().eval(nm), k, "{} at {nm} nm", row[0]);
        assert_eq!(rounded(c.reflectance().eval(nm), 6), row[6], "{} at {nm} nm", row[0]);
    }
}

/// The daylight formula reproduces the tabulated D illuminants to their
/// rounding: D50, D55, D75 (3 decimals) within half a unit, 0.0005; D65
/// (6 significant figures, a unit of 0.001 above 100; its odd 5 nm entries
/// the mean of their neighbours, cut) within 0.001; at every tabulated
/// wavelength from 300 to 780 nm (a millionth of a unit allowed for the
/// formula's own rounding in f64).
#[test]
fn the_daylight_formula_is_the_tabulated_daylight() {
    for (kelvin, table, within) in [
        (5000.0, &lights::D50, 5e-4 + 1e-9),
        (5500.0, &lights::D55, 5e-4 + 1e-9),
        (6500.0, &lights::CIE_D65, 1e-3 + 1e-9),
        (7500.0, &lights::D75, 5e-4 + 1e-9),
    ] {
        let formula = lights::daylight(kelvin).expect("in range");
        let worst =
            table.lambda().iter().map(|&l| (formula.eval(l) - table.eval(l)).abs()).fold(0.0, f64::max);
        assert!(worst <= within, "D{kelvin}: {worst}");
    }
    for bad in [3999.0, 25001.0, f64::NAN] {
        assert!(lights::daylight(bad).is_err(), "{bad}");
    }
}

/// Names: every listed light parses to itself, case aside; daylight
/// temperatures; surfaces (patches and metals); unknown names list the
/// nearest.
#[test]
fn spectra_by_name() {
    assert_eq!(Light::ALL.len(), lights::NAMES.len());
    for light in Light::ALL {
        assert_eq!(light.name().to_lowercase().parse::<Light>().expect("listed"), light);
    }
    assert_eq!(Light::APPENDIX.map(Light::name), ["A", "D65", "F11"]);
    let d6500 = lights::named("d6500").expect("daylight");
    assert!((d6500.eval(460.0) - lights::CIE_D65.eval(460.0)).abs() < 1e-3);
    let err = lights::named("F13").unwrap_err().to_string();
    assert!(
        err.contains("nearest: F11, F1 or F3; 49 names in all") && err.ends_with("found \"F13\""),
        "{err}"
    );
    assert!(lights::named("D1000").is_err() && lights::named("D").is_err());
    assert_eq!(
        speclab::data::surface_named("au").expect("a metal").as_ref(),
        &conductors::AU.reflectance().tabulated()
    );
    // Each metal's reflectance as a table, against the formula.
    let mut worst = 0.0f64;
    for (_, c) in &conductors::ALL {
        let (table, exact) = (c.reflectance().tabulated(), c.reflectance());
        for l in (0..=3500).map(|i| 380.0 + f64::from(i) * 0.1) {
            worst = worst.max((table.eval(l) - exact.eval(l)).abs());
        }
    }
    eprintln!("largest error of a conductor's reflectance table: {worst:e}");
    assert!(worst < 2e-5, "{worst}");
    assert!(speclab::data::surface_named("Kryptonite").is_err());
}
