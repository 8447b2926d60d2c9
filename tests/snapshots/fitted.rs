//! The fitted rules of this version, as a regression snapshot (numbers this
//! project computed, not published truth): a change to the prior, the
//! weighting or the search that moves a rule fails here first.

use speclab::Spectrum;
use speclab::data::lights;
use speclab::sampling::rule::Rule;

/// Regression snapshot (computed by this code, not published): the rules
/// the README and the render survey report on. Any change to the prior,
/// the row weights, the anchors or the search moves them; if one is meant
/// to, rerun what the README quotes and update these.
#[test]
fn the_rules_are_a_regression_snapshot() {
    let close_to = |got: &[f64], want: &[f64]| {
        got.len() == want.len() && got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1e-6 * w.abs())
    };
    let f11 = Rule::fit(&[&lights::F11], 10).unwrap();
    assert_eq!(f11.lambda(), [429.0, 445.0, 466.0, 485.0, 509.0, 540.0, 551.0, 586.0, 611.0, 633.0]);
    let (w, scale) = f11.weights();
    assert_eq!(scale, 1.0);
    let x =
        [13.00822, 9.812318, 4.741065, 0.6793828, 2.243184, 2.903420, 6.752661, 18.76972, 11.26702, 18.39936];
    let y = [
        0.3193335, 1.191911, 0.4402047, 3.195287, 19.04704, 9.797146, 15.06794, 15.18955, 5.547528, 7.574152,
    ];
    let z = [
        58.04105,
        55.91513,
        25.23981,
        8.785503,
        10.05414,
        0.1469434,
        0.1872255,
        0.01249730,
        0.01542283,
        -0.07447691,
    ];
    assert!(close_to(&w[0], &x) && close_to(&w[1], &y) && close_to(&w[2], &z), "{w:?}");
    let each = Rule::fit_each(&[&lights::F11 as &dyn Spectrum, &lights::A], 8).unwrap();
    assert_eq!(each[0].lambda(), [434.0, 462.0, 491.0, 518.0, 546.0, 581.0, 612.0, 649.0]);
    let a_y = [0.8385893, 0.7190702, 6.329853, 18.43345, 32.44116, 27.62482, 15.13972, 5.413732];
    assert!(close_to(&each[1].weights().0[1], &a_y), "{:?}", each[1].weights().0[1]);
    assert_eq!(Rule::fit(&[&lights::D65], 6).unwrap().lambda(), [437.0, 474.0, 517.0, 559.0, 599.0, 641.0]);
}
