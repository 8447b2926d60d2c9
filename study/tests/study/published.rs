//! The published rules against what they promise: ASTM's weights against
//! a published E308 table and against Appendix 2, each quadrature's degree
//! of exactness, prefiltering exact at one bounce.

use speclab::data::{Light, lights, patches};
use speclab::sampling::reference;
use speclab::spectrum::Spectrum;
use speclab::spectrum::observer::xyz_bar;
use speclab_study::evaluate::scene::{self, Depth, Named};
use speclab_study::published::compare::{self, Candidate};
use speclab_study::published::gauss::{Measure, to_t};
use speclab_study::published::prefilter::Space;
use speclab_study::published::rules::{Family, astm_interval};

/// ASTM E308-15's weighting factors for CIE D65, the 1931 observer, 20 nm
/// (360–830 nm rows; 380 nm first here), as reproduced by colour-science's
/// tests (`TWF_D65_CIE_1931_2_20`).
const E308_D65_2_20: [[f64; 3]; 18] = [
    [-0.008, -0.000, -0.039],
    [0.179, 0.002, 0.829],
    [2.542, 0.071, 12.203],
    [6.670, 0.453, 33.637],
    [6.333, 1.316, 36.334],
    [2.213, 2.933, 18.278],
    [0.052, 6.866, 5.543],
    [1.348, 14.106, 1.611],
    [5.767, 18.981, 0.382],
    [11.301, 18.863, 0.068],
    [16.256, 15.455, 0.025],
    [17.933, 10.699, 0.013],
    [14.020, 6.277, 0.003],
    [7.057, 2.743, 0.000],
    [2.527, 0.927, -0.000],
    [0.670, 0.242, -0.000],
    [0.140, 0.050, 0.000],
    [0.035, 0.013, 0.000],
];

#[test]
fn astm_weights_at_20_nm_reproduce_the_e308_table_away_from_the_ends() {
    // Normalised as the table (k = 100/Y of the white). The ends differ:
    // the table spans 360–830 nm and folds what lies beyond its rows into
    // them, speclab integrates 380–730 nm.
    let rule = Family::Astm.rule(&lights::CIE_D65, 18).unwrap();
    assert_eq!((astm_interval(18), rule.lambda()[0], rule.lambda()[17]), (20.0, 380.0, 720.0));
    let k = 100.0 / reference::white(&lights::CIE_D65).y;
    let (w, _) = rule.weights();
    for (i, row) in E308_D65_2_20.iter().enumerate().filter(|(i, _)| (3..=14).contains(i)) {
        for c in 0..3 {
            let ours = w[c][i] * k;
            assert!(
                (ours - row[c]).abs() <= 0.01,
                "{} nm, channel {c}: {ours} against {}",
                380 + 20 * i,
                row[c]
            );
        }
    }
}

#[test]
fn astm_at_10_nm_is_appendix_2_for_its_10_nm_patches() {
    for light in Light::APPENDIX {
        let rule = Family::Astm.rule(light.spectrum(), 36).unwrap();
        for (_, patch) in patches::ALL {
            let (ours, exact) = (rule.xyz_of_product(&[patch]), reference::xyz(light.spectrum(), patch));
            assert!((ours.y - exact.y).abs() <= 1e-9 * exact.y && (ours.z - exact.z).abs() <= 1e-9 * exact.z);
        }
    }
}

#[test]
fn astm_extrapolates_its_last_cubic_to_730_nm() {
    // A cubic reflectance: every cubic interpolant of its samples is the
    // cubic itself, extrapolated too, so ASTM is exact for it at every M,
    // including those whose last sample falls short of 730 nm.
    let cubic = |l: f64| {
        let t = (l - 555.0) / 175.0;
        0.5 + 0.2 * t - 0.1 * t * t + 0.15 * t * t * t
    };
    let lambda: Vec<f64> = (380..=730).map(f64::from).collect();
    let values = lambda.iter().map(|&l| cubic(l)).collect();
    let r = speclab::TabulatedSpectrum::new(lambda, values, speclab::Role::Reflectance).unwrap();
    for light in [&lights::D65, &lights::F11] {
        let exact = reference::xyz(light, &r);
        for m in [18, 37, 52, 60] {
            let rule = Family::Astm.rule(light, m).unwrap();
            assert!(rule.lambda()[m - 1] < 730.0);
            let ours = rule.xyz_of_product(&[&r]);
            for (o, e) in ours.to_array().into_iter().zip(exact.to_array()) {
                assert!((o - e).abs() <= 1e-9 * e, "M = {m}: {o} against {e}");
            }
        }
    }
}

