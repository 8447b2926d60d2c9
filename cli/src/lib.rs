//! # speclab-cli: what speclab's programs show
//!
//! The study ([`speclab_study`]) returns rows and numbers; this crate turns
//! them into what people and programs read, for the examples at the
//! workspace root (`cargo run --release --example grid` and its siblings):
//!
//! - [`report`]: tables for people (with truecolour swatches on a terminal
//!   that takes them) and CSV for programs, one writer per kind of row;
//! - [`sheet`]: the swatch sheet laid out as one labelled image, with a
//!   built-in 5 × 7 bitmap font (no system fonts);
//! - [`png`]: 8-bit sRGB rows written as PNG;
//! - [`progress`]: progress bars on standard error for work that takes
//!   more than a few seconds;
//! - [`args`]: the glue every program shares (exit statuses, counts, help
//!   texts from the library's lists of names).
//!
//! Data goes to standard output, diagnostics and progress to standard
//! error; a closed pipe is not an error.
//!
//! ```
//! use speclab_study::{evaluate::{scene, viewing::Viewing}, experiments::grid::GridOptions};
//! use speclab_cli::report;
//! let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let rows = GridOptions::default().rows(&lights[..1], &surfaces[..1])?;
//! let mut csv = Vec::new();
//! report::grid_csv(&mut csv, &rows, &Viewing::default())?;
//! assert!(String::from_utf8(csv)?.starts_with("light,surface,method,samples,x,y,z,r,g,b,pdf,strata,evals\n"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]
#![forbid(unsafe_code)]

pub mod args;
mod font;
pub mod png;
pub mod progress;
pub mod report;
pub mod sheet;
