//! Accuracy in sequence: for one light × surface (default F11 × A1, the
//! hardest), every method at increasing sample counts, each over many
//! independent trials: bias, spread, RMS and 95th-percentile ΔE00.
//!
//! ```text
//! cargo run --release --example converge [-- --light F11 --surface A1 --trials 1000 --seed 1]
//! cargo run --release --example converge -- --all --csv        # all 18 pairs
//! cargo run --release --example converge -- --all --summary    # the README's table
//! ```

mod common;

use std::io::{self, Write};
use std::num::NonZeroUsize;
use std::process::ExitCode;

use common::{Choice, fail};
use speclab::data::{Light, Patch};
use speclab::method::Method;
use speclab::regular::MAX_BUCKETS;
use speclab::study::{self, Stats};
use speclab::{Role, TabulatedSpectrum};

const USAGE: &str = "\
usage: converge [--light NAME] [--surface NAME] [--trials T] [--seed S] [--all] [--csv] [--summary]
  --light NAME    A, D65 or F11 (default F11)
  --surface NAME  E2, F4, G4, H4, J4 or A1 (default A1)
  --light-file PATH, --surface-file PATH   a spectrum from a file instead
  --trials T      independent trials per row for random and hero (default 1000)
  --seed S        base seed (default 1)
  --all           all 18 light × surface pairs
  --csv           machine-readable rows
  --summary       per light, the smallest n and M reaching RMS ΔE00 < 1 and < 0.5 for every patch (implies --all)";

