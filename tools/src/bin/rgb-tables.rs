//! Fits the built-in RGB spaces' tables and writes each twice: its
//! coefficients as fitted (`f32`, version 1, `tools/rgb-f32/`, the source
//! the tests compare against) and compact (version 2), where speclab
//! embeds it at build time: sRGB's in `data/rgb/`, the wide-gamut spaces'
//! in `wide-gamut/data/`. Run it from the workspace's root when the fit or
//! a space changes; `--compact-only` remakes the compact files from the
//! kept `f32` ones without fitting.
//!
//!
//! A space of one's own: its name, primaries, white and illuminant (a
//! built-in light's name), fitted and written to `--out` as
//! `<name>.rgbt`, compact, for a downstream crate to embed
//! (`speclab::rgb_table!`, as `examples/build-data` does):
//!
//! ```text
//! cargo run --release -p speclab-tools --bin rgb-tables                 # every space, where it is embedded
//! cargo run --release -p speclab-tools --bin rgb-tables -- --compact-only
//! cargo run --release -p speclab-tools --bin rgb-tables -- --space sRGB --out target/rgb
//! cargo run --release -p speclab-tools --bin rgb-tables -- --name rec709-e \
//!     --primaries 0.64,0.33,0.30,0.60,0.15,0.06 --white 0.3333333333333333,0.3333333333333333 --illuminant E \
//!     --out examples/build-data/data
//! ```

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use speclab::color::rgb_table::Quantizer;
use speclab::color::rgb_table::{RESOLUTION, RgbTable};
use speclab::color::space::RgbSpace;

const USAGE: &str = "\
usage: rgb-tables [--space NAME]... [--out DIR] [--resolution N] [--compact-only]
       rgb-tables --name NAME --primaries RX,RY,GX,GY,BX,BY --white X,Y --illuminant LIGHT --out DIR
  --space NAME     a built-in space (sRGB, Display P3, Rec.2020, ACES2065-1, ACEScg); default all
  --out DIR        where <space>.rgbt (compact) and <space>-f32.rgbt (as fitted) go
                   (default: the compact one where it is embedded, data/rgb for sRGB and
                   wide-gamut/data for the others; the fitted one in tools/rgb-f32)
  --resolution N   nodes per axis, 2 to 256 (default 64)
  --compact-only   no fit: the compact files from the fitted ones in tools/rgb-f32
  --name NAME      a space of one's own (with --primaries, --white, --illuminant, --out):
                   its compact table to DIR/NAME.rgbt";

/// The file stem of a space's table: `sRGB` → `srgb`, `Display P3` →
/// `display-p3`, `Rec.2020` → `rec2020`.
fn stem(name: &str) -> String {
    name.to_lowercase().replace(' ', "-").replace('.', "")
}

/// Where a built-in space's compact table is embedded from.
fn embedded_folder(name: &str) -> PathBuf {
    PathBuf::from(if name == "sRGB" { "data/rgb" } else { "wide-gamut/data" })
}

/// A space's rounding: the built-in one, and for ACES2065-1, whose
/// coefficients reach ±2.6 million (ten times the others'), one more
/// mantissa bit (with the built-in 12 its worst round trip on the 9³ grid
/// grew from 0.3627 to 0.3638; with 13 it is 0.3625).
fn quantizer(name: &str) -> Quantizer {
    let mut q = Quantizer::DEFAULT;
    if name == "ACES2065-1" {
        q.float.mantissa += 1;
    }
    q
}

/// The command line.
struct Args {
    spaces: Vec<String>,
    out: Option<PathBuf>,
    resolution: usize,
    compact_only: bool,
    /// A space of one's own: name, primaries and white (8 numbers), illuminant.
    own: Option<(String, Vec<f64>, String)>,
}

/// Comma-separated numbers.
fn numbers(text: &str) -> Result<Vec<f64>, lexopt::Error> {
    text.split(',').map(|v| v.trim().parse::<f64>().map_err(|e| lexopt::Error::from(e.to_string()))).collect()
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut args =
        Args { spaces: Vec::new(), out: None, resolution: RESOLUTION, compact_only: false, own: None };
    let (mut name, mut primaries, mut white, mut illuminant) = (None, None, None, None);
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("space") => args.spaces.push(parser.value()?.string()?),
            Long("name") => name = Some(parser.value()?.string()?),
            Long("primaries") => primaries = Some(numbers(&parser.value()?.string()?)?),
            Long("white") => white = Some(numbers(&parser.value()?.string()?)?),
            Long("illuminant") => illuminant = Some(parser.value()?.string()?),
            Long("out") => args.out = Some(parser.value()?.into()),
            Long("resolution") => args.resolution = parser.value()?.parse()?,
            Long("compact-only") => args.compact_only = true,
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    match (name, primaries, white, illuminant) {
        (None, None, None, None) => {}
        (Some(name), Some(mut p), Some(w), Some(light))
            if p.len() == 6 && w.len() == 2 && args.out.is_some() =>
        {
            p.extend(w);
            args.own = Some((name, p, light));
        }
        _ => {
            return Err(
                "expected --name, --primaries (6 numbers), --white (2) and --illuminant together, with --out"
                    .into(),
            );
        }
    }
    Ok(args)
}

