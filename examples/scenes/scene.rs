//! Scene definitions as data (one small TOML file per scene, `examples/scenes/data/*.toml`, or a
//! user's own file given with `--point FILE.toml`) and the work-precision sweep that runs them.
//!
//! A file names the scene's closed form (`kind`), its parameters, the step sizes of the sweep and
//! the methods, one `[[method]]` table each. Every method states the accuracy its chart claims:
//! error ≤ `claim_floor` + `claim_slope` × (step / reference step), with the reference step the
//! scene's natural time (F6: the period T; F2: one radian of the circle). The test
//! `tests/scenes_driver.rs` holds every method to its claim.
//!
//! Adding a method: one more `[[method]]` table. Adding a kind of method (a rate law solved
//! implicitly or with μ frozen, the adhesive law): a new `law` value, a variant of [`Law`] and a
//! match arm in [`Method::parse`] and in [`run_point_timed`] — nothing else changes.

use std::time::Instant;

use serde::Deserialize;

use crate::circle::Circle;
use crate::oscillator::{Integrator, Oscillator, Stick, Verdict, simulate};
use crate::pull::Pull;
use crate::velocity::{RateLaw, VelocitySteps};

/// A scene file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Short id, e.g. "F6".
    pub id: String,
    /// Title for tables and charts.
    pub title: String,
    /// F6 parameters (kind = "oscillator").
    pub oscillator: Option<Oscillator>,
    /// F2 parameters (kind = "circle").
    pub circle: Option<Circle>,
    /// F1 with a spring host (kind = "pull").
    pub pull: Option<Pull>,
    /// F4 velocity steps with a rate law (kind = "velocity").
    pub velocity: Option<VelocitySteps>,
    /// Step sizes of the full sweep (F6: Δt; F2: increments per turn; F1: increments per
    /// stick stretch τ_c/K).
    pub steps: Vec<f64>,
    /// Step sizes of the reduced sweep (`--quick`, and the test).
    pub quick_steps: Vec<f64>,
    /// The methods.
    #[serde(rename = "method")]
    pub methods: Vec<MethodSpec>,
    /// Stability maps (F6 only).
    #[serde(default, rename = "map")]
    pub maps: Vec<MapSpec>,
}

/// One `[[method]]` table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MethodSpec {
    /// Legend text.
    pub label: String,
    /// The friction law: "coulomb" (F6, F1, F2); "decay" (law 1's exponential decay μ law at
    /// the end-of-increment rate), "decay-frozen" (μ frozen at the start-of-increment rate,
    /// `PROPS(20) = 1`) or "adhesive" (law 2, seed 004) in F4.
    #[serde(default = "coulomb")]
    pub law: String,
    /// F6: "explicit" (central differences), "newmark" or "hht"; F2: "return-map"; F1:
    /// "quasi-static".
    pub integrator: String,
    /// "elastic" (penalty, needs `gamma_crit`) or "exact" (LM = 1).
    pub stick: String,
    /// Allowable elastic slip γ_crit.
    pub gamma_crit: Option<f64>,
    /// HHT α ∈ [−1/3, 0] (default −0.1 for "hht").
    pub alpha: Option<f64>,
    /// Claimed error at any step of the sweep: floor + slope × step/reference.
    pub claim_floor: f64,
    /// See `claim_floor`.
    pub claim_slope: f64,
    /// Claims hold only up to this step (e.g. the explicit stability limit); default: all.
    pub claim_max_step: Option<f64>,
    /// Claims hold only from this step on (F4: the rate-stability limit of a velocity-weakening
    /// law on the stick spring); default: all.
    pub claim_min_step: Option<f64>,
}

fn coulomb() -> String {
    "coulomb".into()
}

/// A `[[map]]` table: a stability map over (Δt, γ_crit) for one integrator.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapSpec {
    /// Title of the map.
    pub label: String,
    /// "explicit", "newmark" or "hht".
    pub integrator: String,
    /// HHT α.
    pub alpha: Option<f64>,
    /// Δt range (log-spaced) and number of columns.
    pub dt: [f64; 2],
    /// Columns (full run).
    pub dt_points: usize,
    /// γ_crit range (log-spaced).
    pub gamma_crit: [f64; 2],
    /// Rows (full run).
    pub gamma_points: usize,
    /// Grid in `--quick` runs (columns, rows).
    pub quick_points: [usize; 2],
    /// Relative error below which a completed run counts as accurate.
    pub accurate: f64,
    /// "guarded" (default: the host stops a diverging run itself) or "unguarded" (the host
    /// trusts the library and cuts back when `fric_` answers `PNEWDT` < 1).
    pub host: Option<String>,
    /// Cycles simulated per cell (default: the scene's `cycles`); an unguarded host needs long
    /// runs for an unstable motion to reach the overflow the library refuses.
    pub cycles: Option<u32>,
}

