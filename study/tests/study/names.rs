//! The study's named choices read and write the names used on command
//! lines, in tables and in CSV, in any case; an unknown name lists them.

use std::fmt::Display;
use std::str::FromStr;

use speclab::Error;
use speclab_study::display::GamutMap;
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::viewing::Normalization;
use speclab_study::render::Way;
use speclab_study::sampling::choice::PdfKind;
use speclab_study::sampling::strata::Strata;

/// Every choice's name reads back as the choice, in any case; names are
/// distinct; an unknown name lists them all.
fn round_trip<T>(all: &[T], names: &[&str], what: &str)
where
    T: Copy + PartialEq + std::fmt::Debug + Display + FromStr<Err = Error>,
{
    let shown: Vec<String> = all.iter().map(T::to_string).collect();
    assert_eq!(shown, names, "{what}");
    for (choice, name) in all.iter().zip(names) {
        assert_eq!(name.parse::<T>().unwrap(), *choice);
        assert_eq!(name.to_uppercase().parse::<T>().unwrap(), *choice);
    }
    let err = "nonsense".parse::<T>().unwrap_err().to_string();
    if names.len() <= 12 {
        // Every name listed, in order (the exact wording: `strata_error`).
        let listed = err
            .strip_prefix(&format!("expected {what} ("))
            .and_then(|e| e.strip_suffix("), found \"nonsense\""));
        let listed = listed.unwrap_or_else(|| panic!("{err}"));
        let mut at = 0;
        for name in names {
            at += listed[at..].find(name).unwrap_or_else(|| panic!("{name} in {err}")) + name.len();
        }
    } else {
        let count = format!("; {} names in all), found \"nonsense\"", names.len());
        assert!(err.starts_with(&format!("expected {what} (nearest: ")) && err.ends_with(&count), "{err}");
    }
    assert!("".parse::<T>().is_err());
}

/// The message in full, for one list.
#[test]
fn study_choices() {
    round_trip(&Normalization::ALL, &["none", "power", "luminance"], "a normalisation");
    let every: Vec<Method> = Method::ALL.iter().chain(&Method::PUBLISHED).copied().collect();
    round_trip(&every, &Method::EVERY_NAME, "a method");
    assert_eq!(&Method::EVERY_NAME[..6], Method::NAMES);
    assert_eq!(&Method::EVERY_NAME[6..], Method::PUBLISHED_NAMES);
    let methods = ["reference", "random", "hero", "regular-center", "regular-box", "fitted"];
    assert_eq!(Method::NAMES, methods);
    round_trip(&Way::ALL, &["hero", "fitted", "rgb", "prefilter"], "a way to carry colour");
}

/// The message in full, for one list.
#[test]
fn strata_error() {
    let err = "nonsense".parse::<Strata>().unwrap_err().to_string();
    assert_eq!(err, "expected a strata (none, jitter or kronecker), found \"nonsense\"");
}

/// The sampling choices the command lines take.
#[test]
fn sampling_choices() {
    round_trip(&Strata::ALL, &["none", "jitter", "kronecker"], "a strata");
    round_trip(&PdfKind::ALL, &["uniform", "visible", "light", "balanced"], "a pdf");
    round_trip(&GamutMap::ALL, &["clip", "chroma"], "a gamut map");
}
