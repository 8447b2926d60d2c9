//! Fixed rules of a size chosen at run time: [`Rule`], M wavelengths and
//! their XYZ weights, as equidistant buckets (centre or box) or fitted to a
//! scene's lights (`Rule::fit`, see [`super::fitted`]).
//!
//! A renderer that knows M at compile time takes the rule as a `Copy`
//! value, [`Rule::wavelengths`], or uses `RegularSpectrum<M, B>`; the study,
//! which tries every M from 1 to [`MAX_M`], keeps it here. Both convert
//! with the one weighted sum, on arrays or on slices: the same numbers.
//!
//! A value at a rule's wavelengths is, per spectrum, its value at each
//! wavelength (centre buckets, fitted rules) or its exact mean over each
//! bucket (box buckets): [`Rule::values_into`]. A path's value is the
//! product of its spectra's values, as a renderer that evaluates each
//! spectrum once would compute it ([`Rule::xyz_of_product`]).
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::{buckets::BucketRule, reference, rule::Rule};
//! let (box16, fitted) = (Rule::buckets(16, BucketRule::BoxAverage)?, Rule::fit(&[&lights::F11], 10)?);
//! let exact = reference::xyz(&lights::F11, &patches::G4);
//! for rule in [&box16, &fitted] {
//!     let xyz = rule.xyz(&lights::F11, &patches::G4);
//!     assert!((xyz.y - exact.y).abs() < 0.05 * exact.y, "M = {}", rule.m());
//! }
//! let at = fitted.wavelengths::<10, f32>()?; // for a renderer's loop
//! assert_eq!(at.lambda()[0], fitted.lambda()[0] as f32);
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::color::Xyz;
use crate::error::Error;
use crate::sampling::buckets::{BucketRule, center};
use crate::sampling::wavelengths::{FixedWavelengths, Weighted};
use crate::spectrum::simd::column_sums;
use crate::spectrum::{Float, LAMBDA_WIDTH, Spectrum, WavelengthRange};

/// The most wavelengths a rule takes (buckets, fitted and given rules alike).
pub const MAX_M: usize = 64;

/// What a rule is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum RuleKind {
    /// Equidistant buckets.
    Buckets(BucketRule),
    /// Wavelengths and weights fitted to lights.
    Fitted,
    /// Wavelengths and weights given by the caller ([`Rule::new`]): a
    /// published rule (a quadrature, an ASTM E308 table) or a renderer's own.
    Given,
}

/// M wavelengths and their XYZ weights, M chosen at run time.
#[derive(Clone, Debug, PartialEq)]
pub struct Rule {
    kind: RuleKind,
    lambda: Vec<f64>,
    /// The rows `w_X`, `w_Y`, `w_Z`, one per wavelength each: the bucketed
    /// observer for buckets, weights in nm for fitted rules.
    weights: [Vec<f64>; 3],
    /// What the weighted sums are multiplied by: the buckets' width `W/M`,
    /// nm, or 1.
    scale: f64,
}

impl Rule {
    /// `m` equidistant buckets under `rule`; an [`Error::Count`] unless
    /// `1 ≤ m ≤` [`MAX_M`].
    pub fn buckets(m: usize, rule: BucketRule) -> Result<Rule, Error> {
        check_m("a bucket count", m)?;
        let lambda = (0..m).map(|i| center(i, m)).collect();
        let weights = [0, 1, 2].map(|c| (0..m).map(|i| rule.observer(i, m)[c]).collect());
        Ok(Rule { kind: RuleKind::Buckets(rule), lambda, weights, scale: LAMBDA_WIDTH / m as f64 })
    }

    /// The rule of these wavelengths (nm) and weight rows `[w_X, w_Y, w_Z]`
    /// (nm, one per wavelength each; XYZ꜀ = `Σᵢ w꜀ᵢ·vᵢ`), sorted by
    /// wavelength. An [`Error::Count`] unless `1 ≤ M ≤` [`MAX_M`]; an
    /// [`Error::RuleShape`] for a row of another length; an
    /// [`Error::RuleEntry`] for a wavelength outside 360–830 nm or a weight
    /// that is not finite.
    ///
    /// ```
    /// use speclab::data::{lights, patches};
    /// use speclab::sampling::{reference, rule::Rule};
    /// // One wavelength carrying the whole of E's Y, its weight including
    /// // the light (as published rules do: pass the reflectances alone).
    /// let y = reference::white(&lights::E).y;
    /// let rule = Rule::new(vec![555.0], [vec![0.0], vec![y], vec![0.0]])?;
    /// assert_eq!(rule.xyz_of_product(&[&patches::A1]).y, y * patches::A1.eval(555.0));
    /// assert!(Rule::new(vec![900.0], [vec![1.0], vec![1.0], vec![1.0]]).is_err());
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn new(lambda: Vec<f64>, weights: [Vec<f64>; 3]) -> Result<Rule, Error> {
        let m = lambda.len();
        check_m("a rule's wavelength count", m)?;
        if let Some(row) = weights.iter().position(|r| r.len() != m) {
            return Err(Error::RuleShape { row, len: weights[row].len(), expected: m });
        }
        let valid = |i: usize| {
            WavelengthRange::VISIBLE.contains(lambda[i]) && weights.iter().all(|r| r[i].is_finite())
        };
        if let Some(i) = (0..m).find(|&i| !valid(i)) {
            return Err(Error::RuleEntry { index: i, lambda: lambda[i] });
        }
        let mut order: Vec<usize> = (0..m).collect();
        order.sort_by(|&a, &b| lambda[a].total_cmp(&lambda[b]));
        let lambda = order.iter().map(|&i| lambda[i]).collect();
        let weights = [0, 1, 2].map(|c| order.iter().map(|&i| weights[c][i]).collect());
        Ok(Rule { kind: RuleKind::Given, lambda, weights, scale: 1.0 })
    }

