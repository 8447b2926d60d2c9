//! What `render` prints and writes: the time per vertex of each mode, the
//! error against a reference render, and the PNG.

use speclab::Xyz;
use speclab::color::{Display, Exposure, GamutMap, lab::lab};
use speclab::sampling::reference;

use crate::tracer::Paint;
use crate::{Args, PdfChoice, Render, render};

/// The time per vertex of each mode, and the spectral overhead.
pub fn report(a: &Args, s: &Render, g: &Render) {
    let per_vertex = |r: &Render| r.seconds * 1e9 * a.threads as f64 / r.vertices.max(1) as f64;
    let (ns_s, ns_g) = (per_vertex(s), per_vertex(g));
    println!(
        "{} × {}, {} paths per pixel, light {}, pdf {:?}{}, strata {}, {} spectra, {} threads",
        a.width,
        a.height,
        a.spp,
        a.light_name,
        a.pdf,
        match (a.pdf, a.bins) {
            (PdfChoice::Uniform, _) => String::new(),
            (_, Some(bins)) => format!(" ({bins} bins)"),
            (_, None) => " (exact)".into(),
        },
        a.strata,
        match (a.dense, a.single) {
            (false, false) => "exact f64",
            (false, true) => "exact f32",
            (true, false) => "dense f64",
            (true, true) => "dense f32",
        },
        a.threads
    );
    println!("spectral: {:.2} s, {} vertices, {ns_s:.1} ns per vertex per thread", s.seconds, s.vertices);
    println!("grey:     {:.2} s, {} vertices, {ns_g:.1} ns per vertex per thread", g.seconds, g.vertices);
    println!("spectral overhead: {:.0} % of the grey time per vertex", 100.0 * (ns_s - ns_g) / ns_g);
}

/// With `--reference N`: renders N paths per pixel and prints the RMS ΔE*ab
/// of `image` against it (CIELAB relative to the displayed white; pixels
/// brighter than that white, the light itself, left out). Returns `image`.
pub fn reference_error<P: Paint>(a: &Args, paint: &P, image: Render) -> Render {
    let Some(n) = a.reference else { return image };
    let truth = render(&crate::scene(), paint, a, n, 2);
    let white = reference::white(&a.light) * exposure_scale(&truth.xyz, reference::white(&a.light));
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
    image
}

/// The factor on the light's white that the display shows as white: the
/// 98th percentile of the pixels' Y over the white's, so the walls are
/// exposed and the light itself is blown out.
fn exposure_scale(xyz: &[Xyz], white: Xyz) -> f64 {
    let mut ys: Vec<f64> = xyz.iter().map(|p| p.y / white.y).filter(|y| y.is_finite()).collect();
    ys.sort_by(f64::total_cmp);
    ys.get(ys.len() * 98 / 100).copied().filter(|&y| y > 0.0).unwrap_or(1.0)
}

pub fn write_png(a: &Args, xyz: &[Xyz], white: Xyz) -> std::io::Result<()> {
    let display = Display::new(Exposure::fit_white(white * exposure_scale(xyz, white)), GamutMap::Chroma);
    let rgb: Vec<u8> = xyz.iter().flat_map(|p| display.pixel(p.to_linear_srgb()).to_array()).collect();
    let out = std::io::BufWriter::new(std::fs::File::create(&a.out)?);
    let mut encoder = png::Encoder::new(out, a.width as u32, a.height as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
    writer.write_image_data(&rgb).map_err(std::io::Error::other)?;
    writer.finish().map_err(std::io::Error::other)?;
    println!("wrote {}", a.out.display());
    Ok(())
}
