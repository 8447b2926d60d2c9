//! PNG output for the programs: the library makes pixels, encoding them
//! is the front end's business.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// An 8-bit sRGB image: `width × height` pixels, R, G, B each, rows top
/// to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// `3 × width × height` bytes: R, G, B per pixel, rows top to bottom.
    pub rgb: Vec<u8>,
}

impl Image {
    /// The pixel at `(x, y)`, or `None` outside the image.
    pub fn pixel(&self, x: usize, y: usize) -> Option<[u8; 3]> {
        let i = 3 * (y * self.width + x);
        (x < self.width && y < self.height).then(|| [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]])
    }
}

/// Writes `image` as an 8-bit RGB PNG tagged sRGB (perceptual intent).
pub fn write(out: impl Write, image: &Image) -> io::Result<()> {
    let size = |n: usize| u32::try_from(n).map_err(|_| io::Error::other("image too large for PNG"));
    let mut encoder = png::Encoder::new(out, size(image.width)?, size(image.height)?);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header().map_err(io::Error::other)?;
    writer.write_image_data(&image.rgb).map_err(io::Error::other)?;
    writer.finish().map_err(io::Error::other)
}

/// [`write()`] to the file at `path`.
pub fn write_file(path: &Path, image: &Image) -> io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    write(&mut out, image)?;
    out.flush()
}
