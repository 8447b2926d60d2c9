//! Sprague (1880) interpolation of samples at a uniform step: the fifth-
//! degree interpolant the CIE recommends for refining 5 nm tables to 1 nm
//! (CIE 015:2018, 7.2.2; CIE 167:2005), and colour-science's default for
//! uniformly spaced data.
//!
//! Between samples `i` and `i + 1`, with `X = (λ − λᵢ)/Δλ` in `[0, 1]`,
//! `S(λ) = rᵢ + Σₖ aₖ·Xᵏ` (k = 1…5), each `aₖ` a fixed combination of the
//! six samples `rᵢ₋₂ … rᵢ₊₃` (Westland, Ripamonti and Cheung, *Computational
//! Colour Science*, 2012, 5.5). Two points are added at each end from the
//! first and last six samples, so the interpolant reaches the ends. It
//! passes through every sample and is smooth (C²) between; it is not a
//! piecewise cubic, so the exact reference integrates it by quadrature.
//! Outside its samples the spectrum holds its end values (as colour-science
//! and pbrt-v4 extrapolate), or is zero ([`Sprague::zero_outside`]).
//!
//! ```
//! use speclab::spectrum::{Spectrum, Sprague};
//! // A reflectance measured every 10 nm, read at 1 nm.
//! let r = Sprague::new(400.0, 10.0, vec![0.1, 0.2, 0.4, 0.5, 0.45, 0.3, 0.2])?;
//! assert_eq!(r.eval(420.0), 0.4); // at a sample, the sample
//! assert!((r.eval(425.0) - 0.46).abs() < 0.02); // between, smooth
//! assert_eq!(r.eval(300.0), 0.1); // outside, the end held
//! # Ok::<(), speclab::Error>(())
//! ```

use super::{Spectrum, WavelengthRange};
use crate::error::Error;
use crate::error::{Field, Invalid, SampleError};

/// The end points' weights on the first (last) six samples, over 209.
const END: [[f64; 6]; 2] =
    [[884.0, -1960.0, 3033.0, -2648.0, 1080.0, -180.0], [508.0, -540.0, 488.0, -367.0, 144.0, -24.0]];

/// `aₖ = Σ A[k]·r / 24` over the six samples `rᵢ₋₂ … rᵢ₊₃`.
const A: [[f64; 6]; 5] = [
    [2.0, -16.0, 0.0, 16.0, -2.0, 0.0],
    [-1.0, 16.0, -30.0, 16.0, -1.0, 0.0],
    [-9.0, 39.0, -70.0, 66.0, -33.0, 7.0],
    [13.0, -64.0, 126.0, -124.0, 61.0, -12.0],
    [-5.0, 25.0, -50.0, 50.0, -25.0, 5.0],
];

/// The fewest samples: the stencil's six.
pub const MIN_SAMPLES: usize = 6;

/// The Sprague interpolant of samples at `first + i·step` nm.
#[derive(Clone, Debug, PartialEq)]
pub struct Sprague {
    range: WavelengthRange,
    step: f64,
    /// The samples with two added points at each end.
    padded: Vec<f64>,
    zero_outside: bool,
}

impl Sprague {
    /// The interpolant of `values` at `first`, `first + step`, …; an
    /// error unless there are at least six finite values and the range
    /// they span is a [`WavelengthRange`].
    pub fn new(first: f64, step: f64, values: Vec<f64>) -> Result<Self, Error> {
        let n = values.len();
        if n < MIN_SAMPLES {
            return Err(Error::Count {
                what: "a Sprague interpolant's samples",
                found: n,
                min: 6,
                max: usize::MAX,
            });
        }
        if let Some(index) = values.iter().position(|v| !v.is_finite()) {
            let problem = Invalid::NonFinite { value: values[index] };
            return Err(Error::Sample(SampleError { index, field: Field::Value, problem }));
        }
        let range = WavelengthRange::new(first, first + step * (n - 1) as f64)?;
        let end = |weights: &[f64; 6], six: &[f64]| -> f64 {
            weights.iter().zip(six).map(|(w, v)| w * v).sum::<f64>() / 209.0
        };
        let (head, tail) = (&values[..6], &values[n - 6..]);
        let reversed: Vec<f64> = tail.iter().rev().copied().collect();
        let mut padded = vec![end(&END[0], head), end(&END[1], head)];
        padded.extend_from_slice(&values);
        padded.extend([end(&END[1], &reversed), end(&END[0], &reversed)]);
        Ok(Sprague { range, step, padded, zero_outside: false })
    }

    /// The same interpolant, zero outside its samples.
    #[must_use]
    pub fn zero_outside(self) -> Self {
        Sprague { zero_outside: true, ..self }
    }

    /// The first and last sampled wavelengths.
    #[must_use]
    pub fn range(&self) -> WavelengthRange {
        self.range
    }

    /// The step, nm.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The samples.
    #[must_use]
    pub fn values(&self) -> &[f64] {
        &self.padded[2..self.padded.len() - 2]
    }

    /// The polynomial of segment `i`: `[rᵢ, a₁, …, a₅]`.
    fn segment(&self, i: usize) -> [f64; 6] {
        let r = &self.padded[i..i + 6];
        let mut c = [r[2], 0.0, 0.0, 0.0, 0.0, 0.0];
        for (k, row) in A.iter().enumerate() {
            c[k + 1] = row.iter().zip(r).map(|(w, v)| w * v).sum::<f64>() / 24.0;
        }
        c
    }

