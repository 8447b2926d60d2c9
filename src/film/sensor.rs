//! A sensor: three response curves over wavelength, an observer with
//! other curves. The CIE observers are sensors whose responses are XYZ; a
//! camera's are its raw r, g, b, which a matrix fitted by least squares
//! ([`Sensor::fit_xyz`]) takes to XYZ.

use std::sync::Arc;

use crate::Xyz;
use crate::color::matrix::{Matrix, determinant, inverse, mul, product};
use crate::error::Error;
use crate::sampling::pdf::LightPdf;
use crate::spectrum::data::sensors;
use crate::spectrum::lookup::{DENSE_ENTRIES, DENSE_RANGE, DENSE_VALUES, entry};
use crate::spectrum::{
    Float, FnSpectrum, Interpolation, Observer, Role, Spectrum, StandardObserver, TabulatedSpectrum,
    WavelengthRange, Wavelengths,
};

/// Three response curves at every whole nanometre of 360–830 nm (zero
/// where the data stop), linear between them, and the rows
/// `[r̄, ḡ, b̄, 1]` a [`HeroSample`](crate::HeroSample) weighs its
/// wavelengths with. Cloning shares the curves (about 36 KB).
#[derive(Clone)]
pub struct Sensor {
    name: Arc<str>,
    curves: Arc<Curves>,
}

struct Curves {
    at_nm: [[f64; 3]; DENSE_VALUES],
    f64: [[f64; 4]; DENSE_ENTRIES],
    f32: [[f32; 4]; DENSE_ENTRIES],
    /// The whole nanometres where some curve is positive, first to last.
    support: Option<WavelengthRange>,
}

