//! The chart's points: the CSV has one row per point and names the Pareto
//! front, worst and mean are over the surfaces, and the front follows the
//! costs given. (The picture is tested with the tools that draw it,
//! `tools/tests/chart_svg.rs`.) Costs are passed in, so that these tests
//! neither time anything nor depend on the machine's speed.

use std::num::NonZeroUsize;

use speclab_cli::report;
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::scene::{Depth, builtin_lights, builtin_surfaces};
use speclab_study::evaluate::trials;
use speclab_study::planning::chart::{self, Point};
use speclab_study::planning::cost::{Config, Cost};

/// A made-up cost model: ns grow with the wavelengths looked at.
fn model(config: Config) -> Result<Cost, speclab_study::StudyError> {
    let evaluations = config.method.evaluations(config.count) as f64;
    Ok(Cost { per_estimate_ns: 5.0 + 2.0 * evaluations, preparation_ns: 1.0 })
}

/// Real points for the three lights: the reference and both bucket rules
/// (deterministic, so quick), over two patches.
fn points() -> Vec<Point> {
    let surfaces = &builtin_surfaces()[..2];
    let methods = [Method::Reference, Method::CENTER, Method::BOX];
    let trials = NonZeroUsize::new(2).unwrap();
    builtin_lights()
        .iter()
        .flat_map(|l| chart::points_with_costs(l, surfaces, &methods, Depth::ONE, trials, 1, model).unwrap())
        .collect()
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
    let ns = header.iter().position(|h| *h == "ns_per_estimate").unwrap();
    for (row, p) in rows.iter().zip(&points) {
        assert_eq!(row.len(), header.len());
        assert_eq!((row[0], row[1]), (p.light.as_str(), p.config.method.to_string().as_str()));
        assert_eq!(row[header.len() - 1], p.pareto.to_string());
        // The costs given are the costs charted.
        assert_eq!(row[ns], model(p.config).unwrap().per_estimate_ns.to_string());
    }
    // On the front, no other point of the light is both cheaper and more
    // accurate; off it (the reference aside), some point is.
    for p in points.iter().filter(|p| p.config.method != Method::Reference) {
        let beaten = points.iter().any(|q| {
            q.light == p.light
                && q.config.method != Method::Reference
                && q.cost.per_estimate_ns <= p.cost.per_estimate_ns
                && q.worst_rms <= p.worst_rms
                && (q.cost.per_estimate_ns < p.cost.per_estimate_ns || q.worst_rms < p.worst_rms)
        });
        assert_eq!(p.pareto, !beaten, "{} {}", p.light, p.config);
    }
    // Each light has a front, and the reference is never on it.
    for light in ["A", "D65", "F11"] {
        let front = rows.iter().filter(|r| r[0] == light && r[header.len() - 1] == "true");
        assert!(front.clone().count() >= 2, "{light}");
        assert!(front.clone().all(|r| r[1] != "reference"), "{light}");
    }
}

#[test]
fn worst_and_mean_are_over_the_surfaces() {
    let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
    let (f11, surfaces) = (&lights[2], &surfaces[..2]);
    let trials = NonZeroUsize::new(2).unwrap();
    let points =
        chart::points_with_costs(f11, surfaces, &[Method::BOX], Depth::ONE, trials, 1, model).unwrap();
    for p in &points[..8] {
        let rms: Vec<f64> = surfaces
            .iter()
            .map(|s| {
                let stats = trials::method(f11, &s.spectrum, Method::BOX, p.config.count, trials, 1);
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
