//! The spectral film's tests: buckets, splats (terminated secondaries
//! included), the image's means, and developing it.

use super::*;
use crate::HeroSample;
use crate::data::{lights, patches};
use crate::sampling::pdf::Uniform;
use crate::spectrum::{Constant, SampledSpectrum, StandardObserver, WavelengthRange};
use crate::{Error, Xyz};

fn range(min: f64, max: f64) -> WavelengthRange {
    WavelengthRange::new(min, max).unwrap()
}

#[test]
fn buckets_split_their_range_evenly() {
    let b = Buckets::new(range(380.0, 730.0), 35).unwrap();
    assert_eq!((b.count(), b.width(), b.center(0), b.center(34)), (35, 10.0, 385.0, 725.0));
    assert_eq!(b.range(), range(380.0, 730.0));
    for (lambda, index) in
        [(380.0, Some(0)), (389.999, Some(0)), (390.0, Some(1)), (729.9, Some(34)), (730.0, Some(34))]
    {
        assert_eq!(b.index(lambda), index, "{lambda}");
    }
    for outside in [379.999, 730.001, f64::NAN] {
        assert_eq!(b.index(outside), None, "{outside}");
    }
    assert!(matches!(Buckets::new(range(380.0, 730.0), 0), Err(Error::Count { .. })));
    assert!(
        Buckets::new(range(380.0, 730.0), 4097).is_err() && Buckets::new(range(380.0, 730.0), 4096).is_ok()
    );
}

#[test]
fn a_splat_adds_each_wavelength_over_its_pdf_to_its_bucket() {
    let b = Buckets::new(range(380.0, 730.0), 7).unwrap();
    let mut film = SpectralFilm::new((3, 2), b, Kind::Emissive).unwrap();
    let h = HeroSample::<4>::from_wavelengths_with(
        [385.0, 440.0, 441.0, 729.0],
        [0.5, 0.25, 0.125, 1.0],
        &crate::spectrum::DenseObserver::ASSIGNMENT,
    )
    .unwrap();
    let v = SampledSpectrum::new([1.0, 2.0, 3.0, 4.0]);
    film.splat((2, 1), &h, v).unwrap();
    film.splat((2, 1), &h, v).unwrap();
    assert_eq!((film.samples(2, 1), film.samples(0, 0), film.samples(3, 0)), (2, 0, 0));
    let image = film.image();
    // v / (K·pdf), summed over 2 samples, over 2 samples and 50 nm.
    let per = |v: f64, pdf: f64| v / (4.0 * pdf) / 50.0;
    let pixel = image.pixel(2, 1).unwrap();
    let expect = [per(1.0, 0.5), per(2.0, 0.25) + per(3.0, 0.125), 0.0, 0.0, 0.0, 0.0, per(4.0, 1.0)];
    assert!(pixel.iter().zip(expect).all(|(p, e)| (f64::from(*p) - e).abs() < 1e-7), "{pixel:?}");
    assert_eq!(image.pixel(0, 0).unwrap(), [0.0; 7]);
    assert_eq!(image.wavelengths(), [405.0, 455.0, 505.0, 555.0, 605.0, 655.0, 705.0]);
    let e = film.splat((3, 0), &h, v).unwrap_err().to_string();
    assert!(e.contains("(3, 0)") && e.contains("3 × 2"), "{e}");
    assert_eq!((film.size(), film.buckets(), image.size()), ((3, 2), b, (3, 2)));
}

#[test]
fn terminated_secondaries_are_not_splatted() {
    let b = Buckets::new(range(380.0, 730.0), 350).unwrap();
    let mut film = SpectralFilm::new((1, 1), b, Kind::Emissive).unwrap();
    let mut h = HeroSample::<4>::from_pdf_with(
        0.3,
        &Uniform::ASSIGNMENT,
        &crate::spectrum::DenseObserver::ASSIGNMENT,
    )
    .unwrap();
    h.terminate_secondary();
    film.splat((0, 0), &h, SampledSpectrum::splat(1.0)).unwrap();
    let pixel = film.image().pixel(0, 0).unwrap().to_vec();
    let hit: Vec<usize> = (0..350).filter(|&i| pixel[i] != 0.0).collect();
    assert_eq!(hit, [b.index(h.lambda()[0]).unwrap()], "only the hero's bucket");
    // The hero alone carries 1/pdf = 350 nm, over one 1 nm bucket.
    assert!((f64::from(pixel[hit[0]]) - 350.0).abs() < 1e-3, "{}", pixel[hit[0]]);
}

