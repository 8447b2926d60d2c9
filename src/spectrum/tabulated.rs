//! Tabulated spectra: samples plus an interpolant, evaluated at any wavelength.
//!
//! A [`TabulatedSpectrum`] holds wavelengths in nanometres (strictly
//! increasing), a value at each, and the piecewise polynomial through them.
//! Its [`Role`] picks the interpolation and clamps the values: lights are
//! linear and non-negative (to keep F11's spikes), reflectances are cubic
//! and clamped to `[0, 1]`, matching functions are cubic and clamped to
//! `≥ 0`.
//!
//! **Outside its support** (below the first or above the last wavelength) a
//! spectrum is zero.
//!
//! ```
//! use speclab::{Role, TabulatedSpectrum};
//! let light = TabulatedSpectrum::parse("{400, 1}, {500, 3}", "<string>", Role::Light)?;
//! assert_eq!(light.eval(450.0), 2.0);
//! assert_eq!(light.eval(390.0), 0.0); // outside the support
//! assert_eq!(light.integral(400.0, 500.0), 200.0);
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;

use crate::Error;
use crate::io::text::Samples;
use crate::io::{brace, read};
use crate::spectrum::interp::{self, Coeffs};
use crate::spectrum::validate::{self, Interpolation, Role};

/// Precomputed tables of a spectrum, as [`crate::codegen`] writes them for
/// static data: samples, the coefficients `[c0, c1, c2, c3]` of each
/// segment's polynomial in `t = λ − λₖ`, and the breaks (samples plus clamp
/// crossings).
#[derive(Clone, Copy, Debug)]
pub struct Tables {
    /// Wavelengths, nm, strictly increasing.
    pub lambda: &'static [f64],
    /// The value at each wavelength.
    pub values: &'static [f64],
    /// One polynomial per segment.
    pub coeffs: &'static [[f64; 4]],
    /// Where the clamped interpolant changes polynomial, sorted.
    pub breaks: &'static [f64],
}

/// Samples of a spectrum and the interpolant through them.
#[derive(Clone, Debug, PartialEq)]
pub struct TabulatedSpectrum {
    role: Role,
    interpolation: Interpolation,
    lambda: Cow<'static, [f64]>,
    values: Cow<'static, [f64]>,
    coeffs: Cow<'static, [Coeffs]>,
    breaks: Cow<'static, [f64]>,
    /// `1 / step` for equidistant tables (fast segment lookup), else 0.
    inv_step: f64,
}

impl TabulatedSpectrum {
    /// A spectrum over static tables, for code that [`crate::codegen`]
    /// generates: the tables must be the ones it computes. `None` if their
    /// lengths do not fit together (generated code turns that into a
    /// compile-time error).
    #[must_use]
    pub const fn from_static(role: Role, interpolation: Interpolation, t: Tables) -> Option<Self> {
        let n = t.lambda.len();
        if n < interpolation.min_samples()
            || t.values.len() != n
            || t.coeffs.len() + 1 != n
            || t.breaks.len() < 2
        {
            return None;
        }
        Some(TabulatedSpectrum {
            role,
            interpolation,
            lambda: Cow::Borrowed(t.lambda),
            values: Cow::Borrowed(t.values),
            coeffs: Cow::Borrowed(t.coeffs),
            breaks: Cow::Borrowed(t.breaks),
            inv_step: interp::uniform_inv_step(t.lambda),
        })
    }

    /// A spectrum from samples, interpolated as its role prescribes.
    ///
    /// The samples are checked as [`crate::spectrum::validate`] describes;
    /// an invalid one is an [`Error::Sample`] naming its index. The spectrum
    /// is zero outside its samples.
    pub fn new(lambda: Vec<f64>, values: Vec<f64>, role: Role) -> Result<Self, Error> {
        Self::with_interpolation(lambda, values, role, role.interpolation())
    }

