//! # speclab-tables: tabulated spectra, from text to static data
//!
//! The std-only half of [speclab](https://docs.rs/speclab): everything a
//! build script needs to turn spectrum files into `static` data, and what
//! speclab's run-time loading shares with it, so both accept and reject the
//! same files with the same messages.
//!
//! - [`read`]: from bytes to validated samples (size cap, format detection,
//!   validation, coverage of 380–730 nm); the formats are [`brace`] (the
//!   assignment's `{λ, v}` notation), [`columns`] (CSV, TSV, whitespace) and
//!   [`json`], over the toolkit in [`text`].
//! - [`validate`]: what makes samples a spectrum for its [`Role`].
//! - [`interp`]: the piecewise polynomials through the samples (linear, or
//!   the cubic through the four nearest samples), their clamp crossings and
//!   exact integrals.
//! - [`observer`]: three responses per wavelength at a uniform step (the
//!   CIE's colour-matching functions, or a camera's), from `nm,x,y,z` rows
//!   to a static table.
//! - [`codegen`]: [`Codegen`], spectrum files → Rust source declaring
//!   `static` `speclab::TabulatedSpectrum`s.
//! - [`error`]: every error names its place (`file:line:column: expected …,
//!   found …`).
//!
//! Wavelengths are in nanometres; the range every integral covers is
//! [`range::LAMBDA_MIN`]–[`range::LAMBDA_MAX`] (380–730 nm).
//!
//! A downstream crate lists this crate under `[build-dependencies]` and
//! speclab under `[dependencies]`; its `build.rs`:
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
//! ```
//! use speclab_tables::{read, Role};
//! let s = read::samples("380 1\n730 3\n", "lamp.txt", Role::Light, Role::Light.interpolation(), None)?;
//! assert_eq!(s.values, [1.0, 3.0]);
//! # Ok::<(), speclab_tables::error::ParseError>(())
//! ```

#![warn(missing_docs)]

pub mod brace;
pub mod codegen;
pub mod columns;
pub mod error;
pub mod interp;
pub mod json;
pub mod observer;
pub mod range;
pub mod read;
pub mod rgb_file;
pub mod text;
pub mod validate;

pub use codegen::Codegen;
pub use error::Error;
pub use validate::{Interpolation, Role};
