//! `render`'s options.

use std::path::PathBuf;
use std::str::FromStr;

use speclab::data::lights;
use speclab::io::Load;
use speclab::sampling::choice::Sampling;
use speclab::sampling::strata::Strata;
use speclab::{Role, TabulatedSpectrum};

pub const USAGE: &str = "\
usage: render [--width W] [--height H] [--spp N] [--light NAME | --light-file PATH]...
              [--wavelengths hero|fitted|rgb] [--m M]
              [--pdf uniform|visible|light|balanced] [--strata none|jitter|kronecker]
              [--bins B | --exact-pdf] [--spectra exact|dense] [--precision f64|f32]
              [--exact] [--survey [--csv PATH] [--strip PATH]] [--reference N] [--threads T] [--out PATH]
  --width, --height  image size in pixels (default 256 × 256)
  --spp N            paths per pixel (default 32)
  --light NAME       a built-in light (listed below; default D65), or D and a temperature for
                     CIE daylight; --light-file reads any light. Twice: two lights in two
                     ceiling squares (at most two)
  --wavelengths W    how colour is carried: hero (default: four wavelengths per path, from --pdf),
                     fitted (a rule of --m wavelengths fitted to all the scene's lights, every
                     spectrum evaluated at them once), rgb (linear sRGB triples: albedos under D65)
  --m M              the fitted rule's wavelengths, 1 to 64 (default 10)
  --pdf P            how hero wavelengths are drawn (default uniform)
  --strata S         how a pixel's primary numbers are spread (default jitter)
  --bins B           sample visible and light pdfs from a histogram of B bins
                     (BinnedPdf, default 256); --exact-pdf samples the density itself
  --spectra S        hero over exact tabulated spectra (default) or dense 1 nm tables
  --precision P      the per-sample values' precision, f64 (default) or f32
  --exact            also integrate each path exactly over wavelength and compare pixel by pixel
                     (ΔE00 in CIELAB of the displayed white)
  --survey           every way (rgb, hero uniform and light pdf at 4 to 64 paths per pixel,
                     fitted M = 4 to 16) against the exact image of its own paths: a table;
                     --csv writes its rows, --strip a PNG of rgb | fitted | hero | exact
  --reference N      also render N paths per pixel and print the RMS ΔE*ab against it
  --threads T        worker threads (default 2)
  --out PATH         the PNG to write (default render.png)";

/// How colour is carried along the paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Hero,
    Fitted,
    Rgb,
}

impl FromStr for Mode {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "hero" => Ok(Mode::Hero),
            "fitted" => Ok(Mode::Fitted),
            "rgb" => Ok(Mode::Rgb),
            _ => Err(format!("expected a way to carry colour (hero, fitted or rgb), found {s:?}")),
        }
    }
}

#[derive(Clone)]
pub struct Args {
    pub width: usize,
    pub height: usize,
    pub spp: usize,
    /// The lights, named (one or two).
    pub lights: Vec<(String, TabulatedSpectrum)>,
    /// Whether the command line named the lights (else D65 alone).
    pub lights_given: bool,
    pub mode: Mode,
    pub m: usize,
    pub sampling: Sampling,
    pub dense: bool,
    pub single: bool,
    /// Bins of the histogram pdf, or `None` for the exact density.
    pub bins: Option<usize>,
    pub reference: Option<usize>,
    pub exact: bool,
    pub survey: bool,
    pub csv: Option<PathBuf>,
    pub strip: Option<PathBuf>,
    pub threads: usize,
    pub out: PathBuf,
}

impl Args {
    /// The lights' names, joined: `F11 + A`.
    pub fn light_names(&self) -> String {
        self.lights.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>().join(" + ")
    }
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
        width: 256,
        height: 256,
        spp: 32,
        lights: Vec::new(),
        lights_given: false,
        mode: Mode::Hero,
        m: 10,
        sampling: Sampling { strata: Strata::Jittered, ..Sampling::DEFAULT },
        dense: false,
        single: false,
        bins: Some(256),
        reference: None,
        exact: false,
        survey: false,
        csv: None,
        strip: None,
        threads: 2,
        out: PathBuf::from("render.png"),
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("width") => a.width = parser.value()?.parse_with(|v| positive("width", v))?,
            Long("height") => a.height = parser.value()?.parse_with(|v| positive("height", v))?,
            Long("spp") => a.spp = parser.value()?.parse_with(|v| positive("path count", v))?,
            Long("light") => {
                let name = parser.value()?.string()?;
                let canonical = lights::NAMES.iter().find(|n| n.eq_ignore_ascii_case(&name));
                let shown = canonical.map_or_else(|| name.to_uppercase(), |n| n.to_string());
                a.lights.push((shown, lights::named(&name)?.into_owned()));
            }
            Long("light-file") => {
                let path: PathBuf = parser.value()?.into();
                let light = Load::new(Role::Light).file(&path)?;
                a.lights.push((path.display().to_string(), light));
            }
            Long("wavelengths") => a.mode = parser.value()?.parse()?,
            Long("m") => {
                a.m = parser.value()?.parse_with(|v| {
                    v.parse::<usize>().ok().filter(|m| (1..=64).contains(m)).ok_or_else(|| {
                        format!("expected a fitted wavelength count from 1 to 64, found {v:?}")
                    })
                })?;
            }
            Long("pdf") => a.sampling.pdf = parser.value()?.parse()?,
            Long("strata") => a.sampling.strata = parser.value()?.parse()?,
            Long("spectra") => {
                let v = parser.value()?.string()?;
                a.dense = choice(&v, &[("exact", false), ("dense", true)], "exact or dense spectra")?;
            }
            Long("precision") => {
                let v = parser.value()?.string()?;
                a.single = choice(&v, &[("f64", false), ("f32", true)], "a precision")?;
            }
            Long("bins") => a.bins = Some(parser.value()?.parse_with(|v| positive("bin count", v))?),
            Long("exact-pdf") => a.bins = None,
            Long("exact") => a.exact = true,
            Long("survey") => a.survey = true,
            Long("csv") => a.csv = Some(parser.value()?.into()),
            Long("strip") => a.strip = Some(parser.value()?.into()),
            Long("reference") => {
                a.reference = Some(parser.value()?.parse_with(|v| positive("path count", v))?)
            }
            Long("threads") => a.threads = parser.value()?.parse_with(|v| positive("thread count", v))?,
            Long("out") => a.out = parser.value()?.into(),
            Short('h') | Long("help") => {
                println!("{USAGE}\nbuilt-in lights (any case): {}", lights::NAMES.join(", "));
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected().into()),
        }
    }
    if a.width.saturating_mul(a.height) > 1 << 24 {
        return Err("expected at most 16 M pixels".into());
    }
    if a.exact && !cfg!(feature = "study") {
        return Err("--exact needs speclab's study feature (on by default) for ΔE00".into());
    }
    if a.lights.len() > 2 {
        return Err(format!("expected one or two lights, found {}", a.lights.len()).into());
    }
    a.lights_given = !a.lights.is_empty();
    if a.lights.is_empty() {
        a.lights.push(("D65".into(), lights::D65.clone()));
    }
    Ok(a)
}
