//! The renderers' normalisations, from their own tables and ranges: pbrt-v4's
//! `CIE_Y_integral` (106.856895, `src/pbrt/util/spectrum.h`) and Mitsuba 3's
//! `MI_CIE_Y_NORMALIZATION` (1 / 106.7502593994140625,
//! `include/mitsuba/core/spectrum.h`), both published constants. pbrt-v4's
//! table is the CIE 1931 observer at 1 nm over 360–830 nm and Mitsuba 3's
//! the same at 5 nm (their entries equal the CIE's, checked outside the
//! project against both sources): both are rows of
//! `StandardObserver::Cie1931`'s table here.

use speclab::sampling::Domain;
use speclab::spectrum::{Constant, StandardObserver, WavelengthRange};

fn y_rows() -> Vec<f64> {
    let (first, step, rows) = StandardObserver::Cie1931.table().expect("a 1 nm table");
    assert_eq!((first, step, rows.len()), (360.0, 1.0, 471));
    rows.iter().map(|r| r[1]).collect()
}

/// pbrt-v4 sums ȳ at 360, 361, …, 830 nm in `f32` (its `InnerProduct`,
/// and its own test of the constant): 106.85683, 5.7e-7 below the printed
/// constant (no order of summation of the table, in f32 or f64, gives its
/// last two digits: f64 gives 106.8569171, 2.1e-7 above).
#[test]
fn pbrt_v4s_y_integral() {
    let y = y_rows();
    let f32_sum = y.iter().fold(0.0f32, |s, &v| s + v as f32);
    assert_eq!(f32_sum, 106.856_834_f32, "regression snapshot of pbrt-v4's own sum");
    let f64_sum: f64 = y.iter().sum();
    for sum in [f64::from(f32_sum), f64_sum] {
        assert!((sum / 106.856_895 - 1.0).abs() < 1e-6, "{sum}");
    }
    // The exact integral of the table's lines (trapezoids) over the range.
    let exact = StandardObserver::Cie1931.y_integral(WavelengthRange::VISIBLE).unwrap();
    assert!((exact / 106.856_895 - 1.0).abs() < 1e-6, "{exact}");
    // The renderer's defaults reach it with no range or observer named:
    // Domain::VISIBLE's `const` ∫ȳ is that integral, and so is the Y of a
    // constant 1 integrated exactly over its range.
    const DEFAULT: f64 = Domain::VISIBLE.y_integral();
    assert!((DEFAULT / exact - 1.0).abs() < 1e-15, "{DEFAULT} vs {exact}");
    let one = Domain::VISIBLE.reference(&[&Constant::new(1.0)]).unwrap();
    assert!((one.y / 106.856_895 - 1.0).abs() < 1e-6, "{one:?}");
    assert!((Domain::VISIBLE.normalized(one).y - 1.0).abs() < 1e-12);
}

/// Mitsuba 3: a 1000-point Riemann sum over 360–830 nm of its 5 nm table,
/// read by `cie1931_y` (t = (λ − 360)·94/470, a fused multiply-add of the
/// two nearest entries), in `f32`, times 470/1000: 106.75025, one `f32`
/// step (7.6e-6) below the printed constant.
#[test]
fn mitsuba_3s_y_normalisation() {
    let table: Vec<f32> = y_rows().iter().step_by(5).map(|&v| v as f32).collect();
    assert_eq!(table.len(), 95);
    let mut sum = 0.0f32;
    for i in 0..1000 {
        let lambda = 360.0f32 + (i as f32 / 999.0f32) * (830.0f32 - 360.0f32);
        let t = (lambda - 360.0) * (94.0f32 / (830.0f32 - 360.0f32));
        let i0 = (t as usize).min(93);
        let w1 = t - i0 as f32;
        sum += (1.0 - w1).mul_add(table[i0], w1 * table[i0 + 1]);
    }
    let normalisation = sum * 470.0 / 1000.0;
    // The printed constant is an f32 exactly: 106.75026 as f32.
    let published = 106.750_26_f32;
    assert_eq!(f64::from(published), 106.750_259_399_414_06); // 106.7502593994140625
    assert_eq!(normalisation.to_bits() + 1, published.to_bits(), "{normalisation}: one f32 step below");
    // Its 1000 points span 360–830 nm in 999 steps of 470/999 nm but are
    // weighed 470/1000 nm each: the constant is 999/1000 of the integral,
    // which the renderer's default domain holds (within 2e-6).
    let integral = f64::from(published) * 1000.0 / 999.0;
    let default = Domain::VISIBLE.y_integral();
    assert!((integral / default - 1.0).abs() < 2e-6, "{integral} vs {default}");
}
