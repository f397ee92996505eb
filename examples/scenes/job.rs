//! The main job itself (`main.rs` only reads the arguments): runs every scene, writes the CSV
//! files and charts, prints the tables and returns the exit status. `tests/scenes_job.rs` runs it
//! on the reduced sweeps (`--quick`) and reads every CSV it writes.

use std::fmt::Write as _;
use std::io::{IsTerminal as _, Write as _};
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::scene::{Point, Scene, Timing, run_point_timed};
use crate::stability::{Map, measured_boundary, run_map, theoretical_boundary};

/// The built-in scene files, in the order they run.
const SCENES: [(&str, &str); 4] = [
    ("data/f6.toml", include_str!("data/f6.toml")),
    ("data/f1.toml", include_str!("data/f1.toml")),
    ("data/f2.toml", include_str!("data/f2.toml")),
    ("data/f4.toml", include_str!("data/f4.toml")),
];

/// The command line.
pub struct Options {
    /// Reduced sweeps and maps (`--quick`).
    pub quick: bool,
    /// The long tables too (`--verbose`).
    pub verbose: bool,
    /// Where the CSV files and charts go (`--out DIR`).
    pub out: PathBuf,
    /// A scene file of the user's, run alone (`--point FILE.toml`).
    pub point: Option<PathBuf>,
}

const USAGE: &str = "usage: scenes [--quick] [--verbose] [--out DIR] [--point FILE.toml]";

impl Options {
    /// Reads the arguments (without the program name); the error is the message to print.
    pub fn parse(args: impl IntoIterator<Item = String>) -> Result<Options, String> {
        let mut o = Options {
            quick: false,
            verbose: false,
            out: Path::new(env!("CARGO_MANIFEST_DIR")).join("target/scenes"),
            point: None,
        };
        let mut args = args.into_iter();
        while let Some(a) = args.next() {
            match a.as_str() {
                "--quick" => o.quick = true,
                "--verbose" | "-v" => o.verbose = true,
                "--out" => o.out = args.next().map(PathBuf::from).ok_or(USAGE)?,
                "--point" => o.point = Some(args.next().map(PathBuf::from).ok_or(USAGE)?),
                "-h" | "--help" => return Err(USAGE.into()),
                other => return Err(format!("scenes: unknown argument '{other}'\n{USAGE}")),
            }
        }
        Ok(o)
    }
}

/// Progress: on a terminal a counter on stderr rewritten in place; on stdout one short line per
/// scene when it is done.
struct Progress {
    done: usize,
    total: usize,
    start: Instant,
    /// When the last scene line was printed.
    last: f64,
}

impl Progress {
    fn tick(&mut self, what: &str) {
        self.done += 1;
        let mut err = std::io::stderr();
        if err.is_terminal() {
            let _ = write!(
                err,
                "\r\x1b[2K[{:>3}/{}] {:>5.1}s  {what}",
                self.done.min(self.total),
                self.total,
                self.start.elapsed().as_secs_f64()
            );
            let _ = err.flush();
        }
    }
    /// Clears the counter line (a terminal) so that stdout's lines stay clean.
    fn clear(&self) {
        let mut err = std::io::stderr();
        if err.is_terminal() {
            let _ = write!(err, "\r\x1b[2K");
            let _ = err.flush();
        }
    }
    /// One scene done: its name, what it produced, and its time.
    fn scene(&mut self, name: &str, what: &str) {
        self.clear();
        let now = self.start.elapsed().as_secs_f64();
        println!("  {name:<58} {what:<22} {:>5.1} s", now - self.last);
        let _ = std::io::stdout().flush();
        self.last = now;
    }
    /// A note on stderr (an expected message that follows).
    fn note(&self, text: &str) {
        self.clear();
        eprintln!("scenes: {text}");
    }
}

/// Every work-precision point of a scene: each run once for its answer, then all of them timed
/// together, interleaved (`scene::time_interleaved`).
pub fn sweep(scene: &Scene, quick: bool, mut tick: impl FnMut(&str)) -> Vec<Point> {
    let steps = if quick {
        &scene.file.quick_steps
    } else {
        &scene.file.steps
    };
    let mut points = Vec::new();
    for m in &scene.methods {
        for &s in steps {
            let p = run_point_timed(scene, m, s, Timing::ONCE);
            tick(&format!("{}: {} at step {s}", scene.file.id, m.spec.label));
            points.push(p);
        }
    }
    crate::scene::time_interleaved(scene, &mut points, Timing::MAIN, tick);
    points
}