    /// A fitted rule of these wavelengths (nm) and `[X, Y, Z]` weights.
    pub(crate) fn fitted(lambda: Vec<f64>, weights: [Vec<f64>; 3]) -> Rule {
        Rule { kind: RuleKind::Fitted, lambda, weights, scale: 1.0 }
    }

    /// What the rule is.
    #[cfg(test)]
    pub(crate) fn kind(&self) -> RuleKind {
        self.kind
    }

    /// The number of wavelengths, M.
    #[must_use]
    pub fn m(&self) -> usize {
        self.lambda.len()
    }

    /// The wavelengths, nm, increasing (for buckets, their centres).
    #[must_use]
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }

    /// The weights as rows `w_X`, `w_Y`, `w_Z` (one per wavelength each)
    /// and a factor: XYZ꜀ is `scale·Σᵢ w꜀ᵢ·vᵢ`. For buckets the rows are
    /// the bucketed observer and the factor the width `W/M` (nm); a fitted
    /// rule's rows are its weights (nm) and the factor 1.
    #[must_use]
    pub fn weights(&self) -> (&[Vec<f64>; 3], f64) {
        (&self.weights, self.scale)
    }

    /// `s`'s values for this rule, into `out` (as many as the shorter
    /// has): at the wavelengths, or for box buckets the exact means over
    /// the buckets. What a renderer stores per spectrum.
    pub fn values_into(&self, s: &(impl Spectrum + ?Sized), out: &mut [f64]) {
        match self.kind {
            RuleKind::Buckets(rule @ BucketRule::BoxAverage) => {
                let m = out.len().min(self.m());
                if m == self.m() {
                    rule.values_into(s, &mut out[..m]);
                } else {
                    let mut all = [0.0; MAX_M];
                    rule.values_into(s, &mut all[..self.m()]);
                    out[..m].copy_from_slice(&all[..m]);
                }
            }
            _ => {
                let m = out.len().min(self.m());
                s.eval_many(&self.lambda[..m], &mut out[..m]);
            }
        }
    }

    /// `s`'s M values ([`Rule::values_into`]).
    #[must_use]
    pub fn values(&self, s: &(impl Spectrum + ?Sized)) -> Vec<f64> {
        let mut out = vec![0.0; self.m()];
        self.values_into(s, &mut out);
        out
    }

    /// `Σᵢ wᵢ·vᵢ` for the values `v` of a spectrum (missing values count as
    /// 0, extra ones are ignored): the one weighted sum.
    #[must_use]
    pub fn xyz_of_values(&self, values: &[f64]) -> Xyz {
        let [x, y, z] = &self.weights;
        Xyz::of_sums(column_sums([x, y, z], values)) * self.scale
    }

    /// The XYZ of the point-wise product of `factors`, each the values of
    /// a spectrum ([`Rule::values_into`]), in the order given. Missing
    /// values count as 0. No allocation.
    #[must_use]
    pub fn xyz_of_factors(&self, factors: &[&[f64]]) -> Xyz {
        let mut product = [1.0; MAX_M];
        let product = &mut product[..self.m()];
        for f in factors {
            let (known, missing) = product.split_at_mut(f.len().min(product.len()));
            known.iter_mut().zip(*f).for_each(|(p, v)| *p *= v);
            missing.fill(0.0);
        }
        self.xyz_of_values(product)
    }

    /// The XYZ of a path whose spectra are `factors` (a light and the
    /// reflectances met): each spectrum's values for this rule, multiplied.
    /// No allocation.
    #[must_use]
    pub fn xyz_of_product(&self, factors: &[&dyn Spectrum]) -> Xyz {
        let (mut product, mut values) = ([1.0; MAX_M], [0.0; MAX_M]);
        let (product, values) = (&mut product[..self.m()], &mut values[..self.m()]);
        for f in factors {
            self.values_into(f, values);
            product.iter_mut().zip(values.iter()).for_each(|(p, v)| *p *= v);
        }
        self.xyz_of_values(product)
    }

    /// The XYZ of `light × surface`.
    #[must_use]
    pub fn xyz(&self, light: &(impl Spectrum + ?Sized), surface: &(impl Spectrum + ?Sized)) -> Xyz {
        self.xyz_of_product(&[&light as &dyn Spectrum, &surface])
    }

    /// The rule as a `Copy` value of compile-time size M in precision `T`,
    /// for a renderer's inner loop: spectra sample at it, and its
    /// `to_xyz` applies the weights. `M` may exceed the rule's size (a
    /// renderer that chooses the rule's size at run time compiles a few
    /// sizes): the lanes beyond it repeat the last wavelength and weigh
    /// nothing, so they change no colour. An [`Error::Count`] for `M` below
    /// the rule's size or above [`MAX_M`]; an [`Error::BoxRule`] for box
    /// buckets, whose values are means over the buckets, not values at
    /// wavelengths (use `RegularSpectrum<M, BoxAverage>`).
    ///
    /// ```
    /// use speclab::data::{lights, patches};
    /// use speclab::sampling::rule::Rule;
    /// let rule = Rule::fit(&[&lights::F11], 10)?;
    /// let (exact, padded) = (rule.wavelengths::<10, f64>()?, rule.wavelengths::<16, f64>()?);
    /// let y10 = exact.y(exact.sample(&lights::F11) * exact.sample(&patches::G4));
    /// let y16 = padded.y(padded.sample(&lights::F11) * padded.sample(&patches::G4));
    /// assert!((y10 - y16).abs() <= 1e-12 * y10);
    /// assert!(rule.wavelengths::<8, f64>().is_err());
    /// # Ok::<(), speclab::Error>(())
    /// ```
    pub fn wavelengths<const M: usize, T: Float>(&self) -> Result<FixedWavelengths<M, T>, Error> {
        let m = self.m();
        if !(m..=MAX_M).contains(&M) {
            return Err(Error::Count { what: "lanes for the rule", found: M, min: m, max: MAX_M });
        }
        if self.kind == RuleKind::Buckets(BucketRule::BoxAverage) {
            return Err(Error::BoxRule);
        }
        let lambda = std::array::from_fn(|i| T::from_f64(self.lambda[i.min(m - 1)]));
        let weight = |c: usize, i: usize| if i < m { self.scale * self.weights[c][i] } else { 0.0 };
        Ok(FixedWavelengths::from_weighted(Weighted::at(lambda).fixed(|c, i| T::from_f64(weight(c, i)))))
    }
}

