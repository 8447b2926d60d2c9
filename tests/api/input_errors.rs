//! Every validation error names the place: origin, line and column, what
//! was found and what was expected. One test per case, in every format.

use std::io::Read as _;

use speclab::error::ReadError;
use speclab::io::{Format, Load, MAX_BYTES};
use speclab::spectrum::validate::{Field, Invalid, MAX_VALUE, SampleError};
use speclab::{Error, Interpolation, Role, TabulatedSpectrum};
use speclab_tables::read;

/// Loads `text` as `role` and returns the error message.
fn error(text: &str, role: Role) -> String {
    match Load::new(role).text(text, "in.txt") {
        Ok(s) => panic!("expected an error, got {s:?}"),
        Err(e) => e.to_string(),
    }
}

/// A valid 380–730 nm table in two-column form, with one line replaced.
fn columns_with(line: usize, replacement: &str) -> String {
    let mut rows: Vec<String> = (0..8).map(|i| format!("{},0.5", 380 + 50 * i)).collect();
    rows[line] = replacement.to_string();
    rows.join("\n")
}

#[test]
fn non_finite_values() {
    assert_eq!(
        error("{380, 0.5}, {390, nan}", Role::Light),
        "in.txt:1:19: expected a finite number, found \"nan\""
    );
    assert_eq!(
        error(&columns_with(2, "480,inf"), Role::Light),
        "in.txt:3:5: expected a finite number, found \"inf\""
    );
    assert_eq!(
        error("{\"wavelengths\": [380, 730],\n \"values\": [1, 1e999]}", Role::Light),
        "in.txt:2:16: expected a finite number, found \"1e999\""
    );
}

#[test]
fn wavelengths_not_increasing() {
    assert_eq!(
        error(&columns_with(3, "480,0.5"), Role::Light),
        "in.txt:4:1: expected a wavelength greater than 480 nm, found 480 nm"
    );
    assert_eq!(
        error("{380, 1}, {370, 1}", Role::Light),
        "in.txt:1:11: expected a wavelength greater than 380 nm, found 370 nm"
    );
    assert_eq!(
        error("{\"wavelengths\": [380, 380, 730], \"values\": [1, 1, 1]}", Role::Light),
        "in.txt:1:23: expected a wavelength greater than 380 nm, found 380 nm"
    );
}

#[test]
fn too_few_samples() {
    assert_eq!(error("{380, 0.5}", Role::Light), "in.txt:1:1: expected at least 2 samples, found 1");
    assert_eq!(
        error("380 0.1\n500 0.2\n730 0.3", Role::Reflectance),
        "in.txt:3:1: expected at least 4 samples, found 3"
    );
    // Stated explicitly, linear needs only two.
    let linear = Load::new(Role::Reflectance).with_interpolation(Interpolation::Linear);
    assert!(linear.text("380 0.1\n500 0.2\n730 0.3", "in.txt").is_ok());
}

#[test]
fn negative_light_power() {
    assert_eq!(
        error(&columns_with(1, "430, -0.2"), Role::Light),
        "in.txt:2:6: expected a non-negative light power, found -0.2"
    );
}

#[test]
fn reflectance_outside_unit_interval() {
    assert_eq!(
        error(&columns_with(5, "630\t1.2"), Role::Reflectance),
        "in.txt:6:5: expected a value in [0, 1], found 1.2"
    );
    assert_eq!(
        error(&columns_with(0, "380\t-0.01"), Role::Reflectance),
        "in.txt:1:5: expected a value in [0, 1], found -0.01"
    );
}

#[test]
fn support_must_cover_the_range() {
    assert_eq!(
        error("400,1\n500,1\n730,1", Role::Light),
        "in.txt:1:1: expected samples covering 380-730 nm, found 400-730 nm"
    );
    assert_eq!(
        error("# lamp\n380,1\n500,1\n700,1", Role::Light),
        "in.txt:4:1: expected samples covering 380-730 nm, found 380-700 nm"
    );
    // Built in code, a spectrum is zero outside its samples instead.
    let partial = TabulatedSpectrum::new(vec![400.0, 500.0], vec![1.0, 1.0], Role::Light).expect("valid");
    assert_eq!(partial.eval(390.0), 0.0);
}

