//! Named choices read and write the names used on command lines, in tables
//! and in CSV (`Display` and `FromStr`, any case), and an unknown name is an
//! error listing the names that exist (or, for long lists, the nearest).

use std::fmt::Display;
use std::str::FromStr;

use speclab::Error;
use speclab::data::{Light, Patch};
use speclab::sampling::buckets::BucketRule;

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
        // Every name listed, in order (the exact wording: `bucket_rule_error`).
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
fn bucket_rule_error() {
    let err = "nonsense".parse::<BucketRule>().unwrap_err().to_string();
    assert_eq!(err, "expected a bucket rule (center or box), found \"nonsense\"");
}

#[test]
fn core_choices() {
    let lights: Vec<Light> = Light::ALL.to_vec();
    round_trip(&lights, &speclab::data::lights::NAMES, "a built-in light");
    assert_eq!(Light::APPENDIX.map(|l| l.to_string()), ["A", "D65", "F11"]);
    round_trip(&Patch::ALL, &["E2", "F4", "G4", "H4", "J4", "A1"], "a built-in patch");
    round_trip(&BucketRule::ALL, &["center", "box"], "a bucket rule");
}

/// The surfaces' names are the patches' then the conductors', each found
/// by `surface_named` (a patch as itself, a conductor tabulated).
#[test]
fn surface_names() {
    use speclab::data::{SURFACE_NAMES, conductors, patches, surface_named};
    let expected: Vec<&str> = patches::NAMES.iter().chain(&conductors::NAMES).copied().collect();
    assert_eq!(SURFACE_NAMES.to_vec(), expected);
    assert!(!conductors::NAMES.is_empty());
    for name in SURFACE_NAMES {
        let s = surface_named(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(s.values().iter().all(|v| (0.0..=1.0).contains(v)), "{name}");
    }
    let err = surface_named("nonsense").unwrap_err().to_string();
    assert!(err.contains("a built-in surface"), "{err}");
}
