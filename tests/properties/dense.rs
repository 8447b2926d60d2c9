//! Dense tables against their sources: every whole nanometre exact (f64)
//! or rounded (f32), steps between, zero outside 380–730 nm, the largest
//! point-wise error and the error of the exact integrals (the bounds the
//! documentation of `spectrum::dense` states, measured here), and the
//! dense observer equal to dense tables of x̄, ȳ, z̄.

use speclab::data::{Light, Patch, cie1931, lights, patches};
use speclab::sampling::reference;
use speclab::spectrum::observer::xyz_bar;
use speclab::spectrum::{AssignmentObserver, DenseObserver, DenseSpectrum, Observer};
use speclab::{Spectrum, Xyz};

/// The largest |dense − source| every 0.01 nm over 380–730 nm.
fn worst(source: &dyn Spectrum, dense: &DenseSpectrum) -> f64 {
    (0..=35_000)
        .map(|i| 380.0 + f64::from(i) * 0.01)
        .map(|l| (dense.eval(l) - source.eval(l)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn whole_nanometres_are_the_source() {
    for s in [&lights::F11 as &dyn Spectrum, &patches::G4, &cie1931::Z_BAR] {
        let d64 = DenseSpectrum::new(s);
        let (f64s, f32s) = (d64.values::<f64>(), d64.values::<f32>());
        for i in 0..=470 {
            let l = 360.0 + f64::from(i);
            assert_eq!(d64.eval(l), s.eval(l), "{l}");
            // The f32 table, what f32 wavelengths read, is the f64 one rounded.
            assert_eq!((f64s[i as usize], f32s[i as usize]), (s.eval(l), s.eval(l) as f32), "{l}");
            let mut one = [0.0f32];
            d64.eval_many_f32(&[l as f32], &mut one);
            assert_eq!(one[0], s.eval(l) as f32, "{l}");
            // A step: the same value to either side, up to half a
            // nanometre (within 360–830 nm).
            assert_eq!(d64.eval((l - 0.49).max(360.0)), d64.eval(l));
            assert_eq!(d64.eval((l + 0.49).min(830.0)), d64.eval(l));
        }
        assert_eq!((f64s.len(), f32s.len()), (471, 471));
    }
}

/// The point-wise errors the documentation states (measured: patches
/// 0.0137, observer 0.0404, F11 4.56 of its 72.84 peak).
#[test]
fn point_wise_errors_within_the_stated_bounds() {
    let patch = Patch::ALL.iter().map(|p| worst(p.spectrum(), &DenseSpectrum::new(p.spectrum())));
    let patch = patch.fold(0.0, f64::max);
    let cmf = [&cie1931::X_BAR, &cie1931::Y_BAR, &cie1931::Z_BAR].map(|c| worst(c, &DenseSpectrum::new(c)));
    let cmf = cmf.into_iter().fold(0.0, f64::max);
    let f11 = worst(&lights::F11, &DenseSpectrum::new(&lights::F11));
    eprintln!("largest point-wise errors: patches {patch:.4}, observer {cmf:.4}, F11 {f11:.3}");
    assert!(patch <= 0.014 && cmf <= 0.041 && f11 <= 4.6, "{patch} {cmf} {f11}");
    assert!(patch > 0.005 && f11 > 1.0, "steps are steps: {patch} {f11}");
}

/// The error the estimates see: the exact XYZ of a dense light times a
/// dense patch against the tables', the largest over the six patches
/// relative to each channel (measured: A 8.1e-5, D65 6.4e-5, F11 9.3e-5;
/// the f32 tables are these rounded, `whole_nanometres_are_the_source`).
#[test]
fn integrals_within_the_stated_error() {
    let mut worst_by_light = Vec::new();
    for light in Light::APPENDIX {
        let mut largest = 0.0f64;
        for patch in Patch::ALL {
            let (l, s) = (light.spectrum(), patch.spectrum());
            let exact = reference::xyz(l, s).to_array();
            let dense = reference::xyz(&DenseSpectrum::new(l), &DenseSpectrum::new(s));
            for (d, e) in dense.to_array().iter().zip(exact) {
                largest = largest.max((d - e).abs() / e);
            }
        }
        eprintln!("{light}: largest relative error of a dense pair's exact XYZ {largest:.2e}");
        worst_by_light.push(largest);
    }
    assert!(worst_by_light.iter().all(|&e| e <= 1e-4), "{worst_by_light:?}");
}

#[test]
fn zero_outside_the_range() {
    let d = DenseSpectrum::new(&lights::D65);
    for l in [359.999, 830.001, f64::NAN, f64::NEG_INFINITY, f64::INFINITY] {
        assert_eq!(d.eval(l), 0.0, "{l}");
    }
    assert!(d.eval(380.0) > 0.0 && d.eval(780.0) > 0.0 && d.eval(781.0) == 0.0, "D65's table: 380–780 nm");
    let breaks = d.pieces().expect("steps").breaks;
    assert_eq!((breaks.len(), breaks[0], breaks[1], breaks[471]), (472, 360.0, 360.5, 830.0));
    let at = [f64::NAN, 359.0, 831.0];
    // No weight outside, and the pdf's column kept.
    assert_eq!(DenseObserver::new().xyz_bar_at(&at), [[0.0, 0.0, 0.0, 1.0]; 3]);
}

/// The dense observer is the dense tables of x̄, ȳ, z̄ in one row, in
/// either precision, and the exact observer at whole nanometres.
#[test]
fn the_dense_observer_is_dense_tables() {
    let tables = [&cie1931::X_BAR, &cie1931::Y_BAR, &cie1931::Z_BAR].map(DenseSpectrum::new);
    let (d64, d32) = (DenseObserver::new(), DenseObserver::new()); // one observer, read in either precision
    for i in 0..=3500 {
        let l = 380.0 + f64::from(i) * 0.1;
        let [row] = d64.xyz_bar_at(&[l]);
        assert_eq!(row, [tables[0].eval(l), tables[1].eval(l), tables[2].eval(l), 1.0], "{l}");
        let [row32] = d32.xyz_bar_at(&[l as f32]);
        for c in 0..3 {
            assert!((f64::from(row32[c]) - row[c]).abs() <= 1e-7 * row[c].max(1e-3), "{l}");
        }
    }
    let whole = [455.0, 555.0];
    assert_eq!(d64.xyz_bar_at(&whole), AssignmentObserver.xyz_bar_at(&whole));
}

/// Steps integrate exactly: the reference of two dense tables equals a
/// 0.001 nm midpoint sum.
#[test]
fn dense_tables_integrate_exactly() {
    let (l, s) = (DenseSpectrum::new(&lights::F11), DenseSpectrum::new(&patches::G4));
    let exact = reference::xyz(&l, &s);
    let h = 0.001;
    let mut sum = Xyz::ZERO;
    for i in 0..350_000 {
        let x = 380.0 + (f64::from(i) + 0.5) * h;
        sum += Xyz::from(xyz_bar(x)) * (l.eval(x) * s.eval(x) * h);
    }
    let gap = (exact - sum).to_array().iter().fold(0.0f64, |m, d| m.max(d.abs()));
    assert!(gap < 1e-6 * exact.y, "{exact:?} vs {sum:?}");
}
