//! Reading: every layer's channels parsed, the first layer with spectral
//! channels read, its channels sorted by wavelength, the layout's
//! attributes checked.

use std::io::{Cursor, Read, Seek, SeekFrom};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use exr::meta::MetaData;
use exr::prelude::{
    AnyChannel, AttributeValue, FlatSamples, ReadChannels, ReadLayers, Text, read as exr_read,
};
use speclab::film::{Kind, SpectralImage};

use crate::channel::{self, Component};
use crate::{ExrError, LAYOUT_VERSION};

/// A spectral image read from a file, with its units and where the file
/// departs from the layout.
#[derive(Clone, Debug, PartialEq)]
pub struct SpectralFile {
    /// The image (the `S0` or `T` channels, by wavelength).
    pub image: SpectralImage,
    /// `emissiveUnits`, for an emissive image that names them.
    pub emissive_units: Option<String>,
    /// What the layout requires and the file lacks, read anyway (empty
    /// for a file in the layout; [`ReadOptions::strict`] refuses these).
    pub departures: Vec<Departure>,
}

/// A departure from the layout that a reader can read through, reported
/// so that nothing is assumed silently.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Departure {
    /// No `spectralLayoutVersion`: read as version 1.0, the only one (what
    /// colour-science's writer makes with its default specification).
    NoLayoutVersion,
    /// An emissive image without `emissiveUnits`: its units are unknown
    /// ([`SpectralFile::emissive_units`] is `None`).
    NoEmissiveUnits,
}

impl std::fmt::Display for Departure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Departure::NoLayoutVersion => "no `spectralLayoutVersion` attribute: read as version 1.0",
            Departure::NoEmissiveUnits => "no `emissiveUnits` attribute: the radiance's units are unknown",
        })
    }
}

/// How a file is read: how many values it may declare, and whether a
/// departure from the layout is an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadOptions {
    /// The most values (pixels × channels, every layer) decoded.
    pub max_values: usize,
    /// Refuse a file that lacks an attribute the layout requires
    /// ([`ExrError::MissingAttribute`]) instead of reporting a
    /// [`Departure`].
    pub strict: bool,
}

impl Default for ReadOptions {
    /// [`DEFAULT_MAX_VALUES`], lenient.
    fn default() -> Self {
        ReadOptions { max_values: DEFAULT_MAX_VALUES, strict: false }
    }
}

impl ReadOptions {
    /// The default limit, every departure an error.
    #[must_use]
    pub fn strict() -> Self {
        ReadOptions { strict: true, ..ReadOptions::default() }
    }
}

/// Reads the spectral image in `path`; errors as [`read_from`], and an
/// [`ExrError::Exr`] if the file cannot be opened.
pub fn read(path: impl AsRef<Path>) -> Result<SpectralFile, ExrError> {
    let bytes = std::fs::read(path).map_err(|e| ExrError::Exr(exr::error::Error::from(e)))?;
    read_from(Cursor::new(bytes))
}

/// The most values (pixels × channels, every layer) [`read_from`] decodes:
/// 2³⁰, 4 GiB of `f32` (a 1920 × 1080 image of 351 channels is 0.7 × 2³⁰).
pub const DEFAULT_MAX_VALUES: usize = 1 << 30;

/// Reads a spectral image from `input` with [`ReadOptions::default`]: an
/// [`ExrError`] naming what is wrong for a file that is not OpenEXR, has
/// no spectral channel, a malformed one, an unknown attribute value, or
/// polarised channels at other wavelengths than `S0`'s; a missing
/// `spectralLayoutVersion` or `emissiveUnits` is a [`Departure`] in the
/// result; [`ExrError::TooLarge`] for a file whose headers declare more
/// than [`DEFAULT_MAX_VALUES`] values.
pub fn read_from(input: impl Read + Seek) -> Result<SpectralFile, ExrError> {
    read_with(input, &ReadOptions::default())
}

/// [`read_from`], decoding at most `max_values` values.
pub fn read_limited(input: impl Read + Seek, max_values: usize) -> Result<SpectralFile, ExrError> {
    read_with(input, &ReadOptions { max_values, ..ReadOptions::default() })
}

