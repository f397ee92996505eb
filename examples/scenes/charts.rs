//! SVG charts (plotters, SVG backend only): work-precision curves and stability maps.
//!
//! Every chart is drawn by [`frame`]: log–log axes with a tick label on every decade (and on 2
//! and 5 when an axis spans less than two decades), the axis titles with their units, an
//! optional second x axis on top (Δt as a fraction of the scene's period), the legend in a panel
//! to the right of the data (never over a point), and notes under the plot (overlapping curves,
//! the highlighted points the docs quote, the machine the times were taken on).

use std::path::Path;

use plotters::chart::MeshStyle;
use plotters::coord::combinators::{BindKeyPoints, LogCoord, WithKeyPoints};
use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;

use crate::oscillator::Oscillator;
use crate::rate_map::{RateCell, RateMap};
use crate::scene::Point;
use crate::stability::{Cell, Map};
use crate::velocity::RateLaw;

/// The series colours, in order (matplotlib's "tab10").
pub const COLORS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

/// Range of positive finite values, widened to whole decades with at least a tenth of a
/// decade to spare at each end.
pub fn decades(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for v in values.filter(|v| v.is_finite() && *v > 0.0) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (1e-3, 1.0);
    }
    // A tenth of a decade of room, so that no curve lies on an axis.
    let (a, b) = ((lo.log10() - 0.1).floor(), (hi.log10() + 0.1).ceil());
    (10f64.powf(a), 10f64.powf(b.max(a + 1.0)))
}

/// Tick values of a log axis over [lo, hi]: every decade, plus 2 and 5 times each decade when
/// the axis spans less than two decades; and the light grid lines 2..9 × each decade.
pub fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let (a, b) = (lo.log10().floor() as i32 - 1, hi.log10().ceil() as i32 + 1);
    let inside = |v: f64| v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
    let few = hi / lo < 500.0;
    let mut bold = Vec::new();
    let mut light = Vec::new();
    for e in a..=b {
        let d = 10f64.powi(e);
        for m in 1..10 {
            let v = d * f64::from(m);
            if !inside(v) {
                continue;
            }
            if m == 1 || (few && (m == 2 || m == 5)) {
                bold.push(v);
            } else {
                light.push(v);
            }
        }
    }
    (bold, light)
}

/// A tick label: 1e-3 style, with the mantissa only when it is not 1; plain for 0.1..1000.
pub fn tick_label(v: f64) -> String {
    if (0.1..1000.0).contains(&v) {
        let s = format!("{v:.1}");
        return s.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    let e = v.log10().floor() as i32;
    let m = (v / 10f64.powi(e)).round() as i32;
    if m == 1 {
        format!("1e{e}")
    } else {
        format!("{m}e{e}")
    }
}

/// One legend entry, drawn in the panel right of the plot.
pub enum Swatch {
    /// A line in a colour with a marker on it (dashed when `true`).
    Line(RGBColor, Marker, bool),
    /// A filled box (a map class).
    Box(RGBColor),
    /// A marker alone.
    Mark(RGBColor, Marker),
}

/// Point markers.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// Filled circle.
    Dot,
    /// Hollow circle, larger (drawn over a coinciding curve's dots).
    Ring,
    /// A larger hollow circle (a second coinciding curve).
    BigRing,
    /// Cross (a run that did not end "ok").
    Cross,
    /// Filled triangle (a run with no error to show).
    Triangle,
    /// None.
    None,
}

/// Axis title with its unit.
pub struct Axis {
    /// Range (log scale).
    pub range: (f64, f64),
    /// Title, with the unit.
    pub title: String,
}

impl Axis {
    pub fn new(range: (f64, f64), title: impl Into<String>) -> Axis {
        Axis {
            range,
            title: title.into(),
        }
    }
}

/// A chart's fixed parts.
pub struct Frame<'a> {
    /// Caption.
    pub title: &'a str,
    /// x axis.
    pub x: Axis,
    /// y axis.
    pub y: Axis,
    /// A second x axis on top: the bottom value divided by `scale`, with its title.
    pub top: Option<(f64, String)>,
    /// Legend panel entries.
    pub legend: Vec<(Swatch, String)>,
    /// Notes under the plot, one line each.
    pub notes: Vec<String>,
    /// Pixel size.
    pub size: (u32, u32),
}

type LogAxis = WithKeyPoints<LogCoord<f64>>;
/// The plotting context every chart body draws into.
pub type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogAxis, LogAxis>>;

