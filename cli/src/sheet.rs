//! The swatch sheet: [`Swatches`] laid out as one labelled image, as 8-bit
//! sRGB rows ready to be written as PNG (by the `swatches` example;
//! encoding is not the library's business).
//!
//! Layout, top to bottom: a title and a legend; then per light its name,
//! the column labels, and one row per patch (the patch's name, then its
//! swatches, one per column). Labels use a built-in 5 × 7 bitmap font.
//! Sizes are in pixels; [`Layout`] gives the sheet's size and says where
//! each swatch is.
//!
//! ```
//! use speclab_cli::sheet;
//! use speclab_study::{evaluate::scene, experiments::swatches::{self, SwatchOptions}};
//! let (lights, patches) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let settings = SwatchOptions { size: 8, ..SwatchOptions::default() };
//! let swatches = swatches::render(&lights[..1], &patches[..1], &settings)?;
//! let rgb = sheet::draw(&swatches);
//! let layout = sheet::Layout::new(&swatches);
//! assert_eq!(rgb.len(), 3 * layout.width() * layout.height());
//! let (x, y) = layout.swatch_origin(0, 0, 0); // A × E2, reference
//! let at = 3 * (y * layout.width() + x);
//! assert_eq!(rgb[at..at + 3], swatches.swatch(0, 0, 0)[0].to_array());
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use crate::font::{self, GLYPH_HEIGHT};
use speclab_study::display::Srgb8;
use speclab_study::experiments::swatches::Swatches;

/// Space around the sheet.
pub const MARGIN: usize = 16;
/// Space between swatches, and between a label and what it names.
pub const GAP: usize = 10;
/// Background: a dark neutral grey, so no colour is judged against a tint.
pub const BACKGROUND: Srgb8 = Srgb8::new(40, 40, 40);
/// Ink of the labels.
pub const INK: Srgb8 = Srgb8::new(225, 225, 225);
/// Ink of the legend: dimmer, so the labels stand out.
pub const LEGEND_INK: Srgb8 = Srgb8::new(165, 165, 165);
/// Scale of titles and row names (the column labels are at 1).
const BIG: usize = 2;
/// Height of a line of text at scale 1, with its spacing.
const LINE: usize = GLYPH_HEIGHT + 4;

/// The sheet being drawn: 8-bit sRGB, row-major, three bytes per pixel.
struct Image {
    width: usize,
    height: usize,
    rgb: Vec<u8>,
}

impl Image {
    /// `width × height` pixels of `colour`.
    fn new(width: usize, height: usize, colour: Srgb8) -> Image {
        Image { width, height, rgb: colour.to_array().repeat(width * height) }
    }

    /// Sets the pixel at `(x, y)`; nothing outside the image.
    fn set(&mut self, x: usize, y: usize, colour: Srgb8) {
        if x < self.width && y < self.height {
            let i = 3 * (y * self.width + x);
            self.rgb[i..i + 3].copy_from_slice(&colour.to_array());
        }
    }

    /// Draws `text` with its top left corner at `(x, y)`, each font pixel
    /// a `scale × scale` square; what falls outside the image is cut.
    fn text(&mut self, x: usize, y: usize, text: &str, scale: usize, colour: Srgb8) {
        for (i, c) in text.chars().enumerate() {
            let glyph = font::glyph(c);
            let left = x + i * font::ADVANCE * scale;
            for (gx, gy) in (0..font::GLYPH_WIDTH).flat_map(|gx| (0..GLYPH_HEIGHT).map(move |gy| (gx, gy))) {
                if font::ink(glyph, gx, gy) {
                    for (dx, dy) in (0..scale).flat_map(|dx| (0..scale).map(move |dy| (dx, dy))) {
                        self.set(left + gx * scale + dx, y + gy * scale + dy, colour);
                    }
                }
            }
        }
    }
}

/// Where everything goes on the sheet.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Layout {
    size: usize,
    lights: usize,
    patches: usize,
    columns: usize,
    /// Left edge of the first column.
    left: usize,
    /// Distance between columns: the swatch or its widest label, and a gap.
    pitch: usize,
    /// Width of the title or the legend, whichever is wider.
    header: usize,
    /// Top of the first light's section.
    top: usize,
    /// Height of a light's section.
    section: usize,
}

/// Lines of the legend under the title.
const LEGEND_LINES: usize = 4;

