//! F7, steady sliding under velocity weakening (`docs/scene-definitions.md`): one point
//! driven at a constant slip velocity v with increments Δγ = r·γ_crit at constant pressure p,
//! law 1 with the exponential decay law μ(v) = μ_k + (μ_s − μ_k)·exp(−d_c·v). The answer is
//! steady sliding at τ = μ(v)·p for every r. Compared: the library's formulation (rate-following
//! stick stiffness, through `fric_`) and the earlier one (rate-free stick stiffness, Rust API
//! `RateFormulation::RateFreeStiffness`, kept for this comparison only).
//!
//! 1. Error of the mean friction against r, per formulation (d_c·v = 1 and 3).
//! 2. Stability map over (r, d_c·v), per formulation, with the earlier formulation's closed-form
//!    boundaries drawn: its slip equation is stable only for r > 2c·x·e^(−x) (x = d_c·v,
//!    c = 1 − μ_k/μ_s; docs/props.md), and its memoryless stick test sticks whenever
//!    μ(v)·p + k_s·Δγ ≤ μ_s·p, i.e. r ≤ c·(1 − e^(−x)).
//! 3. F6 (block on a belt, spring to a wall) with the decay law: genuine stick-slip, implicit
//!    (backward Euler) steps with Newton iterations on `fric_`'s stress and tangent, coarse
//!    steps against a fine-step reference; the Newton iterations per increment with the exact
//!    tangent and with a bounded one (the negative rate term dropped), near the slip onsets and
//!    overall.
//!
//! Every claim is a check row (`checks.csv`, scene F7) that fails when the data stop supporting
//! it.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use interfacial::laws::contact::Conditions;
use interfacial::laws::contact::{Contact, Increment};
use interfacial::laws::coulomb::Coulomb;
use interfacial::laws::coulomb_extended::{ExtendedCoulomb, ExtendedState};
use interfacial::laws::friction_coefficient::{CoefficientLaw, RateFormulation};
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::FricCall;
use plotters::prelude::*;

use crate::charts::{
    Axis, COLORS, Frame, Marker, Swatch, draw_cells, edge, frame as frame_chart, frame_linear,
};
use crate::checks::{Row, slide};

const MU_S: f64 = 0.5;
const MU_K: f64 = 0.2;
const D_C: f64 = 200.0;
const P: f64 = 100.0;
const GAMMA_CRIT: f64 = 1e-3;
/// c = 1 − μ_k/μ_s.
const C: f64 = 1.0 - MU_K / MU_S;

/// Which return map.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Formulation {
    /// The library's (`fric_`): rate-following stick stiffness.
    RateFollowing,
    /// The earlier one (Rust API): rate-free stick stiffness, memoryless stick test.
    RateFree,
}

impl Formulation {
    fn name(self) -> &'static str {
        match self {
            Formulation::RateFollowing => "rate-following stiffness (fric_)",
            Formulation::RateFree => "earlier rate-free stiffness",
        }
    }
}

fn mu_p(x: f64) -> f64 {
    (MU_K + (MU_S - MU_K) * (-x).exp()) * P
}

/// The earlier formulation's bounds: slip equation stable for r > 2c·x·e^(−x); the memoryless
/// stick test lets steady sliding continue only for r > c·(1 − e^(−x)).
pub fn rate_free_bounds(x: f64) -> (f64, f64) {
    (2.0 * C * x * (-x).exp(), C * (1.0 - (-x).exp()))
}

fn decay_props() -> Vec<f64> {
    CoulombBuilder::new()
        .mu(MU_S)
        .gamma_crit(GAMMA_CRIT)
        .mu_law(1.0)
        .mu_k(MU_K)
        .decay(D_C)
        .build_first(10)
}

/// τ of `n` increments of r·γ_crit at the slip velocity v = x/d_c, from rest.
fn drive(f: Formulation, x: f64, r: f64, n: usize) -> Result<Vec<f64>, String> {
    let v = x / D_C;
    let dgam = r * GAMMA_CRIT;
    let dtime = dgam / v;
    let mut taus = Vec::with_capacity(n);
    match f {
        Formulation::RateFollowing => {
            let mut c = FricCall::new(1, &decay_props());
            c.press = P;
            for _ in 0..n {
                slide(&mut c, dgam, dtime, "F7")?;
                taus.push(c.tau[0]);
            }
        }
        Formulation::RateFree => {
            let law = ExtendedCoulomb::new(
                Coulomb::new(MU_S)
                    .and_then(|c| c.with_critical_slip_absolute(GAMMA_CRIT))
                    .map_err(|e| e.to_string())?,
            )
            .with_coefficient_law(
                CoefficientLaw::default()
                    .with_exponential_decay(MU_K / MU_S, D_C)
                    .map_err(|e| e.to_string())?,
            )
            .with_rate_formulation(RateFormulation::RateFreeStiffness);
            let (mut tau, mut state) = (0.0, ExtendedState::<1>::default());
            for _ in 0..n {
                // At constant P; γ_crit is absolute, so no characteristic length is read.
                let inc = Increment::<1> {
                    tau: [tau],
                    dgam: [dgam],
                    pressure: P,
                    dtime,
                    ..Increment::default()
                };
                let up = law
                    .update(&inc, &Conditions::default(), &state)
                    .map_err(|e| format!("F7: earlier formulation refused: {e}"))?;
                let Contact::Motion(t) = up.contact else {
                    return Err("F7: exact stick in elastic stick".into());
                };
                tau = t.tau[0];
                state = up.state;
                taus.push(tau);
            }
        }
    }
    Ok(taus)
}

/// Increments to load from rest and slide long enough to judge.
fn length(r: f64) -> usize {
    (1.5 / r).ceil() as usize + 300
}

