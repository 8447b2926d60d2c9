//! The built-in compact tables against the `f32` tables they came from
//! (`tools/rgb-f32/`, as fitted; not in any package): each compact file
//! is exactly what the encoder makes of its source, decodes and encodes
//! back to the same bytes, and differs from it by at most the stated
//! coefficient, reflectance and colour differences (docs/color.md), with
//! round trips no worse. Regression snapshots of this project's tables:
//! `cargo test -p speclab-tools --test compact_tables -- --nocapture`
//! prints the figures.

use speclab::color::difference::delta_e00;
use speclab::color::rgb_table::RgbTable;
use speclab::color::{LinearRgb, RgbAlbedo, RgbSpace};
use speclab::spectrum::SigmoidPolynomial;
use speclab_tables::rgb_file::{compact, read_header};

/// Each space, its embedded compact table and its `f32` source.
fn tables() -> Vec<(&'static RgbSpace, &'static RgbTable, RgbTable)> {
    let embedded =
        [RgbTable::SRGB, RgbTable::DISPLAY_P3, RgbTable::REC2020, RgbTable::ACES2065_1, RgbTable::ACESCG];
    let stems = ["srgb", "display-p3", "rec2020", "aces2065-1", "acescg"];
    let folder = concat!(env!("CARGO_MANIFEST_DIR"), "/rgb-f32");
    RgbSpace::all()
        .into_iter()
        .zip(embedded)
        .zip(stems)
        .map(|((space, table), stem)| {
            let source = RgbTable::load(format!("{folder}/{stem}.rgbt")).expect("the f32 source");
            (space, table, source)
        })
        .collect()
}

/// The node `i` of a fixed sequence of `count` spread over `len` nodes.
fn pick(i: usize, len: usize) -> usize {
    (i.wrapping_mul(2_654_435_761) ^ (i >> 3)) % len
}

/// Each compact file is its source encoded with its own rounding, and
/// its nodes encode back to its very bytes.
#[test]
fn compact_files_are_their_sources_encoded() {
    for (space, table, source) in tables() {
        let quantizer = table.quantizer().expect("a compact table");
        assert!(source.quantizer().is_none(), "{}: the source is as fitted", space.name());
        assert!(source.compact_with(quantizer) == *table, "{}: the encoder makes other bytes", space.name());
        let bytes = table.as_bytes();
        let header = read_header(bytes).expect("a header");
        let nodes = compact::decode_nodes(bytes);
        let again = compact::encode_nodes(&header, quantizer, table.resolution(), &nodes);
        assert!(again == bytes, "{}: decode then encode", space.name());
    }
}

/// The largest differences between each compact table and its source:
/// coefficients (absolute, and relative to the larger of 1 and the node's
/// largest coefficient), reflectance over 360–830 nm at 1 nm on 20,000 nodes, and
/// the colour of 2,000 nodes under the space's illuminant (ΔE00); each
/// within its stated bound.
#[test]
fn compact_tables_stay_close_to_their_sources() {
    for (space, table, source) in tables() {
        let (c, s) = (table.coefficients(), source.coefficients());
        let (mut absolute, mut relative) = (0f64, 0f64);
        for (a, b) in c.iter().zip(&s) {
            // Relative to the node's largest coefficient: its coefficients
            // cancel, so each one's own size says little.
            let scale = b.iter().fold(1f64, |m, v| m.max(f64::from(v.abs())));
            for (a, b) in a.iter().zip(b) {
                let d = f64::from((a - b).abs());
                absolute = absolute.max(d);
                relative = relative.max(d / scale);
            }
        }
        let poly = |c: [f32; 3]| SigmoidPolynomial::new(c.map(f64::from));
        let mut reflectance = 0f64;
        for i in 0..20_000 {
            let k = pick(i, c.len());
            let (a, b) = (poly(c[k]), poly(s[k]));
            for lambda in 360..=830 {
                reflectance = reflectance.max((a.eval(f64::from(lambda)) - b.eval(f64::from(lambda))).abs());
            }
        }
        let mut colour = 0f64;
        for i in 0..2_000 {
            let k = pick(i + 7, c.len());
            let (a, b) = (RgbAlbedo::from_polynomial(poly(c[k])), RgbAlbedo::from_polynomial(poly(s[k])));
            colour = colour.max(delta_e00(space.albedo_xyz(&a), space.albedo_xyz(&b), space.white()));
        }
        println!(
            "{}: coefficients {absolute:.3e} ({relative:.2e} relative), reflectance {reflectance:.4}, colour ΔE00 {colour:.4}",
            space.name()
        );
        assert!(relative < 2e-3, "{}: coefficients {relative}", space.name());
        assert!(reflectance < 0.2, "{}: reflectance {reflectance}", space.name());
        assert!(colour < 0.02, "{}: ΔE00 {colour}", space.name());
    }
}

/// ΔE00 between the colour asked for and `albedo`'s under the space's
/// illuminant.
fn round_trip(space: &RgbSpace, rgb: LinearRgb, albedo: &RgbAlbedo) -> f64 {
    delta_e00(space.xyz(space.rgb_of(albedo)), space.xyz(rgb), space.white())
}

/// On the 9³ grid of docs/color.md, where a reflectance exists: the
/// compact table's worst round trip is within 0.002 of its source's (the
/// rounding of a node; on four spaces no worse, on Display P3 0.1326
/// against 0.1313 at (0.375, 1, 0), a colour on the object colours' limit
/// that the fit alone reaches under the CIE's 1 nm D65), and the two
/// tables' albedos are within ΔE00 0.015 of each other everywhere.
#[test]
fn round_trips_are_no_worse() {
    for (space, table, source) in tables() {
        let source_space = space.clone().with_table(source).expect("the source fits its space");
        let (mut worst_source, mut worst_compact, mut apart) = (0f64, 0f64, 0f64);
        let (mut gap_source, mut gap_compact, mut unreachable) = (0f64, 0f64, 0);
        for i in 0..729 {
            let rgb =
                LinearRgb::new(f64::from(i / 81) / 8.0, f64::from(i / 9 % 9) / 8.0, f64::from(i % 9) / 8.0);
            let (a, b) = (table.albedo(rgb).unwrap(), source_space.albedo(rgb).unwrap());
            apart = apart.max(delta_e00(space.albedo_xyz(&a), space.albedo_xyz(&b), space.white()));
            let fitted = round_trip(space, rgb, &space.fit_albedo(rgb).unwrap());
            if fitted > 0.01 {
                // No reflectance has it: how far each table lands from the fit.
                unreachable += 1;
                gap_compact = gap_compact.max(round_trip(space, rgb, &a) - fitted);
                gap_source = gap_source.max(round_trip(space, rgb, &b) - fitted);
                continue;
            }
            worst_compact = worst_compact.max(round_trip(space, rgb, &a));
            worst_source = worst_source.max(round_trip(space, rgb, &b));
        }
        println!(
            "{}: worst round trip {worst_compact:.4} (as fitted {worst_source:.4}), tables apart {apart:.4}; \
             {unreachable} of 729 unreachable, the table within {gap_compact:.4} of the fit there \
             (as fitted {gap_source:.4})",
            space.name()
        );
        assert!(worst_compact <= worst_source + 0.002, "{}: {worst_compact} > {worst_source}", space.name());
        assert!(apart < 0.015, "{}: {apart}", space.name());
    }
}
