//! Equidistant wavelength buckets: the one definition of the two rules.
//!
//! A range, 380–730 nm by default (width W = 350 nm), is cut into M equal
//! buckets; bucket i spans `[min + i·W/M, min + (i+1)·W/M]`. A [`BucketRule`] turns
//! a spectrum into M numbers:
//!
//! - [`BucketRule::Center`]: the value at each bucket center;
//! - [`BucketRule::BoxAverage`]: the exact mean of the interpolant over
//!   each bucket (differences of the spectrum's exact running integral).
//!
//! and XYZ is the Riemann sum `W/M · Σᵢ valueᵢ·c̄ᵢ`, with c̄ᵢ the matching
//! functions bucketed by the same rule ([`BucketRule::observer`], a
//! `const fn`). Renderers use `RegularSpectrum<M, B>` (M a compile-time
//! constant, the rule a type); the study, which tries every M from 1 to 64,
//! uses a run-time [`Rule`](super::rule::Rule) of buckets: the same
//! numbers.
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{buckets::BucketRule, rule::Rule};
//! use speclab::{Center, RegularSpectrum};
//! let sixteen = Rule::buckets(16, BucketRule::Center)?;
//! let fixed = RegularSpectrum::<16, Center>::center(&lights::A) * RegularSpectrum::center(&patches::G4);
//! let (run_time, compiled) = (sixteen.xyz(&lights::A, &patches::G4), fixed.to_xyz());
//! assert!((run_time.y - compiled.y).abs() <= 1e-14 * compiled.y);
//! assert!(Rule::buckets(0, BucketRule::Center).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::named_choices;
use crate::spectrum::data::observers;
use crate::spectrum::data::{
    CIE_X_BREAKS, CIE_X_COEFFS, CIE_X_LAMBDA, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_BREAKS,
    CIE_Z_COEFFS, CIE_Z_LAMBDA,
};
use crate::spectrum::{Role, Spectrum, StandardObserver, WavelengthRange, integrate, interp};

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

/// The center of bucket `i` of `m`, nm.
#[inline]
pub(crate) const fn center(i: usize, m: usize) -> f64 {
    center_in(WavelengthRange::ASSIGNMENT, i, m)
}

/// The lower edge of bucket `i` of `m` over `range`, nm.
#[inline]
pub(crate) const fn edge_in(range: WavelengthRange, i: usize, m: usize) -> f64 {
    range.min() + i as f64 * range.width() / m as f64
}

/// The center of bucket `i` of `m` over `range`, nm.
#[inline]
pub(crate) const fn center_in(range: WavelengthRange, i: usize, m: usize) -> f64 {
    0.5 * (edge_in(range, i, m) + edge_in(range, i + 1, m))
}

const CMF_BOUNDS: [f64; 2] = Role::Observer.bounds();

impl BucketRule {
    /// `[x̄ᵢ, ȳᵢ, z̄ᵢ]` of bucket `i` of `m` under this rule: the matching
    /// functions at the center, or their exact means over the bucket (a
    /// bucket's weights are these times its width `W/M`). A `const fn`, so
    /// `RegularSpectrum<M, B>` has them at compile time.
    #[must_use]
    pub const fn observer(self, i: usize, m: usize) -> [f64; 3] {
        self.observer_over(StandardObserver::Assignment, WavelengthRange::ASSIGNMENT, i, m)
    }

