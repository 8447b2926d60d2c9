//! A spectral image as plain data: per pixel, one value per wavelength
//! channel, with what the values are (emissive radiance or a reflective
//! ratio). What a film makes and an OpenEXR file holds.

use crate::error::Error;

/// What a spectral image's values are (the two kinds of Fichet,
/// Pacanowski and Wilkie's layout).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Spectral radiance per nm (channels `S0.<λ>nm`): the light is in the
    /// values.
    #[default]
    Emissive,
    /// A ratio to the light (channels `T.<λ>nm`): reflectance, or a
    /// scene's radiance per unit of one light's power; developed under a
    /// light of the caller's choosing.
    Reflective,
}

/// A spectral image: `width × height` pixels, rows top to bottom, each
/// pixel's values at `wavelengths` (nm, increasing) side by side.
#[derive(Clone, Debug, PartialEq)]
pub struct SpectralImage {
    width: usize,
    height: usize,
    kind: Kind,
    wavelengths: Vec<f64>,
    values: Vec<f32>,
}

impl SpectralImage {
    /// An image from its values, pixel by pixel, `wavelengths.len()` per
    /// pixel. An [`Error::Pixel`] if `values` has another length; an
    /// [`Error::Develop`] for no wavelengths or wavelengths that are not
    /// positive, finite and increasing.
    pub fn new(
        (width, height): (usize, usize),
        kind: Kind,
        wavelengths: Vec<f64>,
        values: Vec<f32>,
    ) -> Result<Self, Error> {
        if wavelengths.is_empty() {
            return Err(Error::Develop("a spectral image needs at least one wavelength"));
        }
        if !(wavelengths.iter().all(|l| l.is_finite() && *l > 0.0) && wavelengths.is_sorted_by(|a, b| a < b))
        {
            return Err(Error::Develop(
                "a spectral image's wavelengths must be positive, finite and increasing",
            ));
        }
        let expected = width.checked_mul(height).and_then(|p| p.checked_mul(wavelengths.len()));
        if expected != Some(values.len()) {
            return Err(Error::Pixel {
                what: format!("{} values", values.len()),
                expected: format!("{width} × {height} pixels × {} wavelengths", wavelengths.len()),
            });
        }
        Ok(SpectralImage { width, height, kind, wavelengths, values })
    }

    /// Width and height, pixels.
    #[must_use]
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// Emissive or reflective.
    #[must_use]
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// The channels' wavelengths, nm, increasing.
    #[must_use]
    pub fn wavelengths(&self) -> &[f64] {
        &self.wavelengths
    }

    /// Every value, pixel by pixel.
    #[must_use]
    pub fn values(&self) -> &[f32] {
        &self.values
    }

    /// Pixel `(x, y)`'s values, one per wavelength; `None` outside.
    #[must_use]
    pub fn pixel(&self, x: usize, y: usize) -> Option<&[f32]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let n = self.wavelengths.len();
        let start = (y * self.width + x) * n;
        self.values.get(start..start + n)
    }

    /// The wavelengths each channel stands for: from halfway to its
    /// neighbour on each side (the ends as far out as inside), nm. For
    /// a film's buckets, their bounds.
    #[must_use]
    pub fn cells(&self) -> Vec<[f64; 2]> {
        let l = &self.wavelengths;
        let n = l.len();
        (0..n)
            .map(|i| {
                let low = if i > 0 {
                    0.5 * (l[i - 1] + l[i])
                } else if n > 1 {
                    l[0] - 0.5 * (l[1] - l[0])
                } else {
                    l[0] - 0.5
                };
                let high = if i + 1 < n {
                    0.5 * (l[i] + l[i + 1])
                } else if n > 1 {
                    l[i] + 0.5 * (l[i] - l[i - 1])
                } else {
                    l[0] + 0.5
                };
                [low, high]
            })
            .collect()
    }
}
