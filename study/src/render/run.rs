//! The way [`Options`] asks for, built and handed on ([`with_carry`]);
//! timed against grey ([`timed`]); compared with the exact image of its own
//! paths ([`against_exact`], [`delta_e`]) or with a reference render
//! ([`reference_error`]).

use std::time::Instant;

use crate::StudyError;
use crate::carry::{Carry, Fitted, Hero, Rgb};
use crate::sampling::choice::PdfKind;
use speclab::color::lab::lab;
use speclab::color::{LinearRgb, RgbSpace};
use speclab::sampling::binned::BinnedPdf;
use speclab::sampling::pdf::WavelengthPdf;
use speclab::sampling::rule::Rule;
use speclab::sampling::{AtWidth, with_lanes};
use speclab::spectrum::{
    AssignmentObserver, DenseObserver, DenseSpectrum, Float, Mixture, Observer, Spectrum,
};
use speclab::{TabulatedSpectrum, Xyz};

use crate::evaluate::perceptual;
use crate::published::prefilter::Space;
use crate::render::ways::{Albedo, Prefilter};
use crate::render::{Options, Render, Setup, Way, render};

/// Something done with a way of carrying colour, whatever its type (a
/// visitor: each way is its own type, monomorphised).
pub trait WithCarry {
    /// What it returns.
    type Out;
    /// Does it with `carry`.
    fn go<C: Carry + Sync>(self, carry: &C) -> Self::Out;
}

/// The density hero wavelengths are drawn from: `o.sampling`'s, following
/// all the scene's lights, as a histogram of `o.bins` bins unless `None`
/// (uniform needs neither).
pub fn wavelength_pdf(o: &Options, setup: &Setup) -> Result<Box<dyn WavelengthPdf + Sync>, speclab::Error> {
    let mut scene = Mixture::new();
    for l in &setup.lights {
        scene = scene.with(1.0, &l.spectrum)?;
    }
    let exact = o.sampling.pdf.for_light(&scene)?;
    Ok(match (o.bins, o.sampling.pdf) {
        (_, PdfKind::Uniform) | (None, _) => Box::new(exact),
        (Some(bins), _) => Box::new(BinnedPdf::new(&exact, bins)?),
    })
}

/// Builds the way `o` asks for and hands it to `with`.
pub fn with_carry<W: WithCarry>(o: &Options, setup: &Setup, with: W) -> Result<W::Out, StudyError> {
    match o.way {
        Way::Rgb => {
            let mut rgb = Rgb::new(&setup.light_spectra(), &setup.patches);
            rgb.surfaces.extend(setup.colours.iter().copied());
            Ok(with.go(&rgb))
        }
        Way::Prefilter => {
            let mut surfaces: Vec<Albedo<&TabulatedSpectrum>> =
                setup.patches.iter().map(Albedo::Measured).collect();
            surfaces.extend(setup.texture.iter().cloned().map(Albedo::Texel));
            Ok(with.go(&Prefilter::new(Space::Sharp, &setup.light_spectra(), &surfaces)?))
        }
        Way::Fitted => {
            let rules = Rule::fit_each(&setup.light_spectra(), o.m)?;
            with_lanes(o.m, FittedWidth { rules: &rules, setup, single: o.single, with })?
        }
        Way::Hero => {
            let pdf = wavelength_pdf(o, setup)?;
            let (lights, patches) = (setup.light_spectra(), &setup.patches);
            if let Some(name) = o.rgb_space {
                let space = RgbSpace::all().into_iter().find(|s| s.name() == name).ok_or_else(|| {
                    speclab::Error::UnknownName {
                        what: "an RGB space",
                        expected: &SPACES,
                        found: name.into(),
                    }
                })?;
                let l: Vec<DenseSpectrum> = lights.iter().map(DenseSpectrum::new).collect();
                let s = textured::<DenseSpectrum>(setup, space, o.rgb_converted);
                let hero = Hero::new(l, s, DenseObserver::new(), pdf)?;
                return Ok(if o.single {
                    with.go(&hero.precision::<f32>())
                } else {
                    with.go(&hero.precision::<f64>())
                });
            }
            Ok(match (o.dense, o.single) {
                (false, false) => {
                    with.go(&hero::<_, _, f64>(setup, lights, patches.clone(), AssignmentObserver, pdf)?)
                }
                (false, true) => {
                    with.go(&hero::<_, _, f32>(setup, lights, patches.clone(), AssignmentObserver, pdf)?)
                }
                (true, false) => {
                    let dense = |s: &TabulatedSpectrum| DenseSpectrum::new(s);
                    let (l, p) = (lights.iter().map(dense).collect(), patches.iter().map(dense).collect());
                    with.go(&hero::<_, _, f64>(setup, l, p, DenseObserver::new(), pdf)?)
                }
                (true, true) => {
                    let dense = |s: &TabulatedSpectrum| DenseSpectrum::new(s);
                    let (l, p) = (lights.iter().map(dense).collect(), patches.iter().map(dense).collect());
                    with.go(&hero::<_, _, f32>(setup, l, p, DenseObserver::new(), pdf)?)
                }
            })
        }
    }
}

