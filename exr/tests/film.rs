//! The tracer's film through a file: written, read back bit for bit, and
//! developed to the tracer's own XYZ of the same paths to rounding; and
//! the cameras' sensor → XYZ fits over the measured Munsell chips, their
//! residuals reported.

use std::io::Cursor;

use speclab::data::lights;
use speclab::film::{Develop, Kind, Quadrature, Sensor};
use speclab::spectrum::{StandardObserver, TabulatedSpectrum, WavelengthRange};
use speclab_exr::{Precision, WriteOptions};
use speclab_study::evaluate::Named;
use speclab_study::published::measured;
use speclab_study::render::film::{spectral, whole_nm};
use speclab_study::render::{Options, Setup};

#[test]
fn a_traced_film_reads_back_and_develops_to_the_tracers_xyz() {
    let setup = Setup::new(&[Named::new("F11", lights::F11.clone())]).unwrap();
    let o = Options { width: 12, height: 10, spp: 4, threads: 1, ..Options::default() };
    let sensor = Sensor::observer(StandardObserver::Assignment);
    let buckets = whole_nm(WavelengthRange::ASSIGNMENT).unwrap();
    let render = spectral(&setup, &o, Kind::Emissive, buckets, &sensor).unwrap();
    let image = render.film.image();
    let mut file = Cursor::new(Vec::new());
    speclab_exr::write_to(&mut file, &image, &WriteOptions::default()).unwrap();
    let bytes = file.into_inner();
    let read = speclab_exr::read_from(Cursor::new(bytes.clone())).unwrap().image;
    assert_eq!(read, image, "bit for bit");
    let develop = Develop::new(sensor).quadrature(Quadrature::Point);
    let xyz = develop.xyz(&read).unwrap();
    let top = render.xyz.iter().map(|p| p.y).fold(0.0, f64::max);
    for (from_file, tracer) in xyz.iter().zip(&render.xyz) {
        let off = (*from_file - *tracer).to_array().map(f64::abs).into_iter().fold(0.0, f64::max);
        // f32 means of f64 sums: rounding, relative to the image's brightest.
        assert!(off <= 1e-6 * top, "{from_file:?} against {tracer:?}");
    }
    // In f16, each value within 2⁻¹¹ (and denormals within 2⁻²⁴).
    let mut half = Cursor::new(Vec::new());
    let options = WriteOptions { precision: Precision::F16, ..WriteOptions::default() };
    speclab_exr::write_to(&mut half, &image, &options).unwrap();
    let read = speclab_exr::read_from(Cursor::new(half.into_inner())).unwrap().image;
    for (r, w) in read.values().iter().zip(image.values()) {
        assert!((r - w).abs() <= w.abs() * 2f32.powi(-11) + 2f32.powi(-25), "{r} for {w}");
    }
}

#[test]
fn a_reflective_film_needs_one_light() {
    let two = [Named::new("A", lights::A.clone()), Named::new("D65", lights::D65.clone())];
    let setup = Setup::new(&two).unwrap();
    let o = Options { width: 2, height: 2, spp: 1, ..Options::default() };
    let sensor = Sensor::observer(StandardObserver::Assignment);
    let buckets = whole_nm(WavelengthRange::ASSIGNMENT).unwrap();
    let e = spectral(&setup, &o, Kind::Reflective, buckets, &sensor).unwrap_err().to_string();
    assert!(e.contains("lights for a reflective film") && e.contains('2'), "{e}");
}

/// Every camera's matrix fitted over the 1269 measured Munsell chips
/// under D65 (regression snapshots: printed with `--nocapture`).
#[test]
fn cameras_fit_over_the_munsell_chips() {
    let chips: Vec<TabulatedSpectrum> =
        measured::munsell().unwrap().into_iter().map(|c| c.spectrum).collect();
    let d65 = lights::named("CIE-D65").unwrap();
    let cie =
        Sensor::observer(StandardObserver::Cie1931).fit_xyz(&chips, &*d65, &*d65, StandardObserver::Cie1931);
    assert!(cie.unwrap().rms < 1e-12);
    println!("| camera | chips | residual RMS | residual max |\n|---|---:|---:|---:|");
    for name in Sensor::camera_names() {
        let fit =
            Sensor::camera(name).unwrap().fit_xyz(&chips, &*d65, &*d65, StandardObserver::Cie1931).unwrap();
        println!("| {name} | {} | {:.4} | {:.4} |", fit.count, fit.rms, fit.max);
        assert!(fit.count == 1269 && fit.rms > 1e-4 && fit.rms < 0.03 && fit.max < 0.2, "{name}: {fit:?}");
    }
}

/// A reflective film (the throughput without the light) developed under
/// the scene's light against the tracer's XYZ of the same paths under it.
/// Per sample, the relit value weighs the light's mean over the sample's
/// 1 nm bucket where the tracer weighs the light at the sample: the same
/// expectation, other noise (most under F11, whose lines rise by up to 18 %
/// of their peak per nanometre in its 5 nm table): the mean
/// per-pixel difference in Y is within 4 standard errors of zero (the
/// largest per-pixel difference printed with `--nocapture`). Under a
/// constant light, weighed at the buckets' wavelengths, they are the same
/// sums: equal to rounding.
#[test]
fn a_reflective_film_relights_to_the_tracers_xyz() {
    for light in ["E", "D65", "A", "F11"] {
        let setup = Setup::new(&[Named::new(light, lights::named(light).unwrap().into_owned())]).unwrap();
        let o = Options { width: 24, height: 20, spp: 4, threads: 1, ..Options::default() };
        let sensor = Sensor::observer(StandardObserver::Assignment);
        let buckets = whole_nm(WavelengthRange::ASSIGNMENT).unwrap();
        let render = spectral(&setup, &o, Kind::Reflective, buckets, &sensor).unwrap();
        let quadrature = if light == "E" { Quadrature::Point } else { Quadrature::Cell };
        let develop = Develop::new(sensor).light(&setup.lights[0].spectrum).quadrature(quadrature);
        let xyz = develop.xyz(&render.film.image()).unwrap();
        let top = render.xyz.iter().map(|p| p.y).fold(0.0, f64::max);
        let d: Vec<f64> = xyz.iter().zip(&render.xyz).map(|(a, b)| a.y - b.y).collect();
        let largest = xyz
            .iter()
            .zip(&render.xyz)
            .flat_map(|(a, b)| (*a - *b).to_array())
            .map(f64::abs)
            .fold(0.0, f64::max);
        let n = d.len() as f64;
        let mean = d.iter().sum::<f64>() / n;
        let se = (d.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt();
        println!(
            "{light}: relit against traced, largest difference {:.2e} of the brightest Y, mean difference in Y {:.2} SE",
            largest / top,
            mean / se
        );
        if light == "E" {
            assert!(largest <= 1e-6 * top, "{light}: {largest} of {top}");
        } else {
            assert!((mean / se).abs() < 4.0, "{light}: {mean} ({se})");
        }
    }
}
