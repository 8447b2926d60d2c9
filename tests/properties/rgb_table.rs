//! The built-in RGB tables as data: each embedded table against fresh fits
//! at a sample of its nodes, the table file round trip bit for bit, clear
//! errors for damaged and foreign files, `const` colours equal to run-time
//! ones, and clones that share one table.

use speclab::color::difference::delta_e00;
use speclab::color::rgb_table::{RESOLUTION, RgbTable, node};
use speclab::color::{LinearRgb, RgbAlbedo, RgbSpace};
use speclab::{Error, Spectrum};

/// ΔE00 between the colour asked for and `albedo`'s under the space's
/// illuminant.
fn round_trip(space: &RgbSpace, rgb: LinearRgb, albedo: &RgbAlbedo) -> f64 {
    delta_e00(space.xyz(space.rgb_of(albedo)), space.xyz(rgb), space.white())
}

/// The colour of node `(case, k, j, i)` of a table of `n` nodes per axis.
fn node_colour(case: usize, k: usize, j: usize, i: usize, n: usize) -> LinearRgb {
    let z = f64::from(node(k, n));
    let mut c = [0.0; 3];
    c[case] = z;
    c[(case + 1) % 3] = i as f64 / (n - 1) as f64 * z;
    c[(case + 2) % 3] = j as f64 / (n - 1) as f64 * z;
    LinearRgb::from(c)
}

/// Every built-in space's embedded table holds, at 60 nodes chosen by a
/// fixed sequence, the reflectance a fit for the node's colour alone
/// gives, wherever that fit reaches the colour (ΔE00 ≤ 0.01; a few dark
/// ACES2065-1 nodes lie at the object colours' limit, where the fit itself
/// misses by up to 0.0064): the two reflectances' colours within ΔE00 0.04
/// of each other (the fits' tolerance and `f32` rounding, 2e-3, and the
/// compact tables' rounding, at most 0.034 on any node: tools' test
/// `compact_tables`, docs/color.md). A stale table (fitted for another
/// space's matrices) misses by whole units, or is refused.
#[test]
fn embedded_tables_are_the_fits_at_their_nodes() {
    let embedded =
        [RgbTable::SRGB, RgbTable::DISPLAY_P3, RgbTable::REC2020, RgbTable::ACES2065_1, RgbTable::ACESCG];
    for (space, table) in RgbSpace::all().into_iter().zip(embedded) {
        // The space uses its embedded table (a stale one would be refitted).
        assert!(std::ptr::eq(space.table().as_bytes(), table.as_bytes()), "{}", space.name());
        assert_eq!(space.table().resolution(), RESOLUTION, "{}", space.name());
        assert!(space.table().header().name == space.name(), "{}: a built-in table", space.name());
        let colour = |albedo: &RgbAlbedo| space.xyz(space.rgb_of(albedo));
        let mut checked = 0;
        for s in 0..60u32 {
            let pick =
                |m: u32, salt: u32| ((s.wrapping_mul(2_654_435_761) ^ salt) >> 7) as usize % m as usize;
            let (case, k, j, i) = (pick(3, 1), 1 + pick(63, 2), pick(64, 3), pick(64, 4));
            let rgb = node_colour(case, k, j, i, RESOLUTION);
            let fitted = space.fit_albedo(rgb).unwrap();
            if round_trip(space, rgb, &fitted) > 0.01 {
                continue; // no reflectance has it
            }
            let de = delta_e00(colour(&space.albedo(rgb).unwrap()), colour(&fitted), space.white());
            assert!(
                de < 0.04,
                "{}: node {case} {k} {j} {i} ({rgb:?}): table and fit {de} apart",
                space.name()
            );
            checked += 1;
        }
        assert!(checked >= 20, "{}: only {checked} reachable nodes checked", space.name());
    }
}

