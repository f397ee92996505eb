//! Scenes R1 and R2: rate-and-state friction (law 3) through `fric_` (docs/scene-definitions.md).
//!
//! - **R1, velocity steps.** A point slid at V₁ until steady, then at V₂ = 10·V₁, then back at
//!   V₁. Closed form at the end of every increment: τ/p = μ(V, θ(t)) with the analytic θ(t) of
//!   the evolution law at constant V (aging: θ = L/V + (θ₁ − L/V)e^(−Vt/L); slip:
//!   ln(Vθ/L) = ln(Vθ₁/L)e^(−Vt/L)). Work-precision: the largest error over the history against
//!   increments per L of slip, for the library (θ advanced exactly at the end-of-increment rate)
//!   and, as the reference a hand-written routine would be, θ advanced by one explicit Euler
//!   step of dθ/dt at the start-of-increment state.
//! - **R2, quasi-static spring-slider.** A spring of stiffness k (stress per length) pulls the
//!   point through a load point moving at constant V: k(Vt − x) = τ(x) solved by Newton with
//!   `DDTDDG` each increment. Linear stability of steady sliding (Ruina 1983, Rice & Ruina
//!   1983): stable for k > k_c = p(b − a)/L, growing oscillations (stick-slip) for k < k_c. The
//!   scene starts from steady sliding with θ perturbed by 1 % and classifies the run by the
//!   growth of the slip-rate oscillation; the map over (k/k_c, V·Δt/L) locates the measured
//!   boundary, which must lie within one cell of k_c at the increments that resolve L.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use interfacial::props::RateStateBuilder;
use interfacial_test_hosts::FricCall;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::checks::{Row, slide};

const MU0: f64 = 0.6;
const A: f64 = 0.01;
const B: f64 = 0.015;
const V0: f64 = 1e-6;
const L: f64 = 1e-5;
const P: f64 = 50.0;
/// Small against L (the interface's own stick compliance γ_crit/(μp) stays 1e-6 of the
/// spring's at the largest k of R2).
const GAMMA_CRIT: f64 = 1e-10;

/// `PROPS` of law 3: aging (0) or slip (1) law, logarithmic μ.
fn props(evolution: f64) -> Vec<f64> {
    RateStateBuilder::new()
        .mu0(MU0)
        .a(A)
        .b(B)
        .v0(V0)
        .l(L)
        .evolution(evolution)
        .gamma_crit(GAMMA_CRIT)
        .build()
}

/// A point in contact at P with NSTATV = 4 and θ = `theta`.
fn point(evolution: f64, theta: f64) -> FricCall {
    let mut c = FricCall::new(1, &props(evolution));
    c.nstatv = 4;
    c.statev = vec![0.0, 0.0, 0.0, theta];
    c.press = P;
    c.dpress = 0.0;
    c
}

/// μ(V, θ), written out from the law's definition.
fn mu(v: f64, theta: f64) -> f64 {
    MU0 + A * (v / V0).ln() + B * (V0 * theta / L).ln()
}

/// θ after sliding for t at constant V from θ₁: each law's analytic solution.
fn theta_at(theta1: f64, v: f64, t: f64, slip_law: bool) -> f64 {
    let decay = (-v * t / L).exp();
    if slip_law {
        L / v * ((v * theta1 / L).ln() * decay).exp()
    } else {
        L / v + (theta1 - L / v) * decay
    }
}

