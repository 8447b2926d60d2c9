//! The estimator's one noun: [`SampledWavelengths<K, T>`], K wavelengths
//! with their XYZ weights, in `f64` (the default) or `f32`.
//!
//! Every way of choosing wavelengths fills one: a hero sample when it is
//! drawn (`HeroSample<K, T>` is this type: weights `c̄(λⱼ)/(K·pdfⱼ)`, see
//! [`super::hero`]), equidistant buckets (weights `W/M·c̄ᵢ`, see
//! [`super::regular`]) and a rule fitted to a scene's lights (fitted
//! weights, see [`super::rule`]). A spectrum sampled at it is a
//! [`SampledSpectrum<K, T>`], and the colour of a value `v` is one weighted
//! sum, written once here for every count (the study's run-time counts go
//! through the same function on slices):
//!
//! `XYZ꜀ = Σⱼ w꜀ⱼ·vⱼ`.
//!
//! The weights are four rows of K, `w_X`, `w_Y`, `w_Z` and `w₀`, where
//! `w₀ = 1/(K·pdfⱼ)` for drawn wavelengths and 0 for fixed rules, which
//! have no density: a colour is three dot products, a luminance one. The
//! value is `Copy` and small (K = 4 in `f32`: 16 bytes of wavelengths, 8 of
//! their whole nanometres, 64 of weights); nothing here allocates.
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, SampledSpectrum};
//! let h = HeroSample::<4, f32>::new(0.25_f32); // drawn: wavelengths and weights
//! let v: SampledSpectrum<4, f32> = lights::D65.sample(&h) * patches::F4.sample(&h);
//! let xyz = h.to_xyz(v); // Σ w·v, in f32, as f64 XYZ
//! assert!(xyz.y > xyz.x && (h.y(v) - h.y_weights().dot(&v)).abs() <= 1e-6 * h.y(v));
//! ```

use crate::color::Xyz;
use crate::spectrum::lookup::nearest_nm;
use crate::spectrum::{Float, SampledSpectrum, Spectrum, Wavelengths};

/// K wavelengths (nm) and their XYZ weights: where spectra are sampled,
/// and how their values become a colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledWavelengths<const K: usize, T: Float = f64> {
    pub(crate) lambda: [T; K],
    /// Each wavelength's nearest whole nanometre (see
    /// [`Wavelengths::nearest_nm`]), found once.
    nearest: [u16; K],
    /// The rows `w_X`, `w_Y`, `w_Z`, `w₀`, one weight per wavelength each.
    pub(crate) weights: [[T; K]; 4],
}

impl<const K: usize, T: Float> SampledWavelengths<K, T> {
    /// Wavelengths and their weights (rows `w_X`, `w_Y`, `w_Z`, `w₀`).
    #[inline(always)]
    pub(crate) fn from_parts(lambda: [T; K], weights: [[T; K]; 4]) -> Self {
        let nearest = std::array::from_fn(|j| nearest_nm(lambda[j].to_f64()));
        SampledWavelengths { lambda, nearest, weights }
    }

    /// Wavelengths whose nearest whole nanometres are known (as
    /// [`Wavelengths::nearest_nm`] would find them), weights to be filled.
    #[inline(always)]
    pub(crate) fn placed(lambda: [T; K], nearest: [u16; K]) -> Self {
        SampledWavelengths { lambda, nearest, weights: [[T::ZERO; K]; 4] }
    }

    /// Wavelengths with their weights still to be filled (from an
    /// observer, which needs the wavelengths' places first).
    #[inline(always)]
    pub(crate) fn unweighted(lambda: [T; K]) -> Self {
        Self::from_parts(lambda, [[T::ZERO; K]; 4])
    }

    /// The wavelengths, nm (a hero sample's hero first).
    #[inline]
    #[must_use]
    pub fn lambda(&self) -> &[T; K] {
        &self.lambda
    }

    /// The weights, nm: rows `w_X`, `w_Y`, `w_Z` (XYZ is `Σⱼ w꜀ⱼ·vⱼ`) and
    /// `w₀` (`1/(K·pdfⱼ)` for drawn wavelengths, 0 for fixed rules).
    #[inline]
    #[must_use]
    pub fn weights(&self) -> &[[T; K]; 4] {
        &self.weights
    }

