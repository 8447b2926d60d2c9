//! From an RGB colour to a spectrum: Jakob and Hanika's sigmoid polynomials
//! (2019), fitted by Gauss–Newton on the CIELAB error under a colour
//! space's illuminant, with speclab's own observer and integrals.
//!
//! A space ([`RgbSpace`]) makes its colours' spectra under its illuminant
//! (CIE D65 for sRGB, Display P3 and Rec.2020), integrated over 380–730 nm
//! like every colour here. There the illuminant's white is not exactly the
//! space's white point, so the fit balances each channel by at most 5e-4:
//! the perfect reflector *is* `(1, 1, 1)`.
//!
//! - [`RgbAlbedo::new`](crate::color::RgbAlbedo::new): a reflectance whose
//!   colour under D65 is the given linear sRGB (each component in [0, 1]);
//!   black and white are the constants 0 and 1, exactly. In any space,
//!   [`RgbSpace::albedo`] looks the colour up in the space's table.
//! - [`RgbUnbounded`](crate::color::RgbUnbounded): any non-negative colour,
//!   as twice its largest component times the albedo of the colour over
//!   that.
//! - [`RgbIlluminant`](crate::color::RgbIlluminant): a light: that, times
//!   the space's illuminant normalised so that (1, 1, 1) has the luminance
//!   of a constant spectrum of 1.
//!
//! **The fit.** `Lab(XYZ(c)) − Lab(target)` is driven to zero by Gauss–
//! Newton steps with the exact Jacobian (halved while they do not reduce
//! the error), from the flat spectrum of the colour's luminance. XYZ(c) is
//! illuminant × s × c̄ integrated by 4-point Gauss–Legendre on each 5 nm
//! piece. Colours the direct descent does not reach (the most saturated)
//! are approached along the line from that grey, each step starting from
//! the last. Round trip, linear sRGB → albedo → XYZ under D65 (the
//! reference integral) → linear sRGB: ΔE00 below 0.01 over a 17³ grid
//! (`tests/properties/upsample.rs`).
//!
//! ```
//! use speclab::{LinearRgb, Spectrum};
//! use speclab::color::{RgbAlbedo, RgbSpace};
//! let orange = LinearRgb::new(0.8, 0.35, 0.05);
//! let albedo = RgbAlbedo::new(orange)?;
//! let back = RgbSpace::srgb().rgb_of(&albedo);
//! assert!(back.distance(orange) < 1e-4);
//! assert!((0.0..=1.0).contains(&albedo.eval(600.0)));
//! # Ok::<(), speclab::Error>(())
//! ```

use wide::f64x4;

use crate::color::lab::{lab, lab_jacobian};
use crate::color::matrix::{Matrix, inverse, mul};
use crate::color::rgb::LinearRgb;
use crate::color::xyz::Xyz;
use crate::spectrum::observer;
use crate::spectrum::sigmoid::constant;
use crate::spectrum::{
    LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, SigmoidPolynomial, Spectrum, TabulatedSpectrum, integrate,
    quadrature,
};

/// What a space's colours are fitted with: its illuminant, the
/// illuminant's white, the balanced matrices, and the quadrature nodes of
/// `∫ illuminant·s·c̄`.
#[derive(Clone)]
pub(crate) struct Fit {
    pub(crate) illuminant: &'static TabulatedSpectrum,
    /// The illuminant's white, `Y = 1`.
    white: Xyz,
    /// The illuminant's white's Y, as integrated (for normalising).
    pub(crate) white_y: f64,
    pub(crate) to_rgb: Matrix,
    to_xyz: Matrix,
    /// Four nodes at a time, `[t, w_x, w_y, w_z]`: the normalised
    /// wavelength and `w·L·c̄/Y_white` (the last group filled with weights
    /// of 0).
    nodes: Vec<[f64x4; 4]>,
}

