//! What `render` prints and writes: the time per vertex, the error against
//! the exact image of the same paths, the PNG, and the survey's table,
//! CSV and strip.

use std::io::Write;
use std::path::Path;

use speclab::data::lights;
use speclab::io::Load;
use speclab::{Role, Xyz};
use speclab_cli::png::{self, Image};
use speclab_cli::progress;
use speclab_study::display::{Exposure, GamutMap, PixelPipeline};
use speclab_study::evaluate::Named;
use speclab_study::render::run::{Timed, delta_e, display_white, exact_cost};
use speclab_study::render::survey::{self, FITTED_M, HERO_SPP, Measured, Row};
use speclab_study::render::{Options, Render, Setup, Way};
use speclab_study::sampling::choice::PdfKind;

use crate::args::Args;

/// What was rendered, the time per vertex of colour and grey, and the
/// colour's overhead.
pub fn report(a: &Args, setup: &Setup, timed: &Timed) {
    let o = &a.options;
    let (ns_s, ns_g) = timed.ns_per_vertex(o.threads);
    let precision = if o.single { "f32" } else { "f64" };
    let how = match o.way {
        Way::Rgb => "rgb triples".to_string(),
        Way::Prefilter => "spectral prefiltering in sharpened RGB (Ward 2002)".to_string(),
        Way::Fitted => format!("a fitted rule of M = {}, {precision}", o.m),
        Way::Hero => format!(
            "hero, pdf {}{}, strata {}, {} {precision} spectra",
            o.sampling.pdf,
            match (o.sampling.pdf.follows_light() || o.sampling.pdf == PdfKind::Visible, o.bins) {
                (false, _) => String::new(),
                (true, Some(bins)) => format!(" ({bins} bins)"),
                (true, None) => " (exact)".into(),
            },
            o.sampling.strata,
            match (o.dense, o.rgb_space) {
                (_, Some(space)) if o.rgb_converted => {
                    format!("dense lights, RGB surfaces in {space} converted once,")
                }
                (_, Some(space)) => format!("dense lights, RGB surfaces in {space} looked up at each hit,"),
                (true, None) => "dense".to_string(),
                (false, None) => "exact".to_string(),
            },
        ),
    };
    let (s, g) = (&timed.image, &timed.grey);
    println!(
        "{} × {}, {} paths per pixel, light {}, {how}, {} threads",
        o.width,
        o.height,
        o.spp,
        setup.light_names(),
        o.threads
    );
    println!("colour: {:.2} s, {} vertices, {ns_s:.1} ns per vertex per thread", s.seconds, s.vertices);
    println!("grey:   {:.2} s, {} vertices, {ns_g:.1} ns per vertex per thread", g.seconds, g.vertices);
    println!("colour's overhead: {:.0} % of the grey time per vertex", 100.0 * (ns_s - ns_g) / ns_g);
}

/// `--exact`: the render against the exact image of its own paths, and
/// what the exact image cost (`prepared`: its quadrature's time, s).
pub fn exact_report(o: &Options, setup: &Setup, with_exact: &Render, seconds: f64, prepared: f64) {
    let Some(exact) = &with_exact.exact else { return };
    let [mean, p95, max] = delta_e(&with_exact.xyz, exact, setup.white);
    println!(
        "against the exact image of the same paths: ΔE00 mean {mean:.3}, 95th percentile {p95:.3}, max {max:.3}"
    );
    println!(
        "the exact image: {:.0} ns more per path per thread (its quadrature prepared in {:.1} ms)",
        exact_cost(o, with_exact, seconds),
        prepared * 1e3
    );
}

/// 8-bit sRGB of `xyz` through `speclab_study::display` (exposed to the display
/// white of `exposed_by`, chroma-reduced into the gamut).
pub fn srgb8(xyz: &[Xyz], white: Xyz, exposed_by: &[Xyz]) -> Vec<u8> {
    let display = PixelPipeline::new(Exposure::fit_white(display_white(exposed_by, white)), GamutMap::Chroma);
    xyz.iter().flat_map(|p| display.pixel(p.to_linear_srgb()).to_array()).collect()
}

/// The image as an sRGB PNG.
pub fn write_png(out: &Path, width: usize, height: usize, xyz: &[Xyz], white: Xyz) -> std::io::Result<()> {
    write_rgb(out, Image { width, height, rgb: srgb8(xyz, white, xyz) })
}

/// 8-bit RGB rows as a PNG.
fn write_rgb(out: &Path, image: Image) -> std::io::Result<()> {
    png::write_file(out, &image)?;
    println!("wrote {}", out.display());
    Ok(())
}

