//! What a compact table stores of a node: its sigmoid polynomial
//! `x(t) = c₀t² + c₁t + c₂` (`t = (λ − 380)/350`) in one of two forms,
//! each number rounded to a few bits, so that the rounding moves the
//! spectrum little whatever the coefficients' size.
//!
//! The coefficients themselves round badly: a saturated colour's reach
//! ±23,000 (±2.6 · 10⁶ in ACES2065-1) and cancel, so the spectrum rests on
//! their low bits. Two forms keep what matters:
//!
//! - **vertex**, `x = a(t − v)² + h`, where the vertex lies within
//!   [`VERTEX_REACH`] of 595 nm: `a` and `h` rounded relatively, `v` to a fixed step. A
//!   narrow peak or notch (`a` large, `h` near 0) keeps its height and
//!   width, and a step keeps its edges: rounding `a` or `h` moves an edge
//!   by a fraction of its distance from the vertex.
//! - **values**, `x` at 360, 595 and 830 nm, each rounded relatively:
//!   curves whose vertex lies far outside (nearly straight ones, and the
//!   constants of black and white).
//!
//! Numbers are rounded as small floats ([`Minifloat`]): `m` mantissa bits
//! above `2^e_min`, a fixed step `2^(e_min − m)` below (so `x` near 0 keeps
//! an absolute precision), stored as one signed integer that rises with
//! the value (neighbouring nodes give neighbouring integers, which the
//! table's prediction needs). Decoding is `const`: a table's colour can be
//! looked up at compile time.
//!
//! ```
//! use speclab_tables::rgb_file::quantize::{Quantizer, Node};
//! let q = Quantizer::DEFAULT;
//! let peak = [-48765.227_f32, 32355.922, -5367.465]; // a narrow peak (ACES2065-1)
//! let node = q.node(peak);
//! assert!(node.vertex);
//! let back = q.coefficients(node);
//! let h = |c: [f32; 3]| f64::from(c[2]) - f64::from(c[1]).powi(2) / (4.0 * f64::from(c[0]));
//! assert!((h(back) - h(peak)).abs() < 2e-3); // the peak's height, about −0.24
//! ```

/// The normalised wavelengths of the value form: 360, 595 and 830 nm.
pub const VALUE_T: [f64; 3] = [-20.0 / 350.0, 215.0 / 350.0, 450.0 / 350.0];

/// How far the vertex of the vertex form lies from the middle of the
/// renderer's range (595 nm, `t = VALUE_T[1]`) at most: 0.75, so between
/// 332 and 857 nm. Past that, `a(t − v)²` and `h` grow large and cancel
/// over 360–830 nm, and the values keep the curve better.
pub const VERTEX_REACH: f64 = 0.75;

/// A node as stored: its form and three rounded numbers, `[a, v, h]`
/// (vertex) or `[x(360), x(595), x(830)]` (values).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Node {
    /// The vertex form (otherwise the values).
    pub vertex: bool,
    /// The three numbers as integers ([`Minifloat`], and `v` in steps of
    /// `2^−vertex_bits`).
    pub k: [i64; 3],
}

/// Rounding a number to `mantissa` bits above `2^low_exponent`, and to
/// the fixed step `2^(low_exponent − mantissa)` below.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Minifloat {
    /// Mantissa bits kept, 1 to 23.
    pub mantissa: u32,
    /// The exponent below which the step is fixed, −60 to 0.
    pub low_exponent: i32,
}

impl Minifloat {
    /// The integer of `x` (round to nearest): its sign times
    /// `(e − e_min + 1)·2^m + mantissa` above `2^e_min`, `|x|/2^(e_min − m)`
    /// below; continuous and rising. NaN is 0.
    #[must_use]
    pub fn encode(self, x: f64) -> i64 {
        let (m, low) = (self.mantissa, self.low_exponent);
        let a = x.abs();
        if a.is_nan() {
            return 0;
        }
        let k = if a < pow2(low) {
            (a * pow2(m as i32 - low)).round() as i64
        } else {
            let e = (a.to_bits() >> 52) as i32 - 1023;
            // The significand from the bits (2^-e would underflow at e = 1023).
            let fraction = f64::from_bits((a.to_bits() & ((1 << 52) - 1)) | (1023 << 52)) - 1.0;
            ((e - low + 1) as i64) * (1 << m) + (fraction * pow2(m as i32)).round() as i64
        };
        if x < 0.0 { -k } else { k }
    }

    /// The value of an integer [`Minifloat::encode`] made (infinite for an
    /// exponent past `f64`'s).
    #[must_use]
    pub const fn decode(self, k: i64) -> f64 {
        let (m, low) = (self.mantissa, self.low_exponent);
        let a = k.unsigned_abs();
        let e = a >> m;
        let magnitude = if e == 0 {
            a as f64 * pow2(low - m as i32)
        } else {
            let fraction = (a & ((1 << m) - 1)) as f64;
            let exponent = if e > 2100 { 2100 } else { e as i32 };
            (pow2(m as i32) + fraction) * pow2(low + exponent - 1 - m as i32)
        };
        if k < 0 { -magnitude } else { magnitude }
    }
}

