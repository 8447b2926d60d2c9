//! The chart's drawing: one log–log panel per light (ns per estimate against
//! worst-patch RMS ΔE00), one curve per method with sample counts at chosen
//! points, the Pareto front as a thick grey line, budget guides, and a
//! legend below the panels. Drawn by `plotters` into SVG; rendered to PNG by
//! `resvg`.

use plotters::coord::Shift;
use plotters::prelude::*;
use speclab::sampling::buckets::BucketRule;
use speclab_study::evaluate::method::Method;
use speclab_study::planning::chart::Point;
use speclab_study::published::rules::Family;

/// Panel and legend sizes, px.
const PANEL: (u32, u32) = (620, 560);
const LEGEND_HEIGHT: u32 = 140;
const TITLE_HEIGHT: u32 = 50;

/// A curve's look: colour, whether its markers are triangles, and its label.
struct Look {
    colour: RGBColor,
    triangle: bool,
    label: String,
}

/// Colours told apart by most readers (Tableau 10, then darker extras), in
/// the order of the curves; the reference is black.
const PALETTE: [RGBColor; 15] = [
    RGBColor(127, 127, 127),
    RGBColor(31, 119, 180),
    RGBColor(23, 190, 207),
    RGBColor(227, 119, 194),
    RGBColor(148, 103, 189),
    RGBColor(214, 39, 40),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(140, 86, 75),
    RGBColor(188, 189, 34),
    RGBColor(0, 0, 128),
    RGBColor(128, 0, 0),
    RGBColor(0, 128, 128),
    RGBColor(204, 153, 0),
    RGBColor(64, 64, 64),
];

/// The look of the `index`-th curve, `method`.
fn look(method: Method, index: usize) -> Look {
    let colour = match method {
        Method::Reference => RGBColor(0, 0, 0),
        _ => PALETTE[index.saturating_sub(1) % PALETTE.len()],
    };
    let label = match method {
        Method::Reference => "reference (exact: ΔE00 0, drawn on the axis)".to_string(),
        Method::Buckets { rule: BucketRule::Center } => "regular, center of M buckets".to_string(),
        Method::Buckets { rule: BucketRule::BoxAverage } => "regular, box mean of M buckets".to_string(),
        Method::Fitted => "fitted: M wavelengths and weights fitted to the light".to_string(),
        Method::Published { family: Family::Astm } => {
            "astm: E308/E2022 weights every ⌊350/(M − 1)⌋ nm".to_string()
        }
        Method::Published { family } => format!("{family}: a published rule of M wavelengths"),
        Method::Prefiltered { space } => format!("prefilter-{space}: three numbers per surface (Ward 2002)"),
        m => format!("{m} {}", m.sampling().unwrap_or_default()),
    };
    let triangle = method.is_fixed();
    Look { colour, triangle, label }
}

/// The methods of `points`, in their order: a method's index here picks its
/// colour in every panel and the legend.
fn methods<'a>(points: impl IntoIterator<Item = &'a Point>) -> Vec<Method> {
    let mut out: Vec<Method> = Vec::new();
    for p in points {
        if !out.contains(&p.config.method) {
            out.push(p.config.method);
        }
    }
    out
}

/// Whether count `n` of `method` gets a label beside its point: the last
/// (and M = 32 for buckets); every curve starts at 1 and doubles n.
fn labelled(method: Method, n: usize, last: usize) -> bool {
    match method {
        Method::Reference => false,
        Method::Buckets { .. } | Method::Fitted | Method::Published { .. } => n == 32 || n == last,
        Method::Prefiltered { .. } => true,
        _ => n == last,
    }
}

/// The count whose point is ringed: 16, a renderer-like n (and M).
const RINGED: usize = 16;

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type Failure = String;