    /// [`BucketRule::observer`] for buckets over `range` with `observer`
    /// (the CIE's 1 nm tables are linear between nanometres, zero outside
    /// 360–830 nm).
    #[must_use]
    pub const fn observer_over(
        self,
        observer: StandardObserver,
        range: WavelengthRange,
        i: usize,
        m: usize,
    ) -> [f64; 3] {
        let (a, b) = (edge_in(range, i, m), edge_in(range, i + 1, m));
        match (observer, self) {
            (StandardObserver::Cie1931, rule) => table_bucket(&observers::CIE_1931_2, rule, a, b),
            (StandardObserver::Cie1964, rule) => table_bucket(&observers::CIE_1964_10, rule, a, b),
            (StandardObserver::Cie2015_2, rule) => table_bucket(&observers::CIE_2015_2, rule, a, b),
            (StandardObserver::Cie2015_10, rule) => table_bucket(&observers::CIE_2015_10, rule, a, b),
            (StandardObserver::Assignment, BucketRule::Center) => {
                let lambda = 0.5 * (a + b);
                [
                    interp::eval(&CIE_X_LAMBDA, &CIE_X_COEFFS, CMF_BOUNDS, lambda),
                    interp::eval(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, CMF_BOUNDS, lambda),
                    interp::eval(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, CMF_BOUNDS, lambda),
                ]
            }
            (StandardObserver::Assignment, BucketRule::BoxAverage) => [
                interp::integral(&CIE_X_LAMBDA, &CIE_X_COEFFS, &CIE_X_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                interp::integral(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, &CIE_Y_BREAKS, CMF_BOUNDS, a, b) / (b - a),
                interp::integral(&CIE_Z_LAMBDA, &CIE_Z_COEFFS, &CIE_Z_BREAKS, CMF_BOUNDS, a, b) / (b - a),
            ],
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

/// The exact means of `s` over each of `out.len()` buckets of 380–730 nm.
#[inline]
pub(crate) fn box_means<S: Spectrum + ?Sized>(s: &S, out: &mut [f64]) {
    box_means_in(s, WavelengthRange::ASSIGNMENT, out);
}

/// The exact means of `s` over each of `out.len()` buckets of `range`:
/// differences of the spectrum's running integral at the edges where it
/// has one at hand (a table's: O(1) per edge), otherwise each bucket's
/// integral piece by piece (exact for a piecewise polynomial, else by
/// quadrature).
#[inline]
pub(crate) fn box_means_in<S: Spectrum + ?Sized>(s: &S, range: WavelengthRange, out: &mut [f64]) {
    let m = out.len();
    let inv_width = m as f64 / range.width();
    let edge = |i| edge_in(range, i, m);
    if let Some(mut below) = s.running_integral(edge(0)) {
        for (i, v) in out.iter_mut().enumerate() {
            let above = s.running_integral(edge(i + 1)).unwrap_or(below);
            *v = (above - below) * inv_width;
            below = above;
        }
        return;
    }
    for (i, v) in out.iter_mut().enumerate() {
        *v = integrate::integral(&s, edge(i), edge(i + 1)) * inv_width;
    }
}

/// A 1 nm table from 360 nm read as lines (zero outside): its value at
/// the center of `[a, b]`, or its mean over it.
const fn table_bucket<const N: usize>(table: &[[f64; 3]; N], rule: BucketRule, a: f64, b: f64) -> [f64; 3] {
    let mut out = [0.0; 3];
    let mut c = 0;
    while c < 3 {
        out[c] = match rule {
            BucketRule::Center => line_value(table, c, 0.5 * (a + b)),
            BucketRule::BoxAverage => line_integral(table, c, a, b) / (b - a),
        };
        c += 1;
    }
    out
}

/// Channel `c` of the table at `lambda` nm (zero outside).
const fn line_value<const N: usize>(table: &[[f64; 3]; N], c: usize, lambda: f64) -> f64 {
    let x = lambda - TABLE_FIRST;
    if !(x >= 0.0 && x <= (N - 1) as f64) {
        return 0.0;
    }
    let j = if x as usize >= N - 1 { N - 2 } else { x as usize };
    on_segment(table, c, j, x)
}

/// Channel `c` on segment `j` (from row `j` to `j + 1`) at `x` rows.
const fn on_segment<const N: usize>(table: &[[f64; 3]; N], c: usize, j: usize, x: f64) -> f64 {
    table[j][c] + (x - j as f64) * (table[j + 1][c] - table[j][c])
}

/// The integral of channel `c` of the table over `[a, b]` nm: a trapezoid
/// per segment the interval meets.
const fn line_integral<const N: usize>(table: &[[f64; 3]; N], c: usize, a: f64, b: f64) -> f64 {
    let lo = (a - TABLE_FIRST).max(0.0);
    let hi = (b - TABLE_FIRST).min((N - 1) as f64);
    let (mut x, mut sum) = (lo, 0.0);
    while x < hi {
        let j = x as usize;
        let end = ((j + 1) as f64).min(hi);
        sum += 0.5 * (on_segment(table, c, j, x) + on_segment(table, c, j, end)) * (end - x);
        x = end;
    }
    sum
}

/// Where the CIE's 1 nm tables start, nm.
const TABLE_FIRST: f64 = observers::CIE_1931_2_FIRST;
const _: () = assert!(observers::CIE_1964_10_FIRST == TABLE_FIRST);
