//! μ from a table in the configuration file (`PROPS(8) = 2`, `[interactions.NAME.friction]`):
//! scene F4 velocity steps against the table's own interpolation, tangents against central
//! differences (rate, pressure and temperature columns, NFDIR 1 and 2, anisotropy, exact stick,
//! frozen μ), `fric_coef_` against the closed form, and bad tables and names (refused with a
//! message, PNEWDT < 1, nothing written). The file is read once per process: this binary sets
//! `INTERFACIAL_CONFIG` before its first call; bad files are tried in child processes.

#![allow(clippy::needless_range_loop)] // index loops mirror the a, b indices of the equations

#[path = "common/central.rs"]
mod central;
#[path = "common/config_file.rs"]
mod config_file;
#[path = "common/fric_coef.rs"]
mod fric_coef_common;
#[path = "common/loading.rs"]
mod loading;
use central::{Shift, along_dgam, along_press, along_temp, central_tau, slide_steadily};
use fric_coef_common::fric_coef_call;
use loading::Loading;

use std::process::Command;

use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;

/// "RATE": μ(γ̇) falling from 0.6 to 0.3 over two segments (and a conductance, to show both
/// live side by side). "FULL": μ(γ̇, p, θ̄), three pressures at θ̄ = 0, two at θ̄ = 100, falling
/// with rate and pressure and rising-then-falling in θ̄, so every derivative is non-zero.
const CONFIG: &str = r#"
[interactions.RATE.friction]
table = [[0.6, 0.0], [0.45, 0.3], [0.3, 1.0]]

[interactions.FULL.friction]
table = [
  [0.50, 0.0, 0.0, 0.0], [0.44, 0.5, 0.0, 0.0], [0.40, 2.0, 0.0, 0.0],
  [0.46, 0.0, 100.0, 0.0], [0.41, 0.5, 100.0, 0.0], [0.35, 2.0, 100.0, 0.0],
  [0.40, 0.0, 300.0, 0.0], [0.37, 0.5, 300.0, 0.0], [0.33, 2.0, 300.0, 0.0],
  [0.45, 0.0, 0.0, 100.0], [0.40, 1.0, 0.0, 100.0],
  [0.42, 0.0, 200.0, 100.0], [0.36, 1.0, 200.0, 100.0],
]

[interactions.RATE.conductance]
law = "constant"
k = 1.0
"#;

fn setup() {
    config_file::config_once("fric-table", CONFIG);
}

/// μ of "RATE", written independently of the library: linear through (0, 0.6), (0.3, 0.45),
/// (1, 0.3), constant outside.
fn rate_mu(v: f64) -> f64 {
    if v <= 0.3 {
        0.6 - 0.5 * v
    } else if v <= 1.0 {
        0.45 - (0.15 / 0.7) * (v - 0.3)
    } else {
        0.3
    }
}

/// Law 1 with the μ table (`PROPS(8) = 2`) of the interaction, μ_ref = `mu_ref`.
fn table_law(mu_ref: f64, mu2: f64, gc: f64, exact: bool, frozen: bool) -> CoulombBuilder {
    CoulombBuilder::new()
        .mu(mu_ref)
        .mu2(mu2)
        .gamma_crit(gc)
        .stick(if exact { 1.0 } else { 0.0 })
        .mu_law(2.0)
        .frozen(if frozen { 1.0 } else { 0.0 })
}

/// [`table_law`], all 20 entries.
fn table_props(mu_ref: f64, mu2: f64, gc: f64, exact: bool, frozen: bool) -> Vec<f64> {
    table_law(mu_ref, mu2, gc, exact, frozen).build()
}