/// The velocity-step history V₁ (steady) → V₂ for 10 L → V₁ for 10 L at `per_l` increments per
/// L; the largest |τ/p − μ(V, θ(t))| after the first step, for the library and for the
/// explicit-Euler θ of the same increments.
fn r1_errors(slip_law: bool, per_l: f64) -> Result<(f64, f64), String> {
    let (v1, v2) = (V0, 10.0 * V0);
    let theta1 = L / v1;
    let mut c = point(if slip_law { 1.0 } else { 0.0 }, theta1);
    // Steady at V₁ from θ = L/V₁: one increment establishes the elastic slip.
    let dgam = L / per_l;
    slide(&mut c, dgam, dgam / v1, "R1")?;
    let (mut err_lib, mut err_euler) = (0.0f64, 0.0f64);
    let (mut theta_exact, mut theta_euler) = (c.statev[3], c.statev[3]);
    for v in [v2, v1] {
        let dtime = dgam / v;
        let start = theta_exact;
        for k in 1..=(10.0 * per_l).round() as usize {
            slide(&mut c, dgam, dtime, "R1")?;
            theta_exact = theta_at(start, v, k as f64 * dtime, slip_law);
            let rate = if slip_law {
                -(v * theta_euler / L) * (v * theta_euler / L).ln()
            } else {
                1.0 - v * theta_euler / L
            };
            theta_euler = (theta_euler + dtime * rate).max(f64::MIN_POSITIVE);
            let want = mu(v, theta_exact);
            err_lib = err_lib.max((c.tau[0] / P - want).abs());
            err_euler = err_euler.max((mu(v, theta_euler) - want).abs());
        }
    }
    Ok((err_lib, err_euler))
}

/// What an R2 run did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    /// The slip-rate oscillation decays: steady sliding.
    Steady,
    /// It grows: stick-slip.
    Growing,
}

/// R2 at spring stiffness `k_ratio`·k_c and V·Δt/L = `courant`, over 120 L/V: the growth
/// factor of the slip-rate deviation |V_slider/V − 1| (its largest value in the second half of
/// the run over its first response to the perturbation) and the `fric_` calls made.
fn r2_run(k_ratio: f64, courant: f64) -> Result<(f64, usize), String> {
    let v = V0;
    let k = k_ratio * P * (B - A) / L;
    let dtime = courant * L / v;
    // Steady sliding at V with θ perturbed by 1 %.
    let mut c = point(0.0, 1.01 * L / v);
    c.tau[0] = mu(v, L / v) * P;
    // The elastic slip and rate of steady sliding (STATEV(2) = V, sliding).
    c.statev[1] = v;
    c.statev[2] = 1.0;
    let t_end = 120.0 * L / v;
    let steps = (t_end / dtime).round() as usize;
    // Spring extension so that k·e = τ at the start.
    let mut extension = c.tau[0] / k;
    let mut deviation = Vec::with_capacity(steps);
    let mut iterations = 0;
    for _ in 0..steps {
        // k·(e + VΔt − Δx) = τ(Δx) for the slip Δx of the increment: the first sign change of
        // the residual on a doubling scan from Δx = 0 (the smallest root: the branch the
        // slider is on), then Newton with `DDTDDG`, kept inside the bracket by bisection.
        let load = extension + v * dtime;
        let residual = |dx: f64, iterations: &mut usize| -> Result<(f64, f64, FricCall), String> {
            let mut t = c.clone();
            slide(&mut t, dx, dtime, "R2")?;
            *iterations += 1;
            Ok((k * (load - dx) - t.tau[0], -k - t.ddtddg(0, 0), t))
        };
        let (mut lo, mut hi) = (0.0, v * dtime * 1e-3);
        loop {
            let (r, _, _) = residual(hi, &mut iterations)?;
            if r <= 0.0 {
                break;
            }
            lo = hi;
            hi *= 2.0;
            if !hi.is_finite() {
                return Err(format!("R2 (k/k_c {k_ratio}, VΔt/L {courant}): no root"));
            }
        }
        let mut dx = 0.5 * (lo + hi);
        let mut answer = None;
        for _ in 0..200 {
            let (r, slope, t) = residual(dx, &mut iterations)?;
            if r.abs() <= 1e-12 * t.tau[0].abs().max(1.0) || hi - lo <= 4.0 * f64::EPSILON * hi {
                answer = Some(t);
                break;
            }
            if r > 0.0 {
                lo = dx
            } else {
                hi = dx
            }
            let newton = dx - r / slope;
            dx = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
        }
        let Some(trial) = answer else {
            return Err(format!(
                "R2 (k/k_c {k_ratio}, VΔt/L {courant}): the increment's solve did not converge"
            ));
        };
        extension = load - dx;
        c = trial;
        deviation.push((dx / dtime / v - 1.0).abs());
    }
    // The perturbation's first response (the first three increments) against the largest
    // deviation in the second half of the run.
    let initial = deviation[..3].iter().fold(0.0f64, |m, x| m.max(*x));
    let late = deviation[deviation.len() / 2..]
        .iter()
        .fold(0.0f64, |m, x| m.max(*x));
    Ok((late / initial, iterations))
}

