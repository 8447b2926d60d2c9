//! What a renderer's colours are over, named once: a wavelength density
//! (which fixes the range), an observer to weigh the wavelengths it draws,
//! and the normalisation that makes a constant 1 have `Y = 1`.
//!
//! A [`Domain`] is checked when it is made (the observer's data cover
//! everything the density draws: no wavelength weighs a silent 0) and then
//! draws without a `Result` ([`Domain::hero`]); it normalises
//! ([`Domain::normalized`]: `∫ȳ` over the range as its observer weighs,
//! a constant) and integrates exactly ([`Domain::reference`], with the
//! observer's exact form) over the same range with the same observer.
//!
//! | domain | density | observer | `∫ȳ`, what a constant 1's `Y` is divided by |
//! |---|---|---|---|
//! | [`Domain::VISIBLE`] | pbrt-v4's visible pdf over 360–830 nm | CIE 1931 2°, 1 nm | 106.8569 (pbrt-v4's `CIE_Y_integral`, 106.856895) |
//! | [`Domain::UNIFORM_VISIBLE`] | uniform over 360–830 nm | CIE 1931 2°, 1 nm | the same |
//! | [`Domain::ASSIGNMENT`] | uniform over 380–730 nm | the assignment's 5 nm table, cubic, at each whole nanometre | 106.8489 (the study's, Appendix 2's range) |
//! | [`Domain::ASSIGNMENT_EXACT`] | uniform over 380–730 nm | the same cubic, exactly | the same |
//! | [`Domain::new`]`(pdf, observer)?` | any | any | its own |
//!
//! ```
//! use speclab::{Spectrum, data::lights, sampling::Domain, spectrum::Constant};
//! let domain = Domain::VISIBLE; // the one place a range and an observer are named
//! let (n, d65) = (4096, &lights::CIE_D65);
//! let (mut white, mut light) = (speclab::Xyz::ZERO, speclab::Xyz::ZERO);
//! for i in 0..n {
//!     let h = domain.hero::<4, f64>((i as f64 + 0.5) / n as f64);
//!     white += h.to_xyz(h.sample(&Constant::new(1.0)));
//!     light += h.to_xyz(h.sample(d65));
//! }
//! let white = domain.normalized(white / n as f64);
//! assert!((white.y - 1.0).abs() < 1e-4); // exactly 1 on average; 1e-7 at 2²⁰ samples
//! let exact = domain.reference(&[d65])?;
//! assert!(((light.y / n as f64) / exact.y - 1.0).abs() < 1e-3);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::Error;
use crate::sampling::hero::{HeroSample, UniformGrid, covers};
use crate::sampling::pdf::{Uniform, Visible, WavelengthPdf};
use crate::spectrum::observer::{AssignmentObserver, Observer, Y_BAR_INTEGRAL};
use crate::spectrum::{
    DenseObserver, Float, SampledSpectrum, Spectrum, StandardObserver, WavelengthRange, integrate,
};

/// A density, the observer that weighs what it draws (a CIE observer's
/// 1 nm table, `DenseObserver`, unless named: a camera's sensor, the
/// exact interpolated tables), and their `∫ȳ` (see the module).
#[derive(Clone, Debug, PartialEq)]
pub struct Domain<P = Visible, O = DenseObserver> {
    pdf: P,
    observer: O,
    y_integral: f64,
    /// A uniform density's whole nanometres, drawn in fixed point.
    grid: Option<UniformGrid>,
}

impl Domain<Visible> {
    /// pbrt-v4's visible-wavelength density over 360–830 nm, weighed by the
    /// CIE 1931 2° observer's 1 nm table: a renderer's.
    pub const VISIBLE: Domain<Visible> = Domain {
        pdf: Visible::VISIBLE,
        observer: DenseObserver::CIE_1931,
        y_integral: DenseObserver::CIE_1931.y_integral_const(WavelengthRange::VISIBLE),
        grid: None,
    };
}

impl Domain<Uniform> {
    /// Uniform over 360–830 nm, weighed by the CIE 1931 2° observer's 1 nm
    /// table.
    pub const UNIFORM_VISIBLE: Domain<Uniform> = Domain {
        pdf: Uniform::VISIBLE,
        observer: DenseObserver::CIE_1931,
        y_integral: DenseObserver::CIE_1931.y_integral_const(WavelengthRange::VISIBLE),
        grid: Some(UniformGrid::VISIBLE),
    };

    /// Uniform over 380–730 nm, weighed by the assignment's observer at
    /// each whole nanometre: the study's, over Appendix 2's range.
    pub const ASSIGNMENT: Domain<Uniform> = Domain {
        pdf: Uniform::ASSIGNMENT,
        observer: DenseObserver::ASSIGNMENT,
        y_integral: DenseObserver::ASSIGNMENT.y_integral_const(WavelengthRange::ASSIGNMENT),
        grid: Some(UniformGrid::ASSIGNMENT),
    };
}

impl Domain<Uniform, AssignmentObserver> {
    /// Uniform over 380–730 nm, weighed by the assignment's observer
    /// interpolated exactly (its cubic): the estimator the study judges
    /// against the exact integrals.
    pub const ASSIGNMENT_EXACT: Domain<Uniform, AssignmentObserver> = Domain {
        pdf: Uniform::ASSIGNMENT,
        observer: AssignmentObserver,
        y_integral: Y_BAR_INTEGRAL,
        grid: Some(UniformGrid::ASSIGNMENT),
    };
}