impl Sensor {
    /// The cameras of [`data::sensors`](crate::spectrum::data::sensors), by
    /// pbrt-v4's names (`canon_eos_100d`, …, `sony_ilce_9`).
    #[must_use]
    pub fn camera_names() -> &'static [&'static str] {
        &sensors::NAMES
    }

    /// A camera by name: its curves as pbrt-v4 reads them (piecewise
    /// linear through the 10 nm data, zero outside 380–720 nm). An
    /// [`Error::UnknownName`] for a name not in [`Sensor::camera_names`].
    pub fn camera(name: &str) -> Result<Sensor, Error> {
        let Some(&(name, first, step, rows)) = sensors::ALL.iter().find(|(n, ..)| *n == name) else {
            return Err(Error::UnknownName {
                what: "a camera",
                expected: &sensors::NAMES,
                found: name.into(),
            });
        };
        let at = |lambda: f64| {
            let x = (lambda - first) / step;
            if x < 0.0 || x > (rows.len() - 1) as f64 {
                return [0.0; 3];
            }
            let i = (x.floor() as usize).min(rows.len() - 2);
            let t = x - i as f64;
            std::array::from_fn(|c| rows[i][c] + t * (rows[i + 1][c] - rows[i][c]))
        };
        Ok(Sensor::from_fn(name, at))
    }

    /// A CIE observer as a sensor: its responses are X, Y and Z.
    #[must_use]
    pub fn observer(observer: StandardObserver) -> Sensor {
        Sensor::from_fn(observer.name(), |lambda| observer.xyz_bar(lambda))
    }

    /// A sensor with curves `r`, `g`, `b`, read at every whole nanometre
    /// of 360–830 nm; an [`Error::Response`] for a negative or non-finite
    /// response there.
    pub fn new(name: &str, [r, g, b]: [&dyn Spectrum; 3]) -> Result<Sensor, Error> {
        for (c, s) in [r, g, b].into_iter().enumerate() {
            for i in 0..DENSE_VALUES {
                let lambda = DENSE_RANGE.min() + i as f64;
                let v = s.eval(lambda);
                if !(v >= 0.0 && v.is_finite()) {
                    return Err(Error::Response { channel: c, lambda, value: v });
                }
            }
        }
        Ok(Sensor::from_fn(name, |lambda| [r.eval(lambda), g.eval(lambda), b.eval(lambda)]))
    }

    fn from_fn(name: &str, curve: impl Fn(f64) -> [f64; 3]) -> Sensor {
        let at_nm: [[f64; 3]; DENSE_VALUES] = std::array::from_fn(|i| curve(DENSE_RANGE.min() + i as f64));
        let mut f64 = [[0.0, 0.0, 0.0, 1.0]; DENSE_ENTRIES];
        for (row, v) in f64.iter_mut().zip(&at_nm) {
            *row = [v[0], v[1], v[2], 1.0];
        }
        let positive = |v: &[f64; 3]| v.iter().any(|&c| c > 0.0);
        let first = at_nm.iter().position(positive);
        let last = at_nm.iter().rposition(positive);
        let support = match (first, last) {
            (Some(a), Some(b)) if b > a => {
                WavelengthRange::new(DENSE_RANGE.min() + a as f64, DENSE_RANGE.min() + b as f64).ok()
            }
            _ => None,
        };
        let f32 = f64.map(|row| row.map(|v| v as f32));
        Sensor { name: name.into(), curves: Arc::new(Curves { at_nm, f64, f32, support }) }
    }

    /// The sensor's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The three responses at `lambda`, nm (linear between whole
    /// nanometres, zero outside 360–830 nm).
    #[must_use]
    pub fn curves(&self, lambda: f64) -> [f64; 3] {
        let x = lambda - DENSE_RANGE.min();
        if !(0.0..=DENSE_RANGE.width()).contains(&x) {
            return [0.0; 3];
        }
        let i = (x.floor() as usize).min(DENSE_VALUES - 2);
        let (a, b, t) = (self.curves.at_nm[i], self.curves.at_nm[i + 1], x - i as f64);
        std::array::from_fn(|c| a[c] + t * (b[c] - a[c]))
    }

    /// The whole nanometres where some curve is positive, first to last
    /// (380–720 nm for the cameras); `None` for a sensor that sees nothing.
    #[must_use]
    pub fn support(&self) -> Option<WavelengthRange> {
        self.curves.support
    }

    /// The responses to `spectrum`: `∫ S(λ)·curve(λ) dλ` over 360–830 nm
    /// by the trapezoid rule on the whole nanometres (exact for a
    /// spectrum linear between them, as the curves are).
    #[must_use]
    pub fn responses(&self, spectrum: &(impl Spectrum + ?Sized)) -> [f64; 3] {
        let mut sum = [0.0; 3];
        for (i, v) in self.curves.at_nm.iter().enumerate() {
            let end = i == 0 || i == DENSE_VALUES - 1;
            let s = spectrum.eval(DENSE_RANGE.min() + i as f64) * if end { 0.5 } else { 1.0 };
            (0..3).for_each(|c| sum[c] += s * v[c]);
        }
        sum
    }

    /// Wavelengths drawn by the curves, `p(λ) ∝ Σ꜀ curve꜀(λ)`, times
    /// `light` if given, over [`Sensor::support`]: a density (1 nm pieces,
    /// linear) for [`HeroSample::from_pdf_with`](crate::HeroSample::from_pdf_with)
    /// with this sensor as the observer. It is zero where the sensor sees
    /// nothing, so it estimates the sensor's responses without bias, not
    /// a spectrum there. An [`Error::NoMass`] if the product has none.
    pub fn pdf(&self, light: Option<&dyn Spectrum>) -> Result<LightPdf, Error> {
        let range = self.support().ok_or(Error::NoMass)?;
        let (first, count) = (range.min(), range.width().round() as usize + 1);
        let lambda: Vec<f64> = (0..count).map(|i| first + i as f64).collect();
        let mut values = Vec::with_capacity(count);
        for &l in &lambda {
            let sum: f64 = self.curves(l).iter().sum();
            let v = sum * light.map_or(1.0, |s| s.eval(l));
            values.push(if v.is_finite() && v > 0.0 { v } else { 0.0 });
        }
        let density =
            TabulatedSpectrum::with_interpolation(lambda, values, Role::Light, Interpolation::Linear)?;
        LightPdf::spectrum_over(&density, range)
    }

    /// The matrix taking this sensor's responses to XYZ, fitted by least
    /// squares over `training` reflectances: the responses to each under
    /// `light` (scaled so the perfect white's middle response is 1)
    /// against its XYZ under `target` by `observer` (scaled so the white's
    /// `Y` is 1). With `target` = `light` the matrix keeps the light's
    /// colour (white balance then follows); with the display's white as
    /// `target` it balances too (pbrt-v4's camera fit). At least three
    /// reflectances ([`Error::Count`]); [`Error::Dark`] if the light gives
    /// the sensor or the observer nothing; [`Error::NoMass`] if the
    /// responses span less than three dimensions.
    pub fn fit_xyz<R: Spectrum>(
        &self,
        training: &[R],
        light: &dyn Spectrum,
        target: &dyn Spectrum,
        observer: StandardObserver,
    ) -> Result<SensorFit, Error> {
        if training.len() < 3 {
            let found = training.len();
            return Err(Error::Count { what: "training reflectances", found, min: 3, max: usize::MAX });
        }
        let cie = Sensor::observer(observer);
        let dark = Error::Dark { range: [DENSE_RANGE.min(), DENSE_RANGE.max()] };
        let (g_white, y_white) = (self.responses(light)[1], cie.responses(target)[1]);
        if !(g_white > 0.0 && y_white > 0.0 && g_white.is_finite() && y_white.is_finite()) {
            return Err(dark);
        }
        let pairs: Vec<([f64; 3], [f64; 3])> = training
            .iter()
            .map(|r| {
                let camera = self.responses(&FnSpectrum(|l: f64| light.eval(l) * r.eval(l)));
                let xyz = cie.responses(&FnSpectrum(|l: f64| target.eval(l) * r.eval(l)));
                (camera.map(|v| v / g_white), xyz.map(|v| v / y_white))
            })
            .collect();
        let matrix = least_squares(&pairs).ok_or(Error::NoMass)?;
        let residuals: Vec<f64> = pairs
            .iter()
            .map(|(c, x)| {
                let m = mul(&matrix, *c);
                ((m[0] - x[0]).powi(2) + (m[1] - x[1]).powi(2) + (m[2] - x[2]).powi(2)).sqrt()
            })
            .collect();
        let rms = (residuals.iter().map(|r| r * r).sum::<f64>() / residuals.len() as f64).sqrt();
        let max = residuals.iter().copied().fold(0.0, f64::max);
        Ok(SensorFit { matrix, rms, max, count: pairs.len() })
    }
}

