//! The interface of every wavelength density ([`WavelengthPdf`], public
//! as `sampling::pdf::WavelengthPdf`), below the densities themselves.

use crate::spectrum::WavelengthRange;

/// A probability density over wavelengths that can be sampled by inverting
/// its cumulative distribution.
pub trait WavelengthPdf {
    /// The wavelength (nm) whose CDF is `u`, for `u` in `[0, 1)`; values
    /// outside are clamped into it.
    fn sample(&self, u: f64) -> f64;
    /// The density at `lambda`, 1/nm; zero outside the support.
    fn pdf(&self, lambda: f64) -> f64;

    /// The range every wavelength it draws lies in: what an observer's
    /// data must cover to weigh them
    /// ([`HeroSample::from_pdf_with`](crate::HeroSample::from_pdf_with),
    /// [`Domain::new`](crate::sampling::Domain::new) check it).
    fn support(&self) -> WavelengthRange;

    /// The cumulative distribution at `lambda`, `∫ pdf` up to it, in
    /// `[0, 1]` (0 for NaN), if the distribution knows it: renderers never
    /// ask; exact variances (`study::variance`) do. `None` by default.
    fn cdf(&self, _lambda: f64) -> Option<f64> {
        None
    }

    /// `1/pdf(λ)`, nm, what an estimate multiplies by; 0 where the density
    /// is 0 (or so small that its reciprocal overflows).
    fn inv_pdf(&self, lambda: f64) -> f64 {
        reciprocal(self.pdf(lambda))
    }

    /// True if the density is constant over its support: a
    /// [`Domain`](crate::sampling::Domain) then draws its hero samples in
    /// fixed point, as [`HeroSample::new`](crate::HeroSample::new) does,
    /// when the support is whole nanometres. `false` by default.
    fn is_uniform(&self) -> bool {
        false
    }

    /// `sample(u)` and its `inv_pdf`, together (a tabulated pdf finds the
    /// density where it found the wavelength).
    fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
        let lambda = self.sample(u);
        (lambda, self.inv_pdf(lambda))
    }
}

/// A reference or a box to a density is the density (a renderer holds
/// mixed densities as `&dyn WavelengthPdf` or `Box<dyn WavelengthPdf>`).
macro_rules! forward_pdf {
    ($($pointer:ty),*) => {$(
        impl<P: WavelengthPdf + ?Sized> WavelengthPdf for $pointer {
            #[inline]
            fn sample(&self, u: f64) -> f64 {
                (**self).sample(u)
            }
            #[inline]
            fn pdf(&self, lambda: f64) -> f64 {
                (**self).pdf(lambda)
            }
            fn cdf(&self, lambda: f64) -> Option<f64> {
                (**self).cdf(lambda)
            }
            fn support(&self) -> WavelengthRange {
                (**self).support()
            }
            fn is_uniform(&self) -> bool {
                (**self).is_uniform()
            }
            #[inline]
            fn inv_pdf(&self, lambda: f64) -> f64 {
                (**self).inv_pdf(lambda)
            }
            #[inline]
            fn sample_with_inv_pdf(&self, u: f64) -> (f64, f64) {
                (**self).sample_with_inv_pdf(u)
            }
        }
    )*};
}

forward_pdf!(&P, Box<P>);

/// `1/p`, or 0 where `p` is 0 or its reciprocal overflows.
#[inline]
pub(crate) fn reciprocal(p: f64) -> f64 {
    let w = 1.0 / p;
    if p > 0.0 && w.is_finite() { w } else { 0.0 }
}