/// `∫ f·w꜀` and a rule's `Σ w꜀ᵢ·f(λᵢ)` for channel `c` of `light`.
fn both(family: Family, light: &dyn Spectrum, m: usize, c: usize, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let w = Measure::new(|l| light.eval(l) * xyz_bar(l)[c]);
    let exact = w.integrate(&w.points().iter().map(|&t| f(t)).collect::<Vec<_>>());
    let rule = family.rule(light, m).unwrap();
    let (weights, _) = rule.weights();
    let sum = rule.lambda().iter().zip(&weights[c]).map(|(&l, w)| w * f(to_t(l))).sum();
    (exact, sum)
}

#[test]
fn each_quadrature_is_exact_to_its_degree() {
    let light: &dyn Spectrum = &lights::D65;
    let power = |k: i32| move |t: f64| (t + 0.3).powi(k);
    // Wallis: a 3-point Gauss rule per channel, degree 5. Borges: 9 shared
    // nodes (degree 8 for any channel) and 3 more degrees for each.
    for (family, m, c, degree) in
        [(Family::Wallis, 9, 1, 5), (Family::Borges, 9, 1, 11), (Family::Borges, 9, 2, 11)]
    {
        for k in [degree - 1, degree] {
            let (exact, sum) = both(family, light, m, c, power(k));
            assert!((sum - exact).abs() <= 1e-9 * exact.abs(), "{family} degree {k}: {sum} against {exact}");
        }
        let (exact, sum) = both(family, light, m, c, power(degree + 1));
        assert!((sum - exact).abs() > 1e-7 * exact.abs(), "{family}: exact beyond its degree?");
    }
    // Meyer's rule is Gauss for L·s̄ (s̄ = x̄ + ȳ + z̄), its Y weights
    // carrying ȳ/s̄: Σ w_Yᵢ·g(tᵢ)·s̄/ȳ(λᵢ) is ∫ g·L·s̄ for g of degree 2·6 − 1.
    let sum = Measure::new(|l| light.eval(l) * xyz_bar(l).iter().sum::<f64>());
    let rule = Family::Meyer.rule(light, 6).unwrap();
    for (c, k) in [(1, 10), (1, 11), (1, 12), (0, 11), (0, 12)] {
        let g = |t: f64| (t + 0.3).powi(k);
        let exact = sum.integrate(&sum.points().iter().map(|&t| g(t)).collect::<Vec<_>>());
        let (w, _) = rule.weights();
        let ours: f64 = rule
            .lambda()
            .iter()
            .zip(&w[c])
            .map(|(&l, w)| w * g(to_t(l)) * xyz_bar(l).iter().sum::<f64>() / xyz_bar(l)[c])
            .sum();
        let close = (ours - exact).abs() <= 1e-9 * exact.abs();
        assert_eq!(close, k < 12, "meyer channel {c}, degree {k}: {ours} against {exact}");
    }
}

#[test]
fn prefiltering_is_exact_at_one_bounce_and_not_at_two() {
    let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
    let candidates = Space::ALL.map(Candidate::Prefiltered);
    for row in compare::table(&lights, &surfaces, &candidates, Depth::ONE).unwrap() {
        assert!(row.worst < 1e-9 && row.pairs == 18, "{}: {}", row.candidate, row.worst);
    }
    let two = Depth::new(2).unwrap();
    for row in compare::table(&lights, &surfaces, &candidates, two).unwrap() {
        assert!(row.worst > 0.05, "{}: {}", row.candidate, row.worst);
    }
}

