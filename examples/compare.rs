//! The assignment's main user story: one light and one surface, the exact
//! reference beside every technique, with sRGB, ΔE00 and, over many trials,
//! RMS ΔE00.
//!
//! ```text
//! cargo run --release --example compare -- --light F11 --surface G4 --n 100 --m 16 --k 4
//! cargo run --release --example compare -- --light-file lamp.csv --surface A1 --normalize luminance --white-balance
//! ```

use std::io;
use std::process::ExitCode;

use speclab::Role;
use speclab_cli::args::{self, fail, finish};
use speclab_cli::report;
use speclab_study::StudyError;
use speclab_study::display::{Exposure, GamutMap, PixelPipeline};
use speclab_study::evaluate::scene::{Choice, Named};
use speclab_study::experiments::compare::{self, CompareOptions};

const USAGE: &str = "\
usage: compare [options]
  --light NAME | --light-file PATH      a built-in light (below) or a file (default D65)
  --surface NAME | --surface-file PATH  a built-in surface (below) or a file (default A1)
  --n N          random and hero samples (default 100)
  --m M          regular buckets and fitted wavelengths, 1 to 64 (default 16)
  --depth D      surfaces per path, 1 to 4: light × surface^D (default 1)
  --k K          hero width: 1, 2, 3, 4, 8 or 16 wavelengths (default 4)
  --seed S       seed of the single estimates and base seed of the trials (default 1)
  --trials T     trials for the RMS ΔE00 column (default 200)
  --normalize none|power|luminance   scale the light first (default none)
  --white-balance                    Bradford-adapt the light's white to D65's before sRGB
  --pdf uniform|visible|light|balanced           random and hero wavelengths' density (default uniform)
  --strata none|jitter|kronecker          how their primary numbers are spread (default none)
  --gamut clip|chroma    how terminal swatches show out-of-gamut colours (default chroma: keep
                         hue and luminance, desaturate); the numbers stay unclamped";

struct Args {
    light: Choice,
    surface: Choice,
    settings: CompareOptions,
    gamut: GamutMap,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut a = Args {
        light: Choice::Name("D65".into()),
        surface: Choice::Name("A1".into()),
        settings: CompareOptions::default(),
        gamut: GamutMap::default(),
    };
    let s = &mut a.settings;
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("light") => a.light = Choice::Name(parser.value()?.string()?),
            Long("light-file") => a.light = Choice::File(parser.value()?.into()),
            Long("surface") => a.surface = Choice::Name(parser.value()?.string()?),
            Long("surface-file") => a.surface = Choice::File(parser.value()?.into()),
            Long("n") => s.n = parser.value()?.parse_with(|v| args::count("samples", v))?,
            Long("m") => s.m = parser.value()?.parse_with(args::buckets)?,
            Long("k") => s.k = parser.value()?.parse_with(args::hero_width)?,
            Long("seed") => s.seed = parser.value()?.parse()?,
            Long("depth") => s.depth = parser.value()?.parse()?,
            Long("trials") => s.trials = parser.value()?.parse_with(|v| args::count("trials", v))?,
            Long("normalize") => s.viewing.normalize = parser.value()?.parse()?,
            Long("white-balance") => s.viewing.white_balance = true,
            Long("pdf") => s.sampling.pdf = parser.value()?.parse()?,
            Long("strata") => s.sampling.strata = parser.value()?.parse()?,
            Long("gamut") => a.gamut = parser.value()?.parse()?,
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", args::names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(a)
}

fn run(args: &Args) -> Result<(Named, Named, Vec<compare::Line>), StudyError> {
    let light = args.light.resolve(Role::Light)?;
    let light = Named::new(light.name, args.settings.viewing.light(&light.spectrum)?);
    let surface = args.surface.resolve(Role::Reflectance)?;
    let lines = compare::compare(&light, &surface, &args.settings)?;
    Ok((light, surface, lines))
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => return fail("compare", format!("{e}\n{USAGE}")),
    };
    match run(&args) {
        Ok((light, surface, lines)) => {
            let white = args.settings.viewing.white(&light.spectrum);
            let swatches = args::color().then(|| PixelPipeline::new(Exposure::fit_white(white), args.gamut));
            let out = &mut io::stdout().lock();
            let written =
                report::compare_table(out, &light.name, &surface.name, &args.settings, &lines, swatches);
            finish("compare", written)
        }
        Err(e) => fail("compare", e),
    }
}