/// `--survey`: every way on the five standard scenes (or on the command
/// line's), a Markdown table as the rows come, then the CSV and the strip
/// if asked.
pub fn survey(a: &Args) -> Result<(), Box<dyn std::error::Error>> {
    let scenes = if a.lights_given {
        vec![a.lights.clone()]
    } else {
        let led = Load::new(Role::Light).file("examples/build-data/data/led.csv")?;
        survey::standard_scenes(Named::new("led.csv", led))
    };
    let per_scene = 1 + FITTED_M.len() + 2 * HERO_SPP.len();
    let bar = progress::bar("survey", (scenes.len() * per_scene) as u64);
    let out = &mut std::io::stdout().lock();
    writeln!(out, "| scene | way | paths per pixel | ns per path | ΔE00 mean | ΔE00 95th | ΔE00 max |")?;
    writeln!(out, "|---|---|---:|---:|---:|---:|---:|")?;
    let mut rows = Vec::new();
    for lights in scenes {
        let setup = Setup::new(&lights)?;
        rows.extend(survey::survey(&a.options, &setup, |m| {
            let r = &m.row;
            let [mean, p95, max] = r.de00;
            let _ = writeln!(
                out,
                "| {} | {} | {} | {:.0} | {mean:.3} | {p95:.3} | {max:.3} |",
                r.scene, r.way, r.spp, r.ns_per_path
            );
            let _ = out.flush();
            bar.inc(1);
        })?);
    }
    bar.finish_and_clear();
    if let Some(path) = &a.csv {
        let lines: Vec<String> = rows.iter().map(|m| m.row.csv()).collect();
        std::fs::write(path, format!("{}\n{}\n", Row::CSV_HEADER, lines.join("\n")))?;
        writeln!(out, "\nwrote {}", path.display())?;
    }
    if let Some(path) = &a.strip {
        strip(&a.options, &rows, path)?;
    }
    Ok(())
}

/// rgb | fitted M = 10 | hero (uniform, jittered) at about the fitted
/// rule's time per pixel | the exact image of the fitted rule's paths,
/// under F11 alone: each the same crop (the left half, the middle half of
/// the rows: the red wall, half the texture, the yellow sphere) at three
/// times the render's size, all exposed as the exact crop is (its 98th
/// percentile white).
fn strip(o: &Options, rows: &[Measured], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let under_f11: Vec<&Measured> = rows.iter().filter(|m| m.row.scene == "F11").collect();
    let find = |way: &str| under_f11.iter().find(|m| m.row.way == way).copied();
    let (Some(rgb), Some(fit)) = (find("rgb"), find("fitted M=10")) else {
        return Err("the strip needs the scene under F11 alone (run the survey without --light)".into());
    };
    let hero = under_f11
        .iter()
        .filter(|m| m.row.way == "hero uniform/jitter")
        .min_by(|x, y| {
            let gap = |m: &Measured| (m.row.ns_per_pixel() - fit.row.ns_per_pixel()).abs();
            gap(x).total_cmp(&gap(y))
        })
        .ok_or("no hero row")?;
    let white = speclab::sampling::reference::white(&lights::F11);
    let (w, h, zoom, gap) = (o.width, o.height, 3, 6);
    let (x0, y0, cw, ch) = (0, h / 4, w / 2, h / 2);
    let crop = |img: &[Xyz]| -> Vec<Xyz> {
        (0..cw * ch).map(|i| img.get((y0 + i / cw) * w + x0 + i % cw).copied().unwrap_or(Xyz::ZERO)).collect()
    };
    let exact = crop(&fit.exact);
    let panels =
        [&rgb.image, &fit.image, &hero.image, &fit.exact].map(|img| srgb8(&crop(img), white, &exact));
    let (big_w, big_h) = (4 * zoom * cw + 3 * gap, zoom * ch);
    let mut out = vec![255u8; big_w * big_h * 3];
    for (p, panel) in panels.iter().enumerate() {
        for y in 0..big_h {
            for x in 0..zoom * cw {
                let src = ((y / zoom) * cw + x / zoom) * 3;
                let dst = (y * big_w + p * (zoom * cw + gap) + x) * 3;
                out[dst..dst + 3].copy_from_slice(&panel[src..src + 3]);
            }
        }
    }
    println!(
        "strip: rgb | fitted M=10 | hero uniform/jitter at {} paths per pixel | exact, {} paths per pixel",
        hero.row.spp, fit.row.spp
    );
    Ok(write_rgb(path, Image { width: big_w, height: big_h, rgb: out })?)
}
