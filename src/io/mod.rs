//! Reading spectra that users measured or downloaded.
//!
//! Three formats ([`Format`]), told apart by content (not by file name):
//! - the assignment's brace notation, `{380, 0.04}, {385, 0.05}, ...`;
//! - JSON, `{"wavelengths": [...], "values": [...]}`;
//! - two-column text: CSV, TSV or whitespace, with `#` comments and an
//!   optional header.
//!
//! The parsers live in the std-only `speclab-tables` crate, so that build
//! scripts read files exactly as [`Load`] does. **A new input format** is
//! a parser there (`tables/src/brace.rs` is one), plus a variant of
//! [`Format`] (and a rule in `Format::detect`); validation, positions in
//! errors and the range check come for free.
//!
//! Samples are validated for their [`Role`] (see
//! [`crate::spectrum::validate`]), and a loaded spectrum **must cover the
//! integration range** 380–730 nm: a lamp file that stops at 700 nm is an
//! error, not a silently darker colour. (A spectrum built in code with
//! [`TabulatedSpectrum::new`] is instead zero outside its samples.) Files
//! and streams larger than [`MAX_BYTES`] are refused, and so is a
//! light with no power in the range. Every error names the source, line and
//! column.
//!
//! ```
//! use speclab::io::Load;
//! use speclab::Role;
//! let text = "nm,power\n380,1\n730,2\n";
//! let lamp = Load::new(Role::Light).text(text, "lamp.csv")?;
//! assert_eq!(lamp.eval(555.0), 1.5);
//! let short = Load::new(Role::Light).text("380,1\n700,2\n", "short.csv").unwrap_err();
//! assert_eq!(short.to_string(), "short.csv:2:1: expected samples covering 380-730 nm, found 380-700 nm");
//! # Ok::<(), speclab::Error>(())
//! ```

use std::path::Path;

#[doc(no_inline)]
pub use speclab_tables::read::{Extend, Format, MAX_BYTES};

use crate::error::Error;
use crate::spectrum::{Interpolation, Role, TabulatedSpectrum};

/// How to load: the role, the interpolation (by default the role's), the
/// format (by default detected) and what to do with samples short of
/// 380–730 nm (by default refuse them: [`Extend`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Load {
    /// What the spectrum is; sets validation and clamping.
    pub role: Role,
    /// How to interpolate.
    pub interpolation: Interpolation,
    /// The format, or `None` to detect it.
    pub format: Option<Format>,
    /// Samples short of 380–730 nm: refused, zero outside, or their end
    /// values held to 360–830 nm.
    pub extend: Extend,
}

impl Load {
    /// Loading as `role`, with its interpolation and a detected format.
    #[must_use]
    pub fn new(role: Role) -> Self {
        Load { role, interpolation: role.interpolation(), format: None, extend: Extend::Refuse }
    }

    /// The same, with `interpolation` stated explicitly.
    #[must_use]
    pub fn with_interpolation(self, interpolation: Interpolation) -> Self {
        Load { interpolation, ..self }
    }

    /// The same, with the format stated explicitly.
    #[must_use]
    pub fn with_format(self, format: Format) -> Self {
        Load { format: Some(format), ..self }
    }

    /// The same, with samples short of 380–730 nm treated as `extend` says.
    ///
    /// ```
    /// use speclab::{Role, io::{Extend, Load}};
    /// let cornell = "400,0.5\n500,0.6\n600,0.7\n700,0.8\n";
    /// assert!(Load::new(Role::Reflectance).text(cornell, "box.csv").is_err());
    /// let held = Load::new(Role::Reflectance).with_extend(Extend::Hold).text(cornell, "box.csv")?;
    /// assert_eq!((held.eval(360.0), held.eval(830.0)), (0.5, 0.8));
    /// let zero = Load::new(Role::Reflectance).with_extend(Extend::Zero).text(cornell, "box.csv")?;
    /// assert_eq!((zero.eval(390.0), zero.eval(400.0)), (0.0, 0.5));
    /// # Ok::<(), speclab::Error>(())
    /// ```
    #[must_use]
    pub fn with_extend(self, extend: Extend) -> Self {
        Load { extend, ..self }
    }

    /// A spectrum from `text`; `origin` names it in errors.
    pub fn text(&self, text: &str, origin: &str) -> Result<TabulatedSpectrum, Error> {
        let (role, interpolation, format) = (self.role, self.interpolation, self.format);
        let s = speclab_tables::read::samples_with(text, origin, role, interpolation, format, self.extend)?;
        Ok(TabulatedSpectrum::from_validated(s.lambda, s.values, self.role, self.interpolation))
    }

    /// A spectrum from the file at `path` (at most [`MAX_BYTES`]).
    pub fn file(&self, path: impl AsRef<Path>) -> Result<TabulatedSpectrum, Error> {
        let path = path.as_ref();
        self.text(&speclab_tables::read::file(path)?, &path.display().to_string())
    }

    /// A spectrum from a stream (at most [`MAX_BYTES`]); `origin`
    /// names it in errors.
    pub fn reader(&self, reader: impl std::io::Read, origin: &str) -> Result<TabulatedSpectrum, Error> {
        self.text(&speclab_tables::read::text(reader, origin, MAX_BYTES)?, origin)
    }
}