    /// `s` at the wavelengths (what `s.sample(&self)` gives).
    #[inline(always)]
    #[must_use]
    pub fn sample(&self, s: &impl Spectrum) -> SampledSpectrum<K, T> {
        s.sample(self)
    }

    /// The XYZ of a spectrum with values `v` at these wavelengths:
    /// `Σⱼ w꜀ⱼ·vⱼ`, summed in `T`, returned in `f64` (a pixel's sum of
    /// many estimates is then exact to `f64`). The assignment's convention,
    /// spectrum·nm; [`Xyz::normalized`] gives a renderer's (a constant 1
    /// has `Y = 1`).
    #[inline(always)]
    #[must_use]
    pub fn to_xyz(&self, v: SampledSpectrum<K, T>) -> Xyz {
        let [x, y, z, _] = &self.weights;
        Xyz::new(dot(x, &v.values).to_f64(), dot(y, &v.values).to_f64(), dot(z, &v.values).to_f64())
    }

    /// The luminance alone, `Σⱼ w_Yⱼ·vⱼ`: the Y of
    /// [`SampledWavelengths::to_xyz`] before rounding to `f64`, for Russian
    /// roulette and other decisions. In the units of `v` times nm, like
    /// every Y here: divide by
    /// [`Y_BAR_INTEGRAL`](crate::spectrum::observer::Y_BAR_INTEGRAL) for
    /// the luminance of a constant spectrum to come out as that constant.
    #[inline(always)]
    #[must_use]
    pub fn y(&self, v: SampledSpectrum<K, T>) -> T {
        dot(&self.weights[1], &v.values)
    }

    /// The weights of [`SampledWavelengths::y`], `w_Yⱼ`: `v.dot(&w)` is
    /// `y(v)` to rounding, for any `v`. A path keeps its wavelengths, so a
    /// renderer takes these once per path and each bounce's luminance is a
    /// dot product of K numbers.
    ///
    /// ```
    /// use speclab::{data::patches, HeroSample};
    /// let h = HeroSample::<4>::new(0.3);
    /// let (w, albedo) = (h.y_weights(), patches::F4.sample(&h));
    /// assert!((albedo.dot(&w) - h.y(albedo)).abs() <= 1e-12 * h.y(albedo));
    /// ```
    #[inline]
    #[must_use]
    pub fn y_weights(&self) -> SampledSpectrum<K, T> {
        SampledSpectrum::new(self.weights[1])
    }

    /// A light's emission folded into the XYZ weights: the colour any
    /// throughput `β` (at these wavelengths) carries from `light` is then
    /// `emission.xyz(β)`, three dot products, the light evaluated once. A
    /// renderer with several lights keeps one per light, each from that
    /// light's own weights ([`Rule::fit_each`](super::rule::Rule::fit_each)).
    ///
    /// ```
    /// use speclab::{data::{lights, patches}, HeroSample};
    /// let h = HeroSample::<4>::new(0.3);
    /// let beta = patches::G4.sample(&h);
    /// let folded = h.emission(&lights::F11).xyz(beta);
    /// let direct = h.to_xyz(beta * lights::F11.sample(&h));
    /// assert!((folded.y - direct.y).abs() <= 1e-12 * direct.y);
    /// ```
    #[inline]
    #[must_use]
    pub fn emission(&self, light: &impl Spectrum) -> Emission<K, T> {
        let le = light.sample(self).values;
        Emission { weights: std::array::from_fn(|c| std::array::from_fn(|j| self.weights[c][j] * le[j])) }
    }

    /// The same wavelengths and weights in precision `U` (a rule fitted in
    /// `f64`, for a renderer in `f32`).
    #[must_use]
    pub fn cast<U: Float>(&self) -> SampledWavelengths<K, U> {
        let convert = |v: T| U::from_f64(v.to_f64());
        let weights = std::array::from_fn(|c| std::array::from_fn(|j| convert(self.weights[c][j])));
        SampledWavelengths::from_parts(std::array::from_fn(|j| convert(self.lambda[j])), weights)
    }
}

