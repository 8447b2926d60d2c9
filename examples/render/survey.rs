//! `--survey`: every way of carrying colour on one scene (or on the five
//! standard scenes), each against the exact image of its own paths:
//! per-pixel ΔE00 (mean, 95th percentile, maximum) and the time per path
//! on one thread. A Markdown table on standard output, its rows as CSV
//! (`--csv`), and a strip of rgb | fitted | hero at equal time | exact
//! (`--strip`) for the scene under F11 alone.

use std::io::Write;
use std::path::Path;

use speclab::data::lights;
use speclab::io::Load;
use speclab::sampling::choice::{PdfKind, Sampling};
use speclab::sampling::strata::Strata;
use speclab::spectrum::Cie1931;
use speclab::{Role, TabulatedSpectrum, Xyz};

use crate::args::{Args, Mode};
use crate::output::{delta_e, srgb8, write_rgb};
use crate::paint::Rgb;
use crate::tracer::Paint;
use crate::{Render, Setup, WithPaint, fitted, hero, render, wavelength_pdf};

/// Hero's paths per pixel in the survey.
const HERO_SPP: [usize; 5] = [4, 8, 16, 32, 64];
/// The fitted rules' sizes in the survey.
const FITTED_M: [usize; 6] = [4, 6, 8, 10, 12, 16];

/// One way on one scene: what it is, and how it did.
pub struct Row {
    pub scene: String,
    pub way: String,
    pub spp: usize,
    pub ns_per_path: f64,
    pub de00: [f64; 3],
    pub image: Vec<Xyz>,
    pub exact: Vec<Xyz>,
}

/// ns per path per thread.
fn ns_per_path(r: &Render, paths: usize, threads: usize) -> f64 {
    r.seconds * 1e9 * threads as f64 / paths.max(1) as f64
}

/// Times a paint on one thread, then renders it again with the exact image
/// of the same paths and measures the difference.
struct Measure<'a> {
    a: &'a Args,
    setup: &'a Setup,
    spp: usize,
}

impl WithPaint for Measure<'_> {
    type Out = (f64, [f64; 3], Render);
    fn go<P: Paint>(self, paint: &P) -> Self::Out {
        let (a, setup, spp) = (self.a, self.setup, self.spp);
        let paths = a.width * a.height * spp;
        let timed = (0..2)
            .map(|_| ns_per_path(&render(&setup.scene, paint, a, (spp, 1), 1, None), paths, 1))
            .fold(f64::INFINITY, f64::min);
        let exact = setup.exact();
        let with_exact = render(&setup.scene, paint, a, (spp, a.threads), 1, Some(&exact));
        let de = delta_e(&with_exact.xyz, with_exact.exact.as_deref().unwrap_or_default(), setup.white);
        (timed, de, with_exact)
    }
}

/// The five standard scenes, or the one of the command line.
fn scenes(a: &Args) -> Result<Vec<Vec<(String, TabulatedSpectrum)>>, speclab::Error> {
    if !a.lights_given {
        let named = |n: &str| (n.to_string(), lights::named(n).map(|l| l.into_owned()));
        let file = Path::new("examples/build-data/data/led.csv");
        let led = ("led.csv".to_string(), Load::new(Role::Light).file(file));
        let list = [named("A"), named("D65"), named("F11"), led];
        let mut out = Vec::new();
        for (name, light) in list {
            out.push(vec![(name, light?)]);
        }
        out.push(vec![("F11".into(), lights::F11.clone()), ("A".into(), lights::A.clone())]);
        return Ok(out);
    }
    Ok(vec![a.lights.clone()])
}

