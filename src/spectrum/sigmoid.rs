//! Spectra from RGB colours: Jakob and Hanika's sigmoid polynomials
//! ("A Low-Dimensional Function Space for Efficient Spectral Upsampling",
//! Eurographics 2019), as pbrt-v4 (`RGBSigmoidPolynomial`) and Mitsuba 3
//! (`rgb2spec`) use them.
//!
//! A [`SigmoidPolynomial`] is `s(λ) = ½ + x / (2√(1 + x²))` with
//! `x = c₀t² + c₁t + c₂`, a quadratic in the normalised wavelength
//! `t = (λ − 380 nm)/350 nm` (so the coefficients stay of moderate size):
//! smooth, in [0, 1] everywhere, three numbers per colour. `x = ±∞` gives
//! the constants 0 and 1 exactly (black and white).
//!
//! The spectra of RGB colours built on it (`RgbAlbedo`, `RgbUnbounded`,
//! `RgbIlluminant`) live with colour (`color::rgb_spectra`, one floor
//! up), beside the fit that gives their coefficients: the fit needs
//! CIELAB. This floor evaluates the polynomial.
//!
//! ```
//! use speclab::spectrum::SigmoidPolynomial;
//! let flat = SigmoidPolynomial::new([0.0, 0.0, 0.0]);
//! assert_eq!(flat.eval(555.0), 0.5);
//! assert_eq!(SigmoidPolynomial::WHITE.eval(400.0), 1.0);
//! assert_eq!(SigmoidPolynomial::BLACK.eval(400.0), 0.0);
//! let red = SigmoidPolynomial::new([-20.0, 30.0, -8.0]); // rising towards long wavelengths
//! assert!(red.eval(700.0) > red.eval(450.0));
//! ```

use std::borrow::Cow;

use crate::spectrum::interface::Pieces;
use crate::spectrum::interp;
use crate::spectrum::{LAMBDA_MIN, LAMBDA_WIDTH, WavelengthRange};

/// `½ + x/(2√(1 + x²))` over a quadratic in `t = (λ − 380)/350`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SigmoidPolynomial {
    c: [f64; 3],
}

impl SigmoidPolynomial {
    /// The constant 0 (`c₂ = −∞`).
    pub const BLACK: SigmoidPolynomial = SigmoidPolynomial { c: [0.0, 0.0, f64::NEG_INFINITY] };
    /// The constant 1 (`c₂ = +∞`).
    pub const WHITE: SigmoidPolynomial = SigmoidPolynomial { c: [0.0, 0.0, f64::INFINITY] };

    /// From `[c₀, c₁, c₂]`, in the normalised wavelength `t`.
    #[must_use]
    pub const fn new(c: [f64; 3]) -> Self {
        SigmoidPolynomial { c }
    }

    /// `[c₀, c₁, c₂]`, in the normalised wavelength `t = (λ − 380)/350`.
    #[must_use]
    pub const fn coefficients(&self) -> [f64; 3] {
        self.c
    }

    /// The value at `lambda` nm, in [0, 1] (NaN for NaN).
    #[inline]
    #[must_use]
    pub fn eval(&self, lambda: f64) -> f64 {
        let t = (lambda - LAMBDA_MIN) * (1.0 / LAMBDA_WIDTH);
        sigmoid(self.c[2] + t * (self.c[1] + t * self.c[0]))
    }

    /// Exact: the largest value over 360–830 nm (t from −20/350 to
    /// 450/350). The sigmoid rises with its argument, a quadratic in t,
    /// largest at an end or at its vertex.
    #[must_use]
    pub fn max_value(&self) -> f64 {
        let [c0, c1, c2] = self.c;
        let t = |lambda: f64| (lambda - LAMBDA_MIN) / LAMBDA_WIDTH;
        let (lo, hi) = (t(WavelengthRange::VISIBLE.min()), t(WavelengthRange::VISIBLE.max()));
        sigmoid(interp::segment_max([c2, c1, c0, 0.0], lo, hi))
    }

