//! Output formats of the study: tables for people, CSV for programs.
//!
//! Each writer takes rows the study computed and an `impl Write`; the
//! examples are argument parsing, one library call and one of these. **A
//! new output format** is one more writer here, over the same rows.
//!
//! ```
//! use speclab_cli::report;
//! use speclab_study::{experiments::grid::GridOptions, evaluate::viewing::Viewing, evaluate::scene};
//! let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let rows = GridOptions::default().rows(&lights[..1], &surfaces[..1])?;
//! let mut csv = Vec::new();
//! report::grid_csv(&mut csv, &rows, &Viewing::default())?;
//! let text = String::from_utf8(csv).unwrap();
//! assert!(text.starts_with("light,surface,method,samples,x,y,z,r,g,b,pdf,strata,evals\nA,E2,reference,0,"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::io::{self, Write};

mod chart;
mod plan;
mod rules;
mod texture;
pub use chart::chart_csv;
pub use plan::plan_text;
pub use rules::{depth_table, needs_table, rules_table};
pub use texture::texture_table;

use speclab::color::{LinearRgb, Xyz};
use speclab_study::display::{Exposure, GamutMap, PixelPipeline, Srgb8};
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::perceptual;
use speclab_study::evaluate::scene::Depth;
use speclab_study::evaluate::viewing::Viewing;
use speclab_study::experiments::compare::{CompareOptions, Line};
use speclab_study::experiments::convergence::{self, ConvergenceRow};
use speclab_study::experiments::grid::{GridOptions, GridRow};

/// Grid rows as CSV: `light,surface,method,samples,x,y,z,r,g,b`, then
/// `pdf,strata,evals`; full f64 precision, colours white-balanced if
/// `viewing` asks.
pub fn grid_csv(out: &mut impl Write, rows: &[GridRow], viewing: &Viewing) -> io::Result<()> {
    writeln!(out, "light,surface,method,samples,x,y,z,r,g,b,pdf,strata,evals")?;
    for row in rows {
        let xyz = viewing.adapt(row.xyz, &row.light.spectrum);
        let [r, g, b] = xyz.to_linear_srgb().to_array();
        let (light, surface, method) = (&row.light.name, &row.surface.name, row.method);
        let (pdf, strata) = sampling_columns(row.method);
        let evals = std::num::NonZeroUsize::new(row.samples).map_or(0, |n| row.method.evaluations(n));
        writeln!(
            out,
            "{light},{surface},{method},{},{},{},{},{r},{g},{b},{pdf},{strata},{evals}",
            row.samples, xyz.x, xyz.y, xyz.z
        )?;
    }
    Ok(())
}

