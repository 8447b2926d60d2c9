//! The study's estimators: the mean of n one-sample estimates of a light
//! times a surface, wavelengths drawn from a pdf with their primary numbers
//! spread by a [`Strata`], at a hero width fixed at compile time
//! ([`estimate_with`]) or chosen at run time ([`estimate_width`]). Each
//! sample is the core's [`HeroSample`](speclab::HeroSample) with the exact observer
//! ([`AssignmentObserver`]), so the means are unbiased for the exact integrals they
//! are judged by.
//!
//! ```
//! use rand::{SeedableRng, rngs::StdRng};
//! use speclab::data::{lights, patches};
//! use speclab_study::sampling::estimate;
//! let n = std::num::NonZeroUsize::new(1000).unwrap();
//! let mean = estimate::estimate::<4, _>(&lights::D65, &patches::A1, n, &mut StdRng::seed_from_u64(1));
//! assert!((mean.y - 82.0).abs() < 5.0);
//! ```

use std::num::NonZeroUsize;

use rand::Rng;
use speclab::sampling::Domain;
use speclab::sampling::pdf::WavelengthPdf;
use speclab::spectrum::observer::{self, AssignmentObserver, Observer};
use speclab::{Error, Spectrum, Xyz};

use crate::sampling::strata::Strata;

/// The usual hero width: four wavelengths per sample.
pub const USUAL_K: usize = 4;

/// The most wavelengths a sample of a width chosen at run time takes
/// ([`estimate_width`]).
pub const MAX_WIDTH: usize = 64;

/// The mean of `n` one-sample estimates of `light × surface`, wavelengths
/// uniform and independent, drawn with `rng`; accumulates in f64. The same
/// seed gives the same result. `n` is non-zero by type: a mean of no
/// samples does not exist.
#[must_use]
pub fn estimate<const K: usize, R: Rng + ?Sized>(
    light: &impl Spectrum,
    surface: &impl Spectrum,
    n: NonZeroUsize,
    rng: &mut R,
) -> Xyz {
    estimate_in::<K, _, _, R>(light, surface, n, &Domain::ASSIGNMENT_EXACT, Strata::None, rng)
}

/// [`estimate`] with wavelengths drawn from `pdf` and the n primary numbers
/// spread by `strata`: unbiased for every pdf that is positive wherever
/// `light × surface` is, and every strata.
pub fn estimate_with<const K: usize, P: WavelengthPdf + ?Sized, R: Rng + ?Sized>(
    light: &impl Spectrum,
    surface: &impl Spectrum,
    n: NonZeroUsize,
    pdf: &P,
    strata: Strata,
    rng: &mut R,
) -> Result<Xyz, Error> {
    let domain = Domain::new(pdf, AssignmentObserver)?;
    Ok(estimate_in::<K, _, _, R>(light, surface, n, &domain, strata, rng))
}

/// [`estimate_with`] in a domain checked once (its density and observer).
pub fn estimate_in<const K: usize, P: WavelengthPdf, O: Observer, R: Rng + ?Sized>(
    light: &impl Spectrum,
    surface: &impl Spectrum,
    n: NonZeroUsize,
    domain: &Domain<P, O>,
    strata: Strata,
    rng: &mut R,
) -> Xyz {
    let sum: Xyz = strata
        .points(n.get(), K, rng)
        .map(|u| {
            let h = domain.hero_by_cdf::<K, f64>(u);
            h.to_xyz(light.sample(&h) * surface.sample(&h))
        })
        .sum();
    sum / n.get() as f64
}