/// A light file with no power in 380–730 nm is refused where its first
/// value is written: every colour under it would be black and every ratio
/// to its white undefined. A black surface is a valid reflectance.
#[test]
fn black_lights_are_refused() {
    let none = "expected a light with power within 380-730 nm, found none";
    assert_eq!(error("380,0\n500,0\n730,0", Role::Light), format!("in.txt:1:5: {none}"));
    assert_eq!(error("# lamp\n380 0\n730 0\n760 5\n780 5", Role::Light), format!("in.txt:2:5: {none}"));
    assert!(Load::new(Role::Light).text("380 0\n729 0\n730 1e-9", "dim.txt").is_ok(), "dim is not black");
    assert!(Load::new(Role::Reflectance).text("380 0\n500 0\n600 0\n730 0", "black.txt").is_ok());
}

#[test]
fn micrometres_are_caught_or_converted() {
    assert!(
        error("0.38 1\n0.73 1", Role::Light).starts_with("in.txt:1:1: expected a wavelength in nanometres")
    );
    let lamp =
        Load::new(Role::Light).text("lambda (µm)\tpower\n0.38\t1\n0.73\t3\n", "in.txt").expect("µm header");
    assert_eq!(lamp.support(), (380.0, 730.0));
}

#[test]
fn malformed_rows() {
    assert_eq!(error("380,1\n550,\n730,1", Role::Light), "in.txt:2:5: expected a number, found nothing");
    assert_eq!(
        error("380,1\n550,1,2\n730,1", Role::Light),
        "in.txt:2:1: expected 2 numbers per entry, found 3"
    );
    assert_eq!(error("380,1\n550,abc\n730,1", Role::Light), "in.txt:2:5: expected a number, found \"abc\"");
    assert_eq!(
        error("{380, 1} {390, 1}", Role::Light),
        "in.txt:1:10: expected ',' between tuples, found '{'"
    );
    assert_eq!(
        error("{\"wavelength\": [380], \"values\": [1]}", Role::Light),
        "in.txt:1:2: expected \"wavelengths\" or \"values\", found \"wavelength\""
    );
    assert_eq!(
        error("{\"wavelengths\": [380, 730], \"values\": [1]}", Role::Light),
        "in.txt:1:40: expected 2 entries, found 1"
    );
}

#[test]
fn unreadable_file_names_the_path() {
    let err = Load::new(Role::Light).file("/nonexistent/lamp.csv").unwrap_err();
    assert!(matches!(err, Error::Read(ReadError::Io { .. })));
    assert!(err.to_string().starts_with("/nonexistent/lamp.csv: cannot read:"), "{err}");
}

#[test]
fn formats_are_detected_from_content() {
    assert_eq!(Format::detect("# comment\n  {380, 1}"), Format::Brace);
    assert_eq!(Format::detect("\n{ \"values\": []}"), Format::Json);
    assert_eq!(Format::detect("wavelength,value\n380,1"), Format::Columns);
    assert_eq!(Format::detect("380\t1"), Format::Columns);
    let text = "{\"values\": [1, 2, 3, 4], \"wavelengths\": [380, 500, 600, 730]}";
    let from_json = Load::new(Role::Light).text(text, "lamp.txt").expect("json by content");
    let from_columns =
        Load::new(Role::Light).text("380 1\n500 2\n600 3\n730 4", "lamp.json").expect("columns");
    assert_eq!(from_json, from_columns);
}

#[test]
fn vector_constructor_names_the_index() {
    let err =
        TabulatedSpectrum::new(vec![380.0, 500.0, 730.0], vec![1.0, -2.0, 1.0], Role::Light).unwrap_err();
    assert_eq!(err.to_string(), "values[1]: expected a non-negative light power, found -2");
    let Error::Sample(SampleError { index, field, problem }) = err else { panic!("a sample error: {err:?}") };
    assert_eq!((index, field, problem), (1, Field::Value, Invalid::NegativePower { value: -2.0 }));
    let err = TabulatedSpectrum::new(vec![380.0, f64::NAN], vec![1.0, 1.0], Role::Light).unwrap_err();
    assert_eq!(err.to_string(), "lambda[1]: expected a finite number, found NaN");
    let err = TabulatedSpectrum::new(vec![380.0, 730.0], vec![1.0], Role::Light).unwrap_err();
    assert_eq!(err.to_string(), "values: expected 2 values, one per wavelength, found 1");
    let err = TabulatedSpectrum::new(vec![380.0, 500.0, 730.0], vec![0.1; 3], Role::Reflectance).unwrap_err();
    assert_eq!(err.to_string(), "lambda: expected at least 4 samples, found 3");
}

