//! Exact integrals against the observer: `∫ Π factors · c̄ dλ` over
//! 380–730 nm, piece by piece.
//!
//! Between two consecutive breaks of every factor and of x̄, ȳ, z̄, each is
//! one polynomial of degree ≤ 3, so the product of a light, a reflectance
//! and a matching function has degree ≤ 7, and a Gauss–Legendre rule of
//! enough points integrates it exactly, up to rounding. Results are
//! `[X, Y, Z]` arrays at this floor; `sampling::reference` makes them
//! `Xyz`.

use crate::spectrum::observer;
use crate::spectrum::piecewise::{View, pieces_into};
use crate::spectrum::quadrature;
use crate::spectrum::tabulated::TabulatedSpectrum;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};

/// `[X, Y, Z]` of the perfect white (reflectance 1) under `light`:
/// `∫ L·c̄` over 380–730 nm ∩ the light's support, exactly.
pub(crate) fn white(light: &View) -> [f64; 3] {
    let cmf = &observer::views();
    let range = [LAMBDA_MIN, LAMBDA_MAX];
    let (a, b) = (light.lambda[0], light.lambda[light.lambda.len() - 1]);
    let mut pieces = Vec::new();
    if !pieces_into(&mut pieces, a, b, range, [light, &cmf[0], &cmf[1], &cmf[2]]) {
        return [0.0; 3];
    }
    quadrature::integrate(quadrature::gauss(5), &pieces, |x| {
        let l = light.eval(x);
        [cmf[0].eval(x) * l, cmf[1].eval(x) * l, cmf[2].eval(x) * l]
    })
}

/// `[X, Y, Z]` of the product of `factors` over 380–730 nm and their
/// common support; zero if that is empty. Exact for any number of factors:
/// the rule has enough points for the product's degree.
pub(crate) fn xyz_of_product(factors: &[&TabulatedSpectrum]) -> [f64; 3] {
    let a = factors.iter().map(|s| s.support().0).fold(LAMBDA_MIN, f64::max);
    let b = factors.iter().map(|s| s.support().1).fold(LAMBDA_MAX, f64::min);
    if a >= b {
        return [0.0; 3];
    }
    let pieces = quadrature::pieces(
        factors
            .iter()
            .copied()
            .chain(observer::CMFS)
            .flat_map(|s| s.breaks().iter().copied())
            .filter(|&x| x > a && x < b)
            .chain([a, b]),
    );
    let degree = 3 + factors.iter().map(|s| s.degree()).sum::<usize>();
    quadrature::integrate(quadrature::for_degree(degree), &pieces, |lambda| {
        let f: f64 = factors.iter().map(|s| s.eval(lambda)).product();
        observer::xyz_bar(lambda).map(|c| c * f)
    })
}