/// Round-off for the steady-sliding stress: a few hundred ulp of μ(v)p, relative. The
/// rate-following formulation is held to it at every increment of the steady window; the
/// measured largest deviation is about 1e-15.
pub const ROUND_OFF: f64 = 1e-13;

/// Over the last 200 increments: |mean τ − μ(v)p|/(μ(v)p), and the largest |τ − μ(v)p|/(μ(v)p)
/// of any one increment.
fn tail_errors(f: Formulation, x: f64, r: f64) -> Result<(f64, f64), String> {
    let taus = drive(f, x, r, length(r))?;
    let tail = &taus[taus.len() - 200..];
    let exact = mu_p(x);
    let mean = tail.iter().sum::<f64>() / tail.len() as f64;
    let largest = tail
        .iter()
        .map(|t| (t - exact).abs() / exact)
        .fold(0.0, f64::max);
    Ok(((mean - exact).abs() / exact, largest))
}

fn mean_error(f: Formulation, x: f64, r: f64) -> Result<f64, String> {
    tail_errors(f, x, r).map(|(mean, _)| mean)
}

/// The largest |τ − μ(v)p|/(μ(v)p) over the last 100 increments; a cell settles when it is
/// within 10⁻⁶ (the earlier formulation's cycles are far larger).
fn tail_deviation(f: Formulation, x: f64, r: f64) -> Result<f64, String> {
    let taus = drive(f, x, r, length(r))?;
    let exact = mu_p(x);
    Ok(taus[taus.len() - 100..]
        .iter()
        .map(|t| (t - exact).abs() / exact)
        .fold(0.0, f64::max))
}

fn log_space(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a * (b / a).powf(i as f64 / (n - 1).max(1) as f64))
        .collect()
}

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

fn row(case: String, quantity: &'static str, exact: f64, computed: f64, tolerance: f64) -> Row {
    Row {
        scene: "F7",
        case,
        quantity,
        exact,
        computed,
        tolerance,
    }
}

/// Part 1: error of the mean friction against r.
fn mean_error_chart(out: &Path, quick: bool, rows: &mut Vec<Row>) -> Result<Vec<PathBuf>, String> {
    let rs = log_space(0.01, 1.0, if quick { 9 } else { 21 });
    let mut csv = String::from("x,r,formulation,mean_error,largest_error\n");
    let mut series = Vec::new();
    for x in [1.0, 3.0] {
        for f in [Formulation::RateFollowing, Formulation::RateFree] {
            let mut pts = Vec::new();
            for &r in &rs {
                let (e, largest) = tail_errors(f, x, r)?;
                let _ = writeln!(
                    csv,
                    "{x},{r:e},{},{e:e},{largest:e}",
                    crate::csvfile::field(f.name())
                );
                pts.push((r, e));
                if f == Formulation::RateFollowing {
                    rows.push(row(
                        format!("d_c·v = {x}, r = {r:.3}"),
                        "rate-following: largest |τ − μ(v)p|/μ(v)p of any increment (round-off)",
                        0.0,
                        largest,
                        ROUND_OFF,
                    ));
                }
            }
            series.push((x, f, pts));
        }
    }
    // The earlier formulation at x = 3, r = 0.25 misses by more than 1 %.
    let earlier = mean_error(Formulation::RateFree, 3.0, 0.25)?;
    rows.push(row(
        "earlier, d_c·v = 3, r = 0.25".into(),
        "earlier formulation misses μ(v)p by > 1 % (1 = yes)",
        1.0,
        f64::from(u8::from(earlier > 0.01)),
        0.0,
    ));
    // The earlier formulation against its closed-form bound r*(x) = max(2c·x·e^(−x),
    // c·(1 − e^(−x))) (docs/props.md): off by more than 1 % at every r below r*/1.2, within 1 %
    // at every r above 1.2·r* (the margins keep the grid's neighbours of r* out of the test).
    let bound_of = |x: f64| {
        let (slip, stick) = rate_free_bounds(x);
        slip.max(stick)
    };
    for x in [1.0, 3.0] {
        let bound = bound_of(x);
        let pts = series
            .iter()
            .filter(|(sx, f, _)| *sx == x && *f == Formulation::RateFree)
            .flat_map(|(_, _, pts)| pts.iter());
        let (below, above): (Vec<_>, Vec<_>) = pts.partition(|(r, _)| *r < bound);
        let wrong = below
            .iter()
            .filter(|(r, e)| *r < bound / 1.2 && *e <= 0.01)
            .count()
            + above
                .iter()
                .filter(|(r, e)| *r > bound * 1.2 && *e > 0.01)
                .count();
        rows.push(row(
            format!("earlier, d_c·v = {x}, r* = {bound:.3}"),
            "earlier formulation: points on the wrong side of its bound (r < r*/1.2 within 1 %, r > 1.2·r* off)",
            0.0,
            wrong as f64,
            0.0,
        ));
    }
    let csv_path = out.join("F7-mean-error.csv");
    std::fs::write(&csv_path, csv).map_err(|e| format!("{}: {e}", csv_path.display()))?;
    let svg = out.join("F7-mean-error.svg");
    let colors = &COLORS[..4];
    let mut legend: Vec<(Swatch, String)> = series
        .iter()
        .enumerate()
        .map(|(i, (x, f, _))| {
            (
                Swatch::Line(colors[i % colors.len()], Marker::Dot, false),
                format!("d_c·v = {x}: {}", f.name()),
            )
        })
        .collect();
    legend.push((
        Swatch::Line(BLACK, Marker::None, true),
        "1 % of μ(v)p".into(),
    ));
    // Each x's bound r* of the earlier formulation, dotted in its curve's colour.
    let bounds: Vec<(f64, RGBColor)> = series
        .iter()
        .enumerate()
        .filter(|(_, (_, f, _))| *f == Formulation::RateFree)
        .map(|(i, (x, _, _))| (bound_of(*x), colors[i % colors.len()]))
        .collect();
    for ((x, _, _), (bound, color)) in series
        .iter()
        .filter(|(_, f, _)| *f == Formulation::RateFree)
        .zip(&bounds)
    {
        legend.push((
            Swatch::Line(*color, Marker::None, true),
            format!("d_c·v = {x}: earlier formulation's bound r* = {bound:.2}"),
        ));
    }
    let zeros = series
        .iter()
        .flat_map(|(_, _, pts)| pts.iter())
        .filter(|(_, e)| *e < 1e-17)
        .count();
    let mut notes = vec![format!(
        "One point sliding at constant v (d_c·v = x) in increments Δγ = r·γ_crit, p = {P}, μ_s = {MU_S}, μ_k = {MU_K}, γ_crit = {GAMMA_CRIT}; error of the mean τ over the last 200 increments against μ(v)p."
    )];
    if zeros > 0 {
        notes.push(format!(
            "Errors below 1e-17 ({zeros} points, round-off exact) are drawn on the bottom edge at 1e-17."
        ));
    }
    let frame = Frame {
        title: "F7: error of the mean friction against the increment r",
        x: Axis::new((0.008, 1.25), "increment r = Δγ/γ_crit (–)"),
        y: Axis::new((1e-17, 10.0), "|mean τ − μ(v)p| / μ(v)p (–)"),
        top: None,
        legend,
        notes,
        size: (760, 560),
    };
    frame_chart(&svg, &frame, |chart| {
        for (i, (_, _, pts)) in series.iter().enumerate() {
            let color = colors[i % colors.len()];
            // An exact zero is drawn at the bottom of the chart.
            let pts: Vec<(f64, f64)> = pts.iter().map(|(r, e)| (*r, e.max(1e-17))).collect();
            chart
                .draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))
                .map_err(err)?;
            chart
                .draw_series(pts.iter().map(|p| Circle::new(*p, 3, color.filled())))
                .map_err(err)?;
        }
        chart
            .draw_series(DashedLineSeries::new(
                vec![(0.008, 0.01), (1.25, 0.01)],
                6,
                4,
                BLACK.stroke_width(1),
            ))
            .map_err(err)?;
        for (bound, color) in &bounds {
            chart
                .draw_series(DashedLineSeries::new(
                    vec![(*bound, 1e-17), (*bound, 10.0)],
                    3,
                    3,
                    color.stroke_width(1),
                ))
                .map_err(err)?;
        }
        Ok(())
    })?;
    Ok(vec![csv_path, svg])
}

