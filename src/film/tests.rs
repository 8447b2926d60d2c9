//! The film's tests: sensors (the data, the fit, the pdf's
//! unbiasedness), white balance, the film's buckets and splats, and
//! developing.

use super::*;
use crate::HeroSample;
use crate::color::adaptation::Cat;
use crate::data::{lights, patches};
use crate::sampling::pdf::WavelengthPdf;
use crate::spectrum::data::sensors;
use crate::spectrum::{Constant, FnSpectrum, Spectrum, StandardObserver, WavelengthRange};
use crate::{Error, Xyz};

/// SplitMix64's uniform numbers in [0, 1).
struct Uniforms(u64);

impl Uniforms {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn cameras_are_pbrt_v4s_data_linear_between_and_zero_outside() {
    assert_eq!(Sensor::camera_names().len(), 17);
    let &(name, first, step, rows) = sensors::ALL.iter().find(|c| c.0 == "canon_eos_100d").unwrap();
    assert_eq!((name, first, step, rows.len()), ("canon_eos_100d", 380.0, 10.0, 35));
    // pbrt-v4's canon_eos_100d_r at 380 and 720 nm, as printed there.
    assert_eq!(rows[0][0], 0.001_034_534_099_999_994_5);
    assert_eq!(rows[34][0], 0.001_427_127_799_999_993_2);
    let camera = Sensor::camera(name).unwrap();
    assert_eq!(camera.curves(380.0), rows[0]);
    let mid = camera.curves(385.0);
    assert!((0..3).all(|c| (mid[c] - 0.5 * (rows[0][c] + rows[1][c])).abs() < 1e-15));
    assert_eq!(camera.curves(379.0), [0.0; 3]);
    assert_eq!(camera.curves(721.0), [0.0; 3]);
    assert_eq!(camera.support().map(|r| (r.min(), r.max())), Some((380.0, 720.0)));
    let e = Sensor::camera("leica_m3").unwrap_err().to_string();
    assert!(e.contains("leica_m3") && e.contains("nikon_d850"), "{e}");
}

#[test]
fn observers_as_sensors_and_sensors_from_spectra() {
    let cie = Sensor::observer(StandardObserver::Cie1931);
    assert_eq!(cie.curves(555.0), StandardObserver::Cie1931.xyz_bar(555.0));
    assert_eq!(cie.name(), StandardObserver::Cie1931.name());
    let white = cie.responses(&Constant::new(1.0));
    let integrals = StandardObserver::Cie1931.integrals(WavelengthRange::VISIBLE).unwrap();
    assert!((0..3).all(|c| (white[c] - integrals[c]).abs() < 1e-6 * integrals[c]), "{white:?} {integrals:?}");
    let flat = Constant::new(0.5);
    let own = Sensor::new("flat", [&flat, &flat, &flat]).unwrap();
    assert_eq!(own.curves(600.5), [0.5; 3]);
    // Its ∫ȳ as a sample's normalisation reads it: 0.5 over 470 nm.
    assert!((crate::spectrum::Observer::y_integral(&own, WavelengthRange::VISIBLE) - 235.0).abs() < 1e-9);
    assert!(own != cie && own.clone() == own);
    let negative = FnSpectrum(|l: f64| if l > 700.0 { -1.0 } else { 1.0 });
    let e = Sensor::new("bad", [&flat, &negative, &flat]).unwrap_err();
    assert!(matches!(e, Error::Response { channel: 1, lambda, .. } if lambda == 701.0), "{e}");
    let black =
        Sensor::new("black", [&Constant::new(0.0), &Constant::new(0.0), &Constant::new(0.0)]).unwrap();
    assert_eq!(black.support(), None);
    assert!(matches!(black.pdf(None), Err(Error::NoMass)));
}

/// The measured Munsell chips are not in the core; a training set with a
/// clear licence that is not held apart: the assignment's six patches
/// are evaluation data, so these tests train on smooth synthetic
/// reflectances (sigmoids of quadratics).
fn synthetic(count: usize) -> Vec<FnSpectrum<impl Fn(f64) -> f64>> {
    (0..count)
        .map(|i| {
            let (c, w) = (400.0 + 300.0 * (i as f64 * 0.618_034).fract(), 30.0 + 10.0 * (i % 7) as f64);
            let up = if i % 2 == 0 { 1.0 } else { -1.0 };
            FnSpectrum(move |l: f64| 1.0 / (1.0 + (-up * ((l - c) / w) - 0.3 * ((l - c) / w).powi(2)).exp()))
        })
        .collect()
}

#[test]
fn a_cie_sensor_fits_itself_and_a_camera_reports_its_residual() {
    let training = synthetic(60);
    let d65 = &lights::D65;
    let cie = Sensor::observer(StandardObserver::Cie1931);
    let fit = cie.fit_xyz(&training, d65, d65, StandardObserver::Cie1931).unwrap();
    assert!(fit.rms < 1e-12 && fit.max < 1e-12, "{fit:?}");
    assert!((fit.matrix[1][1] - 1.0).abs() < 1e-9 && fit.matrix[0][1].abs() < 1e-9, "{:?}", fit.matrix);
    let camera = Sensor::camera("nikon_d850").unwrap();
    let fit = camera.fit_xyz(&training, d65, d65, StandardObserver::Cie1931).unwrap();
    // A regression snapshot of this fit: a camera is no colorimeter.
    assert!(fit.rms > 1e-4 && fit.rms < 0.05 && fit.max >= fit.rms && fit.count == 60, "{fit:?}");
    let white = fit.xyz(camera.responses(d65).map(|v| v / camera.responses(d65)[1]));
    assert!((white.y - 1.0).abs() < 0.05, "{white:?}");
    let e = camera.fit_xyz(&training[..2], d65, d65, StandardObserver::Cie1931).unwrap_err();
    assert!(e.to_string().contains("at least 3"), "{e}");
    let dark = Constant::new(0.0);
    assert!(matches!(
        camera.fit_xyz(&training, &dark, d65, StandardObserver::Cie1931),
        Err(Error::Dark { .. })
    ));
    let same = vec![Constant::new(0.5); 4];
    assert!(matches!(camera.fit_xyz(&same, d65, d65, StandardObserver::Cie1931), Err(Error::NoMass)));
}

/// `∫ v(λ)·curve(round λ) dλ` over `[a, b]`: what a hero sample weighted
/// by the sensor estimates (its rows are read at the nearest nanometre).
fn expected(sensor: &Sensor, v: &dyn Spectrum, [a, b]: [f64; 2]) -> [f64; 3] {
    let (steps, mut sum) = (((b - a) * 200.0) as usize, [0.0; 3]);
    let h = (b - a) / steps as f64;
    for i in 0..steps {
        let l = a + (i as f64 + 0.5) * h;
        let c = sensor.curves(l.round());
        (0..3).for_each(|k| sum[k] += h * v.eval(l) * c[k]);
    }
    sum
}

#[test]
fn wavelengths_drawn_by_a_sensor_estimate_its_responses_without_bias() {
    let (light, surface) = (&lights::F11, &patches::G4);
    let v = FnSpectrum(|l: f64| light.eval(l) * surface.eval(l));
    for sensor in [Sensor::camera("nikon_d850").unwrap(), Sensor::observer(StandardObserver::Cie1931)] {
        let support = sensor.support().unwrap();
        let truth = expected(&sensor, &v, [support.min(), support.max()]);
        let alone = sensor.pdf(None).unwrap();
        let lit = sensor.pdf(Some(light)).unwrap();
        let pdfs: [(&str, &dyn WavelengthPdf); 2] = [("sensor", &alone), ("sensor × F11", &lit)];
        for (name, pdf) in pdfs {
            let mut u = Uniforms(45);
            let n = 20_000;
            let (mut sum, mut squares) = ([0.0; 3], [0.0; 3]);
            for _ in 0..n {
                let h = HeroSample::<4>::from_pdf_with(u.next(), pdf, &sensor).unwrap();
                let e = h.to_xyz(h.sample(&v)).to_array();
                (0..3).for_each(|k| {
                    sum[k] += e[k];
                    squares[k] += e[k] * e[k];
                });
            }
            for k in 0..3 {
                let mean = sum[k] / n as f64;
                let se = ((squares[k] / n as f64 - mean * mean) / (n - 1) as f64).sqrt();
                let z = (mean - truth[k]) / se;
                assert!(
                    z.abs() < 4.0,
                    "{} {name} channel {k}: {mean} against {} ({z:.2} SE)",
                    sensor.name(),
                    truth[k]
                );
            }
        }
        // The light's pdf has no mass where the sensor sees nothing.
        assert!(alone.pdf(support.min() - 1.0) == 0.0 && alone.pdf(550.0) > 0.0);
    }
}

#[test]
fn white_balance_takes_the_white_to_the_display_white() {
    let d65 = Xyz::new(0.950_47, 1.0, 1.088_83);
    for cat in Cat::ALL {
        for balance in [
            WhiteBalance::daylight(4000.0, d65, cat, StandardObserver::Cie1931).unwrap(),
            WhiteBalance::planckian(2856.0, d65, cat, StandardObserver::Cie1964).unwrap(),
            WhiteBalance::light(&lights::F11, d65, cat, StandardObserver::Assignment).unwrap(),
        ] {
            let white = balance.apply(balance.from());
            let off = (white - d65).to_array().map(f64::abs).into_iter().fold(0.0, f64::max);
            assert!(off < 1e-6, "{cat:?}: {white:?} ({off:e})");
            assert!((balance.from().y - 1.0).abs() < 1e-12 && balance.to() == d65 && balance.cat() == cat);
        }
    }
    let bright =
        WhiteBalance::light(&Constant::new(3.0), d65, Cat::Bradford, StandardObserver::Cie1931).unwrap();
    let e_white = bright.from().xy().unwrap();
    assert!((e_white[0] - 1.0 / 3.0).abs() < 2e-3 && (e_white[1] - 1.0 / 3.0).abs() < 2e-3, "{e_white:?}");
    assert!(WhiteBalance::new(Xyz::ZERO, d65, Cat::Bradford).is_err());
    assert!(WhiteBalance::new(d65, Xyz::new(f64::NAN, 1.0, 1.0), Cat::Bradford).is_err());
    assert!(WhiteBalance::new(d65, Xyz::new(-0.1, 1.0, 1.0), Cat::Bradford).is_err());
    assert!(matches!(
        WhiteBalance::daylight(3000.0, d65, Cat::Bradford, StandardObserver::Cie1931),
        Err(Error::Daylight { .. })
    ));
}
