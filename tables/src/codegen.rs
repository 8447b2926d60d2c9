//! Compile-time data for your own crate: spectrum files turned into
//! `static` `speclab::TabulatedSpectrum`s by a build script, with the
//! parser, validation and error messages of run-time loading
//! (speclab's `io::Load`). speclab's own `build.rs` makes its built-in data
//! (`speclab::data`) with this module.
//!
//! A file is read (at most 64 MiB), its format detected (brace, columns or
//! JSON), its samples validated for the role and checked to cover
//! 380–730 nm, and the interpolant's coefficients and breaks computed.
//! [`Codegen::source`] is Rust code declaring one `pub static` per spectrum,
//! documented by the `#` comment lines that open its file (where it comes
//! from); include it in your crate. A bad file fails your build with
//! `file:line:column: expected …, found …`.
//!
//! In your `Cargo.toml`, this crate is a build-dependency and speclab a
//! dependency. Your `build.rs`:
//!
//! ```no_run
//! use speclab_tables::{Codegen, Role};
//! fn main() -> Result<(), speclab_tables::Error> {
//!     let mut code = Codegen::new();
//!     code.file("data/lamp.csv", "LAMP", Role::Light)?;
//!     println!("cargo:rerun-if-changed=data/lamp.csv");
//!     let out = std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("spectra.rs");
//!     std::fs::write(out, code.source()).unwrap();
//!     Ok(())
//! }
//! ```
//!
//! and in your crate: `include!(concat!(env!("OUT_DIR"), "/spectra.rs"));`,
//! after which `LAMP` is a `static` `speclab::TabulatedSpectrum`. A complete
//! crate is speclab's `examples/build-data/`.
//!
//! ```
//! use speclab_tables::{Codegen, Role};
//! let mut code = Codegen::new();
//! code.text("380 1\n730 2\n", "lamp.txt", "LAMP", Role::Light)?;
//! assert!(code.source().contains("pub static LAMP: ::speclab::TabulatedSpectrum"));
//! let err = code.text("380 1\n730 2\n", "lamp.txt", "my lamp", Role::Light).unwrap_err();
//! assert_eq!(err.to_string(), "expected a Rust identifier, found \"my lamp\"");
//! # Ok::<(), speclab_tables::Error>(())
//! ```

use std::fmt::Write as _;
use std::path::Path;

use crate::error::Error;
use crate::interp;
use crate::read;
use crate::text::Samples;
use crate::validate::{Interpolation, Role};

/// Rust source declaring spectra as statics, built up one file at a time.
#[derive(Clone, Debug, PartialEq)]
pub struct Codegen {
    crate_path: String,
    source: String,
}

impl Default for Codegen {
    fn default() -> Self {
        Codegen::new()
    }
}

impl Codegen {
    /// Empty source that names speclab as `::speclab`.
    #[must_use]
    pub fn new() -> Self {
        Codegen { crate_path: "::speclab".into(), source: String::new() }
    }

    /// The same, naming speclab by `path` in the generated code (for
    /// example `crate`, inside speclab itself).
    #[must_use]
    pub fn with_crate_path(self, path: &str) -> Self {
        Codegen { crate_path: path.into(), ..self }
    }

    /// Adds the spectrum in the file at `path` as `pub static {name}`,
    /// interpolated as `role` prescribes.
    pub fn file(&mut self, path: impl AsRef<Path>, name: &str, role: Role) -> Result<&mut Self, Error> {
        let path = path.as_ref();
        self.text(&read::file(path)?, &path.display().to_string(), name, role)
    }

    /// Adds the spectrum in `text` as `pub static {name}`; `origin` names the
    /// text in errors and in the static's documentation.
    pub fn text(&mut self, text: &str, origin: &str, name: &str, role: Role) -> Result<&mut Self, Error> {
        if !is_identifier(name) {
            return Err(Error::Identifier { name: name.into() });
        }
        let interpolation = role.interpolation();
        let samples = read::samples(text, origin, role, interpolation, None)?;
        self.spectrum(name, origin, &header(text), role, interpolation, &samples);
        Ok(self)
    }

    /// The generated source so far.
    #[must_use]
    pub fn source(&self) -> &str {
        &self.source
    }

    fn spectrum(
        &mut self,
        name: &str,
        origin: &str,
        doc: &[String],
        role: Role,
        interpolation: Interpolation,
        s: &Samples,
    ) {
        let coeffs = interp::coeffs(interpolation, &s.lambda, &s.values);
        let brk = interp::breaks(&s.lambda, &coeffs, role.bounds());
        let prefix = interp::prefix(&s.lambda, &coeffs, &brk, role.bounds());
        let clean = interp::clean(&s.lambda, &coeffs, &brk, role.bounds());
        let (n, b, p) = (s.lambda.len(), brk.len(), &self.crate_path);
        let out = &mut self.source;
        // Writing to a String cannot fail.
        // The tables behind the static, public (a crate's own code may
        // read them in `const` context) but out of the documentation; data
        // such as 3.14 is not an approximation of π.
        // A 1 nm table's are large: `const` all the same, for `const` readers.
        let h = "#[doc(hidden)]\n#[allow(clippy::approx_constant, clippy::large_const_arrays)]\npub const";
        let _ = writeln!(out, "{h} {name}_LAMBDA: [f64; {n}] = {:?};", s.lambda);
        let _ = writeln!(out, "{h} {name}_VALUES: [f64; {n}] = {:?};", s.values);
        let _ = writeln!(out, "{h} {name}_COEFFS: [[f64; 4]; {}] = {coeffs:?};", n - 1);
        let _ = writeln!(out, "{h} {name}_BREAKS: [f64; {b}] = {brk:?};");
        let _ = writeln!(out, "{h} {name}_PREFIX: [f64; {n}] = {prefix:?};");
        let _ = writeln!(out, "{h} {name}_CLEAN: [bool; {}] = {clean:?};", n - 1);
        // The file's header: its first line as the summary, all of it as
        // written (a text block: no markdown).
        if let Some(first) = doc.first() {
            let _ = writeln!(out, "/// {first}\n///\n/// ```text");
            for line in doc {
                let _ = writeln!(out, "/// {line}");
            }
            let _ = writeln!(out, "/// ```");
        }
        let _ = writeln!(
            out,
            "/// {role:?} spectrum from {origin:?}: {n} samples, {} to {} nm, zero outside\n\
             /// (`TabulatedSpectrum::extended` holds its ends instead).\n\
             pub static {name}: {p}::TabulatedSpectrum = {p}::__codegen::tabulated(\n    \
             {p}::Role::{role:?},\n    {p}::Interpolation::{interpolation:?},\n    \
             {p}::__codegen::Tables {{ lambda: &{name}_LAMBDA, values: &{name}_VALUES, \
             coeffs: &{name}_COEFFS, breaks: &{name}_BREAKS, prefix: &{name}_PREFIX, clean: &{name}_CLEAN }},\n)\n\
             .expect(\"speclab codegen: inconsistent tables for {name}\");",
            s.lambda[0],
            s.lambda[n - 1],
        );
    }
}

/// The `#` comment lines that open `text` (its provenance, in speclab's
/// data files), without the `#`, for the static's documentation.
fn header(text: &str) -> Vec<String> {
    text.lines()
        .map(str::trim)
        .take_while(|l| l.starts_with('#'))
        .map(|l| l.trim_start_matches('#').trim().replace('`', "'"))
        .collect()
}

/// True for `[A-Za-z_][A-Za-z0-9_]*`, other than `_`.
fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && name != "_"
}
