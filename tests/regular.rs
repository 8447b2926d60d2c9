//! Regular buckets are exactly the Riemann sums `W/M · Σ valueᵢ · c̄ᵢ`, with
//! the compile-time observer tables equal to the run-time definitions.

use speclab::data::{CIE_X, CIE_Y, CIE_Z, Light, Patch};
use speclab::sampling::regular::{self, Rule};
use speclab::spectrum::observer;
use speclab::{BoxAverage, Centre, RegularSpectrum, Xyz};

/// Sums are rearranged (the library multiplies per bucket, then scales):
/// allow f64 rounding only.
const ROUNDING: f64 = 1e-12;

fn close(a: Xyz, b: Xyz) -> bool {
    let scale = b.x.abs() + b.y.abs() + b.z.abs();
    let d = a - b;
    d.x.abs() + d.y.abs() + d.z.abs() <= ROUNDING * scale
}

fn check<const M: usize>() {
    let width = 350.0 / M as f64;
    for light in Light::ALL {
        for patch in Patch::ALL {
            let (l, s) = (light.spectrum(), patch.spectrum());
            // Centre: values at λᵢ = 380 + (i + ½)·W/M.
            let mut centre = Xyz::ZERO;
            let mut boxed = Xyz::ZERO;
            for i in 0..M {
                let lambda = 380.0 + (i as f64 + 0.5) * width;
                centre += observer::xyz_bar(lambda) * (l.eval(lambda) * s.eval(lambda) * width);
                let (a, b) = (380.0 + i as f64 * width, 380.0 + (i + 1) as f64 * width);
                let cmf = Xyz::new(CIE_X.mean(a, b), CIE_Y.mean(a, b), CIE_Z.mean(a, b));
                boxed += cmf * (l.mean(a, b) * s.mean(a, b) * width);
            }
            let c = (RegularSpectrum::<M, Centre>::centre(l) * RegularSpectrum::centre(s)).to_xyz();
            let b =
                (RegularSpectrum::<M, BoxAverage>::box_average(l) * RegularSpectrum::box_average(s)).to_xyz();
            assert!(close(c, centre), "M = {M} {light:?} {patch:?}: {c:?} vs {centre:?}");
            assert!(close(b, boxed), "M = {M} {light:?} {patch:?}: {b:?} vs {boxed:?}");
            assert_eq!(regular::xyz_dyn(M, Rule::Centre, l, s).expect("M supported"), c);
            assert_eq!(regular::xyz_dyn(M, Rule::BoxAverage, l, s).expect("M supported"), b);
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
    for m in [0, regular::MAX_BUCKETS + 1, usize::MAX] {
        let err = regular::xyz_dyn(m, Rule::Centre, &speclab::data::A, &speclab::data::A1).unwrap_err();
        assert!(err.to_string().contains(&m.to_string()), "{err}");
    }
}