fn log_axis(lo: f64, hi: f64) -> LogAxis {
    let (bold, light) = log_ticks(lo, hi);
    (lo..hi)
        .log_scale()
        .with_key_points(bold)
        .with_light_points(light)
}

/// Splits `text` into lines of at most `width` characters at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// Draws the frame (axes, legend panel, notes) and calls `body` to draw the data.
pub fn frame(
    path: &Path,
    f: &Frame,
    body: impl FnOnce(&mut Chart<'_, '_>) -> Result<(), String>,
) -> Result<(), String> {
    let canvas = Canvas::new(path, f.title, f.size, &f.notes)?;
    let root = &canvas.root;
    let mut builder = canvas.builder();
    if f.top.is_some() {
        // Room above the plot for the second x axis, drawn by hand below (a plotters top label
        // area would also carry the primary axis' labels).
        builder.margin_top(92);
    }
    let mut chart = builder
        .build_cartesian_2d(
            log_axis(f.x.range.0, f.x.range.1),
            log_axis(f.y.range.0, f.y.range.1),
        )
        .map_err(err)?;
    draw_mesh(
        chart
            .configure_mesh()
            .x_desc(f.x.title.as_str())
            .y_desc(f.y.title.as_str())
            .x_label_formatter(&|v| tick_label(*v))
            .y_label_formatter(&|v| tick_label(*v)),
    )?;
    body(&mut chart)?;
    if let Some((scale, title)) = &f.top {
        // The second x axis: ticks at every decade of x/scale along the plot's top edge.
        let (a, b) = (f.x.range.0 / scale, f.x.range.1 / scale);
        let (bold, _) = log_ticks(a, b);
        let (left, top) = chart.backend_coord(&(f.x.range.0, f.y.range.1));
        let (right, _) = chart.backend_coord(&(f.x.range.1, f.y.range.1));
        let label = ("sans-serif", 13).into_font();
        root.draw(&PathElement::new(
            vec![(left, top), (right, top)],
            BLACK.stroke_width(1),
        ))
        .map_err(err)?;
        for v in bold {
            let (x, _) = chart.backend_coord(&(v * scale, f.y.range.1));
            root.draw(&PathElement::new(
                vec![(x, top), (x, top - 5)],
                BLACK.stroke_width(1),
            ))
            .map_err(err)?;
            let text = tick_label(v);
            let w = 7 * text.chars().count() as i32;
            root.draw(&Text::new(text, (x - w / 2, top - 21), label.clone()))
                .map_err(err)?;
        }
        let w = 7 * title.chars().count() as i32;
        root.draw(&Text::new(
            title.clone(),
            ((left + right) / 2 - w / 2, top - 44),
            ("sans-serif", 14).into_font(),
        ))
        .map_err(err)?;
    }
    canvas.finish(&f.legend)
}

/// The plotting context of [`frame_linear`].
pub type LinearChart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// Draws `f` with linear axes (a time trace; the same title, legend panel and notes as [`frame`])
/// and calls `body` to draw the data. The second x axis on top is [`frame`]'s only: `f.top` must
/// be `None`.
pub fn frame_linear(
    path: &Path,
    f: &Frame,
    body: impl FnOnce(&mut LinearChart<'_, '_>) -> Result<(), String>,
) -> Result<(), String> {
    if f.top.is_some() {
        return Err(format!("{}: a linear chart has no second x axis", f.title));
    }
    let canvas = Canvas::new(path, f.title, f.size, &f.notes)?;
    let mut chart = canvas
        .builder()
        .build_cartesian_2d(f.x.range.0..f.x.range.1, f.y.range.0..f.y.range.1)
        .map_err(err)?;
    draw_mesh(
        chart
            .configure_mesh()
            .x_desc(f.x.title.as_str())
            .y_desc(f.y.title.as_str()),
    )?;
    body(&mut chart)?;
    canvas.finish(&f.legend)
}

type Area<'b> = DrawingArea<SVGBackend<'b>, plotters::coord::Shift>;

/// The layout every chart shares: the plot (`size` pixels) with the title centred above it, the
/// legend panel to its right and the wrapped notes under both.
struct Canvas<'b> {
    /// The whole image.
    root: Area<'b>,
    /// Where the axes and the data go.
    plot: Area<'b>,
    /// The legend panel.
    side: Area<'b>,
    /// The area under the plot and its wrapped lines.
    notes: Area<'b>,
    note_lines: Vec<String>,
}

