//! The built-in data: all twelve static tables (samples, coefficients,
//! breaks, prefix integrals) are what the run-time loader and constructor
//! make of the same files, and the range is their common support.

use speclab::data::cie1931::{X_BAR, Y_BAR, Z_BAR};
use speclab::data::{Light, Patch};
use speclab::io::Load;
use speclab::{Interpolation, LAMBDA_MAX, LAMBDA_MIN, Role, TabulatedSpectrum};

fn built_in() -> [(&'static str, &'static TabulatedSpectrum); 12] {
    [
        ("illuminant_a", Light::A.spectrum()),
        ("illuminant_d65", Light::D65.spectrum()),
        ("illuminant_f11", Light::F11.spectrum()),
        ("patch_e2", Patch::E2.spectrum()),
        ("patch_f4", Patch::F4.spectrum()),
        ("patch_g4", Patch::G4.spectrum()),
        ("patch_h4", Patch::H4.spectrum()),
        ("patch_j4", Patch::J4.spectrum()),
        ("patch_a1", Patch::A1.spectrum()),
        ("cie1931_x", &X_BAR),
        ("cie1931_y", &Y_BAR),
        ("cie1931_z", &Z_BAR),
    ]
}

#[test]
fn static_tables_equal_runtime_load() {
    for (stem, built_in) in built_in() {
        let path = format!("{}/data/{stem}.txt", env!("CARGO_MANIFEST_DIR"));
        let loaded = Load::new(built_in.role()).file(&path).expect("valid data");
        assert_eq!(&loaded, built_in, "{stem}");
        let (lambda, values) = (built_in.lambda().to_vec(), built_in.values().to_vec());
        let built = TabulatedSpectrum::new(lambda, values, built_in.role()).expect("valid data");
        assert_eq!(&built, built_in, "{stem}");
    }
}

#[test]
fn values_are_exactly_as_printed() {
    assert_eq!(Light::A.spectrum().values()[0], 0.045345);
    assert_eq!(Light::F11.spectrum().eval(545.0), 72.84);
    assert_eq!(Patch::E2.spectrum().values().len(), 36);
    assert_eq!(Y_BAR.eval(555.0), 1.0);
    assert_eq!(speclab::color::XYZ_TO_SRGB[0], [3.2410, -1.5374, -0.4986]);
    assert_eq!(speclab::color::XYZ_TO_SRGB[2], [0.0556, -0.2040, 1.0570]);
}

#[test]
fn range_is_common_support() {
    let (lo, hi) = built_in()
        .iter()
        .map(|(_, s)| s.support())
        .fold((f64::MIN, f64::MAX), |(lo, hi), (a, b)| (lo.max(a), hi.min(b)));
    assert_eq!((lo, hi), (LAMBDA_MIN, LAMBDA_MAX));
}

#[test]
fn roles_pick_interpolation() {
    for (stem, s) in built_in() {
        let (role, interpolation) = match &stem[..4] {
            "illu" => (Role::Light, Interpolation::Linear),
            "patc" => (Role::Reflectance, Interpolation::Cubic),
            _ => (Role::Observer, Interpolation::Cubic),
        };
        assert_eq!((s.role(), s.interpolation()), (role, interpolation), "{stem}");
    }
}
