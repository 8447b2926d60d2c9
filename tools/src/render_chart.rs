//! The render survey's picture: one log–log panel per scene, each way of
//! carrying colour as a curve of time per pixel (ns per path on one thread
//! times paths per pixel) against the 95th-percentile pixel ΔE00 from the
//! exact image of the same paths, with a thin bar from the mean to the
//! maximum at each point, and guides at ΔE00 0.5 and 1. Read from the CSV
//! that `render --survey --csv` writes.

use plotters::prelude::*;

use crate::chart::short;

pub use speclab_study::render::survey::{Row, parse};

/// The curve a row belongs to: fitted rules of every M make one, a hero
/// pdf's counts one.
fn curve_of(row: &Row) -> &str {
    row.way.split(" M=").next().unwrap_or(&row.way)
}

/// The label beside a row's point: M for fitted rules, the count for hero.
fn label(row: &Row) -> String {
    match row.way.split_once(" M=") {
        Some((_, m)) => format!("M{m}"),
        None if row.way == "rgb" || row.way == "prefilter" => row.way.clone(),
        None => format!("{}", row.spp),
    }
}

/// Panel size, px.
const PANEL: (u32, u32) = (520, 470);

/// The curves' colours, in order of first appearance.
const PALETTE: [RGBColor; 6] = [
    RGBColor(0, 0, 0),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
];

fn order<'a>(items: impl Iterator<Item = &'a str>) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for s in items {
        if !out.contains(&s) {
            out.push(s);
        }
    }
    out
}

/// The whole picture as SVG text: three panels to a row.
pub fn svg(rows: &[Row]) -> Result<String, String> {
    let scenes = order(rows.iter().map(|r| r.scene.as_str()));
    let curves = order(rows.iter().map(curve_of));
    let columns = scenes.len().clamp(1, 3);
    let lines = scenes.len().div_ceil(columns).max(1);
    let size = (PANEL.0 * columns as u32, 60 + PANEL.1 * lines as u32);
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (title, rest) = root.split_vertically(60);
        let heading = "Rendered images: time per pixel (one thread) vs pixel ΔE00 from the exact image of the same paths";
        title.titled(heading, ("sans-serif", 19)).map_err(|e| e.to_string())?;
        let note =
            "points: 95th percentile; bars: mean to maximum; labels: M (fitted) or paths per pixel (hero)";
        title.draw(&Text::new(note, (12, 36), ("sans-serif", 14))).map_err(|e| e.to_string())?;
        let (x, y) = ranges(rows);
        for (area, scene) in rest.split_evenly((lines, columns)).iter().zip(&scenes) {
            let mine: Vec<&Row> = rows.iter().filter(|r| r.scene == *scene).collect();
            panel(area, scene, &mine, &curves, (x, y)).map_err(|e| e.to_string())?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(text)
}

/// Shared whole-decade ranges: time per pixel, and ΔE00 (down to 0.01).
fn ranges(rows: &[Row]) -> ((f64, f64), (f64, f64)) {
    let below = |v: f64| 10f64.powf(v.log10().floor());
    let above = |v: f64| 10f64.powf(v.log10().ceil());
    let xs = rows.iter().map(Row::ns_per_pixel).filter(|x| *x > 0.0);
    let (x0, x1) = xs.fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    let y0 = rows.iter().map(|r| r.de00[0]).filter(|y| *y > 0.0).fold(1.0f64, f64::min).max(0.001);
    let y1 = rows.iter().map(|r| r.de00[2]).fold(1.0f64, f64::max);
    let x = if x0 < x1 { (below(x0), above(x1)) } else { (1.0, 1e6) };
    (x, (below(y0), above(y1)))
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    scene: &str,
    rows: &[&Row],
    curves: &[&str],
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let mut chart = ChartBuilder::on(area)
        .caption(format!("Light {scene}"), ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(52)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("ns per pixel")
        .y_desc("pixel ΔE00")
        .x_label_formatter(&|x| short(*x))
        .y_label_formatter(&|y| short(*y))
        .label_style(("sans-serif", 13))
        .light_line_style(RGBColor(242, 242, 242))
        .draw()?;
    for budget in [1.0, 0.5] {
        let style = RGBColor(90, 90, 90).stroke_width(1);
        chart.draw_series(DashedLineSeries::new([(x0, budget), (x1, budget)], 6, 4, style))?;
    }
    for (i, curve) in curves.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let mine: Vec<&&Row> = rows.iter().filter(|r| curve_of(r) == *curve).collect();
        let at = |r: &Row, k: usize| (r.ns_per_pixel(), r.de00[k].max(y0));
        chart
            .draw_series(LineSeries::new(mine.iter().map(|r| at(r, 1)), colour.stroke_width(2)))?
            .label(*curve)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour.stroke_width(3)));
        let bars =
            mine.iter().map(|r| PathElement::new([at(r, 0), at(r, 2)], colour.mix(0.45).stroke_width(1)));
        chart.draw_series(bars)?;
        chart.draw_series(mine.iter().map(|r| Circle::new(at(r, 1), 3, colour.filled())))?;
        let font = ("sans-serif", 12).into_font().color(&colour);
        let labels = mine
            .iter()
            .map(|r| Text::new(label(r), (r.ns_per_pixel() * 1.06, r.de00[1].max(y0) * 1.05), font.clone()));
        chart.draw_series(labels)?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(200, 200, 200))
        .draw()
}