/// One map: classes over (k/k_c, V·Δt/L).
pub struct R2Map {
    /// k/k_c of the columns.
    pub k_ratios: Vec<f64>,
    /// V·Δt/L of the rows.
    pub courants: Vec<f64>,
    /// `growth[row][col]`: late over early slip-rate deviation.
    pub growth: Vec<Vec<f64>>,
}

impl R2Map {
    fn motion(g: f64) -> Motion {
        if g > 1.0 {
            Motion::Growing
        } else {
            Motion::Steady
        }
    }

    /// The measured boundary of a row: between the largest k/k_c that grows and the next
    /// column, `None` when the row has no change of class from growing to steady.
    fn boundary(&self, row: usize) -> Option<(f64, f64)> {
        let g = &self.growth[row];
        let last_growing = (0..g.len())
            .rev()
            .find(|&i| Self::motion(g[i]) == Motion::Growing)?;
        let next = last_growing + 1;
        (next < g.len() && (next..g.len()).all(|i| Self::motion(g[i]) == Motion::Steady))
            .then(|| (self.k_ratios[last_growing], self.k_ratios[next]))
    }
}

/// The R2 map.
fn r2_map(quick: bool) -> Result<(R2Map, usize), String> {
    let k_ratios = vec![0.5, 0.7, 0.85, 0.95, 1.05, 1.2, 1.5, 2.0];
    let courants = if quick {
        vec![0.03, 1.0]
    } else {
        vec![0.01, 0.03, 0.1, 0.3, 1.0, 3.0]
    };
    let mut growth = Vec::new();
    let mut iterations = 0;
    for &c in &courants {
        let mut row = Vec::new();
        for &k in &k_ratios {
            let (g, it) = r2_run(k, c)?;
            row.push(g);
            iterations += it;
        }
        growth.push(row);
    }
    Ok((
        R2Map {
            k_ratios,
            courants,
            growth,
        },
        iterations,
    ))
}

