//! Any spectrum through every path: a renderer's closure, a constant, a
//! blackbody, an RGB albedo and dense tables go through `HeroSample::sample`,
//! `reference::xyz`, `RegularSpectrum` and a hero estimate like tabulated
//! spectra. Where a closure computes a table's own interpolant, every path
//! gives the table's numbers (exactly for the estimators, to rounding for
//! integrals); quadrature of smooth spectra agrees with a fine sum.

use rand::SeedableRng;
use rand::rngs::StdRng;
use speclab::color::RgbAlbedo;
use speclab::data::{lights, patches};
use speclab::sampling::reference;
use speclab::spectrum::{Blackbody, Constant, DenseSpectrum, FnSpectrum};
use speclab::{
    BoxAverage, Center, HeroSample, LinearRgb, RegularSpectrum, Role, Spectrum, TabulatedSpectrum, Xyz,
};

/// Rounding only.
const ROUNDING: f64 = 1e-12;

fn close(a: Xyz, b: Xyz) -> bool {
    (a - b).to_array().iter().all(|d| d.abs() <= ROUNDING * b.y.abs().max(1e-300))
}

/// A closure that is G4's own interpolant: not piecewise polynomial as far
/// as the library knows, so integrated by quadrature; its pieces (10 nm
/// knots) fall on the observer's 5 nm breaks, where the rule is exact.
#[test]
fn a_closure_is_integrated_like_the_table_it_computes() {
    let g4 = FnSpectrum(|l: f64| patches::G4.eval(l));
    assert!(g4.pieces().is_none());
    for light in [&lights::A, &lights::D65, &lights::F11] {
        let (by_closure, by_table) = (reference::xyz(light, &g4), reference::xyz(light, &patches::G4));
        assert!(close(by_closure, by_table), "{by_closure:?} vs {by_table:?}");
    }
    let h = HeroSample::<4>::new(0.37);
    assert_eq!(h.sample(&g4), patches::G4.sample(&h));
    assert_eq!(
        RegularSpectrum::<16, Center>::center(&g4).values(),
        RegularSpectrum::<16, Center>::center(&patches::G4).values()
    );
    let (boxed, table) = (
        RegularSpectrum::<16, BoxAverage>::box_average(&g4),
        RegularSpectrum::<16, BoxAverage>::box_average(&patches::G4),
    );
    for (a, b) in boxed.values().iter().zip(table.values()) {
        assert!((a - b).abs() <= ROUNDING, "{a} vs {b}");
    }
    let estimate =
        |s: &dyn Spectrum| crate::hero_mean::<4>(&lights::F11, s, 64, &mut StdRng::seed_from_u64(3));
    assert_eq!(estimate(&g4), estimate(&patches::G4), "same wavelengths, same values: the same estimate");
}

/// A constant is a polynomial: exact, equal to a two-sample tabulated
/// constant (linear through equal values).
#[test]
fn a_constant_integrates_exactly() {
    let half = Constant::new(0.5);
    let table = TabulatedSpectrum::new(vec![380.0, 730.0], vec![0.5, 0.5], Role::Light).unwrap();
    assert!(close(reference::white(&half), reference::white(&table)));
    assert!(close(reference::xyz(&half, &patches::A1), reference::xyz(&table, &patches::A1)));
    assert_eq!(HeroSample::<4>::new(0.1).sample(&half).values, [0.5; 4]);
}

/// Smooth spectra by quadrature, against a 0.002 nm midpoint sum of the
/// same integrand (itself accurate to about 1e-9 here).
#[test]
fn smooth_spectra_by_quadrature() {
    let sun = Blackbody::new(5778.0).unwrap();
    let orange = RgbAlbedo::new(LinearRgb::new(0.8, 0.35, 0.05)).unwrap();
    let h = 0.002;
    let midpoint = |l: &dyn Spectrum, s: &dyn Spectrum| {
        (0..175_000)
            .map(|i| 380.0 + (f64::from(i) + 0.5) * h)
            .map(|x| Xyz::from(speclab::spectrum::observer::xyz_bar(x)) * (l.eval(x) * s.eval(x) * h))
            .sum::<Xyz>()
    };
    for (l, s) in
        [(&sun as &dyn Spectrum, &patches::H4 as &dyn Spectrum), (&lights::F11, &orange), (&sun, &orange)]
    {
        let (exact, sum) = (reference::xyz(&l, &s), midpoint(l, s));
        let gap = (exact - sum).to_array().iter().fold(0.0f64, |m, d| m.max(d.abs()));
        assert!(gap < 1e-8 * exact.y, "{exact:?} vs {sum:?}");
    }
}

/// A renderer's mixed list, through the estimator and the buckets.
#[test]
fn mixed_spectra_in_a_list() {
    let list: Vec<Box<dyn Spectrum + Send + Sync>> = vec![
        Box::new(patches::F4.clone()),
        Box::new(DenseSpectrum::new(&patches::F4)),
        Box::new(RgbAlbedo::new(LinearRgb::new(0.1, 0.4, 0.1)).unwrap()),
    ];
    let exact = reference::xyz(&lights::D65, &patches::F4);
    for s in &list {
        let xyz = reference::xyz(&lights::D65, s);
        let estimate = crate::hero_mean::<4>(&lights::D65, s, 256, &mut StdRng::seed_from_u64(1));
        let buckets = (RegularSpectrum::<32>::center(&lights::D65) * RegularSpectrum::center(s)).to_xyz();
        assert!((estimate.y - xyz.y).abs() < 0.02 * xyz.y && (buckets.y - xyz.y).abs() < 0.02 * xyz.y);
    }
    // The table and its dense copy are the same colour, to the copy's error.
    assert!((reference::xyz(&lights::D65, &list[1]).y - exact.y).abs() < 1e-4 * exact.y);
}
