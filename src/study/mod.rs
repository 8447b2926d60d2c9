//! The accuracy study (feature `study`, on by default): how far each way of
//! sampling wavelengths lands from the exact reference, perceptually.
//!
//! In four folders, by job:
//!
//! - [`evaluate`]: scenes, methods and trials: how far one method lands
//!   from the exact colour ([`evaluate::Method`], [`evaluate::Named`],
//!   [`evaluate::Depth`]);
//! - [`experiments`]: the grid, convergence, thresholds, one pair in
//!   detail, the fixed rules by M and depth, RGB textures;
//! - [`planning`]: the measured cost of an estimate, speed against
//!   accuracy, and the cheapest configuration within a ΔE00 budget;
//! - [`present`]: tables, CSV and the swatch sheet.
//!
//! The top floor: it uses every floor below it and nothing uses it. Its
//! functions return a [`StudyError`], the library's `Error` or what only a
//! study asks (an empty scene, a budget).
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::{data::{lights, patches}, study::{evaluate::method::Method, evaluate::trials}};
//! let (n, t) = (NonZeroUsize::new(16).unwrap(), NonZeroUsize::new(100).unwrap());
//! let stats = trials::method(&lights::A, &patches::F4, Method::HERO, n, t, 1)?;
//! assert!(stats.rms_de00 > 0.0 && stats.trials == 100);
//! # Ok::<(), speclab::study::StudyError>(())
//! ```

mod error;
pub mod evaluate;
pub mod experiments;
pub mod planning;
pub mod present;

pub use error::StudyError;
