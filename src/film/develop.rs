//! Developing a spectral image: each pixel's values weighed by a sensor's
//! curves (times a light, for a reflective image) over the wavelengths
//! each channel stands for, then the sensor → XYZ matrix, the white
//! balance and the exposure.

use crate::Xyz;
use crate::color::matrix::{Matrix, mul, product};
use crate::error::Error;
use crate::film::balance::WhiteBalance;
use crate::film::image::{Kind, SpectralImage};
use crate::film::sensor::Sensor;
use crate::spectrum::Spectrum;

/// How a channel's weight is taken over the wavelengths it stands for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Quadrature {
    /// `∫ curve·L dλ` over the channel's cell
    /// ([`SpectralImage::cells`]), exactly for the sensor's linear pieces
    /// (three Gauss points per nanometre): the default.
    #[default]
    Cell,
    /// `curve(λ)·L(λ)` at the channel's wavelength times its cell's width:
    /// for 1 nm channels at whole nanometres, what a
    /// [`HeroSample`](crate::HeroSample) weighted by the same sensor sums
    /// (its rows are read at the nearest whole nanometre), so a film's
    /// image develops to the tracer's own estimate to rounding.
    Point,
}

/// How to turn a spectral image into XYZ: a sensor, a light for a
/// reflective image, the sensor → XYZ matrix, a white balance, and the
/// exposure (`seconds × ISO / 100`, pbrt-v4's imaging ratio).
#[derive(Clone)]
pub struct Develop<'a> {
    sensor: Sensor,
    light: Option<&'a dyn Spectrum>,
    to_xyz: Matrix,
    balance: Option<WhiteBalance>,
    ratio: f64,
    quadrature: Quadrature,
}

impl<'a> Develop<'a> {
    /// With `sensor`'s responses as XYZ (the identity matrix: right for a
    /// CIE observer), no light, no balance, an imaging ratio of 1.
    #[must_use]
    pub fn new(sensor: Sensor) -> Self {
        let to_xyz = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        Develop { sensor, light: None, to_xyz, balance: None, ratio: 1.0, quadrature: Quadrature::Cell }
    }

    /// Under `light`: a reflective image's values are multiplied by it.
    #[must_use]
    pub fn light(mut self, light: &'a dyn Spectrum) -> Self {
        self.light = Some(light);
        self
    }

    /// The sensor's responses to XYZ by `matrix` (a
    /// [`SensorFit`](crate::film::SensorFit)'s).
    #[must_use]
    pub fn sensor_to_xyz(mut self, matrix: Matrix) -> Self {
        self.to_xyz = matrix;
        self
    }

    /// Balanced by `balance` after the matrix.
    #[must_use]
    pub fn balance(mut self, balance: WhiteBalance) -> Self {
        self.balance = Some(balance);
        self
    }

    /// An exposure of `seconds` at `iso`: the values times
    /// `seconds × iso / 100`; an [`Error::Scale`] unless that is positive
    /// and finite.
    pub fn exposure(mut self, seconds: f64, iso: f64) -> Result<Self, Error> {
        let ratio = seconds * iso / 100.0;
        if !(ratio > 0.0 && ratio.is_finite()) {
            return Err(Error::Scale { factor: ratio });
        }
        self.ratio = ratio;
        Ok(self)
    }

    /// Weights taken by `quadrature`.
    #[must_use]
    pub fn quadrature(mut self, quadrature: Quadrature) -> Self {
        self.quadrature = quadrature;
        self
    }

    /// The matrix from the sensor's weighted sums to the output XYZ:
    /// balance · sensor → XYZ, times the imaging ratio.
    #[must_use]
    pub fn matrix(&self) -> Matrix {
        let m = self.balance.map_or(self.to_xyz, |b| product(&b.matrix(), &self.to_xyz));
        m.map(|row| row.map(|v| v * self.ratio))
    }

    /// Each channel's weights `[r, g, b]` (the sensor's, times the light
    /// for a reflective image), in nm. An [`Error::Develop`] for an
    /// emissive image with a light (its light is in its values) or a
    /// reflective one without.
    pub fn weights(&self, image: &SpectralImage) -> Result<Vec<[f64; 3]>, Error> {
        let light = match (image.kind(), self.light) {
            (Kind::Emissive, Some(_)) => {
                return Err(Error::Develop("an emissive image carries its light: develop it without one"));
            }
            (Kind::Reflective, None) => {
                return Err(Error::Develop("a reflective image is developed under a light: give one"));
            }
            (_, light) => light,
        };
        let at = |lambda: f64| {
            let (c, l) = (self.sensor.curves(lambda), light.map_or(1.0, |s| s.eval(lambda)));
            c.map(|v| v * l)
        };
        let cells = image.cells();
        Ok(match self.quadrature {
            Quadrature::Point => image
                .wavelengths()
                .iter()
                .zip(&cells)
                .map(|(&l, [a, b])| at(l).map(|v| v * (b - a)))
                .collect(),
            Quadrature::Cell => cells.iter().map(|&cell| integrate(&at, cell)).collect(),
        })
    }

    /// Every pixel's XYZ (rows top to bottom); errors as
    /// [`Develop::weights`].
    pub fn xyz(&self, image: &SpectralImage) -> Result<Vec<Xyz>, Error> {
        let (weights, m) = (self.weights(image)?, self.matrix());
        let n = image.wavelengths().len();
        Ok(image
            .values()
            .chunks(n)
            .map(|pixel| {
                let mut sum = [0.0; 3];
                for (v, w) in pixel.iter().zip(&weights) {
                    (0..3).for_each(|c| sum[c] += f64::from(*v) * w[c]);
                }
                Xyz::from(mul(&m, sum))
            })
            .collect())
    }
}

/// `∫ f` over `[a, b]`, three Gauss–Legendre points on each piece between
/// whole nanometres (exact for a linear curve times a cubic light).
fn integrate(f: &impl Fn(f64) -> [f64; 3], [a, b]: [f64; 2]) -> [f64; 3] {
    const NODES: [(f64, f64); 3] =
        [(-0.774_596_669_241_483_4, 5.0 / 9.0), (0.0, 8.0 / 9.0), (0.774_596_669_241_483_4, 5.0 / 9.0)];
    let mut sum = [0.0; 3];
    let mut lo = a;
    while lo < b {
        let hi = (lo.floor() + 1.0).min(b);
        let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        for (x, w) in NODES {
            let v = f(mid + half * x);
            (0..3).for_each(|c| sum[c] += w * half * v[c]);
        }
        lo = hi;
    }
    sum
}

impl std::fmt::Debug for Develop<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Develop")
            .field("sensor", &self.sensor)
            .field("light", &self.light.is_some())
            .field("to_xyz", &self.to_xyz)
            .field("balance", &self.balance)
            .field("ratio", &self.ratio)
            .field("quadrature", &self.quadrature)
            .finish()
    }
}
