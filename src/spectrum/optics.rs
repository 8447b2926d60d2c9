//! Optical constants as spectra: a conductor's complex refractive index
//! `η + i·k` and its reflectance at normal incidence, and dielectrics'
//! refractive index from a dispersion formula (Sellmeier, Cauchy).
//!
//! - [`Conductor`]: η and k, each a table (linear between the source's
//!   samples); [`Conductor::reflectance`] is the normal-incidence
//!   reflectance `((η − 1)² + k²) / ((η + 1)² + k²)` as a [`Spectrum`], so
//!   a metal can be a surface anywhere a reflectance can.
//! - [`Sellmeier`]: `n² = 1 + Σᵢ Bᵢλ²/(λ² − Cᵢ)` with λ in micrometres and
//!   Cᵢ in µm² (glass catalogues' form); [`Cauchy`]: `n = A + B/λ² + C/λ⁴`,
//!   λ in micrometres.
//!
//! Wavelengths are in nanometres everywhere here, as in the rest of the
//! crate; the formulas convert. The built-in sets are in
//! `data::conductors` and `data::glasses`.
//!
//! ```
//! use speclab::data::{conductors, glasses, lights};
//! use speclab::spectrum::{Cauchy, Conductor, Spectrum};
//! let gold = conductors::AU.reflectance();
//! assert!(Conductor::new(&lights::D65, conductors::AU.k()).is_err()); // a light is no index
//! assert!(gold.eval(650.0) > 0.9 && gold.eval(450.0) < 0.45); // yellow
//! assert!((glasses::N_BK7.eval(587.5618) - 1.5168).abs() < 5e-6); // catalogue n_d
//! let plastic = Cauchy::new(1.5, 0.0042, 0.0)?;
//! assert!(plastic.eval(400.0) > plastic.eval(700.0)); // normal dispersion
//! assert!(Cauchy::new(-1.0, 0.0, 0.0).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::spectrum::interface::{Pieces, Spectrum};
use crate::spectrum::interp;
use crate::spectrum::tabulated::TabulatedSpectrum;
use crate::spectrum::validate::Role;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, WavelengthRange};

/// A conductor's complex refractive index `η + i·k`, as two tables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor<'a> {
    eta: &'a TabulatedSpectrum,
    k: &'a TabulatedSpectrum,
}

impl<'a> Conductor<'a> {
    /// The conductor of real part `eta` (a table of role
    /// [`Role::Index`]) and extinction coefficient `k` (of role
    /// [`Role::Extinction`]); an [`Error::Role`] for a table of another
    /// role (a light's or a reflectance's values are not an index).
    pub fn new(eta: &'a TabulatedSpectrum, k: &'a TabulatedSpectrum) -> Result<Self, Error> {
        for (table, expected, what) in
            [(eta, Role::Index, "a conductor's η"), (k, Role::Extinction, "a conductor's k")]
        {
            if table.role() != expected {
                return Err(Error::Role { what, expected, found: table.role() });
            }
        }
        Ok(Conductor { eta, k })
    }

    /// The built-in conductors' (their tables' roles are the build
    /// script's).
    pub(crate) const fn built_in(eta: &'a TabulatedSpectrum, k: &'a TabulatedSpectrum) -> Self {
        Conductor { eta, k }
    }

    /// η, the real part of the refractive index.
    #[must_use]
    pub fn eta(&self) -> &'a TabulatedSpectrum {
        self.eta
    }

    /// k, the extinction coefficient.
    #[must_use]
    pub fn k(&self) -> &'a TabulatedSpectrum {
        self.k
    }

    /// The reflectance at normal incidence, a spectrum.
    #[must_use]
    pub fn reflectance(&self) -> NormalReflectance<'a> {
        NormalReflectance { conductor: *self }
    }
}

/// A conductor's reflectance at normal incidence,
/// `((η − 1)² + k²) / ((η + 1)² + k²)`, in `[0, 1]`. Not a polynomial:
/// integrated by quadrature between the tables' samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalReflectance<'a> {
    conductor: Conductor<'a>,
}

impl NormalReflectance<'_> {
    /// The reflectance tabulated from 380 to 730 nm at every whole
    /// nanometre and every sample of η and k, linear between (within 2e-5
    /// of the formula, `tests/truth/named.rs`): the form the study's commands
    /// take a surface in.
    #[must_use]
    pub fn tabulated(&self) -> TabulatedSpectrum {
        let knots = self.conductor.eta.lambda().iter().chain(self.conductor.k.lambda());
        let whole = (0..=(LAMBDA_MAX - LAMBDA_MIN) as usize).map(|i| LAMBDA_MIN + i as f64);
        let mut lambda: Vec<f64> =
            whole.chain(knots.copied().filter(|l| (LAMBDA_MIN..=LAMBDA_MAX).contains(l))).collect();
        lambda.sort_by(f64::total_cmp);
        lambda.dedup();
        let values = lambda.iter().map(|&l| self.eval(l)).collect();
        TabulatedSpectrum::with_interpolation(
            lambda,
            values,
            crate::Role::Reflectance,
            crate::Interpolation::Linear,
        )
        .expect("a reflectance in [0, 1] on a 1 nm grid")
    }
}

