//! PNG output for the examples (the `png` crate is a dev-dependency: the
//! library makes pixels, encoding them is the front end's business).

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use speclab::study::sheet::Image;

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

/// [`write`] to the file at `path`.
#[allow(dead_code)] // the tests write to memory
pub fn write_file(path: &Path, image: &Image) -> io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    write(&mut out, image)?;
    out.flush()
}