/// Fits a space of one's own and writes its compact table to
/// `out/<name>.rgbt`.
fn make_own(name: &str, p: &[f64], light: &str, out: &Path, resolution: usize) -> Result<(), String> {
    let illuminant = match speclab::data::lights::named(light).map_err(|e| e.to_string())? {
        std::borrow::Cow::Borrowed(light) => light,
        std::borrow::Cow::Owned(light) => Box::leak(Box::new(light)),
    };
    let name: &'static str = Box::leak(name.to_string().into_boxed_str());
    let primaries = [[p[0], p[1]], [p[2], p[3]], [p[4], p[5]]];
    let space = RgbSpace::new(name, primaries, [p[6], p[7]], illuminant).map_err(|e| e.to_string())?;
    let start = Instant::now();
    let table = RgbTable::fit(&space, resolution).compact();
    let path = out.join(format!("{name}.rgbt"));
    write(&table, &path)?;
    let seconds = start.elapsed().as_secs_f64();
    println!(
        "{name}: fitted and made compact in {seconds:.1} s, {} bytes to {}",
        table.as_bytes().len(),
        path.display()
    );
    Ok(())
}

/// Writes `table` to `path` and reads it back: an error unless it reads
/// back the same.
fn write(table: &RgbTable, path: &Path) -> Result<(), String> {
    if let Some(folder) = path.parent() {
        std::fs::create_dir_all(folder).map_err(|e| format!("{}: cannot create: {e}", folder.display()))?;
    }
    match table.save(path).and_then(|()| RgbTable::load(path)) {
        Ok(back) if back == *table => Ok(()),
        Ok(_) => Err(format!("{} reads back different", path.display())),
        Err(e) => Err(e.to_string()),
    }
}

/// Fits (or, with `--compact-only`, reads) one space's table and writes it
/// as fitted and compact.
fn make(space: &RgbSpace, args: &Args) -> Result<(), String> {
    let name = stem(space.name());
    let (fitted_path, compact_path) = match &args.out {
        Some(dir) => (dir.join(format!("{name}-f32.rgbt")), dir.join(format!("{name}.rgbt"))),
        None => (
            Path::new("tools/rgb-f32").join(format!("{name}.rgbt")),
            embedded_folder(space.name()).join(format!("{name}.rgbt")),
        ),
    };
    let start = Instant::now();
    let fitted = if args.compact_only {
        RgbTable::load(&fitted_path).map_err(|e| e.to_string())?
    } else {
        // A fresh space of the same definition: the built-in one may carry
        // the very table being remade.
        let fresh = RgbSpace::new(space.name(), space.primaries(), space.white_point(), space.illuminant())
            .map_err(|e| e.to_string())?;
        let table = RgbTable::fit(&fresh, args.resolution);
        write(&table, &fitted_path)?;
        table
    };
    let seconds = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let compact = fitted.compact_with(quantizer(space.name()));
    write(&compact, &compact_path)?;
    println!(
        "{}: {} in {seconds:.1} s, {} bytes; compact in {:.2} s, {} bytes to {}",
        space.name(),
        if args.compact_only { "read" } else { "fitted" },
        fitted.as_bytes().len(),
        start.elapsed().as_secs_f64(),
        compact.as_bytes().len(),
        compact_path.display()
    );
    Ok(())
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => {
            eprintln!("rgb-tables: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    if let (Some((name, p, light)), Some(out)) = (&args.own, &args.out) {
        return match make_own(name, p, light, out, args.resolution) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("rgb-tables: {e}");
                ExitCode::FAILURE
            }
        };
    }
    let chosen: Vec<&RgbSpace> = RgbSpace::all()
        .into_iter()
        .filter(|s| args.spaces.is_empty() || args.spaces.iter().any(|n| n.eq_ignore_ascii_case(s.name())))
        .collect();
    if chosen.len() < args.spaces.len().max(1) {
        eprintln!("rgb-tables: expected built-in space names, found {:?}\n{USAGE}", args.spaces);
        return ExitCode::from(2);
    }
    for space in chosen {
        if let Err(e) = make(space, &args) {
            eprintln!("rgb-tables: {e}");
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}