    /// The value outside the samples, below or above them: the nearer
    /// end's, or zero.
    fn outside(&self, below: bool) -> f64 {
        let values = self.values();
        match (self.zero_outside, below) {
            (true, _) => 0.0,
            (false, true) => values[0],
            (false, false) => values[values.len() - 1],
        }
    }
}

impl Spectrum for Sprague {
    fn eval(&self, lambda: f64) -> f64 {
        if !self.range.contains(lambda) {
            return if lambda.is_nan() { f64::NAN } else { self.outside(lambda < self.range.min()) };
        }
        let segments = self.values().len() - 1;
        let t = (lambda - self.range.min()) / self.step;
        let i = t.floor() as usize;
        if i >= segments {
            return self.values()[segments];
        }
        let x = t - i as f64;
        let c = self.segment(i);
        c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * (c[4] + x * c[5]))))
    }

    /// A bound: in each segment the largest coefficient of its polynomial
    /// in Bernstein form (the polynomial lies in their convex hull on
    /// `[0, 1]`), and the value outside.
    fn max_value(&self) -> f64 {
        let segments = self.values().len() - 1;
        (0..segments)
            .map(|i| bernstein(self.segment(i)).into_iter().fold(f64::MIN, f64::max))
            .fold(self.outside(true).max(self.outside(false)), f64::max)
    }
}

/// The Bernstein coefficients of `Σ cₖ·Xᵏ` (degree 5):
/// `bⱼ = Σₖ≤ⱼ C(j, k)/C(5, k)·cₖ`.
fn bernstein(c: [f64; 6]) -> [f64; 6] {
    const BINOMIAL: [[f64; 6]; 6] = [
        [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, 2.0, 1.0, 0.0, 0.0, 0.0],
        [1.0, 3.0, 3.0, 1.0, 0.0, 0.0],
        [1.0, 4.0, 6.0, 4.0, 1.0, 0.0],
        [1.0, 5.0, 10.0, 10.0, 5.0, 1.0],
    ];
    std::array::from_fn(|j| (0..=j).map(|k| BINOMIAL[j][k] / BINOMIAL[5][k] * c[k]).sum())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passes_through_its_samples_and_reproduces_quartics() {
        // A quartic is reproduced exactly where the stencil has six real
        // samples (segments 2 to n − 4); near the ends the added points
        // are Sprague's, not the quartic's.
        let p = |l: f64| {
            let x = (l - 500.0) / 100.0;
            1.0 + x * (0.5 + x * (-0.25 + x * (0.125 + x * 0.0625)))
        };
        let values: Vec<f64> = (0..11).map(|i| p(400.0 + 25.0 * f64::from(i))).collect();
        let s = Sprague::new(400.0, 25.0, values.clone()).unwrap();
        for i in 0..=150 {
            let l = 450.0 + f64::from(i);
            assert!((s.eval(l) - p(l)).abs() < 1e-12, "{l}: {} against {}", s.eval(l), p(l));
        }
        assert!((s.eval(401.0) - p(401.0)).abs() > 1e-6, "the ends are not the quartic's");
        for (i, v) in values.iter().enumerate() {
            assert_eq!(s.eval(400.0 + 25.0 * i as f64), *v);
        }
        assert_eq!(s.values(), &values[..]);
        assert_eq!((s.range(), s.step()), (WavelengthRange::new(400.0, 650.0).unwrap(), 25.0));
    }

    #[test]
    fn outside_holds_or_is_zero() {
        let s = Sprague::new(400.0, 10.0, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
        assert_eq!((s.eval(399.0), s.eval(451.0), s.eval(450.0)), (1.0, 6.0, 6.0));
        assert!(s.eval(449.0) < 6.0 && s.eval(401.0) > 1.0);
        assert!(s.eval(f64::NAN).is_nan());
        let z = s.clone().zero_outside();
        assert_eq!((z.eval(399.0), z.eval(451.0), z.eval(425.0)), (0.0, 0.0, s.eval(425.0)));
        assert!(z.eval(f64::NAN).is_nan());
    }

    #[test]
    fn the_bound_is_above_every_value() {
        // A plateau of two: the interpolant overshoots between them, to
        // 1.171875; the Bernstein bound is 1.2083 (both computed apart).
        let values = vec![0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.2];
        for s in [
            Sprague::new(380.0, 5.0, values.clone()).unwrap(),
            Sprague::new(380.0, 5.0, values).unwrap().zero_outside(),
        ] {
            let top = (0..=47000).map(|i| s.eval(360.0 + 0.01 * f64::from(i))).fold(f64::MIN, f64::max);
            assert!((top - 1.171875).abs() < 1e-6, "{top}");
            assert!((s.max_value() - 1.2083333333333333).abs() < 1e-12, "{}", s.max_value());
        }
        let low = Sprague::new(400.0, 10.0, vec![-2.0; 6]).unwrap();
        assert_eq!(low.max_value(), -2.0);
        assert_eq!(low.zero_outside().max_value(), 0.0);
    }

    #[test]
    fn bad_samples_are_named() {
        let few = Sprague::new(400.0, 10.0, vec![1.0; 5]).unwrap_err().to_string();
        assert_eq!(few, "expected a Sprague interpolant's samples: at least 6, found 5");
        let nan = Sprague::new(400.0, 10.0, vec![1.0, 1.0, f64::NAN, 1.0, 1.0, 1.0]).unwrap_err().to_string();
        assert!(nan.starts_with("values[2]:"), "{nan}");
        for (first, step) in [(400.0, 0.0), (400.0, -5.0), (f64::NAN, 5.0), (0.0, 5.0)] {
            assert!(
                matches!(Sprague::new(first, step, vec![1.0; 6]), Err(Error::Range { .. })),
                "{first} {step}"
            );
        }
    }
}
