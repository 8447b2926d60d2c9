//! The build-time path: `build.rs` turns every data file into code with
//! `speclab_tables::Codegen`, the build helper users get too. These tests
//! drive the same calls: a malformed copy of a real data file (in a
//! temporary directory, so the real build is not broken) gives the
//! `file:line:column: expected …, found …` message that fails the build.
//! (That the generated statics are the run-time loader's tables is
//! `tests/truth/data.rs`.)

use std::path::PathBuf;

use speclab_tables::{Codegen, Role};

fn data_file(stem: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data").join(format!("{stem}.txt"))
}

/// What `build.rs` would say of `data/patch_g4.txt` with `from` replaced by `to`.
fn build_error(name: &str, from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(data_file("patch_g4")).expect("data file").replacen(from, to, 1);
    let dir = std::env::temp_dir().join(format!("speclab-build-data-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, &text).expect("write copy");
    let mut code = Codegen::new().with_crate_path("crate");
    let message = code.file(&path, "G4", Role::Reflectance).expect_err("malformed").to_string();
    std::fs::remove_dir_all(&dir).ok();
    message.replace(&path.display().to_string(), name)
}

#[test]
fn typo_in_a_number() {
    assert_eq!(
        build_error("typo.txt", "{450, 0.0176}", "{450, 0.0l76}"),
        "typo.txt:2:7: expected a number, found \"0.0l76\""
    );
}

#[test]
fn missing_brace() {
    assert_eq!(
        build_error("brace.txt", "{460, 0.0174}", "{460, 0.0174"),
        "brace.txt:2:30: expected a number, found '{'"
    );
}

#[test]
fn wavelength_out_of_order() {
    assert_eq!(
        build_error("order.txt", "{520, 0.0119}", "{500, 0.0119}"),
        "order.txt:3:1: expected a wavelength greater than 510 nm, found 500 nm"
    );
}

/// A reflectance above 1 is refused at build time (not clamped to 1).
#[test]
fn reflectance_above_one() {
    assert_eq!(
        build_error("range.txt", "{730, 0.7357}", "{730, 7.357}"),
        "range.txt:6:7: expected a value in [0, 1], found 7.357"
    );
}

#[test]
fn too_few_and_short_range() {
    let text = std::fs::read_to_string(data_file("patch_g4")).expect("data file");
    let first_line = text.lines().next().expect("a line").trim_end_matches([',', ' ']);
    let last_tuple = first_line.rfind('{').expect("a tuple") + 1;
    let mut code = Codegen::new();
    let err = code.text(first_line, "short.txt", "G4", Role::Reflectance).expect_err("short");
    let want = format!("short.txt:1:{last_tuple}: expected samples covering 380-730 nm, found 380-440 nm");
    assert_eq!(err.to_string(), want);
    let err = code.text("{380, 0.1}, {730, 0.2}", "two.txt", "G4", Role::Reflectance).expect_err("too few");
    assert_eq!(err.to_string(), "two.txt:1:13: expected at least 4 samples, found 2");
    assert!(code.source().is_empty(), "nothing is emitted for a bad file");
}

#[test]
fn names_must_be_identifiers() {
    for bad in ["", "_", "1LAMP", "MY LAMP", "LAMP;fn", "Lämp"] {
        let err = Codegen::new().text("380 1\n730 1", "lamp.txt", bad, Role::Light).expect_err(bad);
        assert_eq!(err.to_string(), format!("expected a Rust identifier, found {bad:?}"));
    }
    assert!(Codegen::new().text("380 1\n730 1", "lamp.txt", "_LAMP_2", Role::Light).is_ok());
}

#[test]
fn every_format_and_a_hostile_origin() {
    let mut code = Codegen::default();
    code.text("nm,power\n380,1\n730,2\n", "lamp.csv", "CSV", Role::Light).expect("columns");
    code.text(r#"{"wavelengths": [380, 730], "values": [1, 2]}"#, "x\n}; fn evil() {", "JSON", Role::Light)
        .expect("json");
    let source = code.source();
    assert!(source.contains("pub static CSV: ::speclab::TabulatedSpectrum"));
    assert!(source.contains(r#"from "x\n}; fn evil() {""#), "the origin is escaped in the doc comment");
    assert!(!source.contains("\n}; fn evil"));
}
