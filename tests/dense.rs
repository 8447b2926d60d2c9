//! Dense tables against their sources: the largest error every 0.01 nm over
//! 380–730 nm for every built-in spectrum and the observer (the bounds the
//! documentation of `spectrum::dense` states), zero outside the range,
//! steps, and exact integrals of the lines.

use speclab::data::{cie1931, lights, patches};
use speclab::sampling::reference;
use speclab::spectrum::{Cie1931, DenseObserver, DenseSpectrum, Observer};
use speclab::{Spectrum, Xyz};

/// The largest |dense − source| every 0.01 nm over 380–730 nm.
fn worst(source: &dyn Spectrum, dense: &DenseSpectrum) -> f64 {
    (0..=35_000)
        .map(|i| 380.0 + f64::from(i) * 0.01)
        .map(|l| (dense.eval(l) - source.eval(l)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn built_in_spectra_within_the_stated_errors() {
    for light in [&lights::A, &lights::D65, &lights::F11] {
        let peak = light.values().iter().copied().fold(0.0, f64::max);
        let error = worst(light, &DenseSpectrum::new(light));
        assert!(error <= 1e-15 * peak, "lights are lines on whole nanometres: {error:e}");
    }
    let surfaces = [&patches::E2, &patches::F4, &patches::G4, &patches::H4, &patches::J4, &patches::A1];
    let errors: Vec<f64> = surfaces.iter().map(|s| worst(s, &DenseSpectrum::new(s))).collect();
    assert!(errors.iter().all(|&e| e <= 1.9e-4), "{errors:?}");
    assert!(errors[..5].iter().all(|&e| e <= 8e-5), "{errors:?}");
    for (cmf, bound) in [(&cie1931::X_BAR, 1.3e-4), (&cie1931::Y_BAR, 9.7e-5), (&cie1931::Z_BAR, 5.92e-4)] {
        assert!(worst(cmf, &DenseSpectrum::new(cmf)) <= bound);
    }
    // The dense observer is the dense tables of x̄, ȳ, z̄ in one row.
    let (dense, exact) = (DenseObserver::new(), Cie1931);
    let mut largest = [0.0f64; 3];
    for i in 0..=35_000 {
        let l = [380.0 + f64::from(i) * 0.01];
        let (a, b) = (dense.xyz_bar_lanes(&l)[0], exact.xyz_bar_lanes(&l)[0]);
        for c in 0..3 {
            largest[c] = largest[c].max((a[c] - b[c]).abs());
        }
    }
    assert!(largest[0] <= 1.3e-4 && largest[1] <= 9.7e-5 && largest[2] <= 5.92e-4, "{largest:?}");
}

#[test]
fn zero_outside_the_range() {
    let d = DenseSpectrum::new(&lights::D65);
    for l in [379.999, 730.001, f64::NAN, f64::NEG_INFINITY, f64::INFINITY] {
        assert_eq!(d.eval(l), 0.0, "{l}");
    }
    assert!((d.eval(730.0) - lights::D65.eval(730.0)).abs() < 1e-12);
    assert!((d.eval(380.0) - lights::D65.eval(380.0)).abs() < 1e-12);
    let knots = d.pieces().expect("lines").breaks;
    assert_eq!((knots.len(), knots[0], knots[350]), (351, 380.0, 730.0));
    let dark = DenseObserver::new().xyz_bar_lanes(&[f64::NAN, 379.0, 731.0]);
    assert_eq!(dark, [[0.0; 3]; 3]);
}

/// A dense table is lines between its knots, so its integrals are exact:
/// the reference of two dense tables equals a 0.001 nm midpoint sum.
#[test]
fn dense_tables_integrate_exactly() {
    let (l, s) = (DenseSpectrum::new(&lights::F11), DenseSpectrum::new(&patches::G4));
    let exact = reference::xyz(&l, &s);
    let h = 0.001;
    let mut sum = Xyz::ZERO;
    for i in 0..350_000 {
        let x = 380.0 + (f64::from(i) + 0.5) * h;
        let [cx, cy, cz] = speclab::spectrum::observer::xyz_bar(x);
        sum += Xyz::new(cx, cy, cz) * (l.eval(x) * s.eval(x) * h);
    }
    let gap = (exact - sum).to_array().iter().fold(0.0f64, |m, d| m.max(d.abs()));
    assert!(gap < 1e-6 * exact.y, "{exact:?} vs {sum:?}");
    // And close to the tables' own reference: the dense tables' error.
    let table = reference::xyz(&lights::F11, &patches::G4);
    assert!((exact.y - table.y).abs() < 1e-4 * table.y, "{exact:?} vs {table:?}");
}
