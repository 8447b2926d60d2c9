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
                // The last u of [0, 1) in `T` draws the range's end.
                let u = T::from_f64(u);
                Ok(self.hero(if u < T::ONE { u } else { T::BELOW_ONE }))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Constant;

    /// The mean normalised Y of a constant 1 over `n` stratified draws.
    fn white<P: WavelengthPdf, O: Observer>(domain: &Domain<P, O>, n: u32) -> f64 {
        let one = Constant::new(1.0);
        let sum: f64 = (0..n)
            .map(|i| {
                let h = domain.hero::<4, f64>((f64::from(i) + 0.5) / f64::from(n));
                h.to_xyz(h.sample(&one)).y
            })
            .sum();
        domain.normalized(Xyz::new(0.0, sum / f64::from(n), 0.0)).y
    }

    /// Each built-in domain's `∫ȳ` is its observer's over its range, and
    /// what a constant 1's draws average to.
    #[test]
    fn built_in_domains_normalise_a_constant_to_1() {
        let visible = DenseObserver::CIE_1931.y_integral(WavelengthRange::VISIBLE);
        assert_eq!(Domain::VISIBLE.y_integral(), visible);
        assert_eq!(Domain::UNIFORM_VISIBLE.y_integral(), visible);
        let assignment = DenseObserver::ASSIGNMENT.y_integral(WavelengthRange::ASSIGNMENT);
        assert_eq!(Domain::ASSIGNMENT.y_integral(), assignment);
        assert!((visible - 106.8569).abs() < 1e-4 && (assignment - 106.8489).abs() < 1e-4);
        // The exact observer's, made at run time: the constant's cubic integral.
        let exact = Domain::new(Uniform::ASSIGNMENT, AssignmentObserver).unwrap();
        assert!((exact.y_integral() / Domain::ASSIGNMENT_EXACT.y_integral() - 1.0).abs() < 1e-14);
        for y in [white(&Domain::VISIBLE, 1 << 14), white(&Domain::UNIFORM_VISIBLE, 1 << 14)] {
            assert!((y - 1.0).abs() < 1e-5, "{y}");
        }
        for y in [white(&Domain::ASSIGNMENT, 1 << 14), white(&Domain::ASSIGNMENT_EXACT, 1 << 14)] {
            assert!((y - 1.0).abs() < 1e-5, "{y}");
        }
        let made = Domain::new(Uniform::VISIBLE, DenseObserver::CIE_1931).unwrap();
        assert_eq!(made, Domain::UNIFORM_VISIBLE);
        assert_eq!(
            (made.range(), made.pdf(), made.observer()),
            (WavelengthRange::VISIBLE, &Uniform::VISIBLE, &DenseObserver::CIE_1931)
        );
        let h = made.hero::<4, f64>(0.3);
        let v = SampledSpectrum::splat(2.0);
        assert!((made.luminance(&h, v) / (h.y(v) / visible) - 1.0).abs() < 1e-15);
    }

    /// A uniform density over whole nanometres draws in fixed point (as
    /// `HeroSample::new`); any other by its inverse CDF.
    #[test]
    fn uniform_domains_draw_in_fixed_point() {
        for u in [0.0f64, 0.1234, 0.5, 0.999] {
            assert_eq!(Domain::ASSIGNMENT.hero::<4, f32>(u as f32), HeroSample::new(u as f32));
            assert_eq!(
                Domain::ASSIGNMENT.hero_by_cdf::<4, f64>(u),
                HeroSample::from_pdf_with(u, &Uniform::ASSIGNMENT, &DenseObserver::ASSIGNMENT).unwrap()
            );
            let v = Domain::UNIFORM_VISIBLE.hero::<4, f64>(u);
            let expected = 360.0 + (u * 470.0 * 65536.0).floor() / 65536.0;
            assert_eq!(v.lambda()[0], expected, "{u}");
            assert_eq!(Domain::VISIBLE.hero::<4, f64>(u), Domain::VISIBLE.hero_by_cdf(u));
        }
        let odd =
            Domain::new(Uniform::over(WavelengthRange::new(400.5, 700.0).unwrap()), DenseObserver::CIE_1931)
                .unwrap();
        assert_eq!(odd.hero::<4, f64>(0.25), odd.hero_by_cdf(0.25), "not whole nanometres: by the CDF");
        // Whole nanometres inside 360–830 nm: in fixed point over that range.
        let inner =
            Domain::new(Uniform::over(WavelengthRange::new(400.0, 700.0).unwrap()), DenseObserver::CIE_1931)
                .unwrap();
        for u in [0.0f64, 0.1234, 0.5, 0.999] {
            let (fixed, by_cdf) = (inner.hero::<4, f64>(u), inner.hero_by_cdf::<4, f64>(u));
            (0..4).for_each(|j| assert!((fixed.lambda()[j] - by_cdf.lambda()[j]).abs() < 1e-4, "{u}"));
            assert_eq!(fixed.lambda()[0], 400.0 + (u * 300.0 * 65536.0).floor() / 65536.0, "{u}");
        }
    }

    /// A density reaching past the observer's data is refused; a hero
    /// wavelength rebuilds its sample; one outside the range is refused.
    #[test]
    fn refusals_and_rebuilds() {
        assert!(matches!(
            Domain::new(Visible::VISIBLE, DenseObserver::ASSIGNMENT),
            Err(Error::RangeOutside { range: [360.0, 830.0], data: [380.0, 780.0], .. })
        ));
        for u in [0.0, 0.3, 0.77] {
            let h = Domain::VISIBLE.hero::<4, f64>(u);
            let back = Domain::VISIBLE.hero_at::<4, f64>(h.lambda()[0]).unwrap();
            (0..4).for_each(|j| assert!((back.lambda()[j] - h.lambda()[j]).abs() < 1e-9, "{u}"));
            let g = Domain::UNIFORM_VISIBLE.hero::<4, f64>(u);
            assert_eq!(Domain::UNIFORM_VISIBLE.hero_at::<4, f64>(g.lambda()[0]).unwrap(), g);
        }
        // The range's last wavelength draws from the last u below 1, in
        // each precision (in f32 the f64 just below 1 is 1, which wraps).
        let end = Domain::UNIFORM_VISIBLE.hero_at::<4, f64>(830.0).unwrap();
        assert!((end.lambda()[0] - 830.0).abs() < 1e-4);
        let end = Domain::VISIBLE.hero_at::<4, f32>(830.0).unwrap();
        assert_eq!(end, Domain::VISIBLE.hero::<4, f32>(1.0 - f32::EPSILON / 2.0));
        assert!((end.lambda()[0] - 830.0).abs() < 1e-3, "{:?}", end.lambda());
        let end = Domain::VISIBLE.hero_at::<4, f64>(830.0).unwrap();
        assert_eq!(end, Domain::VISIBLE.hero::<4, f64>(1.0 - f64::EPSILON / 2.0));
        for outside in [359.0, 830.5, f64::NAN] {
            assert!(Domain::VISIBLE.hero_at::<4, f64>(outside).is_err(), "{outside}");
        }
        // Inside the range where the density is 0: no sample has its hero there.
        let gap = Domain::new(Gap, DenseObserver::CIE_1931).unwrap();
        assert!(gap.hero_at::<4, f64>(550.0).is_err());
        let h = gap.hero_at::<4, f64>(450.0).unwrap();
        assert!((h.lambda()[0] - 450.0).abs() < 1e-9);
        let own = Domain::ASSIGNMENT.wavelengths([500.0, 790.0], [0.01, 0.01]);
        assert!(matches!(own, Err(Error::SampleWavelength { index: 1, .. })));
        assert!(Domain::ASSIGNMENT.wavelengths([500.0, 790.0], [0.01, 0.0]).is_ok());
        let one = Domain::VISIBLE.reference(&[&Constant::new(1.0)]).unwrap();
        assert!((one.y / Domain::VISIBLE.y_integral() - 1.0).abs() < 1e-12);
    }

    /// Uniform over 360–500 and 600–830 nm, 0 between.
    struct Gap;

    impl WavelengthPdf for Gap {
        fn sample(&self, u: f64) -> f64 {
            let x = u * 370.0;
            if x < 140.0 { 360.0 + x } else { 460.0 + x }
        }
        fn pdf(&self, lambda: f64) -> f64 {
            let inside = (360.0..=500.0).contains(&lambda) || (600.0..=830.0).contains(&lambda);
            if inside { 1.0 / 370.0 } else { 0.0 }
        }
        fn support(&self) -> WavelengthRange {
            WavelengthRange::VISIBLE
        }
        fn cdf(&self, lambda: f64) -> Option<f64> {
            let l = lambda.clamp(360.0, 830.0);
            Some(if l < 500.0 {
                (l - 360.0) / 370.0
            } else if l < 600.0 {
                140.0 / 370.0
            } else {
                (l - 460.0) / 370.0
            })
        }
    }
}