impl<'b> Canvas<'b> {
    /// A white image at `path` split into the areas, with the title drawn.
    fn new(
        path: &'b Path,
        title: &str,
        size: (u32, u32),
        notes: &[String],
    ) -> Result<Self, String> {
        const LEGEND_W: u32 = 300;
        const LINE: u32 = 15;
        let note_lines: Vec<String> = notes.iter().flat_map(|n| wrap(n, 120)).collect();
        let notes_h = 10 + LINE * note_lines.len() as u32;
        let root = SVGBackend::new(path, (size.0 + LEGEND_W, size.1 + notes_h)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (upper, notes) = root.split_vertically(size.1);
        let (plot, side) = upper.split_horizontally(size.0);
        let w = 9 * title.chars().count() as i32;
        root.draw(&Text::new(
            title.to_string(),
            ((size.0 as i32 / 2 - w / 2).max(4), 10),
            ("sans-serif", 18).into_font(),
        ))
        .map_err(err)?;
        Ok(Canvas {
            root,
            plot,
            side,
            notes,
            note_lines,
        })
    }

    /// A chart builder on the plot with the margins and label areas every chart shares. The
    /// caption is drawn by [`Canvas::new`], not by plotters (which puts it inside the top margin,
    /// where a second x axis goes).
    fn builder(&self) -> ChartBuilder<'_, '_, SVGBackend<'b>> {
        let mut builder = ChartBuilder::on(&self.plot);
        builder
            .margin(12)
            .margin_top(40)
            .x_label_area_size(48)
            .y_label_area_size(78);
        builder
    }

    /// Draws the legend panel and the notes, and writes the file.
    fn finish(&self, legend: &[(Swatch, String)]) -> Result<(), String> {
        draw_legend(&self.side, legend)?;
        draw_notes(&self.notes, &self.note_lines)?;
        self.root.present().map_err(err)
    }
}

/// The grid and the label fonts every chart shares; draws the mesh.
fn draw_mesh<X, Y>(mesh: &mut MeshStyle<'_, '_, X, Y, SVGBackend<'_>>) -> Result<(), String>
where
    X: Ranged + ValueFormatter<X::ValueType>,
    Y: Ranged + ValueFormatter<Y::ValueType>,
{
    mesh.light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(200, 200, 200))
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 14))
        .draw()
        .map_err(err)
}

/// The legend panel right of the plot.
fn draw_legend(side: &Area<'_>, legend: &[(Swatch, String)]) -> Result<(), String> {
    const LINE: i32 = 15;
    let font = ("sans-serif", 12).into_font();
    let mut y = 40;
    for (swatch, text) in legend {
        let (x0, x1, ym) = (8, 34, y + 6);
        match swatch {
            Swatch::Line(c, m, dashed) => {
                if *dashed {
                    side.draw(&PathElement::new(
                        vec![(x0, ym), (x0 + 8, ym)],
                        c.stroke_width(2),
                    ))
                    .map_err(err)?;
                    side.draw(&PathElement::new(
                        vec![(x0 + 14, ym), (x1, ym)],
                        c.stroke_width(2),
                    ))
                    .map_err(err)?;
                } else {
                    side.draw(&PathElement::new(
                        vec![(x0, ym), (x1, ym)],
                        c.stroke_width(2),
                    ))
                    .map_err(err)?;
                }
                draw_pixel_marker(side, *m, ((x0 + x1) / 2, ym), *c)?;
            }
            Swatch::Box(c) => {
                side.draw(&Rectangle::new([(x0, ym - 6), (x1, ym + 6)], c.filled()))
                    .map_err(err)?;
            }
            Swatch::Mark(c, m) => draw_pixel_marker(side, *m, ((x0 + x1) / 2, ym), *c)?,
        }
        for (i, line) in wrap(text, 36).iter().enumerate() {
            // Each further line one line below the last (y carries the entry's height).
            if i > 0 {
                y += LINE;
            }
            side.draw(&Text::new(line.clone(), (x1 + 8, y), font.clone()))
                .map_err(err)?;
        }
        y += LINE + 6;
    }
    Ok(())
}

/// Notes under the plot, one wrapped line each.
fn draw_notes(notes: &Area<'_>, lines: &[String]) -> Result<(), String> {
    const LINE: i32 = 15;
    for (i, line) in lines.iter().enumerate() {
        notes
            .draw(&Text::new(
                line.clone(),
                (20, 4 + LINE * i as i32),
                ("sans-serif", 12).into_font(),
            ))
            .map_err(err)?;
    }
    Ok(())
}

