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
//! Spectra come from samples in code ([`TabulatedSpectrum::new`]), from
//! files (`speclab::io::Load`, one floor up) or from static data made at
//! compile time (`speclab_tables::Codegen`, as [`crate::data`] is).
//!
//! ```
//! use speclab::{Role, TabulatedSpectrum};
//! let light = TabulatedSpectrum::new(vec![400.0, 500.0], vec![1.0, 3.0], Role::Light)?;
//! assert_eq!(light.eval(450.0), 2.0);
//! assert_eq!(light.eval(390.0), 0.0); // outside the support
//! assert_eq!(light.integral(400.0, 500.0), 200.0);
//! # Ok::<(), speclab::Error>(())
//! ```

use std::borrow::Cow;
use std::fmt;

use crate::error::Error;
use crate::spectrum::WavelengthRange;
use crate::spectrum::float::Float;
use crate::spectrum::interface::{Pieces, Samples, Spectrum};
use crate::spectrum::interp::{self, Coeffs};
use crate::spectrum::lookup::UniformLookup;
use crate::spectrum::piecewise::View;
use crate::spectrum::sampled::{SampledSpectrum, Wavelengths};
use crate::spectrum::validate::{self, Interpolation, Role};
use speclab_tables::error::Position;
use speclab_tables::read::Extend;

/// Precomputed tables of a spectrum, as `speclab_tables::Codegen` writes them for
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
    /// The exact integral from the first wavelength to each wavelength.
    pub prefix: &'static [f64],
    /// Per segment: true where no clamp acts (the function is the polynomial).
    pub clean: &'static [bool],
}

/// Samples of a spectrum and the interpolant through them. Equality looks
/// at the samples and every table of the interpolant.
#[derive(Clone)]
pub struct TabulatedSpectrum {
    role: Role,
    interpolation: Interpolation,
    lambda: Cow<'static, [f64]>,
    values: Cow<'static, [f64]>,
    coeffs: Cow<'static, [Coeffs]>,
    breaks: Cow<'static, [f64]>,
    /// `∫` from the first knot to each knot, exact (see `interp::prefix`).
    prefix: Cow<'static, [f64]>,
    /// Per segment: no clamp acts, so integrals are the primitive's.
    clean: Cow<'static, [bool]>,
    /// First and last wavelength, nm: the support.
    ends: [f64; 2],
    /// O(1) segment lookup for equidistant tables (made for `coeffs` and
    /// `lambda`).
    lookup: Option<UniformLookup>,
    /// The role's clamp interval.
    bounds: [f64; 2],
}

impl PartialEq for TabulatedSpectrum {
    /// Same role, interpolation, samples and interpolant tables.
    fn eq(&self, o: &Self) -> bool {
        (self.role, self.interpolation) == (o.role, o.interpolation)
            && (self.lambda == o.lambda && self.values == o.values)
            && (self.coeffs == o.coeffs && self.breaks == o.breaks)
            && (self.prefix == o.prefix && self.clean == o.clean)
    }
}

impl fmt::Debug for TabulatedSpectrum {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TabulatedSpectrum")
            .field("role", &self.role)
            .field("interpolation", &self.interpolation)
            .field("lambda", &self.lambda)
            .field("values", &self.values)
            .finish_non_exhaustive()
    }
}

