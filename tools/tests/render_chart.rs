//! The render survey's chart: its CSV is read strictly (a bad line is
//! named), and the SVG has one panel per scene.

use speclab_tools::render_chart::{Row, parse, svg};

const CSV: &str = "scene,way,spp,ns_per_path,de00_mean,de00_p95,de00_max
F11,rgb,16,350,3.4,6.0,33
F11,fitted M=10,16,360,0.04,0.15,1.8
F11,hero uniform/jitter,4,440,14.8,35.3,71
F11 + A,rgb,16,400,4.8,8.6,24
";

#[test]
fn the_rows_are_read_and_drawn_one_panel_per_scene() {
    let rows = parse(CSV).unwrap();
    assert_eq!(rows.len(), 4);
    assert_eq!(
        rows[1],
        Row {
            scene: "F11".into(),
            way: "fitted M=10".into(),
            spp: 16,
            ns_per_path: 360.0,
            de00: [0.04, 0.15, 1.8]
        }
    );
    assert_eq!(rows[2].ns_per_pixel(), 1760.0);
    let text = svg(&rows).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
    let titles: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .filter(|t| t.starts_with("Light "))
        .collect();
    assert_eq!(titles, ["Light F11", "Light F11 + A"]);
}

#[test]
fn a_bad_line_is_named() {
    for (bad, expected) in [
        ("F11,rgb,16,350,3.4,6.0\n", "line 2: expected 7 fields"),
        ("F11,rgb,x,350,3.4,6.0,33\n", "line 2: expected a path count and a time"),
        ("F11,rgb,16,350,3.4,NaN,33\n", "line 2: expected three ΔE00 values"),
        ("F11,rgb,16,-1,3.4,6.0,33\n", "line 2: expected a path count and a time"),
    ] {
        let err = parse(&format!("header\n{bad}")).unwrap_err();
        assert!(err.starts_with(expected), "{err}");
    }
}