fn draw_pixel_marker(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    m: Marker,
    (x, y): (i32, i32),
    c: RGBColor,
) -> Result<(), String> {
    match m {
        Marker::Dot => area.draw(&Circle::new((x, y), 3, c.filled())).map_err(err),
        Marker::Ring => area
            .draw(&Circle::new((x, y), 6, c.stroke_width(2)))
            .map_err(err),
        Marker::BigRing => area
            .draw(&Circle::new((x, y), 9, c.stroke_width(2)))
            .map_err(err),
        Marker::Cross => area
            .draw(&Cross::new((x, y), 4, c.stroke_width(2)))
            .map_err(err),
        Marker::Triangle => area
            .draw(&TriangleMarker::new((x, y), 5, c.filled()))
            .map_err(err),
        Marker::None => Ok(()),
    }
}

/// Draws markers at data points.
fn draw_markers(
    chart: &mut Chart<'_, '_>,
    m: Marker,
    points: &[(f64, f64)],
    c: RGBColor,
) -> Result<(), String> {
    let pts = points.iter().copied();
    match m {
        Marker::Dot => chart
            .draw_series(pts.map(|p| Circle::new(p, 3, c.filled())))
            .map(|_| ()),
        Marker::Ring => chart
            .draw_series(pts.map(|p| Circle::new(p, 6, c.stroke_width(2))))
            .map(|_| ()),
        Marker::BigRing => chart
            .draw_series(pts.map(|p| Circle::new(p, 9, c.stroke_width(2))))
            .map(|_| ()),
        Marker::Cross => chart
            .draw_series(pts.map(|p| Cross::new(p, 4, c.stroke_width(2))))
            .map(|_| ()),
        Marker::Triangle => chart
            .draw_series(pts.map(|p| TriangleMarker::new(p, 5, c.filled())))
            .map(|_| ()),
        Marker::None => Ok(()),
    }
    .map_err(err)
}

/// A point the docs quote: drawn with a black ring and a tag, explained in the notes.
pub struct Highlight {
    /// Method label.
    pub method: String,
    /// Step of the point.
    pub step: f64,
    /// Short tag drawn next to it ("A", "B", …).
    pub tag: String,
    /// The note: what the docs say about it.
    pub note: String,
}

/// How the x value of a work-precision point is taken.
pub enum Cost<'a> {
    /// Median wall time per run, with the range of the repeats as an error bar.
    Wall,
    /// `fric_` calls per run.
    Calls,
    /// Median wall time of this many single runs (no inner repetition), with the range of the
    /// runs as an error bar.
    Runs(usize),
    /// Any other cost of a point (no bars).
    Other(&'a dyn Fn(&Point) -> f64),
}

/// What a scene adds to a work-precision chart beyond its points.
#[derive(Default)]
pub struct Extras {
    /// Notes under the chart.
    pub notes: Vec<String>,
    /// Vertical reference lines (dashed, black): x value and legend text.
    pub verticals: Vec<(f64, String)>,
}

/// Whether a method's claimed bound comes within 25 % of its error at some claimed step (its
/// dashed line would lie on the curve).
fn claim_on_curve(mine: &[&Point]) -> bool {
    mine.iter()
        .any(|p| p.claim.is_finite() && p.claim < 1.25 * p.error)
}