/// The built-in spaces' names, for `Options::rgb_space`.
pub const SPACES: [&str; 5] = ["sRGB", "Display P3", "Rec.2020", "ACES2065-1", "ACEScg"];

/// The scene's surfaces as RGB colours in `space`: a patch's colour under
/// the space's illuminant, a texel's sRGB colour taken into the space,
/// each clamped to [0, 1]; each looked up at every hit, or, if
/// `converted`, once here.
pub fn textured<S>(setup: &Setup, space: &'static RgbSpace, converted: bool) -> Vec<Albedo<S>> {
    let clamp = |c: LinearRgb| c.map(|v| v.clamp(0.0, 1.0));
    let patches = setup.patches.iter().map(|p| clamp(space.rgb_of(p)));
    let texels = setup.colours.iter().map(|&c| clamp(space.rgb(RgbSpace::srgb().xyz(c))));
    let albedo = |rgb| if converted { Albedo::converted(rgb, space) } else { Albedo::Lookup(rgb, space) };
    patches.chain(texels).map(albedo).collect()
}

/// The hero way over the scene's spectra, a boxed pdf and observer `O`.
pub type SceneHero<S, O, T> = Hero<S, Albedo<S>, O, Box<dyn WavelengthPdf + Sync>, T>;

/// Hero over these lights and patches (the texels after them), in `T`;
/// an error if the pdf draws where the observer has no data.
pub fn hero<S: Spectrum, O: Observer, T: Float>(
    setup: &Setup,
    lights: Vec<S>,
    patches: Vec<S>,
    observer: O,
    pdf: Box<dyn WavelengthPdf + Sync>,
) -> Result<SceneHero<S, O, T>, speclab::Error> {
    let mut surfaces: Vec<Albedo<S>> = patches.into_iter().map(Albedo::Measured).collect();
    surfaces.extend(setup.texture.iter().cloned().map(Albedo::Texel));
    Ok(Hero::new(lights, surfaces, observer, pdf)?.precision::<T>())
}

/// The fitted rules at the compiled width that holds them, in `f32` or
/// `f64`, handed on.
struct FittedWidth<'a, W> {
    rules: &'a [Rule],
    setup: &'a Setup,
    single: bool,
    with: W,
}

impl<W: WithCarry> AtWidth for FittedWidth<'_, W> {
    type Output = Result<W::Out, StudyError>;

    fn call<const CAP: usize>(self) -> Self::Output {
        let mut surfaces: Vec<Albedo<&TabulatedSpectrum>> =
            self.setup.patches.iter().map(Albedo::Measured).collect();
        surfaces.extend(self.setup.texture.iter().cloned().map(Albedo::Texel));
        let lights = self.setup.light_spectra();
        Ok(if self.single {
            self.with.go(&Fitted::<CAP, f32>::new(self.rules, &lights, &surfaces)?)
        } else {
            self.with.go(&Fitted::<CAP, f64>::new(self.rules, &lights, &surfaces)?)
        })
    }
}

/// A way's image and grey's, each the fastest of three runs, alternating.
#[derive(Clone, Debug)]
pub struct Timed {
    /// The image, in colour.
    pub image: Render,
    /// The same paths in grey.
    pub grey: Render,
}

impl Timed {
    /// ns per vertex per thread: (colour, grey).
    #[must_use]
    pub fn ns_per_vertex(&self, threads: usize) -> (f64, f64) {
        let per_vertex = |r: &Render| r.seconds * 1e9 * threads as f64 / r.vertices.max(1) as f64;
        (per_vertex(&self.image), per_vertex(&self.grey))
    }
}