impl<P: WavelengthPdf, O: Observer> Domain<P, O> {
    /// Draws from `pdf`, weighed by `observer`: an
    /// [`Error::RangeOutside`] if the pdf draws where the observer has no
    /// data.
    pub fn new(pdf: P, observer: O) -> Result<Self, Error> {
        covers(&observer, pdf.support())?;
        let y_integral = observer.y_integral(pdf.support());
        let grid = if pdf.is_uniform() { UniformGrid::of(pdf.support()) } else { None };
        Ok(Domain { pdf, observer, y_integral, grid })
    }

    /// The density.
    #[must_use]
    pub fn pdf(&self) -> &P {
        &self.pdf
    }

    /// The observer.
    #[must_use]
    pub fn observer(&self) -> &O {
        &self.observer
    }

    /// The range the density draws in.
    #[must_use]
    pub fn range(&self) -> WavelengthRange {
        self.pdf.support()
    }

    /// `∫ȳ` over the range, as the observer's 1 nm table weighs what is
    /// drawn: the `Y` of a constant 1, in nm.
    #[must_use]
    pub const fn y_integral(&self) -> f64 {
        self.y_integral
    }

    /// `xyz` over `∫ȳ`: a constant 1 has `Y = 1`.
    #[must_use]
    pub fn normalized(&self, xyz: Xyz) -> Xyz {
        xyz / self.y_integral
    }

    /// The luminance of values `v` at `h`'s wavelengths, in their units:
    /// `h.y(v)` over `∫ȳ`, in `T` (a constant's is the constant, on
    /// average).
    #[inline]
    #[must_use]
    pub fn luminance<const K: usize, T: Float>(&self, h: &HeroSample<K, T>, v: SampledSpectrum<K, T>) -> T {
        h.y(v) * T::from_f64(1.0 / self.y_integral)
    }

    /// The hero sample for `u`, weighed by the observer: for a uniform
    /// density over whole nanometres drawn in fixed point as
    /// [`HeroSample::new`] draws (rounded to 2⁻¹⁶ nm, the nearest
    /// nanometres found without a conversion: the fast path), otherwise
    /// [`Domain::hero_by_cdf`].
    #[inline(always)]
    #[must_use]
    pub fn hero<const K: usize, T: Float>(&self, u: T) -> HeroSample<K, T> {
        match self.grid {
            Some(grid) => HeroSample::uniform_in(u, grid, &self.observer),
            None => HeroSample::drawn(u, &self.pdf, &self.observer),
        }
    }

    /// The hero sample for `u` by the density's inverse CDF in `f64`
    /// rotated in primary-sample space ([`HeroSample::from_pdf_with`],
    /// checked when the domain was made), for every density alike: the
    /// study's estimator, whose published figures were made with it.
    #[inline(always)]
    #[must_use]
    pub fn hero_by_cdf<const K: usize, T: Float>(&self, u: T) -> HeroSample<K, T> {
        HeroSample::drawn(u, &self.pdf, &self.observer)
    }

    /// The hero sample whose hero wavelength is `lambda`: the sample of the
    /// `u` that drew it (`u = P(λ)`, the density's CDF), so its companions
    /// and weights are the ones it was drawn with (a renderer whose rays
    /// carry one wavelength rebuilds the rest). An
    /// [`Error::SampleWavelength`] for a wavelength the density does not
    /// draw, or a density without a CDF.
    pub fn hero_at<const K: usize, T: Float>(&self, lambda: T) -> Result<HeroSample<K, T>, Error> {
        let l = lambda.to_f64();
        let inside = self.range().contains(l) && self.pdf.pdf(l) > 0.0;
        match self.pdf.cdf(l) {
            Some(u) if inside => {
                // The last u of [0, 1) draws the range's end.
                let u = if u < 1.0 { u } else { 1.0 - f64::EPSILON / 2.0 };
                Ok(self.hero(T::from_f64(u)))
            }
            _ => Err(Error::SampleWavelength { index: 0, lambda: l, pdf: self.pdf.pdf(l) }),
        }
    }

    /// The renderer's own wavelengths and their densities, weighed by the
    /// observer ([`HeroSample::from_wavelengths_with`]).
    pub fn wavelengths<const K: usize, T: Float>(
        &self,
        lambda: [T; K],
        pdf: [T; K],
    ) -> Result<HeroSample<K, T>, Error> {
        HeroSample::from_wavelengths_with(lambda, pdf, &self.observer)
    }
}

impl<P: WavelengthPdf> Domain<P, DenseObserver> {
    /// XYZ of the product of `factors` over the range, integrated exactly
    /// with the observer's exact form (the CIE's 1 nm table linear between
    /// rows; the assignment's cubic); normalise it with
    /// [`Domain::normalized`].
    pub fn reference(&self, factors: &[&dyn Spectrum]) -> Result<Xyz, Error> {
        let observer = StandardObserver::of_dense(&self.observer);
        integrate::xyz_of_product_with(observer, self.range(), factors).map(Xyz::from)
    }
}
