//! The swatch sheet end to end: a tiny configuration rendered, drawn,
//! written by the `swatches` example's PNG writer and decoded again. Its
//! size is the layout's, its reference and bucket swatches are flat and
//! carry the pixel the display pipeline gives the exact colour, and every
//! pixel of a Monte Carlo swatch is its own estimate, seeded reproducibly.

#![cfg(feature = "study")]

#[path = "../examples/common/png.rs"]
mod png_file;

use std::num::NonZeroUsize;

use rand::SeedableRng;
use rand::rngs::StdRng;
use speclab::color::display::{Display, Exposure, GamutMap, Srgb8};
use speclab::sampling::reference;
use speclab::study::method::{Method, derive_seed};
use speclab::study::scene::{Named, builtin_lights, builtin_surfaces};
use speclab::study::sheet::{self, Image, Layout};
use speclab::study::swatches::{self, Settings, Swatches};

fn nz(n: usize) -> NonZeroUsize {
    NonZeroUsize::new(n).unwrap()
}

/// D65 and F11 × G4 (out of gamut) and A1 (white), 6 × 6 swatches.
fn tiny() -> (Vec<Named>, Vec<Named>, Settings) {
    let lights: Vec<Named> = builtin_lights().into_iter().skip(1).collect();
    let patches: Vec<Named> =
        builtin_surfaces().into_iter().filter(|p| p.name == "G4" || p.name == "A1").collect();
    let settings = Settings { n: nz(4), m: nz(8), seed: 7, size: 6, ..Settings::default() };
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
    (0..size * size).map(|i| image.pixel(x0 + i % size, y0 + i / size).unwrap()).collect()
}

#[test]
fn tiny_sheet_png_has_the_layout_size_and_the_exact_colours() {
    let (lights, patches, settings) = tiny();
    let swatches = swatches::render(&lights, &patches, &settings).unwrap();
    let mut bytes = Vec::new();
    png_file::write(&mut bytes, &sheet::draw(&swatches)).unwrap();
    let image = decode(&bytes);
    let layout = Layout::new(&swatches);
    assert_eq!((image.width, image.height), (layout.width(), layout.height()));
    for (l, light) in lights.iter().enumerate() {
        let display = Display::new(Exposure::fit_white(reference::white(&light.spectrum)), GamutMap::Chroma);
        for (p, patch) in patches.iter().enumerate() {
            let exact = display.pixel(reference::xyz(&light.spectrum, &patch.spectrum).to_linear_srgb());
            assert!(
                square(&image, &layout, (l, p, 0), 6).iter().all(|&px| px == exact),
                "{} × {}",
                light.name,
                patch.name
            );
            let boxed = Method::RegularBox.xyz(&light.spectrum, &patch.spectrum, nz(8), 0).unwrap();
            let boxed = display.pixel(boxed.to_linear_srgb());
            assert!(square(&image, &layout, (l, p, 4), 6).iter().all(|&px| px == boxed));
        }
    }
    // Regression snapshot (computed by this code, not published): D65 × G4,
    // out of gamut (green < 0), shown on the gamut's edge.
    assert_eq!(square(&image, &layout, (0, 0, 0), 6)[0], Srgb8::new(164, 0, 36));
}

#[test]
fn every_monte_carlo_pixel_is_its_own_seeded_estimate() {
    let (lights, patches, settings) = tiny();
    let swatches: Swatches = swatches::render(&lights, &patches, &settings).unwrap();
    assert_eq!(swatches, swatches::render(&lights, &patches, &settings).unwrap(), "reproducible");
    let (light, patch) = (&lights[1].spectrum, &patches[0].spectrum); // F11 × G4
    let display = Display::new(Exposure::fit_white(reference::white(light)), GamutMap::Chroma);
    let (l, p, c) = (1, 0, 2); // F11 × G4, hero
    let hero = swatches.swatch(l, p, c);
    // Swatch number ((light × patches) + patch) × columns + column; 36 pixels each.
    let first = ((l * patches.len() + p) * swatches.columns.len() + c) * 36;
    for (i, &pixel) in hero.iter().enumerate() {
        let mut rng = StdRng::seed_from_u64(derive_seed(7, (first + i) as u64));
        let xyz = Method::HERO.prepare(light).unwrap().xyz_with_rng(patch, nz(4), &mut rng).unwrap();
        assert_eq!(pixel, display.pixel(xyz.to_linear_srgb()), "pixel {i}");
    }
    let distinct = |s: &[Srgb8]| s.iter().filter(|&&p| p != s[0]).count();
    assert!(distinct(hero) > 18 && distinct(swatches.swatch(1, 0, 1)) > 18, "noise is visible");
    assert_eq!(distinct(swatches.swatch(1, 0, 3)), 0, "centre buckets are flat");
}

#[test]
fn bad_settings_are_errors_or_empty_not_panics() {
    let (lights, patches, settings) = tiny();
    let too_many = Settings { m: nz(65), ..settings };
    assert!(swatches::render(&lights, &patches, &too_many).is_err());
    let empty = swatches::render(&lights, &patches, &Settings { size: 0, ..settings }).unwrap();
    assert!(empty.swatch(0, 0, 0).is_empty() && empty.swatch(9, 0, 0).is_empty());
    let image = sheet::draw(&empty);
    assert_eq!(image.rgb.len(), 3 * image.width * image.height);
    let none = swatches::render(&[], &patches, &settings).unwrap();
    assert_eq!(sheet::draw(&none).height, Layout::new(&none).height());
}
