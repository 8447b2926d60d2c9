//! Spectral OpenEXR read and written: round trips bit for bit (f32) and
//! within f16's rounding; files made by another writer (OpenImageIO, see
//! `data/make.py`), pbrt-v4's channel names among them, read as laid out;
//! each broken file refused with an error naming its fault; no panic on
//! damaged bytes.

#[path = "support/fuzz_body.rs"]
mod fuzz_body;

use std::io::Cursor;
use std::path::Path;

use speclab::film::{Kind, SpectralImage};
use speclab_exr::{Departure, ExrError, Precision, ReadOptions, WriteOptions};

fn data(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
}

/// A 5 × 3 image of values spread over f32's range, negatives and zeros
/// included (a fixed sequence).
fn image(kind: Kind) -> SpectralImage {
    let lambda = vec![380.0, 374.688 + 10.0, 512.25, 729.5];
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let values = (0..5 * 3 * lambda.len())
        .map(|i| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let v = f32::from_bits((state >> 33) as u32 & 0x7F7F_FFFF);
            match i % 7 {
                0 => 0.0,
                1 => -v,
                _ => v,
            }
        })
        .collect();
    SpectralImage::new((5, 3), kind, lambda, values).unwrap()
}

fn round_trip(image: &SpectralImage, options: &WriteOptions) -> SpectralImage {
    let mut out = Cursor::new(Vec::new());
    speclab_exr::write_to(&mut out, image, options).unwrap();
    speclab_exr::read_from(Cursor::new(out.into_inner())).unwrap().image
}

#[test]
fn f32_reads_back_bit_for_bit() {
    for kind in [Kind::Emissive, Kind::Reflective] {
        let written = image(kind);
        let preview = Some(vec![[0.5, 0.25, 1.0]; 15]);
        let read = round_trip(&written, &WriteOptions { preview, ..WriteOptions::default() });
        assert_eq!((read.kind(), read.size(), read.wavelengths()), (kind, (5, 3), written.wavelengths()));
        let bits = |i: &SpectralImage| i.values().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&read), bits(&written));
    }
}

#[test]
fn files_on_disk_read_back() {
    let path = std::env::temp_dir().join(format!("speclab-exr-{}.exr", std::process::id()));
    let written = image(Kind::Reflective);
    speclab_exr::write(&path, &written, &WriteOptions::default()).unwrap();
    let read = speclab_exr::read(&path);
    std::fs::remove_file(&path).unwrap();
    assert_eq!(read.unwrap().image.values().len(), written.values().len());
}

#[test]
fn f16_keeps_eleven_bits_in_its_normal_range() {
    let written = SpectralImage::new(
        (2, 2),
        Kind::Emissive,
        vec![400.0, 500.0],
        vec![1.0, 3.0e-4, 65000.0, 0.1, 1.0 / 3.0, 7.77, 1234.5, 6.2e-5],
    )
    .unwrap();
    let read = round_trip(&written, &WriteOptions { precision: Precision::F16, ..WriteOptions::default() });
    for (r, w) in read.values().iter().zip(written.values()) {
        assert!((r - w).abs() <= w.abs() * 2f32.powi(-11), "{r} for {w}");
    }
    let exact = read.values().iter().zip(written.values()).filter(|(r, w)| r == w).count();
    assert!(exact < 8, "f16 rounds some of these");
}

#[test]
fn pbrt_names_read_in_order_of_wavelength() {
    let file = speclab_exr::read(data("pbrt_emissive.exr")).unwrap();
    let image = &file.image;
    assert_eq!(image.wavelengths(), [374.688, 400.0, 425.312, 1000.0]);
    assert_eq!((image.kind(), image.size()), (Kind::Emissive, (4, 3)));
    assert_eq!(file.emissive_units.as_deref(), Some("W.m^-2.sr^-1"));
    // Written as pixel + channel/8, the S0 channels after R, G, B.
    for (x, y) in [(0, 0), (3, 0), (1, 2)] {
        let p = (y * 4 + x) as f32;
        assert_eq!(image.pixel(x, y).unwrap(), [p + 0.375, p + 0.5, p + 0.625, p + 0.75]);
    }
}

