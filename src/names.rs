//! Named choices: the names used on command lines, in tables and in CSV.
//!
//! `named_choices!` gives an enum of choices `Display` and `FromStr` (any
//! case) from one list of `variant => "name"` pairs, and an `ALL` would list
//! them in the same order; an unknown name is an
//! [`Error::UnknownName`](crate::error::Error::UnknownName) listing the
//! names (or the nearest, for a long list). At the bottom floor, beside the
//! error type, so that every floor can name its choices.

/// `Display` and `FromStr` (any case) for an enum of named choices:
/// `named_choices!(Light, "a built-in light": A => "A", D65 => "D65")`. An
/// unknown name is an [`Error::UnknownName`] listing the names.
macro_rules! named_choices {
    ($ty:ident, $what:literal: $($variant:ident => $name:literal),+ $(,)?) => {
        impl ::std::fmt::Display for $ty {
            /// The name used on command lines, in tables and in CSV.
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str(match self { $($ty::$variant => $name),+ })
            }
        }
        impl $ty {
            /// Every name, in the order of the list.
            pub const NAMES: &'static [&'static str] = &[$($name),+];
        }
        impl ::std::str::FromStr for $ty {
            type Err = $crate::error::Error;
            /// The choice with this name, in any case.
            fn from_str(s: &str) -> ::std::result::Result<Self, Self::Err> {
                $(if s.eq_ignore_ascii_case($name) {
                    return Ok($ty::$variant);
                })+
                Err($crate::error::Error::UnknownName { what: $what, expected: Self::NAMES, found: s.to_string() })
            }
        }
    };
}
pub(crate) use named_choices;