impl std::fmt::Debug for Fit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Fit").field("white", &self.white).finish_non_exhaustive()
    }
}

impl Fit {
    /// The fit for colours whose XYZ → RGB matrix is `xyz_to_rgb`, under
    /// `illuminant`: the matrix balanced so that the illuminant's white
    /// (over 380–730 nm) is `(1, 1, 1)`.
    pub(crate) fn new(illuminant: &'static TabulatedSpectrum, xyz_to_rgb: &Matrix) -> Fit {
        let raw = Xyz::from(integrate::white(illuminant));
        let white = raw / raw.y;
        let balance = mul(xyz_to_rgb, white.to_array());
        let to_rgb = [0, 1, 2].map(|r| xyz_to_rgb[r].map(|v| v / balance[r]));
        let mut pieces: Vec<f64> = illuminant.breaks().to_vec();
        pieces.extend(observer::CMFS.iter().flat_map(|s| s.breaks().iter().copied()));
        let pieces =
            quadrature::pieces(pieces.into_iter().filter(|&x| (LAMBDA_MIN..=LAMBDA_MAX).contains(&x)));
        let rule = quadrature::gauss(4);
        let nodes = pieces
            .windows(2)
            .flat_map(|w| {
                let (mid, half) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
                rule.iter().map(move |&(x, wt)| (mid + half * x, wt * half))
            })
            .map(|(lambda, wt)| {
                let weight = wt * illuminant.eval(lambda) / raw.y;
                ((lambda - LAMBDA_MIN) / LAMBDA_WIDTH, observer::xyz_bar(lambda).map(|c| c * weight))
            })
            .collect::<Vec<_>>()
            .chunks(4)
            .map(|group| {
                // A missing node: t = 0, weights 0.
                let at = |f: fn(&(f64, [f64; 3])) -> f64| {
                    f64x4::from(std::array::from_fn(|i| group.get(i).map_or(0.0, f)))
                };
                [at(|n| n.0), at(|n| n.1[0]), at(|n| n.1[1]), at(|n| n.1[2])]
            })
            .collect();
        Fit { illuminant, white, white_y: raw.y, to_rgb, to_xyz: inverse(&to_rgb), nodes }
    }

    /// Balanced linear RGB of `xyz` (relative to the white's `Y = 1`).
    pub(crate) fn rgb(&self, xyz: Xyz) -> LinearRgb {
        LinearRgb::from(mul(&self.to_rgb, xyz.to_array()))
    }

    /// XYZ (white `Y = 1`) of balanced linear `rgb`.
    pub(crate) fn xyz(&self, rgb: LinearRgb) -> Xyz {
        Xyz::from(mul(&self.to_xyz, rgb.to_array()))
    }

    /// The colour of a reflectance under the illuminant, white `Y = 1`.
    pub(crate) fn albedo_xyz(&self, albedo: &dyn Spectrum) -> Xyz {
        Xyz::from(integrate::xyz_of_product(&[self.illuminant, albedo])) / self.white_y
    }

    /// XYZ of the sigmoid polynomial `c` by the fit's nodes, and its
    /// derivative by each coefficient (`[d/dc₀, d/dc₁, d/dc₂]` per channel).
    /// Four nodes at a time in `f64x4` lanes (the fit's inner loop).
    fn xyz_and_jacobian(&self, c: [f64; 3]) -> (Xyz, [[f64; 3]; 3]) {
        let [c0, c1, c2] = c.map(f64x4::splat);
        let (half, one) = (f64x4::splat(0.5), f64x4::splat(1.0));
        // X, Y, Z, then each channel's derivatives by c₀, c₁, c₂.
        let mut sums = [f64x4::ZERO; 12];
        for &[t, wx, wy, wz] in &self.nodes {
            let x = c2 + t * (c1 + t * c0);
            let r = one / (one + x * x).sqrt();
            let (s, ds) = (half + half * x * r, half * r * r * r);
            let basis = [t * t * ds, t * ds, ds];
            for (ch, w) in [wx, wy, wz].into_iter().enumerate() {
                sums[ch] += w * s;
                for (k, b) in basis.into_iter().enumerate() {
                    sums[3 + 3 * ch + k] += w * b;
                }
            }
        }
        let sum = |v: f64x4| v.to_array().iter().sum::<f64>();
        let xyz = Xyz::new(sum(sums[0]), sum(sums[1]), sum(sums[2]));
        (xyz, std::array::from_fn(|ch| std::array::from_fn(|k| sum(sums[3 + 3 * ch + k]))))
    }