#[test]
fn reflective_units_and_polarised_files() {
    let file = speclab_exr::read(data("reflective_units.exr")).unwrap();
    let lambda = file.image.wavelengths();
    assert_eq!(file.image.kind(), Kind::Reflective);
    assert!(lambda.iter().zip([450.0, 550.0, 650.0]).all(|(l, e)| (l - e).abs() < 1e-9), "{lambda:?}");
    assert_eq!(file.emissive_units, None);
    assert_eq!(file.image.pixel(1, 0).unwrap(), [1.0, 1.125, 1.25]);

    let file = speclab_exr::read(data("polarised.exr")).unwrap();
    assert_eq!(file.image.wavelengths(), [450.0, 550.0, 650.0]);
    assert_eq!(speclab_exr::read(data("polarised_left.exr")).unwrap().image, file.image);
    assert_eq!(file.image.pixel(2, 1).unwrap(), [6.0, 6.125, 6.25], "S0 alone");
}

/// colour-science's writer with its default specification (emissive and
/// reflective, f32 and f16; `make_colour.py`): no `spectralLayoutVersion`
/// and, emissive, no `emissiveUnits`. Read, every value bit for bit (the
/// values are exact in f16), and each missing attribute reported; a
/// strict read refuses them.
#[test]
fn colour_sciences_default_files_read_with_what_they_lack() {
    let wavelengths = [400.0, 450.0, 500.5, 550.0, 600.0, 650.0, 700.0, 750.0];
    for (name, kind, departures) in [
        (
            "colour_emissive_32.exr",
            Kind::Emissive,
            &[Departure::NoLayoutVersion, Departure::NoEmissiveUnits][..],
        ),
        (
            "colour_emissive_16.exr",
            Kind::Emissive,
            &[Departure::NoLayoutVersion, Departure::NoEmissiveUnits][..],
        ),
        ("colour_reflective_32.exr", Kind::Reflective, &[Departure::NoLayoutVersion][..]),
        ("colour_reflective_16.exr", Kind::Reflective, &[Departure::NoLayoutVersion][..]),
    ] {
        let file = speclab_exr::read(data(name)).unwrap();
        assert_eq!(file.departures, departures, "{name}");
        assert_eq!((file.image.kind(), file.image.wavelengths()), (kind, &wavelengths[..]), "{name}");
        assert_eq!(file.emissive_units, None, "{name}");
        for p in 0..12 {
            let expected: Vec<f32> = (0..8).map(|i| p as f32 + 0.125 * i as f32).collect();
            let got = file.image.pixel(p % 4, p / 4).unwrap();
            assert_eq!(
                got.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                expected.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                "{name}, pixel {p}"
            );
        }
        let strict = std::fs::File::open(data(name)).unwrap();
        let e = speclab_exr::read_with(strict, &ReadOptions::strict()).unwrap_err().to_string();
        assert!(e.contains("missing attribute `spectralLayoutVersion`"), "{name}: {e}");
    }
    // Each attribute alone (OpenImageIO's files): reported leniently,
    // refused strictly.
    for (name, departure, says) in [
        ("no_version.exr", Departure::NoLayoutVersion, "spectralLayoutVersion"),
        ("no_units.exr", Departure::NoEmissiveUnits, "emissiveUnits"),
    ] {
        assert_eq!(speclab_exr::read(data(name)).unwrap().departures, [departure], "{name}");
        let strict = speclab_exr::read_with(std::fs::File::open(data(name)).unwrap(), &ReadOptions::strict());
        let e = strict.unwrap_err().to_string();
        assert!(e.contains(says) && e.contains("missing"), "{name}: {e}");
        assert!(departure.to_string().contains(says));
    }
    assert!(speclab_exr::read(data("pbrt_emissive.exr")).unwrap().departures.is_empty());
}

