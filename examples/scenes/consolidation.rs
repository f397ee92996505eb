//! Scene P1 in the main job: the two-layer column of `column.rs` joined by the interface
//! pore-pressure kernel. Closed-form check rows (steady seepage to round-off, the transient
//! column against the series solution and against the column meshed without an interface), a
//! work-precision study over Δt and the element count (the fastest of repeated runs), and
//! where the time stepping stops giving a monotone pressure (spatial oscillation of equal-order
//! u–p elements for small c·Δt/Δz²).
//!
//! Writes `<out>/<id>-u.csv` (columns `time,depth,u,u_series,u_no_interface`: excess pore
//! pressure at the file's depths and times), `<out>/<id>-U.csv` (`time,U,U_series,
//! U_no_interface`: degree of consolidation by settlement), `<out>/<id>-work-precision.csv`,
//! `<out>/<id>-stability.csv` and four SVG charts (error against Δt, elements and wall time; the
//! first-step overshoot against c·Δt/Δz²); the rows join the main job's checks.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Deserialize;

use crate::checks::Row;
use crate::column::{
    Column, Join, Series, consolidate, early_degree, early_time, steady, terzaghi,
};
use crate::scene::Point;

/// The built-in P1 file.
pub const BUILT_IN: (&str, &str) = ("data/p1.toml", include_str!("data/p1.toml"));

/// A P1 scene file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct P1File {
    /// Short id (file names).
    pub id: String,
    /// Title for charts.
    pub title: String,
    /// The column.
    pub column: Column,
    /// Allowed max(|u − u_series|/q₀, |U − U_series|) at the file's Δt and mesh.
    pub tolerance: f64,
    /// Steady seepage with p held at top and base (optional).
    pub steady: Option<SteadySpec>,
    /// Work-precision and stability study (optional).
    pub study: Option<Study>,
}

/// `[steady]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SteadySpec {
    /// p at the top.
    pub p_top: f64,
    /// p at the base.
    pub p_base: f64,
}

/// `[study]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Study {
    /// Δt of the time sweep.
    pub dts: Vec<f64>,
    /// Δt of the time sweep with `--quick`.
    pub quick_dts: Vec<f64>,
    /// Mesh refinement (multiple of the file's element counts) of the time sweep.
    pub dt_sweep_refine: usize,
    /// Mesh refinements of the element sweep.
    pub refines: Vec<usize>,
    /// Mesh refinements of the element sweep with `--quick`.
    pub quick_refines: Vec<usize>,
    /// Δt of the element sweep.
    pub refine_sweep_dt: f64,
    /// Runs per point (the fastest wall time is kept).
    pub repeats: usize,
    /// Observed order in Δt between the two smallest steps must lie in this range.
    pub dt_order: [f64; 2],
    /// Observed order in the element size between the two coarsest meshes must lie here.
    pub mesh_order: [f64; 2],
    /// c₁·Δt/Δz₁² of the stability sweep (one step on the file's mesh).
    pub stability_ratios: Vec<f64>,
}

/// Parses and checks a P1 file.
pub fn parse(text: &str, origin: &str) -> Result<P1File, String> {
    let f: P1File = toml::from_str(text).map_err(|e| format!("{origin}: {e}"))?;
    f.column.validate().map_err(|e| format!("{origin}: {e}"))?;
    if !(f.tolerance.is_finite() && f.tolerance > 0.0) {
        return Err(format!("{origin}: tolerance = {} must be > 0", f.tolerance));
    }
    if let Some(s) = &f.study {
        if s.repeats == 0 || s.dt_sweep_refine == 0 || s.refines.contains(&0) {
            return Err(format!(
                "{origin}: study: repeats and refinements must be ≥ 1"
            ));
        }
        if s.dts
            .iter()
            .chain(&s.quick_dts)
            .any(|d| d.is_nan() || *d <= 0.0)
            || s.refine_sweep_dt.is_nan()
            || s.refine_sweep_dt <= 0.0
        {
            return Err(format!("{origin}: study: every Δt must be > 0"));
        }
    }
    Ok(f)
}

/// Whether `text` is a P1 file (it has a `[column]` table).
pub fn is_p1(text: &str) -> bool {
    text.parse::<toml::Table>()
        .is_ok_and(|t| t.contains_key("column"))
}

