//! The body of the parser fuzz target (`fuzz/fuzz_targets/parsers.rs`
//! includes this file): the text formats and the RGB table file format,
//! so that the API tests replay saved inputs through exactly the same
//! calls.

use speclab::color::LinearRgb;
use speclab::color::rgb_table::RgbTable;
use speclab::data::lights;
use speclab::io::{Format, Load};
use speclab::sampling::reference;
use speclab::spectrum::{Role, Spectrum};
use speclab_tables::{brace, columns, json};

/// Feeds `data` to every run-time parser and evaluates whatever loads.
/// Panics only on a bug: a parser panicking, or a loaded spectrum that
/// evaluates or integrates to a non-finite value.
pub fn parsers(data: &[u8]) {
    // An RGB table file: refused with an error, or read and looked up.
    if let Ok(table) = RgbTable::from_bytes(data, "<fuzz>") {
        let albedo = table.albedo(LinearRgb::new(0.5, 0.2, 0.1)).expect("a colour in the cube");
        assert!(albedo.eval(555.0).is_finite(), "a loaded table's albedo is not finite");
    }
    let Ok(text) = std::str::from_utf8(data) else { return };
    let _ = brace::parse_samples(text, "<fuzz>");
    let _ = brace::parse_rows::<3>(text, "<fuzz>", 3);
    let _ = columns::parse_columns(text, "<fuzz>");
    let _ = json::parse_json(text, "<fuzz>");
    let _ = Format::detect(text);
    for role in [Role::Light, Role::Reflectance, Role::Observer] {
        if let Ok(s) = Load::new(role).text(text, "<fuzz>") {
            assert!(s.eval(555.0).is_finite(), "loaded spectrum is not finite at 555 nm");
            assert!(s.integral(380.0, 730.0).is_finite(), "loaded spectrum has a non-finite integral");
            assert!(reference::xyz(&lights::D65, &s).is_finite(), "non-finite reference");
        }
    }
}
