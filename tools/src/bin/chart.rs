//! Speed against accuracy in one picture: for each light, every charted
//! configuration's measured ns per estimate against its worst-patch RMS
//! ΔE00, one curve per method, the Pareto front drawn thick, and guides at
//! the budgets ΔE00 = 1 and 0.5.
//!
//! Writes `chart.csv` (one row per point), `chart.svg` (drawn by `plotters`'
//! SVG backend: no font or graphics library is needed to build it) and
//! `chart.png` (the SVG rendered by `resvg`, with the system's fonts; skipped
//! with a warning where there are none).
//!
//! ```text
//! cargo run --release -p speclab-tools --bin chart                   # writes chart.* here
//! cargo run --release -p speclab-tools --bin chart -- --out docs     # the README's picture
//! cargo run --release -p speclab-tools --bin chart -- --quick --out target/chart
//! cargo run --release -p speclab-tools --bin chart -- --light F11 --trials 1000 --seed 2
//! ```

use std::fs::File;
use std::io::{BufWriter, Write};
use std::num::NonZeroUsize;
use std::path::PathBuf;
use std::process::ExitCode;

use speclab::Role;
use speclab_cli::report;
use speclab_study::evaluate::scene::{self, Choice, Depth, Named};
use speclab_study::planning::chart::{self, Point};
use speclab_tools::chart as draw;

const USAGE: &str = "\
usage: chart [--trials T] [--seed S] [--light NAME|all] [--depth D] [--out DIR] [--quick]
  --trials T     trials per Monte Carlo point and patch (default 300)
  --seed S       base seed (default 1)
  --light NAME   A, D65, F11, or all (default all); repeat for several
  --depth D      surfaces per path, 1 to 4: light × patch^D (default 1)
  --out DIR      where chart.csv, chart.svg and chart.png go (default: the current directory;
                 `--out docs` replaces the README's picture)
  --quick        40 trials, for a fast check (CI)";

struct Args {
    trials: NonZeroUsize,
    seed: u64,
    lights: Vec<String>,
    depth: Depth,
    out: PathBuf,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let trials = |n: usize| NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
    let mut args =
        Args { trials: trials(300), seed: 1, lights: Vec::new(), depth: Depth::ONE, out: PathBuf::from(".") };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("trials") => args.trials = parser.value()?.parse()?,
            Long("seed") => args.seed = parser.value()?.parse()?,
            Long("light") => args.lights.push(parser.value()?.string()?),
            Long("depth") => args.depth = parser.value()?.parse()?,
            Long("out") => args.out = parser.value()?.into(),
            Long("quick") => args.trials = trials(40),
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(args)
}

/// The lights asked for: every built-in one for none or `all`.
fn lights(names: &[String]) -> Result<Vec<Named>, speclab_study::StudyError> {
    if names.is_empty() || names.iter().any(|n| n.eq_ignore_ascii_case("all")) {
        return Ok(scene::builtin_lights());
    }
    names.iter().map(|n| Choice::Name(n.clone()).resolve(Role::Light)).collect()
}

/// Every light's points, in the order of the lights.
fn points(args: &Args) -> Result<Vec<Point>, speclab_study::StudyError> {
    let surfaces = scene::builtin_surfaces();
    let mut all = Vec::new();
    for light in lights(&args.lights)? {
        eprintln!("chart: measuring under {} ({} trials per point and patch)", light.name, args.trials);
        all.extend(chart::points(&light, &surfaces, &chart::curves(), args.depth, args.trials, args.seed)?);
    }
    Ok(all)
}

/// Writes `text` to `path`.
fn write(path: &PathBuf, text: &[u8]) -> Result<(), String> {
    File::create(path).and_then(|mut f| f.write_all(text)).map_err(|e| format!("{}: {e}", path.display()))
}

fn run(args: &Args) -> Result<(), String> {
    let points = points(args).map_err(|e| e.to_string())?;
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let csv = args.out.join("chart.csv");
    let file = File::create(&csv).map_err(|e| format!("{}: {e}", csv.display()))?;
    let mut out = BufWriter::new(file);
    report::chart_csv(&mut out, &points)
        .and_then(|()| out.flush())
        .map_err(|e| format!("{}: {e}", csv.display()))?;
    let svg = draw::svg(&points, args.trials.get())?;
    write(&args.out.join("chart.svg"), svg.as_bytes())?;
    match draw::png(&svg) {
        Ok(png) => write(&args.out.join("chart.png"), &png)?,
        Err(e) => eprintln!("chart: no PNG: {e}"),
    }
    eprintln!("chart: wrote chart.csv, chart.svg and chart.png in {}", args.out.display());
    Ok(())
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => return fail("chart", format!("{e}\n{USAGE}")),
    };
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail("chart", e),
    }
}

/// Prints `message` as the program's error and returns exit status 2.
fn fail(program: &str, message: impl std::fmt::Display) -> ExitCode {
    eprintln!("{program}: {message}");
    ExitCode::from(2)
}