/// Errors of one run against the series: (max |u − u_s|/q₀, max |U − U_s|).
fn errors(f: &P1File, series: &Series, u: &[Vec<f64>], degree: &[f64]) -> (f64, f64) {
    let c = &f.column;
    let mut eu = 0.0f64;
    for (row, &z) in c.depths.iter().enumerate() {
        for (col, &t) in c.times.iter().enumerate() {
            eu = eu.max((u[row][col] - series.pressure(z, t)).abs() / c.load);
        }
    }
    let e_degree = c
        .times
        .iter()
        .zip(degree)
        .map(|(&t, d)| (d - series.degree(t)).abs())
        .fold(0.0, f64::max);
    (eu, e_degree)
}

/// The fastest wall time of `repeats` runs, the range, and the last run's result.
fn timed<T>(repeats: usize, mut run: impl FnMut() -> T) -> (f64, [f64; 2], T) {
    let mut times = Vec::with_capacity(repeats);
    let mut last = None;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        last = Some(run());
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let fastest = times[0];
    let range = [times[0], times[times.len() - 1]];
    match last {
        Some(v) => (fastest, range, v),
        None => unreachable!("at least one run"),
    }
}

/// What the P1 run produced.
pub struct Outcome {
    /// Check rows.
    pub rows: Vec<Row>,
    /// Files written.
    pub outputs: Vec<PathBuf>,
    /// Failures other than check rows (I/O, a refused kernel call).
    pub failures: usize,
    /// The run's summary, stability brackets and work-precision table (printed with
    /// `--verbose`).
    pub report: String,
}

/// An observed order of convergence against the scene file's band `[lo, hi]`: its middle, within
/// half its width.
fn order_row(
    rows: &mut Vec<Row>,
    case: String,
    quantity: &'static str,
    observed: f64,
    [lo, hi]: [f64; 2],
) {
    row(
        rows,
        case,
        quantity,
        0.5 * (lo + hi),
        observed,
        0.5 * (hi - lo),
    );
}

fn row(rows: &mut Vec<Row>, case: String, quantity: &'static str, exact: f64, got: f64, tol: f64) {
    rows.push(Row {
        scene: "P1",
        case,
        quantity,
        exact,
        computed: got,
        tolerance: tol,
    });
}