/// Part 2: stability maps over (r, d_c·v).
fn stability_maps(out: &Path, quick: bool, rows: &mut Vec<Row>) -> Result<Vec<PathBuf>, String> {
    let (nr, nx) = if quick { (10, 7) } else { (25, 15) };
    let rs = log_space(0.01, 10.0, nr);
    let xs = log_space(0.1, 30.0, nx);
    let mut outputs = Vec::new();
    let mut csv =
        String::from("formulation,r,x,settles,largest_deviation,slip_bound,stick_bound\n");
    for f in [Formulation::RateFollowing, Formulation::RateFree] {
        let mut cells = vec![vec![false; nr]; nx];
        let mut largest = 0.0f64;
        for (j, &x) in xs.iter().enumerate() {
            for (i, &r) in rs.iter().enumerate() {
                let deviation = tail_deviation(f, x, r)?;
                largest = largest.max(deviation);
                cells[j][i] = deviation <= 1e-6;
                let (b1, b2) = rate_free_bounds(x);
                let _ = writeln!(
                    csv,
                    "{},{r:e},{x:e},{},{deviation:e},{b1:e},{b2:e}",
                    crate::csvfile::field(f.name()),
                    cells[j][i]
                );
            }
        }
        let flat = || {
            xs.iter().enumerate().flat_map(|(j, &x)| {
                rs.iter()
                    .enumerate()
                    .map(move |(i, &r)| (x, r, i, j))
                    .collect::<Vec<_>>()
            })
        };
        match f {
            Formulation::RateFollowing => {
                let unsettled = flat().filter(|&(_, _, i, j)| !cells[j][i]).count();
                rows.push(row(
                    format!("{nr}×{nx} cells, r 0.01–10, d_c·v 0.1–30"),
                    "rate-following: cells that do not settle",
                    0.0,
                    unsettled as f64,
                    0.0,
                ));
                rows.push(row(
                    format!("{nr}×{nx} cells, r 0.01–10, d_c·v 0.1–30"),
                    "rate-following: largest |τ − μ(v)p|/μ(v)p over every cell (round-off)",
                    0.0,
                    largest,
                    ROUND_OFF,
                ));
            }
            Formulation::RateFree => {
                // Necessary conditions of the closed forms: below either bound (with a margin
                // of 1.5) no cell settles; well above both, every cell does.
                let below = flat()
                    .filter(|&(x, r, i, j)| {
                        let (b1, b2) = rate_free_bounds(x);
                        (r < b1 / 1.5 || r < b2 / 1.5) && cells[j][i]
                    })
                    .count();
                let above = flat()
                    .filter(|&(x, r, i, j)| {
                        let (b1, b2) = rate_free_bounds(x);
                        r > 1.5 * b1.max(b2) && !cells[j][i]
                    })
                    .count();
                let oscillating = flat().filter(|&(_, _, i, j)| !cells[j][i]).count();
                rows.push(row(
                    "earlier, r below a closed-form bound / 1.5".into(),
                    "cells that settle (closed form: none)",
                    0.0,
                    below as f64,
                    0.0,
                ));
                rows.push(row(
                    "earlier, r above 1.5 × both bounds".into(),
                    "cells that do not settle (closed form: none)",
                    0.0,
                    above as f64,
                    0.0,
                ));
                rows.push(row(
                    "earlier, whole map".into(),
                    "cells that do not settle (> 0: the map has both classes)",
                    1.0,
                    f64::from(u8::from(oscillating > 0)),
                    0.0,
                ));
            }
        }
        let svg = out.join(match f {
            Formulation::RateFollowing => "F7-map-rate-following.svg",
            Formulation::RateFree => "F7-map-earlier.svg",
        });
        map_chart(&svg, f, &rs, &xs, &cells)?;
        outputs.push(svg);
    }
    let csv_path = out.join("F7-maps.csv");
    std::fs::write(&csv_path, csv).map_err(|e| format!("{}: {e}", csv_path.display()))?;
    outputs.push(csv_path);
    Ok(outputs)
}

