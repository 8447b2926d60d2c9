//! The 6 × 3 comparison grid: every ColorChecker patch under every light,
//! by the exact reference, random (K = 1), hero (K = 4), regular buckets
//! (centre and box) and a rule of M wavelengths fitted to the light, with
//! each estimate's deviation from the reference.
//!
//! ```text
//! cargo run --release --example grid [-- --n 100 --m 16 --seed 1 --csv]
//! cargo run --release --example grid -- --normalize luminance --white-balance
//! cargo run --release --example grid -- --m 10 --depth 3
//! ```

use std::io;
use std::process::ExitCode;

use speclab::Role;
use speclab::data::{Light, patches};
use speclab_cli::args::{self, fail, finish};
use speclab_cli::report;
use speclab_study::StudyError;
use speclab_study::display::GamutMap;
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::scene::{Choice, Named};
use speclab_study::evaluate::viewing::Viewing;
use speclab_study::experiments::grid::GridOptions;
use speclab_study::experiments::texture::{self, TextureOptions};

const USAGE: &str = "\
usage: grid [--n N] [--m M] [--seed S] [--depth D] [--csv] [--texture] [--method NAME]...
            [--light NAME | --light-file PATH]... [--surface NAME | --surface-file PATH]...
            [--normalize none|power|luminance] [--white-balance]
            [--pdf uniform|visible|light|balanced] [--strata none|jitter|kronecker]
            [--gamut clip|chroma]
  --n N                samples for random and hero (default 100)
  --m M                buckets for regular sampling, and wavelengths of the fitted rule,
                       1 to 64 (default 16)
  --seed S             base seed of the random methods (default 1)
  --depth D            surfaces per path, 1 to 4: every method and the reference on
                       light × surface^D (default 1)
  --method NAME        also a published method, after the default six: astm, borges, meyer,
                       wallis (M wavelengths, as --m), prefilter-xyz, prefilter-srgb,
                       prefilter-sharp (three numbers per surface); repeat for several
  --csv                print light,surface,method,samples,x,y,z,r,g,b,pdf,strata,evals rows
  --texture            instead, what an RGB texture of each surface costs in colour under each
                       light (its colour under D65, upsampled), beside hero (n, jittered) and
                       buckets (M): a Markdown table
  --light NAME         a built-in light (below) instead of A, D65, F11; repeat for several
  --light-file PATH    a light from a file (brace, CSV/TSV or JSON), likewise
  --surface NAME       a built-in surface (below) instead of the six patches; repeatable
  --surface-file PATH  a reflectance from a file, likewise
  --normalize MODE     scale each light first: none (default, as Appendix 2),
                       power (mean power 1 over 380-730 nm), luminance (white Y = 100)
  --white-balance      Bradford-adapt each light's white to D65's before sRGB
  --pdf PDF            random and hero wavelengths' density (default uniform, as the assignment)
  --strata STRATA      how their primary numbers are spread (default none)
  --gamut MAP          how terminal swatches show out-of-gamut colours: clip per channel,
                       or chroma (default: keep hue and luminance, desaturate); numbers stay unclamped";

struct Args {
    grid: GridOptions,
    extra: Vec<Method>,
    csv: bool,
    texture: bool,
    lights: Vec<Choice>,
    surfaces: Vec<Choice>,
    viewing: Viewing,
    gamut: GamutMap,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let names = |names: &mut dyn Iterator<Item = &str>| names.map(|n| Choice::Name(n.to_string())).collect();
    let mut args = Args {
        grid: GridOptions::default(),
        extra: Vec::new(),
        csv: false,
        texture: false,
        lights: names(&mut Light::APPENDIX.iter().map(|l| l.name())),
        surfaces: names(&mut patches::NAMES.into_iter()),
        viewing: Viewing::default(),
        gamut: GamutMap::default(),
    };
    let (mut own_lights, mut own_surfaces) = (false, false);
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("n") => args.grid.n = parser.value()?.parse_with(|v| args::count("samples", v))?,
            Long("m") => args.grid.m = parser.value()?.parse_with(args::buckets)?,
            Long("seed") => args.grid.seed = parser.value()?.parse()?,
            Long("depth") => args.grid.depth = parser.value()?.parse()?,
            Long("method") => args.extra.push(parser.value()?.parse_with(published)?),
            Long("csv") => args.csv = true,
            Long("texture") => args.texture = true,
            Long("light") => {
                chosen(&mut args.lights, &mut own_lights, Choice::Name(parser.value()?.string()?))
            }
            Long("light-file") => {
                chosen(&mut args.lights, &mut own_lights, Choice::File(parser.value()?.into()))
            }
            Long("surface") => {
                chosen(&mut args.surfaces, &mut own_surfaces, Choice::Name(parser.value()?.string()?))
            }
            Long("surface-file") => {
                chosen(&mut args.surfaces, &mut own_surfaces, Choice::File(parser.value()?.into()))
            }
            Long("normalize") => args.viewing.normalize = parser.value()?.parse()?,
            Long("white-balance") => args.viewing.white_balance = true,
            Long("pdf") => args.grid.sampling.pdf = parser.value()?.parse()?,
            Long("strata") => args.grid.sampling.strata = parser.value()?.parse()?,
            Long("gamut") => args.gamut = parser.value()?.parse()?,
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", args::names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(args)
}

/// A published method's name (the six default methods are always shown).
fn published(name: &str) -> Result<Method, String> {
    match name.parse::<Method>() {
        Ok(m) if Method::PUBLISHED.contains(&m) => Ok(m),
        _ => Err(format!(
            "expected a published method ({}), found {name:?}",
            Method::PUBLISHED_NAMES.join(", ")
        )),
    }
}

/// Adds `choice` to `list`, replacing the defaults on the first one.
fn chosen(list: &mut Vec<Choice>, own: &mut bool, choice: Choice) {
    if !*own {
        list.clear();
        *own = true;
    }
    list.push(choice);
}

/// The chosen lights (normalised) and surfaces.
fn scene(args: &Args) -> Result<(Vec<Named>, Vec<Named>), StudyError> {
    let mut lights = Vec::new();
    for choice in &args.lights {
        let light = choice.resolve(Role::Light)?;
        lights.push(Named::new(light.name, args.viewing.light(&light.spectrum)?));
    }
    let surfaces = args.surfaces.iter().map(|c| c.resolve(Role::Reflectance)).collect::<Result<_, _>>()?;
    Ok((lights, surfaces))
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => return fail("grid", format!("{e}\n{USAGE}")),
    };
    let (lights, surfaces) = match scene(&args) {
        Ok(scene) => scene,
        Err(e) => return fail("grid", e),
    };
    if args.texture {
        let (n, m, seed) = (args.grid.n.get(), args.grid.m.get(), args.grid.seed);
        let options = TextureOptions { n, m, seed, ..TextureOptions::default() };
        return match texture::rows(&lights, &surfaces, &options) {
            Ok(rows) => finish("grid", report::texture_table(&mut io::stdout().lock(), &rows, &options)),
            Err(e) => fail("grid", e),
        };
    }
    let methods: Vec<Method> = Method::ALL.iter().chain(&args.extra).copied().collect();
    let rows = match args.grid.rows_of(&lights, &surfaces, &methods) {
        Ok(rows) => rows,
        Err(e) => return fail("grid", e),
    };
    let out = &mut io::stdout().lock();
    let written = if args.csv {
        report::grid_csv(out, &rows, &args.viewing)
    } else {
        let swatches = args::color().then_some(args.gamut);
        report::grid_table(out, &args.grid, &args.viewing, &rows, swatches)
    };
    finish("grid", written)
}
