//! Wavelengths with their XYZ weights, in two kinds told apart by type
//! (pbrt-v4's `SampledWavelengths`, split where it means something):
//!
//! - **drawn**, [`HeroSample<K, T>`](super::HeroSample): random
//!   wavelengths, each with a density; weights `c̄(λⱼ)/(K·pdfⱼ)`; `pdf`,
//!   `inv_pdf` and `terminate_secondary` exist only here;
//! - **fixed**, [`FixedWavelengths<M, T>`]: a rule's wavelengths (bucket
//!   centres, [`Bucketing::wavelengths`](super::regular::Bucketing::wavelengths),
//!   or a fitted rule, [`Rule::wavelengths`](super::rule::Rule::wavelengths))
//!   with its weights, and no density.
//!
//! Both hold the same three things and answer the same questions: the
//! wavelengths (nm), each one's nearest whole nanometre (found once, for
//! dense tables), and one row of weights per wavelength,
//! `[w_X, w_Y, w_Z, w₀]` (`w₀ = 1/(K·pdf)` for drawn wavelengths, 0 for
//! fixed ones). A spectrum sampled at them is a
//! [`SampledSpectrum<K, T>`], and the colour of values `v` is one weighted
//! sum for every count and both kinds (and for `RegularSpectrum`'s
//! buckets):
//!
//! `XYZ = Σⱼ rowⱼ·vⱼ`,
//!
//! for drawn wavelengths one fused multiply-add per wavelength into a
//! four-lane register whose lanes are X, Y, Z; for fixed ones, which keep
//! their weights as three columns too, three multiply-adds per four
//! wavelengths (see `spectrum::simd`). The values are `Copy` and
//! small (K = 4 in `f32`: 16 bytes of wavelengths, 8 of whole
//! nanometres, 64 of weights); nothing here allocates.
//!
//! **What the luminance weights sum to** (`Σⱼ w_Yⱼ`, the Y of a spectrum
//! that is 1 everywhere; fixed wavelengths'
//! [`luminance`](FixedWavelengths::luminance) divides by that sum, a
//! domain's [`luminance`](crate::sampling::Domain::luminance) by its
//! `∫ȳ`, so that a constant comes out as itself):
//! - drawn: a one-sample estimate of `∫ȳ dλ`, unbiased for the observer
//!   it was weighted by (its mean over draws is `Y_BAR_INTEGRAL` for the
//!   exact observer, and the integral of the dense observer's steps, 6e-8
//!   from it, for the dense one);
//! - box buckets: exactly `Y_BAR_INTEGRAL`;
//! - centre buckets: the M-point midpoint sum of ȳ (2.3 % low at M = 4,
//!   4e-5 low at M = 16, 1e-4 high at M = 32);
//! - a fitted rule: whatever its fit to the scene's lights made it (under
//!   F11 at M = 10 about 77 nm): a rule reproduces light × reflectance
//!   products, not a reflectance alone, so its luminance of a throughput
//!   without the light means nothing, and Russian roulette on it should use
//!   the largest value instead.
//!
//! (`tests/properties/luminance.rs` holds each of these.)
//!
//! ```
//! use speclab::{data::{lights, patches}, HeroSample, SampledSpectrum};
//! let h = HeroSample::<4, f32>::new(0.25); // drawn, the dense observer
//! let v: SampledSpectrum<4, f32> = lights::D65.sample(&h) * patches::F4.sample(&h);
//! let xyz = h.to_xyz(v); // Σ w·v, in f32, as f64 XYZ
//! assert!(xyz.y > xyz.x && (h.y(v) - h.y_weights().dot(&v)).abs() <= 1e-6 * h.y(v));
//! ```
//!
//! A fixed rule has wavelengths and weights:
//!
//! ```
//! use speclab::{data::lights, sampling::rule::Rule};
//! let at = Rule::fit(&[&lights::F11], 10).unwrap().wavelengths::<10, f32>().unwrap();
//! assert_eq!(at.lambda().len(), 10);
//! ```
//!
//! but no density (the same lines with `pdf` do not compile, E0599):
//!
//! ```compile_fail,E0599
//! use speclab::{data::lights, sampling::rule::Rule};
//! let at = Rule::fit(&[&lights::F11], 10).unwrap().wavelengths::<10, f32>().unwrap();
//! let pdf = at.pdf(); // no such method: fixed wavelengths are not drawn
//! ```

use crate::color::Xyz;
use crate::spectrum::lookup::nearest_nm;
use crate::spectrum::simd::{column_sums, columns, weighted_sum};
use crate::spectrum::{Float, SampledSpectrum};

/// What both kinds hold: K wavelengths, their nearest whole nanometres,
/// and a row `[w_X, w_Y, w_Z, w₀]` per wavelength.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Weighted<const K: usize, T: Float> {
    pub(crate) lambda: [T; K],
    /// Each wavelength's nearest whole nanometre (see
    /// [`crate::spectrum::Wavelengths::nearest_nm`]), found once.
    pub(crate) nearest: [u16; K],
    /// One row per wavelength: `w_X`, `w_Y`, `w_Z`, `w₀`.
    pub(crate) rows: [[T; 4]; K],
}

