//! The planner: its choice does not hang on the seed, it holds when measured
//! again, it never takes a bucket count that is within budget by luck, and
//! it refuses bad requests.
//!
//! Costs are measured once per light and shared by the plans compared, so
//! that timing noise (which may reorder configurations of near-equal cost)
//! is not mistaken for seed dependence.

#![cfg(feature = "study")]

use std::num::NonZeroUsize;

use speclab::Error;
use speclab::study::cost::{Config, Cost};
use speclab::study::method::Method;
use speclab::study::plan::{self, Request, Verdict};
use speclab::study::scene::{Named, builtin_lights, builtin_surfaces};
use speclab::study::trials;

fn request(seed: u64) -> Request {
    Request { seed, ..Request::default() }
}

/// The light with this name, alone.
fn light(name: &str) -> Vec<Named> {
    builtin_lights().into_iter().filter(|l| l.name == name).collect()
}

#[test]
fn the_choice_does_not_depend_on_the_seed_and_holds_when_measured_again() {
    let surfaces = builtin_surfaces();
    for lights in [light("A"), light("D65"), light("F11")] {
        let costs = plan::costs(&lights[0], &surfaces[0]).unwrap();
        let first = plan::plan_with_costs(&lights, &surfaces, &request(1), &costs).unwrap();
        let second = plan::plan_with_costs(&lights, &surfaces, &request(2), &costs).unwrap();
        let chosen = first.chosen.as_ref().expect("the built-in lights can be planned for").config;
        assert_eq!(second.chosen.map(|c| c.config), Some(chosen), "{}", lights[0].name);
        // Measured again by the study, with another seed and more trials.
        let t = NonZeroUsize::new(1000).unwrap();
        for s in &surfaces {
            let stats =
                trials::method(&lights[0].spectrum, &s.spectrum, chosen.method, chosen.count, t, 77).unwrap();
            assert!(
                stats.rms_de00 <= 1.0,
                "{} × {}: {chosen} gives {}",
                lights[0].name,
                s.name,
                stats.rms_de00
            );
        }
    }
}

#[test]
fn under_f11_no_bucket_count_within_budget_by_luck_is_chosen() {
    let (lights, surfaces) = (light("F11"), builtin_surfaces());
    let costs = plan::costs(&lights[0], &surfaces[0]).unwrap();
    let plan = plan::plan_with_costs(&lights, &surfaces, &request(1), &costs).unwrap();
    // Box M = 22 is below ΔE00 1 but M = 23 is not: unstable, not chosen.
    let box22 =
        plan.others.iter().find(|c| c.config.method == Method::RegularBox && c.config.count.get() == 22);
    match box22.map(|c| &c.verdict) {
        Some(Verdict::Unstable { worst, m }) => assert!(*worst < 1.0 && *m == 23, "{worst} {m}"),
        other => panic!("box M = 22: {other:?}"),
    }
    for c in plan.chosen.iter().chain(&plan.runners_up) {
        let (method, m) = (c.config.method, c.config.count.get());
        assert!(method != Method::RegularBox || m >= 39, "box M = {m} is above budget again at a larger M");
        assert!(method != Method::RegularCentre || m >= 62, "centre M = {m} is erratic under F11");
    }
}

#[test]
fn without_bias_no_bucket_is_chosen() {
    let (lights, surfaces) = (light("D65"), builtin_surfaces());
    let costs = plan::costs(&lights[0], &surfaces[0]).unwrap();
    let unbiased = Request { allow_bias: false, ..Request::default() };
    let plan = plan::plan_with_costs(&lights, &surfaces, &unbiased, &costs).unwrap();
    let chosen = plan.chosen.expect("hero reaches ΔE00 1 under D65");
    assert!(chosen.config.method.is_random(), "{}", chosen.config);
    let biased = |c: &&plan::Candidate| !c.config.method.is_random() && c.verdict != Verdict::NotTried;
    assert!(plan.others.iter().filter(biased).all(|c| c.verdict == Verdict::Biased));
}

#[test]
fn bad_requests_are_errors() {
    let (lights, surfaces) = (light("A"), builtin_surfaces());
    assert!(matches!(plan::plan(&[], &surfaces, &Request::default()), Err(Error::EmptyScene)));
    assert!(matches!(plan::plan(&lights, &[], &Request::default()), Err(Error::EmptyScene)));
    for budget in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let err = plan::plan(&lights, &surfaces, &Request { budget, ..Request::default() }).unwrap_err();
        assert!(matches!(err, Error::Budget { .. }), "{budget}: {err}");
        assert!(err.to_string().starts_with("expected a finite positive ΔE00 budget, found"), "{err}");
    }
}

/// Hand-made costs, so that the order of the candidates is fixed.
fn costs(configs: &[(Method, usize)]) -> Vec<(Config, Cost)> {
    let cost = |i: usize| Cost { per_estimate_ns: 1.0 + i as f64, preparation_ns: 0.0 };
    configs
        .iter()
        .enumerate()
        .map(|(i, &(m, n))| (Config::new(m, NonZeroUsize::new(n).unwrap()), cost(i)))
        .collect()
}

#[test]
fn buckets_are_judged_at_every_larger_count() {
    // Under A, centre buckets are below ΔE00 1 at M = 11 and 12, above at
    // 13, and below from 14 on (the README's table): 11 is unstable.
    let (lights, surfaces) = (light("A"), builtin_surfaces());
    let two = costs(&[(Method::RegularCentre, 11), (Method::RegularCentre, 14)]);
    let plan = plan::plan_with_costs(&lights, &surfaces, &request(1), &two).unwrap();
    assert!(matches!(plan.others[0].verdict, Verdict::Unstable { worst, m: 13 } if worst < 1.0));
    let chosen = plan.chosen.unwrap();
    assert_eq!((chosen.config.method, chosen.config.count.get()), (Method::RegularCentre, 14));
    // A budget equal to the worst value is met: within means ≤.
    let at64 = costs(&[(Method::RegularCentre, 64)]);
    let plan = plan::plan_with_costs(&lights, &surfaces, &request(1), &at64).unwrap();
    let Some(Verdict::Within { worst }) = plan.chosen.map(|c| c.verdict) else { panic!("M = 64 within 1") };
    let tight = Request { budget: worst, ..request(1) };
    let plan = plan::plan_with_costs(&lights, &surfaces, &tight, &at64).unwrap();
    assert!(matches!(plan.chosen.map(|c| c.verdict), Some(Verdict::Within { worst: w }) if w == worst));
}
