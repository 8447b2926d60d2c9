//! The build-time path: `build.rs` reads every data file with
//! `speclab::samples::read_brace`, the function called here. A malformed
//! copy of a real data file, in a temporary directory, gives the
//! `file:line:column: expected …, found …` message that fails the build.
//! (The real build is not broken: the copy is not in `data/`.)

use std::path::PathBuf;

use speclab::Role;
use speclab::samples::read_brace;

fn malformed_copy(name: &str, from: &str, to: &str) -> (PathBuf, String) {
    let source = format!("{}/data/patch_g4.txt", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(source).expect("data file").replacen(from, to, 1);
    let dir = std::env::temp_dir().join(format!("speclab-build-data-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, &text).expect("write copy");
    (path, text)
}

fn build_error(name: &str, from: &str, to: &str) -> String {
    let (path, text) = malformed_copy(name, from, to);
    let origin = path.display().to_string();
    let message = read_brace(&text, &origin, Role::Reflectance).expect_err("malformed").to_string();
    std::fs::remove_file(&path).ok();
    message.replace(&origin, name)
}

#[test]
fn real_data_file_reads() {
    let text = include_str!("../data/patch_g4.txt");
    assert_eq!(read_brace(text, "patch_g4.txt", Role::Reflectance).expect("valid").lambda.len(), 36);
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

#[test]
fn reflectance_above_one() {
    assert_eq!(
        build_error("range.txt", "{730, 0.7357}", "{730, 7.357}"),
        "range.txt:6:7: expected a value in [0, 1], found 7.357"
    );
}