#[test]
fn the_table_counts_pairs_and_reads_each_lights_worst() {
    let lights = [Named::from(Light::F11), Named::from(Light::D65)];
    let surfaces = scene::builtin_surfaces();
    let rows = compare::table(
        &lights,
        &surfaces,
        &[Candidate::Fitted(6), Candidate::Published(Family::Meyer, 6)],
        Depth::ONE,
    )
    .unwrap();
    for row in &rows {
        assert_eq!((row.pairs, row.per_light.len()), (12, 2));
        assert_eq!(row.worst, row.per_light.iter().copied().fold(0.0, f64::max));
        assert!(row.mean > 0.0 && row.mean < row.worst && row.above_one <= 12);
    }
    assert_eq!(rows[1].candidate.to_string(), "meyer");
    assert!(compare::table(&[], &surfaces, &[Candidate::Fitted(6)], Depth::ONE).is_err());
    assert!(Family::Astm.rule(&lights::D65, 3).is_err() && Family::Wallis.rule(&lights::D65, 65).is_err());
}

#[test]
fn the_published_methods_run_wherever_methods_run() {
    use speclab_study::evaluate::method::Method;
    use std::num::NonZeroUsize;
    let n = |m| NonZeroUsize::new(m).unwrap();
    let astm: Method = "astm".parse().unwrap();
    assert!(astm.is_fixed() && !astm.is_random() && astm.counts(64) == (4..=64).collect::<Vec<_>>());
    for (_, patch) in patches::ALL {
        let (ours, exact) =
            (astm.xyz(&lights::A, patch, n(36), 1).unwrap(), reference::xyz(&lights::A, patch));
        assert!((ours.y - exact.y).abs() <= 1e-9 * exact.y);
    }
    let sharp: Method = "PREFILTER-SHARP".parse().unwrap();
    assert_eq!((sharp.counts(64), sharp.reported_samples(n(16)), sharp.evaluations(n(16))), (vec![3], 3, 3));
    let once = sharp.xyz(&lights::F11, &patches::G4, n(16), 1).unwrap();
    assert!((once.y - reference::xyz(&lights::F11, &patches::G4).y).abs() < 1e-9 * once.y);
    // In XYZ (A = I) a surface's numbers are XYZ(L·ρ) ⊘ XYZ(L), so two
    // bounces give XYZ(L·ρ)² ⊘ XYZ(L), channel by channel.
    let xyz_space: Method = "prefilter-xyz".parse().unwrap();
    let f11 = Named::from(Light::F11);
    let twice = xyz_space.prepare(&f11).unwrap().at_depth(Depth::new(2).unwrap());
    let (once, white) = (reference::xyz(&lights::F11, &patches::G4), reference::white(&lights::F11));
    let ours = twice.xyz(&patches::G4, n(3), 1).unwrap();
    for ((o, x), w) in ours.to_array().into_iter().zip(once.to_array()).zip(white.to_array()) {
        assert!((o - x * x / w).abs() <= 1e-12 * o.abs(), "{o} against {}", x * x / w);
    }
    assert_eq!(Method::Reference.reported_samples(n(16)), 0);
    let borges = Method::Published { family: Family::Borges };
    assert_eq!(borges.to_string(), "borges");
    let config = speclab_study::planning::cost::Config::new(borges, n(12));
    assert_eq!(config.to_string(), "borges M=12");
    assert_eq!(speclab_study::planning::cost::Config::new(sharp, n(3)).to_string(), "prefilter-sharp");
}