    /// The coefficients whose colour is `target` (XYZ, white `Y = 1`),
    /// from `start`: Gauss–Newton on the Lab error, steps halved while they
    /// do not reduce it. The coefficients and the error left.
    fn descend(&self, target: [f64; 3], mut c: [f64; 3], steps: usize) -> ([f64; 3], f64) {
        let goal = lab(Xyz::from(target), self.white);
        let residual = |xyz: Xyz| {
            let l = lab(xyz, self.white);
            [l[0] - goal[0], l[1] - goal[1], l[2] - goal[2]]
        };
        let norm = |r: [f64; 3]| (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).sqrt();
        let (mut xyz, mut jac) = self.xyz_and_jacobian(c);
        let mut r = residual(xyz);
        for _ in 0..steps {
            if norm(r) < TOLERANCE {
                break;
            }
            let j = product(&lab_jacobian(xyz, self.white), &jac);
            let step = mul(&inverse(&j), r);
            let mut scale = 1.0;
            let mut improved = false;
            for _ in 0..12 {
                let next = [0, 1, 2].map(|i| c[i] - scale * step[i]);
                let (x2, j2) = self.xyz_and_jacobian(next);
                let r2 = residual(x2);
                if norm(r2) < norm(r) && next.iter().all(|v| v.is_finite()) {
                    (c, xyz, jac, r, improved) = (next, x2, j2, r2, true);
                    break;
                }
                scale *= 0.5;
            }
            if !improved {
                break;
            }
        }
        (c, norm(r))
    }

    /// The sigmoid polynomial of linear `rgb` (each component in [0, 1]):
    /// exact constants for black and white; otherwise the descent from the
    /// grey of the colour's luminance, and, where that stalls, along the
    /// line from that grey in more and more steps. A colour no reflectance
    /// has (no step comes within the tolerance) gets the fit of the colour
    /// on that line nearest it that one does ([`Fit::fit_reachable`]).
    pub(crate) fn fit(&self, rgb: [f64; 3]) -> SigmoidPolynomial {
        if rgb[0] == rgb[1] && rgb[1] == rgb[2] {
            return constant(rgb[0]);
        }
        match self.fit_with_error(rgb) {
            (c, error) if error < TOLERANCE => SigmoidPolynomial::new(c),
            _ => SigmoidPolynomial::new(self.fit_reachable(rgb)),
        }
    }

