//! Properties of the core that hold for every input: energy conservation,
//! finite results, no panics, exactness of each fast path against the slow
//! one, pdfs that integrate to 1 and are sampled as they say, dense tables
//! within their stated error, round trips through RGB, what the luminance
//! weights of each kind of wavelengths sum to.

mod dense;
mod energy;
mod finite;
mod fitted;
mod luminance;
mod max_value;
mod no_panic;
mod pdfs;
mod prepared;
mod regular;
mod rgb_table;
mod spectra;
mod upsample;