/// The title and the legend.
fn header(s: &Swatches) -> (&'static str, [String; LEGEND_LINES]) {
    let t = &s.settings;
    let balance = if t.white_balance { "BRADFORD TO D65" } else { "OFF" };
    let legend = [
        format!("N={} SAMPLES PER ESTIMATE, M={} BUCKETS, SEED {}.", t.n, t.m, t.seed),
        format!(
            "EXPOSURE: EACH LIGHT'S WHITE JUST FITS. WHITE BALANCE {balance}. GAMUT MAP {}.",
            t.gamut.to_string().to_uppercase()
        ),
        "RANDOM AND HERO: EACH PIXEL IS ONE ESTIMATE, SO GRAIN IS NOISE.".to_string(),
        "FLAT SWATCHES ARE EXACT OR BIASED: COMPARE THEM WITH THE REFERENCE.".to_string(),
    ];
    ("SPECLAB: LIGHT × PATCH BY METHOD", legend)
}

impl Layout {
    /// The layout of `s`.
    #[must_use]
    pub fn new(s: &Swatches) -> Layout {
        let size = s.settings.size;
        let names = s.patches.iter().map(|p| font::text_width(p, BIG)).max().unwrap_or(0);
        let labels = s.columns.iter().flat_map(|c| c.label()).map(|l| font::text_width(&l, 1)).max();
        let top = MARGIN + GLYPH_HEIGHT * BIG + GAP + LEGEND_LINES * LINE + GAP;
        let (title, legend) = header(s);
        let legend = legend.iter().map(|l| font::text_width(l, 1)).max().unwrap_or(0);
        Layout {
            header: font::text_width(title, BIG).max(legend),
            size,
            lights: s.lights.len(),
            patches: s.patches.len(),
            columns: s.columns.len(),
            left: MARGIN + names + GAP,
            pitch: size.max(labels.unwrap_or(0)) + GAP,
            top,
            section: GLYPH_HEIGHT * BIG + GAP / 2 + 3 * LINE + s.patches.len() * (size + GAP) + 2 * GAP,
        }
    }

    /// Image width.
    #[must_use]
    pub fn width(&self) -> usize {
        (self.left + self.columns * self.pitch).saturating_sub(GAP).max(MARGIN + self.header) + MARGIN
    }

    /// Image height.
    #[must_use]
    pub fn height(&self) -> usize {
        (self.top + self.lights * self.section + MARGIN).saturating_sub(3 * GAP)
    }

    /// Top of light `light`'s section (its name).
    fn section_top(&self, light: usize) -> usize {
        self.top + light * self.section
    }

    /// Top left corner of the swatch of `light × patch` in `column`.
    #[must_use]
    pub fn swatch_origin(&self, light: usize, patch: usize, column: usize) -> (usize, usize) {
        let rows = self.section_top(light) + GLYPH_HEIGHT * BIG + GAP / 2 + 3 * LINE;
        (self.left + column * self.pitch, rows + patch * (self.size + GAP))
    }
}

/// The sheet of `s`: title, legend, and per light its labelled swatches,
/// as 8-bit sRGB (R, G, B per pixel, rows top to bottom) of
/// [`Layout::width`] × [`Layout::height`] pixels.
#[must_use]
pub fn draw(s: &Swatches) -> Vec<u8> {
    let layout = Layout::new(s);
    let mut image = Image::new(layout.width(), layout.height(), BACKGROUND);
    let (title, legend) = header(s);
    image.text(MARGIN, MARGIN, title, BIG, INK);
    for (i, line) in legend.iter().enumerate() {
        image.text(MARGIN, MARGIN + GLYPH_HEIGHT * BIG + GAP + i * LINE, line, 1, LEGEND_INK);
    }
    for (l, light) in s.lights.iter().enumerate() {
        let top = layout.section_top(l);
        image.text(MARGIN, top, &format!("LIGHT {light}"), BIG, INK);
        for (c, column) in s.columns.iter().enumerate() {
            let (x, _) = layout.swatch_origin(l, 0, c);
            for (i, line) in column.label().iter().enumerate() {
                image.text(x, top + GLYPH_HEIGHT * BIG + GAP / 2 + i * LINE, line, 1, INK);
            }
        }
        for (p, patch) in s.patches.iter().enumerate() {
            let (_, y) = layout.swatch_origin(l, p, 0);
            image.text(MARGIN, y + s.settings.size.saturating_sub(GLYPH_HEIGHT * BIG) / 2, patch, BIG, INK);
            for c in 0..s.columns.len() {
                paste(&mut image, &layout, s, (l, p, c));
            }
        }
    }
    image.rgb
}

/// Copies one swatch into its place.
fn paste(image: &mut Image, layout: &Layout, s: &Swatches, (l, p, c): (usize, usize, usize)) {
    let size = s.settings.size;
    let (x0, y0) = layout.swatch_origin(l, p, c);
    for (i, &pixel) in s.swatch(l, p, c).iter().enumerate() {
        image.set(x0 + i % size, y0 + i / size, pixel);
    }
}
