//! The spectral film: per pixel, M equal buckets of a wavelength range,
//! each the sum of what the samples that fell in it carried, divided by
//! their pdfs (pbrt-v4's `SpectralFilm`).

use crate::HeroSample;
use crate::error::Error;
use crate::film::image::{Kind, SpectralImage};
use crate::spectrum::{Float, SampledSpectrum, WavelengthRange};

/// M equal buckets over a range: bucket `i` is
/// `[min + i·w, min + (i + 1)·w)` with `w = width / M` (the last closed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Buckets {
    range: WavelengthRange,
    count: usize,
    per_nm: f64,
}

impl Buckets {
    /// `count` buckets over `range`: 1 to 4096 ([`Error::Count`]).
    pub fn new(range: WavelengthRange, count: usize) -> Result<Self, Error> {
        if !(1..=4096).contains(&count) {
            return Err(Error::Count { what: "a bucket count", found: count, min: 1, max: 4096 });
        }
        Ok(Buckets { range, count, per_nm: count as f64 / range.width() })
    }

    /// The range.
    #[must_use]
    pub fn range(&self) -> WavelengthRange {
        self.range
    }

    /// M.
    #[must_use]
    pub fn count(&self) -> usize {
        self.count
    }

    /// A bucket's width, nm.
    #[must_use]
    pub fn width(&self) -> f64 {
        self.range.width() / self.count as f64
    }

    /// The middle of bucket `i`, nm.
    #[must_use]
    pub fn center(&self, i: usize) -> f64 {
        self.range.min() + (i as f64 + 0.5) * self.width()
    }

    /// The bucket holding `lambda` (computed in `f64`; a splat computes
    /// it in its samples' precision, so an `f32` wavelength within a
    /// rounding of a bucket's edge may fall on the other side); `None`
    /// outside the range.
    #[inline]
    #[must_use]
    pub fn index(&self, lambda: f64) -> Option<usize> {
        let x = (lambda - self.range.min()) * self.per_nm;
        if x >= 0.0 && lambda <= self.range.max() { Some((x as usize).min(self.count - 1)) } else { None }
    }
}

/// Per pixel, the sums of a film's buckets and its number of samples.
#[derive(Clone, Debug, PartialEq)]
pub struct SpectralFilm {
    width: usize,
    height: usize,
    buckets: Buckets,
    kind: Kind,
    sums: Vec<f64>,
    samples: Vec<u64>,
}

impl SpectralFilm {
    /// A black film of `width × height` pixels; an [`Error::Pixel`] if it
    /// would hold more than 2³² values.
    pub fn new((width, height): (usize, usize), buckets: Buckets, kind: Kind) -> Result<Self, Error> {
        let pixels =
            width.checked_mul(height).filter(|p| p.checked_mul(buckets.count).is_some_and(|v| v <= 1 << 32));
        let Some(pixels) = pixels else {
            return Err(Error::Pixel {
                what: format!("a film of {width} × {height} pixels × {} buckets", buckets.count),
                expected: "at most 2³² values".into(),
            });
        };
        Ok(SpectralFilm {
            width,
            height,
            buckets,
            kind,
            sums: vec![0.0; pixels * buckets.count],
            samples: vec![0; pixels],
        })
    }

    /// The film's buckets.
    #[must_use]
    pub fn buckets(&self) -> Buckets {
        self.buckets
    }

    /// Width and height, pixels.
    #[must_use]
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// Adds one sample to pixel `(x, y)`: what it carried, `v`, at its
    /// wavelengths, each divided by its pdf as the sample's weights say
    /// (`v / (K·pdf)`); a wavelength whose weight is zero (a terminated
    /// secondary, or one dropped) or that falls outside the range adds
    /// nothing. An [`Error::Pixel`] outside the film (nothing added).
    #[inline(always)]
    pub fn splat<const K: usize, T: Float>(
        &mut self,
        (x, y): (usize, usize),
        sample: &HeroSample<K, T>,
        v: SampledSpectrum<K, T>,
    ) -> Result<(), Error> {
        if x >= self.width || y >= self.height {
            return Err(outside(
                format!("the pixel ({x}, {y})"),
                format!("within {} × {}", self.width, self.height),
            ));
        }
        let (pixel, m) = (y * self.width + x, self.buckets.count);
        let row = FilmRow {
            buckets: self.buckets,
            sums: &mut self.sums[pixel * m..(pixel + 1) * m],
            samples: &mut self.samples[pixel..=pixel],
        };
        row.add(0, sample, v);
        Ok(())
    }