fn map_chart(
    path: &Path,
    f: Formulation,
    rs: &[f64],
    xs: &[f64],
    cells: &[Vec<bool>],
) -> Result<(), String> {
    let (x0, x1) = (edge(rs, 0, false), edge(rs, rs.len() - 1, true));
    let (y0, y1) = (edge(xs, 0, false), edge(xs, xs.len() - 1, true));
    let (settle, cycle) = (COLORS[2], COLORS[3]);
    // The cells' colours at 60 % over white, as drawn.
    let pale = |c: RGBColor| {
        let m = |v: u8| (0.6 * f64::from(v) + 0.4 * 255.0).round() as u8;
        RGBColor(m(c.0), m(c.1), m(c.2))
    };
    let mut legend: Vec<(Swatch, String)> = Vec::new();
    for (label, color, ok) in [
        ("settles at μ(v)p", settle, true),
        ("cycles (does not settle)", cycle, false),
    ] {
        if cells.iter().flatten().any(|c| *c == ok) {
            legend.push((Swatch::Box(pale(color)), label.into()));
        }
    }
    legend.push((
        Swatch::Line(BLACK, Marker::None, false),
        "earlier slip equation stable: r > 2c·x·e^(−x)".into(),
    ));
    legend.push((
        Swatch::Line(BLUE, Marker::None, true),
        "earlier memoryless stick test: r > c·(1 − e^(−x))".into(),
    ));
    let frame = Frame {
        title: &format!("F7: steady sliding under weakening, {}", f.name()),
        x: Axis::new((x0, x1), "increment r = Δγ/γ_crit (–)"),
        y: Axis::new((y0, y1), "x = d_c·v (–)"),
        top: None,
        legend,
        notes: vec![
            format!(
                "Each cell: one point sliding at v = x/d_c in increments r·γ_crit (p = {P}, μ_s = {MU_S}, μ_k = {MU_K}, c = 1 − μ_k/μ_s = {C:.1}); it settles when each of the last 100 increments is within 1e-6 of μ(v)p."
            ),
            "The curves are the earlier (rate-free) formulation's closed-form bounds (docs/props.md), drawn on both maps for comparison.".into(),
        ],
        size: (760, 560),
    };
    frame_chart(path, &frame, |chart| {
        draw_cells(chart, cells, rs, xs, |ok| {
            pale(if ok { settle } else { cycle })
        })?;
        let fine = log_space(y0, y1, 200);
        let curve = |k: usize| -> Vec<(f64, f64)> {
            fine.iter()
                .map(|&x| {
                    let b = rate_free_bounds(x);
                    (if k == 0 { b.0 } else { b.1 }, x)
                })
                .filter(|(r, _)| *r >= x0 && *r <= x1)
                .collect()
        };
        chart
            .draw_series(LineSeries::new(curve(0), BLACK.stroke_width(3)))
            .map_err(err)?;
        chart
            .draw_series(DashedLineSeries::new(curve(1), 6, 4, BLUE.stroke_width(2)))
            .map_err(err)?;
        Ok(())
    })
}

/// F6 with the decay law: block m on a belt at v₀, spring k to a wall, normal force N.
#[derive(Clone, Copy)]
struct Belt {
    mass: f64,
    spring: f64,
    normal: f64,
    mu_s: f64,
    mu_k: f64,
    decay: f64,
    belt: f64,
    gamma_crit: f64,
    /// Law 2 (seed 004) with this v_½ instead of the decay law (μ_s, μ_d = μ_k, no adhesion).
    adhesive_vhalf: Option<f64>,
}

/// The belt of parts 3 and 4: k = m = N = 1, μ 0.6 → 0.5 with d_c = 20, v₀ = 0.1,
/// γ_crit = 1e-3.
const BELT: Belt = Belt {
    mass: 1.0,
    spring: 1.0,
    normal: 1.0,
    mu_s: 0.6,
    mu_k: 0.5,
    decay: 20.0,
    belt: 0.1,
    gamma_crit: 1e-3,
    adhesive_vhalf: None,
};

/// Which tangent the host's Newton iteration uses.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Tangent {
    /// `DDTDDG` as returned (the consistent tangent).
    Exact,
    /// max(`DDTDDG`, 0): the negative rate term dropped (a host-side choice).
    Bounded,
}

/// One backward-Euler run: x(t) at the end of every step, Newton iterations per step, whether
/// a step was near a slip onset (the previous or this step changed stick → slip), failures.
struct BeltRun {
    x: Vec<f64>,
    stuck: Vec<bool>,
    iterations: Vec<u32>,
    onset: Vec<bool>,
    failed: usize,
}

