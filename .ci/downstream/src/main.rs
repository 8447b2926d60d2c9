//! Each built-in space, as a renderer names it: its matrix, a colour as an
//! albedo, an unbounded colour and a light, and a colour at compile time.

use speclab::color::{LinearRgb, RgbAlbedo, RgbSpace, rgb_table::RgbTable};

const RED: RgbAlbedo = match RgbTable::ACESCG.const_albedo(LinearRgb::new(0.8, 0.1, 0.05)) {
    Some(albedo) => albedo,
    None => panic!("a colour in [0, 1]"),
};

fn main() {
    let rgb = LinearRgb::new(0.6, 0.3, 0.2);
    let spaces: [(&RgbSpace, RgbAlbedo); 5] = [
        (RgbSpace::srgb(), RgbSpace::srgb().albedo(rgb).unwrap()),
        (RgbSpace::display_p3(), RgbSpace::display_p3().albedo(rgb).unwrap()),
        (RgbSpace::rec2020(), RgbSpace::rec2020().albedo(rgb).unwrap()),
        (RgbSpace::aces2065_1(), RgbSpace::aces2065_1().albedo(rgb).unwrap()),
        (RgbSpace::acescg(), RgbSpace::acescg().albedo(rgb).unwrap()),
    ];
    for (space, albedo) in spaces {
        let back = space.rgb_of(&albedo);
        assert!(back.distance(rgb) < 2e-3, "{}: {back:?}", space.name());
        assert!(space.unbounded(rgb * 4.0).scale() > 0.0 && space.light(rgb).scale() > 0.0);
        println!("{}: {:.4?} → {:.4?}", space.name(), space.to_xyz_matrix()[1], back);
    }
    assert_eq!(RED, RgbSpace::acescg().albedo(LinearRgb::new(0.8, 0.1, 0.05)).unwrap());
}