impl Spectrum for NormalReflectance<'_> {
    fn eval(&self, lambda: f64) -> f64 {
        let (eta, k) = (self.conductor.eta.eval(lambda), self.conductor.k.eval(lambda));
        let (below, above) = ((eta - 1.0).powi(2) + k * k, (eta + 1.0).powi(2) + k * k);
        if above > 0.0 { (below / above).clamp(0.0, 1.0) } else { 0.0 }
    }

    /// Not a polynomial: integrated by quadrature.
    fn pieces(&self) -> Option<Pieces<'_>> {
        None
    }

    /// A bound: 1 (no reflectance exceeds it).
    fn max_value(&self) -> f64 {
        1.0
    }
}

/// A dielectric's refractive index by Sellmeier's formula,
/// `n² = 1 + Σᵢ Bᵢλ²/(λ² − Cᵢ)` (λ in µm, Cᵢ in µm²), evaluated at
/// wavelengths in nanometres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sellmeier {
    b: [f64; 3],
    c: [f64; 3],
}

impl Sellmeier {
    /// The formula of coefficients `b` and `c` (µm²) as published, for
    /// data made at compile time (not checked; [`Sellmeier::new`] checks).
    #[must_use]
    pub const fn from_coefficients(b: [f64; 3], c: [f64; 3]) -> Self {
        Sellmeier { b, c }
    }

    /// The formula of coefficients `b` and `c` (µm²): an
    /// [`Error::Dispersion`] unless every coefficient is finite, every Cᵢ
    /// non-negative, and n real, finite and positive at every nanometre
    /// from 360 to 830 nm (no resonance inside).
    pub fn new(b: [f64; 3], c: [f64; 3]) -> Result<Self, Error> {
        let finite = b.iter().chain(&c).all(|v| v.is_finite()) && c.iter().all(|&v| v >= 0.0);
        let s = Sellmeier { b, c };
        let (min, max) = (WavelengthRange::VISIBLE.min(), WavelengthRange::VISIBLE.max());
        let resonance = c.iter().any(|&ci| (min * 1e-3..=max * 1e-3).contains(&ci.sqrt()));
        if finite && !resonance && index_is_physical(&s) { Ok(s) } else { Err(Error::Dispersion) }
    }

    /// `Bᵢ`.
    #[must_use]
    pub fn b(&self) -> [f64; 3] {
        self.b
    }

    /// `Cᵢ`, µm².
    #[must_use]
    pub fn c(&self) -> [f64; 3] {
        self.c
    }
}

impl Spectrum for Sellmeier {
    fn eval(&self, lambda: f64) -> f64 {
        let l2 = (lambda * 1e-3).powi(2);
        let n2 = 1.0 + (0..3).map(|i| self.b[i] * l2 / (l2 - self.c[i])).sum::<f64>();
        if n2 > 0.0 { n2.sqrt() } else { f64::NAN }
    }

    /// Exact when every Bᵢ ≥ 0: each term `Bᵢλ²/(λ² − Cᵢ)` then falls as λ
    /// grows (on either side of its resonance, none of which lies in
    /// 360–830 nm), so n is largest at 360 nm. `+∞` (no bound known)
    /// otherwise.
    fn max_value(&self) -> f64 {
        if self.b.iter().all(|&b| b >= 0.0) {
            self.eval(WavelengthRange::VISIBLE.min())
        } else {
            f64::INFINITY
        }
    }
}

/// A dielectric's refractive index by Cauchy's formula,
/// `n = A + B/λ² + C/λ⁴` (λ in µm, B in µm², C in µm⁴), evaluated at
/// wavelengths in nanometres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cauchy {
    a: f64,
    b: f64,
    c: f64,
}

impl Cauchy {
    /// The formula of `a`, `b` (µm²) and `c` (µm⁴): an
    /// [`Error::Dispersion`] unless all are finite and n is positive at
    /// every nanometre from 360 to 830 nm.
    pub fn new(a: f64, b: f64, c: f64) -> Result<Self, Error> {
        let s = Cauchy { a, b, c };
        if [a, b, c].iter().all(|v| v.is_finite()) && index_is_physical(&s) {
            Ok(s)
        } else {
            Err(Error::Dispersion)
        }
    }
}

impl Spectrum for Cauchy {
    fn eval(&self, lambda: f64) -> f64 {
        let l2 = (lambda * 1e-3).powi(2);
        self.a + self.b / l2 + self.c / (l2 * l2)
    }

    /// A polynomial in 1/λ², not in λ: quadrature.
    fn pieces(&self) -> Option<Pieces<'_>> {
        None
    }

    /// Exact: n is a quadratic in u = 1/λ² over u's interval, largest at an
    /// end or at its vertex.
    fn max_value(&self) -> f64 {
        let u = |lambda: f64| 1.0 / (lambda * 1e-3).powi(2);
        let (lo, hi) = (u(WavelengthRange::VISIBLE.max()), u(WavelengthRange::VISIBLE.min()));
        interp::segment_max([self.a, self.b, self.c, 0.0], lo, hi)
    }
}

/// True if `n` is finite and positive at every whole nanometre of
/// 360–830 nm.
fn index_is_physical(n: &impl Spectrum) -> bool {
    (0..=470).all(|i| {
        let v = n.eval(WavelengthRange::VISIBLE.min() + f64::from(i));
        v.is_finite() && v > 0.0
    })
}