impl BeltRun {
    /// Mean and largest number of Newton iterations per step, over every step or over the
    /// slip-onset steps only (`onset`).
    fn newton(&self, onset: bool) -> (f64, u32) {
        let sel: Vec<u32> = self
            .iterations
            .iter()
            .zip(&self.onset)
            .filter(|(_, o)| !onset || **o)
            .map(|(i, _)| *i)
            .collect();
        let mean = sel.iter().map(|&i| f64::from(i)).sum::<f64>() / sel.len().max(1) as f64;
        (mean, sel.iter().copied().max().unwrap_or(0))
    }
}

const MAX_NEWTON: u32 = 50;

impl Belt {
    fn props(&self) -> Vec<f64> {
        if let Some(vhalf) = self.adhesive_vhalf {
            return AdhesiveBuilder::new()
                .coeff(self.mu_k)
                .coeff_static(self.mu_s)
                .vhalf(vhalf)
                .gamma_crit(self.gamma_crit)
                .build_first(8);
        }
        CoulombBuilder::new()
            .mu(self.mu_s)
            .gamma_crit(self.gamma_crit)
            .mu_law(1.0)
            .mu_k(self.mu_k)
            .decay(self.decay)
            .build_first(10)
    }

    /// Backward Euler in x and v for `t_end`, Newton on the end position with `fric_`'s
    /// stress (friction on the block, area 1) and tangent; slip Δγ = v₀Δt − Δx (the belt
    /// relative to the block).
    fn run(&self, dt: f64, t_end: f64, tangent: Tangent) -> BeltRun {
        let steps = (t_end / dt).round() as usize;
        let mut c = FricCall::new(1, &self.props());
        c.press = self.normal;
        c.dtime = dt;
        let (mut x, mut v) = (0.0, 0.0);
        let mut out = BeltRun {
            x: Vec::with_capacity(steps),
            stuck: Vec::with_capacity(steps),
            iterations: Vec::with_capacity(steps),
            onset: Vec::with_capacity(steps),
            failed: 0,
        };
        let mut was_stuck = true;
        let mut onset_before = false;
        for _ in 0..steps {
            let (tau_start, state_start) = (c.tau, c.statev.clone());
            // Predictor: the block stays where it is.
            let mut x1 = x;
            let mut iterations = 0;
            let mut converged = false;
            while iterations < MAX_NEWTON {
                iterations += 1;
                c.tau = tau_start;
                c.statev.clone_from(&state_start);
                c.dgam[0] = self.belt * dt - (x1 - x);
                c.pnewdt = 1e36;
                c.call();
                let v1 = (x1 - x) / dt;
                // m (v₁ − v)/Δt = −k x₁ + τ.
                let residual = self.mass * (v1 - v) / dt + self.spring * x1 - c.tau[0];
                let k_t = match tangent {
                    Tangent::Exact => c.ddtddg[0],
                    Tangent::Bounded => c.ddtddg[0].max(0.0),
                };
                let slope = self.mass / (dt * dt) + self.spring + k_t;
                let scale = self.mu_s * self.normal;
                if residual.abs() <= 1e-10 * scale && iterations > 1 {
                    converged = true;
                    break;
                }
                x1 -= residual / slope;
            }
            if !converged {
                out.failed += 1;
            }
            v = (x1 - x) / dt;
            x = x1;
            let stuck = c.statev[2] == 0.0;
            let onset = was_stuck && !stuck;
            out.onset.push(onset || onset_before);
            onset_before = onset;
            was_stuck = stuck;
            out.x.push(x);
            out.stuck.push(stuck);
            out.iterations.push(iterations);
        }
        out
    }
}

impl Belt {
    /// μ of the decay law at the slip rate |v_rel| (the closed form, not the library).
    fn mu_of(&self, v_rel: f64) -> f64 {
        self.mu_k + (self.mu_s - self.mu_k) * (-self.decay * v_rel.abs()).exp()
    }

    /// The independent reference: an event-driven integration of the belt equations with rigid
    /// stick (no stick spring, no library call). Stuck, the block rides the belt, x = x_s + v₀t,
    /// until k·x reaches μ_s·N; slipping, m·ẍ = −k·x + μ(v₀ − ẋ)·N (classical RK4 with step
    /// `h`), until the block is back at the belt speed, found by linear interpolation inside the
    /// step where v₀ − ẋ changes sign. Sampled every `dt` for `t_end`, like a library run.
    fn rigid_stick_reference(&self, dt: f64, t_end: f64, h: f64) -> BeltRun {
        let n = (t_end / dt).round() as usize;
        let mut out = BeltRun {
            x: Vec::with_capacity(n),
            stuck: Vec::with_capacity(n),
            iterations: Vec::new(),
            onset: Vec::new(),
            failed: 0,
        };
        let accel = |x: f64, v: f64| {
            (-self.spring * x + self.mu_of(self.belt - v) * self.normal) / self.mass
        };
        let x_release = self.mu_s * self.normal / self.spring;
        // The block sticks to the belt from t = 0 (rest on a moving belt: static friction).
        let (mut t, mut x, mut v, mut stuck) = (0.0f64, 0.0f64, self.belt, true);
        let mut next_sample = dt;
        while out.x.len() < n {
            if stuck {
                let t_release = t + (x_release - x) / self.belt;
                while out.x.len() < n && next_sample <= t_release {
                    out.x.push(x + self.belt * (next_sample - t));
                    out.stuck.push(true);
                    next_sample = (out.x.len() + 1) as f64 * dt;
                }
                x = x_release;
                t = t_release;
                v = self.belt;
                stuck = false;
            } else {
                // One RK4 step of the slip.
                let (k1x, k1v) = (v, accel(x, v));
                let (k2x, k2v) = (
                    v + 0.5 * h * k1v,
                    accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v),
                );
                let (k3x, k3v) = (
                    v + 0.5 * h * k2v,
                    accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v),
                );
                let (k4x, k4v) = (v + h * k3v, accel(x + h * k3x, v + h * k3v));
                let x1 = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
                let v1 = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
                // Slip ends when the block is back at the belt speed (from below; the first
                // step of a slip starts at it).
                let ends = v < self.belt && v1 >= self.belt;
                let s = if ends {
                    (self.belt - v) / (v1 - v)
                } else {
                    1.0
                };
                let t1 = t + s * h;
                while out.x.len() < n && next_sample <= t1 {
                    let f = (next_sample - t) / h;
                    out.x.push(x + f * (x1 - x));
                    out.stuck.push(false);
                    next_sample = (out.x.len() + 1) as f64 * dt;
                }
                if ends {
                    x += s * (x1 - x);
                    v = self.belt;
                    stuck = true;
                } else {
                    (x, v) = (x1, v1);
                }
                t = t1;
            }
        }
        out
    }
}