/// Scene F4 with a table: after a few increments at slip velocity v, τ = μ_tab(v)·p (elastic
/// and exact stick, implicit and frozen μ, NFDIR 1 and 2), inside and beyond the table.
#[test]
fn f4_velocity_steps_follow_the_table() {
    setup();
    let (p, gc, dt) = (50.0, 1e-3, 0.01);
    for nfdir in [1usize, 2] {
        for exact in [false, true] {
            for frozen in [false, true] {
                let mut c = FricCall::new(nfdir as i32, &table_props(1.0, 0.0, gc, exact, frozen));
                c.ciname = "rate".into(); // names match ignoring case
                c.press = p;
                c.dtime = dt;
                let dir = if nfdir == 1 { [1.0, 0.0] } else { [0.6, 0.8] };
                for v in [0.05, 0.5, 0.2, 1.5, 0.8] {
                    let tau_eq = slide_steadily(&mut c, nfdir, dir, v, 40);
                    let expected = rate_mu(v) * p;
                    assert!(
                        (tau_eq - expected).abs() < 1e-11 * expected,
                        "NFDIR {nfdir} exact {exact} frozen {frozen} v {v}: {tau_eq} vs {expected}"
                    );
                    assert!((c.statev[1] - v).abs() < 1e-11 * v);
                }
            }
        }
    }
    // μ_ref scales nothing in direction 1: PROPS(2) = 0.25 gives the same τ.
    let mut c = FricCall::new(1, &table_props(0.25, 0.0, gc, false, false));
    c.ciname = "RATE".into();
    c.press = p;
    c.dtime = dt;
    for _ in 0..40 {
        c.dgam[0] = 0.5 * dt;
        c.call();
    }
    assert!((c.tau[0] - rate_mu(0.5) * p).abs() < 1e-11 * p);
}

#[derive(Clone, Debug)]
struct Sample {
    nfdir: usize,
    mu2: f64,
    exact: bool,
    frozen: bool,
    load: Loading,
    theta: f64,
    start_rate: f64,
    dtime: f64,
}

const GC: f64 = 1e-3;

fn sample() -> impl Strategy<Value = Sample> {
    (
        (
            1usize..=2,
            prop_oneof![Just(0.0), Just(0.5)],
            any::<bool>(),
            any::<bool>(),
        ),
        (
            1.0..350.0f64,
            -5.0..5.0f64,
            -20.0..130.0f64,
            0.0..2.5f64,
            0.005..0.5f64,
        ),
        (
            prop::array::uniform2(-0.7..0.7f64),
            prop::array::uniform2(-4.0..4.0f64),
        ),
    )
        .prop_map(
            |(
                (nfdir, mu2, exact, frozen),
                (p0, dp, theta, start_rate, dtime),
                (tau_frac, dgam_frac),
            )| Sample {
                nfdir,
                mu2,
                exact,
                frozen,
                load: Loading {
                    p0,
                    dp,
                    tau_frac,
                    dgam_frac,
                },
                theta,
                start_rate,
                dtime,
            },
        )
}

fn call(s: &Sample, dg: [f64; 2], dp: f64, dt: [f64; 2]) -> FricCall {
    let n = s.nfdir;
    let mut c = FricCall::new(n as i32, &table_props(1.0, s.mu2, GC, s.exact, s.frozen));
    c.ciname = "FULL".into();
    c.statev[1] = s.start_rate;
    c.statev[2] = 1.0;
    // A start stress well inside the cone (μ ≥ 0.33 everywhere in the table).
    for i in 0..n {
        c.tau[i] = s.load.tau_frac[i] * 0.3 * s.load.p0 / (n as f64).sqrt()
            * if i == 1 && s.mu2 > 0.0 { 0.5 } else { 1.0 };
        c.dgam[i] = s.load.dgam_frac[i] * GC + dg[i];
    }
    s.load.set_pressure(&mut c, dp);
    c.dtime = s.dtime;
    c.temp = [s.theta + dt[0], s.theta + dt[1]];
    c.call();
    c
}

