//! A spectral OpenEXR image to an sRGB PNG: developed by a sensor (a CIE
//! observer, or a camera with its sensor → XYZ matrix fitted over the
//! measured Munsell chips), under a light for a reflective image (one
//! panel per `--light`, side by side), white-balanced to D65 if asked,
//! exposed so the 98th percentile of each panel's luminance is white.
//!
//! ```text
//! cargo run --release -p speclab-exr --example develop -- box.exr --out box.png
//! cargo run --release -p speclab-exr --example develop -- box-reflective.exr --light A --light D65 --light F11 --out three.png
//! cargo run --release -p speclab-exr --example develop -- box-reflective.exr --light A --sensor nikon_d850 --white-balance light
//! ```

use std::path::PathBuf;
use std::process::ExitCode;

use speclab::Xyz;
use speclab::color::adaptation::Cat;
use speclab::data::lights;
use speclab::film::{Develop, Kind, Sensor, SpectralImage, WhiteBalance};
use speclab::spectrum::{Spectrum, StandardObserver, TabulatedSpectrum};
use speclab_cli::png::{self, Image};
use speclab_study::display::{Exposure, GamutMap, PixelPipeline};
use speclab_study::published::measured;
use speclab_study::render::run::display_white;

const USAGE: &str = "\
usage: develop FILE.exr [--light NAME]... [--sensor NAME] [--white-balance none|light|KELVIN]
               [--cat bradford|von-kries|cat02|cat16|xyz] [--out PATH]
  --light NAME          a built-in light for a reflective image (one panel each; default D65)
  --sensor NAME         cie1931 (default), cie1964, or a camera: canon_eos_100d … sony_ilce_9
  --white-balance W     none (default), light (each panel's light to D65), or daylight of KELVIN
  --cat C               the cone space of the balance (default bradford)
  --out PATH            the PNG (default develop.png)";

struct Args {
    file: PathBuf,
    lights: Vec<String>,
    sensor: String,
    balance: Option<String>,
    cat: Cat,
    out: PathBuf,
}

fn parse() -> Result<Args, Box<dyn std::error::Error>> {
    use lexopt::prelude::*;
    let (mut file, mut lights, mut sensor, mut balance) = (None, Vec::new(), "cie1931".to_string(), None);
    let (mut cat, mut out) = (Cat::Bradford, PathBuf::from("develop.png"));
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Value(v) if file.is_none() => file = Some(PathBuf::from(v)),
            Long("light") => lights.push(parser.value()?.parse()?),
            Long("sensor") => sensor = parser.value()?.parse()?,
            Long("white-balance") => {
                balance = Some(parser.value()?.parse::<String>()?).filter(|w| w != "none")
            }
            Long("cat") => {
                let name: String = parser.value()?.parse()?;
                cat = match name.as_str() {
                    "bradford" => Cat::Bradford,
                    "von-kries" => Cat::VonKries,
                    "cat02" => Cat::Cat02,
                    "cat16" => Cat::Cat16,
                    "xyz" => Cat::XyzScaling,
                    _ => return Err(format!("unknown --cat {name}").into()),
                };
            }
            Long("out") => out = parser.value()?.into(),
            Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected().into()),
        }
    }
    let file = file.ok_or("expected a spectral OpenEXR file")?;
    Ok(Args { file, lights, sensor, balance, cat, out })
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("develop: {e}\n{USAGE}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let a = parse()?;
    let read = speclab_exr::read(&a.file).map_err(|e| format!("{}: {e}", a.file.display()))?;
    let image = &read.image;
    let names = match (image.kind(), a.lights.is_empty()) {
        (Kind::Emissive, true) => vec![None],
        (Kind::Emissive, false) => {
            return Err("an emissive image carries its light: develop it without --light".into());
        }
        (Kind::Reflective, true) => vec![Some("D65".to_string())],
        (Kind::Reflective, false) => a.lights.iter().cloned().map(Some).collect(),
    };
    let (width, height) = image.size();
    let mut panels = Vec::new();
    for name in &names {
        let light = name.as_deref().map(lights::named).transpose()?.map(|l| l.into_owned());
        let xyz = develop(&a, image, light.as_ref())?;
        let white = xyz.iter().fold(Xyz::ZERO, |w, p| if p.y > w.y { *p } else { w });
        let display = PixelPipeline::new(
            Exposure::fit_white(display_white(&xyz, white * (1.0 / white.y.max(1e-300)))),
            GamutMap::Chroma,
        );
        panels.push(xyz.iter().map(|p| display.pixel(p.to_linear_srgb()).to_array()).collect::<Vec<_>>());
        let label = name.as_deref().unwrap_or("its own light");
        println!(
            "{}: {width} × {height}, {} wavelengths, under {label}, sensor {}",
            a.file.display(),
            image.wavelengths().len(),
            a.sensor
        );
    }
    let mut rgb = Vec::with_capacity(3 * width * height * panels.len());
    for y in 0..height {
        for panel in &panels {
            rgb.extend(panel[y * width..(y + 1) * width].iter().flatten());
        }
    }
    png::write_file(&a.out, &Image { width: width * panels.len(), height, rgb })?;
    println!("wrote {}", a.out.display());
    Ok(())
}

/// The image's XYZ by the sensor, under `light` (reflective), balanced.
fn develop(
    a: &Args,
    image: &SpectralImage,
    light: Option<&TabulatedSpectrum>,
) -> Result<Vec<Xyz>, Box<dyn std::error::Error>> {
    let observer = |name: &str| match name {
        "cie1931" => Some(StandardObserver::Cie1931),
        "cie1964" => Some(StandardObserver::Cie1964),
        _ => None,
    };
    let d65 = lights::named("CIE-D65")?;
    let to = Xyz::new(0.95047, 1.0, 1.08883);
    let (sensor, matrix) = match observer(&a.sensor) {
        Some(o) => (Sensor::observer(o), None),
        None => {
            let camera = Sensor::camera(&a.sensor)?;
            // The camera's matrix under the light it is balanced for.
            let under: &dyn Spectrum = light.map_or(&*d65, |l| l as &dyn Spectrum);
            let chips: Vec<TabulatedSpectrum> =
                measured::munsell()?.into_iter().map(|c| c.spectrum).collect();
            let fit = camera.fit_xyz(&chips, under, under, StandardObserver::Cie1931)?;
            println!(
                "{}: sensor → XYZ fitted over {} Munsell chips, residual RMS {:.4}, max {:.4} (Y of white = 1)",
                a.sensor, fit.count, fit.rms, fit.max
            );
            (camera, Some(fit.matrix))
        }
    };
    let mut develop = Develop::new(sensor);
    if let Some(l) = light {
        develop = develop.light(l);
    }
    if let Some(m) = matrix {
        develop = develop.sensor_to_xyz(m);
    }
    let balance = match a.balance.as_deref() {
        None => None,
        Some("light") => {
            Some(WhiteBalance::light(light.map_or(&*d65, |l| l), to, a.cat, StandardObserver::Cie1931)?)
        }
        Some(kelvin) => Some(WhiteBalance::daylight(kelvin.parse()?, to, a.cat, StandardObserver::Cie1931)?),
    };
    if let Some(b) = balance {
        develop = develop.balance(b);
    }
    Ok(develop.xyz(image)?)
}