impl<const K: usize, T: Float> Weighted<K, T> {
    /// Wavelengths whose nearest whole nanometres are to be found.
    #[inline(always)]
    pub(crate) fn at(lambda: [T; K]) -> Self {
        let nearest = std::array::from_fn(|j| nearest_nm(lambda[j].to_f64()));
        Weighted { lambda, nearest, rows: [[T::ZERO; 4]; K] }
    }

    /// Drawn weights: `[x̄, ȳ, z̄, 1]·sⱼ` (so `w₀ = sⱼ`), with
    /// `sⱼ = 1/(K·pdfⱼ)` and `cmf` the observer's rows at the
    /// wavelengths: one four-lane multiplication per wavelength. `w₀` is
    /// set to `sⱼ` whatever the observer's fourth column holds, so an
    /// observer written as `[x̄, ȳ, z̄, 0]` keeps its pdf.
    #[inline(always)]
    pub(crate) fn drawn(mut self, cmf: [[T; 4]; K], s: [T; K]) -> Self {
        self.rows = std::array::from_fn(|j| {
            let mut row = T::array(T::v4(cmf[j]) * T::splat(s[j]));
            row[3] = s[j];
            row
        });
        self
    }

    /// Fixed weights: `weight(c, j)` for channel c of wavelength j, and
    /// `w₀ = 0`.
    #[inline(always)]
    pub(crate) fn fixed(mut self, weight: impl Fn(usize, usize) -> T) -> Self {
        self.rows = std::array::from_fn(|j| [weight(0, j), weight(1, j), weight(2, j), T::ZERO]);
        self
    }

    /// `[X, Y, Z, Σ w₀·v]` of values `v`, in `T`.
    #[inline(always)]
    pub(crate) fn sums(&self, v: &SampledSpectrum<K, T>) -> [T; 4] {
        weighted_sum(&self.rows, &v.values)
    }

    /// The same wavelengths and weights in precision `U`.
    pub(crate) fn cast<U: Float>(&self) -> Weighted<K, U> {
        let convert = |v: T| U::from_f64(v.to_f64());
        Weighted {
            lambda: self.lambda.map(convert),
            nearest: self.nearest,
            rows: self.rows.map(|row| row.map(convert)),
        }
    }
}

/// What drawn and fixed wavelengths share: the wavelengths, their
/// weights, sampling, XYZ, luminance and a light's emission folded into
/// the weights, for a type `$name<K, T>` holding a [`Weighted`] as `.0`.
macro_rules! weighted_wavelengths {
    ($name:ident) => {
        impl<const K: usize, T: $crate::spectrum::Float> $name<K, T> {
            /// The wavelengths, nm.
            #[inline]
            #[must_use]
            pub fn lambda(&self) -> &[T; K] {
                &self.0.lambda
            }

            /// The weights, one row `[w_X, w_Y, w_Z, w₀]` per wavelength:
            /// XYZ is `Σⱼ rowⱼ·vⱼ`; `w₀` is `1/(K·pdfⱼ)` for drawn
            /// wavelengths and 0 for fixed ones. In nm.
            #[inline]
            #[must_use]
            pub fn weights(&self) -> &[[T; 4]; K] {
                &self.0.rows
            }

            /// `s` at the wavelengths (what `s.sample(&self)` gives).
            #[inline(always)]
            #[must_use]
            pub fn sample(
                &self,
                s: &impl $crate::spectrum::Spectrum,
            ) -> $crate::spectrum::SampledSpectrum<K, T> {
                s.sample(self)
            }

            /// The XYZ of a spectrum with values `v` at these wavelengths:
            /// `Σⱼ rowⱼ·vⱼ`, summed in `T` (four lanes wide: rows for
            /// drawn wavelengths, columns for fixed ones), returned in `f64` so that a
            /// pixel's sum of many estimates keeps its precision. The
            /// assignment's convention, spectrum·nm; a domain's
            /// [`normalized`](crate::sampling::Domain::normalized) (drawn
            /// wavelengths) or the fixed ones' `to_normalized_xyz` gives a
            /// renderer's (a constant 1 has `Y = 1`).
            #[inline(always)]
            #[must_use]
            pub fn to_xyz(&self, v: $crate::spectrum::SampledSpectrum<K, T>) -> $crate::Xyz {
                $crate::Xyz::of_sums(self.sums(&v))
            }

            /// The Y alone, `Σⱼ w_Yⱼ·vⱼ`, in `T` (spectrum·nm, like
            /// every Y here).
            #[inline(always)]
            #[must_use]
            pub fn y(&self, v: $crate::spectrum::SampledSpectrum<K, T>) -> T {
                self.sums(&v)[1]
            }

            /// The weights of [`y`](Self::y), `w_Yⱼ`: `v.dot(&w)` is `y(v)`
            /// to rounding, for any `v`. A path keeps its wavelengths, so a
            /// renderer takes these once per path.
            #[inline]
            #[must_use]
            pub fn y_weights(&self) -> $crate::spectrum::SampledSpectrum<K, T> {
                $crate::spectrum::SampledSpectrum::new(self.0.rows.map(|row| row[1]))
            }

            /// A light's emission folded into the XYZ weights: the colour
            /// any throughput `β` (at these wavelengths) carries from
            /// `light` is then `emission.xyz(β)`, the light evaluated once.
            ///
            /// ```
            /// use speclab::{data::{lights, patches}, HeroSample};
            /// let h = HeroSample::<4>::exact(0.3);
            /// let beta = patches::G4.sample(&h);
            /// let folded = h.emission(&lights::F11).xyz(beta);
            /// let direct = h.to_xyz(beta * lights::F11.sample(&h));
            /// assert!((folded.y - direct.y).abs() <= 1e-12 * direct.y);
            /// ```
            #[inline]
            #[must_use]
            pub fn emission(
                &self,
                light: &impl $crate::spectrum::Spectrum,
            ) -> $crate::sampling::Emission<K, T> {
                let le = light.sample(self).values;
                let rows = std::array::from_fn(|j| self.0.rows[j].map(|w| w * le[j]));
                $crate::sampling::Emission { rows }
            }

            /// The same wavelengths and weights in precision `U` (a rule
            /// fitted in `f64`, for a renderer in `f32`).
            #[must_use]
            pub fn cast<U: $crate::spectrum::Float>(&self) -> $name<K, U> {
                $name::from_weighted(self.0.cast())
            }
        }

        impl<const K: usize, T: $crate::spectrum::Float> $crate::spectrum::Wavelengths<K, T> for $name<K, T> {
            #[inline(always)]
            fn lambda(&self) -> &[T; K] {
                &self.0.lambda
            }

            /// Found once, when the wavelengths were set.
            #[inline(always)]
            fn nearest_nm(&self) -> [u16; K] {
                self.0.nearest
            }
        }
    };
}
pub(crate) use weighted_wavelengths;

