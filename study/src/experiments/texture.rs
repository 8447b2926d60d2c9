//! What an RGB texture costs in colour: each surface's colour under D65,
//! stored as linear sRGB (as a texture would, clipped to the gamut) and
//! upsampled to an `RgbAlbedo`, then lit by each light beside the measured
//! spectrum. Under D65 the two agree (that is how the albedo was fitted);
//! under another light they are metamers that part: the texture's error.
//! Beside it, the sampling errors of the measured spectrum, so a reader
//! sees which is larger.
//!
//! ```
//! use speclab_study::{evaluate::scene, experiments::texture::{self, TextureOptions}};
//! let (lights, surfaces) = (scene::builtin_lights(), scene::builtin_surfaces());
//! let rows = texture::rows(&lights, &surfaces[..1], &TextureOptions { trials: 20, ..Default::default() })?;
//! let d65 = rows.iter().find(|r| r.light == "D65").unwrap();
//! assert!(d65.texture_de00 < 0.01); // fitted under D65
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::Method;
use crate::evaluate::perceptual;
use crate::evaluate::scene::Named;
use crate::evaluate::trials;
use crate::sampling::choice::{PdfKind, Sampling};
use crate::sampling::estimate::USUAL_K;
use crate::sampling::strata::Strata;
use speclab::color::LinearRgb;
use speclab::color::RgbAlbedo;
use speclab::color::RgbSpace;
use speclab::sampling::buckets::BucketRule;
use speclab::sampling::reference;

/// The sampling the texture's error is set beside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextureOptions {
    /// Hero samples (K = 4, uniform, jittered: a renderer's choice).
    pub n: usize,
    /// Buckets.
    pub m: usize,
    /// Trials for hero's RMS ΔE00.
    pub trials: usize,
    /// Base seed.
    pub seed: u64,
}

impl Default for TextureOptions {
    /// n = 16, M = 16, 200 trials, seed 1.
    fn default() -> Self {
        TextureOptions { n: 16, m: 16, trials: 200, seed: 1 }
    }
}

/// One surface under one light.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureRow {
    /// The light's name.
    pub light: String,
    /// The surface's name.
    pub surface: String,
    /// The texture: the surface's linear sRGB under D65, clipped to [0, 1].
    pub rgb: LinearRgb,
    /// True if clipping changed the colour (the surface is outside sRGB).
    pub clipped: bool,
    /// ΔE00 of the texture's exact colour to the measured spectrum's.
    pub texture_de00: f64,
    /// RMS ΔE00 of hero (n samples, K = 4, jittered) on the measured spectrum.
    pub hero_rms_de00: f64,
    /// ΔE00 of M center buckets on the measured spectrum.
    pub center_de00: f64,
    /// ΔE00 of M box buckets on the measured spectrum.
    pub box_de00: f64,
}

/// The texture of `surface`: its colour under D65, clipped into [0, 1], and
/// whether clipping changed it.
pub fn texture(surface: &Named) -> Result<(LinearRgb, RgbAlbedo, bool), StudyError> {
    let measured = RgbSpace::srgb().rgb_of(&surface.spectrum);
    let rgb = measured.map(|v| v.clamp(0.0, 1.0));
    Ok((rgb, RgbAlbedo::new(rgb)?, rgb != measured))
}

/// Every light × surface: the texture's error beside the sampling errors.
pub fn rows(lights: &[Named], surfaces: &[Named], o: &TextureOptions) -> Result<Vec<TextureRow>, StudyError> {
    let nz = |n: usize| NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
    let hero =
        Method::Hero { k: USUAL_K, sampling: Sampling { pdf: PdfKind::Uniform, strata: Strata::Jittered } };
    let mut out = Vec::with_capacity(lights.len() * surfaces.len());
    for light in lights {
        let white = reference::white(&light.spectrum);
        for surface in surfaces {
            let (rgb, albedo, clipped) = texture(surface)?;
            let exact = light.exact(&surface.spectrum);
            let de = |xyz| perceptual::delta_e00(xyz, exact, white);
            let (l, s) = (&light.spectrum, &surface.spectrum);
            let stats = trials::method(light, s, hero, nz(o.n), nz(o.trials), o.seed)?;
            let bucket = |rule| Method::Buckets { rule }.xyz(l, s, nz(o.m), 0);
            out.push(TextureRow {
                light: light.name.clone(),
                surface: surface.name.clone(),
                rgb,
                clipped,
                texture_de00: de(reference::xyz(l, &albedo)),
                hero_rms_de00: stats.rms_de00,
                center_de00: de(bucket(BucketRule::Center)?),
                box_de00: de(bucket(BucketRule::BoxAverage)?),
            });
        }
    }
    Ok(out)
}
