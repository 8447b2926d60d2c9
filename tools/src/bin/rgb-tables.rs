//! Fits the built-in RGB spaces' tables and writes them as table files,
//! where speclab embeds them at build time: sRGB's in `data/rgb/`, the
//! wide-gamut spaces' in `wide-gamut/data/`. Run it from the workspace's
//! root when the fit or a space changes; the tests then hold the embedded
//! tables against fresh fits.
//!
//! ```text
//! cargo run --release -p speclab-tools --bin rgb-tables                 # every space, where it is embedded
//! cargo run --release -p speclab-tools --bin rgb-tables -- --space sRGB --out target/rgb
//! ```

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use speclab::color::rgb_table::{RESOLUTION, RgbTable};
use speclab::color::space::RgbSpace;

const USAGE: &str = "\
usage: rgb-tables [--space NAME]... [--out DIR] [--resolution N]
  --space NAME     a built-in space (sRGB, Display P3, Rec.2020, ACES2065-1, ACEScg); default all
  --out DIR        where <space>.rgbt goes (default: where it is embedded,
                   data/rgb for sRGB and wide-gamut/data for the others)
  --resolution N   nodes per axis, 2 to 256 (default 64)";

/// The file stem of a space's table: `sRGB` → `srgb`, `Display P3` →
/// `display-p3`, `Rec.2020` → `rec2020`.
fn stem(name: &str) -> String {
    name.to_lowercase().replace(' ', "-").replace('.', "")
}

/// Where a built-in space's table is embedded from.
fn embedded_folder(name: &str) -> PathBuf {
    PathBuf::from(if name == "sRGB" { "data/rgb" } else { "wide-gamut/data" })
}

fn parse_args() -> Result<(Vec<String>, Option<PathBuf>, usize), lexopt::Error> {
    use lexopt::prelude::*;
    let (mut spaces, mut out, mut n) = (Vec::new(), None, RESOLUTION);
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("space") => spaces.push(parser.value()?.string()?),
            Long("out") => out = Some(parser.value()?.into()),
            Long("resolution") => n = parser.value()?.parse()?,
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok((spaces, out, n))
}

fn main() -> ExitCode {
    let (names, out, n) = match parse_args() {
        Ok(args) => args,
        Err(e) => {
            eprintln!("rgb-tables: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let chosen: Vec<&RgbSpace> = RgbSpace::all()
        .into_iter()
        .filter(|s| names.is_empty() || names.iter().any(|n| n.eq_ignore_ascii_case(s.name())))
        .collect();
    if chosen.len() < names.len().max(1) {
        eprintln!("rgb-tables: expected built-in space names, found {names:?}\n{USAGE}");
        return ExitCode::from(2);
    }
    for space in chosen {
        let folder = out.clone().unwrap_or_else(|| embedded_folder(space.name()));
        if let Err(e) = std::fs::create_dir_all(&folder) {
            eprintln!("rgb-tables: {}: cannot create: {e}", folder.display());
            return ExitCode::FAILURE;
        }
        // A fresh space of the same definition: the built-in one may carry
        // the very table being remade.
        let fresh = RgbSpace::new(space.name(), space.primaries(), space.white_point(), space.illuminant())
            .expect("a built-in space's definition");
        let start = Instant::now();
        let table = RgbTable::fit(&fresh, n);
        let path = folder.join(format!("{}.rgbt", stem(space.name())));
        let written = table.save(&path).and_then(|()| RgbTable::load(&path));
        match written {
            Ok(back) if back == table => println!(
                "{}: fitted in {:.1} s, {} bytes to {}",
                space.name(),
                start.elapsed().as_secs_f64(),
                table.as_bytes().len(),
                path.display()
            ),
            Ok(_) => {
                eprintln!("rgb-tables: {} reads back different", path.display());
                return ExitCode::FAILURE;
            }
            Err(e) => {
                eprintln!("rgb-tables: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}
