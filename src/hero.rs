//! Random wavelengths: `HeroSample<K>` and the Monte Carlo estimator.
//!
//! One uniform number `u ∈ [0, 1)` gives the hero wavelength
//! `λ₀ = 380 + u·W` (W = 350 nm) and `K − 1` rotations `λ₀ + j·W/K`, wrapped
//! into 380–730 nm (Wilkie et al. 2014, "Hero Wavelength Spectral
//! Sampling"). Every `λⱼ` is uniform on the range, with pdf `1/W`. `K = 1` is
//! plain single-wavelength random sampling; `K = 0` does not compile.
//!
//! A spectrum evaluated at a sample is a [`SampledSpectrum<K>`]: K numbers,
//! `Copy`, multiplied point-wise. The sample's XYZ contribution is
//! `Σⱼ c̄(λⱼ)·vⱼ / (K·pdf)`, and [`estimate`] averages n of them.
//!
//! ```
//! use rand::{SeedableRng, rngs::StdRng};
//! use speclab::{data, hero, HeroSample};
//! let h = HeroSample::<4>::new(0.0);
//! assert_eq!(h.lambda(), &[380.0, 467.5, 555.0, 642.5]);
//! let v = data::D65.sample(&h) * data::A1.sample(&h);
//! let one = h.to_xyz(v); // a one-sample estimate
//! let n = std::num::NonZeroUsize::new(1000).unwrap();
//! let mean = hero::estimate::<4, _>(&data::D65, &data::A1, n, &mut StdRng::seed_from_u64(1));
//! assert!(one.y > 0.0 && (mean.y - 82.0).abs() < 5.0);
//! ```
//!
//! ```compile_fail
//! let nothing = speclab::HeroSample::<0>::new(0.5);
//! ```

use std::num::NonZeroUsize;
use std::ops::Mul;

use rand::{Rng, RngExt};

use crate::{LAMBDA_MIN, TabulatedSpectrum, WIDTH, Xyz, observer};

/// K wavelengths drawn together: a hero and its K − 1 rotations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeroSample<const K: usize> {
    lambda: [f64; K],
}

/// A spectrum's values at the K wavelengths of a [`HeroSample<K>`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledSpectrum<const K: usize> {
    /// One value per wavelength, in the sample's order.
    pub values: [f64; K],
}

impl<const K: usize> HeroSample<K> {
    /// Compile-time guard: a sample has at least one wavelength.
    const NONZERO: () = assert!(K > 0, "HeroSample needs at least one wavelength (K > 0)");

    /// The density of each wavelength, 1/nm: uniform over 380–730 nm.
    pub const PDF: f64 = 1.0 / WIDTH;

    /// The sample for `u`. Only the fractional part of `u` counts
    /// (`u − ⌊u⌋`, so 1.25 acts as 0.25 and −0.25 as 0.75); a non-finite `u`
    /// acts as 0. Every wavelength lies in [380, 730] nm.
    #[inline]
    #[must_use]
    pub fn new(u: f64) -> Self {
        let () = Self::NONZERO;
        let u = if u.is_finite() { u - u.floor() } else { 0.0 };
        let u = if u < 1.0 { u } else { 0.0 };
        let lambda = std::array::from_fn(|j| {
            let v = u + j as f64 / K as f64;
            LAMBDA_MIN + WIDTH * if v >= 1.0 { v - 1.0 } else { v }
        });
        HeroSample { lambda }
    }

    /// The wavelengths, nm; the hero first.
    #[inline]
    #[must_use]
    pub fn lambda(&self) -> &[f64; K] {
        &self.lambda
    }

    /// The density of each wavelength, 1/nm.
    #[inline]
    #[must_use]
    pub fn pdf(&self) -> f64 {
        Self::PDF
    }

    /// The sample's XYZ estimate of a spectrum with values `v`:
    /// `Σⱼ c̄(λⱼ)·vⱼ / (K·pdf)`.
    #[inline]
    #[must_use]
    pub fn to_xyz(&self, v: SampledSpectrum<K>) -> Xyz {
        let mut sum = Xyz::ZERO;
        for (&lambda, &value) in self.lambda.iter().zip(&v.values) {
            sum += observer::xyz_bar(lambda) * value;
        }
        sum / (K as f64 * Self::PDF)
    }
}

impl TabulatedSpectrum {
    /// The spectrum's values at the wavelengths of `h`.
    #[inline]
    #[must_use]
    pub fn sample<const K: usize>(&self, h: &HeroSample<K>) -> SampledSpectrum<K> {
        SampledSpectrum { values: h.lambda.map(|lambda| self.eval(lambda)) }
    }
}

impl<const K: usize> Mul for SampledSpectrum<K> {
    type Output = Self;
    /// The point-wise product.
    #[inline]
    fn mul(self, o: Self) -> Self {
        SampledSpectrum { values: std::array::from_fn(|j| self.values[j] * o.values[j]) }
    }
}

/// The XYZ of one sample of `light × surface` drawn with `rng`.
#[inline]
pub fn sample_xyz<const K: usize, R: Rng + ?Sized>(
    light: &TabulatedSpectrum,
    surface: &TabulatedSpectrum,
    rng: &mut R,
) -> Xyz {
    let h = HeroSample::<K>::new(rng.random::<f64>());
    h.to_xyz(light.sample(&h) * surface.sample(&h))
}

/// The mean of `n` one-sample estimates of `light × surface`, each drawn
/// with `rng`; accumulates in f64. The same seed gives the same result.
/// `n` is non-zero by type: a mean of no samples does not exist.
#[must_use]
pub fn estimate<const K: usize, R: Rng + ?Sized>(
    light: &TabulatedSpectrum,
    surface: &TabulatedSpectrum,
    n: NonZeroUsize,
    rng: &mut R,
) -> Xyz {
    let mut sum = Xyz::ZERO;
    for _ in 0..n.get() {
        sum += sample_xyz::<K, R>(light, surface, rng);
    }
    sum / n.get() as f64
}

/// The hero widths K that [`estimate_dyn`] dispatches to compiled instances.
pub const WIDTHS: [usize; 6] = [1, 2, 3, 4, 8, 16];

/// [`estimate`] for a hero width `k` known only at run time: dispatches to
/// `HeroSample<K>` for K in [`WIDTHS`], an error otherwise.
pub fn estimate_dyn<R: Rng + ?Sized>(
    k: usize,
    light: &TabulatedSpectrum,
    surface: &TabulatedSpectrum,
    n: NonZeroUsize,
    rng: &mut R,
) -> Result<Xyz, crate::Error> {
    Ok(match k {
        1 => estimate::<1, R>(light, surface, n, rng),
        2 => estimate::<2, R>(light, surface, n, rng),
        3 => estimate::<3, R>(light, surface, n, rng),
        4 => estimate::<4, R>(light, surface, n, rng),
        8 => estimate::<8, R>(light, surface, n, rng),
        16 => estimate::<16, R>(light, surface, n, rng),
        _ => return Err(crate::Error::UnsupportedHeroWidth { k }),
    })
}