/// [`read_from`] as `options` say: the headers are read first, and a file
/// declaring more than `max_values` is refused before anything is
/// allocated for its pixels (a few hundred bytes can declare gigabytes);
/// a strict read refuses every [`Departure`].
///
/// ```
/// use speclab_exr::{Departure, ReadOptions, read_with};
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/colour_reflective_32.exr");
/// let file = read_with(std::fs::File::open(path)?, &ReadOptions::default())?;
/// assert_eq!(file.departures, [Departure::NoLayoutVersion]); // colour-science's default writer
/// assert!(read_with(std::fs::File::open(path)?, &ReadOptions::strict()).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn read_with(mut input: impl Read + Seek, options: &ReadOptions) -> Result<SpectralFile, ExrError> {
    let max_values = options.max_values;
    let io = |e: std::io::Error| ExrError::Exr(exr::error::Error::from(e));
    let start = input.stream_position().map_err(io)?;
    let meta = guarded(|| MetaData::read_from_buffered(&mut input, false))?.map_err(ExrError::Exr)?;
    let declared = meta.headers.iter().try_fold(0usize, |sum, h| {
        h.layer_size
            .0
            .checked_mul(h.layer_size.1)?
            .checked_mul(h.channels.list.len())
            .and_then(|v| v.checked_add(sum))
    });
    match declared {
        Some(values) if values <= max_values => {}
        values => return Err(ExrError::TooLarge { values, max: max_values }),
    }
    input.seek(SeekFrom::Start(start)).map_err(io)?;
    let image = guarded(|| {
        exr_read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .all_layers()
            .all_attributes()
            .from_buffered(input)
    })?
    .map_err(ExrError::Exr)?;
    let mut names = Vec::new();
    for layer in &image.layer_data {
        let spectral = spectral_channels(&layer.channel_data.list)?;
        if spectral.is_empty() {
            names.extend(layer.channel_data.list.iter().map(|c| c.name.to_string()));
            continue;
        }
        let text = |name: &str| {
            let key = Text::from(name);
            let value = layer.attributes.other.get(&key).or_else(|| image.attributes.other.get(&key));
            value.map(|v| match v {
                AttributeValue::Text(t) => Ok(t.to_string()),
                other => Err(format!("{other:?}")),
            })
        };
        return build(layer.size.0, layer.size.1, &layer.channel_data.list, spectral, (text, options.strict));
    }
    Err(ExrError::NoSpectralChannels { found: names })
}

/// `decode()`, a panic in the decoder reported as [`ExrError::Decoder`].
fn guarded<T>(decode: impl FnOnce() -> T) -> Result<T, ExrError> {
    catch_unwind(AssertUnwindSafe(decode)).map_err(|panic| {
        let why = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned());
        ExrError::Decoder(why.unwrap_or_else(|| "a panic".into()))
    })
}

/// `(index, component, λ)` of each spectral channel.
fn spectral_channels(list: &[AnyChannel<FlatSamples>]) -> Result<Vec<(usize, Component, f64)>, ExrError> {
    let mut out = Vec::new();
    for (i, c) in list.iter().enumerate() {
        if let Some((component, lambda)) = channel::parse(&c.name.to_string())? {
            out.push((i, component, lambda));
        }
    }
    Ok(out)
}

type Attribute<'a> = dyn Fn(&str) -> Option<Result<String, String>> + 'a;