#[test]
fn rows_splat_as_the_film_does() {
    let b = Buckets::new(range(380.0, 730.0), 5).unwrap();
    let (mut whole, mut by_rows) = (
        SpectralFilm::new((2, 3), b, Kind::Reflective).unwrap(),
        SpectralFilm::new((2, 3), b, Kind::Reflective).unwrap(),
    );
    let h = HeroSample::<4>::from_pdf_with(
        0.7,
        &Uniform::ASSIGNMENT,
        &crate::spectrum::DenseObserver::ASSIGNMENT,
    )
    .unwrap();
    let v = patches::E2.sample(&h);
    whole.splat((1, 2), &h, v).unwrap();
    let mut rows: Vec<FilmRow<'_>> = by_rows.rows_mut().collect();
    assert_eq!(rows.len(), 3);
    rows[2].splat(1, &h, v).unwrap();
    assert!(rows[2].splat(2, &h, v).unwrap_err().to_string().contains("within 2"));
    drop(rows);
    assert_eq!(whole, by_rows);
}

#[test]
fn the_film_estimates_each_bucket_without_bias() {
    // A constant 1 over 380–730 nm: every bucket's mean is 1 per nm.
    let b = Buckets::new(range(380.0, 730.0), 10).unwrap();
    let mut film = SpectralFilm::new((1, 1), b, Kind::Emissive).unwrap();
    let n = 4000;
    for i in 0..n {
        let h = HeroSample::<4>::from_pdf_with(
            (i as f64 + 0.5) / n as f64,
            &Uniform::ASSIGNMENT,
            &crate::spectrum::DenseObserver::ASSIGNMENT,
        )
        .unwrap();
        film.splat((0, 0), &h, SampledSpectrum::splat(1.0)).unwrap();
    }
    let pixel = film.image().pixel(0, 0).unwrap().to_vec();
    assert!(pixel.iter().all(|v| (v - 1.0).abs() < 1e-3), "{pixel:?}");
}

/// A film of 1 nm buckets at whole nanometres, weighed by a sensor,
/// develops (by points) to the hero estimate of the same samples.
#[test]
fn a_whole_nm_film_develops_to_the_hero_estimate() {
    let b = Buckets::new(range(379.5, 730.5), 351).unwrap();
    let sensor = Sensor::observer(StandardObserver::Assignment);
    let mut film = SpectralFilm::new((1, 1), b, Kind::Emissive).unwrap();
    let mut hero = Xyz::ZERO;
    let n = 500;
    for i in 0..n {
        let h =
            HeroSample::<4, f32>::from_pdf_with((i as f32 + 0.5) / n as f32, &Uniform::ASSIGNMENT, &sensor)
                .unwrap();
        let v = h.sample(&lights::F11) * h.sample(&patches::G4);
        hero += h.to_xyz(v);
        film.splat((0, 0), &h, v).unwrap();
    }
    hero /= n as f64;
    let develop = Develop::new(sensor.clone()).quadrature(Quadrature::Point);
    let xyz = develop.xyz(&film.image()).unwrap()[0];
    let off = (xyz - hero).to_array().map(f64::abs).into_iter().fold(0.0, f64::max);
    assert!(off < 1e-6 * hero.y, "{xyz:?} against {hero:?}");
    // By cells, the same to the observer's change across a nanometre.
    let cells = Develop::new(sensor).xyz(&film.image()).unwrap()[0];
    assert!((cells.y - hero.y).abs() < 2e-3 * hero.y, "{cells:?} against {hero:?}");
}