/// `2^p` (0 below f64's smallest normal, infinite above its largest).
const fn pow2(p: i32) -> f64 {
    if p < -1022 {
        0.0
    } else if p > 1023 {
        f64::INFINITY
    } else {
        f64::from_bits(((p + 1023) as u64) << 52)
    }
}

/// How a table's nodes are rounded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quantizer {
    /// `a`, `h` and the values.
    pub float: Minifloat,
    /// Bits after the point of `v`, 4 to 24.
    pub vertex_bits: u32,
}

impl Quantizer {
    /// The built-in tables' rounding: 12 mantissa bits above `2⁻⁸`, `v` in
    /// steps of `2⁻¹⁶` (0.005 nm).
    pub const DEFAULT: Quantizer =
        Quantizer { float: Minifloat { mantissa: 12, low_exponent: -8 }, vertex_bits: 16 };

    /// The node of the coefficients `c`: the vertex form where the vertex
    /// lies within [`VERTEX_REACH`] of 595 nm, the values elsewhere.
    #[must_use]
    pub fn node(self, c: [f32; 3]) -> Node {
        let [a, b, c] = c.map(f64::from);
        let v = -b / (2.0 * a);
        if a != 0.0 && v.is_finite() && (v - VALUE_T[1]).abs() <= VERTEX_REACH {
            // x = a(t − v)² + h: h = c − b²/(4a) = c + b·v/2.
            let h = c + 0.5 * b * v;
            let kv = (v * f64::from(1u32 << self.vertex_bits)).round() as i64;
            Node { vertex: true, k: [self.float.encode(a), kv, self.float.encode(h)] }
        } else {
            let x = VALUE_T.map(|t| c + t * (b + t * a));
            Node { vertex: false, k: x.map(|x| self.float.encode(x)) }
        }
    }

    /// The coefficients of a stored node, computed in `f64` and rounded to
    /// `f32` (the same bits at compile time and at run time).
    #[must_use]
    pub const fn coefficients(self, node: Node) -> [f32; 3] {
        let f = self.float;
        let c = if node.vertex {
            let a = f.decode(node.k[0]);
            let v = node.k[1] as f64 / (1u64 << self.vertex_bits) as f64;
            let h = f.decode(node.k[2]);
            [a, -2.0 * a * v, a * v * v + h]
        } else {
            let x = [f.decode(node.k[0]), f.decode(node.k[1]), f.decode(node.k[2])];
            let w = VALUE_WEIGHTS;
            let mut c = [0.0; 3];
            let mut i = 0;
            while i < 3 {
                c[i] = w[i][0] * x[0] + w[i][1] * x[1] + w[i][2] * x[2];
                i += 1;
            }
            c
        };
        [c[0] as f32, c[1] as f32, c[2] as f32]
    }
}

/// The coefficients of the quadratic through `(VALUE_T[j], x_j)`:
/// `c_i = Σ_j VALUE_WEIGHTS[i][j]·x_j` (Lagrange's form).
pub const VALUE_WEIGHTS: [[f64; 3]; 3] = value_weights();