fn build(
    width: usize,
    height: usize,
    list: &[AnyChannel<FlatSamples>],
    mut spectral: Vec<(usize, Component, f64)>,
    (text, strict): (impl Fn(&str) -> Option<Result<String, String>>, bool),
) -> Result<SpectralFile, ExrError> {
    let text: &Attribute = &text;
    let mut departures = Vec::new();
    spectral.sort_by(|a, b| a.1.cmp(&b.1).then(a.2.total_cmp(&b.2)));
    let name = |i: usize| list[i].name.to_string();
    for w in spectral.windows(2) {
        if w[0].1 == w[1].1 && w[0].2 == w[1].2 {
            return Err(ExrError::Duplicate { names: [name(w[0].0), name(w[1].0)] });
        }
    }
    let of = |c: Component| spectral.iter().filter(move |s| s.1 == c);
    let (emissive, reflective) = (of(Component::Stokes(0)).count(), of(Component::Reflective).count());
    let kind = match (emissive, reflective) {
        (0, 0) => {
            let (k, found) =
                (spectral[0].1, spectral.iter().filter(|s| s.1 == spectral[0].1).map(|s| s.2).collect());
            let component = if let Component::Stokes(k) = k { format!("S{k}") } else { "T".into() };
            return Err(ExrError::Disagree { component, found, expected: Vec::new() });
        }
        (_, 0) => Kind::Emissive,
        (0, _) => Kind::Reflective,
        _ => return Err(ExrError::Mixed),
    };
    if !check_version(text, strict)? {
        departures.push(Departure::NoLayoutVersion);
    }
    let main = if kind == Kind::Emissive { Component::Stokes(0) } else { Component::Reflective };
    let lambda: Vec<f64> = of(main).map(|s| s.2).collect();
    let mut emissive_units = None;
    if kind == Kind::Emissive {
        polarised(&spectral, &lambda, text)?;
        emissive_units = optional(text, "emissiveUnits", "for emissive (S0) channels", strict)?;
        if emissive_units.is_none() {
            departures.push(Departure::NoEmissiveUnits);
        }
    }
    let columns: Vec<Vec<f32>> = of(main).map(|s| list[s.0].sample_data.values_as_f32().collect()).collect();
    let n = lambda.len();
    let mut values = vec![0.0f32; width * height * n];
    for (i, column) in columns.iter().enumerate() {
        for (p, v) in column.iter().enumerate().take(width * height) {
            values[p * n + i] = *v;
        }
    }
    let image = SpectralImage::new((width, height), kind, lambda, values).map_err(ExrError::Image)?;
    Ok(SpectralFile { image, emissive_units, departures })
}

/// `spectralLayoutVersion` `1.0` (true), or absent and not `strict`
/// (false).
fn check_version(text: &Attribute, strict: bool) -> Result<bool, ExrError> {
    match optional(text, "spectralLayoutVersion", "by the spectral layout", strict)? {
        None => Ok(false),
        Some(version) if version == LAYOUT_VERSION => Ok(true),
        Some(found) => Err(ExrError::Attribute { name: "spectralLayoutVersion", found, expected: "1.0" }),
    }
}

/// A text attribute the layout requires: `None` if absent and not
/// `strict`.
fn optional(
    text: &Attribute,
    name: &'static str,
    because: &'static str,
    strict: bool,
) -> Result<Option<String>, ExrError> {
    match required(text, name, because) {
        Err(ExrError::MissingAttribute { .. }) if !strict => Ok(None),
        other => other.map(Some),
    }
}

/// A text attribute that must be there.
fn required(text: &Attribute, name: &'static str, because: &'static str) -> Result<String, ExrError> {
    match text(name) {
        None => Err(ExrError::MissingAttribute { name, because }),
        Some(Err(found)) => Err(ExrError::Attribute { name, found, expected: "text" }),
        Some(Ok(value)) => Ok(value),
    }
}

/// S1–S3, if any, at S0's wavelengths, with `polarisationHandedness`.
fn polarised(spectral: &[(usize, Component, f64)], lambda: &[f64], text: &Attribute) -> Result<(), ExrError> {
    let mut any = false;
    for k in 1..=3 {
        let found: Vec<f64> = spectral.iter().filter(|s| s.1 == Component::Stokes(k)).map(|s| s.2).collect();
        if found.is_empty() {
            continue;
        }
        any = true;
        if found != lambda {
            return Err(ExrError::Disagree { component: format!("S{k}"), found, expected: lambda.to_vec() });
        }
    }
    if any {
        let handedness = required(text, "polarisationHandedness", "for polarised channels (S1–S3)")?;
        if handedness != "left" && handedness != "right" {
            return Err(ExrError::Attribute {
                name: "polarisationHandedness",
                found: handedness,
                expected: "left or right",
            });
        }
    }
    Ok(())
}