/// Error against cost, one curve per method. Points whose run did not end "ok" are left out of
/// the curves and drawn apart in the method's colour: a cross at their error when it is
/// measurable, a triangle on the top edge when it is not. The error is floored at 1e-16 so that
/// round-off-exact results stay on a log axis. A curve that coincides with an earlier one (every
/// point within 5 % in error at the same step) is drawn with rings over the first one's dots,
/// and a note says so. `extras` adds a scene's own notes and reference lines.
#[allow(clippy::too_many_arguments)]
pub fn work_precision_chart(
    path: &Path,
    title: &str,
    x_title: &str,
    y_title: &str,
    points: &[Point],
    cost: Cost,
    highlights: &[Highlight],
    machine: &str,
    extras: &Extras,
) -> Result<(), String> {
    let timed = matches!(cost, Cost::Wall | Cost::Runs(_));
    let x_of = |p: &Point| match cost {
        Cost::Wall | Cost::Runs(_) => p.wall,
        Cost::Calls => p.calls as f64,
        Cost::Other(f) => f(p),
    };
    let usable: Vec<&Point> = points
        .iter()
        .filter(|p| p.verdict == "ok" && p.error.is_finite())
        .collect();
    let failed: Vec<&Point> = points.iter().filter(|p| p.verdict != "ok").collect();
    let (x0, x1) = decades(usable.iter().chain(&failed).flat_map(|p| match cost {
        Cost::Wall | Cost::Runs(_) => vec![p.wall_range[0], p.wall_range[1], p.wall],
        Cost::Calls => vec![p.calls as f64],
        Cost::Other(f) => vec![f(p)],
    }));
    let (y0, y1) = decades(
        usable
            .iter()
            .flat_map(|p| [p.error.max(1e-16), p.claim.max(1e-16)])
            .chain(failed.iter().map(|p| p.error.max(1e-16))),
    );
    let mut methods: Vec<&str> = Vec::new();
    for p in points {
        if !methods.contains(&p.method.as_str()) {
            methods.push(&p.method);
        }
    }
    // Curves identical to an earlier one.
    let same_as = |i: usize| -> Option<usize> {
        let mine: Vec<&&Point> = usable.iter().filter(|p| p.method == methods[i]).collect();
        (0..i).find(|&j| {
            let theirs: Vec<&&Point> = usable.iter().filter(|p| p.method == methods[j]).collect();
            !mine.is_empty()
                && mine.len() == theirs.len()
                && mine.iter().zip(&theirs).all(|(a, b)| {
                    a.step == b.step && (a.error - b.error).abs() <= 0.05 * a.error.max(b.error)
                })
        })
    };
    // Dots; rings for a curve that coincides with an earlier one, larger for the next such.
    let twin_marker = |i: usize| {
        if same_as(i).is_none() {
            Marker::Dot
        } else if (0..i).all(|j| same_as(j).is_none()) {
            Marker::Ring
        } else {
            Marker::BigRing
        }
    };
    let mut legend = Vec::new();
    let mut notes = Vec::new();
    for (i, m) in methods.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let twin = same_as(i);
        let mk = twin_marker(i);
        legend.push((Swatch::Line(color, mk, false), (*m).to_string()));
        if let Some(j) = twin {
            notes.push(if timed {
                format!(
                    "'{m}' has the errors of '{}' (every error within 5 % at the same step; its times differ): drawn as rings on a thin line.",
                    methods[j]
                )
            } else {
                format!(
                    "'{m}' coincides with '{}' (every error within 5 % at the same step): drawn as rings, no line.",
                    methods[j]
                )
            });
        }
    }
    for m in &methods {
        let mine: Vec<&Point> = usable.iter().copied().filter(|p| p.method == *m).collect();
        if mine.iter().filter(|p| p.claim.is_finite()).count() > 1 && claim_on_curve(&mine) {
            let closest = mine
                .iter()
                .filter(|p| p.claim.is_finite())
                .map(|p| p.claim / p.error.max(1e-300))
                .fold(f64::INFINITY, f64::min);
            notes.push(format!(
                "'{m}': its claimed bound comes to {closest:.2} × its error at the closest step, where a dashed line would lie on the curve: checked, not drawn."
            ));
        }
    }
    if usable.iter().any(|p| p.claim.is_finite()) {
        legend.push((
            Swatch::Line(RGBColor(60, 60, 60), Marker::None, true),
            "dashed, same colour: the bound the scene file claims (checked)".into(),
        ));
    }
    for (_, text) in &extras.verticals {
        legend.push((Swatch::Line(BLACK, Marker::None, true), text.clone()));
    }
    if failed.iter().any(|p| p.error.is_finite()) {
        legend.push((
            Swatch::Mark(RGBColor(60, 60, 60), Marker::Cross),
            "run not ok, error measurable (verdict in the CSV)".into(),
        ));
    }
    if failed.iter().any(|p| !p.error.is_finite()) {
        legend.push((
            Swatch::Mark(RGBColor(60, 60, 60), Marker::Triangle),
            "on the top edge: no error to show (diverged, Newton failed, cut-back)".into(),
        ));
    }
    if !highlights.is_empty() {
        legend.push((
            Swatch::Mark(BLACK, Marker::Ring),
            "black ring + tag: a point the docs quote (notes below)".into(),
        ));
    }
    for h in highlights {
        notes.push(format!("{}: {}", h.tag, h.note));
    }
    if matches!(cost, Cost::Wall) {
        notes.push(format!(
            "Times: the fastest of 7 repeats per point (each ≥ 1 ms, the run repeated inside it), all points of the chart timed in 7 interleaved rounds so that load from other jobs spreads over them; bars: fastest to slowest repeat. Wall time moves with the machine's load: the calls chart is the load-independent cost, and the findings compare calls. Machine: {machine}."
        ));
    }
    if let Cost::Runs(n) = cost {
        notes.push(format!(
            "Times: the fastest of {n} single runs per point; bars: fastest to slowest run. Wall time moves with the machine's load; the element count and Δt are the load-independent cost. Machine: {machine}."
        ));
    }
    notes.extend(extras.notes.iter().cloned());
    let f = Frame {
        title,
        x: Axis::new((x0, x1), x_title),
        y: Axis::new((y0, y1), y_title),
        top: None,
        legend,
        notes,
        size: (760, 520),
    };
    frame(path, &f, |chart| {
        let top = y1 / 10f64.powf(0.03 * (y1 / y0).log10());
        for (i, m) in methods.iter().enumerate() {
            let color = COLORS[i % COLORS.len()];
            let mine: Vec<&&Point> = usable.iter().filter(|p| p.method == *m).collect();
            let mut series: Vec<(f64, f64)> =
                mine.iter().map(|p| (x_of(p), p.error.max(1e-16))).collect();
            series.sort_by(|a, b| a.0.total_cmp(&b.0));
            let fails = || failed.iter().filter(|p| p.method == *m);
            let crosses: Vec<(f64, f64)> = fails()
                .filter(|p| p.error.is_finite())
                .map(|p| (x_of(p), p.error.max(1e-16)))
                .collect();
            draw_markers(chart, Marker::Cross, &crosses, color)?;
            let tops: Vec<(f64, f64)> = fails()
                .filter(|p| !p.error.is_finite())
                .map(|p| (x_of(p), top))
                .collect();
            draw_markers(chart, Marker::Triangle, &tops, color)?;
            if timed {
                chart
                    .draw_series(mine.iter().map(|p| {
                        let y = p.error.max(1e-16);
                        PathElement::new(
                            vec![(p.wall_range[0], y), (p.wall_range[1], y)],
                            color.stroke_width(1),
                        )
                    }))
                    .map_err(err)?;
            }
            if series.is_empty() {
                continue;
            }
            let twin = same_as(i).is_some();
            if !twin {
                chart
                    .draw_series(LineSeries::new(series.clone(), color.stroke_width(2)))
                    .map_err(err)?;
            } else if timed {
                // Same errors, other times: a thin line so the curve can be followed.
                chart
                    .draw_series(LineSeries::new(series.clone(), color.stroke_width(1)))
                    .map_err(err)?;
            }
            draw_markers(chart, twin_marker(i), &series, color)?;
            let mut claims: Vec<(f64, f64)> = mine
                .iter()
                .filter(|p| p.claim.is_finite())
                .map(|p| (x_of(p), p.claim.max(1e-16)))
                .collect();
            claims.sort_by(|a, b| a.0.total_cmp(&b.0));
            // A bound within 25 % of the curve at some step would lie on it: checked, not drawn
            // (a note says so).
            if claims.len() > 1
                && !claim_on_curve(&mine.iter().map(|p| **p).collect::<Vec<&Point>>())
            {
                chart
                    .draw_series(DashedLineSeries::new(claims, 6, 4, color.stroke_width(1)))
                    .map_err(err)?;
            }
        }
        for (x, _) in &extras.verticals {
            chart
                .draw_series(DashedLineSeries::new(
                    [(*x, y0), (*x, y1)],
                    8,
                    5,
                    BLACK.stroke_width(2),
                ))
                .map_err(err)?;
        }
        for h in highlights {
            if let Some(p) = usable
                .iter()
                .find(|p| p.method == h.method && p.step == h.step)
            {
                let at = (x_of(p), p.error.max(1e-16));
                chart
                    .draw_series([EmptyElement::at(at)
                        + Circle::new((0, 0), 9, BLACK.stroke_width(2))
                        + Text::new(h.tag.clone(), (10, -18), ("sans-serif", 15).into_font())])
                    .map_err(err)?;
            }
        }
        Ok(())
    })
}

