//! The tracer's paths onto a spectral film: the same paths as a hero
//! render (the same random numbers, pixel by pixel), each path's radiance
//! at its four wavelengths splatted into the film's buckets, beside the
//! tracer's own XYZ of the same paths. Weighted by a sensor (a CIE
//! observer as a [`Sensor`]), so that a film of 1 nm buckets at whole
//! nanometres develops ([`Quadrature::Point`](speclab::film::Quadrature))
//! to the tracer's XYZ to rounding.
//!
//! An emissive film keeps radiance; a reflective one (one light) keeps
//! each path's throughput without the light, to be developed under any
//! light afterwards.

use std::time::Instant;

use rayon::prelude::*;
use speclab::film::{Buckets, FilmRow, Kind, Sensor, SpectralFilm};
use speclab::sampling::pdf::WavelengthPdf;
use speclab::spectrum::{Float, Observer, SampledSpectrum, Spectrum, WavelengthRange};
use speclab::{Error, Xyz};

use crate::StudyError;
use crate::carry::{Carry, Hero};
use crate::render::run::{hero, wavelength_pdf};
use crate::render::tracer::{self, Rng, Sink};
use crate::render::{Options, Setup, seed};

/// A spectral film of a render and the tracer's own XYZ of its paths.
#[derive(Clone, Debug)]
pub struct FilmRender {
    /// The film.
    pub film: SpectralFilm,
    /// The tracer's mean XYZ per pixel (hero, weighed by the sensor).
    pub xyz: Vec<Xyz>,
    /// Wall-clock time, s.
    pub seconds: f64,
}

/// 1 nm buckets centred on the whole nanometres of `range`.
pub fn whole_nm(range: WavelengthRange) -> Result<Buckets, Error> {
    let count = range.width().round() as usize + 1;
    Buckets::new(WavelengthRange::new(range.min() - 0.5, range.max() + 0.5)?, count)
}

/// Renders `o.spp` hero paths per pixel (f64, the scene's exact spectra,
/// `o`'s pdf and strata, weighed by `sensor`) onto a film of `buckets`;
/// a [`StudyError::Spectra`] for a reflective film of a scene with more
/// than one light.
pub fn spectral(
    setup: &Setup,
    o: &Options,
    kind: Kind,
    buckets: Buckets,
    sensor: &Sensor,
) -> Result<FilmRender, StudyError> {
    if kind == Kind::Reflective && setup.lights.len() != 1 {
        let found = setup.lights.len();
        return Err(Error::Count { what: "lights for a reflective film", found, min: 1, max: 1 }.into());
    }
    let pdf = wavelength_pdf(o, setup)?;
    let carry = hero::<_, _, f64>(setup, setup.light_spectra(), setup.patches.clone(), sensor.clone(), pdf)?;
    let mut film = SpectralFilm::new((o.width, o.height), buckets, kind)?;
    let mut xyz = vec![Xyz::ZERO; o.width * o.height];
    let start = Instant::now();
    let rows: Vec<(usize, (FilmRow<'_>, &mut [Xyz]))> =
        film.rows_mut().zip(xyz.chunks_mut(o.width.max(1))).enumerate().collect();
    rows.into_par_iter().for_each(|(y, (mut row, out))| {
        for (x, pixel) in out.iter_mut().enumerate() {
            *pixel = trace_pixel(setup, &carry, o, (x, y), kind, &mut row);
        }
    });
    Ok(FilmRender { film, xyz, seconds: start.elapsed().as_secs_f64() })
}

/// One pixel's paths onto its row of the film; their mean XYZ.
fn trace_pixel<L, S, O, P>(
    setup: &Setup,
    carry: &Hero<L, S, O, P, f64>,
    o: &Options,
    (x, y): (usize, usize),
    kind: Kind,
    row: &mut FilmRow<'_>,
) -> Xyz
where
    L: Spectrum,
    S: Spectrum,
    O: Observer,
    P: WavelengthPdf,
{
    let mut rng = Rng(seed(1, y * o.width + x));
    let shift = rng.uniform();
    let mut sum = Xyz::ZERO;
    for i in 0..o.spp {
        let u = if o.sampling.strata == crate::sampling::strata::Strata::Kronecker {
            shift
        } else {
            rng.uniform()
        };
        let path = carry.path(o.sampling.strata.point(i, o.spp, 4, u));
        let at = ((x as f64 + rng.uniform()) / o.width as f64, (y as f64 + rng.uniform()) / o.height as f64);
        let mut sink = FilmSink {
            xyz: Xyz::ZERO,
            radiance: SampledSpectrum::zero(),
            reflective: kind == Kind::Reflective,
        };
        tracer::trace_into(&setup.scene, carry, &path, at, &mut rng, &mut (), &mut sink);
        sum += sink.xyz;
        // The pixel is inside its row: x < width.
        let _ = row.splat(x, &path, sink.radiance);
    }
    sum / o.spp.max(1) as f64
}

/// A path's radiance at its wavelengths (without the light, for a
/// reflective film) and its XYZ.
struct FilmSink<T: Float> {
    xyz: Xyz,
    radiance: SampledSpectrum<4, T>,
    reflective: bool,
}

impl<L, S, O, P, T> Sink<Hero<L, S, O, P, T>> for FilmSink<T>
where
    L: Spectrum,
    S: Spectrum,
    O: Observer,
    P: WavelengthPdf,
    T: Float,
{
    fn emitted(
        &mut self,
        paint: &Hero<L, S, O, P, T>,
        path: &<Hero<L, S, O, P, T> as Carry>::Path,
        light: usize,
        beta: SampledSpectrum<4, T>,
        factor: f64,
    ) {
        self.xyz += paint.emitted(path, light, beta) * factor;
        let Some(spectrum) = paint.lights.get(light) else { return };
        let through = if self.reflective { beta } else { beta * path.sample(spectrum) };
        self.radiance += through * T::from_f64(factor);
    }
}
