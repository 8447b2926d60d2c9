//! Turns `data/*` into `static` spectra with `speclab_tables::Codegen`: the
//! same parser, validation and errors as speclab's run-time loading. A bad
//! file fails this build with `file:line:column: expected …, found …`.
//! Only `speclab-tables` (std only) is compiled for this script. Any of
//! speclab's own data sets goes through it the same way: here CIE LED-B3
//! and the extinction coefficient of gold, from speclab's `data/`. And the
//! RGB table of a space of this crate's own (`data/rec709-e.rgbt`, made
//! once by speclab's `rgb-tables`), checked here before the program embeds
//! it with `speclab::rgb_table!`.

use speclab_tables::{Codegen, Role};

fn fail(e: &dyn std::fmt::Display) -> ! {
    eprintln!("error: {e}");
    std::process::exit(1);
}

fn main() {
    let mut code = Codegen::new();
    for (path, name, role) in [
        ("data/led.csv", "LED", Role::Light),
        ("data/leaf.json", "LEAF", Role::Reflectance),
        ("../../data/lights/LED-B3.csv", "LED_B3", Role::Light),
        ("../../data/conductors/Au.k.csv", "GOLD_K", Role::Extinction),
    ] {
        println!("cargo:rerun-if-changed={path}");
        code.file(path, name, role).unwrap_or_else(|e| fail(&e));
    }
    let table = "data/rec709-e.rgbt";
    println!("cargo:rerun-if-changed={table}");
    speclab_tables::rgb_file::check_file(std::path::Path::new(table)).unwrap_or_else(|e| fail(&e));
    let out = std::path::Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("spectra.rs");
    std::fs::write(out, code.source()).expect("OUT_DIR is writable");
}
