//! The published few-wavelength rules beside the fitted rule: what a
//! colour scientist or a renderer author compares a rule of M wavelengths
//! against first.
//!
//! - [`rules`]: ASTM E308/E2022 weighting factors, Wallis 1975, Meyer 1988
//!   and Borges 1994 as [`speclab::sampling::rule::Rule`]s built for one
//!   light (their weights include it);
//! - [`prefilter`]: Ward and Eydelberg-Vileshin 2002 spectral prefiltering
//!   (three numbers per surface, in XYZ, linear sRGB or sharpened RGB);
//! - [`gauss`]: orthogonal polynomials and Gauss rules of a weight function
//!   on a fine grid (Stieltjes, Golub–Welsch), and [`solve`] for the small
//!   linear systems;
//! - [`held_apart`]: 53 measured reflectances kept out of every fit;
//! - [`measured`]: 1,269 measured Munsell chips, less those near a
//!   held-apart surface, as a prior to fit rules over (`fitted-munsell`);
//! - [`minimax`]: weights for given wavelengths that lower the worst ΔE00
//!   over a set of surfaces (Lawson's iteration);
//! - [`compare`]: worst and mean ΔE00 of each candidate over lights ×
//!   surfaces, at any depth (`cargo run --release --example published`),
//!   with two bounds that see the judged surfaces (`oracle`,
//!   `oracle-minimax`).
//!
//! Units: wavelengths in nm, weights in nm × the light's unit (a rule's
//! XYZ is on the reference's scale), ΔE00 relative to each light's white.
//!
//! ```
//! use speclab_study::published::{rules::Family, compare::Candidate};
//! use speclab_study::evaluate::scene::{Depth, Named};
//! let f11 = Named::from(speclab::data::Light::F11);
//! let g4 = Named::from(speclab::data::Patch::G4);
//! let rows = speclab_study::published::compare::table(
//!     &[f11], &[g4], &[Candidate::Fitted(10), Candidate::Published(Family::Astm, 36)], Depth::ONE)?;
//! assert!(rows[1].worst < 1e-9); // Appendix 2's patches are 10 nm tables: ASTM at 10 nm is exact
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

pub mod compare;
pub mod gauss;
pub mod held_apart;
pub mod measured;
pub mod minimax;
pub mod prefilter;
pub mod rules;
pub mod solve;
