//! The 6 × 3 comparison grid: every ColorChecker patch under every light,
//! by the exact reference, random (K = 1), hero (K = 4) and regular buckets
//! (centre and box), with each estimate's deviation from the reference.
//!
//! ```text
//! cargo run --release --example grid [-- --n 100 --m 16 --seed 1 --csv]
//! ```

use std::io::{self, IsTerminal, Write};
use std::num::NonZeroUsize;
use std::process::ExitCode;

use speclab::grid::{Grid, Named, Row, builtin_lights, builtin_surfaces};
use speclab::load::Load;
use speclab::method::Method;
use speclab::{LinearSrgb, Role, TabulatedSpectrum, reference};

const USAGE: &str = "\
usage: grid [--n N] [--m M] [--seed S] [--csv] [--light-file PATH] [--surface-file PATH]
  --n N                samples for random and hero (default 100)
  --m M                buckets for regular sampling, 1 to 64 (default 16)
  --seed S             base seed of the random methods (default 1)
  --csv                print light,surface,method,samples,x,y,z,r,g,b rows
  --light-file PATH    use this light instead of A, D65, F11 (brace, CSV/TSV or JSON)
  --surface-file PATH  use this reflectance instead of the six patches";

struct Args {
    grid: Grid,
    csv: bool,
    light_file: Option<std::path::PathBuf>,
    surface_file: Option<std::path::PathBuf>,
}

fn parse_args() -> Result<Args, lexopt::Error> {
    use lexopt::prelude::*;
    let mut args = Args { grid: Grid::default(), csv: false, light_file: None, surface_file: None };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("n") => args.grid.n = parser.value()?.parse::<NonZeroUsize>()?,
            Long("m") => args.grid.m = parser.value()?.parse::<NonZeroUsize>()?,
            Long("seed") => args.grid.seed = parser.value()?.parse()?,
            Long("csv") => args.csv = true,
            Long("light-file") => args.light_file = Some(parser.value()?.into()),
            Long("surface-file") => args.surface_file = Some(parser.value()?.into()),
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
        Err(e) => {
            eprintln!("grid: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let light = args.light_file.as_deref().map(|p| (p, Load::new(Role::Light).file(p)));
    let surface = args.surface_file.as_deref().map(|p| (p, Load::new(Role::Reflectance).file(p)));
    let (light, surface) = match (transpose(light), transpose(surface)) {
        (Ok(light), Ok(surface)) => (light, surface),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("grid: {e}");
            return ExitCode::from(2);
        }
    };
    let lights: Vec<Named> = match &light {
        Some((name, spectrum)) => vec![Named { name, spectrum }],
        None => builtin_lights(),
    };
    let surfaces: Vec<Named> = match &surface {
        Some((name, spectrum)) => vec![Named { name, spectrum }],
        None => builtin_surfaces(),
    };
    let rows = match args.grid.rows(&lights, &surfaces) {
        Ok(rows) => rows,
        Err(e) => {
            eprintln!("grid: {e}");
            return ExitCode::from(2);
        }
    };
    let out = &mut io::stdout().lock();
    let result = if args.csv { write_csv(out, &rows) } else { write_table(out, &args.grid, &lights, &rows) };
    match result {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
            eprintln!("grid: {e}");
            ExitCode::FAILURE
        }
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

/// A loaded file named by its stem, or the load error.
fn transpose(
    loaded: Option<(&std::path::Path, Result<TabulatedSpectrum, speclab::Error>)>,
) -> Result<Option<(String, TabulatedSpectrum)>, speclab::Error> {
    let Some((path, result)) = loaded else { return Ok(None) };
    let name = path.file_stem().map_or_else(|| "file".into(), |s| s.to_string_lossy().into_owned());
    Ok(Some((name, result?)))
}

fn write_table(out: &mut impl Write, grid: &Grid, lights: &[Named], rows: &[Row]) -> io::Result<()> {
    let colour = io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    writeln!(out, "speclab grid: linear sRGB (unclamped) of light × patch, by method")?;
    writeln!(
        out,
        "random: n = {n} wavelengths; hero: n = {n} samples × 4 wavelengths; regular: M = {m} buckets; seed {s}",
        n = grid.n,
        m = grid.m,
        s = grid.seed
    )?;
    writeln!(
        out,
        "Δ = distance to the reference in sRGB (and % of the reference's length); ! = out of gamut"
    )?;
    let mut previous_light = "";
    for chunk in rows.chunks(Method::ALL.len()) {
        let reference = chunk[0].xyz.to_linear_srgb();
        let white =
            lights.iter().find(|l| l.name == chunk[0].light).map_or(1.0, |l| reference::white(l.spectrum).y);
        if chunk[0].light != previous_light {
            previous_light = chunk[0].light;
            writeln!(out, "\nLight {previous_light}")?;
            let head = ["patch", "method", "R", "G", "B", "Δ", "Δ%"];
            writeln!(
                out,
                "{:<5} {:<15} {:>10} {:>10} {:>10}  {:>9} {:>7}",
                head[0], head[1], head[2], head[3], head[4], head[5], head[6]
            )?;
        }
        for row in chunk {
            let rgb = row.xyz.to_linear_srgb();
            let patch = if row.method == Method::Reference { row.surface } else { "" };
            let swatch = if colour { swatch(rgb, white) } else { String::new() };
            let flag = if rgb.in_gamut() { ' ' } else { '!' };
            write!(
                out,
                "{swatch}{patch:<5} {:<15} {:>10.3} {:>10.3} {:>10.3}{flag}",
                row.method.name(),
                rgb.r,
                rgb.g,
                rgb.b
            )?;
            if row.method == Method::Reference {
                writeln!(out)?;
            } else {
                let d = rgb.distance(reference);
                let len = reference.distance(LinearSrgb::default());
                writeln!(out, " {d:>9.3} {:>6.2}%", 100.0 * d / len)?;
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
