//! The render survey: every way of carrying colour on a scene (or on the
//! five standard scenes), each against the exact image of its own paths:
//! per-pixel ΔE00 (mean, 95th percentile, maximum) and the time per path
//! on one thread. Its rows have one CSV form ([`Row::CSV_HEADER`],
//! [`Row::csv`], [`parse`]), which the survey's picture reads.
//!
//! ```
//! use speclab_study::render::survey::{Row, parse};
//! let row = Row { scene: "F11".into(), way: "rgb".into(), spp: 4, ns_per_path: 950.0, de00: [1.0, 2.0, 3.0] };
//! let text = format!("{}\n{}\n", Row::CSV_HEADER, row.csv());
//! assert_eq!(parse(&text)?, vec![row]);
//! assert!(parse("scene,way\nF11,rgb\n").unwrap_err().starts_with("line 2: expected 7 fields"));
//! # Ok::<(), String>(())
//! ```

use crate::carry::Carry;
use crate::sampling::choice::{PdfKind, Sampling};
use crate::sampling::strata::Strata;
use speclab::Xyz;
use speclab::data::Light;
use speclab::spectrum::AssignmentObserver;

use crate::evaluate::Named;
use crate::render::run::{WithCarry, delta_e, hero, wavelength_pdf, with_carry};
use crate::render::{Options, Render, Setup, Way, render};

/// Hero's paths per pixel in the survey.
pub const HERO_SPP: [usize; 5] = [4, 8, 16, 32, 64];
/// The fitted rules' sizes in the survey.
pub const FITTED_M: [usize; 6] = [4, 6, 8, 10, 12, 16];

/// One way on one scene: what it is, and how it did.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The scene's lights, e.g. `F11 + A`.
    pub scene: String,
    /// The way: `rgb`, `fitted M=10`, `hero uniform/jitter`.
    pub way: String,
    /// Paths per pixel.
    pub spp: usize,
    /// ns per path on one thread.
    pub ns_per_path: f64,
    /// Per-pixel ΔE00 against the exact image: mean, 95th percentile,
    /// maximum.
    pub de00: [f64; 3],
}

impl Row {
    /// The CSV header of [`Row::csv`].
    pub const CSV_HEADER: &str = "scene,way,spp,ns_per_path,de00_mean,de00_p95,de00_max";

    /// The row as one CSV line (full precision).
    #[must_use]
    pub fn csv(&self) -> String {
        let [mean, p95, max] = self.de00;
        format!("{},{},{},{},{mean},{p95},{max}", self.scene, self.way, self.spp, self.ns_per_path)
    }

    /// Time per pixel, ns (one thread).
    #[must_use]
    pub fn ns_per_pixel(&self) -> f64 {
        self.ns_per_path * self.spp as f64
    }
}

/// The rows of the survey's CSV ([`Row::CSV_HEADER`] first); an error
/// names the line and what was expected there.
pub fn parse(csv: &str) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for (i, line) in csv.lines().enumerate().skip(1).filter(|(_, l)| !l.trim().is_empty()) {
        let at = |what: &str| format!("line {}: expected {what}, found {line:?}", i + 1);
        let f: Vec<&str> = line.split(',').collect();
        if f.len() != 7 {
            return Err(at(&format!("7 fields ({})", Row::CSV_HEADER)));
        }
        let number = |s: &str| s.parse::<f64>().ok().filter(|v| v.is_finite() && *v >= 0.0);
        let (Some(spp), Some(ns)) = (f[2].parse().ok(), number(f[3])) else {
            return Err(at("a path count and a time"));
        };
        let (Some(mean), Some(p95), Some(max)) = (number(f[4]), number(f[5]), number(f[6])) else {
            return Err(at("three ΔE00 values"));
        };
        rows.push(Row { scene: f[0].into(), way: f[1].into(), spp, ns_per_path: ns, de00: [mean, p95, max] });
    }
    Ok(rows)
}

/// A row and its images: the render and the exact image of its paths.
#[derive(Clone, Debug)]
pub struct Measured {
    /// What it is and how it did.
    pub row: Row,
    /// The render.
    pub image: Vec<Xyz>,
    /// The exact image of the same paths.
    pub exact: Vec<Xyz>,
}

/// The five standard scenes: A, D65, F11 and `led` each alone, and F11
/// with A.
#[must_use]
pub fn standard_scenes(led: Named) -> Vec<Vec<Named>> {
    let named = Named::from;
    vec![
        vec![named(Light::A)],
        vec![named(Light::D65)],
        vec![named(Light::F11)],
        vec![led],
        vec![named(Light::F11), named(Light::A)],
    ]
}

/// Times a way on one thread (the faster of two runs), then renders it
/// again with the exact image of the same paths and measures the
/// difference.
struct Measure<'a> {
    o: &'a Options,
    setup: &'a Setup,
    spp: usize,
}

impl WithCarry for Measure<'_> {
    type Out = (f64, [f64; 3], Render);

    fn go<C: Carry + Sync>(self, carry: &C) -> Self::Out {
        let (o, setup, spp) = (self.o, self.setup, self.spp);
        let paths = (o.width * o.height * spp).max(1) as f64;
        let timed = (0..2)
            .map(|_| render(setup, carry, o, (spp, 1), 1, None).seconds * 1e9 / paths)
            .fold(f64::INFINITY, f64::min);
        let exact = setup.exact();
        let with_exact = render(setup, carry, o, (spp, o.threads), 1, Some(&exact));
        let de = delta_e(&with_exact.xyz, with_exact.exact.as_deref().unwrap_or_default(), setup.white);
        (timed, de, with_exact)
    }
}

/// Every way on one scene, `o` giving the image's size, the paths per
/// pixel of rgb and fitted, and the threads of the exact renders; `each`
/// sees every row as it is measured.
pub fn survey(
    o: &Options,
    setup: &Setup,
    mut each: impl FnMut(&Measured),
) -> Result<Vec<Measured>, crate::StudyError> {
    let scene = setup.light_names();
    let mut rows = Vec::new();
    let mut push = |way: String, spp: usize, (ns, de, r): (f64, [f64; 3], Render)| {
        let row = Row { scene: scene.clone(), way, spp, ns_per_path: ns, de00: de };
        let measured = Measured { row, image: r.xyz, exact: r.exact.unwrap_or_default() };
        each(&measured);
        rows.push(measured);
    };
    let measure = |spp| Measure { o, setup, spp };
    push("rgb".into(), o.spp, with_carry(&Options { way: Way::Rgb, ..o.clone() }, setup, measure(o.spp))?);
    let prefilter = Options { way: Way::Prefilter, ..o.clone() };
    push("prefilter".into(), o.spp, with_carry(&prefilter, setup, measure(o.spp))?);
    for m in FITTED_M {
        let fitted = Options { way: Way::Fitted, m, ..o.clone() };
        push(format!("fitted M={m}"), o.spp, with_carry(&fitted, setup, measure(o.spp))?);
    }
    for pdf in [PdfKind::Uniform, PdfKind::Light] {
        let hero_o = Options { sampling: Sampling { pdf, strata: Strata::Jittered }, ..o.clone() };
        for spp in HERO_SPP {
            let density = wavelength_pdf(&hero_o, setup)?;
            let carry = hero::<_, _, f64>(
                setup,
                setup.light_spectra(),
                setup.patches.clone(),
                AssignmentObserver,
                density,
            )?;
            push(format!("hero {pdf}/jitter"), spp, measure(spp).go(&carry));
        }
    }
    Ok(rows)
}
