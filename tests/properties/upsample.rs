//! RGB to spectrum: the round trip linear sRGB → `RgbAlbedo` → XYZ under
//! D65 (the reference integral) → linear sRGB within ΔE00 0.01 over a 17³
//! grid of albedos; every albedo within [0, 1] at every wavelength; black,
//! white and greys exactly; unbounded colours and illuminants; the table.

use proptest::prelude::*;
use speclab::color::rgb_table::RgbTable;
use speclab::color::space::RgbSpace;
use speclab::color::{LinearRgb, RgbAlbedo, RgbIlluminant, RgbUnbounded};
use speclab::spectrum::SigmoidPolynomial;
use speclab::spectrum::observer::Y_BAR_INTEGRAL;
use speclab::{Error, Spectrum};

/// ΔE00 of the round trip of `rgb` through `albedo` (its colour under the
/// space's illuminant, `rgb_of`), in CIELAB relative to the space's white.
fn round_trip(rgb: LinearRgb, albedo: &RgbAlbedo) -> f64 {
    let space = RgbSpace::srgb();
    speclab::color::difference::delta_e00(space.xyz(space.rgb_of(albedo)), space.xyz(rgb), space.white())
}

/// Published requirement: ΔE00 ≤ 0.01 for every albedo of a 17³ grid in
/// [0, 1]³ (measured: at most 1.6e-7, at (1, 0, 0)).
#[test]
fn round_trip_within_a_hundredth_over_a_grid() {
    let mut worst = (0.0f64, LinearRgb::default());
    for r in 0..=16 {
        for g in 0..=16 {
            for b in 0..=16 {
                let rgb = LinearRgb::new(f64::from(r), f64::from(g), f64::from(b)) / 16.0;
                let de = round_trip(rgb, &RgbAlbedo::new(rgb).expect("in [0, 1]"));
                if de > worst.0 {
                    worst = (de, rgb);
                }
            }
        }
    }
    eprintln!("largest round-trip ΔE00 over the 17³ grid: {:.2e} at {:?}", worst.0, worst.1);
    assert!(worst.0 <= 0.01, "{worst:?}");
}

#[test]
fn black_white_and_greys_are_constants() {
    let space = RgbSpace::srgb();
    assert_eq!(RgbAlbedo::new(LinearRgb::splat(0.0)).unwrap().polynomial(), SigmoidPolynomial::BLACK);
    assert_eq!(RgbAlbedo::new(LinearRgb::splat(1.0)).unwrap().polynomial(), SigmoidPolynomial::WHITE);
    for v in [0.01, 0.18, 0.5, 0.99] {
        let grey = RgbAlbedo::new(LinearRgb::splat(v)).unwrap();
        for l in [380.0, 555.0, 730.0] {
            assert!((grey.eval(l) - v).abs() < 1e-12, "{v} at {l}: {}", grey.eval(l));
        }
        assert!(grey.pieces().is_some(), "a constant integrates exactly");
    }
    // (1, 1, 1) is the space's white: the perfect reflector.
    assert!(space.rgb(space.white()).distance(LinearRgb::splat(1.0)) < 1e-12);
    assert!(
        space.rgb_of(&RgbAlbedo::new(LinearRgb::splat(1.0)).unwrap()).distance(LinearRgb::splat(1.0)) < 1e-12
    );
}

#[test]
fn colours_outside_the_albedo_cube_are_errors() {
    for bad in [[1.5, 0.0, 0.0], [-0.1, 0.5, 0.5], [f64::NAN, 0.0, 0.0], [0.0, 0.0, f64::INFINITY]] {
        let err = RgbAlbedo::new(LinearRgb::from(bad)).unwrap_err();
        assert!(matches!(err, Error::Albedo { .. }), "{bad:?}");
        assert!(err.to_string().starts_with("expected linear sRGB components in [0, 1], found"), "{err}");
        assert!(RgbTable::fit(RgbSpace::srgb(), 4).albedo(LinearRgb::from(bad)).is_err());
    }
}

