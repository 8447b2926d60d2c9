//! The fitted rules' picture for the README: per built-in light, its
//! spectrum with the wavelengths of the rule of M fitted to it (black; the
//! centres of M equidistant buckets as orange ticks), and the rule's X, Y,
//! Z weights as stems.
//!
//! Writes `fits.svg` and `fits.png` (the PNG needs system fonts; skipped
//! with a warning where there are none).
//!
//! ```text
//! cargo run --release -p speclab-tools --bin fits -- --out docs       # the README's picture
//! cargo run --release -p speclab-tools --bin fits -- --m 8 --out target/fits
//! ```

use std::fs::File;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use speclab::data::Light;
use speclab::sampling::rule::Rule;
use speclab_tools::{chart, fits};

const USAGE: &str = "\
usage: fits [--m M] [--out DIR]
  --m M      wavelengths per rule, 1 to 64 (default 10)
  --out DIR  where fits.svg and fits.png go (default: the current directory)";

fn parse_args() -> Result<(usize, PathBuf), lexopt::Error> {
    use lexopt::prelude::*;
    let (mut m, mut out) = (10, PathBuf::from("."));
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("m") => m = parser.value()?.parse()?,
            Long("out") => out = parser.value()?.into(),
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok((m, out))
}

fn write(path: &PathBuf, bytes: &[u8]) -> Result<(), String> {
    File::create(path).and_then(|mut f| f.write_all(bytes)).map_err(|e| format!("{}: {e}", path.display()))
}

fn run(m: usize, out: &PathBuf) -> Result<(), String> {
    let panels = Light::APPENDIX
        .iter()
        .map(|&l| {
            let rule = Rule::fit(&[l.spectrum()], m).map_err(|e| e.to_string())?;
            Ok(fits::Panel { name: l.to_string(), light: l.spectrum(), rule })
        })
        .collect::<Result<Vec<_>, String>>()?;
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let svg = fits::svg(&panels)?;
    write(&out.join("fits.svg"), svg.as_bytes())?;
    match chart::png(&svg) {
        Ok(png) => write(&out.join("fits.png"), &png)?,
        Err(e) => eprintln!("fits: no PNG: {e}"),
    }
    eprintln!("fits: wrote fits.svg and fits.png in {}", out.display());
    Ok(())
}

fn main() -> ExitCode {
    let (m, out) = match parse_args() {
        Ok(args) => args,
        Err(e) => {
            eprintln!("fits: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    match run(m, &out) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("fits: {e}");
            ExitCode::from(2)
        }
    }
}