pub fn run(a: &Args, _: &Setup) -> Result<(), Box<dyn std::error::Error>> {
    let mut rows = Vec::new();
    let out = &mut std::io::stdout().lock();
    writeln!(out, "| scene | way | paths per pixel | ns per path | ΔE00 mean | ΔE00 95th | ΔE00 max |")?;
    writeln!(out, "|---|---|---:|---:|---:|---:|---:|")?;
    for lights in scenes(a)? {
        let scene = Args { lights, ..a.clone() };
        let setup = Setup::new(&scene)?;
        for row in survey(&scene, &setup)? {
            writeln!(
                out,
                "| {} | {} | {} | {:.0} | {:.3} | {:.3} | {:.3} |",
                row.scene, row.way, row.spp, row.ns_per_path, row.de00[0], row.de00[1], row.de00[2]
            )?;
            out.flush()?;
            rows.push(row);
        }
    }
    if let Some(path) = &a.csv {
        let mut csv = String::from("scene,way,spp,ns_per_path,de00_mean,de00_p95,de00_max\n");
        for r in &rows {
            csv += &format!(
                "{},{},{},{},{},{},{}\n",
                r.scene, r.way, r.spp, r.ns_per_path, r.de00[0], r.de00[1], r.de00[2]
            );
        }
        std::fs::write(path, csv)?;
        writeln!(out, "\nwrote {}", path.display())?;
    }
    if let Some(path) = &a.strip {
        strip(a, &rows, path)?;
    }
    Ok(())
}

/// Every way on one scene.
fn survey(a: &Args, setup: &Setup) -> Result<Vec<Row>, Box<dyn std::error::Error>> {
    let scene = a.light_names();
    let mut rows = Vec::new();
    let mut push = |way: String, spp: usize, (ns, de, r): (f64, [f64; 3], Render)| {
        let exact = r.exact.unwrap_or_default();
        rows.push(Row { scene: scene.clone(), way, spp, ns_per_path: ns, de00: de, image: r.xyz, exact });
    };
    let measure = |spp| Measure { a, setup, spp };
    push("rgb".into(), a.spp, measure(a.spp).go(&Rgb::new(&setup.lights, &setup.patches, &setup.colours)));
    for m in FITTED_M {
        let fitted_a = Args { mode: Mode::Fitted, m, ..a.clone() };
        push(format!("fitted M={m}"), a.spp, fitted(&fitted_a, setup, m, measure(a.spp))?);
    }
    for pdf in [PdfKind::Uniform, PdfKind::Light] {
        let hero_a = Args { sampling: Sampling { pdf, strata: Strata::Jittered }, ..a.clone() };
        let density = wavelength_pdf(&hero_a, setup)?;
        for spp in HERO_SPP {
            let paint =
                hero::<_, _, f64>(setup.lights.clone(), setup.patches.clone(), Cie1931, setup, &*density);
            push(format!("hero {pdf}/jitter"), spp, measure(spp).go(&paint));
        }
    }
    Ok(rows)
}

/// rgb | fitted M = 10 | hero (uniform, jittered) at about the fitted
/// rule's time per pixel | the exact image of the fitted rule's paths,
/// under F11 alone: each the same crop (the left half, the middle half of
/// the rows: the red wall, half the texture, the yellow sphere) at three
/// times the render's size, all exposed as the exact crop is (its 98th
/// percentile white).
fn strip(a: &Args, rows: &[Row], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let under_f11: Vec<&Row> = rows.iter().filter(|r| r.scene == "F11").collect();
    let find = |way: &str| under_f11.iter().find(|r| r.way == way).copied();
    let (Some(rgb), Some(fit)) = (find("rgb"), find("fitted M=10")) else {
        return Err("the strip needs the scene under F11 alone (run the survey without --light)".into());
    };
    let per_pixel = |r: &Row| r.ns_per_path * r.spp as f64;
    let hero = under_f11
        .iter()
        .filter(|r| r.way == "hero uniform/jitter")
        .min_by(|x, y| {
            (per_pixel(x) - per_pixel(fit)).abs().total_cmp(&(per_pixel(y) - per_pixel(fit)).abs())
        })
        .ok_or("no hero row")?;
    let white = speclab::sampling::reference::white(&lights::F11);
    let (w, h, zoom, gap) = (a.width, a.height, 3, 6);
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
        hero.spp, fit.spp
    );
    Ok(write_rgb(path, big_w, big_h, &out)?)
}
