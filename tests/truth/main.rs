//! Published truth: the core against numbers it did not compute (Appendix 2
//! of the assignment, Sharma's CIEDE2000 pairs, the CIE's chromaticities,
//! the SCHOTT catalogue, the IEC 61966-2-1 constants, the appendix's data
//! files), each source in `tests/data/` or named in its module.

mod appendix2;
mod ciede2000;
mod colour_pieces;
mod colour_science;
mod colour_tristimulus;
mod data;
mod named;
mod peers;
mod planck;
mod spaces;
mod white;

/// The CIE's 5 nm table of a light the crate ships at 1 nm (A, D65): every
/// fifth row to 780 nm, as colour-science 0.4.7 and CIE 15:2004 have it
/// (the 1 nm table's rows there are the 5 nm table's, 97 of 97).
fn cie_5nm(light: &speclab::TabulatedSpectrum) -> speclab::TabulatedSpectrum {
    let rows = light.lambda().iter().zip(light.values()).filter(|&(&l, _)| l % 5.0 == 0.0 && l <= 780.0);
    let (lambda, values) = rows.map(|(&l, &v)| (l, v)).unzip();
    speclab::TabulatedSpectrum::new(lambda, values, speclab::Role::Light).expect("a light")
}
