//! The display pipeline (`speclab_study::display`): the IEC 61966-2-1 transfer
//! function at its published breakpoints and constants, round trips through
//! 8 bits, exposure, and the gamut maps' promises (every output in [0, 1];
//! the chroma map keeps luminance and hue within the tolerances its doc
//! states).
//!
//! Published truth: IEC 61966-2-1:1999, section 5.2 and 5.3: the linear
//! segment of slope 12.92 below 0.0031308 (encoded 0.04045), above it
//! `1.055·c^(1/2.4) − 0.055`.

use proptest::prelude::*;
use speclab::LinearRgb;
use speclab::color::srgb::luminance;
use speclab::sampling::reference;
use speclab::{Xyz, data};
use speclab_study::display::{
    EncodedSrgb, Exposure, GamutMap, PixelPipeline, Srgb8, WHITE_LUMINANCE, clip, reduce_chroma,
};

/// IEC 61966-2-1's constants.
const TOE: f64 = 0.003_130_8;
const ENCODED_TOE: f64 = 0.040_45;

/// The standard prints the encoded breakpoint as 0.04045, while 12.92 ×
/// 0.0031308 = 0.0404499: its rounded constants leave a step of 6.4e-8.
const BREAKPOINT_TOLERANCE: f64 = 1e-7;

/// Luminance and hue of the chroma map: rounding only (see `reduce_chroma`).
const LUMINANCE_TOLERANCE: f64 = 1e-12;
const HUE_TOLERANCE: f64 = 1e-9;
/// Below this distance from the grey the hue is not checked (far below one
/// 8-bit step; the direction of a vanishing offset is rounding noise).
const HUE_MIN_OFFSET: f64 = 1e-6;

fn grey(v: f64) -> LinearRgb {
    LinearRgb::new(v, v, v)
}

#[test]
fn transfer_function_at_published_breakpoints() {
    let toe = EncodedSrgb::encode(LinearRgb::new(TOE, 0.0, 1.0));
    assert!((toe.r - ENCODED_TOE).abs() < BREAKPOINT_TOLERANCE, "{toe:?}");
    assert_eq!(toe.g, 0.0);
    assert!((toe.b - 1.0).abs() < 1e-15, "1.055 − 0.055 rounds to 1 − 2⁻⁵³");
    assert!((EncodedSrgb { r: ENCODED_TOE, g: 0.0, b: 0.0 }.decode().r - TOE).abs() < BREAKPOINT_TOLERANCE);
    // Below the toe: the line of slope 12.92.
    let low = EncodedSrgb::encode(grey(0.001));
    assert!((low.g - 12.92 * 0.001).abs() < 1e-15, "{low:?}");
    // Above: 1.055·c^(1/2.4) − 0.055.
    let mid = EncodedSrgb::encode(grey(0.5));
    assert!((mid.b - (1.055 * 0.5_f64.powf(1.0 / 2.4) - 0.055)).abs() < 1e-15, "{mid:?}");
    // The curve is continuous there, up to the standard's step.
    let (below, above) = (EncodedSrgb::encode(grey(TOE)), EncodedSrgb::encode(grey(TOE * (1.0 + 1e-12))));
    assert!((above.r - below.r).abs() < BREAKPOINT_TOLERANCE);
}

#[test]
fn every_8bit_code_survives_decode_and_encode() {
    for code in 0..=255u8 {
        let pixel = Srgb8::new(code, 255 - code, code / 2);
        let linear = pixel.to_encoded().decode();
        assert_eq!(EncodedSrgb::encode(linear).to_8bit(), pixel, "code {code}");
        let back = EncodedSrgb::encode(linear);
        let twice = EncodedSrgb::encode(back.decode());
        assert!((twice.r - back.r).abs() < 1e-12 && (twice.g - back.g).abs() < 1e-12);
    }
    // Quantisation rounds to nearest: mid-grey 0.5 encoded is 127.5 → 128.
    assert_eq!(EncodedSrgb { r: 0.5, g: 0.5 - 1e-9, b: 1.0 }.to_8bit(), Srgb8::new(128, 127, 255));
}

#[test]
fn exposure_puts_the_white_at_luminance_one_or_just_in_the_display() {
    for light in [&data::lights::A, &data::lights::D65, &data::lights::F11] {
        let white = reference::white(light);
        let exposed = Exposure::for_white(white).apply(white.to_linear_srgb());
        assert!((luminance(exposed) - 1.0).abs() < 1e-12, "{exposed:?}");
        let pixel =
            PixelPipeline::new(Exposure::for_white(white), GamutMap::Chroma).pixel(white.to_linear_srgb());
        assert_eq!(pixel, Srgb8::new(255, 255, 255));
    }
    // Fitted, A's white keeps its orange: red at full scale, then green, then blue.
    let a = reference::white(&data::lights::A).to_linear_srgb();
    let fitted = Exposure::fit_white(reference::white(&data::lights::A)).apply(a);
    assert!((fitted.r - 1.0).abs() < 1e-12 && luminance(fitted) < 0.7, "{fitted:?}");
    let Srgb8 { r, g, b } =
        PixelPipeline::new(Exposure::fit_white(reference::white(&data::lights::A)), GamutMap::Chroma)
            .pixel(a);
    assert!(r == 255 && g < 255 && b < g, "{r} {g} {b}");
    assert_eq!(Exposure::fit_white(Xyz::new(-1.0, f64::NAN, 0.0)).factor(), 0.0);
    assert_eq!(Exposure::new(2.5).apply(grey(0.2)), grey(0.5));
    assert_eq!(Exposure::new(2.5).factor(), 2.5);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(Exposure::new(bad).factor(), 0.0, "{bad}");
    }
    assert_eq!(Exposure::for_white(Xyz::new(1.0, 0.0, 1.0)).factor(), 0.0);
}

