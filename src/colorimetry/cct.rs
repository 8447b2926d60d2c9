//! Correlated colour temperature: the Planckian locus, and the nearest
//! temperature to a chromaticity (Ohno 2013).
//!
//! Distances are in the CIE 1960 UCS (`u, v`); `Duv` is the signed
//! distance from the locus, positive above it (towards green). The locus
//! is computed, not tabulated: a blackbody's tristimulus values with an
//! observer, range and step ([`Tristimulus`]) and Planck's constants
//! ([`PlanckConstants`]). [`Planckian::CIE`] is CIE 015:2018's practice
//! and colour-science's default: the 1931 observer over 360–780 nm at 1 nm,
//! c₂ = 1.4388e-2 m·K.
//!
//! The CIE daylight locus (CIE 015:2018 §4.1.2): [`daylight_locus_y`]
//! gives `y_D` of `x_D`, `data::lights::daylight_xy` the chromaticity of a
//! temperature, and [`daylight_cct`] the temperature along the locus
//! nearest a chromaticity.
//!
//! ```
//! use speclab::colorimetry::cct::{Planckian, uv_from_xy};
//! let p = Planckian::CIE;
//! let (t, duv) = p.cct([0.1978, 0.3122])?;
//! assert!((t - 6507.47).abs() < 0.01 && (duv - 0.003223).abs() < 1e-6);
//! let uv = p.uv_at(t, duv)?;
//! assert!((uv[0] - 0.1978).abs() < 1e-7 && (uv[1] - 0.3122).abs() < 1e-7);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::colorimetry::Tristimulus;
use crate::error::Error;
use crate::spectrum::data::lights::daylight_xy;
use crate::spectrum::{Constant, FnSpectrum, PlanckConstants, WavelengthRange};

/// The CIE 1960 UCS `[u, v]` of the chromaticity `[x, y]`.
#[must_use]
pub fn uv_from_xy([x, y]: [f64; 2]) -> [f64; 2] {
    let d = -2.0 * x + 12.0 * y + 3.0;
    [4.0 * x / d, 6.0 * y / d]
}

/// The chromaticity `[x, y]` of the CIE 1960 UCS `[u, v]`.
#[must_use]
pub fn xy_from_uv([u, v]: [f64; 2]) -> [f64; 2] {
    let d = 2.0 * u - 8.0 * v + 4.0;
    [3.0 * u / d, 2.0 * v / d]
}

/// The Planckian locus of an observer, range and step, with Planck's constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planckian {
    tristimulus: Tristimulus,
    constants: PlanckConstants,
}

/// Ohno 2013's table: 1000–100000 K, each temperature 1.001 times the
/// last, the factor falling to 1.0001 towards 100000 K (colour-science's
/// construction).
const TABLE: (f64, f64, f64) = (1000.0, 100_000.0, 1.001);

impl Planckian {
    /// CIE 015:2018 and colour-science: the 1931 observer, 360–780 nm, 1 nm, the CIE's c₂.
    pub const CIE: Planckian = Planckian {
        tristimulus: Tristimulus::CIE_1931.with_range(WavelengthRange::VISIBLE.with_max(780.0)),
        constants: PlanckConstants::CIE,
    };

    /// The locus of `tristimulus`'s observer, range and step, with `constants`.
    #[must_use]
    pub const fn new(tristimulus: Tristimulus, constants: PlanckConstants) -> Self {
        Planckian { tristimulus, constants }
    }

    /// The `[u, v]` of a blackbody at `kelvin`; an error unless the
    /// temperature is finite and positive.
    pub fn uv(&self, kelvin: f64) -> Result<[f64; 2], Error> {
        if !(kelvin.is_finite() && kelvin > 0.0) {
            return Err(Error::Temperature { kelvin });
        }
        let c = self.constants;
        let body = FnSpectrum(move |lambda: f64| c.radiance(lambda, kelvin));
        let xyz = self.tristimulus.absolute(&body, &Constant::new(1.0));
        xyz.xy().map(uv_from_xy).ok_or(Error::Temperature { kelvin })
    }

    /// The `[u, v]` at `kelvin` and `duv` off the locus, along its normal
    /// (Ohno 2013: the tangent from the locus at `kelvin` and 0.01 K more).
    pub fn uv_at(&self, kelvin: f64, duv: f64) -> Result<[f64; 2], Error> {
        let (uv0, uv1) = (self.uv(kelvin)?, self.uv(kelvin + 0.01)?);
        let (du, dv) = (uv0[0] - uv1[0], uv0[1] - uv1[1]);
        let h = du.hypot(dv);
        if duv == 0.0 || h == 0.0 {
            return Ok(uv0);
        }
        Ok([uv0[0] - duv * dv / h, uv0[1] + duv * du / h])
    }

