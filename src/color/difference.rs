//! Colour difference: CIEDE2000 (ΔE00) between two CIELAB colours, and
//! between two XYZ colours relative to a white.
//!
//! ΔE00 ≈ 1 is a just-noticeable difference between two colours side by
//! side. The formula is CIE 142-2001 as Sharma, Wu and Dalal (2005) state
//! it, with their conventions where the standard is silent: a colour of
//! zero chroma has hue 0 (its hue then changes nothing), and the mean hue
//! of a pair more than 180° apart is taken on the shorter arc, in
//! [0, 360). Checked
//! against their 34 published test pairs (`tests/truth`). The parametric
//! factors kL, kC, kH are 1 (reference conditions) in [`ciede2000`];
//! [`ciede2000_with`] takes others ([`Parametric::TEXTILES`]: kL = 2, as
//! CIE 142-2001 suggests for textiles and colour-science's
//! `textiles=True` sets).
//!
//! ```
//! use speclab::{Xyz, color::difference::{ciede2000, delta_e00}};
//! // Sharma, Wu and Dalal (2005), Table 1, pair 1:
//! let de = ciede2000([50.0, 2.6772, -79.7751], [50.0, 0.0, -82.7485]);
//! assert!((de - 2.0425).abs() < 5e-5);
//! let white = Xyz::new(95.047, 100.0, 108.883);
//! assert_eq!(delta_e00(white, white, white), 0.0);
//! ```

use crate::color::lab::lab;
use crate::color::xyz::Xyz;

/// `25⁷`, the knee of the chroma terms.
const TWENTY_FIVE_POW_7: f64 = 6_103_515_625.0;

/// CIEDE2000's parametric factors: the weights of lightness, chroma and
/// hue differences under viewing conditions other than the reference
/// ones (each divides its term; all 1 by default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parametric {
    /// kL, lightness.
    pub k_l: f64,
    /// kC, chroma.
    pub k_c: f64,
    /// kH, hue.
    pub k_h: f64,
}

impl Parametric {
    /// The reference conditions: 1, 1, 1.
    pub const REFERENCE: Parametric = Parametric { k_l: 1.0, k_c: 1.0, k_h: 1.0 };
    /// Textiles: kL = 2, kC = kH = 1.
    pub const TEXTILES: Parametric = Parametric { k_l: 2.0, k_c: 1.0, k_h: 1.0 };
}

impl Default for Parametric {
    fn default() -> Self {
        Parametric::REFERENCE
    }
}

/// CIEDE2000 between two L\*a\*b\* colours `[L*, a*, b*]`, under the
/// reference conditions.
#[must_use]
pub fn ciede2000(lab1: [f64; 3], lab2: [f64; 3]) -> f64 {
    ciede2000_with(lab1, lab2, Parametric::REFERENCE)
}

