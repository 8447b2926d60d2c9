//! The study's path tracer onto a spectral film, written as a spectral
//! OpenEXR file: hero paths (four wavelengths, f64, the scene's exact
//! spectra, weighed by the CIE 1931 observer as a sensor) splatted into
//! 1 nm buckets at the whole nanometres of 380–730 nm (or `--buckets M`
//! over 380–730 nm). It reads the file back and prints how the image
//! compares: bit for bit with the film, and the XYZ developed from the
//! file against the tracer's own XYZ of the same paths.
//!
//! ```text
//! cargo run --release -p speclab-exr --example film -- --light D65 --out box.exr
//! cargo run --release -p speclab-exr --example film -- --light E --reflective --out box-reflective.exr
//! ```

use std::path::PathBuf;
use std::process::ExitCode;

use speclab::Xyz;
use speclab::data::lights;
use speclab::film::{Buckets, Develop, Kind, Quadrature, Sensor};
use speclab::spectrum::{StandardObserver, WavelengthRange};
use speclab_exr::{Precision, WriteOptions};
use speclab_study::evaluate::Named;
use speclab_study::render::film::{self, whole_nm};
use speclab_study::render::{Options, Setup};

const USAGE: &str = "\
usage: film [--width W] [--height H] [--spp N] [--light NAME]... [--reflective]
            [--buckets M] [--f16] [--out PATH]
  --light NAME   a built-in light (default D65); twice: two lights (not with --reflective)
  --reflective   keep each path's throughput without its light (T.<λ>nm channels): one light
  --buckets M    M equal buckets over 380–730 nm (default: 351 of 1 nm at 380, 381, …, 730 nm)
  --f16          half floats (default f32)
  --out PATH     the file to write (default film.exr)";

struct Args {
    options: Options,
    lights: Vec<Named>,
    kind: Kind,
    buckets: Option<usize>,
    precision: Precision,
    out: PathBuf,
}

fn parse() -> Result<Args, Box<dyn std::error::Error>> {
    use lexopt::prelude::*;
    let mut a = Args {
        options: Options { width: 64, height: 64, spp: 16, ..Options::default() },
        lights: Vec::new(),
        kind: Kind::Emissive,
        buckets: None,
        precision: Precision::F32,
        out: "film.exr".into(),
    };
    let mut parser = lexopt::Parser::from_env();
    while let Some(arg) = parser.next()? {
        match arg {
            Long("width") => a.options.width = parser.value()?.parse()?,
            Long("height") => a.options.height = parser.value()?.parse()?,
            Long("spp") => a.options.spp = parser.value()?.parse()?,
            Long("light") => {
                let name: String = parser.value()?.parse()?;
                a.lights.push(Named::new(name.clone(), lights::named(&name)?.into_owned()));
            }
            Long("reflective") => a.kind = Kind::Reflective,
            Long("buckets") => a.buckets = Some(parser.value()?.parse()?),
            Long("f16") => a.precision = Precision::F16,
            Long("out") => a.out = parser.value()?.into(),
            Long("help") => {
                println!("{USAGE}");
                std::process::exit(0);
            }
            _ => return Err(arg.unexpected().into()),
        }
    }
    if a.lights.is_empty() {
        a.lights.push(Named::new("D65", lights::D65.clone()));
    }
    Ok(a)
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("film: {e}\n{USAGE}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let a = parse()?;
    let setup = Setup::new(&a.lights)?;
    let buckets = match a.buckets {
        None => whole_nm(WavelengthRange::ASSIGNMENT)?,
        Some(m) => Buckets::new(WavelengthRange::ASSIGNMENT, m)?,
    };
    let sensor = Sensor::observer(StandardObserver::Assignment);
    let render = film::spectral(&setup, &a.options, a.kind, buckets, &sensor)?;
    let image = render.film.image();
    let develop = Develop::new(sensor).quadrature(Quadrature::Point);
    let develop = match a.kind {
        Kind::Emissive => develop,
        Kind::Reflective => develop.light(&setup.lights[0].spectrum),
    };
    let xyz = develop.xyz(&image)?;
    let preview: Vec<[f32; 3]> =
        xyz.iter().map(|p| p.to_linear_srgb().to_array().map(|v| v as f32)).collect();
    let options = WriteOptions { precision: a.precision, preview: Some(preview), ..WriteOptions::default() };
    speclab_exr::write(&a.out, &image, &options)?;
    let read = speclab_exr::read(&a.out)?;
    let (o, m) = (&a.options, buckets.count());
    println!(
        "{} × {}, {} paths per pixel, light {}, {m} buckets of {} nm: {:.2} s; wrote {}",
        o.width,
        o.height,
        o.spp,
        setup.light_names(),
        buckets.width(),
        render.seconds,
        a.out.display()
    );
    let same =
        read.image.values().iter().zip(image.values()).filter(|(r, w)| r.to_bits() == w.to_bits()).count();
    println!("read back: {same} of {} values bit for bit", image.values().len());
    let from_file = develop.xyz(&read.image)?;
    println!(
        "XYZ from the file against the tracer's own: largest relative difference {:.2e} (in Y of the brightest pixel)",
        largest(&from_file, &render.xyz)
    );
    Ok(())
}

/// The largest `|a − b|` over the pixels and channels, relative to the
/// largest `Y` of `b`.
fn largest(a: &[Xyz], b: &[Xyz]) -> f64 {
    let top = b.iter().map(|p| p.y).fold(0.0, f64::max);
    let diff = a.iter().zip(b).flat_map(|(p, q)| (*p - *q).to_array()).map(f64::abs).fold(0.0, f64::max);
    diff / top
}