/// x_max, x_min over the second half, the mean period there (between downward crossings of
/// the middle of [x_min, x_max]: the slips, which are fast; the penalty spring's ringing after
/// a stick makes several stick/slip changes per cycle, so onsets are not counted), and the
/// fraction of steps stuck.
fn cycle_measures(run: &BeltRun, dt: f64) -> (f64, f64, f64, f64) {
    let n = run.x.len();
    let half = &run.x[n / 2..];
    let xmax = half.iter().copied().fold(f64::MIN, f64::max);
    let xmin = half.iter().copied().fold(f64::MAX, f64::min);
    let mid = 0.5 * (xmax + xmin);
    let crossings: Vec<usize> = (n / 2 + 1..n)
        .filter(|&i| run.x[i - 1] >= mid && run.x[i] < mid)
        .collect();
    let period = if crossings.len() >= 2 {
        (crossings[crossings.len() - 1] - crossings[0]) as f64 * dt / (crossings.len() - 1) as f64
    } else {
        f64::NAN
    };
    let stuck = run.stuck[n / 2..].iter().filter(|s| **s).count() as f64 / (n - n / 2) as f64;
    (xmax, xmin, period, stuck)
}

/// Part 3: F6 with velocity weakening, and the Newton iterations.
fn belt(out: &Path, rows: &mut Vec<Row>) -> Result<(Vec<PathBuf>, String), String> {
    let b = BELT;
    let t_end = 40.0;
    // The reference is not the library: an event-driven rigid-stick integration of the same
    // equations (RK4 step 1e-4 s in the slips, sampled every 1e-3 s).
    let reference_dt = 1e-3;
    let reference = b.rigid_stick_reference(reference_dt, t_end, 1e-4);
    let (rmax, rmin, rperiod, rstuck) = cycle_measures(&reference, reference_dt);
    let amplitude = (b.mu_s - b.mu_k) * b.normal / b.spring;
    rows.push(row(
        "event-driven rigid-stick reference".into(),
        "genuine stick-slip: x_max − x_min over A = (μ_s − μ_k)N/k (1–5)",
        3.0,
        (rmax - rmin) / amplitude,
        2.0,
    ));
    rows.push(row(
        "event-driven rigid-stick reference".into(),
        "genuine stick-slip: fraction of time stuck (0.1–0.5)",
        0.3,
        rstuck,
        0.2,
    ));
    let mut csv = String::from(
        "dt,tangent,x_max,x_min,period,stuck_fraction,newton_mean,newton_max,newton_mean_onset,newton_max_onset,unconverged\n",
    );
    let mut table = String::from(
        "| Δt | tangent | x_max − ref | x_min − ref | period − ref | Newton mean | max | mean near onset | max near onset | unconverged |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut traces = vec![(
        "event-driven rigid-stick reference (not the library), dashed".to_string(),
        reference_dt,
        reference.x.clone(),
    )];
    let decay_runs = b.grid_runs(t_end);
    for g in &decay_runs {
        let (dt, tangent, run) = (g.dt, g.tangent, &g.run);
        let (xmax, xmin, period, stuck) = cycle_measures(run, dt);
        let ((mean, max), (omean, omax)) = (g.all, g.onset);
        let _ = writeln!(
            csv,
            "{dt},{tangent:?},{xmax:e},{xmin:e},{period:e},{stuck:e},{mean},{max},{omean},{omax},{}",
            run.failed
        );
        let _ = writeln!(
            table,
            "| {dt} | {tangent:?} | {:+.4} | {:+.4} | {:+.3} | {mean:.2} | {max} | {omean:.2} | {omax} | {} |",
            xmax - rmax,
            xmin - rmin,
            period - rperiod,
            run.failed
        );
        if tangent == Tangent::Exact {
            let case = format!("Δt = {dt}, exact tangent");
            if dt <= 0.02 {
                rows.push(row(
                    case.clone(),
                    "Newton: unconverged steps",
                    0.0,
                    run.failed as f64,
                    0.0,
                ));
                // Coarse steps keep the stick-slip cycle of the rigid-stick reference.
                rows.push(row(
                    case.clone(),
                    "x_max against the rigid-stick reference, over A",
                    0.0,
                    (xmax - rmax) / amplitude,
                    0.05,
                ));
                rows.push(row(
                    case.clone(),
                    "x_min against the rigid-stick reference, over A",
                    0.0,
                    (xmin - rmin) / amplitude,
                    0.1,
                ));
                rows.push(row(
                    case,
                    "period against the rigid-stick reference, relative",
                    0.0,
                    (period - rperiod) / rperiod,
                    0.05,
                ));
            }
            traces.push((format!("Δt = {dt} s, exact tangent"), dt, run.x.clone()));
        }
    }
    let csv_path = out.join("F7-belt.csv");
    std::fs::write(&csv_path, csv).map_err(|e| format!("{}: {e}", csv_path.display()))?;
    // The traces drawn on the chart: x(t) of the reference (every 0.01 s) and of each coarse run
    // (every step).
    let mut trace_csv = String::from("trace,t,x\n");
    for (k, (label, dt, xs)) in traces.iter().enumerate() {
        let stride = if k == 0 { 10 } else { 1 };
        for (i, x) in xs.iter().enumerate().skip(stride - 1).step_by(stride) {
            let _ = writeln!(
                trace_csv,
                "{},{:e},{x:e}",
                crate::csvfile::field(label),
                (i + 1) as f64 * dt
            );
        }
    }
    let traces_path = out.join("F7-belt-traces.csv");
    std::fs::write(&traces_path, trace_csv)
        .map_err(|e| format!("{}: {e}", traces_path.display()))?;
    let svg = out.join("F7-belt.svg");
    let colors = [BLACK, COLORS[0], COLORS[1], COLORS[2]];
    let legend = traces
        .iter()
        .enumerate()
        .map(|(k, (label, _, _))| {
            (
                Swatch::Line(colors[k % colors.len()], Marker::None, k == 0),
                label.clone(),
            )
        })
        .collect();
    let frame = Frame {
        title: "F7: F6 with velocity-weakening μ (decay law), implicit steps",
        x: Axis::new((0.0, t_end), "time t (s)"),
        y: Axis::new((0.0, 0.75), "block position x (m)"),
        top: None,
        legend,
        notes: vec![
            format!(
                "Block m = {} kg on a belt at v₀ = {} m/s, spring k = {} N/m to a wall, N = {} N, μ_s = {}, μ_k = {}, d_c = {} s/m, γ_crit = {} m; backward Euler with Newton iterations on fric_'s stress and tangent.",
                b.mass, b.belt, b.spring, b.normal, b.mu_s, b.mu_k, b.decay, b.gamma_crit
            ),
            "Reference (black, dashed, drawn on top): event-driven integration of the same equations with rigid stick, independent of the library. For Δt ≤ 0.02 s the cycle's x_max, x_min and period are check rows against it (F7 in checks.csv); every trace is in F7-belt-traces.csv.".into(),
        ],
        size: (860, 500),
    };
    frame_linear(&svg, &frame, |chart| {
        // The coarse runs first, the reference dashed on top of them.
        for (k, (_, dt, xs)) in traces
            .iter()
            .enumerate()
            .skip(1)
            .chain(traces.iter().enumerate().take(1))
        {
            let color = colors[k % colors.len()];
            let stride = (xs.len() / 4000).max(1);
            let pts: Vec<(f64, f64)> = xs
                .iter()
                .enumerate()
                .step_by(stride)
                .map(|(i, x)| ((i + 1) as f64 * dt, *x))
                .collect();
            if k == 0 {
                chart
                    .draw_series(DashedLineSeries::new(pts, 5, 4, color.stroke_width(1)))
                    .map_err(err)?;
            } else {
                chart
                    .draw_series(LineSeries::new(pts, color.stroke_width(2)))
                    .map_err(err)?;
            }
        }
        Ok(())
    })?;
    // The same belt with the adhesive law and a small v_½ (a steep onset
    // drop, strongly negative tangent): Newton iterations only.
    let _ = writeln!(
        table,
        "\nAdhesive law (seed 004), μ_s 0.6, μ_d 0.5, v_½ = 0.005, same belt:\n\n| Δt | tangent | Newton mean | max | mean near onset | max near onset | unconverged |\n|---|---|---:|---:|---:|---:|---:|"
    );
    let a = Belt {
        adhesive_vhalf: Some(0.005),
        ..b
    };
    let adhesive_runs = a.grid_runs(t_end);
    for g in &adhesive_runs {
        let _ = writeln!(
            table,
            "| {} | {:?} | {:.2} | {} | {:.2} | {} | {} |",
            g.dt, g.tangent, g.all.0, g.all.1, g.onset.0, g.onset.1, g.run.failed
        );
        // Measured: 2 steps of 2000 at Δt = 0.02 (slip → stick, not onsets) and 9 at 0.05 do
        // not converge in 50 iterations (a host cuts back there); claimed from 0.01 down.
        if g.tangent == Tangent::Exact && g.dt <= 0.01 {
            rows.push(row(
                format!("adhesive v_½ = 0.005, Δt = {}, exact tangent", g.dt),
                "Newton: unconverged steps",
                0.0,
                g.run.failed as f64,
                0.0,
            ));
        }
    }
    // Mean Newton iterations, exact against bounded tangent (docs/props.md: the exact tangent
    // stays the default because it needs fewer on average at every step; near the onsets from
    // Δt = 0.02 down). Unconverged steps are not compared: at the coarsest steps the exact
    // tangent can leave more of them (the table).
    let comparisons: [Comparison; 2] = [
        (
            &[0.05, 0.02, 0.01],
            "Newton mean over every step: exact tangent needs fewer than bounded (1 = yes)",
            |g| g.all.0,
        ),
        (
            &[0.02, 0.01],
            "Newton near onset: exact tangent needs fewer iterations than bounded (1 = yes)",
            |g| g.onset.0,
        ),
    ];
    for (law, runs) in [("decay", &decay_runs), ("adhesive", &adhesive_runs)] {
        for (dts, quantity, mean) in comparisons {
            for &dt in dts {
                let of = |t: Tangent| {
                    runs.iter()
                        .find(|g| g.dt == dt && g.tangent == t)
                        .map_or(f64::NAN, mean)
                };
                rows.push(row(
                    format!("{law}, Δt = {dt}"),
                    quantity,
                    1.0,
                    f64::from(u8::from(of(Tangent::Exact) < of(Tangent::Bounded))),
                    0.0,
                ));
            }
        }
    }
    Ok((vec![csv_path, traces_path, svg], table))
}

