//! The chart's outputs: the CSV has one row per point and names the Pareto
//! front; the SVG is well-formed XML with one panel per light.

#![cfg(feature = "study")]

#[path = "../examples/chart/draw.rs"]
#[allow(dead_code)]
mod draw;

use std::num::NonZeroUsize;

use speclab::study::chart::{self, Point};
use speclab::study::method::Method;
use speclab::study::report;
use speclab::study::scene::{builtin_lights, builtin_surfaces};
use speclab::study::trials;

/// Real points for the three lights: the reference and both bucket rules
/// (deterministic, so quick), over two patches.
fn points() -> Vec<Point> {
    let surfaces = &builtin_surfaces()[..2];
    let methods = [Method::Reference, Method::RegularCentre, Method::RegularBox];
    let trials = NonZeroUsize::new(2).unwrap();
    builtin_lights().iter().flat_map(|l| chart::points(l, surfaces, &methods, trials, 1).unwrap()).collect()
}

#[test]
fn the_csv_has_one_row_per_point_and_names_the_front() {
    let points = points();
    assert_eq!(points.len(), 3 * (1 + 64 + 64));
    let mut csv = Vec::new();
    report::chart_csv(&mut csv, &points).unwrap();
    let text = String::from_utf8(csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[..5], ["light", "method", "pdf", "strata", "count"]);
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), points.len());
    for (row, p) in rows.iter().zip(&points) {
        assert_eq!(row.len(), header.len());
        assert_eq!((row[0], row[1]), (p.light.as_str(), p.config.method.name()));
        assert_eq!(row[header.len() - 1], p.pareto.to_string());
    }
    // Each light has a front, and the reference is never on it.
    for light in ["A", "D65", "F11"] {
        let front = rows.iter().filter(|r| r[0] == light && r[header.len() - 1] == "true");
        assert!(front.clone().count() >= 2, "{light}");
        assert!(front.clone().all(|r| r[1] != "reference"), "{light}");
    }
}

#[test]
fn the_svg_is_well_formed_with_three_panels() {
    let svg = draw::svg(&points(), 2).unwrap();
    let doc = roxmltree::Document::parse(&svg).expect("well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect();
    for light in ["A", "D65", "F11"] {
        let title = format!("Light {light}");
        assert_eq!(texts.iter().filter(|t| **t == title).count(), 1, "{title}");
    }
    assert_eq!(texts.iter().filter(|t| t.starts_with("Light ")).count(), 3);
    assert!(draw::svg(&[], 2).is_ok(), "no points still draws an empty chart");
}

#[test]
fn worst_and_mean_are_over_the_surfaces() {
    let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
    let (f11, surfaces) = (&lights[2], &surfaces[..2]);
    let trials = NonZeroUsize::new(2).unwrap();
    let points = chart::points(f11, surfaces, &[Method::RegularBox], trials, 1).unwrap();
    for p in &points[..8] {
        let rms: Vec<f64> = surfaces
            .iter()
            .map(|s| {
                let stats =
                    trials::method(&f11.spectrum, &s.spectrum, Method::RegularBox, p.config.count, trials, 1);
                stats.unwrap().rms_de00
            })
            .collect();
        assert_ne!(rms[0], rms[1]);
        assert_eq!(p.worst_rms, rms[0].max(rms[1]), "M = {}", p.config.count);
        assert!(
            (p.mean_rms - (rms[0] + rms[1]) / 2.0).abs() <= 1e-12 * p.worst_rms,
            "M = {}",
            p.config.count
        );
    }
}
