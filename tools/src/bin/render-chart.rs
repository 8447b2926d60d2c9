//! The render survey's chart for the README: reads the CSV that
//! `render --survey --csv` wrote and draws time per pixel against pixel
//! ΔE00, one panel per scene. Writes `render-chart.svg` and
//! `render-chart.png` (the PNG needs system fonts; skipped with a warning
//! where there are none).
//!
//! ```text
//! cargo run --release --example render -- --survey --csv docs/render.csv --strip docs/render-strip.png
//! cargo run --release -p speclab-tools --bin render-chart -- docs/render.csv --out docs
//! ```

use std::path::PathBuf;
use std::process::ExitCode;

use speclab_tools::{chart, render_chart};

const USAGE: &str = "\
usage: render-chart CSV [--out DIR]
  CSV        the survey's rows (render --survey --csv CSV)
  --out DIR  where render-chart.svg and render-chart.png go (default: the current directory)";

fn parse_args() -> Result<(PathBuf, PathBuf), lexopt::Error> {
    use lexopt::prelude::*;
    let (mut csv, mut out) = (None, PathBuf::from("."));
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Value(path) if csv.is_none() => csv = Some(PathBuf::from(path)),
            Long("out") => out = parser.value()?.into(),
            Short('h') | Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected()),
        }
    }
    Ok((csv.ok_or("expected the survey's CSV file")?, out))
}

fn run(csv: &PathBuf, out: &PathBuf) -> Result<(), String> {
    let text = std::fs::read_to_string(csv).map_err(|e| format!("{}: {e}", csv.display()))?;
    let rows = render_chart::parse(&text).map_err(|e| format!("{}: {e}", csv.display()))?;
    if rows.is_empty() {
        return Err(format!("{}: expected survey rows after the header, found none", csv.display()));
    }
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let svg = render_chart::svg(&rows)?;
    let write = |name: &str, bytes: &[u8]| {
        let path = out.join(name);
        std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))
    };
    write("render-chart.svg", svg.as_bytes())?;
    match chart::png(&svg) {
        Ok(png) => write("render-chart.png", &png)?,
        Err(e) => eprintln!("render-chart: no PNG: {e}"),
    }
    eprintln!("render-chart: wrote render-chart.svg and render-chart.png in {}", out.display());
    Ok(())
}

fn main() -> ExitCode {
    let result = parse_args().map_err(|e| format!("{e}\n{USAGE}")).and_then(|(csv, out)| run(&csv, &out));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("render-chart: {e}");
            ExitCode::from(2)
        }
    }
}