/// A Newton comparison of the exact and bounded tangents: the steps Δt compared, the quantity
/// it checks, and the mean it reads off a run.
type Comparison = (&'static [f64], &'static str, fn(&GridRun) -> f64);

/// The steps of the F7 Newton tables, in table order: Δt = 0.05, 0.02, 0.01, each with the exact
/// and then the bounded tangent.
fn step_grid() -> impl Iterator<Item = (f64, Tangent)> {
    [0.05, 0.02, 0.01]
        .into_iter()
        .flat_map(|dt| [Tangent::Exact, Tangent::Bounded].map(|tangent| (dt, tangent)))
}

/// A belt run at one step of [`step_grid`] with its Newton iterations per step, (mean, max)
/// over every step and over the steps near a slip onset.
struct GridRun {
    dt: f64,
    tangent: Tangent,
    run: BeltRun,
    all: (f64, u32),
    onset: (f64, u32),
}

impl Belt {
    /// One run per step of [`step_grid`], in table order.
    fn grid_runs(&self, t_end: f64) -> Vec<GridRun> {
        step_grid()
            .map(|(dt, tangent)| {
                let run = self.run(dt, t_end, tangent);
                let (all, onset) = (run.newton(false), run.newton(true));
                GridRun {
                    dt,
                    tangent,
                    run,
                    all,
                    onset,
                }
            })
            .collect()
    }
}