/// An [`Error::Count`] naming `what` unless `1 ≤ m ≤` [`MAX_M`].
pub(crate) fn check_m(what: &'static str, m: usize) -> Result<(), Error> {
    if (1..=MAX_M).contains(&m) { Ok(()) } else { Err(Error::Count { what, found: m, min: 1, max: MAX_M }) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_given_rule_is_sorted_and_checked_entry_by_entry() {
        let rule = Rule::new(vec![600.0, 450.0], [vec![1.0, 2.0], vec![3.0, 4.0], vec![5.0, 6.0]]).unwrap();
        assert_eq!((rule.kind(), rule.lambda()), (RuleKind::Given, &[450.0, 600.0][..]));
        assert_eq!(rule.weights(), (&[vec![2.0, 1.0], vec![4.0, 3.0], vec![6.0, 5.0]], 1.0));
        let rows = |w: [f64; 2]| [w.to_vec(), vec![1.0; 2], vec![1.0; 2]];
        let entry = |e: Result<Rule, Error>| match e {
            Err(Error::RuleEntry { index, lambda }) => Some((index, lambda)),
            _ => None,
        };
        assert_eq!(entry(Rule::new(vec![500.0, 831.0], rows([1.0, 1.0]))), Some((1, 831.0)));
        assert_eq!(entry(Rule::new(vec![359.0, 500.0], rows([1.0, 1.0]))), Some((0, 359.0)));
        assert_eq!(entry(Rule::new(vec![500.0, 600.0], rows([1.0, f64::NAN]))), Some((1, 600.0)));
        assert_eq!(entry(Rule::new(vec![500.0, 600.0], rows([f64::INFINITY, 1.0]))), Some((0, 500.0)));
        let short = Rule::new(vec![500.0, 600.0], [vec![1.0; 2], vec![1.0], vec![1.0; 2]]);
        assert!(matches!(short, Err(Error::RuleShape { row: 1, len: 1, expected: 2 })));
        let long = Rule::new(vec![500.0, 600.0], [vec![1.0; 2], vec![1.0; 2], vec![1.0; 3]]);
        assert!(matches!(long, Err(Error::RuleShape { row: 2, len: 3, expected: 2 })));
        let shape = Error::RuleShape { row: 1, len: 1, expected: 2 }.to_string();
        assert_eq!(shape, "rule weights for Y: expected 2 (one per wavelength), found 1");
        assert!(matches!(Rule::new(Vec::new(), Default::default()), Err(Error::Count { found: 0, .. })));
        let edges = Rule::new(vec![360.0, 830.0], rows([1.0, 1.0])).unwrap();
        assert_eq!(edges.m(), 2);
        assert!(Error::RuleEntry { index: 1, lambda: 731.0 }.to_string().contains("rule wavelength 1"));
    }
}
