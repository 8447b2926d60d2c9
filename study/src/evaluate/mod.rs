//! Evaluating a method: what is looked at, how a colour is computed, and
//! how far it lands from the exact one.
//!
//! - [`scene`]: lights and surfaces, built-in or from files, named
//!   ([`Named`]), and the path depth ([`Depth`]: light × surface^D);
//! - [`method`]: the methods (reference, hero of any width with its pdf
//!   and strata, centre and box buckets, fitted rules) behind one call,
//!   [`Method`];
//! - [`trials`]: T independent estimates of a method: bias, spread, RMS and
//!   95th-percentile ΔE00, gamut agreement (on all cores);
//! - [`variance`]: exact variances of one random or hero sample;
//! - [`perceptual`]: CIELAB relative to the light's white, CIEDE2000;
//! - [`viewing`]: the assignment's three remarks as options
//!   (normalisation, gamut, white balance);
//! - [`shapes`]: named reflectances outside the fitted rules' prior.
//!
//! Units: XYZ as the reference computes it (the light's own scale), ΔE00
//! in CIELAB relative to the light's white.
//!
//! ```
//! use std::num::NonZeroUsize;
//! use speclab::data::{Light, patches};
//! use speclab_study::evaluate::{Method, trials};
//! let (n, t) = (NonZeroUsize::new(16).unwrap(), NonZeroUsize::new(50).unwrap());
//! let stats = trials::method(&Light::F11.into(), &patches::G4, Method::HERO, n, t, 1)?;
//! assert!(stats.rms_de00 > 0.0 && stats.trials == 50);
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

pub mod method;
pub mod perceptual;
pub mod scene;
pub mod shapes;
pub mod trials;
pub mod viewing;

/// Exact variances of one random or hero sample: the core's.
pub use speclab::sampling::variance;

pub use method::Method;
pub use scene::{Depth, Named};
