//! A texture's colours converted once, when it loads: each texel's
//! spectrum in 12 bytes, sampled with no table lookup.
//!
//! An [`RgbTexel`] is `scale · s(λ)`: a scale in `f32` and the sigmoid
//! polynomial `s` rounded as the compact tables round their nodes (the
//! vertex or value form, 12 mantissa bits, the vertex in steps of
//! 0.005 nm: `speclab_tables::rgb_file::quantize`) and packed in 64 bits.
//! Albedos, unbounded colours and lights alike convert to one
//! ([`From`]); a light's texel is its tint, and the texture keeps the
//! space's illuminant once ([`RgbSpace::illuminant`](crate::color::RgbSpace::illuminant)) to multiply in.
//! The rounding moves a texel's colour under the space's illuminant by
//! ΔE00 0.001–0.002 on average and at most 0.021, and its reflectance by
//! at most 0.006, measured on 4,000 random colours of each built-in space
//! (`tests/properties/texel.rs`, a regression snapshot); black and white
//! stay exact; pbrt-v4's texels keep RGB and look up at each hit, Mitsuba
//! 3's keep three `f32` coefficients (12 bytes, exact).
//!
//! ```
//! use speclab::color::{LinearRgb, RgbSpace, RgbTexel};
//! use speclab::{HeroSample, Spectrum};
//! let space = RgbSpace::acescg();
//! let texture = [LinearRgb::new(0.6, 0.3, 0.1), LinearRgb::new(4.0, 2.0, 0.5)];
//! let texels: Vec<RgbTexel> = texture.iter().map(|&rgb| space.unbounded(rgb).into()).collect();
//! assert_eq!(std::mem::size_of::<RgbTexel>(), 12);
//! let path = HeroSample::<4, f32>::new(0.3);
//! let beta = texels[1].sample(&path); // no lookup at the hit
//! let exact = space.unbounded(texture[1]);
//! assert!((f64::from(beta.values[0]) - exact.eval(f64::from(path.lambda()[0]))).abs() < 0.05);
//! ```

use speclab_tables::rgb_file::quantize::{Node, Quantizer};

use crate::color::rgb_spectra::{RgbAlbedo, RgbIlluminant, RgbUnbounded};
use crate::spectrum::{Pieces, SigmoidPolynomial, Spectrum};

/// A texel's spectrum, `scale · s(λ)`, in 12 bytes (see the module).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RgbTexel {
    scale: f32,
    /// The form (top bit) and three numbers of 21 bits each, two's
    /// complement.
    node: [u32; 2],
}

/// Bits of each packed number.
const BITS: u32 = 21;
/// The largest packed magnitude.
const LARGEST: i64 = (1 << (BITS - 1)) - 1;
/// Its negative: black's three numbers.
const SMALLEST: i64 = -LARGEST;

impl RgbTexel {
    /// `scale` times `poly`, rounded (the scale to `f32`, at most
    /// `f32::MAX`).
    #[must_use]
    pub fn new(scale: f64, poly: SigmoidPolynomial) -> RgbTexel {
        let c = poly.coefficients();
        let node = if c[2].is_infinite() && c[0] == 0.0 && c[1] == 0.0 {
            // Black and white, exactly: the largest values, all three.
            Node { vertex: false, k: [LARGEST * c[2].signum() as i64; 3] }
        } else {
            Quantizer::DEFAULT.node(c.map(|c| c as f32))
        };
        let k = node.k.map(|k| (k.clamp(-LARGEST, LARGEST) as u64) & ((1 << BITS) - 1));
        let bits = u64::from(node.vertex) << 63 | k[0] << (2 * BITS) | k[1] << BITS | k[2];
        RgbTexel { scale: scale.min(f64::from(f32::MAX)) as f32, node: [(bits >> 32) as u32, bits as u32] }
    }

    /// The scale.
    #[must_use]
    pub fn scale(&self) -> f64 {
        f64::from(self.scale)
    }

    /// The sigmoid polynomial, decoded.
    #[must_use]
    #[inline]
    pub fn polynomial(&self) -> SigmoidPolynomial {
        SigmoidPolynomial::new(self.coefficients().map(f64::from))
    }

    /// The polynomial's coefficients in `f32`.
    #[inline(always)]
    fn coefficients(&self) -> [f32; 3] {
        let bits = u64::from(self.node[0]) << 32 | u64::from(self.node[1]);
        // Each number's 21 bits, sign-extended.
        let field = |shift: u32| ((bits >> shift) << (64 - BITS)) as i64 >> (64 - BITS);
        let node = Node { vertex: bits >> 63 == 1, k: [field(2 * BITS), field(BITS), field(0)] };
        match node.k {
            [LARGEST, LARGEST, LARGEST] if !node.vertex => [0.0, 0.0, f32::INFINITY],
            [SMALLEST, SMALLEST, SMALLEST] if !node.vertex => [0.0, 0.0, f32::NEG_INFINITY],
            _ => Quantizer::DEFAULT.coefficients(node),
        }
    }
}

impl From<RgbAlbedo> for RgbTexel {
    fn from(albedo: RgbAlbedo) -> RgbTexel {
        RgbTexel::new(1.0, albedo.polynomial())
    }
}

impl From<RgbUnbounded> for RgbTexel {
    fn from(colour: RgbUnbounded) -> RgbTexel {
        RgbTexel::new(colour.scale(), colour.polynomial())
    }
}

/// The light's tint alone: the texture multiplies by its illuminant
/// ([`RgbIlluminant::illuminant`]), which it keeps once.
impl From<RgbIlluminant> for RgbTexel {
    fn from(light: RgbIlluminant) -> RgbTexel {
        RgbTexel::new(light.scale(), light.polynomial())
    }
}

impl Spectrum for RgbTexel {
    #[inline]
    fn eval(&self, lambda: f64) -> f64 {
        self.scale() * self.polynomial().eval(lambda)
    }

    /// Decoded once, then four lanes in `f32` at once.
    #[inline(always)]
    fn eval_many_f32(&self, lambda: &[f32], values: &mut [f32]) {
        SigmoidPolynomial::eval_many_f32_coefficients(self.coefficients(), self.scale, lambda, values);
    }

    /// As [`RgbTexel::eval_many_f32`]: a texel needs no table.
    #[inline(always)]
    fn eval_many_nearest_f32(&self, lambda: &[f32], _nearest: &[u16], values: &mut [f32]) {
        SigmoidPolynomial::eval_many_f32_coefficients(self.coefficients(), self.scale, lambda, values);
    }

    fn pieces(&self) -> Option<Pieces<'_>> {
        self.polynomial().pieces()
    }

    /// Exact: the scale times the decoded polynomial's.
    fn max_value(&self) -> f64 {
        self.scale() * self.polynomial().max_value()
    }
}