    /// `scale` times the values at `lambda` (nm), into `values`, in `f32`
    /// arithmetic with no branch (the coefficients rounded to `f32`): the
    /// four lanes of an `f32` hero sample at once, behind a `Box<dyn
    /// Spectrum>` too (the RGB spectra's `eval_many_f32` and
    /// `eval_many_nearest_f32`).
    #[inline(always)]
    pub fn eval_many_f32(&self, scale: f32, lambda: &[f32], values: &mut [f32]) {
        SigmoidPolynomial::eval_many_f32_coefficients(self.c.map(|v| v as f32), scale, lambda, values);
    }

    /// [`SigmoidPolynomial::eval_many_f32`] of the coefficients `c`, already
    /// in `f32`.
    #[inline(always)]
    pub fn eval_many_f32_coefficients(c: [f32; 3], scale: f32, lambda: &[f32], values: &mut [f32]) {
        let [c0, c1, c2] = c;
        for (v, &l) in values.iter_mut().zip(lambda) {
            let t = (l - LAMBDA_MIN as f32) * (1.0 / LAMBDA_WIDTH as f32);
            *v = scale * sigmoid_f32(c2 + t * (c1 + t * c0));
        }
    }

    /// True if the polynomial is a constant (`c₀ = c₁ = 0`).
    fn is_constant(&self) -> bool {
        self.c[0] == 0.0 && self.c[1] == 0.0
    }

    /// Constant pieces (none: integrated exactly) for a constant
    /// polynomial, `None` (integrated by quadrature) otherwise: the
    /// [`Spectrum::pieces`](crate::spectrum::Spectrum::pieces) of the
    /// spectra built on it.
    pub(crate) fn pieces(&self) -> Option<Pieces<'static>> {
        self.is_constant().then_some(Pieces { breaks: Cow::Borrowed(&[]), degree: 0 })
    }
}

/// `½ + x/(2√(1 + x²))`, going to 1 and 0 where `x²` overflows. For `x < 0` it is
/// computed as `1/(2r(r − x))`, `r = √(1 + x²)` (the same value without
/// the cancellation of `½ − ½|x|/r`), so the tail keeps its relative
/// precision: `sigmoid(-1e3)` is `2.5e-7` to the last digit.
#[inline]
#[must_use]
pub fn sigmoid(x: f64) -> f64 {
    let r = (1.0 + x * x).sqrt();
    if r.is_infinite() {
        return if x > 0.0 { 1.0 } else { 0.0 };
    }
    if x < 0.0 { 0.5 / (r * (r - x)) } else { 0.5 + 0.5 * x / r }
}

/// [`sigmoid`] in `f32` with one square root, one division and no
/// branch (so four lanes vectorise): `t = 1/(2r(r + |x|))` is the distance
/// to the nearer limit, `t` below 0 and `1 − t` above, each without
/// cancellation; 1 and 0 where `x²` overflows, NaN for NaN.
#[inline(always)]
#[must_use]
pub fn sigmoid_f32(x: f32) -> f32 {
    let r = (1.0 + x * x).sqrt();
    let t = 0.5 / (r * (r + x.abs()));
    if x < 0.0 { t } else { 1.0 - t }
}

/// The constant `v` in [0, 1] as a sigmoid polynomial, 0 and 1 exactly:
/// `c₂ = u/√(1 − u²)`, `u = 2v − 1` (the sigmoid's inverse), the square
/// root by Newton's steps so that compile time and run time agree.
#[inline]
pub(crate) const fn constant(v: f64) -> SigmoidPolynomial {
    if v == 0.0 {
        return SigmoidPolynomial::BLACK;
    } else if v == 1.0 {
        return SigmoidPolynomial::WHITE;
    }
    let u = 2.0 * v - 1.0;
    let root = const_sqrt(1.0 - u * u);
    SigmoidPolynomial::new([0.0, 0.0, u / root])
}

