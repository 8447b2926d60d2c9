//! The fitted rules' picture: per light, its spectrum with the rule's
//! wavelengths marked (and the centres of as many equidistant buckets as
//! ticks below, for comparison), and under it the rule's X, Y and Z
//! weights at each wavelength as stems. Drawn by `plotters` into SVG.

use plotters::coord::Shift;
use plotters::prelude::*;
use speclab::sampling::rule::Rule;
use speclab::{LAMBDA_MAX, LAMBDA_MIN, LAMBDA_WIDTH, Spectrum};

/// One light: its name, spectrum and rule.
pub struct Panel<'a> {
    /// The light's name.
    pub name: String,
    /// The light.
    pub light: &'a dyn Spectrum,
    /// The rule fitted to it.
    pub rule: Rule,
}

const COLUMN: (u32, u32) = (520, 620);
const TITLE: u32 = 44;
/// Stem colours for X, Y, Z.
const CHANNELS: [RGBColor; 3] = [RGBColor(214, 39, 40), RGBColor(44, 160, 44), RGBColor(31, 119, 180)];

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// The picture as SVG text.
pub fn svg(panels: &[Panel]) -> Result<String, String> {
    let err = |e: DrawingAreaErrorKind<std::io::Error>| e.to_string();
    let width = COLUMN.0 * panels.len().max(1) as u32;
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, (width, TITLE + COLUMN.1)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (title, rest) = root.split_vertically(TITLE);
        let m = panels.first().map_or(0, |p| p.rule.m());
        let heading = format!(
            "Rules of M = {m} wavelengths fitted to each light: where they sit, and their X, Y, Z weights"
        );
        title.titled(&heading, ("sans-serif", 20)).map_err(err)?;
        for (area, panel) in rest.split_evenly((1, panels.len().max(1))).iter().zip(panels) {
            column(area, panel)?;
        }
        root.present().map_err(err)?;
    }
    Ok(text)
}

/// One light's column: spectrum above, weights below.
fn column(area: &Area, p: &Panel) -> Result<(), String> {
    let err = |e: DrawingAreaErrorKind<std::io::Error>| e.to_string();
    let (top, bottom) = area.split_vertically(COLUMN.1 * 11 / 20);
    let samples: Vec<(f64, f64)> =
        (0..=700).map(|i| LAMBDA_MIN + 0.5 * f64::from(i)).map(|l| (l, p.light.eval(l))).collect();
    let peak = samples.iter().map(|s| s.1).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let mut chart = ChartBuilder::on(&top)
        .caption(format!("Light {}", p.name), ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(30)
        .y_label_area_size(50)
        .build_cartesian_2d(LAMBDA_MIN..LAMBDA_MAX, -0.08..1.05)
        .map_err(err)?;
    chart
        .configure_mesh()
        .y_desc("power (peak = 1)")
        .label_style(("sans-serif", 13))
        .light_line_style(RGBColor(242, 242, 242))
        .draw()
        .map_err(err)?;
    let grey = RGBColor(110, 110, 110);
    chart
        .draw_series(LineSeries::new(samples.iter().map(|&(l, v)| (l, v / peak)), grey.stroke_width(2)))
        .map_err(err)?;
    let marker = RGBColor(0, 0, 0);
    for &l in p.rule.lambda() {
        chart
            .draw_series(LineSeries::new([(l, 0.0), (l, 1.0)], marker.mix(0.55).stroke_width(1)))
            .map_err(err)?;
        chart.draw_series([Circle::new((l, p.light.eval(l) / peak), 4, marker.filled())]).map_err(err)?;
    }
    // The centres of M equidistant buckets, as ticks below the axis.
    let m = p.rule.m();
    let centres = (0..m).map(|i| LAMBDA_MIN + (i as f64 + 0.5) * LAMBDA_WIDTH / m as f64);
    let tick = RGBColor(230, 120, 20).stroke_width(2);
    for c in centres {
        chart.draw_series(LineSeries::new([(c, -0.07), (c, -0.02)], tick)).map_err(err)?;
    }
    weights(&bottom, p)
}

/// The weights as stems, X, Y and Z side by side at each wavelength.
fn weights(area: &Area, p: &Panel) -> Result<(), String> {
    let err = |e: DrawingAreaErrorKind<std::io::Error>| e.to_string();
    let (w, _) = p.rule.weights();
    let most = w.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs())).max(f64::MIN_POSITIVE);
    let (lo, hi) = (w.iter().flatten().fold(0.0f64, |a, &v| a.min(v)) / most, 1.0);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(LAMBDA_MIN..LAMBDA_MAX, (lo - 0.05).min(-0.05)..hi + 0.05)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("wavelength, nm")
        .y_desc("weight (largest = 1)")
        .label_style(("sans-serif", 13))
        .light_line_style(RGBColor(242, 242, 242))
        .draw()
        .map_err(err)?;
    for (i, &l) in p.rule.lambda().iter().enumerate() {
        for (c, colour) in CHANNELS.iter().enumerate() {
            let x = l + (c as f64 - 1.0) * 1.8;
            let v = w[c][i] / most;
            chart.draw_series(LineSeries::new([(x, 0.0), (x, v)], colour.stroke_width(3))).map_err(err)?;
        }
    }
    let font = ("sans-serif", 13).into_font();
    for (c, (colour, name)) in CHANNELS.iter().zip(["X", "Y", "Z"]).enumerate() {
        let at = (LAMBDA_MAX - 60.0 + 20.0 * c as f64, hi - 0.02);
        chart.draw_series([Text::new(name, at, font.clone().color(colour))]).map_err(err)?;
    }
    Ok(())
}
