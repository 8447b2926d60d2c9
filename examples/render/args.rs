//! `render`'s options.

use std::path::PathBuf;

use speclab::Role;
use speclab::data::lights;
use speclab::io::Load;
use speclab_study::evaluate::Named;
use speclab_study::render::{Options, Way};

pub const USAGE: &str = "\
usage: render [--width W] [--height H] [--spp N] [--light NAME | --light-file PATH]...
              [--wavelengths hero|fitted|rgb|prefilter] [--m M]
              [--pdf uniform|visible|light|balanced] [--strata none|jitter|kronecker]
              [--bins B | --exact-pdf] [--spectra exact|dense|rgb] [--space NAME] [--precision f64|f32]
              [--exact] [--survey [--csv PATH] [--strip PATH]] [--reference N] [--threads T] [--out PATH]
  --width, --height  image size in pixels (default 256 × 256)
  --spp N            paths per pixel (default 32)
  --light NAME       a built-in light (listed below; default D65), or D and a temperature for
                     CIE daylight; --light-file reads any light. Twice: two lights in two
                     ceiling squares (at most two)
  --wavelengths W    how colour is carried: hero (default: four wavelengths per path, from --pdf),
                     fitted (a rule of --m wavelengths fitted to all the scene's lights, every
                     spectrum evaluated at them once), rgb (linear sRGB triples: albedos under D65),
                     prefilter (three numbers per surface prefiltered under the scene's lights,
                     in sharpened RGB: Ward and Eydelberg-Vileshin 2002)
  --m M              the fitted rule's wavelengths, 1 to 64 (default 10)
  --pdf P            how hero wavelengths are drawn (default uniform)
  --strata S         how a pixel's primary numbers are spread (default jitter)
  --bins B           sample visible and light pdfs from a histogram of B bins
                     (BinnedPdf, default 256); --exact-pdf samples the density itself
  --spectra S        hero over exact tabulated spectra (default), dense 1 nm tables, or rgb: every
                     surface an RGB colour in --space looked up in its table at each hit
                     (a textured scene, as pbrt-v4 reads image textures; the lights dense), or
                     rgb-converted: the same colours converted once, when the scene is built
                     (as Mitsuba 3 loads bitmap textures)
  --space NAME       rgb's space: sRGB (default), Display P3, Rec.2020, ACES2065-1, ACEScg
  --precision P      the per-sample values' precision, f64 (default) or f32
  --exact            also integrate each path exactly over wavelength and compare pixel by pixel
                     (ΔE00 in CIELAB of the displayed white)
  --survey           every way (rgb, prefilter, hero uniform and light pdf at 4 to 64 paths per pixel,
                     fitted M = 4 to 16) against the exact image of its own paths: a table;
                     --csv writes its rows, --strip a PNG of rgb | fitted | hero | exact
  --reference N      also render N paths per pixel and print the RMS ΔE*ab against it
  --threads T        worker threads (default 2)
  --out PATH         the PNG to write (default render.png)";

/// What to render (the study's options) and what to do with it.
pub struct Args {
    pub options: Options,
    /// The lights, named (one or two).
    pub lights: Vec<Named>,
    /// Whether the command line named the lights (else D65 alone).
    pub lights_given: bool,
    pub reference: Option<usize>,
    pub exact: bool,
    pub survey: bool,
    pub csv: Option<PathBuf>,
    pub strip: Option<PathBuf>,
    pub out: PathBuf,
}

fn positive(what: &str, v: &str) -> Result<usize, String> {
    v.parse::<usize>()
        .ok()
        .filter(|&n| n > 0)
        .ok_or_else(|| format!("expected a positive {what}, found {v:?}"))
}

fn choice<T>(value: &str, pairs: &[(&str, T)], what: &str) -> Result<T, String>
where
    T: Copy,
{
    let found = pairs.iter().find(|(name, _)| name.eq_ignore_ascii_case(value)).map(|&(_, v)| v);
    let names: Vec<&str> = pairs.iter().map(|(n, _)| *n).collect();
    found.ok_or_else(|| format!("expected {what} ({}), found {value:?}", names.join(" or ")))
}