/// Grid rows as a table per light, each estimate beside the reference with
/// its distance and ΔE00; with `swatches`, a truecolour swatch per row
/// (exposed by `Exposure::fit_white` for the light's white, mapped into the
/// gamut as it says).
pub fn grid_table(
    out: &mut impl Write,
    grid: &GridOptions,
    viewing: &Viewing,
    rows: &[GridRow],
    swatches: Option<GamutMap>,
) -> io::Result<()> {
    writeln!(out, "speclab grid: linear sRGB (unclamped) of light × patch, by method")?;
    let (n, m, seed, sampling) = (grid.n, grid.m, grid.seed, grid.sampling);
    writeln!(
        out,
        "random: n = {n} wavelengths; hero: n = {n} samples × 4 wavelengths; regular: M = {m} buckets; seed {seed}"
    )?;
    writeln!(out, "fitted: M = {m} wavelengths and weights fitted to each light (sampling::fitted)")?;
    if grid.depth != Depth::ONE {
        writeln!(out, "paths: light × patch^{} (every method, the reference included)", grid.depth)?;
    }
    let (pdf, strata) = (sampling.pdf, sampling.strata);
    writeln!(out, "random and hero wavelengths: pdf {pdf}, strata {strata}")?;
    let balance = if viewing.white_balance { "Bradford to D65" } else { "off" };
    writeln!(out, "normalise: {}; white balance: {balance}", viewing.normalize)?;
    writeln!(
        out,
        "Δ = distance to the reference in sRGB (and % of its length); ΔE00 in CIELAB of the light's white"
    )?;
    writeln!(out, "! = out of gamut (a negative component)")?;
    if let Some(gamut) = swatches {
        writeln!(out, "{}", swatch_legend(gamut))?;
    }
    let mut previous_light = "";
    for cell in rows.chunk_by(|a, b| a.light.name == b.light.name && a.surface.name == b.surface.name) {
        let light = &cell[0].light;
        if light.name != previous_light {
            previous_light = &light.name;
            writeln!(out, "\nLight {previous_light}")?;
            let h = ["patch", "method", "R", "G", "B", "Δ", "Δ%", "ΔE00"];
            let (a, b, c, d, e, f, g, i) = (h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]);
            let pad = swatch_pad(swatches.is_some());
            writeln!(out, "{pad}{a:<5} {b:<15} {c:>10} {d:>10} {e:>10}  {f:>9} {g:>7} {i:>7}")?;
        }
        let white = viewing.white(&light.spectrum);
        let display = swatches.map(|gamut| PixelPipeline::new(Exposure::fit_white(white), gamut));
        let reference = cell.iter().find(|r| r.method == Method::Reference).map(|r| r.xyz);
        let reference = reference.map(|x| viewing.adapt(x, &light.spectrum));
        for row in cell {
            let xyz = viewing.adapt(row.xyz, &light.spectrum);
            grid_line(out, row, xyz, reference, white, display)?;
        }
    }
    Ok(())
}

/// One grid row: swatch, patch (on the reference row), method, sRGB, and
/// the errors against `reference`.
fn grid_line(
    out: &mut impl Write,
    row: &GridRow,
    xyz: Xyz,
    reference: Option<Xyz>,
    white: Xyz,
    display: Option<PixelPipeline>,
) -> io::Result<()> {
    let rgb = xyz.to_linear_srgb();
    let patch = if row.method == Method::Reference { row.surface.name.as_str() } else { "" };
    let swatch = display.map_or_else(String::new, |d| swatch(d.pixel(rgb)));
    let flag = if rgb.in_gamut() { ' ' } else { '!' };
    let name = row.method.to_string();
    write!(out, "{swatch}{patch:<5} {name:<15} {:>10.3} {:>10.3} {:>10.3}{flag}", rgb.r, rgb.g, rgb.b)?;
    match reference.filter(|_| row.method != Method::Reference) {
        Some(exact) => {
            let exact_rgb = exact.to_linear_srgb();
            let d = rgb.distance(exact_rgb);
            let de = perceptual::delta_e00(xyz, exact, white);
            writeln!(out, " {d:>9.3} {:>7} {de:>7.2}", share(d, exact_rgb.distance(LinearRgb::default())))
        }
        None => writeln!(out),
    }
}

/// `part` as a percentage of `whole`, or `–` where that is undefined (a
/// black reference: a black surface, or a light without power).
fn share(part: f64, whole: f64) -> String {
    let percent = 100.0 * part / whole;
    if percent.is_finite() { format!("{percent:.2}%") } else { "–".to_string() }
}

/// Two truecolour terminal cells showing `pixel`.
fn swatch(pixel: Srgb8) -> String {
    let Srgb8 { r, g, b } = pixel;
    format!("\x1b[48;2;{r};{g};{b}m  \x1b[0m ")
}

/// Blanks as wide as a swatch, to align headers over rows that have one.
fn swatch_pad(swatches: bool) -> &'static str {
    if swatches { "   " } else { "" }
}