/// An unbounded colour is twice its largest component times an albedo
/// from the space's table; an illuminant is that times the space's
/// illuminant, with (1, 1, 1) as bright as a constant spectrum of 1. Their
/// colours come back within the table's accuracy (ΔE00 ≤ 0.05, as
/// `table_round_trip_on_a_grid`), measured as the albedo of the colour over
/// its scale.
#[test]
fn unbounded_colours_and_illuminants() {
    let space = RgbSpace::srgb();
    let de = |a: LinearRgb, b: LinearRgb, scale: f64| {
        speclab::color::difference::delta_e00(space.xyz(a / scale), space.xyz(b / scale), space.white())
    };
    let rgb = LinearRgb::new(2.0, 0.5, 0.1);
    let unbounded = RgbUnbounded::new(rgb);
    assert_eq!((unbounded, unbounded.scale()), (space.unbounded(rgb), 4.0));
    assert!(de(space.rgb_of(&unbounded), rgb, 4.0) < 0.05, "{:?}", space.rgb_of(&unbounded));
    let clamped = RgbUnbounded::new(LinearRgb::new(-1.0, f64::NAN, 0.5));
    assert!(de(space.rgb_of(&clamped), LinearRgb::new(0.0, 0.0, 0.5), 1.0) < 0.05);
    assert_eq!(RgbUnbounded::new(LinearRgb::splat(0.0)).eval(500.0), 0.0);
    let white = RgbIlluminant::new(LinearRgb::splat(1.0));
    let y = speclab::sampling::reference::white(&white).y;
    assert!((y - Y_BAR_INTEGRAL).abs() < 1e-9 * y, "{y} vs {Y_BAR_INTEGRAL}");
    assert!(std::ptr::eq(white.illuminant(), space.illuminant()));
    // An illuminant's colour is twice its largest component times its
    // albedo's under the illuminant (exactly), and that is its rgb.
    let rgb = LinearRgb::new(1.0, 0.6, 0.2);
    let light = RgbIlluminant::new(rgb);
    let emitted = speclab::sampling::reference::white(&light) / Y_BAR_INTEGRAL;
    let albedo = RgbAlbedo::from_polynomial(light.polynomial());
    let expected = space.albedo_xyz(&albedo) * 2.0;
    assert!((emitted - expected).to_array().iter().all(|d| d.abs() < 1e-12), "{emitted:?}");
    assert!(de(space.rgb_of(&albedo) * 2.0, rgb, 2.0) < 0.05);
}