/// [`estimate_with`] for a hero width `k` chosen at run time (the study's),
/// on slices: `k` wavelengths per sample, `1 ≤ k ≤` [`MAX_WIDTH`] (else an
/// [`Error::Count`]). The same wavelengths and weights as
/// `estimate_with::<K>` from the same draws, summed in another order (equal
/// to rounding: `widths_agree_with_compile_time_ones`).
pub fn estimate_width<P: WavelengthPdf + ?Sized, R: Rng + ?Sized>(
    k: usize,
    light: &(impl Spectrum + ?Sized),
    surface: &(impl Spectrum + ?Sized),
    n: NonZeroUsize,
    pdf: &P,
    strata: Strata,
    rng: &mut R,
) -> Result<Xyz, Error> {
    if !(1..=MAX_WIDTH).contains(&k) {
        return Err(Error::Count { what: "a hero width", found: k, min: 1, max: MAX_WIDTH });
    }
    let (mut lambda, mut rows) = ([0.0; MAX_WIDTH], [[0.0; MAX_WIDTH]; 3]);
    let (mut light_at, mut surface_at) = ([0.0; MAX_WIDTH], [0.0; MAX_WIDTH]);
    let lambda = &mut lambda[..k];
    let (light_at, surface_at) = (&mut light_at[..k], &mut surface_at[..k]);
    let per_k = 1.0 / k as f64;
    let mut sum = Xyz::ZERO;
    // Every strata's points are in [0, 1) (`Strata::point`), as the
    // rotations need.
    for u in strata.points(n.get(), k, rng) {
        for (j, l) in lambda.iter_mut().enumerate() {
            let (drawn, inv_pdf) = pdf.sample_with_inv_pdf(rotation(u, j, k));
            let (cmf, s) = (observer::xyz_bar(drawn), inv_pdf * per_k);
            *l = drawn;
            (0..3).for_each(|c| rows[c][j] = cmf[c] * s);
        }
        light.eval_many(lambda, light_at);
        surface.eval_many(lambda, surface_at);
        light_at.iter_mut().zip(surface_at.iter()).for_each(|(l, s)| *l *= s);
        sum += Xyz::new(
            dot(&rows[0][..k], light_at),
            dot(&rows[1][..k], light_at),
            dot(&rows[2][..k], light_at),
        );
    }
    Ok(sum / n.get() as f64)
}

/// Rotation `j` of `k` from `u ∈ [0, 1)`: `(u + j/k) mod 1`, as
/// [`HeroSample::from_pdf_with`] rotates.
fn rotation(u: f64, j: usize, k: usize) -> f64 {
    let v = u + j as f64 / k as f64;
    if v >= 1.0 { v - 1.0 } else { v }
}

/// `Σᵢ wᵢ·vᵢ` in four interleaved partial sums, `(a₀ + a₂) + (a₁ + a₃)`:
/// the order the study's figures were made in (the core's column sums add
/// in the same order; a study's run-time width cannot name them).
fn dot(w: &[f64], values: &[f64]) -> f64 {
    let n = w.len().min(values.len());
    let ((w4, w_rest), (v4, v_rest)) = (w[..n].as_chunks::<4>(), values[..n].as_chunks::<4>());
    let mut acc = [0.0; 4];
    for (w, v) in w4.iter().zip(v4) {
        for l in 0..4 {
            acc[l] += w[l] * v[l];
        }
    }
    for (l, (&w, &v)) in w_rest.iter().zip(v_rest).enumerate() {
        acc[l] += w * v;
    }
    (acc[0] + acc[2]) + (acc[1] + acc[3])
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use speclab::data::{lights, patches};
    use speclab::sampling::pdf::Uniform;

    /// A width chosen at run time gives the compile-time width's estimate
    /// from the same draws (to rounding: another order of the sums), under
    /// the uniform pdf and one that follows F11, for every strata.
    #[test]
    fn widths_agree_with_compile_time_ones() {
        let n = NonZeroUsize::new(64).expect("64");
        let f11 = speclab::sampling::pdf::LightPdf::light(&lights::F11).expect("bright");
        let pdfs: [&dyn WavelengthPdf; 2] = [&Uniform::ASSIGNMENT, &f11];
        for pdf in pdfs {
            for strata in Strata::ALL {
                let rng = || rand::rngs::StdRng::seed_from_u64(9);
                let (light, surface) = (&lights::F11, &patches::G4);
                let one = estimate_width(1, light, surface, n, pdf, strata, &mut rng()).expect("width 1");
                let four = estimate_width(4, light, surface, n, pdf, strata, &mut rng()).expect("width 4");
                let want_one = estimate_with::<1, _, _>(light, surface, n, pdf, strata, &mut rng()).unwrap();
                let want_four = estimate_with::<4, _, _>(light, surface, n, pdf, strata, &mut rng()).unwrap();
                for (got, want) in [(one, want_one), (four, want_four)] {
                    let close = (got - want).to_array().iter().all(|d| d.abs() <= 1e-12 * want.y);
                    assert!(close, "{strata:?}: {got:?} against {want:?}");
                }
            }
        }
    }
}