    /// Like [`TabulatedSpectrum::new`], with the interpolation stated explicitly.
    pub fn with_interpolation(
        lambda: Vec<f64>,
        values: Vec<f64>,
        role: Role,
        interpolation: Interpolation,
    ) -> Result<Self, Error> {
        validate::validate(&lambda, &values, role, interpolation)?;
        Ok(Self::build(lambda, values, role, interpolation))
    }

    /// A spectrum from brace-notation text; `origin` names the text in
    /// errors. Unlike [`crate::io::Load`], it need not cover 380–730 nm.
    pub fn parse(text: &str, origin: &str, role: Role) -> Result<Self, Error> {
        let interpolation = role.interpolation();
        let samples = read::locate(brace::parse_samples(text, origin)?, origin, role, interpolation)?;
        Ok(Self::from_samples(samples, role, interpolation))
    }

    /// A spectrum from samples already validated for `role` and `interpolation`.
    pub(crate) fn from_samples(s: Samples, role: Role, interpolation: Interpolation) -> Self {
        Self::build(s.lambda, s.values, role, interpolation)
    }

    fn build(lambda: Vec<f64>, values: Vec<f64>, role: Role, interpolation: Interpolation) -> Self {
        let coeffs = interp::coeffs(interpolation, &lambda, &values);
        let breaks = interp::breaks(&lambda, &coeffs, role.bounds());
        TabulatedSpectrum {
            role,
            interpolation,
            inv_step: interp::uniform_inv_step(&lambda),
            lambda: Cow::Owned(lambda),
            values: Cow::Owned(values),
            coeffs: Cow::Owned(coeffs),
            breaks: Cow::Owned(breaks),
        }
    }

    /// The value at `lambda` nm: the clamped interpolant inside the support,
    /// zero outside it and for NaN.
    #[inline]
    #[must_use]
    pub fn eval(&self, lambda: f64) -> f64 {
        let x = &self.lambda;
        let n = x.len();
        if !(lambda >= x[0] && lambda <= x[n - 1]) {
            return 0.0;
        }
        let k = if self.inv_step > 0.0 {
            (((lambda - x[0]) * self.inv_step) as usize).min(n - 2)
        } else {
            interp::segment_of(x, lambda)
        };
        let v = interp::segment_value(self.coeffs[k], lambda - x[k]);
        interp::clamp(v, self.role.bounds())
    }

    /// The spectrum times `factor` (finite and positive, and keeping every
    /// value within [`validate::MAX_VALUE`]; otherwise an error).
    pub fn scaled(&self, factor: f64) -> Result<Self, Error> {
        if !(factor.is_finite() && factor > 0.0) {
            return Err(Error::Scale { factor });
        }
        let values: Vec<f64> = self.values.iter().map(|v| v * factor).collect();
        Self::with_interpolation(self.lambda.to_vec(), values, self.role, self.interpolation)
    }

    /// The exact integral of the spectrum over `[a, b]` nm (zero if `b ≤ a`).
    #[must_use]
    pub fn integral(&self, a: f64, b: f64) -> f64 {
        let bounds = self.role.bounds();
        interp::integral(&self.lambda, &self.coeffs, &self.breaks, bounds, a, b)
    }

    /// The exact mean of the spectrum over `[a, b]` nm (zero if `b ≤ a`).
    #[must_use]
    pub fn mean(&self, a: f64, b: f64) -> f64 {
        if b > a { self.integral(a, b) / (b - a) } else { 0.0 }
    }

    /// The tabulated wavelengths, nm.
    #[must_use]
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }

    /// The tabulated values.
    #[must_use]
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// First and last tabulated wavelength, nm.
    #[must_use]
    pub fn support(&self) -> (f64, f64) {
        (self.lambda[0], self.lambda[self.lambda.len() - 1])
    }

    /// What the spectrum is.
    #[must_use]
    pub fn role(&self) -> Role {
        self.role
    }

    /// How it is interpolated.
    #[must_use]
    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// Wavelengths between which the spectrum is one polynomial: the samples
    /// plus the points where the interpolant meets a clamp bound.
    #[must_use]
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }
}