/// The cells every map shares, one colour each: an answer that settles (accurate), one that
/// oscillates (unstable), a host cut-back.
const SETTLES: RGBColor = RGBColor(102, 194, 120);
const OSCILLATES: RGBColor = RGBColor(244, 109, 67);
const CUT_BACK: RGBColor = RGBColor(49, 54, 149);

fn cell_color(c: Cell) -> RGBColor {
    match c {
        Cell::Accurate => SETTLES,
        Cell::Inaccurate => RGBColor(199, 233, 192),
        Cell::Chattering => RGBColor(254, 224, 139),
        Cell::Unstable => OSCILLATES,
        Cell::Diverged => RGBColor(215, 48, 39),
        Cell::NewtonFailed => RGBColor(117, 107, 177),
        Cell::CutBack => CUT_BACK,
    }
}

/// A map's cells as filled boxes: row `r`, column `c` spans the edges ([`edge`]) of `xs[c]`
/// and `ys[r]`, in the colour `color` gives its cell.
pub fn draw_cells<T: Copy>(
    chart: &mut Chart<'_, '_>,
    cells: &[Vec<T>],
    xs: &[f64],
    ys: &[f64],
    color: impl Fn(T) -> RGBColor,
) -> Result<(), String> {
    for (r, row) in cells.iter().enumerate() {
        chart
            .draw_series(row.iter().enumerate().map(|(c, cell)| {
                Rectangle::new(
                    [
                        (edge(xs, c, false), edge(ys, r, false)),
                        (edge(xs, c, true), edge(ys, r, true)),
                    ],
                    color(*cell).filled(),
                )
            }))
            .map_err(err)?;
    }
    Ok(())
}

