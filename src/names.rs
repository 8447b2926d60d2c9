//! Named choices: the names used on command lines, in tables and in CSV.
//!
//! `named_choices!` gives an enum of choices `Display`, `FromStr` (any
//! case), `ALL` and `NAMES` from one list of `variant => "name"` pairs; an
//! unknown name is an
//! [`Error::UnknownName`](crate::error::Error::UnknownName) listing the
//! names (or the nearest, for a long list). At the bottom floor, beside the
//! error type, so that every floor can name its choices; exported, so that
//! the study and programs name theirs the same way.

/// `Display`, `FromStr` (any case), `ALL` and `NAMES` for an enum of
/// fieldless named choices, from one list. An unknown name is an
/// [`Error::UnknownName`](crate::Error::UnknownName) listing the names
/// (the nearest three, for a long list).
///
/// ```
/// #[derive(Clone, Copy, Debug, PartialEq)]
/// enum Finish { Matte, Gloss }
/// speclab::named_choices!(Finish, "a finish": Matte => "matte", Gloss => "gloss");
/// assert_eq!("GLOSS".parse::<Finish>()?, Finish::Gloss);
/// assert_eq!(Finish::ALL.map(|f| f.to_string()), ["matte", "gloss"]);
/// let err = "satin".parse::<Finish>().unwrap_err();
/// assert_eq!(err.to_string(), r#"expected a finish (matte or gloss), found "satin""#);
/// # Ok::<(), speclab::Error>(())
/// ```
#[macro_export]
macro_rules! named_choices {
    ($ty:ident, $what:literal: $($variant:ident => $name:literal),+ $(,)?) => {
        impl ::std::fmt::Display for $ty {
            /// The name used on command lines, in tables and in CSV.
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str(match self { $($ty::$variant => $name),+ })
            }
        }
        impl $ty {
            /// Every choice, in the order of the list.
            pub const ALL: [$ty; [$($name),+].len()] = [$($ty::$variant),+];
            /// Every name, in the order of [`Self::ALL`].
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