/// A law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Law {
    /// The extended Coulomb law through `fric_` (`PROPS(1) = 1`).
    Coulomb,
    /// A rate law of F4.
    Rate(RateLaw),
}

/// A parsed method.
#[derive(Clone, Debug)]
pub struct Method {
    /// The table it came from.
    pub spec: MethodSpec,
    /// The law.
    pub law: Law,
    /// F6 time integration (unused for F2).
    pub integrator: Integrator,
    /// Stick enforcement.
    pub stick: Stick,
}

impl Method {
    /// Checks a `[[method]]` table.
    pub fn parse(spec: &MethodSpec, kind: &str) -> Result<Method, String> {
        let law = match spec.law.as_str() {
            "coulomb" if kind != "velocity" => Law::Coulomb,
            "decay" if kind == "velocity" => Law::Rate(RateLaw::Decay),
            "decay-frozen" if kind == "velocity" => Law::Rate(RateLaw::DecayFrozen),
            "adhesive" if kind == "velocity" => Law::Rate(RateLaw::Adhesive),
            other => {
                return Err(format!(
                    "method '{}': law '{other}' is not available in a {kind} scene (known: \
                     coulomb in F6, F1, F2; decay, decay-frozen, adhesive in F4)",
                    spec.label
                ));
            }
        };
        let stick = match (spec.stick.as_str(), spec.gamma_crit) {
            ("elastic", Some(g)) if g.is_finite() && g > 0.0 => Stick::Elastic { gamma_crit: g },
            ("elastic", _) => {
                return Err(format!(
                    "method '{}': elastic stick needs gamma_crit > 0",
                    spec.label
                ));
            }
            ("exact", _) => Stick::Exact,
            (other, _) => {
                return Err(format!(
                    "method '{}': stick '{other}' (expected elastic or exact)",
                    spec.label
                ));
            }
        };
        let integrator = match (kind, spec.integrator.as_str()) {
            ("oscillator", "explicit") if stick != Stick::Exact => Integrator::Explicit,
            ("oscillator", "explicit") => {
                return Err(format!(
                    "method '{}': explicit stepping needs elastic stick (no multipliers)",
                    spec.label
                ));
            }
            ("oscillator", "newmark") => Integrator::Implicit { alpha: 0.0 },
            ("oscillator", "hht") => {
                let alpha = spec.alpha.unwrap_or(-0.1);
                if !(-1.0 / 3.0..=0.0).contains(&alpha) {
                    return Err(format!(
                        "method '{}': HHT alpha = {alpha} outside [-1/3, 0]",
                        spec.label
                    ));
                }
                Integrator::Implicit { alpha }
            }
            ("circle", "return-map") if matches!(stick, Stick::Elastic { .. }) => {
                Integrator::Explicit
            }
            ("pull", "quasi-static") => Integrator::Explicit,
            ("velocity", "quasi-static") if matches!(stick, Stick::Elastic { .. }) => {
                Integrator::Explicit
            }
            (k, i) => {
                return Err(format!(
                    "method '{}': integrator '{i}' does not apply to a {k} scene",
                    spec.label
                ));
            }
        };
        check_bounds(&[
            ("claim_floor", spec.claim_floor, Bound::NonNegative),
            ("claim_slope", spec.claim_slope, Bound::NonNegative),
        ])
        .map_err(|e| format!("method '{}': {e}", spec.label))?;
        Ok(Method {
            spec: spec.clone(),
            law,
            integrator,
            stick,
        })
    }
}

/// A parsed scene.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The file.
    pub file: SceneFile,
    /// "oscillator" or "circle".
    pub kind: &'static str,
    /// Parsed methods, in file order.
    pub methods: Vec<Method>,
}

