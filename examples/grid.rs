//! The 6 × 3 comparison grid: every ColorChecker patch under every light,
//! by the exact reference, random (K = 1), hero (K = 4) and regular buckets
//! (centre and box), with each estimate's deviation from the reference.
//!
//! ```text
//! cargo run --release --example grid [-- --n 100 --m 16 --seed 1 --csv]
//! cargo run --release --example grid -- --normalize luminance --white-balance
//! ```

mod common;

use std::io::{self, IsTerminal, Write};
use std::process::ExitCode;

use common::{Choice, fail};
use speclab::grid::{Grid, Named, Row};
use speclab::method::Method;
use speclab::remarks::{self, Normalization};
use speclab::{LinearSrgb, Role, TabulatedSpectrum, Xyz, perceptual, reference};

const USAGE: &str = "\
usage: grid [--n N] [--m M] [--seed S] [--csv] [--light-file PATH] [--surface-file PATH]
            [--normalize none|power|luminance] [--white-balance]
  --n N                samples for random and hero (default 100)
  --m M                buckets for regular sampling, 1 to 64 (default 16)
  --seed S             base seed of the random methods (default 1)
  --csv                print light,surface,method,samples,x,y,z,r,g,b rows
  --light-file PATH    use this light instead of A, D65, F11 (brace, CSV/TSV or JSON)
  --surface-file PATH  use this reflectance instead of the six patches
  --normalize MODE     scale each light first: none (default, as Appendix 2),
                       power (mean power 1 over 380-730 nm), luminance (white Y = 100)
  --white-balance      Bradford-adapt each light's white to D65's before sRGB";

struct Args {
    grid: Grid,
    csv: bool,
    lights: Vec<Choice>,
    surfaces: Vec<Choice>,
    normalize: Normalization,
    white_balance: bool,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let names = |names: &[&str]| names.iter().map(|n| Choice::Name(n.to_string())).collect();
    let mut args = Args {
        grid: Grid::default(),
        csv: false,
        lights: names(&["A", "D65", "F11"]),
        surfaces: names(&["E2", "F4", "G4", "H4", "J4", "A1"]),
        normalize: Normalization::None,
        white_balance: false,
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("n") => args.grid.n = parser.value()?.parse()?,
            Long("m") => args.grid.m = parser.value()?.parse()?,
            Long("seed") => args.grid.seed = parser.value()?.parse()?,
            Long("csv") => args.csv = true,
            Long("light-file") => args.lights = vec![Choice::File(parser.value()?.into())],
            Long("surface-file") => args.surfaces = vec![Choice::File(parser.value()?.into())],
            Long("normalize") => args.normalize = common::normalization(&parser.value()?.string()?)?,
            Long("white-balance") => args.white_balance = true,
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok(args)
}

/// Resolves choices to named spectra, normalising lights.
fn resolve(
    choices: &[Choice],
    role: Role,
    normalize: Normalization,
) -> Result<Vec<(String, TabulatedSpectrum)>, String> {
    choices
        .iter()
        .map(|c| {
            let (name, s) = c.resolve(role)?;
            let s = if role == Role::Light { normalize.apply(&s).map_err(|e| e.to_string())? } else { s };
            Ok((name, s))
        })
        .collect()
}

fn named(v: &[(String, TabulatedSpectrum)]) -> Vec<Named<'_>> {
    v.iter().map(|(name, spectrum)| Named { name, spectrum }).collect()
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(args) => args,
        Err(e) => return fail("grid", format!("{e}\n{USAGE}")),
    };
    let lights = match resolve(&args.lights, Role::Light, args.normalize) {
        Ok(l) => l,
        Err(e) => return fail("grid", e),
    };
    let surfaces = match resolve(&args.surfaces, Role::Reflectance, Normalization::None) {
        Ok(s) => s,
        Err(e) => return fail("grid", e),
    };
    let (light_refs, surface_refs) = (named(&lights), named(&surfaces));
    let mut rows = match args.grid.rows(&light_refs, &surface_refs) {
        Ok(rows) => rows,
        Err(e) => return fail("grid", e),
    };
    // Each light's white, in the space the colours end up in.
    let spectrum_of = |name: &str| light_refs.iter().find(|l| l.name == name).map(|l| l.spectrum);
    let mut whites = Vec::new();
    for row in &mut rows {
        let Some(light) = spectrum_of(row.light) else { continue };
        if args.white_balance {
            row.xyz = remarks::white_balance(row.xyz, light);
        }
        let white = if args.white_balance { remarks::target_white(light) } else { reference::white(light) };
        whites.push(white);
    }
    let out = &mut io::stdout().lock();
    let result = if args.csv { write_csv(out, &rows) } else { write_table(out, &args, &rows, &whites) };
    match result {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => fail("grid", e),
        _ => ExitCode::SUCCESS,
    }
}

