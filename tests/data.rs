//! The built-in data: the static tables are what the run-time loader makes
//! of the same files, and the range is their common support.

use speclab::data::{CIE_X, CIE_Y, CIE_Z, Light, Patch};
use speclab::{LAMBDA_MAX, LAMBDA_MIN, Role, TabulatedSpectrum};

#[test]
fn static_tables_equal_runtime_parse() {
    let files = [
        ("illuminant_a", Light::A.spectrum()),
        ("illuminant_d65", Light::D65.spectrum()),
        ("illuminant_f11", Light::F11.spectrum()),
        ("patch_e2", Patch::E2.spectrum()),
        ("patch_a1", Patch::A1.spectrum()),
        ("cie1931_z", &CIE_Z),
    ];
    for (stem, built_in) in files {
        let path = format!("{}/data/{stem}.txt", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("data file");
        let parsed = TabulatedSpectrum::parse(&text, &path, built_in.role()).expect("valid data");
        assert_eq!(&parsed, built_in, "{stem}");
    }
}

#[test]
fn values_are_exactly_as_printed() {
    assert_eq!(Light::A.spectrum().values()[0], 0.045345);
    assert_eq!(Light::F11.spectrum().eval(545.0), 72.84);
    assert_eq!(Patch::E2.spectrum().values().len(), 36);
    assert_eq!(CIE_Y.eval(555.0), 1.0);
    assert_eq!(speclab::color::XYZ_TO_SRGB[0], [3.2410, -1.5374, -0.4986]);
}

#[test]
fn range_is_common_support() {
    let all = Light::ALL
        .map(|l| l.spectrum().support())
        .into_iter()
        .chain(Patch::ALL.map(|p| p.spectrum().support()))
        .chain([CIE_X.support(), CIE_Y.support(), CIE_Z.support()]);
    let (lo, hi) = all.fold((f64::MIN, f64::MAX), |(lo, hi), (a, b)| (lo.max(a), hi.min(b)));
    assert_eq!((lo, hi), (LAMBDA_MIN, LAMBDA_MAX));
}

#[test]
fn roles_pick_interpolation() {
    assert_eq!(Light::F11.spectrum().role(), Role::Light);
    assert_eq!(Light::F11.spectrum().interpolation(), speclab::Interpolation::Linear);
    assert_eq!(Patch::G4.spectrum().interpolation(), speclab::Interpolation::Cubic);
    assert_eq!(CIE_X.interpolation(), speclab::Interpolation::Cubic);
}
