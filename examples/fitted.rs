//! Wavelength rules fitted to a light, beside equidistant buckets: the
//! worst ΔE00 by M over the six patches and over two named sets outside
//! the rules' prior (`study::shapes`), and per light and path depth the
//! smallest M each fixed rule needs, and the smallest n hero needs, to
//! stay within a budget. Markdown tables, as the README quotes them.
//!
//! ```text
//! cargo run --release --example fitted
//! cargo run --release --example fitted -- --light F11 --section by-m
//! cargo run --release --example fitted -- --section depth --budget 0.5 --trials 400
//! cargo run --release --example fitted -- --section lights
//! ```

use std::io::{self, Write};
use std::num::NonZeroUsize;
use std::process::ExitCode;

use speclab::Role;
use speclab_cli::args::{self, fail, finish};
use speclab_cli::{progress, report};
use speclab_study::evaluate::scene::{self, Choice, Depth, Named};
use speclab_study::{StudyError, evaluate::shapes, experiments::rules};

const USAGE: &str = "\
usage: fitted [--light NAME|all] [--section by-m|shapes|depth|lights|all] [--budget B] [--trials T] [--seed S]
  --light NAME   a built-in light (below), or all (default: A, D65 and F11; for the lights
                 section, every built-in light); repeat for several
  --section S    by-m: the six patches, M = 4 to 32; shapes: the ColorChecker 24 and the
                 edge shapes; depth: smallest counts within the budget at depth 1 to 4;
                 lights: smallest counts within the budget for the six patches under each
                 light, then for gold and copper under A, D65 and F11 (not in all: minutes);
                 all (default: by-m, shapes and depth)
  --budget B     the depth table's ΔE00 budget (default 1)
  --trials T     trials per hero count and patch in the depth table (default 200)
  --seed S       base seed of those trials (default 1)";

/// The Ms the tables show.
const MS: [usize; 14] = [4, 6, 8, 9, 10, 11, 12, 13, 14, 15, 16, 24, 32, 64];

struct Args {
    lights: Vec<String>,
    section: String,
    budget: f64,
    trials: NonZeroUsize,
    seed: u64,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut a = Args {
        lights: Vec::new(),
        section: "all".into(),
        budget: 1.0,
        trials: NonZeroUsize::new(200).unwrap_or(NonZeroUsize::MIN),
        seed: 1,
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("light") => a.lights.push(parser.value()?.string()?),
            Long("section") => {
                a.section = parser.value()?.string()?;
                if !["by-m", "shapes", "depth", "lights", "all"].contains(&a.section.as_str()) {
                    return Err(format!(
                        "expected a section (by-m, shapes, depth, lights or all), found {:?}",
                        a.section
                    )
                    .into());
                }
            }
            Long("budget") => {
                a.budget = parser.value()?.parse()?;
                if !(a.budget.is_finite() && a.budget > 0.0) {
                    return Err(StudyError::Budget { value: a.budget }.to_string().into());
                }
            }
            Long("trials") => a.trials = parser.value()?.parse_with(|v| args::count("trials", v))?,
            Long("seed") => a.seed = parser.value()?.parse()?,
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", args::names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(a)
}

/// The lights named, or the appendix's three for none; every built-in
/// light for `all` (or, in the lights section, for none).
fn lights(names: &[String], every: bool) -> Result<Vec<Named>, StudyError> {
    let all = names.iter().any(|n| n.eq_ignore_ascii_case("all"));
    if all || (every && names.is_empty()) {
        return Ok(scene::every_light());
    }
    if names.is_empty() {
        return Ok(scene::builtin_lights());
    }
    names.iter().map(|n| Choice::Name(n.clone()).resolve(Role::Light)).collect()
}

fn run(args: &Args, out: &mut impl Write) -> Result<(), Box<dyn std::error::Error>> {
    if args.section == "lights" {
        return by_light(args, out);
    }
    let lights = lights(&args.lights, false)?;
    let patches = scene::builtin_surfaces();
    let show = |section: &str| args.section == "all" || args.section == section;
    if show("by-m") {
        writeln!(out, "## Worst ΔE00 over the six patches, by M (depth 1)\n")?;
        for light in &lights {
            report::rules_table(out, "patches", &rules::by_m(light, &patches, Depth::ONE)?, &MS)?;
        }
        writeln!(out)?;
    }
    if show("shapes") {
        for (set, surfaces) in [("ColorChecker 24", shapes::colorchecker()?), ("edges", shapes::edges()?)] {
            writeln!(out, "## Worst ΔE00 over {set} (outside the prior), by M\n")?;
            for light in &lights {
                report::rules_table(out, set, &rules::by_m(light, &surfaces, Depth::ONE)?, &MS)?;
            }
            writeln!(out)?;
        }
    }
    if show("depth") {
        writeln!(
            out,
            "## Paths of depth 1 to 4 (light × patch^depth): what stays within ΔE00 {}\n",
            args.budget
        )?;
        let bar = progress::bar("depths", (lights.len() * Depth::ALL.len()) as u64);
        let mut rows = Vec::new();
        for light in &lights {
            for depth in Depth::ALL {
                rows.push(rules::needs(light, &patches, depth, args.budget, args.trials, args.seed)?);
                bar.inc(1);
            }
        }
        bar.finish_and_clear();
        report::depth_table(out, &rows, args.budget)?;
    }
    Ok(())
}

/// Per light, what the six patches need at depth 1; then gold and copper
/// under the appendix's lights.
fn by_light(args: &Args, out: &mut impl Write) -> Result<(), Box<dyn std::error::Error>> {
    let (budget, trials, seed) = (args.budget, args.trials, args.seed);
    writeln!(out, "## Every built-in light: what keeps the six patches within ΔE00 {budget}\n")?;
    let patches = scene::builtin_surfaces();
    let (every, mut rows) = (lights(&args.lights, true)?, Vec::new());
    let bar = progress::bar("lights", every.len() as u64);
    for light in every {
        rows.push(rules::needs(&light, &patches, Depth::ONE, budget, trials, seed)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    report::needs_table(out, &rows, budget, "light", |r| r.light.clone())?;
    writeln!(out, "\n## Metals: what keeps gold and copper (normal incidence) within ΔE00 {budget}\n")?;
    let metals = ["Au", "Cu"].map(|m| Choice::Name(m.into()).resolve(Role::Reflectance));
    let metals = metals.into_iter().collect::<Result<Vec<_>, _>>()?;
    let mut rows = Vec::new();
    for light in scene::builtin_lights() {
        rows.push(rules::needs(&light, &metals, Depth::ONE, budget, trials, seed)?);
    }
    report::needs_table(out, &rows, budget, "surfaces, light", |r| format!("Au and Cu, {}", r.light))?;
    Ok(())
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => return fail("fitted", format!("{e}\n{USAGE}")),
    };
    let out = &mut io::stdout().lock();
    match run(&args, out) {
        Ok(()) => finish("fitted", out.flush()),
        Err(e) => fail("fitted", e),
    }
}