/// CIEDE2000 with parametric factors `k`.
///
/// ```
/// use speclab::color::difference::{Parametric, ciede2000, ciede2000_with};
/// let (a, b) = ([100.0, 21.57210357, 272.2281935], [50.0, 74.05216981, 276.45318193]);
/// assert!((ciede2000_with(a, b, Parametric::TEXTILES) - 23.55420943).abs() < 1e-7);
/// assert_eq!(ciede2000_with(a, b, Parametric::default()), ciede2000(a, b));
/// ```
#[must_use]
pub fn ciede2000_with(lab1: [f64; 3], lab2: [f64; 3], k: Parametric) -> f64 {
    let [l1, a1, b1] = lab1;
    let [l2, a2, b2] = lab2;
    // a′ stretched by G, from the mean chroma of the pair.
    let c_bar = (a1.hypot(b1) + a2.hypot(b2)) / 2.0;
    let g = 0.5 * (1.0 - chroma_weight(c_bar));
    let (a1, a2) = (a1 * (1.0 + g), a2 * (1.0 + g));
    let (c1, c2) = (a1.hypot(b1), a2.hypot(b2));
    let (h1, h2) = (hue_degrees(b1, a1), hue_degrees(b2, a2));
    // The differences ΔL′, ΔC′, ΔH′. Sharma et al. set Δh′ = 0 and h̄′ =
    // h₁′ + h₂′ when a colour is neutral (C′ = 0); then ΔH′ = 0 whatever
    // Δh′ is, and h̄′ enters only S_H and R_T, both through ΔH′: those cases
    // need no branch of their own.
    let dh = h2 - h1;
    let dh = match () {
        _ if dh.abs() <= 180.0 => dh,
        _ if h2 <= h1 => dh + 360.0,
        _ => dh - 360.0,
    };
    let (dl, dc) = (l2 - l1, c2 - c1);
    let d_big_h = 2.0 * (c1 * c2).sqrt() * (dh / 2.0).to_radians().sin();
    // The means L̄′, C̄′, H̄′.
    let h_bar = match () {
        _ if (h1 - h2).abs() <= 180.0 => (h1 + h2) / 2.0,
        _ if h1 + h2 < 360.0 => (h1 + h2 + 360.0) / 2.0,
        _ => (h1 + h2 - 360.0) / 2.0,
    };
    let (l_bar, c_bar) = ((l1 + l2) / 2.0, (c1 + c2) / 2.0);
    // The weights S_L, S_C, S_H and the rotation R_T.
    let t = 1.0 - 0.17 * (h_bar - 30.0).to_radians().cos()
        + 0.24 * (2.0 * h_bar).to_radians().cos()
        + 0.32 * (3.0 * h_bar + 6.0).to_radians().cos()
        - 0.20 * (4.0 * h_bar - 63.0).to_radians().cos();
    let l50 = (l_bar - 50.0) * (l_bar - 50.0);
    let s_l = 1.0 + 0.015 * l50 / (20.0 + l50).sqrt();
    let (s_c, s_h) = (1.0 + 0.045 * c_bar, 1.0 + 0.015 * c_bar * t);
    let theta = 30.0 * (-((h_bar - 275.0) / 25.0).powi(2)).exp();
    let r_t = -2.0 * chroma_weight(c_bar) * (2.0 * theta).to_radians().sin();
    let (l, c, h) = (dl / (k.k_l * s_l), dc / (k.k_c * s_c), d_big_h / (k.k_h * s_h));
    (l * l + c * c + h * h + r_t * c * h).sqrt()
}

/// `√(C⁷ / (C⁷ + 25⁷))`.
fn chroma_weight(c: f64) -> f64 {
    let c7 = c.powi(7);
    (c7 / (c7 + TWENTY_FIVE_POW_7)).sqrt()
}

/// The hue angle of `(a′, b)` in degrees, in [0, 360); 0 for a neutral.
fn hue_degrees(b: f64, a: f64) -> f64 {
    if a == 0.0 && b == 0.0 {
        return 0.0;
    }
    let h = b.atan2(a).to_degrees();
    if h < 0.0 { h + 360.0 } else { h }
}

/// ΔE00 between two colours given as XYZ, both in CIELAB relative to
/// `white` (see [`lab`]): how far an estimate lands from a reference, as
/// seen under the light whose white it is.
#[must_use]
pub fn delta_e00(estimate: Xyz, reference: Xyz, white: Xyz) -> f64 {
    ciede2000(lab(estimate, white), lab(reference, white))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each factor divides its own term: a pair that differs in one of
    /// lightness, chroma or hue alone is halved by that factor at 2 and
    /// unchanged by the others.
    #[test]
    fn each_factor_weighs_its_own_term() {
        let two = |k_l, k_c, k_h| Parametric { k_l, k_c, k_h };
        let cases = [
            ([40.0, 10.0, 10.0], [60.0, 10.0, 10.0], two(2.0, 1.0, 1.0)), // lightness
            ([50.0, 10.0, 0.0], [50.0, 20.0, 0.0], two(1.0, 2.0, 1.0)),   // chroma, the same hue
            ([50.0, 10.0, 10.0], [50.0, 10.0, -10.0], two(1.0, 1.0, 2.0)), // hue, the same chroma
        ];
        for (a, b, k) in cases {
            let reference = ciede2000(a, b);
            assert!((2.0 * ciede2000_with(a, b, k) - reference).abs() < 1e-12 * reference, "{k:?}");
            for other in [two(2.0, 1.0, 1.0), two(1.0, 2.0, 1.0), two(1.0, 1.0, 2.0)] {
                if other != k {
                    assert!((ciede2000_with(a, b, other) - reference).abs() < 1e-12 * reference, "{other:?}");
                }
            }
        }
        assert_eq!(Parametric::default(), Parametric::REFERENCE);
    }
}