/// Runs a P1 file: checks, CSV, study (unless `quick` drops it to its quick lists).
pub fn run(f: &P1File, quick: bool, out: &Path) -> Result<Outcome, String> {
    let mut rows = Vec::new();
    let mut outputs = Vec::new();
    let mut failures = 0;
    let c = &f.column;
    let id = &f.id;

    // Steady seepage: q = Δp/(H₁/k₁ + H₂/k₂), linear in each layer, continuous flux.
    if let Some(s) = &f.steady {
        let st = steady(c, s.p_top, s.p_base)?;
        let [l1, l2] = &c.layers;
        let resistance = l1.thickness / l1.permeability + l2.thickness / l2.permeability;
        let q = (s.p_top - s.p_base) / resistance;
        let scale = q.abs().max(f64::MIN_POSITIVE);
        row(
            &mut rows,
            "steady seepage".into(),
            "flux q̂/2 across the interface",
            q,
            st.interface_flux(),
            1e-12 * scale,
        );
        let worst = st
            .element_fluxes()
            .into_iter()
            .fold(q, |w, v| if (v - q).abs() > (w - q).abs() { v } else { w });
        // Each element flux is k·(p₁ − p₀)/ℓ: the nodal pressures' round-off (a few ulp of the
        // largest |p|) divided by a short element can exceed 1e-12·q on a fine mesh of a stiff
        // contrast; 64 ulp of the largest k·|p|/ℓ is the data's round-off scale.
        let p_max = s.p_top.abs().max(s.p_base.abs());
        let flux_round_off = 64.0 * f64::EPSILON * st.largest_conductance() * p_max;
        row(
            &mut rows,
            "steady seepage".into(),
            "worst element flux -k dp/dz",
            q,
            worst,
            1e-12 * scale + flux_round_off,
        );
        let p_interface = s.p_top - q * l1.thickness / l1.permeability;
        let dp = (s.p_top - s.p_base).abs().max(f64::MIN_POSITIVE);
        let (mut worst_p, mut worst_exact) = (p_interface, p_interface);
        for (z, p) in st.nodal_pressures() {
            let exact = if z <= l1.thickness {
                s.p_top - q * z / l1.permeability
            } else {
                p_interface - q * (z - l1.thickness) / l2.permeability
            };
            if (p - exact).abs() > (worst_p - worst_exact).abs() {
                worst_p = p;
                worst_exact = exact;
            }
        }
        row(
            &mut rows,
            "steady seepage".into(),
            "worst nodal pressure (linear per layer)",
            worst_exact,
            worst_p,
            1e-12 * dp,
        );
        if let Some((p1, p2, _)) = st.mesh.interface_state(&st.x) {
            row(
                &mut rows,
                "steady seepage".into(),
                "p1 at the interface",
                p_interface,
                p1,
                1e-12 * dp,
            );
            row(
                &mut rows,
                "steady seepage".into(),
                "p2 at the interface",
                p_interface,
                p2,
                1e-12 * dp,
            );
        }
        row(
            &mut rows,
            "steady seepage".into(),
            "Newton: |R| after / before the update",
            0.0,
            st.newton_reduction,
            1e-12,
        );
    }

    // The series itself against Terzaghi's single layer: both layers alike (same k and M).
    {
        let mut same = c.clone();
        same.layers[1].permeability = same.layers[0].permeability;
        same.layers[1].modulus = same.layers[0].modulus;
        let h = same.height();
        let (d, z) = if same.bottom == crate::column::Drainage::Drained {
            (h / 2.0, h / 4.0)
        } else {
            (h, h / 2.0)
        };
        let cv = same.layers[0].cv();
        let t = 0.1 * d * d / cv;
        let series = Series::new(&same, t)?;
        let zz = if same.top == crate::column::Drainage::Undrained {
            h - z
        } else {
            z
        };
        row(
            &mut rows,
            "series, both layers alike".into(),
            "u(z, T_v = 0.1) / q0 vs Terzaghi",
            terzaghi(z / d, 0.1),
            series.pressure(zz, t) / same.load,
            1e-9,
        );
    }

    // No eigenvalue missed: at an early time the series' degree of consolidation equals the
    // error-function solution of the drained faces (every term matters there).
    {
        let t = early_time(c);
        let early = Series::new(c, t)?;
        row(
            &mut rows,
            format!("series at t = {t:.1e}, {} terms", early.terms()),
            "U vs erfc solution at the drained faces",
            early_degree(c, t),
            early.degree(t),
            1e-9,
        );
    }

    // Transient step load at the file's Δt and mesh, with and without the interface.
    let t_min = c.times.iter().copied().fold(c.end, f64::min);
    let series = Series::new(c, t_min)?;
    let with = consolidate(c, Join::Interface, 1, c.dt, true)?;
    let without = consolidate(c, Join::Shared, 1, c.dt, false)?;
    let (eu, e_degree) = errors(f, &series, &with.u, &with.degree);
    let case = format!(
        "step load, Δt {:e}, {}+{} elements",
        c.dt, c.layers[0].elements, c.layers[1].elements
    );
    row(
        &mut rows,
        case.clone(),
        "max |u - u_series| / q0",
        0.0,
        eu,
        f.tolerance,
    );
    row(
        &mut rows,
        case.clone(),
        "max |U - U_series|",
        0.0,
        e_degree,
        f.tolerance,
    );
    let mut du = 0.0f64;
    for (a, b) in with.u.iter().zip(&without.u) {
        for (x, y) in a.iter().zip(b) {
            du = du.max((x - y).abs() / c.load);
        }
    }
    let d_degree = with
        .degree
        .iter()
        .zip(&without.degree)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    row(
        &mut rows,
        case.clone(),
        "max |u - u_no_interface| / q0",
        0.0,
        du,
        1e-10,
    );
    row(
        &mut rows,
        case.clone(),
        "max |U - U_no_interface|",
        0.0,
        d_degree,
        1e-10,
    );
    row(
        &mut rows,
        case.clone(),
        "max |p1 - p2| / q0 at the interface",
        0.0,
        with.jump / c.load,
        1e-12,
    );
    row(
        &mut rows,
        case.clone(),
        "Newton: largest |R| after an update / largest before",
        0.0,
        with.newton_reduction,
        1e-10,
    );

    // u(z, t) and U(t).
    let mut u_csv = String::from("time,depth,u,u_series,u_no_interface\n");
    for (col, &t) in c.times.iter().enumerate() {
        for (r, &z) in c.depths.iter().enumerate() {
            let _ = writeln!(
                u_csv,
                "{t:e},{z:e},{:e},{:e},{:e}",
                with.u[r][col],
                series.pressure(z, t),
                without.u[r][col]
            );
        }
    }
    let mut degree_csv = String::from("time,U,U_series,U_no_interface\n");
    for (col, &t) in c.times.iter().enumerate() {
        let _ = writeln!(
            degree_csv,
            "{t:e},{:e},{:e},{:e}",
            with.degree[col],
            series.degree(t),
            without.degree[col]
        );
    }
    for (name, text) in [("u", u_csv), ("U", degree_csv)] {
        let path = out.join(format!("{id}-{name}.csv"));
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        outputs.push(path);
    }
    let mut report = String::new();
    let _ = writeln!(
        report,
        "P1 {}: {} steps, {} kernel calls, series {} terms; max |u - u_series|/q0 {eu:.2e}, max |U - U_series| {e_degree:.2e}",
        f.title,
        with.steps,
        with.kernel_calls,
        series.terms()
    );

    if let Some(s) = &f.study {
        failures += study(
            f,
            s,
            &series,
            quick,
            out,
            &mut rows,
            &mut outputs,
            &mut report,
        )?;
    }
    Ok(Outcome {
        rows,
        outputs,
        failures,
        report,
    })
}