struct Args {
    light: Choice,
    surface: Choice,
    trials: NonZeroUsize,
    seed: u64,
    all: bool,
    csv: bool,
    summary: bool,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut a = Args {
        light: Choice::Name("F11".into()),
        surface: Choice::Name("A1".into()),
        trials: NonZeroUsize::new(1000).unwrap_or(NonZeroUsize::MIN),
        seed: 1,
        all: false,
        csv: false,
        summary: false,
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("light") => a.light = Choice::Name(parser.value()?.string()?),
            Long("surface") => a.surface = Choice::Name(parser.value()?.string()?),
            Long("light-file") => a.light = Choice::File(parser.value()?.into()),
            Long("surface-file") => a.surface = Choice::File(parser.value()?.into()),
            Long("trials") => a.trials = parser.value()?.parse()?,
            Long("seed") => a.seed = parser.value()?.parse()?,
            Long("all") => a.all = true,
            Long("csv") => a.csv = true,
            Long("summary") => a.summary = true,
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(a)
}

/// One row of the sequence.
struct Row {
    light: String,
    surface: String,
    method: Method,
    samples: usize,
    stats: Stats,
}

/// The sample counts studied for `method`.
fn counts(method: Method) -> Vec<usize> {
    match method {
        Method::Random | Method::Hero => (0..=12).map(|e| 1 << e).collect(),
        Method::RegularCentre | Method::RegularBox => (1..=MAX_BUCKETS).collect(),
        Method::Reference => Vec::new(),
    }
}

/// Wavelength evaluations per estimate.
fn evaluations(method: Method, samples: usize) -> usize {
    if method == Method::Hero { 4 * samples } else { samples }
}

fn sequence(args: &Args, light: (&str, &TabulatedSpectrum), surface: (&str, &TabulatedSpectrum)) -> Vec<Row> {
    let mut rows = Vec::new();
    for method in [Method::Random, Method::Hero, Method::RegularCentre, Method::RegularBox] {
        for samples in counts(method) {
            let n = NonZeroUsize::new(samples).unwrap_or(NonZeroUsize::MIN);
            // Every count is compiled (M ≤ MAX_BUCKETS), so this cannot fail.
            let Ok(stats) = study::method(light.1, surface.1, method, n, args.trials, args.seed) else {
                continue;
            };
            rows.push(Row { light: light.0.into(), surface: surface.0.into(), method, samples, stats });
        }
    }
    rows
}

fn main() -> ExitCode {
    let mut args = match parse_args() {
        Ok(a) => a,
        Err(e) => return fail("converge", format!("{e}\n{USAGE}")),
    };
    args.all |= args.summary;
    let pairs: Vec<(Choice, Choice)> = if args.all {
        let names = |n: &str| Choice::Name(n.into());
        Light::ALL.iter().flat_map(|l| Patch::ALL.map(|p| (names(l.name()), names(p.name())))).collect()
    } else {
        vec![(args.light.clone(), args.surface.clone())]
    };
    let mut rows = Vec::new();
    for (light, surface) in &pairs {
        let (light, surface) = match (light.resolve(Role::Light), surface.resolve(Role::Reflectance)) {
            (Ok(l), Ok(s)) => (l, s),
            (Err(e), _) | (_, Err(e)) => return fail("converge", e),
        };
        rows.extend(sequence(&args, (&light.0, &light.1), (&surface.0, &surface.1)));
    }
    let out = &mut io::stdout().lock();
    let result = if args.summary {
        write_summary(out, &rows, &args)
    } else if args.csv {
        write_csv(out, &rows)
    } else {
        write_table(out, &rows, &args)
    };
    match result {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => fail("converge", e),
        _ => ExitCode::SUCCESS,
    }
}

/// bias X, Y, Z; sd X, Y, Z; RMS and p95 ΔE00.
fn numbers(r: &Row) -> [f64; 8] {
    let (b, s) = (r.stats.bias, r.stats.sd);
    [b.x, b.y, b.z, s.x, s.y, s.z, r.stats.rms_de00, r.stats.p95_de00]
}

fn write_csv(out: &mut impl Write, rows: &[Row]) -> io::Result<()> {
    writeln!(
        out,
        "light,surface,method,samples,trials,bias_x,bias_y,bias_z,sd_x,sd_y,sd_z,rms_de00,p95_de00"
    )?;
    for r in rows {
        let numbers: Vec<String> = numbers(r).iter().map(f64::to_string).collect();
        let head = format!("{},{},{},{},{}", r.light, r.surface, r.method.name(), r.samples, r.stats.trials);
        writeln!(out, "{head},{}", numbers.join(","))?;
    }
    Ok(())
}

fn write_table(out: &mut impl Write, rows: &[Row], args: &Args) -> io::Result<()> {
    writeln!(out, "speclab converge: {} trials per random row, base seed {}", args.trials, args.seed)?;
    writeln!(
        out,
        "evals = wavelength evaluations per estimate; bias and sd in XYZ; ΔE00 against the exact reference"
    )?;
    let heads = ["bias X", "bias Y", "bias Z", "sd X", "sd Y", "sd Z", "rms ΔE", "p95 ΔE"];
    let mut previous = (String::new(), String::new(), None);
    for r in rows {
        let key = (r.light.clone(), r.surface.clone(), Some(r.method));
        if key != previous {
            writeln!(out, "\n{} × {}: {}", r.light, r.surface, r.method.name())?;
            let heads: String = heads.iter().map(|h| format!(" {h:>10}")).collect();
            writeln!(out, "{:>7} {:>7}{heads}", "samples", "evals")?;
            previous = key;
        }
        let cells: String = numbers(r).iter().map(|v| format!(" {v:>10.4}")).collect();
        writeln!(out, "{:>7} {:>7}{cells}", r.samples, evaluations(r.method, r.samples))?;
    }
    Ok(())
}

/// Per light and method: the smallest count whose RMS ΔE00 is below
/// `threshold` for every patch at once.
fn smallest(rows: &[Row], light: &str, method: Method, threshold: f64) -> Option<usize> {
    counts(method).into_iter().find(|&n| {
        let cell = rows.iter().filter(|r| r.light == light && r.method == method && r.samples == n);
        let mut count = 0;
        let all_below = cell.inspect(|_| count += 1).all(|r| r.stats.rms_de00 < threshold);
        all_below && count == Patch::ALL.len()
    })
}

fn write_summary(out: &mut impl Write, rows: &[Row], args: &Args) -> io::Result<()> {
    writeln!(
        out,
        "Smallest n (random, hero) and M (regular) with RMS ΔE00 below the threshold for all six patches"
    )?;
    writeln!(
        out,
        "({} trials per random row, base seed {}; evals = wavelength evaluations)\n",
        args.trials, args.seed
    )?;
    writeln!(out, "| light | threshold | random n (evals) | hero n (evals) | centre M | box M |")?;
    writeln!(out, "|---|---|---|---|---|---|")?;
    for light in Light::ALL {
        for threshold in [1.0, 0.5] {
            let cell = |method| match smallest(rows, light.name(), method, threshold) {
                Some(n) if matches!(method, Method::Random | Method::Hero) => {
                    format!("{n} ({})", evaluations(method, n))
                }
                Some(n) => n.to_string(),
                None => "not reached".into(),
            };
            writeln!(
                out,
                "| {} | {threshold} | {} | {} | {} | {} |",
                light.name(),
                cell(Method::Random),
                cell(Method::Hero),
                cell(Method::RegularCentre),
                cell(Method::RegularBox)
            )?;
        }
    }
    Ok(())
}