#[test]
fn the_planner_takes_the_published_methods_for_one_light_only() {
    use speclab_study::evaluate::method::Method;
    use speclab_study::planning::cost::{Config, Cost};
    use speclab_study::planning::plan::{self, Request, Verdict};
    use std::num::NonZeroUsize;
    let n = |m| NonZeroUsize::new(m).unwrap();
    let cost = |ns| Cost { per_estimate_ns: ns, preparation_ns: 0.0 };
    let sharp = Method::PUBLISHED[6];
    let costs = [
        (Config::new(sharp, n(3)), cost(1.0)),
        (Config::new(Method::PUBLISHED[0], n(36)), cost(2.0)),
        (Config::new(Method::FITTED, n(20)), cost(3.0)),
    ];
    let surfaces = scene::builtin_surfaces();
    let one = [Named::from(Light::F11)];
    let request = Request::default();
    let at_one = plan::plan_with_costs(&one, &surfaces, &request, &costs).unwrap();
    assert_eq!(at_one.chosen.map(|c| c.config.method), Some(sharp)); // exact at one bounce
    assert_eq!(at_one.runners_up.len(), 2);
    let deeper = Request { depth: Depth::new(3).unwrap(), ..Request::default() };
    let at_three = plan::plan_with_costs(&one, &surfaces, &deeper, &costs).unwrap();
    let first = &at_three.others[0];
    assert!(first.config.method == sharp && matches!(first.verdict, Verdict::Above { .. }), "{first:?}");
    let two = [Named::from(Light::F11), Named::from(Light::A)];
    let both = plan::plan_with_costs(&two, &surfaces, &request, &costs).unwrap();
    let listed: Vec<Method> =
        both.chosen.iter().chain(&both.runners_up).chain(&both.others).map(|c| c.config.method).collect();
    assert_eq!(listed, [Method::FITTED]);
}

#[test]
fn the_table_keeps_lights_without_a_borges_rule_and_counts_pairs_above_one() {
    let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
    // No D65, A or F11 has a Borges rule of 36 with real nodes inside.
    let rows =
        compare::table(&lights, &surfaces, &[Candidate::Published(Family::Borges, 36)], Depth::ONE).unwrap();
    assert_eq!(rows[0].pairs, 0);
    assert!(rows[0].worst.is_nan() && rows[0].mean.is_nan());
    assert!(rows[0].per_light.iter().all(|w| w.is_nan()));
    // Two wavelengths are far off everywhere; prefiltering nowhere.
    let four = Depth::new(speclab_study::evaluate::scene::MAX_DEPTH).unwrap();
    let rows =
        compare::table(&lights, &surfaces, &[Candidate::Fitted(2), Candidate::Prefiltered(Space::Xyz)], four)
            .unwrap();
    // The count, recomputed pair by pair through the study's `Method`.
    let mut above = 0;
    for light in &lights {
        let fitted = speclab_study::evaluate::Method::FITTED.prepare(light).unwrap().at_depth(four);
        for s in &surfaces {
            let ours = fitted.xyz(&s.spectrum, std::num::NonZeroUsize::new(2).unwrap(), 1).unwrap();
            let exact = light.exact_at(four, &s.spectrum);
            let de = speclab_study::evaluate::perceptual::delta_e00(
                ours,
                exact,
                reference::white(&light.spectrum),
            );
            above += usize::from(de > 1.0);
        }
    }
    assert!(above > 0 && above < 18);
    assert_eq!((rows[0].above_one, rows[0].pairs, rows[0].depth), (above, 18, 4));
    let at_one =
        compare::table(&lights, &surfaces, &[Candidate::Prefiltered(Space::Xyz)], Depth::ONE).unwrap();
    assert_eq!(at_one[0].above_one, 0);
    // Another candidate's failure is an error, not a missing light.
    let black = Named::new(
        "black",
        speclab::TabulatedSpectrum::new(vec![380.0, 730.0], vec![0.0, 0.0], speclab::Role::Light).unwrap(),
    );
    assert!(compare::table(&[black], &surfaces, &[Candidate::Fitted(6)], Depth::ONE).is_err());
}