impl Scene {
    /// Parses and checks a scene file's text (`origin` names it in messages).
    pub fn parse(text: &str, origin: &str) -> Result<Scene, String> {
        let file: SceneFile = toml::from_str(text).map_err(|e| format!("{origin}: {e}"))?;
        let kind = match (&file.oscillator, &file.circle, &file.pull) {
            _ if file.velocity.is_some() => {
                if file.oscillator.is_some() || file.circle.is_some() || file.pull.is_some() {
                    return Err(format!(
                        "{origin}: give exactly one of [oscillator], [circle], [pull] or [velocity]"
                    ));
                }
                if let Some(v) = &file.velocity {
                    v.validate()
                        .map_err(|e| format!("{origin}: [velocity] {e}"))?;
                }
                "velocity"
            }
            (Some(o), None, None) => {
                o.validate()
                    .map_err(|e| format!("{origin}: [oscillator] {e}"))?;
                "oscillator"
            }
            (None, Some(c), None) => {
                c.validate()
                    .map_err(|e| format!("{origin}: [circle] {e}"))?;
                "circle"
            }
            (None, None, Some(p)) => {
                p.validate().map_err(|e| format!("{origin}: [pull] {e}"))?;
                "pull"
            }
            _ => {
                return Err(format!(
                    "{origin}: give exactly one of [oscillator] (F6), [circle] (F2) or [pull] (F1)"
                ));
            }
        };
        for (name, steps) in [("steps", &file.steps), ("quick_steps", &file.quick_steps)] {
            if steps.is_empty() || steps.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
                return Err(format!(
                    "{origin}: {name} must be a non-empty list of positive steps"
                ));
            }
        }
        let methods = file
            .methods
            .iter()
            .map(|m| Method::parse(m, kind).map_err(|e| format!("{origin}: {e}")))
            .collect::<Result<Vec<_>, _>>()?;
        if methods.is_empty() {
            return Err(format!("{origin}: no [[method]]"));
        }
        if !file.maps.is_empty() && kind != "oscillator" {
            return Err(format!(
                "{origin}: [[map]] applies to oscillator scenes only"
            ));
        }
        Ok(Scene {
            file,
            kind,
            methods,
        })
    }

    /// The step in claim units: F6 Δt/T; F2 Δθ in radians; F1 Δu/(τ_c/K); F4 Δt/hold.
    pub fn reference_step(&self, step: f64) -> f64 {
        if let Some(v) = &self.file.velocity {
            return step / v.hold;
        }
        match (&self.file.oscillator, &self.file.circle) {
            (Some(o), _) => step / o.period(),
            // Increments per turn → Δθ in radians.
            (_, Some(_)) => 2.0 * std::f64::consts::PI / step,
            _ => 1.0 / step,
        }
    }
}

/// One point of a work-precision curve.
#[derive(Clone, Debug)]
pub struct Point {
    /// Scene id.
    pub scene: String,
    /// Method label.
    pub method: String,
    /// Step (Δt, or increments per turn).
    pub step: f64,
    /// The step in claim units (Δt/T, or Δθ).
    pub relative_step: f64,
    /// Error against the closed form (relative for F6, radians for F2); ∞ when not measurable.
    pub error: f64,
    /// The per-quantity errors (F6: T, x₂, energy).
    pub details: Vec<f64>,
    /// `fric_` calls in the run.
    pub calls: usize,
    /// Wall time of one run, seconds: the fastest of the timed repeats (the least disturbed by
    /// other load on the machine; [`time_interleaved`]).
    pub wall: f64,
    /// Fastest and slowest of the timed repeats (seconds per run): the spread drawn.
    pub wall_range: [f64; 2],
    /// Timed repeats, and runs inside each (each repeat lasts ≥ `Timing::min_repeat`).
    pub repeats: [usize; 2],
    /// How the run ended ("ok", "chattering", "diverged", "newton-failed", "cut-back").
    pub verdict: &'static str,
    /// The claimed bound at this step (∞ when no claim applies).
    pub claim: f64,
}

impl Point {
    /// Meets its claim (points without a claim pass).
    pub fn meets_claim(&self) -> bool {
        !self.claim.is_finite() || self.error <= self.claim
    }
}

/// How a point is timed.
#[derive(Clone, Copy, Debug)]
pub struct Timing {
    /// Timed repeats (with [`Timing::MAIN`] the main job reports the fastest, and draws the
    /// range from the fastest to the slowest as an error bar).
    pub repeats: usize,
    /// Each repeat runs the scene as many times as it takes to last at least this long (s).
    pub min_repeat: f64,
}

impl Timing {
    /// The main job: 7 rounds over every point of a scene, interleaved (see
    /// [`time_interleaved`]), each point's repeat lasting ≥ 1 ms.
    pub const MAIN: Timing = Timing {
        repeats: 7,
        min_repeat: 1e-3,
    };
    /// One run, timed once (tests/scenes_driver.rs: the answer, not the time).
    #[allow(dead_code)]
    pub const ONCE: Timing = Timing {
        repeats: 1,
        min_repeat: 0.0,
    };
}