/// Writes a CSV file: the `header` line, then one line per item of `lines`.
fn write_csv(path: &Path, header: &str, lines: impl Iterator<Item = String>) -> Result<(), String> {
    let mut s = format!("{header}\n");
    for line in lines {
        let _ = writeln!(s, "{line}");
    }
    std::fs::write(path, s).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn write_points(path: &Path, points: &[Point]) -> Result<(), String> {
    let header = "scene,method,step,relative_step,error,claim,meets_claim,verdict,calls,wall_s_fastest,wall_min_s,wall_max_s,repeats,runs_per_repeat,ns_per_call,details";
    write_csv(
        path,
        header,
        points.iter().map(|p| {
            format!(
                "{},{},{:e},{:e},{:e},{:e},{},{},{},{:e},{:e},{:e},{},{},{:.1},{}",
                crate::csvfile::field(&p.scene),
                crate::csvfile::field(&p.method),
                p.step,
                p.relative_step,
                p.error,
                p.claim,
                if p.claim.is_finite() {
                    if p.meets_claim() { "true" } else { "false" }
                } else {
                    "no claim"
                },
                p.verdict,
                p.calls,
                p.wall,
                p.wall_range[0],
                p.wall_range[1],
                p.repeats[0],
                p.repeats[1],
                p.wall / p.calls.max(1) as f64 * 1e9,
                crate::csvfile::field(
                    &p.details
                        .iter()
                        .map(|d| format!("{d:e}"))
                        .collect::<Vec<_>>()
                        .join(";")
                )
            )
        }),
    )
}

fn write_map(path: &Path, map: &Map) -> Result<(), String> {
    let cells = map.cells.iter().enumerate().flat_map(|(r, row)| {
        row.iter().enumerate().map(move |(c, cell)| {
            format!(
                "{:e},{:e},{},{:e}",
                map.dts[c],
                map.gammas[r],
                crate::csvfile::field(cell.name()),
                map.errors[r][c]
            )
        })
    });
    write_csv(path, "dt,gamma_crit,class,error", cells)
}

fn write_checks(path: &Path, rows: &[crate::checks::Row]) -> Result<(), String> {
    let header = "scene,case,quantity,closed_form,computed,error,tolerance,ok";
    write_csv(
        path,
        header,
        rows.iter().map(|r| {
            format!(
                "{},{},{},{:e},{:e},{:e},{:e},{}",
                crate::csvfile::field(r.scene),
                crate::csvfile::field(&r.case),
                crate::csvfile::field(r.quantity),
                r.exact,
                r.computed,
                r.error(),
                r.tolerance,
                r.ok()
            )
        }),
    )
}

fn print_points(points: &[Point], verbose: bool) -> usize {
    let header = format!(
        "{:<5} {:<34} {:>9} {:>10} {:>10} {:>10} {:>8} {:>11}  {:<14} claim met",
        "scene", "method", "step", "error", "claim", "run (ms)", "calls", "ns/call", "verdict"
    );
    crate::checks::print_table(
        "Work-precision (error against the closed form; claim = the chart's stated bound)",
        &header,
        points,
        Point::meets_claim,
        verbose,
        |p| {
            format!(
                "{:<5} {:<34} {:>9.3e} {:>10.2e} {:>10} {:>10.3} {:>8} {:>11.1}  {:<14} {}",
                p.scene,
                p.method,
                p.step,
                p.error,
                if p.claim.is_finite() {
                    format!("{:.2e}", p.claim)
                } else {
                    "-".into()
                },
                p.wall * 1e3,
                p.calls,
                p.wall / p.calls.max(1) as f64 * 1e9,
                p.verdict,
                if !p.claim.is_finite() {
                    "no claim"
                } else if p.meets_claim() {
                    "yes"
                } else {
                    "NO"
                }
            )
        },
    )
}

/// Runs the main job; returns the exit status (0: every check, claim and finding holds).
pub fn run(opts: &Options) -> i32 {
    // The run-time finding times the whole job, P1 included.
    let start = Instant::now();
    let machine = crate::charts::machine();
    if let Err(e) = std::fs::create_dir_all(&opts.out) {
        eprintln!("scenes: cannot create {}: {e}", opts.out.display());
        return 2;
    }
    println!(
        "interfacial {} — the main job: closed-form checks, work-precision sweeps, stability maps and\nfindings, through the entry points a host calls (fric_, gapcon_, uinter_, ifl_pore_pressure)\n",
        interfacial::VERSION
    );
    println!(
        "  run      {}{}\n  output   {}\n  machine  {machine}\n",
        if opts.quick {
            "reduced sweeps and maps (--quick): findings are not checked"
        } else {
            "full sweeps and maps"
        },
        if opts.verbose {
            ", every table (--verbose)"
        } else {
            ""
        },
        opts.out.display()
    );
    // Scene P1 (consolidation column): a --point file with a [column] table runs alone.
    let p1 = crate::consolidation::hook(opts.point.as_deref(), opts.quick, &opts.out);
    if let (Some(_), Some(p1)) = (&opts.point, &p1) {
        return crate::consolidation::alone(p1);
    }
    let sources: Vec<(String, String)> = match &opts.point {
        Some(path) => match std::fs::read_to_string(path) {
            Ok(text) => vec![(path.display().to_string(), text)],
            Err(e) => {
                eprintln!("scenes: cannot read {}: {e}", path.display());
                return 2;
            }
        },
        None => SCENES
            .iter()
            .map(|(n, t)| ((*n).to_string(), (*t).to_string()))
            .collect(),
    };
    let scenes: Vec<Scene> = match sources
        .iter()
        .map(|(origin, text)| Scene::parse(text, origin))
        .collect::<Result<_, _>>()
    {
        Ok(s) => s,
        Err(e) => {
            eprintln!("scenes: {e}");
            return 2;
        }
    };
    let total = scenes
        .iter()
        .map(|s| {
            let steps = if opts.quick {
                s.file.quick_steps.len()
            } else {
                s.file.steps.len()
            };
            s.methods.len() * steps
                + s.file
                    .maps
                    .iter()
                    .map(|m| {
                        if opts.quick {
                            m.quick_points[1]
                        } else {
                            m.gamma_points
                        }
                    })
                    .sum::<usize>()
        })
        .sum::<usize>()
        + scenes.len() * Timing::MAIN.repeats
        + usize::from(opts.point.is_none())
        + scenes.iter().filter(|s| s.file.velocity.is_some()).count() * 2;
    let mut progress = Progress {
        done: 0,
        total,
        start,
        last: 0.0,
    };
    let mut expected_stderr = false;
    let mut failures = 0;
    let mut check_rows = Vec::new();
    let mut report = String::new();
    let mut outputs = Vec::new();
    let p1_rows = match &p1 {
        Some(Ok(o)) => o.rows.len(),
        _ => 0,
    };
    failures += crate::consolidation::join(p1, &mut check_rows, &mut outputs, &mut report);
    progress.scene(
        "P1 two-layer consolidation column (ifl_pore_pressure)",
        &format!("{p1_rows} checks"),
    );
    if opts.point.is_none() {
        progress.tick("closed-form checks (F1-F5, T1, T2, A1)");
        match crate::checks::run() {
            Ok(rows) => {
                progress.scene(
                    "F1-F5, T1, T2, A1 closed forms (fric_, gapcon_, uinter_)",
                    &format!("{} checks", rows.len()),
                );
                check_rows.extend(rows);
            }
            Err(e) => {
                eprintln!("\nscenes: {e}");
                return 2;
            }
        }
    }
    let mut all_points = Vec::new();
    let mut maps: Vec<(usize, Map)> = Vec::new();
    let mut rate_maps: Vec<crate::rate_map::RateMap> = Vec::new();
    // F7, velocity weakening (examples/scenes/weakening.rs): its rows join the checks.
    let mut newton_table = String::new();
    if opts.point.is_none() {
        match crate::weakening::run(&opts.out, opts.quick) {
            Ok((rows, files, table)) => {
                progress.scene(
                    "F7 velocity weakening: steady sliding, maps, belt",
                    &format!("{} checks", rows.len()),
                );
                check_rows.extend(rows);
                outputs.extend(files);
                newton_table = table;
            }
            Err(e) => {
                eprintln!("\nscenes: {e}");
                failures += 1;
            }
        }
    }
    // R1 and R2, rate-and-state friction (examples/scenes/rate_state.rs): rows join the checks.
    if opts.point.is_none() {
        match crate::rate_state::run(&opts.out, opts.quick) {
            Ok((rows, files)) => {
                progress.scene(
                    "R1 velocity steps, R2 spring-slider map (rate-and-state, fric_)",
                    &format!("{} checks", rows.len()),
                );
                check_rows.extend(rows);
                outputs.extend(files);
            }
            Err(e) => {
                eprintln!("\nscenes: {e}");
                failures += 1;
            }
        }
    }
    for scene in &scenes {
        let mut points = sweep(scene, opts.quick, |w| progress.tick(w));
        let swept = points.len();
        if scene.kind == "circle" {
            // The same runs' lag error against the chord of the last step (second order), as
            // its own curve for the middle γ_crit/R (the three coincide).
            let chord: Vec<Point> = points
                .iter()
                .filter(|p| p.method.ends_with("0.1") && p.details.len() > 2)
                .map(|p| Point {
                    method: format!("{}, against the chord", p.method),
                    error: p.details[2],
                    claim: f64::INFINITY,
                    ..p.clone()
                })
                .collect();
            points.extend(chord);
        }
        let id = &scene.file.id;
        let csv = opts.out.join(format!("{id}-work-precision.csv"));
        let time_svg = opts.out.join(format!("{id}-error-vs-time.svg"));
        let calls_svg = opts.out.join(format!("{id}-error-vs-calls.svg"));
        let error_label = match scene.kind {
            "oscillator" => "largest relative error of T, x₂, energy/cycle (–)",
            "pull" => "max |γ − γ_exact| / (τ_c/K) (–)",
            "velocity" => "mean |τ − τ_law(v)| / swing of τ_law (–)",
            _ => "lag angle error (rad), against the end-of-step tangent unless marked",
        };
        let highlights = crate::findings::highlights(id);
        let extras = crate::charts::Extras {
            notes: if scene.kind == "velocity" {
                vec!["The implicit curve with γc = 1e-3 rises as the step shrinks, to a plateau (F4-elastic-plateau): the closed form is rigid stick, and the fine steps resolve the stick spring's elastic transient after each velocity step, which large backward-Euler steps step over.".into()]
            } else {
                Vec::new()
            },
            verticals: Vec::new(),
        };
        // The error against each cost: wall time, then fric_ calls.
        let views = [
            (
                &time_svg,
                "wall time",
                "wall time per run (s): fastest of 7 interleaved repeats, bar = fastest..slowest",
                crate::charts::Cost::Wall,
            ),
            (
                &calls_svg,
                "fric_ calls",
                "fric_ calls per run, Newton iterations included (–)",
                crate::charts::Cost::Calls,
            ),
        ];
        let written = write_points(&csv, &points).and_then(|()| {
            views
                .into_iter()
                .try_for_each(|(svg, cost_name, x_title, cost)| {
                    crate::charts::work_precision_chart(
                        svg,
                        &format!("{}: error against {cost_name}", scene.file.title),
                        x_title,
                        error_label,
                        &points,
                        cost,
                        &highlights,
                        &machine,
                        &extras,
                    )
                })
        });
        if let Err(e) = written {
            eprintln!("\nscenes: {e}");
            failures += 1;
        }
        outputs.extend([csv, time_svg, calls_svg]);
        all_points.extend(points);
        if let Some(v) = &scene.file.velocity {
            // Rate-stability maps over (Δt, d_c) with a soft stick spring (γ_crit = 1e-3).
            let (nx, ny) = if opts.quick { (10, 4) } else { (31, 13) };
            for (i, law) in [
                crate::velocity::RateLaw::Decay,
                crate::velocity::RateLaw::DecayFrozen,
            ]
            .into_iter()
            .enumerate()
            {
                let map = crate::rate_map::RateMap::run(v, law, 1e-3, nx, ny);
                progress.tick(&format!("{id} rate map {}", i + 1));
                let csv = opts.out.join(format!("{id}-map-{}.csv", i + 1));
                let svg = opts.out.join(format!("{id}-map-{}.svg", i + 1));
                let mut text = String::from("dt,decay,class,closed_form_limit\n");
                for (r, row) in map.cells.iter().enumerate() {
                    for (c, cell) in row.iter().enumerate() {
                        let _ = writeln!(
                            text,
                            "{:e},{:e},{},{:e}",
                            map.dts[c],
                            map.decays[r],
                            crate::csvfile::field(cell.name()),
                            map.limit(r)
                        );
                    }
                }
                if let Err(e) = std::fs::write(&csv, text)
                    .map_err(|e| format!("cannot write {}: {e}", csv.display()))
                    .and_then(|()| crate::charts::rate_map(&svg, &map))
                {
                    eprintln!("\nscenes: {e}");
                    failures += 1;
                }
                outputs.extend([csv, svg]);
                rate_maps.push(map);
            }
        }
        if let Some(o) = &scene.file.oscillator {
            for (i, spec) in scene.file.maps.iter().enumerate() {
                let label = spec.label.clone();
                if spec.host.as_deref() == Some("unguarded") {
                    expected_stderr = true;
                    progress.note(&format!(
                        "{id} map {}: a host without a divergence check; the library's 'bad input: DGAM is NaN or infinite' message below is EXPECTED (fric_ refuses the host's overflow, the host cuts back)",
                        i + 1
                    ));
                }
                match run_map(o, spec, opts.quick, |r, n| {
                    progress.tick(&format!("{id} map '{label}': row {r}/{n}"));
                }) {
                    Ok(map) => {
                        let csv = opts.out.join(format!("{id}-map-{}.csv", i + 1));
                        let svg = opts.out.join(format!("{id}-map-{}.svg", i + 1));
                        let (marks, notes) = crate::findings::map_marks(&map);
                        if let Err(e) = write_map(&csv, &map).and_then(|()| {
                            crate::charts::stability_map(&svg, o, &map, &marks, &notes)
                        }) {
                            eprintln!("\nscenes: {e}");
                            failures += 1;
                        }
                        outputs.extend([csv, svg]);
                        maps.push((
                            scenes.iter().position(|s| s.file.id == *id).unwrap_or(0),
                            map,
                        ));
                    }
                    Err(e) => {
                        eprintln!("\nscenes: {e}");
                        failures += 1;
                    }
                }
            }
        }
        let maps_here = scene.file.maps.len() + if scene.file.velocity.is_some() { 2 } else { 0 };
        progress.scene(
            &if scene.file.title.starts_with(&scene.file.id) {
                scene.file.title.clone()
            } else {
                format!("{} {}", scene.file.id, scene.file.title)
            },
            &format!("{swept} points, {maps_here} maps"),
        );
    }
    progress.clear();
    println!();
    let verbose = opts.verbose;
    // The long tables print with --verbose; without it only their failing lines do.
    let mut summary: Vec<(String, usize, usize)> = Vec::new();
    if verbose && !report.is_empty() {
        println!("{report}");
    }
    if !check_rows.is_empty() {
        let mut scenes_seen: Vec<&str> = Vec::new();
        for r in &check_rows {
            if !scenes_seen.contains(&r.scene) {
                scenes_seen.push(r.scene);
            }
        }
        for sc in scenes_seen {
            let of: Vec<&crate::checks::Row> =
                check_rows.iter().filter(|r| r.scene == sc).collect();
            let failed = of.iter().filter(|r| !r.ok()).count();
            summary.push((format!("closed-form checks, {sc}"), of.len(), failed));
        }
        let failed = crate::checks::print(&check_rows, verbose, "Closed-form checks");
        failures += failed;
        let path = opts.out.join("checks.csv");
        if let Err(e) = write_checks(&path, &check_rows) {
            eprintln!("scenes: {e}");
            failures += 1;
        }
        outputs.insert(0, path);
    }
    if verbose && !newton_table.is_empty() {
        println!(
            "F7: F6 with the decay law, Newton iterations per implicit step\n\n{newton_table}"
        );
    }
    let claim_failures = print_points(&all_points, verbose);
    failures += claim_failures;
    summary.push((
        "work-precision points held to their chart's claim".into(),
        all_points.iter().filter(|p| p.claim.is_finite()).count(),
        claim_failures,
    ));
    let (mut boundary_rows, mut boundary_failures) = (0, 0);
    for (si, map) in &maps {
        let Some(o) = &scenes[*si].file.oscillator else {
            continue;
        };
        let mut lines = Vec::new();
        // The explicit boundary is held to the theory for a host that stops diverging runs.
        let explicit = map.integrator == crate::oscillator::Integrator::Explicit
            && map.host == crate::oscillator::Host::Guarded;
        for r in 0..map.gammas.len() {
            let counts = crate::stability::Cell::ALL
                .iter()
                .map(|c| {
                    let n = map.cells[r].iter().filter(|x| *x == c).count();
                    format!("{} {n}", c.name())
                })
                .collect::<Vec<_>>()
                .join(", ");
            let (boundary, ok) = if explicit {
                let m = measured_boundary(map, r);
                let t = theoretical_boundary(o, map, r);
                let ok = match (m, t) {
                    (Some(m), Some(t)) => m.abs_diff(t) <= 1,
                    (None, None) => true,
                    _ => false,
                };
                boundary_rows += 1;
                if !ok {
                    boundary_failures += 1;
                }
                (
                    format!(
                        "  limit {:.3e}, first unstable Δt {} ({})",
                        o.explicit_limit(map.gammas[r]),
                        m.map_or("none".into(), |c| format!("{:.3e}", map.dts[c])),
                        if ok { "within one cell" } else { "MISMATCH" }
                    ),
                    ok,
                )
            } else {
                (String::new(), true)
            };
            if verbose || !ok {
                lines.push(format!(
                    "  γ_crit {:.1e}: {counts}{boundary}",
                    map.gammas[r]
                ));
            }
        }
        if !lines.is_empty() {
            println!("Stability map: {}\n{}\n", map.spec.label, lines.join("\n"));
        }
    }
    for map in &rate_maps {
        let mut lines = Vec::new();
        for r in 0..map.decays.len() {
            let ok = map.boundary_matches(r);
            if map.checked(r) {
                boundary_rows += 1;
            }
            if !ok {
                boundary_failures += 1;
            }
            let first = map.cells[r]
                .iter()
                .position(|c| *c == crate::rate_map::RateCell::Settles)
                .map_or("none".into(), |c| format!("{:.3e}", map.dts[c]));
            let cutbacks = map.cells[r]
                .iter()
                .filter(|c| **c == crate::rate_map::RateCell::CutBack)
                .count();
            if verbose || !ok {
                lines.push(format!(
                    "  d_c {:>7.3}: closed-form limit {:.3e}, first settling Δt {first} ({}), cut-backs {cutbacks}",
                    map.decays[r],
                    map.limit(r),
                    if map.limit(r) == 0.0 {
                        "no step limit: the cell must settle (F4-map-implicit)"
                    } else if !map.checked(r) {
                        "d_c v > 1: not held to the linear limit"
                    } else if ok {
                        "within one cell"
                    } else {
                        "MISMATCH"
                    }
                ));
            }
        }
        if !lines.is_empty() {
            println!("{}\n{}\n", map.title(), lines.join("\n"));
        }
    }
    failures += boundary_failures;
    summary.push((
        "stability boundaries within one cell of the closed form".into(),
        boundary_rows,
        boundary_failures,
    ));
    if opts.point.is_none() {
        let map_refs: Vec<&Map> = maps.iter().map(|(_, m)| m).collect();
        let mut found = crate::findings::evaluate(&all_points, &map_refs, &rate_maps, !opts.quick);
        found.push(crate::findings::run_time(
            start.elapsed().as_secs_f64(),
            opts.quick,
        ));
        let failed = crate::findings::print(&found, verbose);
        failures += failed;
        let checked = found.iter().filter(|f| f.ok.is_some()).count();
        summary.push((
            if checked < found.len() {
                format!(
                    "findings ({} not checked on --quick)",
                    found.len() - checked
                )
            } else {
                "findings (the figures README.md and docs/scenes.md quote)".into()
            },
            checked,
            failed,
        ));
        let path = opts.out.join("findings.csv");
        if let Err(e) = std::fs::write(&path, crate::findings::csv(&found)) {
            eprintln!("scenes: cannot write {}: {e}", path.display());
            failures += 1;
        }
        outputs.push(path);
    }
    println!("Summary\n");
    println!("  {:<64} {:>7} {:>7}", "", "checked", "failed");
    for (what, checked, failed) in &summary {
        println!("  {what:<64} {checked:>7} {failed:>7}");
    }
    println!(
        "\n  Times: the fastest of interleaved repeats per point, on {machine}; the charts also give fric_ calls."
    );
    if expected_stderr {
        println!(
            "  Expected on stderr: fric_'s 'bad input: DGAM is NaN or infinite' from F6 map 3 (a host that lets its motion overflow; fric_ refuses, the host cuts back)."
        );
    }
    if verbose {
        println!("\nWritten:");
        for p in &outputs {
            println!("  {}", p.display());
        }
    } else {
        println!(
            "  Written: {} files (CSV and SVG) to {} (--verbose lists them and prints every table).",
            outputs.len(),
            opts.out.display()
        );
    }
    println!(
        "\n{} in {:.1} s; {failures} failure(s)",
        if failures == 0 {
            "PASSED: every check, claim and finding holds"
        } else {
            "FAILED"
        },
        start.elapsed().as_secs_f64()
    );
    i32::from(failures > 0)
}