pub fn parse() -> Result<Args, Box<dyn std::error::Error>> {
    use lexopt::prelude::*;
    let mut a = Args {
        options: Options::default(),
        lights: Vec::new(),
        lights_given: false,
        reference: None,
        exact: false,
        survey: false,
        csv: None,
        strip: None,
        out: PathBuf::from("render.png"),
    };
    let o = &mut a.options;
    let mut parser = lexopt::Parser::from_env();
    let mut space: Option<&'static str> = None;
    while let Some(arg) = parser.next()? {
        match arg {
            Long("width") => o.width = parser.value()?.parse_with(|v| positive("width", v))?,
            Long("height") => o.height = parser.value()?.parse_with(|v| positive("height", v))?,
            Long("spp") => o.spp = parser.value()?.parse_with(|v| positive("path count", v))?,
            Long("light") => {
                let name = parser.value()?.string()?;
                let canonical = lights::NAMES.iter().find(|n| n.eq_ignore_ascii_case(&name));
                let shown = canonical.map_or_else(|| name.to_uppercase(), |n| n.to_string());
                a.lights.push(Named::new(shown, lights::named(&name)?.into_owned()));
            }
            Long("light-file") => {
                let path: PathBuf = parser.value()?.into();
                let light = Load::new(Role::Light).file(&path)?;
                a.lights.push(Named::new(path.display().to_string(), light));
            }
            Long("wavelengths") => o.way = parser.value()?.parse::<Way>()?,
            Long("m") => {
                o.m = parser.value()?.parse_with(|v| {
                    v.parse::<usize>().ok().filter(|m| (1..=64).contains(m)).ok_or_else(|| {
                        format!("expected a fitted wavelength count from 1 to 64, found {v:?}")
                    })
                })?;
            }
            Long("pdf") => o.sampling.pdf = parser.value()?.parse()?,
            Long("strata") => o.sampling.strata = parser.value()?.parse()?,
            Long("spectra") => {
                let v = parser.value()?.string()?;
                let kinds = [
                    ("exact", (false, false, false)),
                    ("dense", (true, false, false)),
                    ("rgb", (true, true, false)),
                    ("rgb-converted", (true, true, true)),
                ];
                let (dense, rgb, converted) = choice(&v, &kinds, "a kind of spectra")?;
                o.dense = dense;
                o.rgb_space = rgb.then_some(o.rgb_space.unwrap_or("sRGB"));
                o.rgb_converted = converted;
            }
            Long("space") => {
                let v = parser.value()?.string()?;
                let spaces = speclab_study::render::run::SPACES;
                let name = spaces.iter().find(|s| s.eq_ignore_ascii_case(&v));
                let name = name
                    .ok_or_else(|| format!("expected an RGB space ({}), found {v:?}", spaces.join(", ")))?;
                space = Some(*name);
            }
            Long("precision") => {
                let v = parser.value()?.string()?;
                o.single = choice(&v, &[("f64", false), ("f32", true)], "a precision")?;
            }
            Long("bins") => o.bins = Some(parser.value()?.parse_with(|v| positive("bin count", v))?),
            Long("exact-pdf") => o.bins = None,
            Long("exact") => a.exact = true,
            Long("survey") => a.survey = true,
            Long("csv") => a.csv = Some(parser.value()?.into()),
            Long("strip") => a.strip = Some(parser.value()?.into()),
            Long("reference") => {
                a.reference = Some(parser.value()?.parse_with(|v| positive("path count", v))?)
            }
            Long("threads") => o.threads = parser.value()?.parse_with(|v| positive("thread count", v))?,
            Long("out") => a.out = parser.value()?.into(),
            Short('h') | Long("help") => {
                println!("{USAGE}\n{}", speclab_cli::args::names_help());
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected().into()),
        }
    }
    if let Some(name) = space {
        if a.options.rgb_space.is_none() {
            return Err("expected --spectra rgb with --space".into());
        }
        a.options.rgb_space = Some(name);
    }
    if a.options.rgb_space.is_some() && a.options.way != Way::Hero {
        return Err("expected --wavelengths hero with --spectra rgb (the textured scene is hero's)".into());
    }
    if a.options.width.saturating_mul(a.options.height) > 1 << 24 {
        return Err("expected at most 16 M pixels".into());
    }
    if a.lights.len() > 2 {
        return Err(format!("expected one or two lights, found {}", a.lights.len()).into());
    }
    a.lights_given = !a.lights.is_empty();
    if a.lights.is_empty() {
        a.lights.push(Named::new("D65", lights::D65.clone()));
    }
    Ok(a)
}
