//! # speclab-study: how far each way of sampling wavelengths lands from the exact colour
//!
//! The accuracy study of [`speclab`]: every way of choosing wavelengths
//! (random, hero, centre and box buckets, fitted rules) measured against
//! the exact reference, perceptually (ΔE00), with its cost. It returns rows
//! and numbers; the programs (`cargo run --release --example grid` and its
//! siblings, with `speclab-cli`) show them.
//!
//! In five folders, by job:
//!
//! - [`evaluate`]: scenes, methods and trials: how far one method lands
//!   from the exact colour ([`evaluate::Method`], [`evaluate::Named`],
//!   [`evaluate::Depth`]);
//! - [`experiments`]: the grid, convergence, thresholds, one pair in
//!   detail, the fixed rules by M and depth, RGB textures, swatches;
//! - [`planning`]: the measured cost of an estimate, speed against
//!   accuracy, and the cheapest configuration within a ΔE00 budget;
//! - [`render`]: a small path tracer carrying colour four ways (hero,
//!   fitted, RGB, prefiltered RGB), the exact image of its own paths, and
//!   the survey;
//! - [`display`]: from a colour to a pixel (exposure, gamut mapping,
//!   encoding, 8 bits), for the programs' pictures;
//! - [`published`]: the published few-wavelength rules (ASTM E308/E2022,
//!   Wallis, Meyer, Borges) and spectral prefiltering, on 53 held-apart
//!   measured reflectances.
//!
//! Its functions return a [`StudyError`]: the library's `Error` or what
//! only a study asks (an empty scene, a budget). Work over many cells or
//! trials runs on all cores (rayon); the results do not depend on the
//! number of threads.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::data::{Light, patches};
//! use speclab_study::evaluate::{Method, trials};
//! let (n, t) = (NonZeroUsize::new(16).unwrap(), NonZeroUsize::new(100).unwrap());
//! let stats = trials::method(&Light::A.into(), &patches::F4, Method::HERO, n, t, 1)?;
//! assert!(stats.rms_de00 > 0.0 && stats.trials == 100);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

#![warn(missing_docs)]
#![forbid(unsafe_code)]

pub mod carry;
pub mod display;
mod error;
pub mod evaluate;
pub mod experiments;
pub mod planning;
pub mod published;
pub mod render;
pub mod sampling;

pub use error::StudyError;