/// p beyond [0, q₀] by more than this fraction of q₀ is a spatial oscillation (round-off stays
/// below 1e-15).
const OSCILLATION: f64 = 1e-12;

/// A chart: file name, x label, y label, points, x value of a point, notes and reference lines.
type Chart<'a> = (
    &'a str,
    &'a str,
    &'a str,
    &'a [Point],
    crate::charts::Cost<'a>,
    crate::charts::Extras,
);

/// A run's (output time, value) pairs: u/q₀ at every depth, then U.
type Solution = Vec<(f64, f64)>;

/// Observed order log(e_a/e_b)/log(s_a/s_b).
fn order(a: &Point, b: &Point) -> f64 {
    (a.error / b.error).ln() / (a.step / b.step).ln()
}

#[allow(clippy::too_many_arguments)]
fn study(
    f: &P1File,
    s: &Study,
    series: &Series,
    quick: bool,
    out: &Path,
    rows: &mut Vec<Row>,
    outputs: &mut Vec<PathBuf>,
    report: &mut String,
) -> Result<usize, String> {
    let c = &f.column;
    let id = &f.id;
    let mut failures = 0;
    // Each point with its solution at the file's depths and times (u/q₀, then U): the observed
    // orders compare solutions with each other, not with the series.
    let mut solutions: Vec<(String, f64, Solution)> = Vec::new();
    let mut point = |method: String, step: f64, join: Join, refine: usize, dt: f64| {
        let (wall, wall_range, h) = timed(s.repeats, || consolidate(c, join, refine, dt, false));
        let h = h?;
        let (eu, e_degree) = errors(f, series, &h.u, &h.degree);
        // (output time, value): u/q₀ at every depth, then U.
        let solution: Vec<(f64, f64)> =
            h.u.iter()
                .flat_map(|row| c.times.iter().copied().zip(row.iter().map(|u| u / c.load)))
                .chain(c.times.iter().copied().zip(h.degree.iter().copied()))
                .collect();
        solutions.push((method.clone(), step, solution));
        Ok::<Point, String>(Point {
            scene: id.clone(),
            method,
            step,
            relative_step: step,
            error: eu.max(e_degree),
            details: vec![eu, e_degree, h.overshoot[0].max(h.overshoot[1]).max(0.0)],
            calls: h.kernel_calls,
            wall,
            wall_range,
            repeats: [s.repeats.max(1), 1],
            // A finite run is "ok" for the charts; a first-step oscillation (c·Δt/Δz² < 1/4 in a
            // layer) is reported in the table and the CSV, and mapped by the stability sweep.
            verdict: "ok",
            claim: f64::INFINITY,
        })
    };
    let dts = if quick { &s.quick_dts } else { &s.dts };
    let refines = if quick { &s.quick_refines } else { &s.refines };
    let elements = |r: usize| (c.layers[0].elements + c.layers[1].elements) * r;
    let mut dt_points = Vec::new();
    for &dt in dts {
        for join in [Join::Interface, Join::Shared] {
            let label = format!(
                "Δt sweep, {} elements, {}",
                elements(s.dt_sweep_refine),
                if join == Join::Interface {
                    "interface kernel"
                } else {
                    "no interface"
                }
            );
            dt_points.push(point(label, dt, join, s.dt_sweep_refine, dt)?);
        }
    }
    let mut mesh_points = Vec::new();
    for &r in refines {
        for join in [Join::Interface, Join::Shared] {
            let label = format!(
                "element sweep, Δt {:e} s, {}",
                s.refine_sweep_dt,
                if join == Join::Interface {
                    "interface kernel"
                } else {
                    "no interface"
                }
            );
            mesh_points.push(point(
                label,
                elements(r) as f64,
                join,
                r,
                s.refine_sweep_dt,
            )?);
        }
    }
    // Observed orders from the interface-kernel runs, by self-convergence: with three steps
    // s₁ > s₂ > s₃ in one ratio q, the differences of successive solutions shrink as q^order
    // whatever the other discretisation's error (the mesh's in the Δt sweep, Δt's in the element
    // sweep), so that any column shows the orders: the three smallest Δt (u and U), the three
    // coarsest meshes (U). Backward Euler is first order for t ≫ Δt only (the step load is not smooth at
    // t = 0), so the Δt sweep compares output times from 10 × its largest step on. Fewer than
    // three steps in that ratio (--quick): the order of the error against the series between
    // the two. The order in Δz is minus the slope in elements.
    let dt_case: fn(f64, f64) -> String = |a, b| format!("Δt {a:e} → {b:e}");
    let mesh_case: fn(f64, f64) -> String = |a, b| format!("{a} → {b} elements");
    let dt_quantity = "observed order in Δt (backward Euler: 1)";
    let mesh_quantity = "observed order in Δz (linear elements: 2)";
    let largest_difference = |a: &[(f64, f64)], b: &[(f64, f64)], from: f64| {
        a.iter()
            .zip(b)
            .filter(|((t, _), _)| *t >= from)
            .map(|((_, x), (_, y))| (x - y).abs())
            .fold(0.0, f64::max)
    };
    for (points, case, quantity, sign, claim, finest_first) in [
        (&dt_points, dt_case, dt_quantity, 1.0, s.dt_order, true),
        (
            &mesh_points,
            mesh_case,
            mesh_quantity,
            -1.0,
            s.mesh_order,
            false,
        ),
    ] {
        let mut kernel: Vec<(f64, &Solution, &Point)> = points
            .iter()
            .filter(|p| p.method.ends_with("interface kernel"))
            .filter_map(|p| {
                solutions
                    .iter()
                    .find(|(m, st, _)| *m == p.method && *st == p.step)
                    .map(|(_, st, sol)| (*st, sol, p))
            })
            .collect();
        // Coarsest first: the largest Δt, the fewest elements.
        kernel.sort_by(|a, b| {
            if finest_first {
                b.0.total_cmp(&a.0)
            } else {
                a.0.total_cmp(&b.0)
            }
        });
        let three = if finest_first {
            kernel.len().checked_sub(3).map(|i| &kernel[i..])
        } else {
            kernel.get(..3)
        };
        let observed = match three {
            Some([(s1, u1, _), (s2, u2, _), (s3, u3, _)])
                if ((s1 / s2).ln() - (s2 / s3).ln()).abs() < 1e-9 =>
            {
                let from = if finest_first { 10.0 * s1 } else { 0.0 };
                // The element sweep compares U only (the last entries): u at a depth that is a
                // node of one mesh and not of the next converges irregularly, U (an integral over
                // the column) smoothly.
                let skip = if finest_first {
                    0
                } else {
                    u1.len().saturating_sub(c.times.len())
                };
                let (d1, d2) = (
                    largest_difference(&u1[skip..], &u2[skip..], from),
                    largest_difference(&u2[skip..], &u3[skip..], from),
                );
                Some((*s1, *s3, sign * (d1 / d2).ln() / (s1 / s2).ln()))
            }
            _ => {
                let mut two: Vec<&Point> = kernel.iter().map(|k| k.2).collect();
                two.sort_by(|a, b| a.step.total_cmp(&b.step));
                match two[..] {
                    [a, b, ..] => Some((a.step, b.step, sign * order(a, b))),
                    _ => None,
                }
            }
        };
        if let Some((a, b, o)) = observed {
            order_row(rows, case(a, b), quantity, o, claim);
        }
    }
    // Interface and shared meshes agree point by point.
    let worst = dt_points
        .chunks(2)
        .chain(mesh_points.chunks(2))
        .map(|pair| (pair[0].details[0] - pair[1].details[0]).abs())
        .fold(0.0, f64::max);
    row(
        rows,
        "every study point".into(),
        "|error with - without interface|",
        0.0,
        worst,
        1e-9,
    );

    // Where the time stepping stops giving a monotone pressure: one backward-Euler step after the
    // step load on the file's mesh. On a uniform mesh of linear u–p elements (incompressible
    // constituents) the equilibrium rows give M·ε_e + p̄_e = q₀ per element, and the mass balance
    // of an interior node becomes, with u = q₀ − p and α = Δz²/(4·c·Δt),
    //   (α − 1)(u_{i−1} + u_{i+1}) + 2(α + 1)·u_i = 0,
    // whose solutions λ^i have λ + 1/λ = −2(α + 1)/(α − 1): λ < 0 (a node-to-node oscillation,
    // p > q₀ next to the drained face) when α > 1, i.e. c·Δt/Δz² < 1/4. Backward Euler itself
    // never diverges; it is the spatial oscillation that a too small step exposes, in each layer
    // at its own ratio ρ_i = c_i·Δt/Δz_i².
    let dz = [0, 1].map(|i| c.layers[i].thickness / c.layers[i].elements as f64);
    let cv = [0, 1].map(|i| c.layers[i].cv());
    let mut stab = String::from(
        "ratio_layer_1,ratio_layer_2,dt,overshoot_layer_1,overshoot_layer_2,undershoot\n",
    );
    let mut ratios = s.stability_ratios.clone();
    ratios.sort_by(f64::total_cmp);
    let mut sweep = Vec::new();
    let mut stability_points = Vec::new();
    for &ratio in &ratios {
        let dt = ratio * dz[0] * dz[0] / cv[0];
        let mut one = c.clone();
        one.end = dt;
        one.times = vec![dt];
        one.dt = dt;
        let h = consolidate(&one, Join::Interface, 1, dt, false)?;
        let rho = [0, 1].map(|i| cv[i] * dt / (dz[i] * dz[i]));
        let _ = writeln!(
            stab,
            "{:e},{:e},{dt:e},{:e},{:e},{:e}",
            rho[0], rho[1], h.overshoot[0], h.overshoot[1], h.undershoot
        );
        sweep.push((rho, h.overshoot));
        for (layer, (&ratio, &overshoot)) in rho.iter().zip(&h.overshoot).enumerate() {
            stability_points.push(Point {
                scene: id.clone(),
                method: format!("layer {}", layer + 1),
                step: ratio,
                relative_step: ratio,
                error: overshoot.max(0.0),
                details: Vec::new(),
                calls: h.kernel_calls,
                wall: 0.0,
                wall_range: [0.0, 0.0],
                repeats: [0, 0],
                verdict: "ok",
                claim: f64::INFINITY,
            });
        }
    }
    // The closed form holds next to a drained face, where the first step's pressure front is:
    // the layer at a drained face is held to it. The other layer's first step is driven through
    // the interface by the first one's and need not be monotone in its own ratio (on the
    // built-in column layer 2 is clean at 0.096 and 0.104 and overshoots again, by under 1e-7 of
    // q₀, at 0.12 to 0.24): its bracket is reported, not checked.
    let at_drained_face = [
        c.top == crate::column::Drainage::Drained,
        c.bottom == crate::column::Drainage::Drained,
    ];
    for layer in 0..2 {
        // The last oscillating ratio and the first monotone one above it bracket the boundary.
        let last_bad = sweep
            .iter()
            .filter(|(_, o)| o[layer] > OSCILLATION)
            .map(|(r, _)| r[layer])
            .fold(f64::NAN, f64::max);
        let first_good = sweep
            .iter()
            .filter(|(r, o)| o[layer] <= OSCILLATION && (last_bad.is_nan() || r[layer] > last_bad))
            .map(|(r, _)| r[layer])
            .fold(f64::NAN, f64::min);
        let clean_below = sweep
            .iter()
            .filter(|(r, o)| o[layer] <= OSCILLATION && r[layer] < last_bad)
            .count();
        let _ = writeln!(
            report,
            "P1 stability, layer {}{}: last oscillating first step at c·Δt/Δz² = {last_bad:.3}, monotone from {first_good:.3} on (closed form 1/4){}",
            layer + 1,
            if at_drained_face[layer] {
                ", at a drained face"
            } else {
                ", driven through the interface (not checked)"
            },
            if clean_below > 0 {
                format!("; {clean_below} smaller ratio(s) also clean: not monotone in the ratio")
            } else {
                String::new()
            }
        );
        if at_drained_face[layer] {
            row(
                rows,
                format!(
                    "first step, layer {} (drained face), bracket {last_bad:.3}..{first_good:.3}",
                    layer + 1
                ),
                "monotone from c·Δt/Δz² = 1/4",
                0.25,
                first_good,
                first_good - last_bad,
            );
        }
    }
    let path = out.join(format!("{id}-stability.csv"));
    std::fs::write(&path, stab).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    outputs.push(path);

    // CSV and charts.
    let all: Vec<Point> = dt_points.iter().chain(&mesh_points).cloned().collect();
    let mut csv = String::from(
        "sweep,method,dt,elements,error,u_error,U_error,kernel_calls,wall_s_fastest,overshoot\n",
    );
    let mut table = String::new();
    let _ = writeln!(
        table,
        "{:<52} {:>10} {:>9} {:>10} {:>10} {:>10}  first step",
        "method", "Δt", "elements", "error", "calls", "run (ms)"
    );
    for (sweep, points) in [("dt", &dt_points), ("elements", &mesh_points)] {
        for p in points {
            let (dt, n) = if sweep == "dt" {
                (p.step, elements(s.dt_sweep_refine))
            } else {
                (s.refine_sweep_dt, p.step as usize)
            };
            let _ = writeln!(
                csv,
                "{sweep},{},{dt:e},{n},{:e},{:e},{:e},{},{:e},{:e}",
                crate::csvfile::field(&p.method),
                p.error,
                p.details[0],
                p.details[1],
                p.calls,
                p.wall,
                p.details[2]
            );
            let first = if p.details[2] > OSCILLATION {
                format!("oscillates (p/q0 - 1 = {:.1e})", p.details[2])
            } else {
                "monotone".into()
            };
            let _ = writeln!(
                table,
                "{:<52} {dt:>10.3e} {n:>9} {:>10.2e} {:>10} {:>10.3}  {first}",
                p.method,
                p.error,
                p.calls,
                p.wall * 1e3
            );
        }
    }
    let path = out.join(format!("{id}-work-precision.csv"));
    std::fs::write(&path, csv).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    outputs.push(path);
    let label = "error max(|u − u_series|/q₀, |U − U_series|) (–)";
    let units = "Units: the scene file's consistent units (p1.toml: m, kPa, s; c_v in m²/s).";
    let error_note = format!(
        "Error: the larger of the pore-pressure error over q₀ and the error in the degree of consolidation U, at the file's depths and output times (earliest t = {} s), against the series solution.",
        c.times.iter().copied().fold(f64::INFINITY, f64::min)
    );
    // The three error charts' notes: what the error is, in which units.
    let error_notes = || crate::charts::Extras {
        notes: vec![error_note.clone(), units.into()],
        verticals: Vec::new(),
    };
    let machine = crate::charts::machine();
    let charts: [Chart; 4] = [
        (
            "error-vs-dt",
            "time increment Δt (s)",
            label,
            &dt_points,
            crate::charts::Cost::Other(&|p| p.step),
            error_notes(),
        ),
        (
            "error-vs-elements",
            "elements in the column (count)",
            label,
            &mesh_points,
            crate::charts::Cost::Other(&|p| p.step),
            error_notes(),
        ),
        (
            "error-vs-time",
            "wall time per run, fastest (s)",
            label,
            &all,
            crate::charts::Cost::Runs(s.repeats.max(1)),
            error_notes(),
        ),
        (
            "stability",
            "c·Δt/Δz² of the layer (–; one step after the load)",
            "max p/q₀ − 1 in the layer (–; 0 drawn at 1e-16)",
            &stability_points,
            crate::charts::Cost::Other(&|p| p.step),
            crate::charts::Extras {
                notes: vec![
                    "One backward-Euler step after the step load q₀ on the file's mesh; a pressure above q₀ is the node-to-node oscillation of equal-order u–p elements.".into(),
                    format!(
                        "A layer counts as oscillating when max p/q₀ − 1 > {OSCILLATION:e}. The layer at the drained face is checked: its last oscillating and first monotone ratio bracket 1/4. The other layer is driven through the interface and need not be monotone in its own ratio (reported, not checked)."
                    ),
                    format!(
                        "At the same Δt layer 2's ratio is {:.3} times layer 1's (c_v and Δz of each layer).",
                        (cv[1] / (dz[1] * dz[1])) / (cv[0] / (dz[0] * dz[0]))
                    ),
                ],
                verticals: vec![(
                    0.25,
                    "closed form: the first step is monotone from c·Δt/Δz² = 1/4".into(),
                )],
            },
        ),
    ];
    for (name, x_label, y_label, points, cost, extras) in charts {
        let svg = out.join(format!("{id}-{name}.svg"));
        if let Err(e) = crate::charts::work_precision_chart(
            &svg,
            &format!(
                "{}: {}",
                f.title,
                match name {
                    "error-vs-dt" => "error against the time increment Δt",
                    "error-vs-elements" => "error against the element count",
                    "error-vs-time" => "error against wall time",
                    _ => "first-step overshoot against c·Δt/Δz²",
                }
            ),
            x_label,
            y_label,
            points,
            cost,
            &[],
            &machine,
            &extras,
        ) {
            eprintln!("scenes: {e}");
            failures += 1;
        }
        outputs.push(svg);
    }
    let _ = writeln!(
        report,
        "\nP1 work-precision (fastest wall time of {} runs)\n\n{table}",
        s.repeats
    );
    Ok(failures)
}

