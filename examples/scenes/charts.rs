//! SVG charts (plotters, SVG backend only): work-precision curves and stability maps.

use std::path::Path;

use plotters::element::DashedPathElement;
use plotters::prelude::*;

use crate::oscillator::Oscillator;
use crate::rate_map::{RateCell, RateMap};
use crate::scene::Point;
use crate::stability::{Cell, Map};
use crate::velocity::RateLaw;

const COLORS: [RGBColor; 10] = [
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

/// Range of positive finite values, widened to whole decades.
fn decades(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for v in values.filter(|v| v.is_finite() && *v > 0.0) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (1e-3, 1.0);
    }
    (
        10f64.powf(lo.log10().floor()),
        10f64.powf(hi.log10().ceil().max(lo.log10().floor() + 1.0)),
    )
}

/// Error against cost, one curve per method; `cost` picks the x value of a point. Points whose
/// run did not end "ok" are left out of the curves and drawn apart in the method's colour: a
/// cross at their error when it is measurable (chattering, rate-unstable, …), a triangle on the
/// top edge when it is not (a library cut-back, PNEWDT < 1, or a diverged run). The error is
/// floored at 1e-16 so that round-off-exact results stay on a log axis.
pub fn work_precision(
    path: &Path,
    title: &str,
    x_label: &str,
    error_label: &str,
    points: &[Point],
    legend: SeriesLabelPosition,
    cost: impl Fn(&Point) -> f64,
) -> Result<(), String> {
    let usable: Vec<&Point> = points
        .iter()
        .filter(|p| p.verdict == "ok" && p.error.is_finite())
        .collect();
    let failed: Vec<&Point> = points.iter().filter(|p| p.verdict != "ok").collect();
    let (x0, x1) = decades(usable.iter().chain(&failed).map(|p| cost(p)));
    let (y0, y1) = decades(
        usable
            .iter()
            .flat_map(|p| [p.error.max(1e-16), p.claim.max(1e-16)])
            .chain(failed.iter().map(|p| p.error.max(1e-16))),
    );
    let root = SVGBackend::new(path, (820, 540)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(error_label)
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(err)?;
    let mut methods: Vec<&str> = Vec::new();
    for p in points {
        if !methods.contains(&p.method.as_str()) {
            methods.push(&p.method);
        }
    }
    for (i, m) in methods.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let mut series: Vec<(f64, f64)> = usable
            .iter()
            .filter(|p| p.method == *m)
            .map(|p| (cost(p), p.error.max(1e-16)))
            .collect();
        series.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Runs that did not end "ok": crosses at a measurable error, triangles on top.
        let top = y1 / 10f64.powf(0.05 * (y1 / y0).log10());
        let mine = || failed.iter().filter(|p| p.method == *m);
        chart
            .draw_series(
                mine()
                    .filter(|p| p.error.is_finite())
                    .map(|p| Cross::new((cost(p), p.error.max(1e-16)), 4, color.stroke_width(2))),
            )
            .map_err(err)?;
        chart
            .draw_series(
                mine()
                    .filter(|p| !p.error.is_finite())
                    .map(|p| TriangleMarker::new((cost(p), top), 5, color.filled())),
            )
            .map_err(err)?;
        if series.is_empty() {
            continue;
        }
        chart
            .draw_series(LineSeries::new(series.clone(), color.stroke_width(2)))
            .map_err(err)?
            .label(*m)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
            });
        chart
            .draw_series(
                series
                    .iter()
                    .map(|&(x, y)| Circle::new((x, y), 3, color.filled())),
            )
            .map_err(err)?;
        // The bound the scene file claims for this method (dashed, same colour).
        let mut claims: Vec<(f64, f64)> = usable
            .iter()
            .filter(|p| p.method == *m && p.claim.is_finite())
            .map(|p| (cost(p), p.claim.max(1e-16)))
            .collect();
        claims.sort_by(|a, b| a.0.total_cmp(&b.0));
        if claims.len() > 1 {
            chart
                .draw_series(DashedLineSeries::new(claims, 6, 4, color.stroke_width(1)))
                .map_err(err)?;
        }
    }
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
        .map_err(err)?
        .label("dashed: the claimed bound (tests/scenes_driver.rs)")
        .legend(|(x, y)| {
            DashedPathElement::new(vec![(x, y), (x + 18, y)], 4, 3, BLACK.stroke_width(1))
        });
    if !failed.is_empty() {
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
            .map_err(err)?
            .label("×: run not ok (verdict in the CSV); ▲ on top: no error (diverged, Newton failed, cut-back)")
            .legend(|(x, y)| Cross::new((x + 9, y), 4, BLACK.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(legend)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}

fn cell_color(c: Cell) -> RGBColor {
    match c {
        Cell::Accurate => RGBColor(102, 194, 120),
        Cell::Inaccurate => RGBColor(199, 233, 192),
        Cell::Chattering => RGBColor(254, 224, 139),
        Cell::Unstable => RGBColor(244, 109, 67),
        Cell::Diverged => RGBColor(215, 48, 39),
        Cell::NewtonFailed => RGBColor(117, 107, 177),
        Cell::CutBack => RGBColor(49, 54, 149),
    }
}

/// The stability map with the theoretical explicit limit Δt = 2/sqrt((k + K_f)/m) drawn on it.
pub fn stability_map(path: &Path, o: &Oscillator, map: &Map) -> Result<(), String> {
    let half = |v: &[f64], i: usize, up: bool| -> f64 {
        // Cell edges halfway (geometrically) between grid values.
        let n = v.len();
        let ratio = if n > 1 { (v[1] / v[0]).sqrt() } else { 2.0 };
        if up { v[i] * ratio } else { v[i] / ratio }.max(f64::MIN_POSITIVE)
    };
    let (nx, ny) = (map.dts.len(), map.gammas.len());
    let (x0, x1) = (half(&map.dts, 0, false), half(&map.dts, nx - 1, true));
    let (y0, y1) = (half(&map.gammas, 0, false), half(&map.gammas, ny - 1, true));
    let root = SVGBackend::new(path, (820, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("F6 stability map: {}", map.spec.label),
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(err)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("time step Δt")
        .y_desc("allowable elastic slip γ_crit")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(err)?;
    for (r, row) in map.cells.iter().enumerate() {
        chart
            .draw_series(row.iter().enumerate().map(|(c, cell)| {
                Rectangle::new(
                    [
                        (half(&map.dts, c, false), half(&map.gammas, r, false)),
                        (half(&map.dts, c, true), half(&map.gammas, r, true)),
                    ],
                    cell_color(*cell).filled(),
                )
            }))
            .map_err(err)?;
    }
    for cell in Cell::ALL {
        if map.cells.iter().flatten().any(|c| *c == cell) {
            let color = cell_color(cell);
            chart
                .draw_series(std::iter::empty::<Rectangle<(f64, f64)>>())
                .map_err(err)?
                .label(cell.name())
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 14, y + 5)], color.filled())
                });
        }
    }
    // The explicit limit as a curve in (Δt, γ_crit): γ_crit = μ_s N / (m (2/Δt)² − k).
    let limit: Vec<(f64, f64)> = crate::stability::log_space(y0, y1, 200)
        .into_iter()
        .map(|g| (o.explicit_limit(g), g))
        .filter(|(dt, _)| *dt >= x0 && *dt <= x1)
        .collect();
    chart
        .draw_series(LineSeries::new(limit, BLACK.stroke_width(3)))
        .map_err(err)?
        .label("explicit limit Δt = 2/sqrt((k+K_f)/m)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], BLACK.stroke_width(3)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}

fn rate_cell_color(c: RateCell) -> RGBColor {
    match c {
        RateCell::Settles => RGBColor(102, 194, 120),
        RateCell::Oscillates => RGBColor(244, 109, 67),
        RateCell::CutBack => RGBColor(49, 54, 149),
    }
}

/// An F4 rate-stability map over (Δt, d_c) with the closed-form limit drawn on it.
pub fn rate_map(path: &Path, map: &RateMap) -> Result<(), String> {
    let half = |v: &[f64], i: usize, up: bool| -> f64 {
        let n = v.len();
        let ratio = if n > 1 { (v[1] / v[0]).sqrt() } else { 2.0 };
        if up { v[i] * ratio } else { v[i] / ratio }.max(f64::MIN_POSITIVE)
    };
    let (nx, ny) = (map.dts.len(), map.decays.len());
    let (x0, x1) = (half(&map.dts, 0, false), half(&map.dts, nx - 1, true));
    let (y0, y1) = (half(&map.decays, 0, false), half(&map.decays, ny - 1, true));
    let root = SVGBackend::new(path, (820, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(map.title(), ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(err)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("time step Δt")
        .y_desc("decay coefficient d_c")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.1}"))
        .draw()
        .map_err(err)?;
    for (r, row) in map.cells.iter().enumerate() {
        chart
            .draw_series(row.iter().enumerate().map(|(c, cell)| {
                Rectangle::new(
                    [
                        (half(&map.dts, c, false), half(&map.decays, r, false)),
                        (half(&map.dts, c, true), half(&map.decays, r, true)),
                    ],
                    rate_cell_color(*cell).filled(),
                )
            }))
            .map_err(err)?;
    }
    for cell in [RateCell::Settles, RateCell::Oscillates, RateCell::CutBack] {
        if map.cells.iter().flatten().any(|c| *c == cell) {
            let color = rate_cell_color(cell);
            chart
                .draw_series(std::iter::empty::<Rectangle<(f64, f64)>>())
                .map_err(err)?
                .label(cell.name())
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 14, y + 5)], color.filled())
                });
        }
    }
    // The closed-form limit, row by row on a fine d_c grid.
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
        .map_err(err)?
        .label(if map.law == RateLaw::DecayFrozen {
            "closed-form limit Δt = |dτ/dv|/k_s"
        } else {
            "earlier rate-free stiffness's limit Δt = 2|dτ/dv|/k_s"
        })
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], BLACK.stroke_width(3)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}
