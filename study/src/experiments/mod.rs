//! The study's experiments, each a table or a few numbers over a scene:
//!
//! - [`grid`]: every light × surface by every method (Appendix 2's
//!   layout);
//! - [`convergence`] and [`threshold`]: accuracy against sample count, and
//!   where it first stays within a budget;
//! - [`compare`]: one light and one surface in detail;
//! - [`rules`]: the fixed rules (fitted, centre, box) side by side by M,
//!   by path depth and by light;
//! - [`texture`]: what RGB texturing costs in colour under each light,
//!   beside the sampling errors.
//!
//! They compute; the programs (`speclab-cli`) format.
//!
//! ```
//! use speclab_study::evaluate::scene::{builtin_lights, builtin_surfaces};
//! use speclab_study::experiments::grid::GridOptions;
//! let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
//! let rows = GridOptions::default().rows(&lights[..1], &surfaces[..2])?;
//! assert_eq!(rows.len(), 2 * 6); // two cells, six methods each
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

pub mod compare;
pub mod convergence;
pub mod grid;
pub mod rules;
pub mod swatches;
pub mod texture;
pub mod threshold;
