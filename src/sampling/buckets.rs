//! Equidistant wavelength buckets, the one definition of the two rules,
//! and buckets whose count is chosen at run time.
//!
//! The range 380–730 nm (width W = 350 nm) is cut into M equal buckets;
//! bucket i spans `[380 + i·W/M, 380 + (i+1)·W/M]`. A [`BucketRule`] turns
//! a spectrum into M numbers:
//!
//! - [`BucketRule::Center`]: the value at each bucket center;
//! - [`BucketRule::BoxAverage`]: the exact mean of the interpolant over
//!   each bucket (differences of the spectrum's exact cumulative integral).
//!
//! and XYZ is the Riemann sum `W/M · Σᵢ valueᵢ·c̄ᵢ`, with c̄ᵢ the matching
//! functions bucketed by the same rule ([`BucketRule::observer`], a
//! `const fn`). Renderers use `RegularSpectrum<M, B>` (M a compile-time
//! constant, the rule a type); the study, which tries every M from 1 to
//! [`MAX_BUCKETS`], uses [`Buckets`]: the same numbers (bit for bit),
//! with M chosen at run time.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::buckets::{BucketRule, Buckets};
//! use speclab::{Center, RegularSpectrum};
//! let sixteen = Buckets::new(16, BucketRule::Center)?;
//! let (l, s) = (sixteen.values(&lights::A), sixteen.values(&patches::G4));
//! let fixed = RegularSpectrum::<16, Center>::center(&lights::A) * RegularSpectrum::center(&patches::G4);
//! assert_eq!(sixteen.xyz_of_product(&[&l, &s]), fixed.to_xyz());
//! assert!(Buckets::new(0, BucketRule::Center).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::{Error, named_choices};
use crate::spectrum::data::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA,
};
use crate::spectrum::{LAMBDA_MIN, LAMBDA_WIDTH, Role, Spectrum, integrate, interp};

/// The most buckets the study uses, and [`Buckets`] accepts.
pub const MAX_BUCKETS: usize = 64;

/// How a spectrum becomes bucket values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BucketRule {
    /// Point samples at bucket centers.
    #[default]
    Center,
    /// Exact means over each bucket.
    BoxAverage,
}

named_choices!(BucketRule, "a bucket rule": Center => "center", BoxAverage => "box");

/// The lower edge of bucket `i` of `m`, nm (`edge(m, m)` is 730 nm).
#[inline]
pub(crate) const fn edge(i: usize, m: usize) -> f64 {
    LAMBDA_MIN + i as f64 * LAMBDA_WIDTH / m as f64
}

/// The center of bucket `i` of `m`, nm.
#[inline]
pub(crate) const fn center(i: usize, m: usize) -> f64 {
    0.5 * (edge(i, m) + edge(i + 1, m))
}

const CMF_BOUNDS: [f64; 2] = Role::Observer.bounds();

impl BucketRule {
    /// Both rules.
    pub const ALL: [BucketRule; 2] = [BucketRule::Center, BucketRule::BoxAverage];