impl TabulatedSpectrum {
    /// A spectrum over static tables, for code that `speclab_tables::Codegen`
    /// generates: the tables must be the ones it computes. `None` if their
    /// lengths do not fit together (generated code turns that into a
    /// compile-time error). Reached through `speclab::__codegen`, not part
    /// of the API.
    #[must_use]
    pub(crate) const fn from_static(role: Role, interpolation: Interpolation, t: Tables) -> Option<Self> {
        let n = t.lambda.len();
        let fits = n >= interpolation.min_samples()
            && t.values.len() == n
            && t.coeffs.len() + 1 == n
            && t.breaks.len() >= 2
            && t.prefix.len() == n
            && t.clean.len() + 1 == n;
        if !fits {
            return None;
        }
        Some(TabulatedSpectrum {
            role,
            interpolation,
            lambda: Cow::Borrowed(t.lambda),
            values: Cow::Borrowed(t.values),
            coeffs: Cow::Borrowed(t.coeffs),
            breaks: Cow::Borrowed(t.breaks),
            prefix: Cow::Borrowed(t.prefix),
            clean: Cow::Borrowed(t.clean),
            ends: [t.lambda[0], t.lambda[n - 1]],
            lookup: UniformLookup::for_table(t.lambda, t.coeffs.len()),
            bounds: role.bounds(),
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

    /// A spectrum from samples already validated for `role` and
    /// `interpolation` (by the reader of files one floor up).
    pub(crate) fn from_validated(
        lambda: Vec<f64>,
        values: Vec<f64>,
        role: Role,
        interpolation: Interpolation,
    ) -> Self {
        Self::build(lambda, values, role, interpolation)
    }

    fn build(lambda: Vec<f64>, values: Vec<f64>, role: Role, interpolation: Interpolation) -> Self {
        let coeffs = interp::coeffs(interpolation, &lambda, &values);
        let breaks = interp::breaks(&lambda, &coeffs, role.bounds());
        let prefix = interp::prefix(&lambda, &coeffs, &breaks, role.bounds());
        let clean = interp::clean(&lambda, &coeffs, &breaks, role.bounds());
        TabulatedSpectrum {
            prefix: Cow::Owned(prefix),
            clean: Cow::Owned(clean),
            role,
            interpolation,
            ends: [lambda[0], lambda[lambda.len() - 1]],
            lookup: UniformLookup::for_table(&lambda, coeffs.len()),
            bounds: role.bounds(),
            lambda: Cow::Owned(lambda),
            values: Cow::Owned(values),
            coeffs: Cow::Owned(coeffs),
            breaks: Cow::Owned(breaks),
        }
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

    /// The spectrum past its samples as `extend` says: [`Extend::Zero`] as
    /// it is (zero outside), [`Extend::Hold`] its end values held out to
    /// 360–830 nm (as `io::Load` holds a file's, and pbrt-v4 pads),
    /// [`Extend::Refuse`] an [`Error::RangeOutside`] unless it covers
    /// 380–730 nm.
    ///
    /// ```
    /// use speclab::{Role, TabulatedSpectrum, io::Extend};
    /// let s = TabulatedSpectrum::new(vec![400.0, 700.0], vec![2.0, 8.0], Role::Light)?;
    /// let held = s.extended(Extend::Hold)?;
    /// assert_eq!((held.eval(370.0), held.eval(820.0)), (2.0, 8.0));
    /// assert_eq!(s.extended(Extend::Zero)?.eval(820.0), 0.0);
    /// assert!(s.extended(Extend::Refuse).is_err());
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn extended(&self, extend: Extend) -> Result<Self, Error> {
        let [lo, hi] = self.ends;
        match extend {
            Extend::Zero => Ok(self.clone()),
            Extend::Refuse => {
                let need = WavelengthRange::ASSIGNMENT;
                if lo <= need.min() && hi >= need.max() {
                    Ok(self.clone())
                } else {
                    Err(Error::RangeOutside {
                        range: [need.min(), need.max()],
                        of: "the spectrum",
                        data: [lo, hi],
                    })
                }
            }
            Extend::Hold => {
                let mut samples = speclab_tables::text::Samples::default();
                for (&l, &v) in self.lambda.iter().zip(self.values.iter()) {
                    samples.push(l, v, Position::START, Position::START);
                }
                let held = speclab_tables::read::hold(samples);
                Ok(Self::build(held.lambda, held.values, self.role, self.interpolation))
            }
        }
    }

    /// The exact integral of the spectrum over `[a, b]` nm (zero if `b ≤ a`).
    #[must_use]
    pub fn integral(&self, a: f64, b: f64) -> f64 {
        let bounds = self.role.bounds();
        interp::integral(&self.lambda, &self.coeffs, &self.breaks, bounds, a, b)
    }

    /// The exact integral from the first wavelength to `x` nm: the prefix
    /// up to `x`'s segment plus the segment's primitive (exact integration
    /// of the pieces where a clamp acts). O(1) on an equidistant table.
    #[inline]
    pub(crate) fn cumulative(&self, x: f64) -> f64 {
        let [first, last] = self.ends;
        let n = self.lambda.len();
        if x.is_nan() || x <= first {
            return 0.0;
        }
        if x >= last {
            return self.prefix[n - 1];
        }
        let k = match self.lookup {
            Some(lookup) => lookup.segment(x),
            None => interp::segment_of(&self.lambda, x),
        };
        let knot = self.lambda[k];
        let part = if self.clean[k] {
            interp::primitive(self.coeffs[k], x - knot)
        } else {
            interp::integral(&self.lambda, &self.coeffs, &self.breaks, self.bounds, knot, x)
        };
        self.prefix[k] + part
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
        (self.ends[0], self.ends[1])
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

    /// The degree of the polynomial pieces: 1 (linear) or 3 (cubic).
    pub(crate) fn degree(&self) -> usize {
        match self.interpolation {
            Interpolation::Linear => 1,
            Interpolation::Cubic => 3,
        }
    }

    /// The tables, borrowed, for exact integration.
    pub(crate) fn view(&self) -> View<'_> {
        View { lambda: &self.lambda, coeffs: &self.coeffs, breaks: &self.breaks, bounds: self.bounds }
    }

    /// Wavelengths between which the spectrum is one polynomial: the samples
    /// plus the points where the interpolant meets a clamp bound.
    #[must_use]
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }
}

impl Spectrum for TabulatedSpectrum {
    #[inline(always)]
    fn eval(&self, lambda: f64) -> f64 {
        TabulatedSpectrum::eval(self, lambda)
    }

    #[inline(always)]
    fn eval_many(&self, lambda: &[f64], values: &mut [f64]) {
        self.eval_into(lambda, values);
    }

    /// The samples and the clamp crossings; linear (degree 1) or cubic (3).
    #[inline(always)]
    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        for (v, &l) in values.iter_mut().zip(lambda) {
            *v = f32::from_f64(self.eval_lanes(&[f64::from(l)])[0]);
        }
    }

    #[inline(always)]
    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        TabulatedSpectrum::sample(self, at)
    }

    /// The samples and the clamp crossings; linear (degree 1) or cubic (3).
    fn pieces(&self) -> Option<Pieces<'_>> {
        Some(Pieces { breaks: Cow::Borrowed(&self.breaks), degree: self.degree() })
    }