/// Runs F7: check rows, and the charts and CSV written to `out`. Returns the rows, the files
/// written and the Newton table (markdown) for the summary.
pub fn run(out: &Path, quick: bool) -> Result<(Vec<Row>, Vec<PathBuf>, String), String> {
    let mut rows = Vec::new();
    let mut outputs = mean_error_chart(out, quick, &mut rows)?;
    outputs.extend(stability_maps(out, quick, &mut rows)?);
    let (files, table) = belt(out, &mut rows)?;
    outputs.extend(files);
    numerical_or_physical(&mut rows)?;
    Ok((rows, outputs, table))
}

/// Part 4, "γ_crit: numerical or physical?" (docs/scenes.md): one compliance of 1e-3 m with the
/// belt's velocity-weakening law (μ_s 0.6, μ_k 0.5, d_c = 20, N = 1, v₀ = 0.1), two ways.
/// (a) As γ_crit, the stick penalty, the point driven at v₀: the default formulation slides
/// steadily at μ(v₀)·N, to round-off — the penalty gives no stick-slip. (b) As a spring in the
/// host, k_c = μ_s·N/1e-3, with a small mass (1e-3) and γ_crit = 1e-6: genuine stick-slip, its
/// cycle that of an event-driven rigid-stick integration of the same equations.
fn numerical_or_physical(rows: &mut Vec<Row>) -> Result<(), String> {
    let compliance = 1e-3;
    let base = Belt {
        gamma_crit: compliance,
        ..BELT
    };
    // (a) The point driven at v₀ through fric_ alone, Δt = 1e-3 (increments of 0.1·γ_crit).
    let mut c = FricCall::new(1, &base.props());
    c.press = base.normal;
    let dt = 1e-3;
    let mut taus = Vec::new();
    for _ in 0..2000 {
        slide(&mut c, base.belt * dt, dt, "F7")?;
        taus.push(c.tau[0]);
    }
    let steady = base.mu_of(base.belt) * base.normal;
    let deviation = taus[taus.len() - 100..]
        .iter()
        .map(|t| (t - steady).abs() / steady)
        .fold(0.0, f64::max);
    rows.push(row(
        "compliance 1e-3 m as γ_crit, driven at v₀".into(),
        "steady sliding: largest |τ − μ(v₀)N|/μ(v₀)N, last 100 increments (round-off)",
        0.0,
        deviation,
        ROUND_OFF,
    ));
    // (b) The same compliance as a host spring, γ_crit small.
    let physical = Belt {
        mass: 1e-3,
        spring: base.mu_s * base.normal / compliance,
        gamma_crit: 1e-6,
        ..base
    };
    let (dt, t_end) = (1e-5, 0.05);
    let run = physical.run(dt, t_end, Tangent::Exact);
    let reference = physical.rigid_stick_reference(dt, t_end, 1e-6);
    let (xmax, xmin, period, stuck) = cycle_measures(&run, dt);
    let (rmax, rmin, rperiod, _) = cycle_measures(&reference, dt);
    let amplitude = (physical.mu_s - physical.mu_k) * physical.normal / physical.spring;
    let case =
        || "compliance 1e-3 m as a host spring, m = 1e-3, γ_crit = 1e-6, Δt = 1e-5".to_string();
    rows.push(row(
        case(),
        "stick-slip: x_max − x_min over A = (μ_s − μ_k)N/k_c (1–5)",
        3.0,
        (xmax - xmin) / amplitude,
        2.0,
    ));
    rows.push(row(
        case(),
        "stick-slip: fraction of time stuck (0.1–0.5)",
        0.3,
        stuck,
        0.2,
    ));
    rows.push(row(
        case(),
        "x_max against the rigid-stick reference, over A",
        0.0,
        (xmax - rmax) / amplitude,
        0.05,
    ));
    rows.push(row(
        case(),
        "x_min against the rigid-stick reference, over A",
        0.0,
        (xmin - rmin) / amplitude,
        0.1,
    ));
    rows.push(row(
        case(),
        "period against the rigid-stick reference, relative",
        0.0,
        (period - rperiod) / rperiod,
        0.05,
    ));
    Ok(())
}