    /// The film's rows, each to splat into on its own thread.
    pub fn rows_mut(&mut self) -> impl Iterator<Item = FilmRow<'_>> {
        let (buckets, m) = (self.buckets, self.buckets.count);
        let width = self.width.max(1);
        self.sums
            .chunks_mut(width * m)
            .zip(self.samples.chunks_mut(width))
            .map(move |(sums, samples)| FilmRow { buckets, sums, samples })
    }

    /// The samples added to pixel `(x, y)` (0 outside).
    #[must_use]
    pub fn samples(&self, x: usize, y: usize) -> u64 {
        if x < self.width && y < self.height { self.samples[y * self.width + x] } else { 0 }
    }

    /// The image: per pixel and bucket, the sum over the pixel's samples
    /// divided by their number and the bucket's width (the mean spectral
    /// value per nm over the bucket; 0 for a pixel without samples), at
    /// the buckets' middles.
    #[must_use]
    pub fn image(&self) -> SpectralImage {
        let (m, width) = (self.buckets.count, self.buckets.width());
        let mut values = Vec::with_capacity(self.sums.len());
        for (sums, &n) in self.sums.chunks(m).zip(&self.samples) {
            let scale = if n > 0 { 1.0 / (n as f64 * width) } else { 0.0 };
            values.extend(sums.iter().map(|s| (s * scale) as f32));
        }
        let wavelengths = (0..m).map(|i| self.buckets.center(i)).collect();
        SpectralImage::new((self.width, self.height), self.kind, wavelengths, values)
            .expect("a film's buckets increase and its sums match its size")
    }
}

/// One row of a [`SpectralFilm`], borrowed to splat into.
#[derive(Debug)]
pub struct FilmRow<'a> {
    buckets: Buckets,
    sums: &'a mut [f64],
    samples: &'a mut [u64],
}

impl FilmRow<'_> {
    /// [`SpectralFilm::splat`] into pixel `x` of the row; an
    /// [`Error::Pixel`] past its end.
    #[inline(always)]
    pub fn splat<const K: usize, T: Float>(
        &mut self,
        x: usize,
        sample: &HeroSample<K, T>,
        v: SampledSpectrum<K, T>,
    ) -> Result<(), Error> {
        if x >= self.samples.len() {
            return Err(outside(format!("the pixel {x} of a row"), format!("within {}", self.samples.len())));
        }
        let row = FilmRow { buckets: self.buckets, sums: &mut *self.sums, samples: &mut *self.samples };
        row.add(x, sample, v);
        Ok(())
    }

    /// The buckets in the samples' precision (four lanes at a time in
    /// `f32`); a wavelength that adds nothing (a weight of zero, outside
    /// the range) adds 0 to the nearest bucket, without a branch.
    #[inline(always)]
    fn add<const K: usize, T: Float>(self, x: usize, sample: &HeroSample<K, T>, v: SampledSpectrum<K, T>) {
        let (m, b) = (self.buckets.count, self.buckets);
        let pixel = &mut self.sums[x * m..(x + 1) * m];
        let (lambda, weights) = (sample.lambda(), sample.weights());
        let range = [b.range.min(), b.range.max(), b.per_nm].map(T::from_f64);
        let wv = std::array::from_fn(|j| [weights[j][3], v.values[j]]);
        for (cell, value) in T::splat_lanes(lambda, wv, range, m - 1) {
            pixel[cell] += value;
        }
        self.samples[x] += 1;
    }
}

/// A pixel outside the film (out of the splat's hot path).
#[cold]
#[inline(never)]
fn outside(what: String, expected: String) -> Error {
    Error::Pixel { what, expected }
}