/// `√x` for finite `x > 0` in a `const fn`: eight Newton's steps from
/// half the exponent (to the last bit or one off).
const fn const_sqrt(x: f64) -> f64 {
    let mut y = f64::from_bits((x.to_bits() >> 1) + (1023u64 << 51));
    let mut i = 0;
    while i < 8 {
        y = 0.5 * (y + x / y);
        i += 1;
    }
    y
}

#[cfg(test)]
mod tests {
    use super::{SigmoidPolynomial, const_sqrt, constant, sigmoid, sigmoid_f32};

    /// The f32 form against the f64 one, relatively, over the range of
    /// arguments and at the limits; lanes against single values.
    #[test]
    fn f32_lanes_follow_f64() {
        for i in -2000i32..=2000 {
            let x = f64::from(i) * 0.01 * f64::from(i.abs()).max(1.0);
            let (exact, single) = (sigmoid(x), f64::from(sigmoid_f32(x as f32)));
            assert!((single - exact).abs() <= 4e-7 * exact, "x = {x}: {single} against {exact}");
        }
        assert_eq!((sigmoid_f32(f32::INFINITY), sigmoid_f32(f32::NEG_INFINITY)), (1.0, 0.0));
        assert_eq!((sigmoid_f32(1e30), sigmoid_f32(-1e30), sigmoid_f32(0.0)), (1.0, 0.0, 0.5));
        assert!(sigmoid_f32(f32::NAN).is_nan());
        let poly = SigmoidPolynomial::new([-20.0, 30.0, -8.0]);
        let lambda = [380.0f32, 451.5, 555.0, 729.9, 600.0];
        let mut values = [0.0f32; 5];
        poly.eval_many_f32(2.0, &lambda, &mut values);
        for (v, l) in values.iter().zip(lambda) {
            let exact = 2.0 * poly.eval(f64::from(l));
            assert!((f64::from(*v) - exact).abs() <= 2e-6 * exact, "{l}: {v} against {exact}");
        }
        let mut white = [0.0f32; 2];
        SigmoidPolynomial::WHITE.eval_many_f32(1.0, &[400.0, 700.0], &mut white);
        assert_eq!(white, [1.0, 1.0]);
    }

    /// The tail to the last digits (50-digit decimal values, quoted to 20),
    /// the middle, and the limits where `x²` overflows.
    #[test]
    #[allow(clippy::excessive_precision)]
    fn keeps_its_tail() {
        for (x, exact) in [
            (-1e3, 2.499_998_125_001_562_5e-7),
            (-3.0, 0.025_658_350_974_743_1),
            (-1e8, 2.499_999_999_999_999_8e-17),
        ] {
            let s = sigmoid(x);
            assert!((s - exact).abs() <= 4.0 * f64::EPSILON * exact, "sigmoid({x}) = {s}");
        }
        assert_eq!(sigmoid(0.0), 0.5);
        assert!((sigmoid(3.0) - (1.0 - 0.025_658_350_974_743_1)).abs() < 1e-16);
        assert_eq!((sigmoid(1e200), sigmoid(-1e200)), (1.0, 0.0));
        assert_eq!((sigmoid(f64::INFINITY), sigmoid(f64::NEG_INFINITY)), (1.0, 0.0));
    }

    /// Newton's root within an ulp of the machine's, and greys' constants
    /// the sigmoid's inverse.
    #[test]
    fn roots_and_greys() {
        for i in 1..10_000 {
            let x = f64::from(i) * 1e-4;
            let (newton, exact) = (const_sqrt(x), x.sqrt());
            assert!((newton - exact).abs() <= f64::EPSILON * exact, "{x}: {newton} against {exact}");
        }
        assert_eq!(constant(0.0), SigmoidPolynomial::BLACK);
        assert_eq!(constant(1.0), SigmoidPolynomial::WHITE);
        for v in [1e-9, 0.18, 0.5, 0.75, 1.0 - 1e-9] {
            assert!((constant(v).eval(500.0) - v).abs() < 1e-9 * v.max(1e-3), "{v}");
        }
    }
}