/// Renders with `carry` and grey alternately, three times each (the
/// fastest of each kept).
pub fn timed<C: Carry + Sync>(o: &Options, setup: &Setup, carry: &C) -> Timed {
    let (mut best, mut best_grey): (Option<Render>, Option<Render>) = (None, None);
    for _ in 0..3 {
        let s = render(setup, carry, o, (o.spp, o.threads), 1, None);
        let g = render(setup, &setup.grey, o, (o.spp, o.threads), 1, None);
        if best.as_ref().is_none_or(|b| s.seconds < b.seconds) {
            best = Some(s);
        }
        if best_grey.as_ref().is_none_or(|b| g.seconds < b.seconds) {
            best_grey = Some(g);
        }
    }
    let (Some(image), Some(grey)) = (best, best_grey) else { unreachable!("three runs") };
    Timed { image, grey }
}

/// The white the display shows as white: the scene's (its lights' whites
/// summed) times the 98th percentile of the pixels' Y over its Y, so the
/// walls are exposed and the lights blown out.
#[must_use]
pub fn display_white(xyz: &[Xyz], white: Xyz) -> Xyz {
    let mut ys: Vec<f64> = xyz.iter().map(|p| p.y / white.y).filter(|y| y.is_finite()).collect();
    ys.sort_by(f64::total_cmp);
    white * ys.get(ys.len() * 98 / 100).copied().filter(|&y| y > 0.0).unwrap_or(1.0)
}

/// Per-pixel ΔE00 of `image` against `exact`, in CIELAB relative to the
/// display white of the exact image: mean, 95th percentile, maximum, over
/// the pixels not brighter than that white (the lights left out).
#[must_use]
pub fn delta_e(image: &[Xyz], exact: &[Xyz], white: Xyz) -> [f64; 3] {
    let white = display_white(exact, white);
    let mut de: Vec<f64> = image
        .iter()
        .zip(exact)
        .filter(|(_, e)| e.y <= white.y)
        .map(|(&p, &e)| perceptual::delta_e00(p, e, white))
        .collect();
    de.sort_by(f64::total_cmp);
    let n = de.len().max(1);
    let mean = de.iter().sum::<f64>() / n as f64;
    [mean, de.get(n * 95 / 100).copied().unwrap_or(0.0), de.last().copied().unwrap_or(0.0)]
}

/// Renders the way `o` asks for with the exact image of its paths: the
/// render and its ΔE00 against the exact image ([`delta_e`]).
pub fn against_exact(o: &Options, setup: &Setup) -> Result<(Render, [f64; 3]), StudyError> {
    struct Compare<'a>(&'a Options, &'a Setup);
    impl WithCarry for Compare<'_> {
        type Out = (Render, [f64; 3]);
        fn go<C: Carry + Sync>(self, carry: &C) -> Self::Out {
            let (o, setup) = (self.0, self.1);
            let with_exact = render(setup, carry, o, (o.spp, o.threads), 1, Some(&setup.exact()));
            let de = delta_e(&with_exact.xyz, with_exact.exact.as_deref().unwrap_or_default(), setup.white);
            (with_exact, de)
        }
    }
    with_carry(o, setup, Compare(o, setup))
}

/// The RMS ΔE\*ab of `image` against a render of `n` paths per pixel
/// (CIELAB relative to its displayed white; pixels brighter than that
/// white, the lights, left out), the pixels compared, and the reference's
/// time, s.
#[must_use]
pub fn reference_error<C: Carry + Sync>(
    o: &Options,
    setup: &Setup,
    carry: &C,
    image: &Render,
    n: usize,
) -> (f64, usize, f64) {
    let truth = render(setup, carry, o, (n, o.threads), 2, None);
    let white = display_white(&truth.xyz, setup.white);
    let (mut sum, mut count) = (0.0, 0usize);
    for (p, t) in image.xyz.iter().zip(&truth.xyz) {
        if t.y <= white.y {
            let (l1, l2) = (lab(*p, white), lab(*t, white));
            sum += (0..3).map(|c| (l1[c] - l2[c]).powi(2)).sum::<f64>();
            count += 1;
        }
    }
    ((sum / count.max(1) as f64).sqrt(), count, truth.seconds)
}

/// What the exact image costs: ns more per path per thread than `seconds`
/// (the time of the render without it).
#[must_use]
pub fn exact_cost(o: &Options, with_exact: &Render, seconds: f64) -> f64 {
    let paths = o.width * o.height * o.spp;
    (with_exact.seconds - seconds).max(0.0) * 1e9 * o.threads as f64 / paths.max(1) as f64
}

/// `f`'s result and how long it took, s.
pub fn seconds<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64())
}
