//! Planck's law in absolute units against published values: a
//! blackbody's spectral radiance at stated wavelengths and temperatures
//! (spectralcalc.com's blackbody calculator, W·sr⁻¹·m⁻²·µm⁻¹ there, as
//! pbrt-v4's `TEST(Spectrum, Blackbody)` quotes them per metre), and the
//! peak where Wien's displacement law (CODATA 2018, b = 2.897771955 mm·K)
//! puts it.

use speclab::Spectrum;
use speclab::spectrum::{Blackbody, planck};

/// `(λ nm, T K, radiance W·sr⁻¹·m⁻³)`, published to five or six digits.
const PUBLISHED: [(f64, f64, f64); 4] = [
    (483.0, 6000.0, 3.1849e13),
    (600.0, 6000.0, 2.86772e13),
    (500.0, 3700.0, 1.59845e12),
    (600.0, 4500.0, 7.46497e12),
];

/// Within 1e-4, relative. The published figures lie 3e-5 to 5e-5 above
/// Planck's law with CODATA 2018's constants (which an independent
/// evaluation in Python's `math` gives as this function does, to 1e-15):
/// more than their last digit, so they are held to what they agree on.
/// pbrt-v4 holds them to 1e-3.
#[test]
fn spectral_radiance_is_spectralcalcs() {
    for (lambda, kelvin, per_m) in PUBLISHED {
        let per_nm = per_m * 1e-9;
        for got in [planck(lambda, kelvin), Blackbody::absolute(kelvin).unwrap().eval(lambda)] {
            assert!((got - per_nm).abs() <= 1e-4 * per_nm, "{lambda} nm, {kelvin} K: {got} vs {per_nm}");
        }
    }
    // The independent evaluation's figures, to 1e-12: the constants and the
    // formula, not only their first four digits.
    let independent =
        [31_847.965_803_434_33, 28_676.391_377_692_914, 1_598.366_918_971_836_7, 7_464.706_361_655_986];
    for ((lambda, kelvin, _), want) in PUBLISHED.into_iter().zip(independent) {
        assert!((planck(lambda, kelvin) - want).abs() <= 1e-12 * want, "{lambda} nm, {kelvin} K");
    }
}

/// The normalised blackbody is the absolute one over its peak, and the
/// peak lies where Wien puts it.
#[test]
fn the_normalised_blackbody_peaks_at_one_where_wien_says() {
    for kelvin in [2700.0, 3000.0, 4500.0, 5600.0, 6000.0] {
        let (normal, absolute) = (Blackbody::new(kelvin).unwrap(), Blackbody::absolute(kelvin).unwrap());
        let peak = 2.897_771_955e-3 / kelvin * 1e9;
        assert!((normal.peak() - peak).abs() < 1e-9);
        assert!((normal.eval(peak) - 1.0).abs() < 1e-12);
        assert!(normal.eval(0.999 * peak) < 1.0 && normal.eval(1.001 * peak) < 1.0);
        let ratio = absolute.eval(555.0) / normal.eval(555.0);
        assert!((ratio - absolute.eval(peak)).abs() < 1e-12 * ratio, "{kelvin} K");
    }
}
