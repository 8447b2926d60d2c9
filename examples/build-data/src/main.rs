//! Spectra compiled into this program by `build.rs`, used like speclab's own
//! built-in data; and an RGB space of this crate's own, its table embedded
//! as the built-in spaces' are: Rec.709 primaries with an equal-energy
//! white (a renderer's working space), whose table speclab's `rgb-tables`
//! fitted once (3 s) into `data/rec709-e.rgbt`.

use speclab::color::{LinearRgb, RgbAlbedo, RgbSpace, rgb_table::RgbTable};
use speclab::data::lights;
use speclab::sampling::reference;
use speclab::{Error, TabulatedSpectrum};

include!(concat!(env!("OUT_DIR"), "/spectra.rs"));

/// The space's table, in the program once (1.5 MB), decoded a tile at a
/// time as colours need it.
const REC709_E: &RgbTable = speclab::rgb_table!(concat!(env!("CARGO_MANIFEST_DIR"), "/data/rec709-e.rgbt"));

/// A colour of that space at compile time.
const ORANGE: RgbAlbedo = match REC709_E.const_albedo(LinearRgb::new(0.8, 0.35, 0.05)) {
    Some(albedo) => albedo,
    None => panic!("a colour in [0, 1]"),
};

/// Rec.709's primaries, the equal-energy white, spectra under CIE E: the
/// definition the table was fitted for.
fn rec709_e() -> Result<RgbSpace, Error> {
    let primaries = [[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]];
    RgbSpace::new("rec709-e", primaries, [1.0 / 3.0; 2], &lights::E)?.with_table(REC709_E.clone())
}

fn main() -> Result<(), Error> {
    let leaf: &'static TabulatedSpectrum = &LEAF;
    let rgb = reference::xyz(&LED, leaf).to_linear_srgb();
    println!("leaf under a white LED, linear sRGB: {:.3} {:.3} {:.3}", rgb.r, rgb.g, rgb.b);
    assert!(rgb.g > rgb.r && rgb.g > rgb.b, "a leaf is green");
    // speclab's data sets, compiled here the same way, are speclab's values.
    assert_eq!(&LED_B3, &speclab::data::lights::LED_B3);
    assert_eq!(GOLD_K.eval(500.0), speclab::data::conductors::AU.k().eval(500.0));
    println!("CIE LED-B3 and gold's k, compiled by this crate, equal speclab's built-in ones");
    let start = std::time::Instant::now();
    let space = rec709_e()?;
    let orange = space.albedo(LinearRgb::new(0.8, 0.35, 0.05))?;
    let first_use = start.elapsed();
    assert_eq!(orange, ORANGE, "the same coefficients at compile time and at run time");
    let back = space.rgb_of(&orange);
    println!(
        "rec709-e: first use {:.2} ms ({} of {} tiles decoded, nothing fitted); orange comes back as {:.3} {:.3} {:.3}",
        first_use.as_secs_f64() * 1e3,
        space.table().decoded_tiles().0,
        space.table().decoded_tiles().1,
        back.r,
        back.g,
        back.b
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The embedded table is this space's (a table of another space is
    /// refused), its first use decodes one tile and fits nothing, and its
    /// colours come back: the colours a fit for each alone gives, within
    /// the compact table's rounding.
    #[test]
    fn the_embedded_table_serves_the_space() {
        let space = rec709_e().expect("the table fits the space");
        assert!(
            RgbSpace::srgb().clone().with_table(REC709_E.clone()).is_err(),
            "D65's sRGB is another space"
        );
        let before = space.table().decoded_tiles().0;
        let rgb = LinearRgb::new(0.2, 0.6, 0.4);
        let looked_up = space.albedo(rgb).unwrap();
        assert_eq!(space.table().decoded_tiles().0, before + 1);
        assert!(space.rgb_of(&looked_up).distance(rgb) < 2e-3, "{:?}", space.rgb_of(&looked_up));
        assert!(space.rgb_of(&ORANGE).distance(LinearRgb::new(0.8, 0.35, 0.05)) < 2e-3);
        assert!(
            std::ptr::eq(space.table().as_bytes(), REC709_E.as_bytes()),
            "the embedded bytes, not a copy"
        );
    }
}
