//! The chart's picture: the SVG is well-formed XML with one panel per light,
//! and an empty chart still draws.

use std::num::NonZeroUsize;

use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::scene::{Depth, builtin_lights, builtin_surfaces};
use speclab_study::planning::chart::{self, Point};
use speclab_study::planning::cost::Cost;
use speclab_tools::chart as draw;

/// Real points for the three lights (the reference and both bucket rules,
/// deterministic, over two patches), with made-up costs: the drawing does
/// not depend on how fast this machine is.
fn points() -> Vec<Point> {
    let surfaces = &builtin_surfaces()[..2];
    let methods = [Method::Reference, Method::CENTER, Method::BOX];
    let trials = NonZeroUsize::new(2).unwrap();
    let cost = |c: speclab_study::planning::cost::Config| {
        Ok(Cost { per_estimate_ns: 10.0 + c.count.get() as f64, preparation_ns: 1.0 })
    };
    builtin_lights()
        .iter()
        .flat_map(|l| chart::points_with_costs(l, surfaces, &methods, Depth::ONE, trials, 1, cost).unwrap())
        .collect()
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