/// M fixed wavelengths (nm) with their XYZ weights and no density: bucket
/// centres or a fitted rule, for a renderer's inner loop.
///
/// Besides the rows, the weights are kept as three columns (`w_X`, `w_Y`,
/// `w_Z` of every wavelength), which is how their sums are computed: three
/// four-lane multiply-adds per four wavelengths instead of one per
/// wavelength, half the work at M = 16.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedWavelengths<const M: usize, T: Float = f64>(pub(crate) Weighted<M, T>, [[T; M]; 3]);

weighted_wavelengths!(FixedWavelengths);

impl<const M: usize, T: Float> FixedWavelengths<M, T> {
    /// Wavelengths with fixed weights (`w₀` = 0), their columns made.
    pub(crate) fn from_weighted(w: Weighted<M, T>) -> Self {
        FixedWavelengths(w, columns(&w.rows))
    }

    /// `[X, Y, Z, 0]` of values `v`, from the columns.
    #[inline(always)]
    fn sums(&self, v: &SampledSpectrum<M, T>) -> [T; 4] {
        let [x, y, z] = column_sums(self.1.each_ref().map(|c| &c[..]), &v.values);
        [x, y, z, T::ZERO]
    }

    /// The `Y` of a constant 1, `Σⱼ w_Yⱼ`: what these weights normalise by.
    #[must_use]
    pub fn white_y(&self) -> T {
        self.1[1].iter().fold(T::ZERO, |s, &w| s + w)
    }

    /// [`to_xyz`](Self::to_xyz) over [`white_y`](Self::white_y): a
    /// constant 1 has `Y = 1` exactly (these weights' own normalisation,
    /// whatever range and observer they were made for).
    #[inline]
    #[must_use]
    pub fn to_normalized_xyz(&self, v: SampledSpectrum<M, T>) -> Xyz {
        self.to_xyz(v) / self.white_y().to_f64()
    }

    /// The luminance in the units of `v`: [`y`](Self::y) over
    /// [`white_y`](Self::white_y), in `T`: a constant's is the constant.
    #[inline]
    #[must_use]
    pub fn luminance(&self, v: SampledSpectrum<M, T>) -> T {
        self.y(v) / self.white_y()
    }
}

/// A light's emission times the XYZ weights of some wavelengths (see
/// `emission` on [`HeroSample`](super::HeroSample) and
/// [`FixedWavelengths`]): rows `rowⱼ·L(λⱼ)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission<const K: usize, T: Float = f64> {
    pub(crate) rows: [[T; 4]; K],
}

impl<const K: usize, T: Float> Emission<K, T> {
    /// The XYZ that throughput `beta` carries from the light:
    /// `Σⱼ rowⱼ·L(λⱼ)·βⱼ`, summed in `T`, returned in `f64`.
    #[inline(always)]
    #[must_use]
    pub fn xyz(&self, beta: SampledSpectrum<K, T>) -> Xyz {
        Xyz::of_sums(weighted_sum(&self.rows, &beta.values))
    }
}
