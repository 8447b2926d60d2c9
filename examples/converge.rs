//! Accuracy in sequence: for one light × surface (default F11 × A1, the
//! hardest), every method at increasing sample counts, each over many
//! independent trials: bias, spread, RMS and 95th-percentile ΔE00.
//!
//! ```text
//! cargo run --release --example converge [-- --light F11 --surface A1 --trials 1000 --seed 1]
//! cargo run --release --example converge -- --all --csv        # all 18 pairs
//! cargo run --release --example converge -- --all --summary    # the README's table
//! ```

use std::io;
use std::num::NonZeroUsize;
use std::process::ExitCode;

use speclab::Role;
use speclab_cli::args::{self, fail, finish};
use speclab_cli::report;
use speclab_study::StudyError;
use speclab_study::evaluate::scene::{self, Choice, Depth};
use speclab_study::experiments::convergence;
use speclab_study::sampling::choice::{PdfKind, Sampling};
use speclab_study::sampling::strata::Strata;

const USAGE: &str = "\
usage: converge [--light NAME] [--surface NAME] [--trials T] [--seed S] [--depth D] [--all] [--csv] [--summary]
  --light NAME    a built-in light (below; default F11)
  --surface NAME  a built-in surface (below; default A1)
  --light-file PATH, --surface-file PATH   a spectrum from a file instead
  --trials T      independent trials per row for random and hero (default 1000)
  --seed S        base seed (default 1)
  --depth D       surfaces per path, 1 to 4: light × surface^D (default 1)
  --all           all 18 light × surface pairs
  --csv           machine-readable rows
  --summary       per light, the first n and M with RMS ΔE00 < 1 and < 0.5 for every patch,
                  and the count from which it stays below (implies --all, and every pdf and strata
                  unless --pdf or --strata is given)
  --pdf PDF       random and hero wavelengths' density: uniform (default), visible, light, balanced, all
  --strata S      how their primary numbers are spread: none (default), jitter, kronecker, all";

struct Args {
    light: Choice,
    surface: Choice,
    trials: NonZeroUsize,
    seed: u64,
    depth: Depth,
    all: bool,
    csv: bool,
    summary: bool,
    pdfs: Option<Vec<PdfKind>>,
    strata: Option<Vec<Strata>>,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut a = Args {
        light: Choice::Name("F11".into()),
        surface: Choice::Name("A1".into()),
        trials: NonZeroUsize::new(1000).unwrap_or(NonZeroUsize::MIN),
        seed: 1,
        depth: Depth::ONE,
        all: false,
        csv: false,
        summary: false,
        pdfs: None,
        strata: None,
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("light") => a.light = Choice::Name(parser.value()?.string()?),
            Long("surface") => a.surface = Choice::Name(parser.value()?.string()?),
            Long("light-file") => a.light = Choice::File(parser.value()?.into()),
            Long("surface-file") => a.surface = Choice::File(parser.value()?.into()),
            Long("trials") => a.trials = parser.value()?.parse_with(|v| args::count("trials", v))?,
            Long("seed") => a.seed = parser.value()?.parse()?,
            Long("depth") => a.depth = parser.value()?.parse()?,
            Long("all") => a.all = true,
            Long("csv") => a.csv = true,
            Long("summary") => a.summary = true,
            Long("pdf") => {
                let v = parser.value()?.string()?;
                a.pdfs = Some(if v == "all" {
                    PdfKind::ALL.to_vec()
                } else {
                    vec![v.parse().map_err(|e: speclab::Error| e.to_string())?]
                });
            }
            Long("strata") => {
                let v = parser.value()?.string()?;
                a.strata = Some(if v == "all" {
                    Strata::ALL.to_vec()
                } else {
                    vec![v.parse().map_err(|e: speclab::Error| e.to_string())?]
                });
            }
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", args::names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    a.all |= a.summary;
    Ok(a)
}

/// Every pdf × strata asked for; all of them for a summary that names none.
fn samplings(args: &Args) -> Vec<Sampling> {
    let every = args.summary && args.pdfs.is_none() && args.strata.is_none();
    let pdfs = args
        .pdfs
        .clone()
        .unwrap_or_else(|| if every { PdfKind::ALL.to_vec() } else { vec![PdfKind::Uniform] });
    let strata =
        args.strata.clone().unwrap_or_else(|| if every { Strata::ALL.to_vec() } else { vec![Strata::None] });
    pdfs.iter().flat_map(|&pdf| strata.iter().map(move |&strata| Sampling { pdf, strata })).collect()
}

fn rows(args: &Args) -> Result<Vec<convergence::ConvergenceRow>, StudyError> {
    let (lights, surfaces) = if args.all {
        (scene::builtin_lights(), scene::builtin_surfaces())
    } else {
        (vec![args.light.resolve(Role::Light)?], vec![args.surface.resolve(Role::Reflectance)?])
    };
    let mut rows = Vec::new();
    for light in &lights {
        for surface in &surfaces {
            let samplings = samplings(args);
            rows.extend(convergence::sequence(
                light,
                surface,
                &samplings,
                args.depth,
                args.trials,
                args.seed,
            )?);
        }
    }
    Ok(rows)
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => return fail("converge", format!("{e}\n{USAGE}")),
    };
    let rows = match rows(&args) {
        Ok(rows) => rows,
        Err(e) => return fail("converge", e),
    };
    let (out, trials) = (&mut io::stdout().lock(), args.trials.get());
    let written = if args.summary {
        report::converge_summary(out, &rows, trials, args.seed)
    } else if args.csv {
        report::converge_csv(out, &rows)
    } else {
        report::converge_table(out, &rows, trials, args.seed)
    };
    finish("converge", written)
}
