//! Glue shared by the programs: exit statuses, option values the library
//! does not parse itself, help texts from the library's lists of names, and
//! whether the terminal takes colour.
//!
//! ```
//! use speclab_cli::args;
//! assert_eq!(args::buckets("16").map(|m| m.get()), Ok(16));
//! assert!(args::buckets("65").is_err());
//! assert!(args::names_help().contains("CIE-D65"));
//! ```

use std::io::{self, IsTerminal};
use std::num::NonZeroUsize;
use std::process::ExitCode;

use speclab::sampling::rule::MAX_M;
use speclab_study::sampling::estimate::MAX_WIDTH;

/// The built-in names, for help texts: every light and surface, read from
/// the library's lists.
pub fn names_help() -> String {
    let wrap = |names: &[&str]| {
        let mut lines: Vec<Vec<&str>> = vec![Vec::new()];
        for &name in names {
            let width: usize = lines.last().map_or(0, |l| l.iter().map(|n| n.len() + 2).sum());
            if width + name.len() > 84 {
                lines.push(Vec::new());
            }
            lines.last_mut().expect("a line").push(name);
        }
        let lines: Vec<String> = lines.iter().map(|l| l.join(", ")).collect();
        lines.join(",\n                       ")
    };
    let pbrt: Vec<&str> = speclab::data::lights::ALIASES.iter().map(|(a, _)| *a).collect();
    format!(
        "built-in names (any case):\n  lights:              {},\n                       \
         or D and a temperature for CIE daylight (D5000 is 5000 K);\n                       \
         A, D65 and F11 are the assignment's tables (Appendix 2's, 380-780 nm, D65 normalised\n                       \
         at 460 nm); CIE-A and CIE-D65 are the CIE's, also by pbrt-v4's names:\n                       \
         {}\n  surfaces:            {}",
        wrap(&speclab::data::lights::NAMES),
        wrap(&pbrt),
        wrap(&speclab::data::SURFACE_NAMES),
    )
}

/// Prints `message` as the program's error and returns exit status 2.
pub fn fail(program: &str, message: impl std::fmt::Display) -> ExitCode {
    eprintln!("{program}: {message}");
    ExitCode::from(2)
}

/// Success, or status 2 for a write error other than a closed pipe (`| head`).
pub fn finish(program: &str, written: io::Result<()>) -> ExitCode {
    match written {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => fail(program, e),
        _ => ExitCode::SUCCESS,
    }
}

/// A `--m` value: a bucket count from 1 to 64, or a message saying so.
pub fn buckets(value: &str) -> Result<NonZeroUsize, String> {
    let m = value.parse::<usize>().ok().and_then(NonZeroUsize::new).filter(|m| m.get() <= MAX_M);
    m.ok_or_else(|| format!("expected a bucket count from 1 to {MAX_M}, found {value:?}"))
}

/// A sample count (`--n`, `--trials`): a positive integer, or a message saying so.
pub fn count(what: &str, value: &str) -> Result<NonZeroUsize, String> {
    value
        .parse::<NonZeroUsize>()
        .map_err(|_| format!("expected a positive number of {what}, found {value:?}"))
}

/// True if standard output takes truecolour swatches: a terminal that says
/// so (`COLORTERM` is `truecolor` or `24bit`), and `NO_COLOR` unset or empty.
pub fn color() -> bool {
    let truecolor = std::env::var("COLORTERM").is_ok_and(|v| v == "truecolor" || v == "24bit");
    let no_color = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
    io::stdout().is_terminal() && truecolor && !no_color
}

/// A `--k` value: a hero width from 1 to 64, or a message saying so.
pub fn hero_width(value: &str) -> Result<usize, String> {
    let k = value.parse::<usize>().ok().filter(|k| (1..=MAX_WIDTH).contains(k));
    k.ok_or_else(|| format!("expected a hero width from 1 to {MAX_WIDTH} wavelengths, found {value:?}"))
}