/// The main job's hook: runs the built-in P1 file (no `--point`), or a `--point` file that is a
/// P1 file. Returns None when `--point` names another kind of scene.
pub fn hook(point: Option<&Path>, quick: bool, out: &Path) -> Option<Result<Outcome, String>> {
    let (origin, text) = match point {
        None => (BUILT_IN.0.to_string(), BUILT_IN.1.to_string()),
        Some(p) => {
            let text = std::fs::read_to_string(p).ok()?;
            if !is_p1(&text) {
                return None;
            }
            (p.display().to_string(), text)
        }
    };
    Some(parse(&text, &origin).and_then(|f| run(&f, quick, out)))
}

/// A `--point` P1 file run alone: prints its rows; the process exit code.
pub fn alone(p1: &Result<Outcome, String>) -> i32 {
    match p1 {
        Ok(o) => {
            println!("{}", o.report);
            let failed = crate::checks::print(&o.rows, true, "P1 checks") + o.failures;
            println!("\nWritten:");
            for p in &o.outputs {
                println!("  {}", p.display());
            }
            println!("\n{failed} failure(s)");
            i32::from(failed > 0)
        }
        Err(e) => {
            eprintln!("scenes: {e}");
            2
        }
    }
}

/// The built-in P1 run joined to the main job: its rows join the checks, its files the list;
/// returns the failures outside the rows.
pub fn join(
    p1: Option<Result<Outcome, String>>,
    rows: &mut Vec<Row>,
    outputs: &mut Vec<PathBuf>,
    report: &mut String,
) -> usize {
    match p1 {
        Some(Ok(o)) => {
            rows.extend(o.rows);
            outputs.extend(o.outputs);
            report.push_str(&o.report);
            o.failures
        }
        Some(Err(e)) => {
            eprintln!("scenes: P1: {e}");
            1
        }
        None => 0,
    }
}