/// Runs R1 and R2, writes `R1-*.csv`, `R2-map.csv` and their charts into `out`, and returns
/// the checked rows (each with the bound the docs quote) and the files written.
pub fn run(out: &Path, quick: bool) -> Result<(Vec<Row>, Vec<PathBuf>), String> {
    let mut rows = Vec::new();
    // R1.
    let per_l: Vec<f64> = if quick {
        vec![1.0, 10.0, 100.0]
    } else {
        vec![0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0]
    };
    let mut csv = String::from("law,increments_per_L,error_library,error_explicit_euler\n");
    let mut curves = Vec::new();
    for (slip_law, name) in [(false, "aging"), (true, "slip")] {
        let mut curve = Vec::new();
        for &n in &per_l {
            let (lib, euler) = r1_errors(slip_law, n)?;
            let _ = writeln!(csv, "{name},{n},{lib:e},{euler:e}");
            curve.push((n, lib, euler));
        }
        // The library's error is round-off at every increment size (θ exact at constant V).
        let worst = curve.iter().fold(0.0f64, |m, x| m.max(x.1));
        rows.push(Row {
            scene: "R1",
            case: format!("{name} law, 0.5-200 increments per L"),
            quantity: "max |τ/p − μ(V, θ(t))|",
            exact: 0.0,
            computed: worst,
            tolerance: 1e-12,
        });
        // The explicit update is first order: its error falls ≥ 5× per 10× increments (from
        // 10 to 100 increments per L in both sweeps).
        let at = |n: f64| curve.iter().find(|p| p.0 == n).map_or(f64::NAN, |p| p.2);
        let (coarse, fine) = (at(10.0), at(100.0));
        rows.push(Row {
            scene: "R1",
            case: format!("{name} law, explicit-Euler θ (reference)"),
            quantity: "error ratio, 10× more increments",
            exact: 10.0,
            computed: coarse / fine,
            tolerance: 5.0,
        });
        curves.push((name, curve));
    }
    let files = vec![
        out.join("R1-velocity-steps.csv"),
        out.join("R1-work-precision.svg"),
        out.join("R2-map.csv"),
        out.join("R2-map.svg"),
    ];
    std::fs::write(&files[0], csv).map_err(|e| e.to_string())?;
    r1_chart(&files[1], &curves)?;
    // R2.
    let (map, _iterations) = r2_map(quick)?;
    let mut csv = String::from("V_dt_over_L,k_over_kc,growth,class\n");
    for (r, c) in map.courants.iter().enumerate() {
        for (i, k) in map.k_ratios.iter().enumerate() {
            let g = map.growth[r][i];
            let class = match R2Map::motion(g) {
                Motion::Steady => "steady",
                Motion::Growing => "growing",
            };
            let _ = writeln!(csv, "{c},{k},{g:e},{class}");
        }
    }
    std::fs::write(&files[2], csv).map_err(|e| e.to_string())?;
    r2_chart(&files[3], &map)?;
    // The rows that resolve L (V·Δt/L ≤ 0.1): boundary within one cell of k_c = 1.
    for (r, &c) in map.courants.iter().enumerate() {
        if c > 0.1 {
            continue;
        }
        let (lo, hi) = map.boundary(r).unwrap_or((f64::NAN, f64::NAN));
        // Within one cell: the bracketing pair is (0.95, 1.05) or one of its neighbours.
        let within = (0.85..=1.05).contains(&lo) && (0.95..=1.2).contains(&hi);
        rows.push(Row {
            scene: "R2",
            case: format!("V·Δt/L = {c}: boundary between k/k_c {lo} and {hi}"),
            quantity: "boundary within one cell of k_c",
            exact: 1.0,
            computed: if within { 1.0 } else { 0.0 },
            tolerance: 0.0,
        });
    }
    Ok((rows, files))
}

/// The R1 chart's lowest error (an error of exactly 0 is drawn there).
const FLOOR: f64 = 1e-17;

/// One R1 curve: the law's name and (increments per L, library error, explicit-Euler error).
type R1Curve<'a> = (&'a str, Vec<(f64, f64, f64)>);