#[test]
fn chroma_map_edge_cases() {
    assert_eq!(reduce_chroma(LinearRgb::new(0.2, 0.9, 0.0)), LinearRgb::new(0.2, 0.9, 0.0));
    assert_eq!(reduce_chroma(LinearRgb::new(-0.5, -0.1, 0.2)), grey(0.0), "Y < 0 is black");
    assert_eq!(reduce_chroma(LinearRgb::new(3.0, 0.8, -0.1)), grey(1.0), "Y > white is white");
    assert_eq!(reduce_chroma(LinearRgb::new(f64::NAN, 2.0, -1.0)), LinearRgb::new(0.0, 1.0, 0.0));
    // Y = 0.648 with red beyond 1: desaturated until red is 1, no further.
    let out = reduce_chroma(LinearRgb::new(1.6, 0.4, 0.3));
    assert!((out.r - 1.0).abs() < 1e-15 && out.g > 0.4 && out.b > 0.3, "{out:?}");
    assert_eq!(clip(LinearRgb::new(1.6, -0.4, f64::NAN)), LinearRgb::new(1.0, 0.0, 0.0));
    // A channel exactly at the grey of equal luminance stays there (no
    // division by its zero offset): g is the fixed point of g = Y(r, g, b)/Y(white).
    let (r, b) = (1.2, 0.0);
    let grey_of = |g: f64| luminance(LinearRgb::new(r, g, b)) / WHITE_LUMINANCE;
    let g = (0..200).fold(0.5, |g, _| grey_of(g));
    assert_eq!(grey_of(g), g, "a fixed point in f64");
    let out = reduce_chroma(LinearRgb::new(r, g, b));
    assert!(in_unit_cube(out) && out.g == g && (out.r - 1.0).abs() < 1e-15, "{out:?}");
}

#[test]
fn srgb8_to_array() {
    assert_eq!(Srgb8::new(1, 2, 3).to_array(), [1, 2, 3]);
}

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(f64::MAX),
        Just(f64::MIN),
        any::<f64>(),
        -2.0..3.0f64,
    ]
}

fn in_unit_cube(c: LinearRgb) -> bool {
    c.to_array().iter().all(|v| (0.0..=1.0).contains(v))
}

/// The offset of `c` from the grey of luminance `y`, as a unit vector, and
/// its length.
fn direction(c: LinearRgb, y: f64) -> ([f64; 3], f64) {
    let g = y / WHITE_LUMINANCE;
    let d = [c.r - g, c.g - g, c.b - g];
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    (d.map(|v| v / len), len)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn every_output_lies_in_the_unit_cube(r in any_f64(), g in any_f64(), b in any_f64()) {
        let c = LinearRgb::new(r, g, b);
        for map in GamutMap::ALL {
            prop_assert!(in_unit_cube(map.apply(c)), "{map:?} {c:?} → {:?}", map.apply(c));
        }
        let display = PixelPipeline::new(Exposure::new(r), GamutMap::Chroma);
        let _pixel: Srgb8 = display.pixel(c);
    }

    #[test]
    fn chroma_map_keeps_luminance_and_hue(
        y in 1e-4..0.9999f64,
        d in prop::array::uniform3(-10.0..10.0f64),
        s in prop_oneof![Just(1.0), 0.0..1.0f64],
    ) {
        // A colour of luminance about y: a grey plus s·d, with d's own luminance removed.
        let ld = luminance(LinearRgb::new(d[0], d[1], d[2])) / WHITE_LUMINANCE;
        let c = LinearRgb::new(y + s * (d[0] - ld), y + s * (d[1] - ld), y + s * (d[2] - ld));
        let y = luminance(c);
        prop_assume!(y > 0.0 && y < WHITE_LUMINANCE);
        let out = reduce_chroma(c);
        prop_assert!(in_unit_cube(out));
        prop_assert!((luminance(out) - y).abs() < LUMINANCE_TOLERANCE, "{c:?} → {out:?}");
        let ((u, _), (v, len)) = (direction(c, y), direction(out, y));
        if len >= HUE_MIN_OFFSET {
            let angle = (u[1] * v[2] - u[2] * v[1]).hypot(u[2] * v[0] - u[0] * v[2]).hypot(u[0] * v[1] - u[1] * v[0]);
            prop_assert!(angle < HUE_TOLERANCE && u[0] * v[0] + u[1] * v[1] + u[2] * v[2] > 0.0, "{c:?} → {out:?}");
        }
        // The least desaturation: an input outside the cube ends on its surface.
        if !in_unit_cube(c) {
            let on_surface = |v: f64| v.abs() < 1e-12 || (1.0 - v).abs() < 1e-12;
            prop_assert!(out.to_array().into_iter().any(on_surface), "{out:?}");
        }
    }
}