/// Saved and loaded, a table is the same bytes; a built-in one too; a
/// loaded table given to its space is used by it.
#[test]
fn saved_tables_load_back_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("speclab-rgb-table-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fitted = RgbTable::fit(RgbSpace::srgb(), 6);
    for (name, table) in [("fitted", &fitted), ("built-in", RgbTable::SRGB)] {
        let path = dir.join(format!("{name}.rgbt"));
        table.save(&path).unwrap();
        let back = RgbTable::load(&path).unwrap();
        assert_eq!(back.as_bytes(), table.as_bytes(), "{name}");
        assert_eq!(&back, table, "{name}");
        assert_eq!(back.resolution(), table.resolution());
    }
    assert_ne!(&fitted, RgbTable::SRGB);
    // Debug names the kind and size, not 9.4 MB of bytes.
    let bytes = RgbTable::SRGB.as_bytes().len();
    assert_eq!(
        format!("{:?}", RgbTable::SRGB),
        format!("RgbTable {{ resolution: 64, version: 2, bytes: {bytes}, kind: \"built in\" }}")
    );
    assert!(format!("{fitted:?}").ends_with("kind: \"shared\" }"), "{fitted:?}");
    let rgb = LinearRgb::new(0.7, 0.2, 0.4);
    let space =
        RgbSpace::srgb().clone().with_table(RgbTable::load(dir.join("fitted.rgbt")).unwrap()).unwrap();
    assert_eq!(space.albedo(rgb).unwrap(), fitted.albedo(rgb).unwrap());
    assert_ne!(space.albedo(rgb).unwrap(), RgbSpace::srgb().albedo(rgb).unwrap());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A file that is not a table, a damaged one, a cut one, a missing one and
/// a table of another space: each a clear error naming what is wrong.
#[test]
fn damaged_and_foreign_tables_are_refused() {
    let good = RgbTable::fit(RgbSpace::srgb(), 3);
    let bytes = good.as_bytes();
    let mut flipped = bytes.to_vec();
    flipped[300] ^= 0x10;
    let cases: [(&[u8], &str); 4] = [
        (b"\x89PNG\r\n\x1a\n not a table", "lamp.rgbt: expected an RGB table file"),
        (&flipped, "lamp.rgbt: expected checksum"),
        (
            &bytes[..bytes.len() - 5],
            "lamp.rgbt: expected 1108 bytes for what its header declares, found 1103",
        ),
        (&[], "lamp.rgbt: expected an RGB table file"),
    ];
    for (bytes, message) in cases {
        let e = RgbTable::from_bytes(bytes, "lamp.rgbt").unwrap_err();
        assert!(matches!(e, Error::TableFile(_)) && e.to_string().starts_with(message), "{e}");
        let source = std::error::Error::source(&e).expect("the file's error");
        assert_eq!(source.to_string(), e.to_string());
    }
    let missing = RgbTable::load("/nonexistent/srgb.rgbt").unwrap_err();
    assert!(missing.to_string().starts_with("/nonexistent/srgb.rgbt: cannot read"), "{missing}");
    let foreign = RgbSpace::display_p3().clone().with_table(good).unwrap_err();
    assert_eq!(
        foreign.to_string(),
        "expected a table fitted for the RGB space Display P3, found one fitted for \"sRGB\" \
         (another XYZ to RGB matrix, or an illuminant of another white)"
    );
}

/// "Within 1e-5" is relative for matrix entries above 1 (sRGB's 3.24,
/// −1.54, 1.88): a space whose one primary coordinate moved by 1e-6
/// takes sRGB's table (its matrix moves by up to 9.9e-6 of an entry,
/// 3.2e-5 absolute); one moved by 5e-6 (1.2e-5 to 5.0e-5 of an entry)
/// does not.
#[test]
fn a_table_fits_a_space_within_1e_5_relative() {
    let srgb = RgbSpace::srgb();
    let table = RgbTable::fit(srgb, 2);
    for (d, takes) in [(1e-6, true), (5e-6, false)] {
        for coordinate in 0..6 {
            let mut primaries = srgb.primaries();
            primaries[coordinate / 2][coordinate % 2] += d;
            let space = RgbSpace::new("moved", primaries, srgb.white_point(), srgb.illuminant()).unwrap();
            let given = space.with_table(table.clone());
            assert_eq!(given.is_ok(), takes, "coordinate {coordinate} moved by {d:e}");
        }
    }
}

/// A `const` colour is the run-time lookup's, to the bit: 8 colours
/// evaluated at compile time (one `const` item holds a few: each decodes
/// its corners' blocks in the compiler), and 2,000 through the cube and
/// greys with the `const fn` called at run time (its scalar form against
/// the lookup's four lanes); out-of-range components are `None`, and so is
/// a table fitted at run time.
#[test]
fn const_colours_are_run_time_colours() {
    const RED: Option<RgbAlbedo> = RgbTable::SRGB.const_albedo(LinearRgb::new(0.8, 0.1, 0.05));
    assert_eq!(RED, Some(RgbSpace::srgb().albedo(LinearRgb::new(0.8, 0.1, 0.05)).unwrap()));
    // Colours looked up at compile time (two of each three with two equal
    // components), against the same at run time.
    const fn colour(i: usize) -> LinearRgb {
        let v = (i as f64 * 0.618_034) % 1.0;
        let w = (v * 3.7) % 1.0;
        match i % 3 {
            0 => LinearRgb::new(v, w, (v * 7.3) % 1.0),
            1 => LinearRgb::new(v, v, w),
            _ => LinearRgb::new(w, v, v),
        }
    }
    const LOOKED_UP: [Option<RgbAlbedo>; 8] = {
        let mut out = [None; 8];
        let mut i = 0;
        while i < 8 {
            out[i] = RgbTable::SRGB.const_albedo(colour(i));
            i += 1;
        }
        out
    };
    for (i, looked_up) in LOOKED_UP.iter().enumerate() {
        let run_time = RgbSpace::srgb().albedo(colour(i)).unwrap();
        assert_eq!(*looked_up, Some(run_time), "{:?}", colour(i));
    }
    for i in 0..2000 {
        let v = (f64::from(i) * 0.618_033_988_7).fract();
        let rgb = LinearRgb::new(v, (v * 3.7).fract(), (v * 7.3).fract());
        let run_time = RgbSpace::srgb().albedo(rgb).unwrap();
        assert_eq!(RgbTable::SRGB.const_albedo(rgb), Some(run_time), "{rgb:?}");
    }
    for grey in [0.0, 0.18, 0.5, 1.0] {
        let albedo = RgbTable::SRGB.const_albedo(LinearRgb::splat(grey)).unwrap();
        assert_eq!(albedo, RgbSpace::srgb().albedo(LinearRgb::splat(grey)).unwrap());
        for lambda in [400.0, 550.0, 700.0] {
            assert!((albedo.eval(lambda) - grey).abs() < 1e-12, "{grey} at {lambda}");
        }
    }
    for bad in [[1.5, 0.0, 0.0], [-0.1, 0.5, 0.5], [f64::NAN, 0.0, 0.0]] {
        assert_eq!(RgbTable::SRGB.const_albedo(LinearRgb::from(bad)), None, "{bad:?}");
    }
    assert_eq!(RgbTable::fit(RgbSpace::srgb(), 2).const_albedo(LinearRgb::new(0.5, 0.2, 0.1)), None);
}

/// Clones of a space share its table: one given, one embedded, and one
/// fitted on first use after the space was cloned (seconds: 64³ fits).
#[test]
fn clones_share_one_table() {
    let srgb = RgbSpace::srgb();
    let mine = RgbSpace::new("mine", srgb.primaries(), srgb.white_point(), srgb.illuminant()).unwrap();
    let given = mine.clone().with_table(RgbTable::fit(srgb, 4)).unwrap();
    assert!(std::ptr::eq(given.table().as_bytes(), given.clone().table().as_bytes()));
    assert!(std::ptr::eq(srgb.clone().table().as_bytes(), RgbTable::SRGB.as_bytes()));
    let clone = mine.clone();
    let fitted = mine.table();
    assert_eq!(fitted.resolution(), RESOLUTION);
    assert!(std::ptr::eq(fitted.as_bytes(), clone.table().as_bytes()), "the clone fitted its own");
}

/// Components so small that `1/z` overflows in `f32` (and 0 in `f32`):
/// finite albedos, at run time and compile time.
#[test]
fn tiny_components_give_finite_albedos() {
    for rgb in [[1e-38, 0.0, 0.0], [1e-40, 1e-41, 0.0], [3e-39, 1e-39, 2e-39], [1e-50, 0.0, 0.0]] {
        let albedo = RgbSpace::srgb().albedo(LinearRgb::from(rgb)).unwrap();
        assert!(albedo.polynomial().coefficients().iter().all(|c| !c.is_nan()), "{rgb:?}: {albedo:?}");
        assert!((0.0..=1e-6).contains(&albedo.eval(550.0)), "{rgb:?}: {}", albedo.eval(550.0));
        let at_compile_time = RgbTable::SRGB.const_albedo(LinearRgb::from(rgb)).unwrap();
        assert!(at_compile_time.polynomial().coefficients().iter().all(|c| !c.is_nan()), "{rgb:?}");
    }
    let bright = RgbSpace::srgb().unbounded_up_to_one(LinearRgb::new(1e-39, 0.0, 0.0));
    assert!(bright.eval(600.0).is_finite());
}

/// "1 up to 1": inside the cube a colour is its albedo at scale 1; beyond,
/// its largest component times the albedo of the colour over that;
/// pbrt-v4's rule halves the albedo's brightness instead. Both spectra of
/// a bright colour have its colour (different spectra: metamers).
#[test]
fn unbounded_up_to_one_and_twice() {
    let space = RgbSpace::srgb();
    let inside = LinearRgb::new(0.6, 0.3, 0.1);
    let one = space.unbounded_up_to_one(inside);
    assert_eq!(one.scale(), 1.0);
    assert_eq!(one.polynomial(), space.albedo(inside).unwrap().polynomial());
    let twice = space.unbounded(inside);
    assert_eq!(twice.scale(), 1.2);
    assert_eq!(twice.polynomial(), space.albedo(inside / 1.2).unwrap().polynomial());
    let bright = LinearRgb::new(4.0, 1.0, 0.2);
    let one = space.unbounded_up_to_one(bright);
    assert_eq!(one.scale(), 4.0);
    assert_eq!(one.polynomial(), space.albedo(bright / 4.0).unwrap().polynomial());
    // Two metamers of one colour: each comes back as the colour (measured
    // at the brightness of the largest component 1).
    for spectrum in [one, space.unbounded(bright)] {
        let de = delta_e00(space.xyz(space.rgb_of(&spectrum) / 4.0), space.xyz(bright / 4.0), space.white());
        assert!(de < 0.05, "{spectrum:?}: {de}");
    }
    assert_eq!(space.unbounded_up_to_one(LinearRgb::new(-1.0, f64::NAN, 0.0)).scale(), 0.0);
    assert_eq!(space.unbounded_up_to_one(LinearRgb::new(-1.0, 0.5, 0.0)).scale(), 1.0);
}

/// The RGB spectra's `f32` lanes (a hero sample's, and behind a `Box<dyn
/// Spectrum>`) against their `f64` values: within the `f32` polynomial's
/// rounding, `4ε·(2 + Σ|cᵢ|)` relatively, `cᵢ` the unbounded colour's
/// coefficients (the albedo is the colour it looks up, at a quarter of
/// its brightness: the same polynomial; one more ε for the scale, and for
/// the light the illuminant's own `f32` rounding).
#[test]
fn rgb_spectra_sample_in_f32_lanes() {
    use speclab::HeroSample;
    let space = RgbSpace::acescg();
    let rgb = LinearRgb::new(2.0, 0.7, 0.3);
    let spectra: [Box<dyn Spectrum>; 3] = [
        Box::new(space.albedo(rgb / 4.0).unwrap()),
        Box::new(space.unbounded(rgb)),
        Box::new(space.light(rgb)),
    ];
    let c = space.unbounded(rgb).polynomial().coefficients();
    assert_eq!(space.albedo(rgb / 4.0).unwrap().polynomial().coefficients(), c);
    let bound = 4.0 * f64::from(f32::EPSILON) * (2.0 + c.iter().map(|v| v.abs()).sum::<f64>());
    let lambda: Vec<f32> = (0..=35).map(|i| 380.0 + 10.0 * i as f32).collect();
    for (which, s) in spectra.iter().enumerate() {
        let mut values = vec![f32::NAN; lambda.len()];
        s.eval_many_f32(&lambda, &mut values);
        for (v, l) in values.iter().zip(&lambda) {
            let exact = s.eval(f64::from(*l));
            assert!((f64::from(*v) - exact).abs() <= bound * exact.abs().max(1e-3), "{which} at {l}: {v}");
        }
    }
    for i in 0..200 {
        let h = HeroSample::<4, f32>::new((i as f32 + 0.5) / 200.0);
        for (which, s) in spectra.iter().enumerate() {
            for (v, l) in h.sample(s).values.iter().zip(h.lambda()) {
                let exact = s.eval(f64::from(*l));
                assert!(
                    (f64::from(*v) - exact).abs() <= bound * exact.abs().max(1e-3),
                    "spectrum {which} at {l}: {v} against {exact}"
                );
            }
        }
    }
}