/// What the swatches show, for a table's header.
fn swatch_legend(gamut: GamutMap) -> String {
    let how = match gamut {
        GamutMap::Clip => "clipped per channel",
        GamutMap::Chroma => "out-of-gamut colours desaturated, hue and luminance kept",
    };
    format!(
        "swatches: exposed so the light's white just fits the display in its own colour; {how} (gamut map {}); sRGB",
        gamut
    )
}

/// bias X, Y, Z; sd X, Y, Z; RMS and p95 ΔE00.
fn numbers(r: &ConvergenceRow) -> [f64; 8] {
    let (b, s) = (r.stats.bias, r.stats.sd);
    [b.x, b.y, b.z, s.x, s.y, s.z, r.stats.rms_de00, r.stats.p95_de00]
}

/// Wavelength evaluations of a convergence row.
fn evals(r: &ConvergenceRow) -> usize {
    r.method.evaluations(std::num::NonZeroUsize::new(r.samples).unwrap_or(std::num::NonZeroUsize::MIN))
}

/// A random method's pdf and strata for tables and CSV, `-` for others.
fn sampling_columns(method: Method) -> (String, String) {
    method.sampling().map_or(("-".into(), "-".into()), |s| (s.pdf.to_string(), s.strata.to_string()))
}

/// Convergence rows as CSV, one per method, sampling and count. The first
/// thirteen columns are those of earlier versions; `pdf`, `strata` and
/// `evals` follow.
pub fn converge_csv(out: &mut impl Write, rows: &[ConvergenceRow]) -> io::Result<()> {
    writeln!(
        out,
        "light,surface,method,samples,trials,bias_x,bias_y,bias_z,sd_x,sd_y,sd_z,rms_de00,p95_de00,pdf,strata,evals"
    )?;
    for r in rows {
        let numbers: Vec<String> = numbers(r).iter().map(f64::to_string).collect();
        let head = format!("{},{},{},{},{}", r.light, r.surface, r.method, r.samples, r.stats.trials);
        let (pdf, strata) = sampling_columns(r.method);
        writeln!(out, "{head},{},{pdf},{strata},{}", numbers.join(","), evals(r))?;
    }
    Ok(())
}

/// Convergence rows as a table per light × surface × method (and sampling).
pub fn converge_table(
    out: &mut impl Write,
    rows: &[ConvergenceRow],
    trials: usize,
    seed: u64,
) -> io::Result<()> {
    writeln!(out, "speclab converge: {trials} trials per random row, base seed {seed}")?;
    writeln!(
        out,
        "evals = wavelength evaluations per estimate; bias and sd in XYZ; ΔE00 against the exact reference"
    )?;
    let heads = ["bias X", "bias Y", "bias Z", "sd X", "sd Y", "sd Z", "rms ΔE", "p95 ΔE"];
    for run in rows.chunk_by(|a, b| (&a.light, &a.surface, a.method) == (&b.light, &b.surface, b.method)) {
        let r = &run[0];
        let sampling = r.method.sampling().map_or(String::new(), |s| format!(" ({s})"));
        writeln!(out, "\n{} × {}: {}{sampling}", r.light, r.surface, r.method)?;
        let heads: String = heads.iter().map(|h| format!(" {h:>10}")).collect();
        writeln!(out, "{:>7} {:>7}{heads}", "samples", "evals")?;
        for r in run {
            let cells: String = numbers(r).iter().map(|v| format!(" {v:>10.4}")).collect();
            writeln!(out, "{:>7} {:>7}{cells}", r.samples, evals(r))?;
        }
    }
    Ok(())
}