/// `M` minimising `Σ‖M·c − x‖²` over `(c, x)` pairs: `(Σ x cᵀ)(Σ c cᵀ)⁻¹`;
/// `None` if `Σ c cᵀ` is singular.
fn least_squares(pairs: &[([f64; 3], [f64; 3])]) -> Option<Matrix> {
    let (mut cc, mut xc) = ([[0.0; 3]; 3], [[0.0; 3]; 3]);
    for (c, x) in pairs {
        for i in 0..3 {
            for j in 0..3 {
                cc[i][j] += c[i] * c[j];
                xc[i][j] += x[i] * c[j];
            }
        }
    }
    // Singular to rounding: the determinant against the size of Σ c cᵀ.
    let size = cc.iter().flatten().map(|v| v.abs()).fold(0.0, f64::max);
    let det = determinant(&cc);
    if !(det.abs() > 1e-12 * size.powi(3) && det.is_finite()) {
        return None;
    }
    Some(product(&xc, &inverse(&cc)))
}

/// A sensor → XYZ matrix and how well it fits its training set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorFit {
    /// Sensor responses (relative to the white's middle one) to XYZ
    /// (relative to the white's `Y`).
    pub matrix: Matrix,
    /// The root mean square of `‖M·c − x‖` over the training set, in the
    /// white's `Y`.
    pub rms: f64,
    /// The largest `‖M·c − x‖`.
    pub max: f64,
    /// The training reflectances.
    pub count: usize,
}

impl SensorFit {
    /// XYZ of sensor responses `c` (relative, as fitted).
    #[must_use]
    pub fn xyz(&self, c: [f64; 3]) -> Xyz {
        Xyz::from(mul(&self.matrix, c))
    }
}

impl std::fmt::Debug for Sensor {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Sensor({})", self.name)
    }
}

impl PartialEq for Sensor {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.curves, &other.curves) || self.curves.at_nm == other.curves.at_nm
    }
}

impl Observer for Sensor {
    /// `[r̄, ḡ, b̄, 1]` at the nearest whole nanometre (as
    /// [`DenseObserver`](crate::spectrum::DenseObserver) reads its rows).
    #[inline(always)]
    fn xyz_bar_at<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> [[T; 4]; K] {
        let (nearest, rows) = (at.nearest_nm(), T::choose(&self.curves.f32, &self.curves.f64));
        std::array::from_fn(|j| entry(rows, nearest[j]))
    }

    /// 360–830 nm, where its curves are tabulated (zero outside its
    /// [`support`](Sensor::support)).
    fn data_range(&self) -> WavelengthRange {
        WavelengthRange::VISIBLE
    }

    /// The middle curve's, read at the nearest whole nanometre.
    fn y_integral(&self, range: WavelengthRange) -> f64 {
        crate::spectrum::observer::cells_integral(&self.curves.f64, 1, range)
    }
}
