//! Checks the four table files before they are embedded: a damaged or
//! foreign file fails the build with its name and what is wrong.

fn main() {
    for stem in ["display-p3", "rec2020", "aces2065-1", "acescg"] {
        let path = format!("data/{stem}.rgbt");
        println!("cargo:rerun-if-changed={path}");
        if let Err(e) = speclab_tables::rgb_file::check_file(std::path::Path::new(&path)) {
            println!("cargo:warning={e}");
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    }
}
