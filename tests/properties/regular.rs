//! Regular buckets are exactly the Riemann sums `W/M · Σ valueᵢ · c̄ᵢ`: the
//! compile-time type `RegularSpectrum<M, B>` against sums written out here
//! from the definitions, and the run-time `Rule::buckets` (its weights
//! computed when made, its values on slices) against the compile-time
//! type, to rounding (the compile-time sum runs four lanes wide, fused
//! where the build has FMA; the run-time one keeps the study's order).
//! Bucket values carry a path's throughput with the same arithmetic as
//! sampled spectra.

use speclab::data::cie1931::{X_BAR, Y_BAR, Z_BAR};
use speclab::data::{Light, Patch, lights, patches};
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::rule::{MAX_M, Rule};
use speclab::spectrum::observer;
use speclab::{BoxAverage, Center, RegularSpectrum, Xyz};

/// Sums are rearranged (in another order, four lanes wide, with the width
/// folded into the weights): allow f64 rounding only.
const ROUNDING: f64 = 1e-14;

fn close(a: Xyz, b: Xyz) -> bool {
    let scale = b.x.abs() + b.y.abs() + b.z.abs();
    let d = a - b;
    d.x.abs() + d.y.abs() + d.z.abs() <= ROUNDING * scale
}

fn check<const M: usize>() {
    let width = 350.0 / M as f64;
    let (center, boxed) =
        (Rule::buckets(M, BucketRule::Center).unwrap(), Rule::buckets(M, BucketRule::BoxAverage).unwrap());
    for light in Light::APPENDIX {
        for patch in Patch::ALL {
            let (l, s) = (light.spectrum(), patch.spectrum());
            // Center: values at λᵢ = 380 + (i + ½)·W/M; box: means over buckets.
            let mut center_sum = Xyz::ZERO;
            let mut box_sum = Xyz::ZERO;
            for i in 0..M {
                let lambda = 380.0 + (i as f64 + 0.5) * width;
                center_sum +=
                    Xyz::from(observer::xyz_bar(lambda)) * (l.eval(lambda) * s.eval(lambda) * width);
                let (a, b) = (380.0 + i as f64 * width, 380.0 + (i + 1) as f64 * width);
                let cmf = Xyz::new(X_BAR.mean(a, b), Y_BAR.mean(a, b), Z_BAR.mean(a, b));
                box_sum += cmf * (l.mean(a, b) * s.mean(a, b) * width);
            }
            let c = (RegularSpectrum::<M, Center>::center(l) * RegularSpectrum::center(s)).to_xyz();
            let b =
                (RegularSpectrum::<M, BoxAverage>::box_average(l) * RegularSpectrum::box_average(s)).to_xyz();
            assert!(close(c, center_sum), "M = {M} {light} {patch}: {c:?} vs {center_sum:?}");
            assert!(close(b, box_sum), "M = {M} {light} {patch}: {b:?} vs {box_sum:?}");
            assert!(close(center.xyz(l, s), c), "M = {M} {light} {patch}: run-time center");
            assert!(close(boxed.xyz(l, s), b), "M = {M} {light} {patch}: run-time box");
        }
    }
}

#[test]
fn riemann_sums_for_several_m() {
    check::<1>();
    check::<8>();
    check::<16>();
    check::<45>();
    check::<64>();
}

#[test]
fn unsupported_bucket_counts_are_errors() {
    for m in [0, MAX_M + 1, usize::MAX] {
        let err = Rule::buckets(m, BucketRule::Center).unwrap_err();
        assert_eq!(err.to_string(), format!("expected a bucket count from 1 to 64, found {m}"));
    }
    let one = Rule::buckets(1, BucketRule::BoxAverage).unwrap();
    assert_eq!((one.m(), one.lambda()), (1, &[555.0][..]));
    // A factor shorter than M counts as 0 where it has no value.
    let three = Rule::buckets(3, BucketRule::Center).unwrap();
    let full = three.xyz_of_factors(&[&[1.0, 1.0, 1.0]]);
    let short = three.xyz_of_factors(&[&[1.0, 1.0, 1.0], &[1.0, 1.0]]);
    assert!(short.y < full.y && short.y > 0.0);
}

/// A path's throughput in buckets, as with sampled spectra: two bounces off
/// the patch, seen through the light, and the shared arithmetic.
#[test]
fn buckets_carry_a_throughput() {
    type R = RegularSpectrum<16, Center>;
    let (le, albedo) = (R::center(&lights::D65), R::center(&patches::G4));
    let (mut beta, mut l) = (R::splat(1.0), R::zero());
    for _bounce in 0..2 {
        beta *= albedo;
        l += beta * le;
    }
    let by_hand = R::from_values(std::array::from_fn(|i| {
        let (a, e) = (albedo.values()[i], le.values()[i]);
        a * e + a * a * e
    }));
    assert_eq!(l, by_hand);
    assert!(l.to_xyz().y > (albedo * le).to_xyz().y);
    assert_eq!((2.0 * albedo - albedo) / 1.0, albedo);
    assert_eq!(-(-le), le);
    assert_eq!(albedo.clamp(0.0, 0.1).max_value(), 0.1);
    assert!(albedo.safe_div(R::zero()).is_black());
    assert_eq!(albedo.lerp(le, 0.0), albedo);
    assert_eq!(R::default(), R::zero());
    assert_eq!([albedo, albedo].into_iter().sum::<R>(), albedo * 2.0);
    assert!(albedo.min_value() >= 0.0 && albedo.average() > albedo.min_value());
    let mut v = albedo;
    v[0] = 2.0;
    assert_eq!(v[0], 2.0);
}
