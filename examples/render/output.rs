//! What `render` prints and writes: the time per vertex, the error against
//! the exact image of the same paths or against a reference render, and
//! the PNG.

use std::path::Path;

use speclab::Xyz;
use speclab::color::{Display, Exposure, GamutMap, lab::lab};

use crate::args::{Args, Mode};
use crate::tracer::Paint;
use crate::{Render, Setup, render};

/// What was rendered, the time per vertex of colour and grey, and the
/// colour's overhead.
pub fn report(a: &Args, s: &Render, g: &Render) {
    let per_vertex = |r: &Render| r.seconds * 1e9 * a.threads as f64 / r.vertices.max(1) as f64;
    let (ns_s, ns_g) = (per_vertex(s), per_vertex(g));
    let how = match a.mode {
        Mode::Rgb => "rgb triples".to_string(),
        Mode::Fitted => format!("a fitted rule of M = {}, {}", a.m, if a.single { "f32" } else { "f64" }),
        Mode::Hero => format!(
            "hero, pdf {}{}, strata {}, {} {} spectra",
            a.sampling.pdf,
            match (
                a.sampling.pdf.follows_light()
                    || a.sampling.pdf == speclab::sampling::choice::PdfKind::Visible,
                a.bins
            ) {
                (false, _) => String::new(),
                (true, Some(bins)) => format!(" ({bins} bins)"),
                (true, None) => " (exact)".into(),
            },
            a.sampling.strata,
            if a.dense { "dense" } else { "exact" },
            if a.single { "f32" } else { "f64" },
        ),
    };
    println!(
        "{} × {}, {} paths per pixel, light {}, {how}, {} threads",
        a.width,
        a.height,
        a.spp,
        a.light_names(),
        a.threads
    );
    println!("colour: {:.2} s, {} vertices, {ns_s:.1} ns per vertex per thread", s.seconds, s.vertices);
    println!("grey:   {:.2} s, {} vertices, {ns_g:.1} ns per vertex per thread", g.seconds, g.vertices);
    println!("colour's overhead: {:.0} % of the grey time per vertex", 100.0 * (ns_s - ns_g) / ns_g);
}

/// The white the display shows as white: the scene's (its lights' whites
/// summed) times the 98th percentile of the pixels' Y over its Y, so the
/// walls are exposed and the lights blown out.
pub fn display_white(xyz: &[Xyz], white: Xyz) -> Xyz {
    let mut ys: Vec<f64> = xyz.iter().map(|p| p.y / white.y).filter(|y| y.is_finite()).collect();
    ys.sort_by(f64::total_cmp);
    white * ys.get(ys.len() * 98 / 100).copied().filter(|&y| y > 0.0).unwrap_or(1.0)
}

/// Per-pixel ΔE00 of `image` against `exact`, in CIELAB relative to the
/// display white of the exact image: mean, 95th percentile, maximum, over
/// the pixels not brighter than that white (the lights left out).
#[cfg(feature = "study")]
pub fn delta_e(image: &[Xyz], exact: &[Xyz], white: Xyz) -> [f64; 3] {
    let white = display_white(exact, white);
    let mut de: Vec<f64> = image
        .iter()
        .zip(exact)
        .filter(|(_, e)| e.y <= white.y)
        .map(|(&p, &e)| speclab::study::evaluate::perceptual::delta_e00(p, e, white))
        .collect();
    de.sort_by(f64::total_cmp);
    let n = de.len().max(1);
    let mean = de.iter().sum::<f64>() / n as f64;
    [mean, de.get(n * 95 / 100).copied().unwrap_or(0.0), de.last().copied().unwrap_or(0.0)]
}

/// `--exact`: the render against the exact image of its own paths, and
/// what the exact image cost.
pub fn exact_report(a: &Args, setup: &Setup, with_exact: &Render, seconds: f64, prepared: f64) {
    let Some(exact) = &with_exact.exact else { return };
    let paths = a.width * a.height * a.spp;
    #[cfg(feature = "study")]
    {
        let [mean, p95, max] = delta_e(&with_exact.xyz, exact, setup.white);
        println!(
            "against the exact image of the same paths: ΔE00 mean {mean:.3}, 95th percentile {p95:.3}, max {max:.3}"
        );
    }
    #[cfg(not(feature = "study"))]
    let _ = (setup, exact);
    let extra = (with_exact.seconds - seconds).max(0.0) * 1e9 * a.threads as f64 / paths.max(1) as f64;
    println!(
        "the exact image: {:.0} ns more per path per thread (its quadrature prepared in {:.1} ms)",
        extra,
        prepared * 1e3
    );
}

/// With `--reference N`: renders N paths per pixel and prints the RMS ΔE*ab
/// of `image` against it (CIELAB relative to the displayed white; pixels
/// brighter than that white, the lights, left out).
pub fn reference_error<P: Paint>(a: &Args, setup: &Setup, paint: &P, image: &Render) {
    let Some(n) = a.reference else { return };
    let truth = render(&setup.scene, paint, a, (n, a.threads), 2, None);
    let white = display_white(&truth.xyz, setup.white);
    let (mut sum, mut count) = (0.0, 0usize);
    for (p, t) in image.xyz.iter().zip(&truth.xyz) {
        if t.y <= white.y {
            let (l1, l2) = (lab(*p, white), lab(*t, white));
            sum += (0..3).map(|c| (l1[c] - l2[c]).powi(2)).sum::<f64>();
            count += 1;
        }
    }
    println!(
        "RMS ΔE*ab against {n} paths per pixel ({:.1} s): {:.3} over {count} pixels",
        truth.seconds,
        (sum / count.max(1) as f64).sqrt()
    );
}

/// 8-bit sRGB of `xyz` through `color::display` (exposed to the display
/// white, chroma-reduced into the gamut).
pub fn srgb8(xyz: &[Xyz], white: Xyz, exposed_by: &[Xyz]) -> Vec<u8> {
    let display = Display::new(Exposure::fit_white(display_white(exposed_by, white)), GamutMap::Chroma);
    xyz.iter().flat_map(|p| display.pixel(p.to_linear_srgb()).to_array()).collect()
}

/// The image as an sRGB PNG.
pub fn write_png(out: &Path, width: usize, height: usize, xyz: &[Xyz], white: Xyz) -> std::io::Result<()> {
    write_rgb(out, width, height, &srgb8(xyz, white, xyz))
}

/// 8-bit RGB rows as a PNG.
pub fn write_rgb(out: &Path, width: usize, height: usize, rgb: &[u8]) -> std::io::Result<()> {
    let file = std::io::BufWriter::new(std::fs::File::create(out)?);
    let mut encoder = png::Encoder::new(file, width as u32, height as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
    writer.write_image_data(rgb).map_err(std::io::Error::other)?;
    writer.finish().map_err(std::io::Error::other)?;
    println!("wrote {}", out.display());
    Ok(())
}
