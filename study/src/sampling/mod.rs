//! How the study draws its wavelengths: named densities and ways of
//! spreading the primary numbers, chosen on command lines ([`choice`],
//! [`strata`]); the estimators it measures ([`estimate`]); and the seeds
//! that make a result independent of threads ([`seed`]). A renderer needs
//! none of it: it has its own sampler and calls the core's
//! [`HeroSample`](speclab::HeroSample) constructors.

pub mod choice;
pub mod estimate;
pub mod seed;
pub mod strata;
