//! A plan for a scene: the cheapest way of sampling wavelengths, in
//! measured ns per estimate, whose worst RMS ΔE00 over every light ×
//! surface of the scene stays within a budget.
//!
//! ```text
//! cargo run --release --example plan -- --light F11 --surface all
//! cargo run --release --example plan -- --light all --surface all --budget 0.5 --unbiased
//! cargo run --release --example plan -- --light-file examples/build-data/data/led.csv --surface A1 --surface-file examples/build-data/data/leaf.json
//! ```

use std::io;
use std::process::ExitCode;

use speclab::Role;
use speclab_cli::args::{self, fail, finish};
use speclab_cli::report;
use speclab_study::StudyError;
use speclab_study::evaluate::scene::{self, Choice, Named};
use speclab_study::planning::plan::{self, Request};

const USAGE: &str = "\
usage: plan --light NAME|all ... --surface NAME|all ... [--budget B] [--unbiased] [--depth D]
            [--trials T] [--seed S]
  --light NAME         a built-in light (below), or all (A, D65, F11); repeat for more lights
  --light-file PATH    a light from a file (brace, CSV/TSV or JSON); repeatable
  --surface NAME       a built-in surface (below), or all (the six patches); repeat for more
  --surface-file PATH  a reflectance from a file; repeatable
  --budget B           the largest acceptable RMS ΔE00 in any light × surface (default 1)
  --unbiased           exclude biased methods (regular buckets, fitted rules)
  --depth D            surfaces per path, 1 to 4: light × surface^D (default 1)
  --trials T           trials per Monte Carlo light × surface (default 200)
  --seed S             base seed (default 1)";

struct Args {
    lights: Vec<Choice>,
    surfaces: Vec<Choice>,
    request: Request,
}

/// `name`, or every built-in one for `all`.
fn names(name: String, builtin: fn() -> Vec<Named>) -> Vec<Choice> {
    if name.eq_ignore_ascii_case("all") {
        builtin().into_iter().map(|n| Choice::Name(n.name)).collect()
    } else {
        vec![Choice::Name(name)]
    }
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut args = Args { lights: Vec::new(), surfaces: Vec::new(), request: Request::default() };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("light") => args.lights.extend(names(parser.value()?.string()?, scene::builtin_lights)),
            Long("surface") => {
                args.surfaces.extend(names(parser.value()?.string()?, scene::builtin_surfaces))
            }
            Long("light-file") => args.lights.push(Choice::File(parser.value()?.into())),
            Long("surface-file") => args.surfaces.push(Choice::File(parser.value()?.into())),
            Long("budget") => args.request.budget = parser.value()?.parse()?,
            Long("unbiased") => args.request.allow_bias = false,
            Long("trials") => {
                args.request.trials = parser.value()?.parse_with(|v| args::count("trials", v))?
            }
            Long("seed") => args.request.seed = parser.value()?.parse()?,
            Long("depth") => args.request.depth = parser.value()?.parse()?,
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", args::names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(args)
}

fn resolve(choices: &[Choice], role: Role) -> Result<Vec<Named>, StudyError> {
    choices.iter().map(|c| c.resolve(role)).collect()
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => return fail("plan", format!("{e}\n{USAGE}")),
    };
    let scene =
        resolve(&args.lights, Role::Light).and_then(|l| Ok((l, resolve(&args.surfaces, Role::Reflectance)?)));
    let (lights, surfaces) = match scene {
        Ok(scene) => scene,
        Err(e) => return fail("plan", e),
    };
    let plan = match plan::plan(&lights, &surfaces, &args.request) {
        Ok(plan) => plan,
        Err(e) => return fail("plan", format!("{e}\n{USAGE}")),
    };
    finish("plan", report::plan_text(&mut io::stdout().lock(), &lights, &surfaces, &args.request, &plan))
}
