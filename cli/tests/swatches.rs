//! The swatch sheet end to end: a tiny configuration rendered, drawn,
//! written by the programs' PNG writer (`speclab_cli::png`) and decoded again. Its
//! size is the layout's, its reference and bucket swatches are flat and
//! carry the pixel the display pipeline gives the exact colour, and every
//! pixel of a Monte Carlo swatch is its own estimate, seeded reproducibly.

use std::num::NonZeroUsize;

use speclab::LinearRgb;
use speclab::sampling::reference;
use speclab_cli::png as png_file;
use speclab_cli::png::Image;
use speclab_cli::sheet::{self, Layout};
use speclab_study::display::EncodedSrgb;
use speclab_study::display::{Exposure, GamutMap, PixelPipeline, Srgb8};
use speclab_study::evaluate::method::Method;
use speclab_study::evaluate::scene::{Named, builtin_lights, builtin_surfaces};
use speclab_study::experiments::swatches::{self, SwatchOptions};

fn nz(n: usize) -> NonZeroUsize {
    NonZeroUsize::new(n).unwrap()
}

/// D65 and F11 × G4 (out of gamut) and A1 (white), 6 × 6 swatches.
fn tiny() -> (Vec<Named>, Vec<Named>, SwatchOptions) {
    let lights: Vec<Named> = builtin_lights().into_iter().skip(1).collect();
    let patches: Vec<Named> =
        builtin_surfaces().into_iter().filter(|p| p.name == "G4" || p.name == "A1").collect();
    let settings = SwatchOptions { n: nz(4), m: nz(8), seed: 7, size: 6, ..SwatchOptions::default() };
    (lights, patches, settings)
}

fn decode(bytes: &[u8]) -> Image {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().unwrap();
    let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut rgb).unwrap();
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgb, png::BitDepth::Eight));
    rgb.truncate(info.buffer_size());
    Image { width: info.width as usize, height: info.height as usize, rgb }
}

/// Every pixel of a swatch's square in `image`.
fn square(image: &Image, layout: &Layout, (l, p, c): (usize, usize, usize), size: usize) -> Vec<Srgb8> {
    let (x0, y0) = layout.swatch_origin(l, p, c);
    let at = |i: usize| image.pixel(x0 + i % size, y0 + i / size).unwrap();
    (0..size * size).map(at).map(|[r, g, b]| Srgb8::new(r, g, b)).collect()
}

#[test]
fn tiny_sheet_png_has_the_layout_size_and_the_exact_colours() {
    let (lights, patches, settings) = tiny();
    let swatches = swatches::render(&lights, &patches, &settings).unwrap();
    let layout = Layout::new(&swatches);
    let sheet = Image { width: layout.width(), height: layout.height(), rgb: sheet::draw(&swatches) };
    let mut bytes = Vec::new();
    png_file::write(&mut bytes, &sheet).unwrap();
    let image = decode(&bytes);
    assert_eq!((image.width, image.height), (layout.width(), layout.height()));
    for (l, light) in lights.iter().enumerate() {
        let display =
            PixelPipeline::new(Exposure::fit_white(reference::white(&light.spectrum)), GamutMap::Chroma);
        for (p, patch) in patches.iter().enumerate() {
            let exact = display.pixel(reference::xyz(&light.spectrum, &patch.spectrum).to_linear_srgb());
            assert!(
                square(&image, &layout, (l, p, 0), 6).iter().all(|&px| px == exact),
                "{} × {}",
                light.name,
                patch.name
            );
            let boxed = Method::BOX.xyz(&light.spectrum, &patch.spectrum, nz(8), 0).unwrap();
            let boxed = display.pixel(boxed.to_linear_srgb());
            assert!(square(&image, &layout, (l, p, 4), 6).iter().all(|&px| px == boxed));
        }
    }
    // Regression snapshot (computed by this code, not published): D65 × G4,
    // out of gamut (green < 0), shown on the gamut's edge.
    assert_eq!(square(&image, &layout, (0, 0, 0), 6)[0], Srgb8::new(164, 0, 36));
}

/// Every pixel of a Monte Carlo swatch is its own estimate of the exact
/// colour: decoded back to linear sRGB, the pixels of D65 × E2 (in gamut,
/// dark: no clipping) average to the exact colour within 4 standard errors
/// of their mean plus half an 8-bit step, and they differ from each other.
/// A swatch whose pixels repeated one estimate would have no spread and
/// miss the exact colour; one biased estimator would miss it by its bias.
#[test]
fn every_monte_carlo_pixel_is_its_own_estimate() {
    let d65: Vec<Named> = builtin_lights().into_iter().filter(|l| l.name == "D65").collect();
    let e2: Vec<Named> = builtin_surfaces().into_iter().filter(|p| p.name == "E2").collect();
    let options = SwatchOptions { n: nz(16), seed: 3, size: 32, ..SwatchOptions::default() };
    let swatches = swatches::render(&d65, &e2, &options).unwrap();
    assert_eq!(swatches, swatches::render(&d65, &e2, &options).unwrap(), "reproducible");
    let (light, patch) = (&d65[0].spectrum, &e2[0].spectrum);
    let factor = Exposure::fit_white(reference::white(light)).factor();
    let exact = reference::xyz(light, patch).to_linear_srgb() * factor;
    for column in [1, 2, 5, 6] {
        let pixels: Vec<LinearRgb> =
            swatches.swatch(0, 0, column).iter().map(|p| p.to_encoded().decode()).collect();
        let count = pixels.len() as f64;
        let mean = pixels.iter().copied().sum::<LinearRgb>() / count;
        let var = pixels.iter().map(|&p| (p - mean) * (p - mean)).sum::<LinearRgb>() / (count - 1.0);
        for ((m, v), x) in mean.to_array().into_iter().zip(var.to_array()).zip(exact.to_array()) {
            let half_step = |x: f64| {
                let code = EncodedSrgb::encode(LinearRgb::splat(x)).r;
                EncodedSrgb { r: code + 0.5 / 255.0, g: 0.0, b: 0.0 }.decode().r - x
            };
            let bound = 4.0 * (v / count).sqrt() + half_step(x);
            assert!(v > 0.0, "column {column}: the pixels differ");
            assert!((m - x).abs() < bound, "column {column}: mean {m} vs exact {x} (± {bound})");
        }
    }
    let distinct = |s: &[Srgb8]| s.iter().filter(|&&p| p != s[0]).count();
    assert_eq!(distinct(swatches.swatch(0, 0, 3)), 0, "center buckets are flat");
}

#[test]
fn bad_settings_are_errors_or_empty_not_panics() {
    let (lights, patches, settings) = tiny();
    let too_many = SwatchOptions { m: nz(65), ..settings };
    assert!(swatches::render(&lights, &patches, &too_many).is_err());
    let empty = swatches::render(&lights, &patches, &SwatchOptions { size: 0, ..settings }).unwrap();
    assert!(empty.swatch(0, 0, 0).is_empty() && empty.swatch(9, 0, 0).is_empty());
    let layout = Layout::new(&empty);
    assert_eq!(sheet::draw(&empty).len(), 3 * layout.width() * layout.height());
    let none = swatches::render(&[], &patches, &settings).unwrap();
    let layout = Layout::new(&none);
    assert_eq!(sheet::draw(&none).len(), 3 * layout.width() * layout.height());
}
