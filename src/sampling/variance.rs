//! Exact variances of one-sample estimates, for checking the estimators'
//! spread against theory, under any wavelength pdf.
//!
//! With `f = L·R·c̄` (per channel), one hero sample of K wavelengths drawn
//! from a pdf p by rotation in primary-sample space is
//! `g(u) = (1/K)·Σⱼ h((u + j/K) mod 1)`, with `h(u) = f(λ)/p(λ)` at
//! `λ = P⁻¹(u)` and u uniform; K = 1 is one random wavelength. Since `g` has
//! period `1/K`, its second moment is `K·∫₀^{1/K} g²`, and the variance is
//! that minus `(∫f)²`: for K = 1, `∫ f²/p − (∫f)²`.
//!
//! The integral runs piece by piece over u, between the CDF values of every
//! break of the factors (folded into one period), where each term is
//! smooth. For the uniform pdf, λ is linear in u and `g²` a polynomial of
//! degree ≤ 14 on each piece: 8-point Gauss–Legendre is exact. For other
//! pdfs `g²` is smooth but not polynomial; each piece is split in four, and
//! the result agrees with a finer rule to about 1e-10 relative.
//!
//! ```
//! use speclab::{data::{lights, patches}, sampling::variance, sampling::pdf::LightPdf};
//! let one = variance::hero::<1>(&lights::D65, &patches::A1);
//! let four = variance::hero::<4>(&lights::D65, &patches::A1);
//! assert!(four.y < one.y / 4.0); // hero beats four independent wavelengths
//! let f11 = LightPdf::light(&lights::F11)?;
//! let following = variance::hero_with::<1>(&lights::F11, &patches::A1, &f11);
//! assert!(following.y < variance::hero::<1>(&lights::F11, &patches::A1).y / 10.0);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::sampling::pdf::{Uniform, WavelengthPdf};
use crate::sampling::reference;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN, TabulatedSpectrum, observer, quadrature};

/// Per-channel variance of one `HeroSample<K>` estimate of
/// `light × surface`, wavelengths uniform (K = 1: one uniformly random
/// wavelength). Exact.
#[must_use]
pub fn hero<const K: usize>(light: &TabulatedSpectrum, surface: &TabulatedSpectrum) -> Xyz {
    hero_with::<K>(light, surface, &Uniform::ASSIGNMENT)
}

/// Per-channel variance of one `HeroSample<K>` estimate of
/// `light × surface` with wavelengths drawn from `pdf`
/// ([`crate::HeroSample::from_pdf_with`]). The pieces in primary-sample space
/// come from the pdf's CDF at the factors' breaks; a pdf without a CDF is
/// integrated over 1,024 equal pieces of `u` instead.
#[must_use]
pub fn hero_with<const K: usize>(
    light: &TabulatedSpectrum,
    surface: &TabulatedSpectrum,
    pdf: &(impl WavelengthPdf + ?Sized),
) -> Xyz {
    let period = 1.0 / K as f64;
    let g = |u: f64| {
        let mut sum = [0.0; 3];
        for j in 0..K {
            let lambda = pdf.sample(u + j as f64 * period);
            let f = Xyz::from(observer::xyz_bar(lambda))
                * (light.eval(lambda) * surface.eval(lambda) * pdf.inv_pdf(lambda));
            for (s, c) in sum.iter_mut().zip(f.to_array()) {
                *s += c;
            }
        }
        sum.map(|s| s / K as f64)
    };
    let breaks = [light, surface]
        .into_iter()
        .chain(observer::CMFS)
        .flat_map(|s| s.breaks().iter().copied())
        .filter(|b| (LAMBDA_MIN..=LAMBDA_MAX).contains(b));
    let pieces = match pdf.cdf(LAMBDA_MIN) {
        Some(_) => {
            quadrature::pieces(breaks.filter_map(|b| pdf.cdf(b)).map(|c| c % period).chain([0.0, period]))
        }
        None => (0..=1024).map(|i| period * f64::from(i) / 1024.0).collect(),
    };
    // Each piece split in four: exact for the uniform pdf anyway, and a
    // finer rule for the others.
    let fine: Vec<f64> = pieces
        .windows(2)
        .flat_map(|w| (0..4).map(move |i| w[0] + (w[1] - w[0]) * f64::from(i) / 4.0))
        .chain([period])
        .collect();
    let [x2, y2, z2] = quadrature::integrate(quadrature::gauss(8), &fine, |u| g(u).map(|v| v * v));
    let mean = reference::xyz(light, surface);
    let m2 = Xyz::new(x2, y2, z2) * K as f64;
    Xyz::new(m2.x - mean.x * mean.x, m2.y - mean.y * mean.y, m2.z - mean.z * mean.z)
}
