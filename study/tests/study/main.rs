//! The study's tests: the planner's choices, depths,
//! statistics in units of their standard error (unbiasedness, stability
//! where each method fails), thread safety, names, finite numbers.

mod alloc;
mod carry;
mod depth;
mod display;
mod finite;
mod names;
mod plan;
mod published;
mod stability;
mod threads;
mod unbiased;
mod viewing;
mod wiring;
