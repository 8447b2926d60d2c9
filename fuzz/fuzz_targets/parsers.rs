//! Every run-time parser on arbitrary bytes: brace notation, two-column
//! text, JSON, the format-detecting loader for each role, and evaluation of
//! whatever loads. The only failure is a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use speclab::load::{Format, Load};
use speclab::{Role, parse};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let _ = parse::parse_samples(text, "<fuzz>");
    let _ = parse::parse_tuples::<3>(text, "<fuzz>");
    let _ = speclab::columns::parse_columns(text, "<fuzz>");
    let _ = speclab::json::parse_json(text, "<fuzz>");
    let _ = Format::detect(text);
    for role in [Role::Light, Role::Reflectance, Role::Observer] {
        if let Ok(s) = Load::new(role).text(text, "<fuzz>") {
            assert!(s.eval(555.0).is_finite());
            let _ = s.integral(380.0, 730.0);
            let _ = speclab::reference::xyz(&speclab::data::D65, &s);
        }
    }
});
