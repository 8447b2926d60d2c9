//! What an estimate costs, and the cheapest one that is accurate enough:
//!
//! - [`cost`]: the measured ns per estimate of a configuration (method,
//!   pdf and strata, count), on this machine;
//! - [`chart`]: speed against accuracy for every charted configuration,
//!   and its Pareto front;
//! - [`plan`]: the cheapest configuration within a scene's ΔE00 budget,
//!   judged on every light × surface of the scene.
//!
//! Times are medians of repeated timings in a release build; they move
//! with the machine, the accuracies do not (fixed seeds).
//!
//! ```
//! use speclab::data::{Light, patches};
//! use speclab_study::evaluate::Method;
//! use speclab_study::planning::cost::{self, Config};
//! let config = Config::new(Method::HERO, std::num::NonZeroUsize::new(16).unwrap());
//! let measured = cost::measure(config, &Light::A.into(), &patches::F4)?;
//! assert!(measured.per_estimate_ns > 0.0);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

pub mod chart;
pub mod cost;
pub mod plan;
