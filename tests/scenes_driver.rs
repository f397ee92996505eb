//! The scene driver (examples/scenes/) on its reduced sweep: every built-in scene meets its closed
//! form within the accuracy its chart claims; the explicit stability boundary measured on the F6
//! map is within one grid cell of the theoretical limit Δt = 2/sqrt((k + K_f)/m); implicit
//! stepping never diverges; scene files are checked before anything runs.
//!
//! The driver's modules are compiled into this test by path, so the test runs the same code.
#![allow(dead_code)]

include!("common/scene_modules.rs");

use oscillator::{Integrator, Oscillator, Stick, Verdict, simulate};
use scene::{Scene, Timing, run_point_timed};

/// The answer of one point (the test checks accuracy, not time).
fn run_point(scene: &Scene, m: &scene::Method, step: f64) -> scene::Point {
    run_point_timed(scene, m, step, Timing::ONCE)
}
use stability::{Cell, measured_boundary, run_map, theoretical_boundary};

const SCENES: [(&str, &str); 4] = [
    ("f6.toml", include_str!("../examples/scenes/data/f6.toml")),
    ("f1.toml", include_str!("../examples/scenes/data/f1.toml")),
    ("f2.toml", include_str!("../examples/scenes/data/f2.toml")),
    ("f4.toml", include_str!("../examples/scenes/data/f4.toml")),
];

fn f6() -> Scene {
    Scene::parse(SCENES[0].1, SCENES[0].0).expect("f6.toml")
}

/// F6's oscillator and the quick run of its first stability map that `pick` accepts (`what`
/// names it in a failure).
fn f6_map(what: &str, pick: impl Fn(&scene::MapSpec) -> bool) -> (Oscillator, stability::Map) {
    let scene = f6();
    let o = scene.file.oscillator.expect("F6");
    let spec = scene
        .file
        .maps
        .iter()
        .find(|m| pick(m))
        .unwrap_or_else(|| panic!("no {what} in f6.toml"));
    let map = run_map(&o, spec, true, |_, _| {}).expect("map");
    (o, map)
}

