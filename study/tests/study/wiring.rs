//! The published methods reach every place methods appear: the grid's
//! extra rows, the one-pair comparison, the chart's points and the
//! planner's candidates (measured only where they can be chosen).

use std::num::NonZeroUsize;

use speclab::data::{Light, Patch};
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::scene::{self, Depth, Named};
use speclab_study::experiments::compare::{self, CompareOptions};
use speclab_study::experiments::grid::GridOptions;
use speclab_study::planning::chart;
use speclab_study::planning::cost::Cost;
use speclab_study::planning::plan::{self, Request};
use speclab_study::published::rules::Family;

fn n(m: usize) -> NonZeroUsize {
    NonZeroUsize::new(m).unwrap()
}

#[test]
fn the_grid_appends_published_rows_with_their_own_numbers() {
    let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
    let options = GridOptions { m: n(10), ..GridOptions::default() };
    let borges = Method::Published { family: Family::Borges };
    let methods: Vec<Method> = Method::ALL.iter().copied().chain([borges]).collect();
    let rows = options.rows_of(&lights, &surfaces, &methods).unwrap();
    assert_eq!(rows.len(), 3 * 6 * 7);
    assert_eq!(options.rows(&lights, &surfaces).unwrap().len(), 3 * 6 * 6);
    for row in rows.iter().filter(|r| r.method == borges) {
        let ours = borges.xyz(&row.light.spectrum, &row.surface.spectrum, n(10), 0).unwrap();
        assert_eq!((row.xyz, row.samples), (ours, 10));
    }
}

#[test]
fn the_comparison_lists_the_published_methods_that_exist_for_the_light() {
    let (f11, g4) = (Named::from(Light::F11), Named::from(Patch::G4));
    let at = |m| {
        compare::compare(&f11, &g4, &CompareOptions { m: n(m), trials: n(2), ..CompareOptions::default() })
    };
    let labels = |m| at(m).unwrap().into_iter().map(|l| l.label).collect::<Vec<_>>();
    let ten = labels(10);
    assert_eq!(
        &ten[6..13],
        [
            "astm M=10",
            "borges M=10",
            "meyer M=10",
            "wallis M=10",
            "prefilter-xyz",
            "prefilter-srgb",
            "prefilter-sharp"
        ]
    );
    // F11 has no Borges rule of 36 wavelengths: no line, and no error.
    assert!(f11.published(Family::Borges, 36).is_err());
    let thirty_six = labels(36);
    assert!(
        thirty_six.contains(&"astm M=36".to_string()) && !thirty_six.iter().any(|l| l.starts_with("borges"))
    );
}

#[test]
fn the_chart_has_a_point_per_existing_count() {
    let f11 = Named::from(Light::F11);
    let surfaces = [Named::from(Patch::G4)];
    let borges = Method::Published { family: Family::Borges };
    let cost = |_| Ok(Cost { per_estimate_ns: 1.0, preparation_ns: 0.0 });
    let points =
        chart::points_with_costs(&f11, &surfaces, &[borges, Method::PUBLISHED[6]], Depth::ONE, n(1), 1, cost)
            .unwrap();
    let counts: Vec<usize> =
        points.iter().filter(|p| p.config.method == borges).map(|p| p.config.count.get()).collect();
    let exist: Vec<usize> = (1..=64).filter(|&m| f11.published(Family::Borges, m).is_ok()).collect();
    assert_eq!(counts, exist);
    assert!(exist.len() < 64 && exist.contains(&10));
    let prefilter: Vec<_> = points.iter().filter(|p| p.config.method == Method::PUBLISHED[6]).collect();
    assert_eq!(prefilter.len(), 1);
    assert!(prefilter[0].worst_rms < 1e-9);
}

#[test]
fn the_planner_measures_published_methods_only_where_they_can_be_chosen() {
    let surfaces = [Named::from(Patch::G4)];
    let listed = |lights: &[Named], request: &Request| {
        let plan = plan::plan(lights, &surfaces, request).unwrap();
        plan.chosen.iter().chain(&plan.runners_up).chain(&plan.others).any(|c| c.config.method.is_published())
    };
    let one = [Named::from(Light::F11)];
    let two = [Named::from(Light::F11), Named::from(Light::A)];
    let unbiased = Request { allow_bias: false, trials: n(20), ..Request::default() };
    let biased = Request { trials: n(20), ..Request::default() };
    assert!(listed(&one, &biased));
    // A rule that does not exist at its M is above budget, not an error.
    use speclab_study::planning::cost::Config;
    use speclab_study::planning::plan::Verdict;
    let borges36 = [(
        Config::new(Method::Published { family: Family::Borges }, n(36)),
        Cost { per_estimate_ns: 1.0, preparation_ns: 0.0 },
    )];
    let judged = plan::plan_with_costs(&one, &surfaces, &biased, &borges36).unwrap();
    assert!(
        matches!(&judged.others[0].verdict, Verdict::Above { worst, cell } if worst.is_nan() && cell.contains("no borges rule of 36"))
    );
    assert!(!listed(&one, &unbiased));
    assert!(!listed(&two, &biased));
}

/// The fitted tables' published columns are each family's worst over the
/// surfaces, the same number the comparison table reads, `None` below a
/// family's smallest M and where it has no rule.
#[test]
fn the_fitted_tables_carry_each_published_rule_worst() {
    use speclab_study::experiments::rules;
    use speclab_study::published::compare::{self as table, Candidate};
    let (light, surfaces) = (Named::from(Light::F11), scene::builtin_surfaces());
    let rows = rules::by_m(&light, &surfaces, Depth::ONE).unwrap();
    for m in [6, 10, 16] {
        let row = &rows[m - 1];
        let candidates = Family::ALL.map(|f| Candidate::Published(f, m));
        let expected =
            table::table(std::slice::from_ref(&light), &surfaces, &candidates, Depth::ONE).unwrap();
        for (got, want) in row.published.iter().zip(&expected) {
            let want = want.per_light[0];
            match got {
                Some(got) => assert!((got - want).abs() <= 1e-12, "M = {m}, {}: {got} vs {want}", want),
                None => assert!(want.is_nan(), "M = {m}: {want}"),
            }
        }
    }
    // ASTM takes four wavelengths, Wallis three: none below.
    assert_eq!(rows[2].published[0], None);
    assert!(rows[2].published[3].is_some() && rows[1].published[3].is_none());
    // Borges has no rule of 64 shared nodes under F11.
    assert_eq!(rows[63].published[1], None);
    assert!(rows[63].published[0].is_some());
}

/// The textured scene renders the same image, bit for bit, whether its
/// colours are looked up at each hit or converted once (the same albedos,
/// read at different times), and neither is the dense scene's.
#[test]
fn converted_texels_render_what_lookups_render() {
    use speclab_study::render::{Options, Setup, run};
    let setup = Setup::new(&[Named::from(Light::F11)]).expect("a scene");
    let o = Options {
        width: 8,
        height: 8,
        spp: 2,
        dense: true,
        single: true,
        threads: 1,
        rgb_space: Some("ACEScg"),
        ..Options::default()
    };
    let (looked_up, _) = run::against_exact(&o, &setup).expect("a render");
    let (converted, _) = run::against_exact(&Options { rgb_converted: true, ..o }, &setup).expect("a render");
    assert_eq!(looked_up.xyz, converted.xyz);
    let (dense, _) = run::against_exact(&Options { rgb_space: None, ..o }, &setup).expect("a render");
    assert_ne!(dense.xyz, looked_up.xyz);
}