/// Cell edges halfway (geometrically) between grid values.
pub fn edge(v: &[f64], i: usize, up: bool) -> f64 {
    let ratio = if v.len() > 1 {
        (v[1] / v[0]).sqrt()
    } else {
        2.0
    };
    if up { v[i] * ratio } else { v[i] / ratio }.max(f64::MIN_POSITIVE)
}

/// A map cell the docs quote: ringed and tagged.
pub struct CellMark {
    /// Row and column.
    pub cell: (usize, usize),
    /// Tag.
    pub tag: String,
    /// Note.
    pub note: String,
}

/// The F6 stability map with the theoretical explicit limit Δt = 2/sqrt((k + K_f)/m) drawn on
/// it, Δt also as a fraction of the period T on the top axis.
pub fn stability_map(
    path: &Path,
    o: &Oscillator,
    map: &Map,
    marks: &[CellMark],
    notes: &[String],
) -> Result<(), String> {
    let (nx, ny) = (map.dts.len(), map.gammas.len());
    let (x0, x1) = (edge(&map.dts, 0, false), edge(&map.dts, nx - 1, true));
    let (y0, y1) = (edge(&map.gammas, 0, false), edge(&map.gammas, ny - 1, true));
    let mut legend: Vec<(Swatch, String)> = Cell::ALL
        .iter()
        .filter(|c| map.cells.iter().flatten().any(|x| x == *c))
        .map(|c| (Swatch::Box(cell_color(*c)), c.name().to_string()))
        .collect();
    legend.push((
        Swatch::Line(BLACK, Marker::None, false),
        if map.integrator == crate::oscillator::Integrator::Explicit {
            "explicit limit Δt = 2/sqrt((k + K_f)/m), K_f = μ_s N/γ_crit".into()
        } else {
            "for reference, the explicit limit Δt = 2/sqrt((k + K_f)/m), K_f = μ_s N/γ_crit".into()
        },
    ));
    let spring_limit = 2.0 * (o.mass / o.spring).sqrt();
    legend.push((
        Swatch::Line(BLACK, Marker::None, true),
        format!("the spring's own explicit limit 2·sqrt(m/k) = {spring_limit:.3} s"),
    ));
    if !marks.is_empty() {
        legend.push((
            Swatch::Mark(BLACK, Marker::Ring),
            "ring + tag: a cell the docs quote".into(),
        ));
    }
    let mut all_notes: Vec<String> = marks
        .iter()
        .map(|m| format!("{}: {}", m.tag, m.note))
        .collect();
    all_notes.extend(notes.iter().cloned());
    let period = o.period();
    let f = Frame {
        title: &format!("F6 stability map: {}", map.spec.label),
        x: Axis::new((x0, x1), "time step Δt (s)"),
        y: Axis::new((y0, y1), "allowable elastic slip γ_crit (m)"),
        top: Some((period, format!("Δt / T, period T = {period:.3} s"))),
        legend,
        notes: all_notes,
        size: (760, 560),
    };
    frame(path, &f, |chart| {
        draw_cells(chart, &map.cells, &map.dts, &map.gammas, cell_color)?;
        let limit: Vec<(f64, f64)> = crate::stability::log_space(y0, y1, 200)
            .into_iter()
            .map(|g| (o.explicit_limit(g), g))
            .filter(|(dt, _)| *dt >= x0 && *dt <= x1)
            .collect();
        chart
            .draw_series(LineSeries::new(limit, BLACK.stroke_width(3)))
            .map_err(err)?;
        if spring_limit > x0 && spring_limit < x1 {
            chart
                .draw_series(DashedLineSeries::new(
                    [(spring_limit, y0), (spring_limit, y1)],
                    8,
                    5,
                    BLACK.stroke_width(2),
                ))
                .map_err(err)?;
        }
        draw_cell_marks(chart, &map.dts, &map.gammas, marks)
    })
}