/// The oracle's rule is fitted to each light over the very surfaces the
/// table judges: each light's worst is that of
/// `FittedRules::with_surfaces(&[light], surfaces)` computed by hand, and
/// it is not the rule fitted to the prior.
#[test]
fn the_oracle_is_fitted_to_the_surfaces_it_is_judged_on() {
    use speclab::sampling::fitted::FittedRules;
    use speclab_study::evaluate::perceptual::delta_e00;
    let lights = [Named::from(Light::F11), Named::from(Light::A)];
    let surfaces = scene::builtin_surfaces();
    let candidates = [Candidate::Oracle(4), Candidate::Fitted(4), Candidate::OracleMinimax(4)];
    let rows = compare::table(&lights, &surfaces, &candidates, Depth::ONE).unwrap();
    assert_eq!(rows[0].candidate.to_string(), "oracle");
    assert_eq!(rows[2].candidate.to_string(), "oracle-minimax");
    for (i, light) in lights.iter().enumerate() {
        let own: Vec<&dyn Spectrum> = surfaces.iter().map(|s| &s.spectrum as &dyn Spectrum).collect();
        let rules = FittedRules::with_surfaces(&[&light.spectrum], &own).unwrap();
        let rule = rules.rule(4).unwrap();
        let white = reference::white(&light.spectrum);
        let worst = own
            .iter()
            .map(|&s| {
                let got = rule.xyz_of_product(&[&light.spectrum, s]);
                delta_e00(got, reference::xyz(&light.spectrum, s), white)
            })
            .fold(0.0, f64::max);
        assert!(
            (rows[0].per_light[i] - worst).abs() <= 1e-12,
            "{}: {} vs {worst}",
            light.name,
            rows[0].per_light[i]
        );
        // Fitted to these six, it serves them better than the prior's rule.
        assert!(rows[0].per_light[i] < rows[1].per_light[i], "{}", light.name);
        // Its wavelengths with Lawson's weights: minimax's own worst, and
        // lower still.
        let better = speclab_study::published::minimax::minimax(&light.spectrum, rule, &own, 100).unwrap();
        let want = speclab_study::published::minimax::worst(&light.spectrum, &better, &own);
        assert!((rows[2].per_light[i] - want).abs() <= 1e-12, "{}: {want}", light.name);
        assert!(rows[2].per_light[i] < rows[0].per_light[i], "{}", light.name);
    }
}

/// `fitted-munsell` is the rule fitted to each light over the Munsell
/// prior: each light's worst is that of
/// `FittedRules::with_surfaces(&[light], measured::prior())` (by
/// `minimax::worst`), and it is neither the generated prior's rule nor the oracle's.
#[test]
fn fitted_munsell_is_fitted_over_the_munsell_prior() {
    use speclab::sampling::fitted::FittedRules;
    use speclab_study::published::{measured, minimax};
    let lights = [Named::from(Light::F11), Named::from(Light::D65)];
    let surfaces = scene::builtin_surfaces();
    let candidates = [Candidate::FittedMunsell(6), Candidate::Fitted(6), Candidate::Oracle(6)];
    let rows = compare::table(&lights, &surfaces, &candidates, Depth::ONE).unwrap();
    assert_eq!(rows[0].candidate.to_string(), "fitted-munsell");
    let prior: Vec<&dyn Spectrum> =
        measured::prior().unwrap().iter().map(|c| &c.spectrum as &dyn Spectrum).collect();
    for (i, light) in lights.iter().enumerate() {
        let rules = FittedRules::with_surfaces(&[&light.spectrum], &prior).unwrap();
        let own: Vec<&dyn Spectrum> = surfaces.iter().map(|s| &s.spectrum as &dyn Spectrum).collect();
        let worst = minimax::worst(&light.spectrum, rules.rule(6).unwrap(), &own);
        assert!((rows[0].per_light[i] - worst).abs() <= 1e-12, "{}: {}", light.name, rows[0].per_light[i]);
        assert_ne!(rows[0].per_light[i], rows[1].per_light[i], "{}", light.name);
        assert_ne!(rows[0].per_light[i], rows[2].per_light[i], "{}", light.name);
    }
}

/// Every candidate tells its wavelength count; prefiltering has none.
#[test]
fn each_candidate_tells_its_count() {
    let counts = [
        Candidate::Fitted(4),
        Candidate::FittedMunsell(5),
        Candidate::Oracle(6),
        Candidate::OracleMinimax(7),
        Candidate::Published(Family::Borges, 8),
    ]
    .map(Candidate::m);
    assert_eq!(counts, [Some(4), Some(5), Some(6), Some(7), Some(8)]);
    assert_eq!(Candidate::Prefiltered(Space::Sharp).m(), None);
}
