//! Spectra compiled into this program by `build.rs`, used like speclab's own
//! built-in data.

use speclab::TabulatedSpectrum;
use speclab::sampling::reference;

include!(concat!(env!("OUT_DIR"), "/spectra.rs"));

fn main() {
    let leaf: &'static TabulatedSpectrum = &LEAF;
    let rgb = reference::xyz(&LED, leaf).to_linear_srgb();
    println!("leaf under a white LED, linear sRGB: {:.3} {:.3} {:.3}", rgb.r, rgb.g, rgb.b);
    assert!(rgb.g > rgb.r && rgb.g > rgb.b, "a leaf is green");
    // speclab's data sets, compiled here the same way, are speclab's values.
    assert_eq!(&LED_B3, &speclab::data::lights::LED_B3);
    assert_eq!(GOLD_K.eval(500.0), speclab::data::conductors::AU.k().eval(500.0));
    println!("CIE LED-B3 and gold's k, compiled by this crate, equal speclab's built-in ones");
}