    fn samples(&self) -> Option<Samples<'_>> {
        Some(Samples {
            lambda: &self.lambda,
            values: &self.values,
            interpolation: self.interpolation,
            role: self.role,
        })
    }

    /// From the running sums kept with the table: O(1) on an equidistant
    /// table.
    fn running_integral(&self, lambda: f64) -> Option<f64> {
        Some(self.cumulative(lambda))
    }

    /// Exact: the largest value of the clamped interpolant over 360–830 nm
    /// (each segment's polynomial at the ends of its part of the range and
    /// where its derivative vanishes), and 0 if the table does not cover
    /// the whole range.
    fn max_value(&self) -> f64 {
        let (min, max) = (WavelengthRange::VISIBLE.min(), WavelengthRange::VISIBLE.max());
        let (lo, hi) = (self.ends[0].max(min), self.ends[1].min(max));
        let outside = if self.ends[0] > min || self.ends[1] < max { 0.0 } else { f64::NEG_INFINITY };
        let mut best = outside;
        for (k, c) in self.coeffs.iter().enumerate() {
            let (a, b) = (self.lambda[k].max(lo), self.lambda[k + 1].min(hi));
            if a > b {
                continue;
            }
            let (a, b) = (a - self.lambda[k], b - self.lambda[k]);
            best = best.max(interp::segment_max(*c, a, b));
        }
        best.clamp(self.bounds[0], self.bounds[1])
    }
}

#[path = "tabulated_eval.rs"]
mod eval;

#[cfg(test)]
#[path = "tabulated_tests.rs"]
mod tests;