/// Finite but huge values would overflow the integrals (`{390, 1e308}` once
/// printed inf and NaN in every cell): rejected where they are written.
#[test]
fn values_too_large_for_finite_integrals() {
    assert_eq!(
        error("{380, 1}, {390, 1e308}, {730, 1}", Role::Light),
        "in.txt:1:17: expected a value of magnitude at most 1e100, found 1e308"
    );
    let err = TabulatedSpectrum::new(vec![380.0, 730.0], vec![1.0, 2e100], Role::Light).unwrap_err();
    assert_eq!(err.to_string(), "values[1]: expected a value of magnitude at most 1e100, found 2e100");
    assert!(TabulatedSpectrum::new(vec![380.0, 730.0], vec![1.0, MAX_VALUE], Role::Light).is_ok());
    let light = TabulatedSpectrum::new(vec![380.0, 730.0], vec![1.0, 1e99], Role::Light).expect("valid");
    assert!(matches!(light.scaled(100.0), Err(Error::Sample(_))), "scaling past the limit is refused too");
}

/// `--light-file /dev/zero` once grew to 5 GB: reading stops past the limit.
#[test]
fn endless_stream_is_refused() {
    let endless = std::io::repeat(b'0');
    let err = Load::new(Role::Light).reader(endless, "/dev/zero").unwrap_err();
    assert!(matches!(err, Error::Read(ReadError::TooLarge { limit, .. }) if limit == MAX_BYTES));
    assert_eq!(err.to_string(), "/dev/zero: expected at most 67108864 bytes (64 MiB), found more");
    let small = read::text(std::io::repeat(b' ').take(10), "<stream>", 10).expect("exactly at the limit");
    assert_eq!(small.len(), 10);
    assert!(matches!(
        read::text(std::io::repeat(b' ').take(11), "<stream>", 10),
        Err(speclab::error::ReadError::TooLarge { .. })
    ));
}

#[test]
fn binary_input_is_an_io_error() {
    let err = Load::new(Role::Light).reader(&[0xff, 0xfe, b'1'][..], "lamp.bin").unwrap_err();
    assert!(matches!(err, Error::Read(ReadError::Io { .. })), "{err:?}");
    assert!(err.to_string().starts_with("lamp.bin: cannot read:"), "{err}");
}

/// A format stated with `with_format` is the one parsed: two-column text
/// read as JSON or as the brace notation is an error, read as columns (or
/// detected) it loads.
#[test]
fn a_stated_format_is_the_one_parsed() {
    let text = "380 0.5\n555 0.7\n730 0.6";
    assert!(Load::new(Role::Light).text(text, "in.txt").is_ok());
    assert!(Load::new(Role::Light).with_format(Format::Columns).text(text, "in.txt").is_ok());
    assert!(Load::new(Role::Light).with_format(Format::Json).text(text, "in.txt").is_err());
    assert!(Load::new(Role::Light).with_format(Format::Brace).text(text, "in.txt").is_err());
}

/// Tables of the wrong role as a conductor's η or k, a power past the
/// limit, and an exact scene of any depth: errors or values, never panics.
#[test]
fn caller_counts_and_roles() {
    use speclab::data::{conductors, lights, patches};
    use speclab::sampling::reference::ExactPaths;
    use speclab::spectrum::{Conductor, MAX_POWER, Product, Spectrum};
    let gold = &conductors::AU;
    let err = Conductor::new(&lights::D65, gold.k()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "expected a table of role Index for a conductor's η, found one of role Light"
    );
    assert!(matches!(
        Conductor::new(gold.eta(), gold.eta()),
        Err(Error::Role { expected: Role::Extinction, .. })
    ));
    let own = Conductor::new(gold.eta(), gold.k()).expect("gold's own tables");
    assert_eq!(own.reflectance().eval(600.0), gold.reflectance().eval(600.0));
    assert_eq!(Product::power(&patches::G4, MAX_POWER).map(|p| p.len()).ok(), Some(MAX_POWER));
    let err = Product::power(&patches::G4, MAX_POWER + 1).unwrap_err();
    assert!(matches!(err, Error::Count { found: 65, max: 64, .. }), "{err}");
    let spectra: [&dyn Spectrum; 2] = [&lights::A, &patches::G4];
    for depth in [0, 1, usize::MAX] {
        let scene = ExactPaths::new(&spectra, depth);
        assert!(scene.xyz(0, &[1], &[0.0, 1.0]).is_ok_and(|x| x.y > 0.0), "depth {depth}");
    }
}