/// One row per method (with its pdf and strata), one column per light and
/// threshold (1, then 0.5): the first count with RMS ΔE00 below the
/// threshold for every surface, and the count from which it stays below
/// when that differs (a Markdown table).
pub fn converge_summary(
    out: &mut impl Write,
    rows: &[ConvergenceRow],
    trials: usize,
    seed: u64,
) -> io::Result<()> {
    let mut lights: Vec<&str> = Vec::new();
    let mut methods: Vec<Method> = Vec::new();
    for r in rows {
        if !lights.contains(&r.light.as_str()) {
            lights.push(&r.light);
        }
        if !methods.contains(&r.method) {
            methods.push(r.method);
        }
    }
    writeln!(
        out,
        "Smallest n (random, hero: n samples of 1 or 4 wavelengths) and M (buckets) with RMS ΔE00"
    )?;
    writeln!(out, "below 1 and below 0.5 for every patch; `first / stays below from` where they differ;")?;
    writeln!(
        out,
        "n over powers of two up to {}, M up to 64; {trials} trials per random row, seed {seed}.\n",
        convergence::CONVERGENCE_MAX_N
    )?;
    let heads: Vec<String> =
        [1.0, 0.5].iter().flat_map(|t| lights.iter().map(move |l| format!("{l} < {t}"))).collect();
    writeln!(out, "| method | pdf | strata | {} |", heads.join(" | "))?;
    writeln!(out, "|---|---|---|{}", "---|".repeat(heads.len()))?;
    for method in methods {
        let cells: Vec<String> = [1.0, 0.5]
            .iter()
            .flat_map(|&t| lights.iter().map(move |l| convergence::crossing(rows, l, method, t)))
            .map(|c| {
                let show = |n: Option<usize>| n.map_or_else(|| "–".to_string(), |n| n.to_string());
                if c.first == c.stable {
                    show(c.first)
                } else {
                    format!("{} / {}", show(c.first), show(c.stable))
                }
            })
            .collect();
        let (pdf, strata) = sampling_columns(method);
        writeln!(out, "| {method} | {pdf} | {strata} | {} |", cells.join(" | "))?;
    }
    writeln!(out, "\n– : not reached within the counts studied.")
}

/// The lines of [`speclab_study::experiments::compare::compare`] as a table; with
/// `swatches`, a truecolour swatch per line shown through that display
/// (its exposure for the light's white: `Exposure::fit_white`).
pub fn compare_table(
    out: &mut impl Write,
    light: &str,
    surface: &str,
    s: &CompareOptions,
    lines: &[Line],
    swatches: Option<PixelPipeline>,
) -> io::Result<()> {
    let balance = if s.viewing.white_balance { "Bradford to D65" } else { "off" };
    let normalize = s.viewing.normalize;
    writeln!(
        out,
        "{light} × {surface}; normalise: {normalize}; white balance: {balance}; seed {}; RMS over {} trials",
        s.seed, s.trials
    )?;
    writeln!(out, "random and hero wavelengths: {}", s.sampling)?;
    if s.depth != Depth::ONE {
        writeln!(out, "paths: light × surface^{} (every line, the reference included)", s.depth)?;
    }
    if let Some(display) = swatches {
        writeln!(out, "{}", swatch_legend(display.gamut))?;
    }
    let h = ["technique", "evals", "R", "G", "B", "gamut", "ΔE00", "RMS ΔE00"];
    writeln!(
        out,
        "{}{:<18} {:>6} {:>11} {:>11} {:>11}  {:>6} {:>8} {:>8}",
        swatch_pad(swatches.is_some()),
        h[0],
        h[1],
        h[2],
        h[3],
        h[4],
        h[5],
        h[6],
        h[7]
    )?;
    for l in lines {
        let gamut = if l.rgb.in_gamut() { "in" } else { "OUT" };
        let LinearRgb { r, g, b } = l.rgb;
        let swatch = swatches.map_or_else(String::new, |d| swatch(d.pixel(l.rgb)));
        writeln!(
            out,
            "{swatch}{:<18} {:>6} {r:>11.4} {g:>11.4} {b:>11.4}  {gamut:>6} {:>8.3} {:>8.3}",
            l.label, l.evals, l.de00, l.rms_de00
        )?;
    }
    Ok(())
}