const fn value_weights() -> [[f64; 3]; 3] {
    let t = VALUE_T;
    let mut w = [[0.0; 3]; 3];
    let mut j = 0;
    while j < 3 {
        let (p, q) = (t[(j + 1) % 3], t[(j + 2) % 3]);
        let d = (t[j] - p) * (t[j] - q);
        w[0][j] = 1.0 / d;
        w[1][j] = -(p + q) / d;
        w[2][j] = p * q / d;
        j += 1;
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The integers rise with the value, meet at 2^e_min without a gap,
    /// and decode to within half a step (relative above, absolute below).
    #[test]
    fn minifloats_round_to_their_step_and_rise() {
        let f = Minifloat { mantissa: 12, low_exponent: -8 };
        let mut last = i64::MIN;
        for i in -4000..4000 {
            let x = f64::from(i).powi(3) * 1e-6;
            let k = f.encode(x);
            assert!(k >= last, "{x}");
            last = k;
            let step = if x.abs() < 2f64.powi(-8) { 2f64.powi(-20) } else { x.abs() * 2f64.powi(-12) };
            assert!((f.decode(k) - x).abs() <= 0.5 * step + 1e-300, "{x}: {}", f.decode(k));
        }
        assert_eq!(f.encode(2f64.powi(-8)), 1 << 12);
        assert_eq!(
            f.encode(2f64.powi(-8) * (1.0 - 2f64.powi(-14))),
            1 << 12,
            "rounds up into the first octave"
        );
        assert_eq!((f.encode(f64::NAN), f.decode(0)), (0, 0.0));
        assert!(f.decode(0).is_sign_positive(), "0 is +0.0, as a fitted table's zero");
        assert_eq!(f.decode(i64::MAX), f64::INFINITY);
        assert_eq!(f.decode(-(3 << 12)), -2f64.powi(-6));
        // The top octave of f64 keeps rising and decodes to itself.
        let below = 2f64.powi(1023) * (1.0 - 2f64.powi(-13));
        let (k0, k1, k2) = (f.encode(below), f.encode(2f64.powi(1023)), f.encode(f64::MAX));
        assert!(k0 < k1 && k1 < k2, "{k0} {k1} {k2}");
        assert_eq!(f.decode(k1), 2f64.powi(1023));
        assert_eq!(f.decode(f.encode(1.5 * 2f64.powi(1023))), 1.5 * 2f64.powi(1023));
    }

    /// `pow2` is exact over f64's normal exponents, 0 below, infinite above.
    #[test]
    fn pow2_covers_the_normal_exponents() {
        for p in -1022..=1023 {
            assert_eq!(pow2(p), 2f64.powi(p), "{p}");
        }
        assert_eq!(pow2(-1022), f64::MIN_POSITIVE);
        for p in [-1023, -1024, -5000, i32::MIN] {
            assert_eq!(pow2(p).to_bits(), 0, "{p}");
        }
        for p in [1024, 5000, i32::MAX] {
            assert_eq!(pow2(p), f64::INFINITY, "{p}");
        }
    }

    /// The value form stores `x` at 360, 595 and 830 nm, `t = (λ − 380)/350`,
    /// each within half a step, for a curve as well as a line.
    #[test]
    fn values_are_taken_at_360_595_and_830_nm() {
        let q = Quantizer::DEFAULT;
        for c in [[0.0, 30.0, -12.0], [2.0, 30.0, -12.0], [-0.5, -3.0, 4.0]] {
            let node = q.node(c);
            assert!(!node.vertex, "{c:?}");
            let [a, b, c0] = c.map(f64::from);
            for (j, nm) in [360.0, 595.0, 830.0].into_iter().enumerate() {
                let t = (nm - 380.0) / 350.0;
                let x = a * t * t + b * t + c0;
                let got = q.float.decode(node.k[j]);
                assert!((got - x).abs() <= x.abs() * 2f64.powi(-13), "{c:?} at {nm} nm: {got}, {x}");
            }
        }
    }

    /// The Lagrange weights reproduce a quadratic's coefficients.
    #[test]
    fn value_weights_invert_the_values() {
        let c = [-3.5, 2.25, 0.75];
        let x = VALUE_T.map(|t| c[2] + t * (c[1] + t * c[0]));
        for i in 0..3 {
            let back: f64 = (0..3).map(|j| VALUE_WEIGHTS[i][j] * x[j]).sum();
            assert!((back - c[i]).abs() < 1e-12, "{i}: {back}");
        }
    }

    /// Each form is chosen where it belongs, and round trips to within its
    /// rounding: black, a flat grey, a straight ramp, a bump.
    #[test]
    fn forms_and_round_trips() {
        let q = Quantizer::DEFAULT;
        let black = q.node([0.0, 0.0, -1e4]);
        assert!(!black.vertex);
        let c = q.coefficients(black);
        assert!(c[0].abs() < 1e-9 && c[1].abs() < 1e-9 && c[2] == -1e4, "{c:?}");
        let ramp = q.node([0.0, 30.0, -12.0]);
        assert!(!ramp.vertex);
        let c = q.coefficients(ramp);
        // Each value within half a step, 2⁻¹³ of itself; each coefficient
        // within the weighted sum of those.
        let x = VALUE_T.map(|t| 30.0 * t - 12.0);
        for (i, (got, want)) in c.iter().zip([0.0, 30.0, -12.0]).enumerate() {
            let bound: f64 = (0..3).map(|j| VALUE_WEIGHTS[i][j].abs() * x[j].abs() * 2f64.powi(-13)).sum();
            assert!((f64::from(*got) - want).abs() <= bound + 1e-5, "{i}: {c:?}, {bound}");
        }
        let bump = q.node([-20.0, 30.0, -8.0]);
        assert!(bump.vertex && bump.k[1] == (0.75 * 65536.0) as i64, "{bump:?}");
        let c = q.coefficients(bump);
        assert!(
            (c[0] + 20.0).abs() < 1e-2 && (c[1] - 30.0).abs() < 2e-2 && (c[2] + 8.0).abs() < 2e-2,
            "{c:?}"
        );
        // Far vertex: the values.
        assert!(!q.node([1e-3, 30.0, -12.0]).vertex);
    }
}