fn write_csv(out: &mut impl Write, rows: &[Row]) -> io::Result<()> {
    writeln!(out, "light,surface,method,samples,x,y,z,r,g,b")?;
    for row in rows {
        let (xyz, rgb) = (row.xyz, row.xyz.to_linear_srgb());
        writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{}",
            row.light,
            row.surface,
            row.method.name(),
            row.samples,
            xyz.x,
            xyz.y,
            xyz.z,
            rgb.r,
            rgb.g,
            rgb.b
        )?;
    }
    Ok(())
}

fn write_table(out: &mut impl Write, args: &Args, rows: &[Row], whites: &[Xyz]) -> io::Result<()> {
    let colour = io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let g = &args.grid;
    writeln!(out, "speclab grid: linear sRGB (unclamped) of light × patch, by method")?;
    writeln!(
        out,
        "random: n = {} wavelengths; hero: n = {} samples × 4 wavelengths; regular: M = {} buckets; seed {}",
        g.n, g.n, g.m, g.seed
    )?;
    writeln!(
        out,
        "normalise: {}; white balance: {}",
        args.normalize.name(),
        if args.white_balance { "Bradford to D65" } else { "off" }
    )?;
    writeln!(
        out,
        "Δ = distance to the reference in sRGB (and % of its length); ΔE00 in CIELAB of the light's white"
    )?;
    writeln!(out, "! = out of gamut (a negative component)")?;
    let mut previous_light = "";
    for (chunk, whites) in rows.chunks(Method::ALL.len()).zip(whites.chunks(Method::ALL.len())) {
        let (reference, white) = (chunk[0].xyz, whites[0]);
        if chunk[0].light != previous_light {
            previous_light = chunk[0].light;
            writeln!(out, "\nLight {previous_light}")?;
            let h = ["patch", "method", "R", "G", "B", "Δ", "Δ%", "ΔE00"];
            writeln!(
                out,
                "{:<5} {:<15} {:>10} {:>10} {:>10}  {:>9} {:>7} {:>7}",
                h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]
            )?;
        }
        for row in chunk {
            let rgb = row.xyz.to_linear_srgb();
            let patch = if row.method == Method::Reference { row.surface } else { "" };
            let swatch = if colour { swatch(rgb, white.y) } else { String::new() };
            let flag = if rgb.in_gamut() { ' ' } else { '!' };
            let name = row.method.name();
            write!(
                out,
                "{swatch}{patch:<5} {name:<15} {:>10.3} {:>10.3} {:>10.3}{flag}",
                rgb.r, rgb.g, rgb.b
            )?;
            if row.method == Method::Reference {
                writeln!(out)?;
            } else {
                let reference = reference.to_linear_srgb();
                let d = rgb.distance(reference);
                let share = 100.0 * d / reference.distance(LinearSrgb::default());
                let de = perceptual::delta_e00(row.xyz, chunk[0].xyz, white);
                writeln!(out, " {d:>9.3} {share:>6.2}% {de:>7.2}")?;
            }
        }
    }
    Ok(())
}

/// Two truecolour cells showing `rgb` scaled so the light's white is 1.
fn swatch(rgb: LinearSrgb, white_y: f64) -> String {
    let encode = |c: f64| {
        let c = (c / white_y).clamp(0.0, 1.0);
        let v = if c <= 0.003_130_8 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 };
        (v * 255.0).round() as u8
    };
    format!("\x1b[48;2;{};{};{}m  \x1b[0m ", encode(rgb.r), encode(rgb.g), encode(rgb.b))
}