/// Runs `run` once for its answer, then times it: `timing.repeats` repeats, each of enough
/// runs to last `timing.min_repeat`. Returns the answer, the median time per run, the fastest and
/// slowest repeat, and [repeats, runs per repeat].
fn timed<R>(timing: Timing, mut run: impl FnMut() -> R) -> (R, f64, [f64; 2], [usize; 2]) {
    let t = Instant::now();
    let answer = run();
    let once = t.elapsed().as_secs_f64();
    if timing.repeats <= 1 {
        return (answer, once, [once, once], [1, 1]);
    }
    let inner = ((timing.min_repeat / once.max(1e-9)).ceil() as usize).clamp(1, 1_000_000);
    let mut per_run: Vec<f64> = (0..timing.repeats)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..inner {
                std::hint::black_box(run());
            }
            t.elapsed().as_secs_f64() / inner as f64
        })
        .collect();
    per_run.sort_by(f64::total_cmp);
    let n = per_run.len();
    let median = if n % 2 == 1 {
        per_run[n / 2]
    } else {
        0.5 * (per_run[n / 2 - 1] + per_run[n / 2])
    };
    (
        answer,
        median,
        [per_run[0], per_run[n - 1]],
        [timing.repeats, inner],
    )
}

/// What a scene parameter must be besides finite.
#[derive(Clone, Copy, Debug)]
pub enum Bound {
    /// > 0.
    Positive,
    /// ≥ 0.
    NonNegative,
}

/// The first of the named parameters that is not finite or not within its bound, as an error
/// ("name = value must be finite and > 0", or "≥ 0").
pub fn check_bounds(parameters: &[(&str, f64, Bound)]) -> Result<(), String> {
    for &(name, v, bound) in parameters {
        let (ok, rule) = match bound {
            Bound::Positive => (v > 0.0, "> 0"),
            Bound::NonNegative => (v >= 0.0, "≥ 0"),
        };
        if !(v.is_finite() && ok) {
            return Err(format!("{name} = {v} must be finite and {rule}"));
        }
    }
    Ok(())
}

/// Runs one method at one step, timed as the main job times it (the earlier entry point).
#[allow(dead_code)]
pub fn run_point(scene: &Scene, method: &Method, step: f64) -> Point {
    run_point_timed(scene, method, step, Timing::MAIN)
}

/// Runs one method at one step.
pub fn run_point_timed(scene: &Scene, method: &Method, step: f64, timing: Timing) -> Point {
    let relative_step = scene.reference_step(step);
    let spec = &method.spec;
    let claim = if spec.claim_max_step.is_none_or(|m| step <= m)
        && spec.claim_min_step.is_none_or(|m| step >= m)
    {
        spec.claim_floor + spec.claim_slope * relative_step
    } else {
        f64::INFINITY
    };
    let mut p = Point {
        scene: scene.file.id.clone(),
        method: spec.label.clone(),
        step,
        relative_step,
        error: f64::INFINITY,
        details: Vec::new(),
        calls: 0,
        wall: 0.0,
        wall_range: [0.0; 2],
        repeats: [0; 2],
        verdict: "ok",
        claim,
    };
    if let Some(o) = &scene.file.oscillator {
        let (run, wall, range, repeats) = timed(timing, || {
            simulate(o, method.integrator, method.stick, step)
        });
        p.error = run.error();
        p.details = run.errors.to_vec();
        p.calls = run.calls;
        (p.wall, p.wall_range, p.repeats) = (wall, range, repeats);
        p.verdict = match run.verdict {
            Verdict::Completed if run.stick_unstable(o) => "unstable",
            Verdict::Completed if run.chattering() => "chattering",
            Verdict::Completed => "ok",
            Verdict::Diverged => "diverged",
            Verdict::NewtonFailed => "newton-failed",
            Verdict::CutBack => "cut-back",
        };
    } else if let Some(c) = &scene.file.circle {
        let gamma_crit = match method.stick {
            Stick::Elastic { gamma_crit } => gamma_crit,
            Stick::Exact => c.radius,
        };
        let per_turn = step.round().max(3.0) as usize;
        let (run, wall, range, repeats) = timed(timing, || c.run(gamma_crit, per_turn));
        p.error = run.error;
        // Lag error against the tangent, |τ| error relative to μp, lag error against the chord.
        p.details = vec![
            run.error,
            run.magnitude_error / (c.mu * c.pressure),
            run.chord_error,
        ];
        p.calls = run.calls;
        (p.wall, p.wall_range, p.repeats) = (wall, range, repeats);
        p.verdict = if run.ok { "ok" } else { "cut-back" };
    } else if let Some(f1) = &scene.file.pull {
        let per_stretch = step.round().max(1.0) as usize;
        let (run, wall, range, repeats) = timed(timing, || f1.run(method.stick, per_stretch));
        p.error = run.error;
        p.details = vec![run.error];
        p.calls = run.calls;
        (p.wall, p.wall_range, p.repeats) = (wall, range, repeats);
        p.verdict = if run.ok { "ok" } else { "newton-failed" };
    } else if let (Some(v), Law::Rate(law)) = (&scene.file.velocity, method.law) {
        let gamma_crit = match method.stick {
            Stick::Elastic { gamma_crit } => gamma_crit,
            Stick::Exact => v.hold,
        };
        let (run, wall, range, repeats) = timed(timing, || v.run(law, gamma_crit, step));
        p.error = run.error;
        p.details = vec![run.error, run.steady_error];
        p.calls = run.calls;
        (p.wall, p.wall_range, p.repeats) = (wall, range, repeats);
        // PNEWDT < 1: the library's own local solve asked for a smaller step.
        p.verdict = if !run.ok {
            "cut-back"
        } else if step < v.rate_stability_limit(law, gamma_crit) {
            "rate-unstable"
        } else {
            "ok"
        };
    }
    p
}

