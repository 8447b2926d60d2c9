//! White balance: von Kries scaling in a cone space the caller chooses
//! ([`Cat`]), from the white of a light, a colour temperature or an XYZ to
//! the display's white.

use crate::Xyz;
use crate::color::adaptation::Cat;
use crate::color::matrix::{Matrix, mul};
use crate::colorimetry::Tristimulus;
use crate::error::Error;
use crate::spectrum::data::lights;
use crate::spectrum::{Blackbody, Spectrum, StandardObserver, WavelengthRange};

/// A white balance: the matrix that takes the scene's white `from` to the
/// display's white `to` by von Kries scaling in `cat`'s cone space
/// (pbrt-v4 balances in Bradford's, its default here).
///
/// ```
/// use speclab::film::WhiteBalance;
/// use speclab::color::adaptation::Cat;
/// use speclab::spectrum::StandardObserver;
/// use speclab::Xyz;
/// let d65 = Xyz::new(0.95047, 1.0, 1.08883);
/// for balance in [
///     WhiteBalance::daylight(5000.0, d65, Cat::Bradford, StandardObserver::Cie1931)?,
///     WhiteBalance::planckian(3200.0, d65, Cat::Cat16, StandardObserver::Cie1931)?,
/// ] {
///     let white = balance.apply(balance.from());
///     assert!((white.x - d65.x).abs() < 1e-9 && (white.z - d65.z).abs() < 1e-9);
/// }
/// // CIE daylight is defined from 4000 K up.
/// assert!(WhiteBalance::daylight(3200.0, d65, Cat::Bradford, StandardObserver::Cie1931).is_err());
/// # Ok::<(), speclab::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WhiteBalance {
    from: Xyz,
    to: Xyz,
    cat: Cat,
    matrix: Matrix,
}

impl WhiteBalance {
    /// From the white `from` to the white `to` (each with a positive,
    /// finite `Y`; an [`Error::Develop`] otherwise).
    pub fn new(from: Xyz, to: Xyz, cat: Cat) -> Result<Self, Error> {
        let fine = |w: Xyz| w.y > 0.0 && w.to_array().iter().all(|v| v.is_finite() && *v >= 0.0);
        if !(fine(from) && fine(to)) {
            return Err(Error::Develop("a white balance needs whites with a positive, finite Y"));
        }
        Ok(WhiteBalance { from, to, cat, matrix: cat.matrix(from, to) })
    }

    /// From the white of `light` (its colour with `Y = 1`, by `observer`
    /// at 1 nm over 360–830 nm, or 380–780 nm for the assignment's).
    pub fn light(
        light: &(impl Spectrum + ?Sized),
        to: Xyz,
        cat: Cat,
        observer: StandardObserver,
    ) -> Result<Self, Error> {
        let range = observer.data_range().min().max(360.0);
        let grid =
            Tristimulus::new(observer, WavelengthRange::new(range, observer.data_range().max())?, 1.0)?;
        WhiteBalance::new(grid.white(light)? * 0.01, to, cat)
    }

    /// From CIE daylight of correlated colour temperature `kelvin`
    /// (4000–25 000 K: pbrt-v4's `whitebalance`).
    pub fn daylight(kelvin: f64, to: Xyz, cat: Cat, observer: StandardObserver) -> Result<Self, Error> {
        WhiteBalance::light(&lights::daylight(kelvin)?, to, cat, observer)
    }

    /// From a blackbody at `kelvin` (any positive temperature).
    pub fn planckian(kelvin: f64, to: Xyz, cat: Cat, observer: StandardObserver) -> Result<Self, Error> {
        WhiteBalance::light(&Blackbody::new(kelvin)?, to, cat, observer)
    }

    /// The scene's white.
    #[must_use]
    pub fn from(&self) -> Xyz {
        self.from
    }

    /// The display's white.
    #[must_use]
    pub fn to(&self) -> Xyz {
        self.to
    }

    /// The cone space.
    #[must_use]
    pub fn cat(&self) -> Cat {
        self.cat
    }

    /// The balance as one matrix on XYZ.
    #[must_use]
    pub fn matrix(&self) -> Matrix {
        self.matrix
    }

    /// `xyz` balanced.
    #[must_use]
    pub fn apply(&self, xyz: Xyz) -> Xyz {
        Xyz::from(mul(&self.matrix, xyz.to_array()))
    }
}
