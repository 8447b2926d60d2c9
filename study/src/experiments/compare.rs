//! The assignment's main user story: one light and one surface, the exact
//! reference beside every technique, with sRGB, ΔE00 of one estimate and,
//! over many trials, RMS ΔE00; and last, the surface as an RGB texture
//! would store it (its colour under D65, upsampled), lit by the light. With
//! a depth above 1, every line is light × surface^depth. The published
//! rules (ASTM, Borges, Meyer, Wallis at the same M) and spectral
//! prefiltering in three spaces follow the fitted rule
//! ([`crate::published`]); a rule that does not exist for the light (a
//! Borges rule without real nodes, a count below the family's smallest)
//! has no line.
//!
//! ```
//! use speclab_study::experiments::compare::{self, CompareOptions};
//! use speclab_study::evaluate::scene::Choice;
//! use speclab::Role;
//! let light = Choice::Name("F11".into()).resolve(Role::Light)?;
//! let patch = Choice::Name("G4".into()).resolve(Role::Reflectance)?;
//! let lines = compare::compare(&light, &patch, &CompareOptions::default())?;
//! assert_eq!(lines[0].label, "reference");
//! assert_eq!(lines[0].de00, 0.0);
//! assert_eq!(lines.len(), 14);
//! assert_eq!(lines[5].label, "fitted M=16");
//! assert_eq!(lines[6].label, "astm M=16");
//! assert_eq!(lines[12].label, "prefilter-sharp");
//! assert!(lines[12].de00 < 1e-6); // exact at one bounce
//! assert_eq!(lines[13].label, "rgb texture (D65)");
//! # Ok::<(), speclab_study::StudyError>(())
//! ```

use std::num::NonZeroUsize;

use crate::StudyError;
use crate::evaluate::method::Method;
use crate::evaluate::perceptual;
use crate::evaluate::scene::{Depth, Named};
use crate::evaluate::viewing::Viewing;
use crate::sampling::choice::Sampling;
use crate::sampling::estimate::USUAL_K;
use crate::{evaluate::trials, experiments::texture};
use speclab::color::LinearRgb;
use speclab::sampling::buckets::BucketRule;

/// What to compare, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CompareOptions {
    /// Samples for random and hero.
    pub n: NonZeroUsize,
    /// Buckets for the regular methods, and wavelengths of the fitted rule.
    pub m: NonZeroUsize,
    /// Hero width.
    pub k: usize,
    /// The random and hero methods' pdf and strata.
    pub sampling: Sampling,
    /// Seed of the single estimates, and base seed of the trials.
    pub seed: u64,
    /// Trials for the RMS ΔE00.
    pub trials: NonZeroUsize,
    /// Normalisation (already applied to the light) and white balance.
    pub viewing: Viewing,
    /// Surfaces per path.
    pub depth: Depth,
}

impl Default for CompareOptions {
    /// n = 100, M = 16, K = 4, seed 1, 200 trials, depth 1, as Appendix 2.
    fn default() -> Self {
        let nz = |n| NonZeroUsize::new(n).unwrap_or(NonZeroUsize::MIN);
        let (k, sampling, viewing) = (USUAL_K, Sampling::DEFAULT, Viewing::default());
        let depth = Depth::ONE;
        CompareOptions { n: nz(100), m: nz(16), k, sampling, seed: 1, trials: nz(200), viewing, depth }
    }
}

/// One technique's result.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// The technique and its count, e.g. `hero n=100 K=4`.
    pub label: String,
    /// Wavelengths evaluated per estimate.
    pub evals: usize,
    /// One estimate, as linear sRGB (white-balanced if asked).
    pub rgb: LinearRgb,
    /// ΔE00 of that estimate to the reference.
    pub de00: f64,
    /// RMS ΔE00 over the trials (one trial for deterministic techniques).
    pub rms_de00: f64,
}

/// The reference, random, hero, centre, box, fitted, published and texture
/// lines for `light × surface`.
pub fn compare(light: &Named, surface: &Named, s: &CompareOptions) -> Result<Vec<Line>, StudyError> {
    let (l, r) = (&light.spectrum, &surface.spectrum);
    let mut techniques = vec![
        (Method::Reference, s.n, "reference".to_string()),
        (Method::Hero { k: 1, sampling: s.sampling }, s.n, format!("random n={}", s.n)),
        (Method::Hero { k: s.k, sampling: s.sampling }, s.n, format!("hero n={} K={}", s.n, s.k)),
        (Method::Buckets { rule: BucketRule::Center }, s.m, format!("center M={}", s.m)),
        (Method::Buckets { rule: BucketRule::BoxAverage }, s.m, format!("box M={}", s.m)),
        (Method::Fitted, s.m, format!("fitted M={}", s.m)),
    ];
    for method in Method::PUBLISHED {
        let label = match method {
            Method::Prefiltered { .. } => method.to_string(),
            _ => format!("{method} M={}", s.m),
        };
        techniques.push((method, s.m, label));
    }
    let white = s.viewing.white(l);
    let exact = s.viewing.adapt(light.exact_at(s.depth, r), l);
    let (_, albedo, _) = texture::texture(surface)?;
    let textured = s.viewing.adapt(s.depth.exact(l, &albedo), l);
    let de00 = perceptual::delta_e00(textured, exact, white);
    let texture_line = Line {
        label: "rgb texture (D65)".into(),
        evals: 0,
        rgb: textured.to_linear_srgb(),
        de00,
        rms_de00: de00,
    };
    let lines: Result<Vec<Line>, StudyError> = techniques
        .into_iter()
        .filter(|&(method, count, _)| exists(method, light, count))
        .map(|(method, count, label)| {
            let prepared = method.prepare(light)?.at_depth(s.depth);
            let estimate = |seed| prepared.xyz(r, count, seed).map(|x| s.viewing.adapt(x, l));
            let xyz = estimate(s.seed)?;
            let t = if method.is_random() { s.trials } else { NonZeroUsize::MIN };
            let stats = trials::run(exact, white, t, s.seed, estimate)?;
            let de00 = perceptual::delta_e00(xyz, exact, white);
            let evals = method.evaluations(count);
            Ok(Line { label, evals, rgb: xyz.to_linear_srgb(), de00, rms_de00: stats.rms_de00 })
        })
        .collect();
    let mut lines = lines?;
    lines.push(texture_line);
    Ok(lines)
}

/// False for a published rule that does not exist for `light` at `count`.
fn exists(method: Method, light: &Named, count: NonZeroUsize) -> bool {
    match method {
        Method::Published { family } => {
            !matches!(light.published(family, count.get()), Err(StudyError::NoRule { .. }))
        }
        _ => true,
    }
}
