//! What can go wrong reading or writing a spectral OpenEXR file.

use std::fmt;

/// An error reading or writing a spectral image, naming what is wrong.
#[derive(Debug)]
#[non_exhaustive]
pub enum ExrError {
    /// The file could not be read or written as OpenEXR (the `exr`
    /// crate's message).
    Exr(exr::error::Error),
    /// A channel named like a spectral one that does not follow the
    /// layout's grammar.
    ChannelName {
        /// The channel's name.
        name: String,
        /// What was expected.
        why: String,
    },
    /// A required attribute that is absent.
    MissingAttribute {
        /// Its name, e.g. `emissiveUnits`.
        name: &'static str,
        /// Why it is required.
        because: &'static str,
    },
    /// An attribute with a value this reader does not take.
    Attribute {
        /// Its name.
        name: &'static str,
        /// The value found.
        found: String,
        /// What was expected.
        expected: &'static str,
    },
    /// No `S0.<λ>nm` or `T.<λ>nm` channel.
    NoSpectralChannels {
        /// The channels found.
        found: Vec<String>,
    },
    /// Both emissive and reflective channels in one image.
    Mixed,
    /// Two channels of one component at the same wavelength.
    Duplicate {
        /// The two channels' names.
        names: [String; 2],
    },
    /// A Stokes component whose wavelengths are not `S0`'s.
    Disagree {
        /// The component, e.g. `S1`.
        component: String,
        /// Its wavelengths, nm.
        found: Vec<f64>,
        /// `S0`'s, nm.
        expected: Vec<f64>,
    },
    /// A preview of another size than the image.
    Preview {
        /// The preview's pixels.
        found: usize,
        /// The image's.
        expected: usize,
    },
    /// The image read does not form a spectral image (speclab's message).
    Image(speclab::Error),
    /// A file whose headers declare more values than the reader decodes.
    TooLarge {
        /// The values declared (pixels × channels), `None` past `usize`.
        values: Option<usize>,
        /// The most the reader takes.
        max: usize,
    },
    /// The OpenEXR decoder panicked on this file (reported, not passed on).
    Decoder(String),
}

impl fmt::Display for ExrError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExrError::Exr(e) => write!(f, "OpenEXR: {e}"),
            ExrError::ChannelName { name, why } => write!(f, "channel `{name}`: expected {why}"),
            ExrError::MissingAttribute { name, because } => {
                write!(f, "missing attribute `{name}`: required {because}")
            }
            ExrError::Attribute { name, found, expected } => {
                write!(f, "attribute `{name}`: expected {expected}, found {found:?}")
            }
            ExrError::NoSpectralChannels { found } => write!(
                f,
                "no spectral channel: expected S0.<λ>nm or T.<λ>nm (a comma as decimal mark), found {}",
                if found.is_empty() { "no channels".into() } else { found.join(", ") }
            ),
            ExrError::Mixed => {
                f.write_str("both emissive (S0.…) and reflective (T.…) channels: expected one kind")
            }
            ExrError::Duplicate { names: [a, b] } => {
                write!(f, "channels `{a}` and `{b}` are at the same wavelength")
            }
            ExrError::Disagree { component, found, expected } => write!(
                f,
                "the wavelengths of {component} disagree with S0's: {component} has {} ({:?} nm), S0 has {} ({:?} nm)",
                found.len(),
                found,
                expected.len(),
                expected
            ),
            ExrError::Preview { found, expected } => {
                write!(f, "a preview of {found} pixels for an image of {expected}")
            }
            ExrError::Image(e) => write!(f, "{e}"),
            ExrError::TooLarge { values, max } => match values {
                Some(v) => {
                    write!(f, "the file declares {v} values (pixels × channels): expected at most {max}")
                }
                None => write!(f, "the file declares more values than memory holds: expected at most {max}"),
            },
            ExrError::Decoder(why) => write!(f, "the OpenEXR decoder failed on this file: {why}"),
        }
    }
}

impl std::error::Error for ExrError {}