/// DDTDDG, DDTDDP and DDTDDT against central differences of TAU with the four-column table
/// (every derivative of μ is non-zero somewhere), and the stress on the table's yield surface
/// in slip. Samples whose stencil crosses a kink are skipped; at most a fifth may be.
#[test]
fn tangents_match_central_differences_with_a_table() {
    setup();
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig {
        cases: 1500,
        failure_persistence: None,
        ..ProptestConfig::default()
    });
    let counts = std::cell::Cell::new((0u32, 0u32, 0u32));
    let result = runner.run(&sample(), |s| {
        let n = s.nfdir;
        let base = call(&s, [0.0; 2], 0.0, [0.0; 2]);
        prop_assert!(base.guards_intact());
        prop_assert!(base.pnewdt == 1e36, "{}: {s:?}", FricCall::last_error());
        if base.lm != 0 {
            return Ok(());
        }
        let at = |(g, dp, dt): Shift| call(&s, g, dp, dt);
        let p = s.load.p_end();
        let k_scale = 0.5 * p.max(1.0) / GC;
        let mut skipped = false;
        let mut check =
            |what: String, fd: Option<f64>, an: f64, scale: f64| -> Result<(), TestCaseError> {
                match fd {
                    Some(fd) => prop_assert!(
                        (fd - an).abs() <= 1e-6 * scale + 1e-6 * an.abs(),
                        "{what}: analytic {an}, central difference {fd}, {s:?}"
                    ),
                    None => skipped = true,
                }
                Ok(())
            };
        for b in 0..n {
            for a in 0..n {
                let fd = central_tau(a, 1e-6 * GC, k_scale, along_dgam(b), at);
                check(format!("DDTDDG({a},{b})"), fd, base.ddtddg(a, b), k_scale)?;
            }
        }
        for a in 0..n {
            let fd = central_tau(a, 1e-6 * s.load.p0, 1.0, along_press, at);
            check(format!("DDTDDP({a})"), fd, base.ddtddp[a], 1.0)?;
        }
        let t_scale = p.max(1.0) * 1e-3;
        for k in 0..2 {
            for a in 0..n {
                let fd = central_tau(a, 1e-4, t_scale, along_temp(k), at);
                check(
                    format!("DDTDDT({a},{k})"),
                    fd,
                    base.ddtddt[a + k * n],
                    t_scale,
                )?;
            }
        }
        let (c, sk, slip) = counts.get();
        counts.set((
            c + 1,
            sk + u32::from(skipped),
            slip + u32::from(base.statev[2] == 1.0),
        ));
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    let (checked, skipped, slipping) = counts.get();
    println!("table tangents: {checked} samples, {skipped} with a kink, {slipping} slipping");
    assert!(
        checked > 500 && skipped * 5 < checked,
        "{skipped} of {checked} skipped"
    );
    assert!(
        slipping * 4 > checked,
        "too few slipping samples: {slipping} of {checked}"
    );
}

/// μ of "FULL" at (γ̇, p, θ̄) = (0.25, 50, 25), interpolated by hand: at θ̄ = 0, p = 0:
/// 0.5 − 0.06·0.5 = 0.47 and p = 100: 0.46 − 0.05·0.5 = 0.435, so 0.4525 at p = 50; at θ̄ = 100,
/// p = 0: 0.45 − 0.05·0.25 = 0.4375 and p = 200: 0.42 − 0.06·0.25 = 0.405, so 0.429375 at p = 50;
/// then 0.75·0.4525 + 0.25·0.429375 = 0.44671875.
#[test]
fn fric_coef_reads_the_table() {
    setup();
    let props = table_props(2.0, 1.0, GC, false, false);
    let n = 1usize;
    let mut coef = vec![0.0; 2 * n];
    let mut deriv = vec![0.0; 40 * n];
    let slip = [0.25, 0.0, 0.0, 0.0, 0.0, 0.0];
    let (p, theta) = ([50.0f64], [25.0f64]);
    fric_coef_call(
        &mut coef,
        &mut deriv,
        &props,
        &slip,
        &p,
        &theta,
        b"FULL    ",
    );
    let mu = 0.44671875;
    assert!(
        (coef[0] - mu).abs() < 1e-14,
        "{coef:?} {}",
        FricCall::last_error()
    );
    // μ₂ = μ_tab·PROPS(3)/PROPS(2).
    assert!((coef[1] - 0.5 * mu).abs() < 1e-14);
    // ∂μ/∂γ̇ = 0.75·(0.5·(−0.12) + 0.5·(−0.1)) + 0.25·(0.75·(−0.05) + 0.25·(−0.06)).
    let d_rate = 0.75 * (0.5 * -0.12 + 0.5 * -0.1) + 0.25 * (0.75 * -0.05 + 0.25 * -0.06);
    // ∂μ/∂p = 0.75·(0.435 − 0.47)/100 + 0.25·(0.405 − 0.4375)/200.
    let d_p = 0.75 * (0.435 - 0.47) / 100.0 + 0.25 * (0.405 - 0.4375) / 200.0;
    // ∂μ/∂θ̄ = (0.429375 − 0.4525)/100.
    let d_t = (0.429375 - 0.4525) / 100.0;
    for (j, want) in [(0, d_rate), (1, d_p), (2, d_t)] {
        assert!(
            (deriv[j] - want).abs() < 1e-14,
            "deriv {j}: {} vs {want}",
            deriv[j]
        );
        assert!((deriv[j + 20] - 0.5 * want).abs() < 1e-14);
    }
}

/// Bad PROPS with a table and a name without a table: one message naming FRIC, the
/// interaction and the cause, PNEWDT < 1, nothing written.
#[test]
fn bad_props_and_missing_interaction_are_refused() {
    setup();
    let good = || table_law(1.0, 0.0, GC, false, false);
    let cases: Vec<(&str, Vec<f64>, &str, &str)> = vec![
        (
            "missing interaction",
            good().build(),
            "NOPE",
            "[interactions.NOPE.friction]",
        ),
        (
            "PROPS(9) with table",
            good().mu_k(0.2).build(),
            "RATE",
            "PROPS(9)",
        ),
        (
            "PROPS(12) with table",
            good().b_theta(0.01).build(),
            "RATE",
            "PROPS(12)",
        ),
        ("μ_ref = 0", good().mu(0.0).build(), "RATE", "PROPS(2)"),
    ];
    for (what, props, name, word) in cases {
        let mut c = FricCall::new(2, &props);
        c.ciname = name.into();
        c.statev = vec![0.5, 0.1, 1.0];
        c.nstatv = 3;
        c.set_guards();
        c.press = 100.0;
        c.tau = [3.0, -1.0, c.tau[2], c.tau[3]];
        c.dgam = [1e-3, 2e-3, 0.0];
        c.dtime = 0.1;
        let before = c.clone();
        c.call();
        assert!(c.pnewdt < 1.0, "{what}: not refused");
        let msg = FricCall::last_error();
        assert!(
            msg.contains("FRIC") && msg.contains(name) && msg.contains(word),
            "{what}: {msg}"
        );
        assert_eq!(&c.tau[..2], &before.tau[..2], "{what}");
        assert_eq!(&c.statev[..3], &before.statev[..3], "{what}");
        assert!(c.guards_intact(), "{what}");
    }
}

/// Child side of `bad_tables`: one fric_ call with whatever INTERFACIAL_CONFIG the parent set.
#[test]
fn child_one_call() {
    if std::env::var_os("IFL_FRIC_TABLE_CHILD").is_none() {
        return;
    }
    let mut c = FricCall::new(2, &table_props(1.0, 0.0, GC, false, false));
    c.ciname = "A".into();
    c.statev = vec![0.5, 0.1, 1.0];
    c.nstatv = 3;
    c.set_guards();
    c.press = 10.0;
    c.tau[..2].copy_from_slice(&[1.0, 0.5]);
    c.dgam = [1e-2, 0.0, 0.0];
    c.dtime = 0.1;
    let before = c.clone();
    c.call();
    let unchanged =
        c.tau[..2] == before.tau[..2] && c.statev[..3] == before.statev[..3] && c.guards_intact();
    println!("PNEWDT={}", c.pnewdt);
    println!("UNCHANGED={unchanged}");
    println!("MSG={}", FricCall::last_error());
}

/// Bad tables: file:line of the row at fault, the key and the cause; PNEWDT < 1; state unchanged.
#[test]
fn bad_tables() {
    let dir = std::env::temp_dir();
    let cases = [
        (
            "unsorted",
            "[interactions.A.friction]\ntable = [\n  [0.5, 1.0],\n  [0.4, 0.5],\n]\n",
            ":4:",
            "strictly increasing",
        ),
        (
            "nan",
            "[interactions.A.friction]\ntable = [\n  [0.5, 0.0],\n  [nan, 1.0],\n]\n",
            ":4:",
            "not finite",
        ),
        (
            "negative",
            "[interactions.A.friction]\ntable = [[-0.1, 0.0]]\n",
            ":2:",
            "negative",
        ),
        (
            "width",
            "[interactions.A.friction]\ntable = [\n  [0.5, 0.0, 1.0],\n  [0.4, 1.0],\n]\n",
            ":4:",
            "every row needs 3",
        ),
        (
            "pressure order",
            "[interactions.A.friction]\ntable = [\n  [0.5, 0.0, 9.0],\n  [0.4, 0.0, 1.0],\n]\n",
            ":4:",
            "pressure 1",
        ),
        (
            "empty",
            "[interactions.A.friction]\ntable = []\n",
            ":2:",
            "empty",
        ),
        (
            "unknown key",
            "[interactions.A.friction]\ntable = [[0.5, 0.0]]\nmu = 1.0\n",
            ":3:",
            "mu",
        ),
        (
            "other interaction only",
            "[interactions.B.friction]\ntable = [[0.5, 0.0]]\n",
            "",
            "[interactions.A.friction]",
        ),
    ];
    let exe = std::env::current_exe().unwrap();
    for (tag, text, line, needle) in cases {
        let path = dir.join(
            format!(
                "interfacial-fric-table-bad-{tag}-{}.toml",
                std::process::id()
            )
            .replace(' ', "-"),
        );
        std::fs::write(&path, text).unwrap();
        let out = Command::new(&exe)
            .args([
                "--exact",
                "child_one_call",
                "--nocapture",
                "--test-threads=1",
            ])
            .env("IFL_FRIC_TABLE_CHILD", "1")
            .env("INTERFACIAL_CONFIG", &path)
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{tag}: {text}");
        let pnewdt: f64 = text
            .lines()
            .find_map(|l| l.split("PNEWDT=").nth(1))
            .and_then(|v| v.parse().ok())
            .unwrap_or(f64::NAN);
        assert!(pnewdt < 1.0, "{tag}: {text}");
        assert!(text.contains("UNCHANGED=true"), "{tag}: {text}");
        let msg = text.lines().find(|l| l.starts_with("MSG=")).unwrap_or("");
        assert!(msg.contains("FRIC") && msg.contains(needle), "{tag}: {msg}");
        if !line.is_empty() {
            assert!(
                msg.contains(&format!("{}{line}", path.display())),
                "{tag}: {msg}"
            );
            // (serde names an unknown key itself, without its table.)
            assert!(
                tag == "unknown key" || msg.contains("interactions.A.friction.table"),
                "{tag}: {msg}"
            );
        }
        let _ = std::fs::remove_file(&path);
    }
}

/// Fuzz find (fric target): the extended law (anisotropic, constant μ) at p = 0 with a
/// subnormal DTIME slips a finite amount; STATEV(2) = slip/DTIME saturates at f64::MAX like
/// the plain law's, never ∞.
#[test]
fn extended_slip_rate_saturates_over_a_subnormal_dtime() {
    let props = CoulombBuilder::new()
        .mu(2524902.34375)
        .mu2(49.881744384765625)
        .build_first(5);
    let mut c = FricCall::new(2, &props);
    c.tau[..2].copy_from_slice(&[49.88, 49.88]);
    c.dgam[..2].copy_from_slice(&[49.88, 49.88]);
    c.press = 0.0;
    c.dpress = 2.5e10;
    c.dtime = f64::MIN_POSITIVE;
    c.chrlngth = f64::MIN_POSITIVE;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    assert!(
        c.statev[..3].iter().all(|x| x.is_finite()),
        "{:?}",
        c.statev
    );
    assert_eq!(c.statev[1], f64::MAX);
}