#[test]
fn every_scene_meets_the_accuracy_its_chart_claims() {
    let mut checked = 0;
    for (name, text) in SCENES {
        let scene = Scene::parse(text, name).expect("built-in scene file");
        for m in &scene.methods {
            for &step in &scene.file.quick_steps {
                let p = run_point(&scene, m, step);
                assert!(
                    p.meets_claim(),
                    "{name}: {} at step {step}: error {} > claim {} ({})",
                    m.spec.label,
                    p.error,
                    p.claim,
                    p.verdict
                );
                assert!(!p.error.is_nan(), "{name}: {} gave NaN", m.spec.label);
                if p.claim.is_finite() {
                    assert_eq!(p.verdict, "ok", "{name}: {} at {step}", m.spec.label);
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 15, "only {checked} claimed points");
}

#[test]
fn exact_stick_converges_at_first_order_in_the_step() {
    // Halving Δt twice (÷4) must shrink the error of exact stick by at least 2 (first order
    // gives 4; transitions falling at random places in a step make it noisy).
    let o = f6().file.oscillator.expect("F6");
    let e = |dt: f64| simulate(&o, Integrator::Implicit { alpha: 0.0 }, Stick::Exact, dt).error();
    let (coarse, fine) = (e(0.02), e(0.005));
    assert!(
        fine.is_finite() && fine * 2.0 <= coarse,
        "{coarse} → {fine}"
    );
}

#[test]
fn closed_form_of_the_oscillator_is_self_consistent() {
    // x(t) = x_k + R cos(ωt − φ) starts at x₁ with ẋ = v₀ and ends the slip at x₂ with ẋ = v₀.
    let o = f6().file.oscillator.expect("F6");
    let r = o.amplitude().hypot(o.belt_speed / o.omega());
    let x = |t: f64| o.x_kinetic() + r * (o.omega() * t - o.phase()).cos();
    let v = |t: f64| -r * o.omega() * (o.omega() * t - o.phase()).sin();
    let ts = o.t_slip();
    assert!((x(0.0) - o.x_slip_start()).abs() < 1e-12);
    assert!((v(0.0) - o.belt_speed).abs() < 1e-12);
    assert!((x(ts) - o.x_slip_end()).abs() < 1e-12);
    assert!((v(ts) - o.belt_speed).abs() < 1e-12);
    // Slip is forward throughout (v < v₀ strictly inside), so the dissipation is μ_k N × slip.
    for i in 1..100 {
        assert!(v(ts * f64::from(i) / 100.0) < o.belt_speed);
    }
    // The stick phase brings x₂ back to x₁ at the belt speed.
    assert!((o.x_slip_end() + o.belt_speed * o.t_stick() - o.x_slip_start()).abs() < 1e-12);
}

#[test]
fn measured_explicit_boundary_is_the_theoretical_limit_within_one_cell() {
    let (o, map) = f6_map("explicit map", |m| m.integrator == "explicit");
    assert!(map.gammas.len() >= 5);
    for r in 0..map.gammas.len() {
        let measured = measured_boundary(&map, r);
        let theory = theoretical_boundary(&o, &map, r);
        let (Some(m), Some(t)) = (measured, theory) else {
            panic!("row {r}: measured {measured:?}, theory {theory:?}");
        };
        assert!(
            m.abs_diff(t) <= 1,
            "γ_crit {}: first unstable column {m} (Δt {}), theory {t} (limit {})",
            map.gammas[r],
            map.dts[m],
            o.explicit_limit(map.gammas[r])
        );
        // Below the limit nothing is unstable; beyond 2·sqrt(m/k) (the spring alone) every cell
        // diverges.
        assert!(map.cells[r][..m].iter().all(|c| !c.unstable()));
        let spring_limit = 2.0 * (o.mass / o.spring).sqrt();
        for (c, dt) in map.dts.iter().enumerate() {
            if *dt > spring_limit * 1.05 {
                assert_eq!(map.cells[r][c], Cell::Diverged, "Δt {dt}");
            }
        }
    }
    assert!(map.errors.iter().flatten().all(|e| !e.is_nan()));
}

#[test]
fn implicit_stepping_never_diverges() {
    let (_, map) = f6_map("implicit map", |m| m.integrator == "hht");
    assert!(map.cells.iter().flatten().all(|c| *c != Cell::Diverged));
    assert!(map.errors.iter().flatten().all(|e| !e.is_nan()));
}

#[test]
fn explicit_stepping_blows_up_beyond_the_spring_limit_without_nan() {
    let o = f6().file.oscillator.expect("F6");
    let run = simulate(
        &o,
        Integrator::Explicit,
        Stick::Elastic { gamma_crit: 1e-3 },
        2.5,
    );
    assert_eq!(run.verdict, Verdict::Diverged);
    assert!(!run.error().is_nan());
}

#[test]
fn scene_files_are_checked_before_running() {
    let base = SCENES[0].1;
    let bad = [
        (
            base.replace("mu_kinetic = 0.5", "mu_kinetic = 0.7"),
            "must exceed mu_kinetic",
        ),
        (
            base.replacen(
                "integrator = \"newmark\"\nstick = \"exact\"",
                "integrator = \"explicit\"\nstick = \"exact\"",
                1,
            ),
            "explicit stepping needs elastic stick",
        ),
        (
            base.replacen(
                "label = \"explicit CD, elastic γc=1e-3\"",
                "label = \"x\"\nlaw = \"rate-and-state\"",
                1,
            ),
            "law 'rate-and-state' is not available",
        ),
        (
            base.replace("mass = 1.0", "mass = -1.0"),
            "mass = -1 must be finite and > 0",
        ),
        (base.replace("[oscillator]", "[oscilator]"), "unknown field"),
    ];
    for (text, expected) in bad {
        let e = Scene::parse(&text, "user.toml").expect_err(expected);
        assert!(e.contains(expected) && e.starts_with("user.toml"), "{e}");
    }
}

#[test]
fn a_user_point_file_runs_like_a_built_in_scene() {
    // The --point path: a user's own F6 parameters, one method, one step.
    let text = r#"
        id = "MINE"
        title = "my oscillator"
        steps = [0.01]
        quick_steps = [0.01]
        [oscillator]
        mass = 2.0
        spring = 8.0
        normal_force = 10.0
        mu_static = 0.5
        mu_kinetic = 0.3
        belt_speed = 0.2
        cycles = 2
        [[method]]
        label = "Newmark, exact"
        integrator = "newmark"
        stick = "exact"
        claim_floor = 0.0
        claim_slope = 8.0
    "#;
    let scene = Scene::parse(text, "mine.toml").expect("user scene");
    let p = run_point(&scene, &scene.methods[0], 0.01);
    assert!(p.meets_claim() && p.verdict == "ok", "{p:?}");
    assert!(p.calls > 0 && p.error < 0.05);
}

#[test]
fn the_oscillator_keeps_its_parameters_out_of_nan() {
    let o = Oscillator {
        mass: 1.0,
        spring: 1.0,
        normal_force: 1.0,
        mu_static: 0.6,
        mu_kinetic: 0.5,
        belt_speed: 0.1,
        cycles: 1,
    };
    for dt in [1e-3, 0.05, 1.0, 3.0] {
        for (i, s) in [
            (Integrator::Explicit, Stick::Elastic { gamma_crit: 1e-4 }),
            (
                Integrator::Implicit { alpha: -0.1 },
                Stick::Elastic { gamma_crit: 1e-4 },
            ),
            (Integrator::Implicit { alpha: 0.0 }, Stick::Exact),
        ] {
            let r = simulate(&o, i, s, dt);
            assert!(!r.error().is_nan(), "{i:?} {s:?} {dt}");
        }
    }
}

fn f4() -> Scene {
    Scene::parse(SCENES[3].1, SCENES[3].0).expect("f4.toml")
}

#[test]
fn frozen_mu_lags_one_increment_a_first_order_error() {
    // μ frozen at the start-of-increment rate: the error falls tenfold with the step (first
    // order), from the closed form's lag Δt·Σ|Δτ_law|; the implicit law does not depend on Δt.
    let v = f4().file.velocity.expect("F4");
    let e = |law, dt| v.run(law, 1e-5, dt).error;
    let (coarse, fine) = (
        e(velocity::RateLaw::DecayFrozen, 0.01),
        e(velocity::RateLaw::DecayFrozen, 0.001),
    );
    let ratio = coarse / fine;
    assert!((7.0..=13.0).contains(&ratio), "{coarse} → {fine}");
    // The lag's closed form: one increment behind every change of τ_law (and behind μ_s at
    // the start), over the history's length and the swing.
    let mut jumps =
        (v.mu_static * v.pressure - v.tau_law(velocity::RateLaw::Decay, v.rates[0])).abs();
    for w in v.rates.windows(2) {
        jumps += (v.tau_law(velocity::RateLaw::Decay, w[1])
            - v.tau_law(velocity::RateLaw::Decay, w[0]))
        .abs();
    }
    let lag = 0.01 * jumps / (v.hold * v.rates.len() as f64 * v.swing(velocity::RateLaw::Decay));
    assert!(
        (coarse - lag).abs() < 0.05 * lag,
        "{coarse} against the lag {lag}"
    );
    let (ic, if_) = (
        e(velocity::RateLaw::Decay, 0.01),
        e(velocity::RateLaw::Decay, 0.001),
    );
    assert!(ic < 3e-5 && if_ < 3e-5, "implicit {ic}, {if_}");
}

#[test]
fn velocity_weakening_sliding_is_stable_above_the_closed_form_step_limit_only() {
    // One hold at the steepest rate of F4 with a soft stick spring (γ_crit = 1e-3): steady
    // sliding settles to τ_law(v) just above the linearised limit and does not just below it.
    let mut v = f4().file.velocity.expect("F4");
    v.rates = vec![0.05];
    v.hold = 2.0;
    for law in [
        velocity::RateLaw::Decay,
        velocity::RateLaw::DecayFrozen,
        velocity::RateLaw::Adhesive,
    ] {
        let limit = v.rate_free_stiffness_limit(law, 1e-3);
        assert!(limit > 1e-4, "{law:?}: weakening expected");
        let tau = v.tau_law(law, 0.05);
        let steady = |dt: f64| {
            let r = v.run(law, 1e-3, dt);
            assert!(r.ok, "{law:?} at {dt}: cut-back");
            // details: steady error relative to the swing; the swing of one rate is 0, so
            // compare the end-of-hold stress with τ_law directly.
            r.steady_error * v.swing(law) / tau
        };
        let (above, below) = (steady(1.3 * limit), steady(0.7 * limit));
        assert!(above < 1e-9, "{law:?}: Δt = 1.3 × limit {limit}: {above}");
        if law == velocity::RateLaw::DecayFrozen {
            assert!(below > 1e-3, "{law:?}: Δt = 0.7 × limit {limit}: {below}");
        } else {
            // The rate-following stiffness (the default) has no step limit (scene F7).
            assert_eq!(v.rate_stability_limit(law, 1e-3), 0.0);
            assert!(below < 1e-9, "{law:?}: Δt = 0.7 × limit {limit}: {below}");
            assert!(
                steady(0.05 * limit) < 1e-9,
                "{law:?}: Δt = 0.05 × limit {limit}"
            );
        }
    }
}

#[test]
fn rate_stability_maps_follow_the_closed_form_limit() {
    // The reduced F4 maps over (Δt, d_c): in every row held to the linear limit the first
    // settling Δt is within one cell of it, oscillating cells lie below it, and both classes
    // occur (the map is not all one colour); the library never cuts back.
    let v = f4().file.velocity.expect("F4");
    for law in [velocity::RateLaw::Decay, velocity::RateLaw::DecayFrozen] {
        let map = rate_map::RateMap::run(&v, law, 1e-3, 10, 4);
        let mut checked = 0;
        for r in 0..map.decays.len() {
            assert!(
                map.boundary_matches(r),
                "{law:?}: row d_c = {}",
                map.decays[r]
            );
            if map.checked(r) {
                checked += 1;
                let limit = map.limit(r);
                for (c, cell) in map.cells[r].iter().enumerate() {
                    if map.dts[c] < limit / 1.5 {
                        assert_eq!(*cell, rate_map::RateCell::Oscillates, "{law:?} r{r} c{c}");
                    }
                    if map.dts[c] > 1.5 * limit {
                        assert_eq!(*cell, rate_map::RateCell::Settles, "{law:?} r{r} c{c}");
                    }
                }
            }
        }
        // The implicit law has no step limit (limit 0): no row is held to a boundary, so the
        // map's test is that every cell settles (below); μ frozen has rows to hold.
        if law == velocity::RateLaw::DecayFrozen {
            assert!(checked >= 2, "{law:?}: {checked} rows checked");
        } else {
            assert_eq!(checked, 0, "{law:?}: a row held to a limit of 0");
        }
        let cells: Vec<_> = map.cells.iter().flatten().collect();
        assert!(cells.contains(&&rate_map::RateCell::Settles));
        // Frozen μ keeps a step limit; the default implicit law (rate-following stiffness)
        // settles in every cell (scene F7).
        assert_eq!(
            cells.contains(&&rate_map::RateCell::Oscillates),
            law == velocity::RateLaw::DecayFrozen,
            "{law:?}"
        );
        assert!(!cells.contains(&&rate_map::RateCell::CutBack));
    }
}

#[test]
fn the_rate_stability_limits_docs_scenes_md_quotes() {
    // docs/scenes.md: "With γ_c = 1e-3 (k_s = μ_s p/γ_c) the limits at v = 0.05 are 3.3e-3 and
    // 1.6e-3": 2|dτ/dv|/k_s and |dτ/dv|/k_s with |dτ/dv| = (μ_s − μ_k)·d_c·e^(−d_c v)·p.
    let mut v = f4().file.velocity.expect("F4");
    v.rates = vec![0.05];
    let slope = (v.mu_static - v.mu_kinetic) * v.decay * (-v.decay * 0.05f64).exp() * v.pressure;
    let k_s = v.mu_static * v.pressure / 1e-3;
    // The implicit law's limit is that of the earlier rate-free stiffness (docs/props.md, "The
    // rate-dependent formulation"); the rate-following default has none.
    let (implicit, frozen) = (
        v.rate_free_stiffness_limit(velocity::RateLaw::Decay, 1e-3),
        v.rate_stability_limit(velocity::RateLaw::DecayFrozen, 1e-3),
    );
    assert_eq!(v.rate_stability_limit(velocity::RateLaw::Decay, 1e-3), 0.0);
    assert!((implicit - 2.0 * slope / k_s).abs() < 1e-12 * implicit);
    assert!((frozen - slope / k_s).abs() < 1e-12 * frozen);
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/scenes.md"))
        .expect("docs/scenes.md");
    assert!(text.contains("the limits at v = 0.05 are 3.3e-3 and 1.6e-3"));
    assert_eq!(format!("{implicit:.1e}"), "3.3e-3");
    assert_eq!(format!("{frozen:.1e}"), "1.6e-3");
}

#[test]
fn a_finding_fails_when_the_data_stops_supporting_it() {
    // F6-penalty-floor ("the penalty stays above 10 %") on points built from one real run: holds
    // with every error at 20 %, fails as soon as one completed run is within 5 %; with too few
    // points it fails on the full run (its data is missing) and is not checked on --quick.
    let scene = f6();
    let base = run_point(&scene, &scene.methods[0], 0.01);
    let make = |errors: &[f64]| -> Vec<scene::Point> {
        let methods = [
            "explicit CD, elastic γc=1e-3",
            "explicit CD, elastic γc=1e-4",
            "Newmark, elastic γc=1e-3",
            "Newmark, elastic γc=1e-4",
        ];
        errors
            .iter()
            .enumerate()
            .map(|(i, e)| scene::Point {
                method: methods[i % 4].into(),
                step: 1e-3 * (1 + i) as f64,
                error: *e,
                verdict: "ok",
                ..base.clone()
            })
            .collect()
    };
    let verdict = |points: &[scene::Point], full: bool| {
        findings::evaluate(points, &[], &[], full)
            .into_iter()
            .find(|f| f.id == "F6-penalty-floor")
            .expect("the finding")
            .ok
    };
    let mut errors = vec![0.2; 12];
    assert_eq!(verdict(&make(&errors), true), Some(true));
    errors[7] = 0.05;
    assert_eq!(verdict(&make(&errors), true), Some(false));
    assert_eq!(verdict(&make(&errors[..4]), true), Some(false));
    assert_eq!(verdict(&make(&errors[..4]), false), None);
}

#[test]
fn a_finding_whose_data_is_missing_fails_on_the_full_run() {
    // F2-3000 quotes the error at 3 000 increments per turn: the full F2 sweep holds it; the same
    // sweep with that step taken out of f2.toml must fail the finding, not skip it. Every finding
    // fails on the full run without data.
    let text = SCENES[2].1;
    assert!(text.contains("3000"), "f2.toml has no step 3000");
    let f2_3000 = |text: &str| {
        let scene = Scene::parse(text, "f2.toml").expect("f2.toml");
        let mut points = Vec::new();
        for m in &scene.methods {
            for &s in &scene.file.steps {
                points.push(run_point(&scene, m, s));
            }
        }
        let found = findings::evaluate(&points, &[], &[], true);
        found
            .into_iter()
            .find(|f| f.id == "F2-3000")
            .expect("the finding")
    };
    let with = f2_3000(text);
    assert_eq!(with.ok, Some(true), "{}", with.measured);
    let without = f2_3000(&text.replace(", 3000,", ",").replace(", 3000]", "]"));
    assert_eq!(without.ok, Some(false), "{}", without.measured);
    for f in findings::evaluate(&[], &[], &[], true) {
        assert_eq!(f.ok, Some(false), "{}: {}", f.id, f.measured);
    }
}

#[test]
fn an_unguarded_host_gets_a_refusal_and_cuts_back_beyond_the_spring_limit() {
    // F6 map 3 (reduced grid): a host with no divergence check of its own. Beyond 2·sqrt(m/k)
    // the motion overflows, fric_ refuses the non-finite DGAM (PNEWDT = 0.25) and the host cuts
    // back; below 1.6 s nothing is refused; no cell holds a NaN.
    let (o, map) = f6_map("cut-back map", |m| m.host.as_deref() == Some("unguarded"));
    let spring_limit = 2.0 * (o.mass / o.spring).sqrt();
    let mut beyond = 0;
    for row in &map.cells {
        for (c, cell) in row.iter().enumerate() {
            if map.dts[c] > 1.05 * spring_limit {
                assert_eq!(*cell, Cell::CutBack, "Δt {}", map.dts[c]);
                beyond += 1;
            }
            if map.dts[c] < 1.6 {
                assert_ne!(*cell, Cell::CutBack, "Δt {}", map.dts[c]);
            }
        }
    }
    assert!(beyond >= 2, "{beyond} cells beyond the limit");
    assert!(map.cutbacks >= beyond);
    assert!(map.refused.contains("DGAM"), "{}", map.refused);
    assert!(map.errors.iter().flatten().all(|e| !e.is_nan()));
}

#[test]
fn interleaved_timing_keeps_every_point_and_reports_its_fastest_repeat() {
    // F1's reduced sweep timed in 3 interleaved rounds: every point gets one repeat per round,
    // its wall time is the fastest of them and the bar runs from there to the slowest; the
    // answers (error, calls) are those of the untimed run.
    let scene = Scene::parse(SCENES[1].1, SCENES[1].0).expect("f1.toml");
    let mut points = Vec::new();
    for m in &scene.methods {
        for &s in &scene.file.quick_steps {
            points.push(run_point(&scene, m, s));
        }
    }
    let before: Vec<(f64, usize)> = points.iter().map(|p| (p.error, p.calls)).collect();
    let mut rounds = 0;
    let timing = Timing {
        repeats: 3,
        min_repeat: 0.0,
    };
    scene::time_interleaved(&scene, &mut points, timing, |_| rounds += 1);
    assert_eq!(rounds, 3);
    for (p, (error, calls)) in points.iter().zip(before) {
        assert_eq!(p.repeats[0], 3, "{}", p.method);
        assert!(p.wall > 0.0 && p.wall == p.wall_range[0], "{p:?}");
        assert!(p.wall_range[0] <= p.wall_range[1], "{p:?}");
        assert_eq!((p.error.to_bits(), p.calls), (error.to_bits(), calls));
    }
}