#[test]
fn broken_files_say_what_is_wrong() {
    for (name, says) in [
        ("bad_name.exr", ["S0.550.5nm", "comma"]),
        ("disagree.exr", ["S1", "560"]),
        ("rgb_only.exr", ["no spectral channel", "B, G, R"]),
        ("stokes_only.exr", ["S1 has 2", "S0 has 0"]),
        ("duplicate.exr", ["S0.450nm", "S0.4,5e2nm"]),
        ("bad_handedness.exr", ["polarisationHandedness", "left or right, found \"up\""]),
        ("version_2.exr", ["spectralLayoutVersion", "2.0"]),
    ] {
        let e = speclab_exr::read(data(name)).unwrap_err().to_string();
        assert!(says.iter().all(|s| e.contains(s)), "{name}: {e}");
    }
    let e = speclab_exr::read_from(Cursor::new(b"not an OpenEXR file".to_vec())).unwrap_err();
    assert!(matches!(e, ExrError::Exr(_)), "{e}");
    let e = speclab_exr::read(data("absent.exr")).unwrap_err();
    assert!(e.to_string().contains("No such file"), "{e}");
}

/// A file declaring more values than the reader takes is refused from
/// its headers (the fuzzer's first find: 468 bytes declaring 20 GB).
#[test]
fn files_declaring_too_much_are_refused_before_decoding() {
    let small = std::fs::read(data("pbrt_emissive.exr")).unwrap();
    let e = speclab_exr::read_limited(Cursor::new(small.clone()), 83).unwrap_err().to_string();
    assert!(e.contains("84 values") && e.contains("at most 83"), "{e}");
    assert!(speclab_exr::read_limited(Cursor::new(small), 84).is_ok());
    let huge = std::fs::read(data("regressions/oom-declares-20-gb.exr")).unwrap();
    let e = speclab_exr::read_from(Cursor::new(huge)).unwrap_err();
    assert!(matches!(e, ExrError::TooLarge { values: Some(v), .. } if v > 1 << 30), "{e}");
}

#[test]
fn writing_refuses_what_it_cannot_write() {
    let image = image(Kind::Emissive);
    let mut out = Cursor::new(Vec::new());
    let preview = Some(vec![[0.0; 3]; 14]);
    let e = speclab_exr::write_to(&mut out, &image, &WriteOptions { preview, ..WriteOptions::default() });
    assert!(e.unwrap_err().to_string().contains("14 pixels for an image of 15"));
    let units = WriteOptions { emissive_units: "W·m⁻²".into(), ..WriteOptions::default() };
    let e = speclab_exr::write_to(&mut out, &image, &units).unwrap_err().to_string();
    assert!(e.contains("emissiveUnits") && e.contains("Latin-1"), "{e}");
}

/// The fuzz target's body on every hand-made file, every input the
/// fuzzer once failed on (`data/regressions/`), every prefix of one file,
/// and copies with single bytes changed: never a panic.
#[test]
fn damaged_files_never_panic() {
    let mut replayed = 0;
    for dir in ["", "regressions"] {
        for entry in std::fs::read_dir(data(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "exr") {
                fuzz_body::spectral_exr(&std::fs::read(&path).unwrap());
                replayed += 1;
            }
        }
    }
    assert!(replayed >= 13, "{replayed}");
    let whole = std::fs::read(data("pbrt_emissive.exr")).unwrap();
    for end in (0..whole.len()).step_by(7) {
        fuzz_body::spectral_exr(&whole[..end]);
    }
    for i in (0..whole.len()).step_by(3) {
        for flip in [0x01, 0x80, 0xFF] {
            let mut damaged = whole.clone();
            damaged[i] ^= flip;
            fuzz_body::spectral_exr(&damaged);
        }
    }
}
