//! The assignment's main user story: one light and one surface, the exact
//! reference beside every technique, with sRGB, ΔE00 and, over many trials,
//! RMS ΔE00.
//!
//! ```text
//! cargo run --release --example compare -- --light F11 --surface G4 --n 100 --m 16 --k 4
//! cargo run --release --example compare -- --light-file lamp.csv --surface A1 --normalize luminance --white-balance
//! ```

mod common;

use std::io::{self, Write};
use std::num::NonZeroUsize;
use std::process::ExitCode;

use common::{Choice, fail};
use rand::SeedableRng;
use rand::rngs::StdRng;
use speclab::method::Method;
use speclab::remarks::{self, Normalization};
use speclab::{Error, Role, TabulatedSpectrum, Xyz, hero, perceptual, reference, study};

const USAGE: &str = "\
usage: compare [options]
  --light NAME | --light-file PATH      A, D65, F11, or a file (default D65)
  --surface NAME | --surface-file PATH  E2, F4, G4, H4, J4, A1, or a file (default A1)
  --n N          random and hero samples (default 100)
  --m M          regular buckets, 1 to 64 (default 16)
  --k K          hero width: 1, 2, 3, 4, 8 or 16 wavelengths (default 4)
  --seed S       seed of the single estimates and base seed of the trials (default 1)
  --trials T     trials for the RMS ΔE00 column (default 200)
  --normalize none|power|luminance   scale the light first (default none)
  --white-balance                    Bradford-adapt the light's white to D65's before sRGB";

struct Args {
    light: Choice,
    surface: Choice,
    n: NonZeroUsize,
    m: NonZeroUsize,
    k: usize,
    seed: u64,
    trials: NonZeroUsize,
    normalize: Normalization,
    white_balance: bool,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let nz = |n| NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
    let mut a = Args {
        light: Choice::Name("D65".into()),
        surface: Choice::Name("A1".into()),
        n: nz(100),
        m: nz(16),
        k: 4,
        seed: 1,
        trials: nz(200),
        normalize: Normalization::None,
        white_balance: false,
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("light") => a.light = Choice::Name(parser.value()?.string()?),
            Long("light-file") => a.light = Choice::File(parser.value()?.into()),
            Long("surface") => a.surface = Choice::Name(parser.value()?.string()?),
            Long("surface-file") => a.surface = Choice::File(parser.value()?.into()),
            Long("n") => a.n = parser.value()?.parse()?,
            Long("m") => a.m = parser.value()?.parse()?,
            Long("k") => {
                a.k = parser.value()?.parse()?;
                if !hero::WIDTHS.contains(&a.k) {
                    return Err(format!(
                        "hero width {} is not compiled: expected one of {:?}",
                        a.k,
                        hero::WIDTHS
                    )
                    .into());
                }
            }
            Long("seed") => a.seed = parser.value()?.parse()?,
            Long("trials") => a.trials = parser.value()?.parse()?,
            Long("normalize") => a.normalize = common::normalization(&parser.value()?.string()?)?,
            Long("white-balance") => a.white_balance = true,
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(a)
}

/// One technique: its label, wavelength evaluations, and an estimator.
struct Technique<'a> {
    label: String,
    evals: usize,
    estimate: Box<dyn Fn(u64) -> Result<Xyz, Error> + Sync + 'a>,
    random: bool,
}

fn techniques<'a>(
    a: &Args,
    light: &'a TabulatedSpectrum,
    surface: &'a TabulatedSpectrum,
) -> Vec<Technique<'a>> {
    let (n, m, k) = (a.n, a.m, a.k);
    let method = move |method: Method, samples| {
        Box::new(move |seed| method.xyz(light, surface, samples, seed)) as Box<dyn Fn(u64) -> _ + Sync>
    };
    vec![
        Technique {
            label: "reference".into(),
            evals: 0,
            estimate: method(Method::Reference, n),
            random: false,
        },
        Technique {
            label: format!("random n={n}"),
            evals: n.get(),
            estimate: method(Method::Random, n),
            random: true,
        },
        Technique {
            label: format!("hero n={n} K={k}"),
            evals: n.get() * k,
            estimate: Box::new(move |seed| {
                hero::estimate_dyn(k, light, surface, n, &mut StdRng::seed_from_u64(seed))
            }),
            random: true,
        },
        Technique {
            label: format!("centre M={m}"),
            evals: m.get(),
            estimate: method(Method::RegularCentre, m),
            random: false,
        },
        Technique {
            label: format!("box M={m}"),
            evals: m.get(),
            estimate: method(Method::RegularBox, m),
            random: false,
        },
    ]
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => return fail("compare", format!("{e}\n{USAGE}")),
    };
    let (light, surface) = match (args.light.resolve(Role::Light), args.surface.resolve(Role::Reflectance)) {
        (Ok(l), Ok(s)) => (l, s),
        (Err(e), _) | (_, Err(e)) => return fail("compare", e),
    };
    let scaled = match args.normalize.apply(&light.1) {
        Ok(s) => s,
        Err(e) => return fail("compare", e),
    };
    let lines = match run(&args, (&light.0, &scaled), (&surface.0, &surface.1)) {
        Ok(lines) => lines,
        Err(e) => return fail("compare", e),
    };
    let out = &mut io::stdout().lock();
    match lines.iter().try_for_each(|line| writeln!(out, "{line}")) {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => fail("compare", e),
        _ => ExitCode::SUCCESS,
    }
}

/// The table's lines: a header, column names, and one line per technique.
fn run(
    a: &Args,
    light: (&str, &TabulatedSpectrum),
    surface: (&str, &TabulatedSpectrum),
) -> Result<Vec<String>, Error> {
    // White balance maps the light's white to D65's; Lab is taken relative
    // to whichever white the colours end up under.
    let adapt = |xyz: Xyz| if a.white_balance { remarks::white_balance(xyz, light.1) } else { xyz };
    let white = if a.white_balance { remarks::target_white(light.1) } else { reference::white(light.1) };
    let exact = adapt(reference::xyz(light.1, surface.1));
    let balance = if a.white_balance { "Bradford to D65" } else { "off" };
    let mut lines = vec![
        format!(
            "{} × {}; normalise: {}; white balance: {balance}; seed {}; RMS over {} trials",
            light.0,
            surface.0,
            a.normalize.name(),
            a.seed,
            a.trials
        ),
        format!(
            "{:<18} {:>6} {:>11} {:>11} {:>11}  {:>6} {:>8} {:>8}",
            "technique", "evals", "R", "G", "B", "gamut", "ΔE00", "RMS ΔE00"
        ),
    ];
    for t in techniques(a, light.1, surface.1) {
        let xyz = adapt((t.estimate)(a.seed)?);
        let trials = if t.random { a.trials } else { NonZeroUsize::MIN };
        let stats = study::run(exact, white, trials, a.seed, |seed| (t.estimate)(seed).map(adapt))?;
        let rgb = xyz.to_linear_srgb();
        let gamut = if rgb.in_gamut() { "in" } else { "OUT" };
        let de = perceptual::delta_e00(xyz, exact, white);
        lines.push(format!(
            "{:<18} {:>6} {:>11.4} {:>11.4} {:>11.4}  {:>6} {:>8.3} {:>8.3}",
            t.label, t.evals, rgb.r, rgb.g, rgb.b, gamut, de, stats.rms_de00
        ));
    }
    Ok(lines)
}
