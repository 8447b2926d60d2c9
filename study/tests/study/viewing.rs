//! The assignment's remarks as options use the one range: a light
//! normalised to luminance has a white of Y = 100 over 380–730 nm.

use speclab::data::Light;
use speclab::sampling::reference;
use speclab_study::evaluate::viewing::Normalization;

#[test]
fn luminance_normalisation_uses_the_same_range() {
    let d65 = Normalization::Luminance.apply(Light::D65.spectrum()).expect("bright");
    assert!((reference::white(&d65).y - 100.0).abs() < 1e-9, "luminance normalisation uses the same range");
}
