//! How the study's path tracer carries colour along its paths: one
//! interface, [`Carry`], over three ways of doing it (a rule size chosen at
//! run time reaches compile-time lanes through the core's
//! [`speclab::sampling::with_lanes`]).
//!
//! A path tracer keeps a throughput β from the camera and adds what each
//! light contributes through it. What β *is* depends on the way colour is
//! carried:
//!
//! - [`Hero`]: K = 4 hero wavelengths drawn per path from a pdf, every
//!   spectrum evaluated at them at each vertex (unbiased: noise, no bias);
//! - [`Fitted`]: M wavelengths fitted once to the scene's lights
//!   (`Rule::fit_each`: shared wavelengths, each light its own weights);
//!   every surface evaluated there once, when the scene is built, so a
//!   vertex is M multiplications (deterministic: bias, no colour noise);
//! - [`Rgb`]: linear sRGB triples, as a renderer without spectra.
//!
//! A tracer written once against [`Carry`] runs with each; the types are
//! small and `Copy` per path and per vertex, and nothing allocates after
//! construction. Lights and surfaces are numbered in the order given.
//!
//! ```
//! use speclab_study::carry::{Carry, Fitted, Hero, Rgb};
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{pdf::Uniform, reference, rule::Rule};
//! use speclab::spectrum::DenseObserver;
//!
//! /// One bounce: the camera sees surface 0, lit by light 0.
//! fn one_bounce<C: Carry>(c: &C, u: f64) -> speclab::Xyz {
//!     let path = c.path(u);
//!     let beta = c.one() * c.albedo(&path, 0);
//!     c.emitted(&path, 0, beta)
//! }
//! let (light, surface) = (&lights::F11, &patches::G4);
//! let exact = reference::xyz(light, surface);
//! let hero = Hero::new(vec![light], vec![surface], DenseObserver::new(), Uniform::ASSIGNMENT)?;
//! let mean = (0..256).map(|i| one_bounce(&hero, (i as f64 + 0.5) / 256.0)).sum::<speclab::Xyz>() / 256.0;
//! let fitted = Fitted::<12, f32>::new(&Rule::fit_each(&[light], 10)?, &[light], &[surface])?;
//! let rgb = Rgb::new(&[light], &[surface]);
//! for estimate in [mean, one_bounce(&fitted, 0.0)] {
//!     assert!((estimate.y - exact.y).abs() < 0.01 * exact.y, "{estimate:?} against {exact:?}");
//! }
//! let off = (one_bounce(&rgb, 0.0).y - exact.y).abs() / exact.y;
//! assert!(off > 0.05, "RGB misses F11's lines: {off}");
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

mod ways;

pub use ways::{Fitted, Hero, Rgb};

use std::ops::{Mul, MulAssign};

use speclab::Xyz;

/// A way of carrying colour along a path: what a path keeps (its
/// wavelengths, or nothing), what a throughput is, and how a light's
/// contribution through it becomes XYZ.
pub trait Carry {
    /// Per-path state: the wavelengths (hero), or `()` (fixed rules, RGB).
    type Path: Copy;
    /// A throughput or radiance value at the path's wavelengths (or RGB).
    type Value: Copy + Mul<Output = Self::Value> + MulAssign;

    /// A new path's state from its uniform number in [0, 1).
    fn path(&self, u: f64) -> Self::Path;

    /// The throughput of a path that has met nothing: 1.
    fn one(&self) -> Self::Value;

    /// `v` times a scalar (a geometric factor, a Russian roulette weight).
    fn scale(&self, v: Self::Value, s: f64) -> Self::Value;

    /// The XYZ that throughput `beta` carries from light `light` (an
    /// estimate: each light converted with its own weights where the way
    /// has them); zero for an index past the scene's lights.
    fn emitted(&self, path: &Self::Path, light: usize, beta: Self::Value) -> Xyz;

    /// Surface `surface`'s albedo on this path; black for an index past
    /// the scene's surfaces.
    fn albedo(&self, path: &Self::Path, surface: usize) -> Self::Value;

    /// The throughput's luminance relative to a white path's (1 for
    /// [`Carry::one`]): what Russian roulette on luminance compares.
    fn luminance(&self, path: &Self::Path, beta: Self::Value) -> f64;

    /// The throughput's largest component over its wavelengths (or
    /// channels): what pbrt-v4's and Mitsuba 3's Russian roulette compare
    /// (pbrt-v4 ends a path with probability `max(0, 1 − max β)` and
    /// divides the survivors' β by `max β`).
    fn max_component(&self, path: &Self::Path, beta: Self::Value) -> f64;
}