/// The whole chart as SVG text.
pub fn svg(points: &[Point], trials: usize) -> Result<String, Failure> {
    let mut lights: Vec<&str> = Vec::new();
    for p in points {
        if !lights.contains(&p.light.as_str()) {
            lights.push(&p.light);
        }
    }
    let width = PANEL.0 * lights.len().max(1) as u32;
    let mut text = String::new();
    {
        let root = SVGBackend::with_string(&mut text, (width, TITLE_HEIGHT + PANEL.1 + LEGEND_HEIGHT))
            .into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (title, rest) = root.split_vertically(TITLE_HEIGHT);
        let (panels, legend) = rest.split_vertically(PANEL.1);
        let heading = format!(
            "Speed against accuracy: ns per estimate (measured, one thread) vs worst RMS ΔE00 over 6 patches ({trials} trials)"
        );
        title.titled(&heading, ("sans-serif", 20)).map_err(|e| e.to_string())?;
        let areas = panels.split_evenly((1, lights.len().max(1)));
        let (ranges, order) = (ranges(points), methods(points));
        for (area, light) in areas.iter().zip(&lights) {
            let mine: Vec<&Point> = points.iter().filter(|p| p.light == *light).collect();
            panel(area, light, &mine, &order, ranges)?;
        }
        draw_legend(&legend, &order)?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(text)
}

/// The smallest ΔE00 the y axis shows.
const FLOOR: f64 = 1e-4;

/// The x (ns) and y (ΔE00) ranges shared by every panel: whole decades.
fn ranges(points: &[Point]) -> ((f64, f64), (f64, f64)) {
    let decade_below = |v: f64| 10f64.powf(v.log10().floor());
    let decade_above = |v: f64| 10f64.powf(v.log10().ceil());
    let xs = points.iter().map(|p| p.cost.per_estimate_ns).filter(|x| *x > 0.0);
    let (x0, x1) = xs.fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    let y1 = points.iter().map(|p| p.worst_rms).fold(1.0f64, f64::max);
    // The smallest error above 0 sets the floor, but not below FLOOR; the
    // reference (exactly 0) and what is exact to rounding (prefiltering at
    // one bounce, ASTM on tables of its own step) are drawn on it.
    let y0 = points.iter().map(|p| p.worst_rms).filter(|y| *y > 0.0).fold(0.1f64, f64::min).max(FLOOR);
    let x = if x0 < x1 { (decade_below(x0), decade_above(x1)) } else { (1.0, 1e6) };
    (x, (decade_below(y0), decade_above(y1)))
}

/// One light's panel.
fn panel(
    area: &Area,
    light: &str,
    points: &[&Point],
    order: &[Method],
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
) -> Result<(), Failure> {
    let err = |e: DrawingAreaErrorKind<_>| e.to_string();
    let mut chart = ChartBuilder::on(area)
        .caption(format!("Light {light}"), ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(58)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("ns per estimate")
        .y_desc("worst RMS ΔE00")
        .x_label_formatter(&|x| short(*x))
        .y_label_formatter(&|y| short(*y))
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(RGBColor(242, 242, 242))
        .draw()
        .map_err(err)?;
    // The Pareto front first, so the curves are drawn over it.
    let mut front: Vec<(f64, f64)> =
        points.iter().filter(|p| p.pareto).map(|p| (p.cost.per_estimate_ns, p.worst_rms.max(y0))).collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let grey = RGBColor(60, 60, 60).mix(0.35);
    chart.draw_series(LineSeries::new(front, grey.stroke_width(9))).map_err(err)?;
    for budget in [1.0, 0.5] {
        let style = RGBColor(90, 90, 90).stroke_width(1);
        chart.draw_series(DashedLineSeries::new([(x0, budget), (x1, budget)], 6, 4, style)).map_err(err)?;
        let at = (x0 * 1.15, budget * 1.12);
        chart.draw_series([Text::new(format!("ΔE00 {budget}"), at, ("sans-serif", 13))]).map_err(err)?;
    }
    for (index, &method) in order.iter().enumerate() {
        let curve: Vec<&&Point> = points.iter().filter(|p| p.config.method == method).collect();
        curve_series(&mut chart, look(method, index), method, &curve, y0).map_err(err)?;
    }
    let reference = points.iter().filter(|p| p.config.method == Method::Reference);
    let font = ("sans-serif", 13).into_font();
    let labels =
        reference.map(|p| Text::new("reference", (p.cost.per_estimate_ns * 1.3, y0 * 1.6), font.clone()));
    chart.draw_series(labels).map_err(err)?;
    Ok(())
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// One method's line, markers and count labels.
fn curve_series(
    chart: &mut Chart,
    look: Look,
    method: Method,
    curve: &[&&Point],
    y0: f64,
) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
    let xy: Vec<(f64, f64)> = curve.iter().map(|p| (p.cost.per_estimate_ns, p.worst_rms.max(y0))).collect();
    let style = look.colour.stroke_width(2);
    chart.draw_series(LineSeries::new(xy.clone(), style))?;
    if look.triangle {
        chart.draw_series(xy.iter().map(|&c| TriangleMarker::new(c, 4, look.colour.filled())))?;
    } else {
        chart.draw_series(xy.iter().map(|&c| Circle::new(c, 3, look.colour.filled())))?;
    }
    let ringed = curve.iter().zip(&xy).filter(|(p, _)| p.config.count.get() == RINGED);
    chart.draw_series(ringed.map(|(_, &c)| Circle::new(c, 7, look.colour.stroke_width(2))))?;
    let text = ("sans-serif", 13).into_font().color(&look.colour);
    let last = curve.iter().map(|p| p.config.count.get()).max().unwrap_or(0);
    let labels = curve.iter().zip(&xy).filter(|(p, _)| labelled(method, p.config.count.get(), last));
    chart.draw_series(labels.map(|(p, &(x, y))| {
        let label = match method {
            Method::Prefiltered { .. } => "prefilter".to_string(),
            m if m.is_fixed() => format!("M{}", p.config.count),
            _ => format!("n{}", p.config.count),
        };
        Text::new(label, (x * 1.08, y * 1.04), text.clone())
    }))?;
    Ok(())
}

/// The legend: one entry per method, in rows below the panels.
fn draw_legend(area: &Area, order: &[Method]) -> Result<(), Failure> {
    let (width, _) = area.dim_in_pixel();
    let columns = 4usize;
    let cell = (width as i32 - 40) / columns as i32;
    let font = ("sans-serif", 14).into_font();
    for (i, &method) in order.iter().enumerate() {
        let look = look(method, i);
        let (x, y) = (20 + (i % columns) as i32 * cell, 14 + (i / columns) as i32 * 24);
        let line = PathElement::new([(x, y), (x + 26, y)], look.colour.stroke_width(3));
        area.draw(&line).map_err(|e| e.to_string())?;
        area.draw(&Text::new(look.label, (x + 34, y - 8), font.clone())).map_err(|e| e.to_string())?;
    }
    let note = "points: n = 1, 2, 4, … 1024 samples (random: 1 wavelength each, hero: 4), M = 1 … 64 buckets or wavelengths; \
                ring: n = 16 or M = 16. Thick grey: the Pareto front (nothing else is both faster and more \
                accurate). Dashed: budgets. Errors below 1e-4 (exact) are drawn on the axis.";
    let rows = order.len().div_ceil(columns) as i32;
    area.draw(&Text::new(note, (20, 14 + rows * 24), font)).map_err(|e| e.to_string())
}

/// A tick label: 1, 10, 100, 1k, 10k, 1M; 0.1, 0.01.
pub(crate) fn short(v: f64) -> String {
    match v {
        v if v >= 1e6 => format!("{}M", v / 1e6),
        v if v >= 1e3 => format!("{}k", v / 1e3),
        v if v >= 1.0 => format!("{v}"),
        v => format!("{}", (v * 1e6).round() / 1e6),
    }
}

/// The SVG rendered to PNG with the system's fonts (an error if it has
/// none: the labels would be missing).
pub fn png(svg: &str) -> Result<Vec<u8>, Failure> {
    use resvg::{tiny_skia, usvg};
    let mut options = usvg::Options::default();
    let fonts = options.fontdb_mut();
    fonts.load_system_fonts();
    let family =
        fonts.faces().flat_map(|f| f.families.iter().map(|(n, _)| n.clone())).find(|n| n == "DejaVu Sans");
    match family {
        Some(f) => fonts.set_sans_serif_family(f),
        None if fonts.is_empty() => return Err("no system fonts to draw the labels with".into()),
        None => {}
    }
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| e.to_string())?;
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height()).ok_or("empty image")?;
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| e.to_string())
}
