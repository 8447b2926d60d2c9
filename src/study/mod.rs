//! The accuracy study (feature `study`, on by default): how far each way of
//! sampling wavelengths lands from the exact reference, perceptually.
//!
//! - [`scene`]: lights and surfaces, built-in or from files, named.
//! - [`method`]: the six methods (reference, random, hero, center and box
//!   buckets, fitted rules) behind one call, at any path depth
//!   ([`scene::Depth`]); [`fits`]: the fitted rules, fitted once per set
//!   of lights; [`sampling`]: the random methods' pdf and
//!   strata.
//! - [`grid`]: every light × surface by every method (Appendix 2's layout).
//! - [`trials`]: T independent estimates of a method: bias, spread, RMS and
//!   95th-percentile ΔE00, gamut agreement (on all cores).
//! - [`variance`]: exact variances of one random or hero sample.
//! - [`perceptual`]: CIELAB relative to the light's white; CIEDE2000.
//! - [`remarks`]: the assignment's three remarks (normalisation, white
//!   balance).
//! - [`convergence`], [`threshold`], [`compare`]: accuracy against sample
//!   count, where it crosses a budget, one pair in detail.
//! - [`cost`]: the measured cost of one estimate; [`chart`]: speed against
//!   accuracy and its Pareto front; [`plan`]: the cheapest configuration
//!   within a scene's ΔE00 budget.
//! - [`rules`]: the fixed rules (fitted, centre, box) side by side by M
//!   and by path depth; [`shapes`]: named reflectances outside the fitted
//!   rules' prior, to judge them on.
//! - [`texture`]: what RGB texturing costs in colour under each light,
//!   beside the sampling errors.
//! - [`report`]: tables and CSV.
//! - [`swatches`]: every light × patch by every method as swatches whose
//!   pixels are independent estimates; [`sheet`] lays them out as a
//!   labelled image, with the built-in bitmap [`font`].
//!
//! The top floor: it uses every floor below it and nothing uses it. Its
//! functions return a [`StudyError`], the library's `Error` or what only a
//! study asks (an empty scene, a budget).
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::{data::{lights, patches}, study::{method::Method, trials}};
//! let (n, t) = (NonZeroUsize::new(16).unwrap(), NonZeroUsize::new(100).unwrap());
//! let stats = trials::method(&lights::A, &patches::F4, Method::HERO, n, t, 1)?;
//! assert!(stats.rms_de00 > 0.0 && stats.trials == 100);
//! # Ok::<(), speclab::study::StudyError>(())
//! ```

pub mod chart;
pub mod compare;
pub mod convergence;
pub mod cost;
mod error;
pub mod font;
pub mod grid;
pub mod method;
pub mod perceptual;
pub mod plan;
pub mod remarks;
pub mod report;
pub mod rules;
pub mod scene;
pub mod shapes;
pub mod sheet;
pub mod swatches;
pub mod texture;
pub mod threshold;
pub mod trials;
pub mod variance;

pub use error::StudyError;
