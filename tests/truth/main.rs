//! Published truth: the core against numbers it did not compute (Appendix 2
//! of the assignment, Sharma's CIEDE2000 pairs, the CIE's chromaticities,
//! the SCHOTT catalogue, the IEC 61966-2-1 constants, the appendix's data
//! files), each source in `tests/data/` or named in its module.

mod appendix2;
mod ciede2000;
mod colour_science;
mod colour_tristimulus;
mod data;
mod named;
mod peers;
mod planck;
mod spaces;
mod white;