#[test]
fn develop_checks_kind_and_light_and_scales_by_exposure_and_balance() {
    let image = SpectralImage::new((1, 1), Kind::Reflective, vec![500.0, 600.0], vec![0.5, 0.25]).unwrap();
    let sensor = Sensor::observer(StandardObserver::Cie1931);
    let e = Develop::new(sensor.clone()).xyz(&image).unwrap_err().to_string();
    assert!(e.contains("reflective") && e.contains("light"), "{e}");
    let emissive = SpectralImage::new((1, 1), Kind::Emissive, vec![500.0, 600.0], vec![0.5, 0.25]).unwrap();
    let flat = Constant::new(2.0);
    assert!(
        Develop::new(sensor.clone())
            .light(&flat)
            .xyz(&emissive)
            .unwrap_err()
            .to_string()
            .contains("emissive")
    );
    let plain = Develop::new(sensor.clone()).light(&flat).xyz(&image).unwrap()[0];
    // Cells 450–550 and 550–650 nm: 0.5·2·∫ȳ over the first and 0.25·2·∫ȳ over the second.
    let y = |a: f64, b: f64| StandardObserver::Cie1931.integrals(range(a, b)).unwrap()[1];
    let truth = 0.5 * 2.0 * y(450.0, 550.0) + 0.25 * 2.0 * y(550.0, 650.0);
    assert!((plain.y - truth).abs() < 1e-3 * truth, "{} against {truth}", plain.y);
    // By points: each channel's curve and light at its wavelength, times its cell's 100 nm.
    let points =
        Develop::new(sensor.clone()).light(&flat).quadrature(Quadrature::Point).xyz(&image).unwrap()[0];
    let bar = |l: f64| StandardObserver::Cie1931.xyz_bar(l)[1];
    let by_points = 0.5 * 2.0 * bar(500.0) * 100.0 + 0.25 * 2.0 * bar(600.0) * 100.0;
    assert!((points.y - by_points).abs() < 1e-12 * by_points, "{} against {by_points}", points.y);
    let exposed =
        Develop::new(sensor.clone()).light(&flat).exposure(0.5, 400.0).unwrap().xyz(&image).unwrap()[0];
    assert!((exposed.y - 2.0 * plain.y).abs() < 1e-12 * plain.y);
    assert!(Develop::new(sensor.clone()).exposure(0.0, 100.0).is_err());
    assert!(Develop::new(sensor.clone()).exposure(1.0, f64::INFINITY).is_err());
    let to = Xyz::new(0.95, 1.0, 1.09);
    let balance =
        WhiteBalance::new(Xyz::new(1.1, 1.0, 0.35), to, crate::color::adaptation::Cat::Bradford).unwrap();
    let balanced = Develop::new(sensor.clone()).light(&flat).balance(balance).xyz(&image).unwrap()[0];
    let direct = balance.apply(plain);
    assert!((balanced - direct).to_array().iter().all(|d| d.abs() < 1e-12 * plain.y));
    let swapped =
        Develop::new(sensor).light(&flat).sensor_to_xyz([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    let s = swapped.xyz(&image).unwrap()[0];
    assert_eq!((s.x, s.y), (plain.y, plain.x));
    assert!(format!("{swapped:?}").contains("light: true"));
}

#[test]
fn spectral_images_check_their_shape() {
    let ok = SpectralImage::new((2, 1), Kind::Emissive, vec![400.0, 500.0, 700.0], vec![0.0; 6]).unwrap();
    assert_eq!(
        (ok.size(), ok.kind(), ok.wavelengths().len(), ok.values().len()),
        ((2, 1), Kind::Emissive, 3, 6)
    );
    assert_eq!(ok.cells(), [[350.0, 450.0], [450.0, 600.0], [600.0, 800.0]]);
    assert_eq!((ok.pixel(1, 0).map(<[f32]>::len), ok.pixel(2, 0), ok.pixel(0, 1)), (Some(3), None, None));
    let square = SpectralImage::new((2, 2), Kind::Emissive, vec![500.0], vec![1.0, 2.0, 3.0, 4.0]).unwrap();
    assert_eq!(
        (square.pixel(2, 0), square.pixel(0, 2), square.pixel(0, 1)),
        (None, None, Some(&[3.0f32][..]))
    );
    let one = SpectralImage::new((1, 1), Kind::Reflective, vec![550.0], vec![1.0]).unwrap();
    assert_eq!(one.cells(), [[549.5, 550.5]]);
    for lambda in [vec![], vec![500.0, 500.0], vec![500.0, 400.0], vec![f64::NAN], vec![-1.0]] {
        assert!(matches!(
            SpectralImage::new((1, 1), Kind::Emissive, lambda.clone(), vec![0.0; lambda.len()]),
            Err(Error::Develop(_))
        ));
    }
    let e = SpectralImage::new((2, 2), Kind::Emissive, vec![500.0], vec![0.0; 3]).unwrap_err().to_string();
    assert!(e.contains("3 values") && e.contains("2 × 2"), "{e}");
    assert!(SpectralImage::new((usize::MAX, 2), Kind::Emissive, vec![500.0], vec![]).is_err());
    assert!(
        SpectralFilm::new((1 << 20, 1 << 20), Buckets::new(range(380.0, 730.0), 4).unwrap(), Kind::Emissive)
            .is_err()
    );
}
