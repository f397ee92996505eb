//! Stability maps of F6 over (Δt, γ_crit): every cell is one simulation, classified as
//! stable and accurate, stable but inaccurate, chattering (spurious stick/slip flips), diverged,
//! Newton failed, or a cut-back request from the library (PNEWDT < 1, never a NaN).

use crate::oscillator::{Host, Integrator, Oscillator, Stick, Verdict, simulate_host};
use crate::scene::MapSpec;

/// The class of one cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cell {
    /// Completed, error below the map's threshold.
    Accurate,
    /// Completed without spurious flips, error above the threshold.
    Inaccurate,
    /// Spurious stick/slip flips (friction reversing, phases far shorter than the closed
    /// form's) with the stick phase itself stable.
    Chattering,
    /// The stick mode grows step by step (the first stick phase, started without any ringing,
    /// ends early): beyond the integrator's stability limit in stick.
    Unstable,
    /// The motion blew up.
    Diverged,
    /// The host's Newton iteration failed.
    NewtonFailed,
    /// The library asked for a smaller step (PNEWDT < 1).
    CutBack,
}

impl Cell {
    /// Name in CSV files and legends.
    pub fn name(self) -> &'static str {
        match self {
            Cell::Accurate => "stable, accurate",
            Cell::Inaccurate => "stable, inaccurate",
            Cell::Chattering => "chattering",
            Cell::Unstable => "unstable stick (grows)",
            Cell::Diverged => "diverged",
            Cell::NewtonFailed => "Newton failed",
            Cell::CutBack => "cut-back (PNEWDT<1)",
        }
    }
    /// Unstable in the sense of the explicit limit: the stick mode grows, or everything does.
    pub fn unstable(self) -> bool {
        matches!(self, Cell::Unstable | Cell::Diverged)
    }
    /// All classes, in legend order.
    pub const ALL: [Cell; 7] = [
        Cell::Accurate,
        Cell::Inaccurate,
        Cell::Chattering,
        Cell::Unstable,
        Cell::Diverged,
        Cell::NewtonFailed,
        Cell::CutBack,
    ];
}

/// A computed map.
#[derive(Clone, Debug)]
pub struct Map {
    /// Its definition.
    pub spec: MapSpec,
    /// The integrator.
    pub integrator: Integrator,
    /// Column Δt values (ascending).
    pub dts: Vec<f64>,
    /// Row γ_crit values (ascending).
    pub gammas: Vec<f64>,
    /// `cells[row][column]`.
    pub cells: Vec<Vec<Cell>>,
    /// `errors[row][column]` (∞ when not measurable).
    pub errors: Vec<Vec<f64>>,
    /// Total `fric_` calls.
    pub calls: usize,
    /// The host of the map's runs.
    pub host: Host,
    /// Increments the library refused (`PNEWDT` < 1), over the whole map.
    pub cutbacks: usize,
    /// The library's message for the first refusal, if any.
    pub refused: String,
}

/// `n` log-spaced values from `a` to `b`.
pub fn log_space(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n < 2 {
        return vec![a];
    }
    let (la, lb) = (a.ln(), b.ln());
    (0..n)
        .map(|i| (la + (lb - la) * i as f64 / (n - 1) as f64).exp())
        .collect()
}

/// Parses the integrator of a map.
pub fn integrator(spec: &MapSpec) -> Result<Integrator, String> {
    match spec.integrator.as_str() {
        "explicit" => Ok(Integrator::Explicit),
        "newmark" => Ok(Integrator::Implicit { alpha: 0.0 }),
        "hht" => Ok(Integrator::Implicit {
            alpha: spec.alpha.unwrap_or(-0.1),
        }),
        other => Err(format!(
            "map '{}': integrator '{other}' (expected explicit, newmark or hht)",
            spec.label
        )),
    }
}

/// Computes a map; `progress` is called after each row.
pub fn run_map(
    o: &Oscillator,
    spec: &MapSpec,
    quick: bool,
    mut progress: impl FnMut(usize, usize),
) -> Result<Map, String> {
    let integrator = integrator(spec)?;
    let host = match spec.host.as_deref() {
        None | Some("guarded") => Host::Guarded,
        Some("unguarded") if integrator == Integrator::Explicit => Host::Unguarded,
        Some(other) => {
            return Err(format!(
                "map '{}': host '{other}' (expected guarded, or unguarded with explicit stepping)",
                spec.label
            ));
        }
    };
    let mut o = *o;
    if let Some(cycles) = spec.cycles {
        o.cycles = cycles;
        o.validate()
            .map_err(|e| format!("map '{}': {e}", spec.label))?;
    }
    let o = &o;
    let (nc, nr) = if quick {
        (spec.quick_points[0], spec.quick_points[1])
    } else {
        (spec.dt_points, spec.gamma_points)
    };
    let dts = log_space(spec.dt[0], spec.dt[1], nc);
    let gammas = log_space(spec.gamma_crit[0], spec.gamma_crit[1], nr);
    let mut map = Map {
        spec: spec.clone(),
        integrator,
        dts: dts.clone(),
        gammas: gammas.clone(),
        cells: Vec::new(),
        errors: Vec::new(),
        calls: 0,
        host,
        cutbacks: 0,
        refused: String::new(),
    };
    for (r, &g) in gammas.iter().enumerate() {
        let mut row = Vec::new();
        let mut errs = Vec::new();
        for &dt in &dts {
            let run = simulate_host(o, integrator, Stick::Elastic { gamma_crit: g }, dt, host);
            map.calls += run.calls;
            map.cutbacks += run.cutbacks;
            if map.refused.is_empty() {
                map.refused.clone_from(&run.refused);
            }
            let cell = match run.verdict {
                _ if run.cutbacks > 0 => Cell::CutBack,
                // An unguarded host does not stop a diverging run: classify it here.
                _ if run.peak.is_nan() || run.peak > 1e3 => Cell::Diverged,
                Verdict::Diverged => Cell::Diverged,
                Verdict::NewtonFailed => Cell::NewtonFailed,
                Verdict::CutBack => Cell::CutBack,
                Verdict::Completed if run.stick_unstable(o) => Cell::Unstable,
                Verdict::Completed if run.chattering() => Cell::Chattering,
                Verdict::Completed if run.error() <= spec.accurate => Cell::Accurate,
                Verdict::Completed => Cell::Inaccurate,
            };
            row.push(cell);
            errs.push(run.error());
        }
        map.cells.push(row);
        map.errors.push(errs);
        progress(r + 1, gammas.len());
    }
    Ok(map)
}

/// Per row: the first column whose cell is unstable (stick mode grows, or diverged), if any.
pub fn measured_boundary(map: &Map, row: usize) -> Option<usize> {
    map.cells[row].iter().position(|c| c.unstable())
}

/// Per row: the first column beyond the theoretical explicit limit Δt < 2/sqrt((k + K_f)/m).
pub fn theoretical_boundary(o: &Oscillator, map: &Map, row: usize) -> Option<usize> {
    let limit = o.explicit_limit(map.gammas[row]);
    map.dts.iter().position(|dt| *dt >= limit)
}