    /// `(T, Duv)` of the chromaticity `[u, v]` by Ohno 2013: the nearest
    /// entry of a table of the locus, then the triangle through it and its
    /// neighbours, or (where `|Duv| ≥ 0.002`) the parabola through their
    /// distances. About 4,600 blackbodies summed per call: a colour
    /// scientist's function, not a renderer's per-pixel one.
    pub fn cct(&self, uv: [f64; 2]) -> Result<(f64, f64), Error> {
        let temperatures = table_temperatures();
        let distance = |t: f64| -> Result<(f64, [f64; 2]), Error> {
            let p = self.uv(t)?;
            Ok(((p[0] - uv[0]).hypot(p[1] - uv[1]), p))
        };
        let mut best = (f64::INFINITY, 1);
        for (i, &t) in temperatures.iter().enumerate() {
            let (d, _) = distance(t)?;
            if d < best.0 {
                best = (d, i);
            }
        }
        let i = best.1.clamp(1, temperatures.len() - 2);
        let (tp, ti, tn) = (temperatures[i - 1], temperatures[i], temperatures[i + 1]);
        let ((dp, p), (di, _), (dn, n)) = (distance(tp)?, distance(ti)?, distance(tn)?);
        Ok(solve([tp, ti, tn], [dp, di, dn], p, n, uv[1]))
    }
}

/// The CIE daylight locus: `y_D = −3.000·x_D² + 2.870·x_D − 0.275`.
#[must_use]
pub fn daylight_locus_y(x: f64) -> f64 {
    -3.000 * x * x + 2.870 * x - 0.275
}

/// The temperature (K, 4000–25000, as `data::lights::daylight_xy` takes
/// it) whose daylight chromaticity is nearest `xy` in CIE 1931 `x, y`
/// (colour-science's `xy_to_CCT_CIE_D`): a chromaticity past either end
/// of the locus gets that end. An [`Error::Chromaticity`] for a
/// non-finite `xy`. Golden-section search to 1e-7 K.
///
/// ```
/// use speclab::colorimetry::cct::daylight_cct;
/// use speclab::data::lights::daylight_xy;
/// let t = daylight_cct(daylight_xy(5003.0)?)?;
/// assert!((t - 5003.0).abs() < 1e-6);
/// # Ok::<(), speclab::Error>(())
/// ```
pub fn daylight_cct(xy: [f64; 2]) -> Result<f64, Error> {
    if !(xy[0].is_finite() && xy[1].is_finite()) {
        return Err(Error::Chromaticity { xy });
    }
    let distance = |t: f64| {
        let d = daylight_xy(t).unwrap_or([f64::INFINITY; 2]);
        (d[0] - xy[0]).hypot(d[1] - xy[1])
    };
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = DAYLIGHT;
    let (mut c, mut d) = (b - ratio * (b - a), a + ratio * (b - a));
    let (mut fc, mut fd) = (distance(c), distance(d));
    while b - a > 1e-7 {
        if fc <= fd {
            (b, d, fd) = (d, c, fc);
            c = b - ratio * (b - a);
            fc = distance(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + ratio * (b - a);
            fd = distance(d);
        }
    }
    // The ends themselves, where the locus stops.
    let middle = 0.5 * (a + b);
    let best =
        [DAYLIGHT.0, middle, DAYLIGHT.1].into_iter().min_by(|&s, &t| distance(s).total_cmp(&distance(t)));
    Ok(best.unwrap_or(middle))
}

/// The daylight locus' temperatures, K.
const DAYLIGHT: (f64, f64) = (4000.0, 25000.0);

/// The triangular solution, or the parabolic one where `|Duv| ≥ 0.002`.
fn solve([tp, ti, tn]: [f64; 3], [dp, di, dn]: [f64; 3], p: [f64; 2], n: [f64; 2], v: f64) -> (f64, f64) {
    let l = (n[0] - p[0]).hypot(n[1] - p[1]);
    let x = (dp * dp - dn * dn + l * l) / (2.0 * l);
    let t_triangle = tp + (tn - tp) * (x / l);
    let v_x = p[1] + (n[1] - p[1]) * (x / l);
    let sign = (v - v_x).signum() * f64::from(v != v_x);
    let duv_triangle = (dp * dp - x * x).sqrt() * sign;
    if duv_triangle.abs() < 0.002 {
        return (t_triangle, duv_triangle);
    }
    let big_x = (tn - ti) * (tp - tn) * (ti - tp);
    let a = (tp * (dn - di) + ti * (dp - dn) + tn * (di - dp)) / big_x;
    let b = -(tp * tp * (dn - di) + ti * ti * (dp - dn) + tn * tn * (di - dp)) / big_x;
    let c = -(dp * (tn - ti) * ti * tn + di * (tp - tn) * tp * tn + dn * (ti - tp) * tp * ti) / big_x;
    let t = -b / (2.0 * a);
    (t, (a * t * t + b * t + c) * sign)
}

/// The table's temperatures: 1000 and 1001 K, then each the last times a
/// factor that falls linearly from 1.001 to 1.0001 across the range, then
/// 99999 and 100000 K.
fn table_temperatures() -> Vec<f64> {
    let (start, end, spacing) = TABLE;
    let mut out = vec![start, start + 1.0];
    let (mut next, mut factor) = (start + 1.0, spacing);
    loop {
        next *= factor;
        if next >= end {
            break;
        }
        out.push(next);
        let d = ((next - start) / (end - start)).clamp(0.0, 1.0);
        factor = spacing * (1.0 - d) + (1.0 + (spacing - 1.0) / 10.0) * d;
    }
    out.extend([end - 1.0, end]);
    out
}
