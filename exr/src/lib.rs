//! Spectral OpenEXR images in the layout of Fichet, Pacanowski and Wilkie
//! ("An OpenEXR Layout for Spectral Images", JCGT 10(3), 2021), read into
//! and written from speclab's [`SpectralImage`]: what pbrt-v4's
//! `SpectralFilm` writes and colour-science reads.
//!
//! - Emissive images: one channel per wavelength, `S0.<λ>nm` (a comma as
//!   decimal mark: `S0.374,688nm`), spectral radiance, with the attributes
//!   `spectralLayoutVersion` (`"1.0"`) and `emissiveUnits`
//!   (`"W.m^-2.sr^-1"`). `S1`–`S3` (polarisation) are checked and not read.
//! - Reflective images: `T.<λ>nm`, with `spectralLayoutVersion`.
//! - An RGB preview (`R`, `G`, `B`) for viewers that know nothing of
//!   spectra, if the writer gives one; ignored when read.
//!
//! Reading sorts the channels by wavelength (OpenEXR stores them sorted
//! by name, so `S0.1000nm` comes before `S0.380nm`); a malformed channel
//! name, two channels at one wavelength, or Stokes components whose
//! wavelengths disagree with `S0`'s is an [`ExrError`] naming it. Files
//! other writers make without `spectralLayoutVersion` or `emissiveUnits`
//! (colour-science's with its default specification) are read, and what
//! they lack is reported ([`SpectralFile::departures`]);
//! [`ReadOptions::strict`] refuses them. Reading never panics on a file (`fuzz/`, target
//! `spectral_exr`).
//!
//! ```
//! use speclab::film::{Kind, SpectralImage};
//! use speclab_exr::{Precision, WriteOptions};
//!
//! let image = SpectralImage::new((2, 1), Kind::Emissive, vec![450.0, 550.5, 650.0], vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0])?;
//! let mut file = std::io::Cursor::new(Vec::new());
//! speclab_exr::write_to(&mut file, &image, &WriteOptions::default())?;
//! let read = speclab_exr::read_from(std::io::Cursor::new(file.into_inner()))?;
//! assert_eq!(read.image, image);
//! assert_eq!(read.emissive_units.as_deref(), Some("W.m^-2.sr^-1"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod channel;
mod error;
mod read;

use std::io::{Seek, Write};
use std::path::Path;

use exr::prelude::f16;
use exr::prelude::{
    AnyChannel, AnyChannels, AttributeValue, Encoding, FlatSamples, Image, Layer, LayerAttributes, Text,
    WritableImage,
};
use speclab::film::{Kind, SpectralImage};

pub use channel::Component;
pub use error::ExrError;
pub use read::{
    DEFAULT_MAX_VALUES, Departure, ReadOptions, SpectralFile, read, read_from, read_limited, read_with,
};

/// The layout version this crate writes and reads.
pub const LAYOUT_VERSION: &str = "1.0";

/// How the spectral channels are stored.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Precision {
    /// 32-bit floats: read back bit for bit.
    #[default]
    F32,
    /// 16-bit floats: half the file; a relative error of at most 2⁻¹¹
    /// (0.049 %) for values in f16's normal range (6.1e-5 to 65504),
    /// larger below it, and infinity above.
    F16,
}

/// What to write besides the spectral channels.
#[derive(Clone, Debug, PartialEq)]
pub struct WriteOptions {
    /// The spectral channels' precision.
    pub precision: Precision,
    /// An RGB preview, one `[r, g, b]` per pixel (linear, in the caller's
    /// space), written as `R`, `G`, `B`.
    pub preview: Option<Vec<[f32; 3]>>,
    /// `emissiveUnits` for an emissive image.
    pub emissive_units: String,
}

impl Default for WriteOptions {
    fn default() -> Self {
        WriteOptions { precision: Precision::F32, preview: None, emissive_units: "W.m^-2.sr^-1".into() }
    }
}

/// Writes `image` to `path` (ZIP-compressed, lossless); errors as
/// [`write_to`].
pub fn write(path: impl AsRef<Path>, image: &SpectralImage, options: &WriteOptions) -> Result<(), ExrError> {
    let layer = layer(image, options)?;
    Image::from_layer(layer).write().to_file(path).map_err(ExrError::Exr)
}

/// Writes `image` to `out`; an [`ExrError::Preview`] for a preview of
/// another size than the image, an [`ExrError::Exr`] if writing fails.
pub fn write_to(
    out: impl Write + Seek,
    image: &SpectralImage,
    options: &WriteOptions,
) -> Result<(), ExrError> {
    let layer = layer(image, options)?;
    Image::from_layer(layer).write().to_buffered(out).map_err(ExrError::Exr)
}

type Channels = AnyChannels<FlatSamples>;

fn layer(image: &SpectralImage, options: &WriteOptions) -> Result<Layer<Channels>, ExrError> {
    let (width, height) = image.size();
    let n = image.wavelengths().len();
    let component = match image.kind() {
        Kind::Emissive => Component::Stokes(0),
        Kind::Reflective => Component::Reflective,
    };
    let samples = |values: Vec<f32>| match options.precision {
        Precision::F32 => FlatSamples::F32(values),
        Precision::F16 => FlatSamples::F16(values.into_iter().map(f16::from_f32).collect()),
    };
    let mut list: Vec<AnyChannel<FlatSamples>> = Vec::with_capacity(n + 3);
    for (i, &lambda) in image.wavelengths().iter().enumerate() {
        let values: Vec<f32> = image.values().iter().skip(i).step_by(n).copied().collect();
        list.push(AnyChannel::new(channel::name(component, lambda).as_str(), samples(values)));
    }
    if let Some(preview) = &options.preview {
        if preview.len() != width * height {
            return Err(ExrError::Preview { found: preview.len(), expected: width * height });
        }
        for (c, name) in ["R", "G", "B"].into_iter().enumerate() {
            list.push(AnyChannel::new(name, FlatSamples::F32(preview.iter().map(|p| p[c]).collect())));
        }
    }
    let mut attributes = LayerAttributes::default();
    let mut set = |name: &'static str, value: &str| {
        let text = Text::new_or_none(value).ok_or(ExrError::Attribute {
            name,
            found: value.into(),
            expected: "Latin-1 text",
        })?;
        attributes.other.insert(Text::from(name), AttributeValue::Text(text));
        Ok::<(), ExrError>(())
    };
    set("spectralLayoutVersion", LAYOUT_VERSION)?;
    if image.kind() == Kind::Emissive {
        set("emissiveUnits", &options.emissive_units)?;
    }
    let channels = AnyChannels::sort(list.into());
    Ok(Layer::new((width, height), attributes, Encoding::SMALL_LOSSLESS, channels))
}