fn draw_cell_marks(
    chart: &mut Chart<'_, '_>,
    xs: &[f64],
    ys: &[f64],
    marks: &[CellMark],
) -> Result<(), String> {
    for m in marks {
        let (r, c) = m.cell;
        chart
            .draw_series([EmptyElement::at((xs[c], ys[r]))
                + Circle::new((0, 0), 8, WHITE.stroke_width(4))
                + Circle::new((0, 0), 8, BLACK.stroke_width(2))
                + Text::new(m.tag.clone(), (10, -20), ("sans-serif", 15).into_font())])
            .map_err(err)?;
    }
    Ok(())
}

fn rate_cell_color(c: RateCell) -> RGBColor {
    match c {
        RateCell::Settles => SETTLES,
        RateCell::Oscillates => OSCILLATES,
        RateCell::CutBack => CUT_BACK,
    }
}

/// An F4 rate-stability map over (Δt, d_c) with the closed-form limit drawn on it.
pub fn rate_map(path: &Path, map: &RateMap) -> Result<(), String> {
    let (nx, ny) = (map.dts.len(), map.decays.len());
    let (x0, x1) = (edge(&map.dts, 0, false), edge(&map.dts, nx - 1, true));
    let (y0, y1) = (edge(&map.decays, 0, false), edge(&map.decays, ny - 1, true));
    let mut legend: Vec<(Swatch, String)> =
        [RateCell::Settles, RateCell::Oscillates, RateCell::CutBack]
            .into_iter()
            .filter(|c| map.cells.iter().flatten().any(|x| x == c))
            .map(|c| (Swatch::Box(rate_cell_color(c)), c.name().to_string()))
            .collect();
    legend.push((
        Swatch::Line(BLACK, Marker::None, false),
        if map.law == RateLaw::DecayFrozen {
            "closed-form limit Δt = |dτ/dv|/k_s".into()
        } else {
            "earlier rate-free stiffness's limit Δt = 2|dτ/dv|/k_s".into()
        },
    ));
    let f = Frame {
        title: &map.title(),
        x: Axis::new((x0, x1), "time step Δt (s)"),
        y: Axis::new((y0, y1), "decay coefficient d_c (s/m)"),
        top: None,
        legend,
        notes: vec![format!(
            "Each cell: steady sliding at v = {} m/s from first contact over two time units; it settles when the end stress is τ_law(v) to 1e-9. {}",
            map.scene.rates.first().copied().unwrap_or(0.0),
            if (0..map.decays.len()).any(|r| map.checked(r)) {
                "Rows with d_c·v ≤ 1 are held to the limit within one cell."
            } else {
                "This law has no step limit: the check is that every cell settles (finding F4-map-implicit); the curve is the earlier formulation's limit, for comparison."
            }
        )],
        size: (760, 560),
    };
    frame(path, &f, |chart| {
        draw_cells(chart, &map.cells, &map.dts, &map.decays, rate_cell_color)?;
        let mut fine = map.scene.clone();
        let limit: Vec<(f64, f64)> = crate::stability::log_space(y0, y1, 200)
            .into_iter()
            .map(|dc| {
                fine.decay = dc;
                (fine.rate_free_stiffness_limit(map.law, map.gamma_crit), dc)
            })
            .filter(|(dt, _)| *dt >= x0 && *dt <= x1)
            .collect();
        chart
            .draw_series(LineSeries::new(limit, BLACK.stroke_width(3)))
            .map_err(err)?;
        Ok(())
    })
}

/// The machine the times were taken on: CPU model and logical CPUs.
pub fn machine() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, m)| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cpus = std::thread::available_parallelism().map_or(0, std::num::NonZero::get);
    format!("{model}, {cpus} logical CPUs")
}