impl<const K: usize, T: Float> Wavelengths<K, T> for SampledWavelengths<K, T> {
    #[inline(always)]
    fn lambda(&self) -> &[T; K] {
        &self.lambda
    }

    /// Found once, when the wavelengths were set.
    #[inline(always)]
    fn nearest_nm(&self) -> [u16; K] {
        self.nearest
    }
}

/// A light's emission times the XYZ weights of some wavelengths (see
/// [`SampledWavelengths::emission`]): rows `w꜀ⱼ·L(λⱼ)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission<const K: usize, T: Float = f64> {
    weights: [[T; K]; 3],
}

impl<const K: usize, T: Float> Emission<K, T> {
    /// The XYZ that throughput `beta` carries from the light:
    /// `Σⱼ w꜀ⱼ·L(λⱼ)·βⱼ`, summed in `T`, returned in `f64`.
    #[inline(always)]
    #[must_use]
    pub fn xyz(&self, beta: SampledSpectrum<K, T>) -> Xyz {
        let [x, y, z] = &self.weights;
        Xyz::new(dot(x, &beta.values).to_f64(), dot(y, &beta.values).to_f64(), dot(z, &beta.values).to_f64())
    }
}

/// `Σᵢ wᵢ·vᵢ`: the estimator, written once for every count (the colour is
/// three of these, the luminance one), in four interleaved partial sums so
/// that the additions do not wait on each other. Missing values (fewer than
/// weights) count as 0. For a count known at compile time (unrolled).
#[inline(always)]
pub(crate) fn dot<T: Float>(w: &[T], values: &[T]) -> T {
    let mut acc = [T::ZERO; 4];
    for (i, (&w, &v)) in w.iter().zip(values).enumerate() {
        acc[i % 4] += w * v;
    }
    (acc[0] + acc[2]) + (acc[1] + acc[3])
}

/// [`dot`] for a count known only at run time (the study's rules and hero
/// widths): the same partial sums in the same order, walked in chunks of
/// four so that they stay in registers instead of an array indexed by
/// `i % 4` on the stack (twice as fast on 8 to 16 values).
#[inline(always)]
pub(crate) fn dot_slices(w: &[f64], values: &[f64]) -> f64 {
    let n = w.len().min(values.len());
    let ((w4, w_rest), (v4, v_rest)) = (w[..n].as_chunks::<4>(), values[..n].as_chunks::<4>());
    let mut acc = [0.0; 4];
    for (w, v) in w4.iter().zip(v4) {
        for l in 0..4 {
            acc[l] += w[l] * v[l];
        }
    }
    for (l, (&w, &v)) in w_rest.iter().zip(v_rest).enumerate() {
        acc[l] += w * v;
    }
    (acc[0] + acc[2]) + (acc[1] + acc[3])
}

#[cfg(test)]
mod tests {
    use super::{dot, dot_slices};

    /// The run-time form is the compile-time form to the bit, for every
    /// count from 0 to 13 (whole chunks, remainders, and values shorter
    /// than the weights, which count as 0).
    #[test]
    fn both_forms_of_the_sum_agree_to_the_bit() {
        let w: Vec<f64> = (0..13).map(|i| 1.0 / (f64::from(i) + 1.7)).collect();
        let v: Vec<f64> = (0..13).map(|i| (f64::from(i) * 0.618_034).fract() - 0.3).collect();
        for n in 0..=13 {
            let by_hand = (0..n).fold([0.0; 4], |mut acc, i| {
                acc[i % 4] += w[i] * v[i];
                acc
            });
            let expected = (by_hand[0] + by_hand[2]) + (by_hand[1] + by_hand[3]);
            assert_eq!(dot(&w[..n], &v[..n]).to_bits(), expected.to_bits(), "n = {n}");
            assert_eq!(dot_slices(&w[..n], &v[..n]).to_bits(), expected.to_bits(), "n = {n}");
            assert_eq!(dot_slices(&w, &v[..n]).to_bits(), expected.to_bits(), "missing values, n = {n}");
        }
    }
}
