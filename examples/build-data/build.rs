//! Turns `data/*` into `static` spectra with speclab's build helper: the
//! same parser, validation and errors as run-time loading. A bad file
//! fails this build with `file:line:column: expected …, found …`.

use speclab::Role;
use speclab::codegen::Codegen;

fn main() {
    let mut code = Codegen::new();
    for (path, name, role) in
        [("data/led.csv", "LED", Role::Light), ("data/leaf.json", "LEAF", Role::Reflectance)]
    {
        println!("cargo:rerun-if-changed={path}");
        if let Err(e) = code.file(path, name, role) {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    }
    let out = std::path::Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("spectra.rs");
    std::fs::write(out, code.source()).expect("OUT_DIR is writable");
}
