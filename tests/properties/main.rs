//! Properties of the core that hold for every input: energy conservation,
//! finite results, no panics, exactness of each fast path against the slow
//! one, pdfs that integrate to 1 and are sampled as they say, dense tables
//! within their stated error, round trips through RGB, what the luminance
//! weights of each kind of wavelengths sum to.

mod dense;
mod energy;
mod finite;
mod fitted;
mod luminance;
mod max_value;
mod no_panic;
mod pdfs;
mod prepared;
mod regular;
mod rgb_table;
mod spectra;
mod texel;
mod upsample;
mod visible;

/// The mean XYZ of `n` hero samples of `light × surface`, wavelengths
/// uniform and independent from `rng`, weighted by the exact observer (the
/// study's estimator, written as a renderer would).
pub fn hero_mean<const K: usize>(
    light: &(impl speclab::Spectrum + ?Sized),
    surface: &(impl speclab::Spectrum + ?Sized),
    n: usize,
    rng: &mut impl rand::Rng,
) -> speclab::Xyz {
    use rand::RngExt;
    let sum: speclab::Xyz = (0..n)
        .map(|_| {
            let h = speclab::HeroSample::<K>::exact(rng.random::<f64>());
            h.to_xyz(h.sample(&light) * h.sample(&surface))
        })
        .sum();
    sum / n as f64
}
