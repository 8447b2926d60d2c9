//! The swatch sheet: every light × patch by every method, as a PNG you can
//! look at. Every pixel of a random or hero swatch is its own independent
//! estimate with n samples, so their noise shows as grain; the reference and
//! the fixed buckets are flat, so their error shows as a shift of colour.
//!
//! Columns: reference, random (n), hero (n, K = 4), regular-centre (M),
//! regular-box (M), and two of the 4 pdfs × 3 strata that renderers use:
//! hero with jittered strata (stratification alone), and hero with jittered
//! strata drawn from the light's pdf (importance sampling on top, which
//! matters on F11's spikes). Two columns rather than twelve keep the sheet
//! readable; `compare --pdf … --strata …` shows any other.
//!
//! ```text
//! cargo run --release --example swatches
//! cargo run --release --example swatches -- --n 64 --m 32 --white-balance --gamut clip --out sheet.png
//! ```

use std::path::PathBuf;
use std::process::ExitCode;

use speclab_cli::args::{self, fail};
use speclab_cli::{png, sheet};
use speclab_study::evaluate::scene;
use speclab_study::experiments::swatches::{self, SwatchOptions};

const USAGE: &str = "\
usage: swatches [--n N] [--m M] [--seed S] [--white-balance] [--gamut clip|chroma] [--out PATH]
  --n N            samples per estimate for random and hero (default 16, a renderer's count)
  --m M            buckets for regular sampling, 1 to 64 (default 16)
  --seed S         base seed: every pixel's estimate has a seed derived from it (default 1)
  --white-balance  Bradford-adapt each light's white to D65's before display
  --gamut MAP      out-of-gamut colours: chroma (default: keep hue and luminance,
                   desaturate until the colour fits) or clip (per channel)
  --out PATH       where to write the PNG (default swatches.png)";

struct Args {
    settings: SwatchOptions,
    out: PathBuf,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut args = Args { settings: SwatchOptions::default(), out: PathBuf::from("swatches.png") };
    let s = &mut args.settings;
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("n") => s.n = parser.value()?.parse_with(|v| args::count("samples", v))?,
            Long("m") => s.m = parser.value()?.parse_with(args::buckets)?,
            Long("seed") => s.seed = parser.value()?.parse()?,
            Long("white-balance") => s.white_balance = true,
            Long("gamut") => s.gamut = parser.value()?.parse()?,
            Long("out") => args.out = parser.value()?.into(),
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(args)
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => return fail("swatches", format!("{e}\n{USAGE}")),
    };
    let (lights, patches) = (scene::builtin_lights(), scene::builtin_surfaces());
    let swatches = match swatches::render(&lights, &patches, &args.settings) {
        Ok(swatches) => swatches,
        Err(e) => return fail("swatches", e),
    };
    let layout = sheet::Layout::new(&swatches);
    let image = png::Image { width: layout.width(), height: layout.height(), rgb: sheet::draw(&swatches) };
    match png::write_file(&args.out, &image) {
        Ok(()) => {
            eprintln!("swatches: wrote {} ({} × {} pixels)", args.out.display(), image.width, image.height);
            ExitCode::SUCCESS
        }
        Err(e) => fail("swatches", format!("{}: {e}", args.out.display())),
    }
}