fn r1_chart(path: &Path, curves: &[R1Curve<'_>]) -> Result<(), String> {
    let e = |x: DrawingAreaErrorKind<std::io::Error>| x.to_string();
    let root = SVGBackend::new(path, (760, 480)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let (x0, x1) = (0.3, 400.0);
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "R1 velocity steps: error of μ at increment ends",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(64)
        .build_cartesian_2d((x0..x1).log_scale(), (FLOOR..100.0).log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("increments per L of slip")
        .y_desc("max |τ/p − μ(V, θ(t))| (0 drawn at 1e-17)")
        .x_label_formatter(&|x| format!("{x}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()
        .map_err(e)?;
    let colors = [RGBColor(31, 119, 180), RGBColor(214, 39, 40)];
    for (i, (name, curve)) in curves.iter().enumerate() {
        let color = colors[i % 2];
        // The library at round-off is drawn at max(error, FLOOR) so that 0 stays on the chart.
        chart
            .draw_series(LineSeries::new(
                curve.iter().map(|p| (p.0, p.1.max(FLOOR))),
                color.stroke_width(2),
            ))
            .map_err(e)?
            .label(format!("library, {name} law (θ exact at constant V)"))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
            });
        chart
            .draw_series(
                curve
                    .iter()
                    .map(|p| Circle::new((p.0, p.1.max(FLOOR)), 3, color.filled())),
            )
            .map_err(e)?;
        chart
            .draw_series(LineSeries::new(
                curve.iter().map(|p| (p.0, p.2)),
                ShapeStyle::from(color).stroke_width(1),
            ))
            .map_err(e)?
            .label(format!("explicit-Euler θ, {name} law (reference)"))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], color));
        chart
            .draw_series(
                curve
                    .iter()
                    .map(|p| TriangleMarker::new((p.0, p.2), 4, color)),
            )
            .map_err(e)?;
    }
    legend_and_write(&mut chart, &root)
}

/// Draws the series' legend at the upper right and writes the chart's file (R1 and R2).
fn legend_and_write<'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, SVGBackend<'a>, CT>,
    root: &DrawingArea<SVGBackend<'a>, Shift>,
) -> Result<(), String> {
    let e = |x: DrawingAreaErrorKind<std::io::Error>| x.to_string();
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(e)?;
    root.present().map_err(e)
}

/// The label of the cell whose centre is the integer nearest `at` (1-based), or none between.
fn label(values: &[f64], at: f64) -> String {
    let i = at.round();
    if (at - i).abs() > 1e-9 || i < 1.0 {
        return String::new();
    }
    values
        .get(i as usize - 1)
        .map_or(String::new(), |v| format!("{v}"))
}

fn r2_chart(path: &Path, map: &R2Map) -> Result<(), String> {
    let e = |x: DrawingAreaErrorKind<std::io::Error>| x.to_string();
    let root = SVGBackend::new(path, (760, 480)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let (nc, nr) = (map.k_ratios.len(), map.courants.len());
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "R2 spring-slider: steady (green) or growing (red) against k/k_c and V·Δt/L",
            ("sans-serif", 16),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(64)
        // Cell i spans [i + 0.5, i + 1.5]: the integer ticks fall on the cell centres.
        .build_cartesian_2d(0.5f64..nc as f64 + 0.5, 0.5f64..nr as f64 + 0.5)
        .map_err(e)?;
    let ks = map.k_ratios.clone();
    let cs = map.courants.clone();
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(nc)
        .y_labels(nr)
        .x_label_formatter(&move |x| label(&ks, *x))
        .y_label_formatter(&move |y| label(&cs, *y))
        .x_desc("k/k_c (spring stiffness over the critical stiffness)")
        .y_desc("V·Δt/L (increment over the state's slip scale)")
        .draw()
        .map_err(e)?;
    for r in 0..nr {
        for i in 0..nc {
            let color = match R2Map::motion(map.growth[r][i]) {
                Motion::Steady => RGBColor(44, 160, 44),
                Motion::Growing => RGBColor(214, 39, 40),
            };
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [
                        (i as f64 + 0.54, r as f64 + 0.54),
                        (i as f64 + 1.46, r as f64 + 1.46),
                    ],
                    color.mix(0.7).filled(),
                )))
                .map_err(e)?;
        }
    }
    // k = k_c lies between the columns 0.95 and 1.05.
    let x = map.k_ratios.iter().position(|&k| k > 1.0).unwrap_or(nc) as f64 + 0.5;
    chart
        .draw_series(std::iter::once(PathElement::new(
            vec![(x, 0.5), (x, nr as f64 + 0.5)],
            BLACK.stroke_width(3),
        )))
        .map_err(e)?
        .label("k = k_c = p(b − a)/L (linear theory)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], BLACK.stroke_width(3)));
    legend_and_write(&mut chart, &root)
}