    /// `[x̄ᵢ, ȳᵢ, z̄ᵢ]` of bucket `i` of `m` under this rule: the matching
    /// functions at the center, or their exact means over the bucket. A
    /// `const fn`, so `RegularSpectrum<M, B>` has its tables at compile time.
    #[must_use]
    pub const fn observer(self, i: usize, m: usize) -> [f64; 3] {
        match self {
            BucketRule::Center => {
                let lambda = center(i, m);
                [
                    interp::eval(&CIE_X_LAMBDA, &CIE_X_COEFFS, CMF_BOUNDS, lambda),
                    interp::eval(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, CMF_BOUNDS, lambda),
                    interp::eval(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, CMF_BOUNDS, lambda),
                ]
            }
            BucketRule::BoxAverage => {
                let (a, b) = (edge(i, m), edge(i + 1, m));
                [
                    interp::integral(&CIE_X_LAMBDA, &CIE_X_COEFFS, &CIE_X_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                    interp::integral(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, &CIE_Y_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                    interp::integral(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, &CIE_Z_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                ]
            }
        }
    }

    /// The `out.len()` bucket values of `s` under this rule.
    pub fn values_into<S: Spectrum + ?Sized>(self, s: &S, out: &mut [f64]) {
        let m = out.len();
        match self {
            BucketRule::Center => {
                for (i, v) in out.iter_mut().enumerate() {
                    *v = s.eval(center(i, m));
                }
            }
            BucketRule::BoxAverage => box_means(s, out),
        }
    }
}

/// The exact means of `s` over each of `out.len()` buckets: for a table,
/// differences of its exact cumulative integral at the edges (O(1) per edge
/// from the integrals stored with it); otherwise each bucket's integral
/// (exact for a piecewise polynomial, else by quadrature).
#[inline]
pub(crate) fn box_means<S: Spectrum + ?Sized>(s: &S, out: &mut [f64]) {
    let m = out.len();
    let inv_width = m as f64 / LAMBDA_WIDTH;
    let Some(table) = s.as_tabulated() else {
        for (i, v) in out.iter_mut().enumerate() {
            *v = integrate::integral(&s, edge(i, m), edge(i + 1, m)) * inv_width;
        }
        return;
    };
    let mut below = table.cumulative(edge(0, m));
    for (i, v) in out.iter_mut().enumerate() {
        let above = table.cumulative(edge(i + 1, m));
        *v = (above - below) * inv_width;
        below = above;
    }
}

/// `Σ aᵢ·bᵢ` in four interleaved partial sums, so that the additions do not
/// wait on each other.
#[inline(always)]
pub(crate) fn dot4(n: usize, mut term: impl FnMut(usize) -> f64) -> f64 {
    let mut acc = [0.0; 4];
    for i in 0..n {
        acc[i % 4] += term(i);
    }
    (acc[0] + acc[2]) + (acc[1] + acc[3])
}

/// M buckets and a rule chosen at run time, with the bucketed observer.
#[derive(Clone, Debug, PartialEq)]
pub struct Buckets {
    rule: BucketRule,
    /// x̄ᵢ, ȳᵢ and z̄ᵢ as three rows of M (one dot product each).
    observer: [Vec<f64>; 3],
}

impl Buckets {
    /// `m` buckets under `rule`; an error unless `1 ≤ m ≤` [`MAX_BUCKETS`].
    pub fn new(m: usize, rule: BucketRule) -> Result<Self, Error> {
        if !(1..=MAX_BUCKETS).contains(&m) {
            return Err(Error::BucketCount { m, max: MAX_BUCKETS });
        }
        let table: Vec<[f64; 3]> = (0..m).map(|i| rule.observer(i, m)).collect();
        let observer = [0, 1, 2].map(|c| table.iter().map(|row| row[c]).collect());
        Ok(Buckets { rule, observer })
    }

    /// The number of buckets, M.
    #[must_use]
    pub fn m(&self) -> usize {
        self.observer[0].len()
    }

    /// The rule.
    #[must_use]
    pub fn rule(&self) -> BucketRule {
        self.rule
    }

    /// The M bucket values of `s`.
    #[must_use]
    pub fn values(&self, s: &(impl Spectrum + ?Sized)) -> Vec<f64> {
        let mut out = vec![0.0; self.m()];
        self.rule.values_into(s, &mut out);
        out
    }

    /// `W/M · Σᵢ (Πf fᵢ)·c̄ᵢ`: the XYZ of the point-wise product of
    /// `factors` (each M bucket values, in the order given), without
    /// allocating. Missing values (a factor shorter than M) count as 0.
    #[must_use]
    pub fn xyz_of_product(&self, factors: &[&[f64]]) -> Xyz {
        let m = self.m();
        let mut product = [1.0; MAX_BUCKETS];
        let product = &mut product[..m];
        for f in factors {
            let (known, missing) = product.split_at_mut(f.len().min(m));
            for (p, v) in known.iter_mut().zip(*f) {
                *p *= v;
            }
            missing.fill(0.0);
        }
        // Three dot products in one pass, each in four interleaved partial
        // sums (the same order as `RegularSpectrum::to_xyz`, so the same bits).
        let [x, y, z] = &self.observer;
        let mut acc = [[0.0; 4]; 3];
        for (i, (((p, x), y), z)) in product.iter().zip(x).zip(y).zip(z).enumerate() {
            acc[0][i % 4] += p * x;
            acc[1][i % 4] += p * y;
            acc[2][i % 4] += p * z;
        }
        let [x, y, z] = acc.map(|a| (a[0] + a[2]) + (a[1] + a[3]));
        Xyz::new(x, y, z) * (LAMBDA_WIDTH / m as f64)
    }

    /// XYZ of `light × surface` bucketed by this rule.
    #[must_use]
    pub fn xyz(&self, light: &(impl Spectrum + ?Sized), surface: &(impl Spectrum + ?Sized)) -> Xyz {
        self.xyz_of_product(&[&self.values(light), &self.values(surface)])
    }
}