/// Runs one method at one step for its cost only (the same calls as [`run_point_timed`]).
fn run_only(scene: &Scene, method: &Method, step: f64) {
    if let Some(o) = &scene.file.oscillator {
        std::hint::black_box(simulate(o, method.integrator, method.stick, step));
    } else if let Some(c) = &scene.file.circle {
        let gamma_crit = match method.stick {
            Stick::Elastic { gamma_crit } => gamma_crit,
            Stick::Exact => c.radius,
        };
        std::hint::black_box(c.run(gamma_crit, step.round().max(3.0) as usize));
    } else if let Some(f1) = &scene.file.pull {
        std::hint::black_box(f1.run(method.stick, step.round().max(1.0) as usize));
    } else if let (Some(v), Law::Rate(law)) = (&scene.file.velocity, method.law) {
        let gamma_crit = match method.stick {
            Stick::Elastic { gamma_crit } => gamma_crit,
            Stick::Exact => v.hold,
        };
        std::hint::black_box(v.run(law, gamma_crit, step));
    }
}

/// Times every point of a scene the way that survives a busy machine: `timing.repeats` rounds,
/// each round timing every point once (a repeat of enough runs to last `timing.min_repeat`), the
/// points visited in a different order every round (rotated, and reversed on odd rounds), so
/// that a burst of load from other jobs falls on many points a little rather than on one point's
/// repeats. A point's `wall` is its fastest repeat (the least disturbed), `wall_range` the
/// fastest and slowest. `points` carry their answers already ([`run_point_timed`] with
/// [`Timing::ONCE`]); `tick` is called once per point and round.
pub fn time_interleaved(
    scene: &Scene,
    points: &mut [Point],
    timing: Timing,
    mut tick: impl FnMut(&str),
) {
    let n = points.len();
    if n == 0 || timing.repeats == 0 {
        return;
    }
    // Runs per repeat, from the single run that gave the answer.
    let methods: Vec<Option<&Method>> = points
        .iter()
        .map(|p| scene.methods.iter().find(|m| m.spec.label == p.method))
        .collect();
    let inner: Vec<usize> = points
        .iter()
        .map(|p| ((timing.min_repeat / p.wall.max(1e-9)).ceil() as usize).clamp(1, 1_000_000))
        .collect();
    let mut times = vec![Vec::with_capacity(timing.repeats); n];
    for round in 0..timing.repeats {
        for k in 0..n {
            let i = if round % 2 == 0 {
                (k + round) % n
            } else {
                (n - 1 - k + round) % n
            };
            let Some(m) = methods[i] else { continue };
            let step = points[i].step;
            let t = Instant::now();
            for _ in 0..inner[i] {
                run_only(scene, m, step);
            }
            times[i].push(t.elapsed().as_secs_f64() / inner[i] as f64);
        }
        tick(&format!(
            "{}: timing round {}/{}",
            scene.file.id,
            round + 1,
            timing.repeats
        ));
    }
    for ((p, t), inner) in points.iter_mut().zip(&times).zip(&inner) {
        if t.is_empty() {
            continue;
        }
        let fastest = t.iter().copied().fold(f64::INFINITY, f64::min);
        let slowest = t.iter().copied().fold(0.0, f64::max);
        p.wall = fastest;
        p.wall_range = [fastest, slowest];
        p.repeats = [t.len(), *inner];
    }
}