/// `3t² − 2t³`, the table's spacing of its largest component (twice).
fn smoothstep(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// The table interpolates fits made at its nodes (the documented layout:
/// the largest component at `smoothstep(smoothstep(k/(n − 1)))`, the others
/// as `i/(n − 1)` of it): at a node a lookup is the fit.
#[test]
fn table_lookups_at_nodes_are_fits() {
    let n = 8;
    let table = RgbTable::fit(RgbSpace::srgb(), n);
    let space = RgbSpace::srgb();
    for (case, k, i, j) in [(0, 5, 3, 0), (1, 7, 0, 4), (2, 2, 6, 6), (0, 6, 1, 5)] {
        let z = smoothstep(smoothstep(f64::from(k) / 7.0));
        let mut rgb = [0.0; 3];
        rgb[case] = z;
        rgb[(case + 1) % 3] = f64::from(i) / 7.0 * z;
        rgb[(case + 2) % 3] = f64::from(j) / 7.0 * z;
        let rgb = LinearRgb::from(rgb);
        let looked_up = space.rgb_of(&table.albedo(rgb).unwrap());
        assert!(looked_up.distance(rgb) < 1e-6, "{rgb:?}: {looked_up:?}");
    }
}

/// The full table's accuracy between nodes, on 4,000 colours spread over
/// [0, 1]³ (a golden-ratio sequence): mean ΔE00 below 0.02, the 95th
/// percentile below 0.05, the worst below 0.35 (measured: 0.013, 0.033,
/// 0.315).
#[test]
fn table_accuracy_between_nodes() {
    let table = RgbTable::SRGB;
    let mut de: Vec<f64> = (0..4000)
        .map(|i| {
            let v = (f64::from(i) * 0.618_033_988_7).fract();
            let rgb = LinearRgb::new(v, (v * 3.7).fract(), (v * 7.3).fract());
            round_trip(rgb, &table.albedo(rgb).unwrap())
        })
        .collect();
    de.sort_by(f64::total_cmp);
    let mean = de.iter().sum::<f64>() / de.len() as f64;
    eprintln!("table ΔE00: mean {mean:.3}, p95 {:.3}, worst {:.3}", de[3799], de[3999]);
    assert!(mean < 0.02 && de[3799] < 0.05 && de[3999] < 0.35);
}

/// The round trip through the full table on a 9³ grid of albedos (every
/// component 0, 1/8, …, 1): within ΔE00 0.05 of the colour asked for.
#[test]
fn table_round_trip_on_a_grid() {
    let table = RgbTable::SRGB;
    let mut worst = (0.0f64, LinearRgb::splat(0.0));
    let mut sum = 0.0;
    for i in 0..729 {
        let rgb = LinearRgb::new(f64::from(i / 81) / 8.0, f64::from(i / 9 % 9) / 8.0, f64::from(i % 9) / 8.0);
        let de = round_trip(rgb, &table.albedo(rgb).unwrap());
        sum += de;
        if de > worst.0 {
            worst = (de, rgb);
        }
    }
    eprintln!(
        "9³ grid through the table: ΔE00 mean {:.4}, worst {:.4} at {:?}",
        sum / 729.0,
        worst.0,
        worst.1
    );
    assert!(worst.0 <= 0.05, "{worst:?}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every fitted albedo is a reflectance: within [0, 1] at every
    /// wavelength (the sigmoid's range), here at 351 wavelengths and one
    /// more anywhere in 300–800 nm.
    #[test]
    fn albedos_stay_within_zero_and_one(r in 0.0..=1.0f64, g in 0.0..=1.0f64, b in 0.0..=1.0f64, lambda in 300.0..800.0f64) {
        let albedo = RgbAlbedo::new(LinearRgb::new(r, g, b)).expect("in [0, 1]");
        for l in (0..=350).map(|i| 380.0 + f64::from(i)).chain([lambda]) {
            let v = albedo.eval(l);
            prop_assert!((0.0..=1.0).contains(&v), "{} at {}", v, l);
        }
    }
}

/// Every built-in space's table on a 9³ grid of albedos: the round trip
/// (look up, then the albedo's colour under the space's illuminant) against
/// the colour asked for, wherever a reflectance of that colour exists (a
/// fit for that colour alone comes back within ΔE00 0.01), and, where none
/// does, against the fit's own error (both give the reflectance of the last
/// colour reached on the line from the colour's grey).
///
/// The target, ΔE00 0.05, holds for sRGB and Display P3 (measured with the
/// embedded compact tables: 0.0360 and 0.0416; P3's gap where no
/// reflectance exists 0.115). It is **missed** for Rec.2020 (0.329), ACEScg (0.726)
/// and ACES2065-1 (0.363): their
/// saturated colours lie at or past the object colours' limit, where a
/// sigmoid polynomial's fit is a step of unbounded steepness and
/// interpolating coefficients between steps with different edges blurs
/// them. The bounds below are the previous tables' figures: a regression
/// guard, not the target.
#[test]
fn every_spaces_table_round_trips_on_a_grid() {
    let mut results = Vec::new();
    for space in RgbSpace::all() {
        let table = space.table();
        let de = |rgb: LinearRgb, albedo: &RgbAlbedo| {
            speclab::color::difference::delta_e00(
                space.xyz(space.rgb_of(albedo)),
                space.xyz(rgb),
                space.white(),
            )
        };
        let (mut worst, mut unreachable, mut worst_gap) = ((0.0f64, LinearRgb::default()), 0, 0.0f64);
        for i in 0..729 {
            let rgb =
                LinearRgb::new(f64::from(i / 81) / 8.0, f64::from(i / 9 % 9) / 8.0, f64::from(i % 9) / 8.0);
            let (looked_up, fitted) =
                (de(rgb, &table.albedo(rgb).unwrap()), de(rgb, &space.fit_albedo(rgb).unwrap()));
            if fitted > 0.01 {
                unreachable += 1;
                worst_gap = worst_gap.max(looked_up - fitted);
            } else if looked_up > worst.0 {
                worst = (looked_up, rgb);
            }
        }
        eprintln!(
            "{}: round trip worst ΔE00 {:.4} at {:?}; {unreachable} of 729 colours \
             no reflectance has, the table within {worst_gap:.4} of the fit there",
            space.name(),
            worst.0,
            worst.1
        );
        results.push((space.name(), worst.0, worst_gap));
    }
    // The worst round trips: no worse than the f64 tables fitted on first
    // use were (0.0369, 0.0417, 0.3294, 0.3627, 0.7256); the compact
    // tables' are 0.0360, 0.0416, 0.3293, 0.3625, 0.7254 (tools' test
    // `compact_tables` holds each against its f32 source). The gaps where
    // no reflectance exists are the compact tables' (regression snapshot;
    // the f32 tables' were 0, 0.1137, 0.1923, 1.1859, 0.2780).
    // Display P3: the tables were fitted under D65 at 5 nm, the fit here
    // runs under D65 at 1 nm (the same to 6 significant figures), and at
    // (0.375, 1, 0), on the object colours' limit, the fit alone now lands
    // (ΔE00 0.0000; 0.0178 under the 5 nm table): that colour counts as
    // reachable, and the table's 0.1326 there (0.1315 before) is P3's
    // worst; the largest gap left is 0.0786 (snapshots).
    let bounds = [
        ("sRGB", 0.037, 0.001),
        ("Display P3", 0.133, 0.079),
        ("Rec.2020", 0.33, 0.194),
        ("ACES2065-1", 0.363, 1.188),
        ("ACEScg", 0.73, 0.280),
    ];
    for ((name, worst, gap), (bound_name, worst_bound, gap_bound)) in results.into_iter().zip(bounds) {
        assert_eq!(name, bound_name);
        assert!(worst <= worst_bound && gap <= gap_bound, "{name}: worst {worst}, gap {gap}");
    }
}