    /// The grey of `rgb`'s luminance and `rgb`, as XYZ, and the constant
    /// spectrum of that grey's coefficients.
    fn grey_and_target(&self, rgb: [f64; 3]) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let target = self.xyz(LinearRgb::from(rgb)).to_array();
        // The flat spectrum of the colour's luminance has the white's colour
        // at that luminance: the path starts there, at constant Y.
        let y = target[1].clamp(1e-9, 1.0 - 1e-9);
        ((self.white * y).to_array(), target, constant(y).coefficients())
    }

    /// [`Fit::fit`]'s best coefficients for a colour that is not a grey,
    /// and the Lab error left.
    fn fit_with_error(&self, rgb: [f64; 3]) -> ([f64; 3], f64) {
        let (grey, target, start) = self.grey_and_target(rgb);
        let mut best = (start, f64::INFINITY);
        for legs in [1, 4, 16] {
            let mut fitted = (start, f64::INFINITY);
            for leg in 1..=legs {
                let share = leg as f64 / legs as f64;
                let point = [0, 1, 2].map(|i| grey[i] * (1.0 - share) + target[i] * share);
                fitted = self.descend(point, fitted.0, if leg == legs { 40 } else { 8 });
            }
            if fitted.1 < best.1 {
                best = fitted;
            }
            if best.1 < TOLERANCE {
                break;
            }
        }
        best
    }

    /// For a colour no reflectance has, the fit of the last colour the line
    /// from its grey (at its luminance) reaches within the tolerance:
    /// [`LEGS`] steps along the line, each from the last one's
    /// coefficients, then [`HALVINGS`] halvings of the step past the last
    /// reached. A colour a reflectance has is reached at the end of the
    /// line: its own fit. A continuous, bounded choice, so a table of such fits can be
    /// interpolated.
    fn fit_reachable(&self, rgb: [f64; 3]) -> [f64; 3] {
        let (grey, target, mut c) = self.grey_and_target(rgb);
        let point = |share: f64| [0, 1, 2].map(|i| grey[i] * (1.0 - share) + target[i] * share);
        let mut reached = 0.0;
        for leg in 1..=LEGS {
            let share = f64::from(leg) / f64::from(LEGS);
            match self.descend(point(share), c, PROBE_STEPS) {
                (next, error) if error < TOLERANCE => (c, reached) = (next, share),
                _ => break,
            }
        }
        let mut step = 1.0 / f64::from(LEGS);
        for _ in 0..HALVINGS {
            step *= 0.5;
            if reached + step <= 1.0
                && let (next, error) = self.descend(point(reached + step), c, PROBE_STEPS)
                && error < TOLERANCE
            {
                (c, reached) = (next, reached + step);
            }
        }
        c
    }

    /// [`RgbSpace::fit`], starting from `start` if given (a neighbour's
    /// coefficients, for tables): the full fit only where that falls short.
    pub(crate) fn fit_from(&self, rgb: [f64; 3], start: Option<[f64; 3]>) -> SigmoidPolynomial {
        if rgb == [0.0; 3] {
            // Finite, for interpolating tables: 2.5e-9 everywhere.
            return SigmoidPolynomial::new([0.0, 0.0, -1e4]);
        }
        let target = self.xyz(LinearRgb::from(rgb)).to_array();
        let continued =
            start.filter(|s| s.iter().all(|v| v.is_finite())).map(|start| self.descend(target, start, 40));
        if let Some((c, error)) = continued
            && error < TOLERANCE
        {
            return SigmoidPolynomial::new(c);
        }
        if rgb[0] == rgb[1] && rgb[1] == rgb[2] {
            return constant(rgb[0]);
        }
        // A colour the neighbour's path does not reach: the walk from its
        // grey, which reaches it if a reflectance has it, and otherwise stops
        // at the last colour one has.
        let c = self.fit_reachable(rgb);
        if c.iter().all(|v| v.is_finite()) {
            SigmoidPolynomial::new(c)
        } else {
            SigmoidPolynomial::new([0.0, 0.0, c[2].clamp(-1e4, 1e4)])
        }
    }
}

/// The Lab error at which a fit stops: far below a just-noticeable difference.
const TOLERANCE: f64 = 1e-7;

/// The steps [`Fit::fit_reachable`] walks the line from grey in.
const LEGS: u16 = 8;
/// How many times it halves its step past the last colour reached (to
/// 1/8 · 2⁻⁴ = 1/128 of the line).
const HALVINGS: usize = 4;
/// Gauss–Newton steps it gives a point: one past the last reachable never
/// converges, and each try costs.
const PROBE_STEPS: usize = 12;

/// `a · b`.
fn product(a: &Matrix, b: &Matrix) -> Matrix {
    std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|k| a[r][k] * b[k][c]).sum()))
}
