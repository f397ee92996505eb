//! Rate-and-state friction (`PROPS(1) = 3`) through `fric_`, increment by increment as a host
//! drives it, against closed forms of the Dieterich–Ruina law at constant slip rate:
//!
//! - steady sliding at V: τ = μ_ss(V)·p, μ_ss = μ₀ + (a − b)·ln(V/V₀) (logarithmic form; the
//!   regularised form's own steady state a·asinh(V/(2V₀)·e^((μ₀ + b·ln(V₀/V))/a))), aging and
//!   slip laws, NFDIR 1 and 2, reached to round-off at any increment size (θ is advanced
//!   exactly at constant V and the elastic slip stays γ_crit);
//! - a velocity step V₁ → V₂ from steady state: at the end of every increment after the step
//!   τ/p = μ(V₂, θ(t)) with the analytic θ(t) of each evolution law at constant rate, so the
//!   jump is a·ln(V₂/V₁) as Δt → 0 and the relaxation to μ_ss(V₂) takes place over a slip of
//!   order L (checked at slip L and 10 L);
//! - DDTDDG and DDTDDP against central differences of `TAU` in stick and slip, NFDIR 1 and 2;
//! - bad input refused by name with PNEWDT < 1 and TAU, STATEV unchanged.

#[path = "common/central.rs"]
mod central;

use central::{move_press, sides, slope};
use interfacial::props::RateStateBuilder;
use interfacial_test_hosts::FricCall;

const MU0: f64 = 0.6;
const A: f64 = 0.01;
const B: f64 = 0.015;
const V0: f64 = 1e-6;
const L: f64 = 1e-5;
const GAMMA_CRIT: f64 = 1e-7;
const P: f64 = 50.0;

fn props(evolution: f64, form: f64) -> Vec<f64> {
    RateStateBuilder::new()
        .mu0(MU0)
        .a(A)
        .b(B)
        .v0(V0)
        .l(L)
        .evolution(evolution)
        .form(form)
        .gamma_crit(GAMMA_CRIT)
        .build()
}

/// A point in contact at pressure P with NSTATV = 4 (θ not yet started).
fn point(nfdir: i32, props: &[f64]) -> FricCall {
    let mut c = FricCall::new(nfdir, props);
    c.nstatv = 4;
    c.statev = vec![0.0; 4];
    c.press = P;
    c.dpress = P;
    c
}

/// One increment of slip `dgam` (first direction, or along (3, 4)/5 in 3-D) over `dtime`;
/// panics on a refusal.
fn step(c: &mut FricCall, dgam: f64, dtime: f64) {
    let dir = if c.nfdir == 2 { [0.6, 0.8] } else { [1.0, 0.0] };
    c.dgam = [dgam * dir[0], dgam * dir[1], 0.0];
    c.dtime = dtime;
    c.pnewdt = 1e36;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "refused: {}", FricCall::last_error());
    c.dpress = 0.0;
}

fn tau_eq(c: &FricCall) -> f64 {
    (0..c.nfdir as usize)
        .map(|i| c.tau[i] * c.tau[i])
        .sum::<f64>()
        .sqrt()
}

/// The steady-state coefficient at V of each form.
fn mu_ss(v: f64, regularized: bool) -> f64 {
    if regularized {
        A * (v / (2.0 * V0) * ((MU0 + B * (V0 / v).ln()) / A).exp()).asinh()
    } else {
        MU0 + (A - B) * (v / V0).ln()
    }
}

/// μ(V, θ) of each form, written out here from the law's definition.
fn mu(v: f64, theta: f64, regularized: bool) -> f64 {
    let psi = MU0 + B * (V0 * theta / L).ln();
    if regularized {
        A * (v / (2.0 * V0) * (psi / A).exp()).asinh()
    } else {
        psi + A * (v / V0).ln()
    }
}

/// θ after sliding at constant V for a time t from θ₁, each evolution law's analytic solution.
fn theta_at(theta1: f64, v: f64, t: f64, slip_law: bool) -> f64 {
    let decay = (-v * t / L).exp();
    if slip_law {
        L / v * ((v * theta1 / L).ln() * decay).exp()
    } else {
        L / v + (theta1 - L / v) * decay
    }
}

#[test]
fn steady_sliding_reaches_the_steady_state_coefficient_at_any_increment() {
    for evolution in [0.0, 1.0] {
        for form in [0.0, 1.0] {
            for nfdir in [1, 2] {
                for (v, per_l) in [(1e-6, 10.0), (1e-4, 3.0), (3e-7, 100.0), (1e-5, 0.5)] {
                    // `per_l` increments per slip L; 60 L of slip reaches steady state.
                    let props = props(evolution, form);
                    let mut c = point(nfdir, &props);
                    let dgam = L / per_l;
                    let dtime = dgam / v;
                    let n = (60.0 * per_l) as usize;
                    for _ in 0..n {
                        step(&mut c, dgam, dtime);
                    }
                    let want = mu_ss(v, form == 1.0) * P;
                    let got = tau_eq(&c);
                    assert!(
                        (got - want).abs() <= 1e-9 * want,
                        "evolution {evolution} form {form} NFDIR {nfdir} V {v}: τ {got} vs μ_ss·p {want}"
                    );
                    // STATEV: slip rate V, sliding, θ = L/V.
                    assert!((c.statev[1] - v).abs() <= 1e-9 * v);
                    assert_eq!(c.statev[2], 1.0);
                    assert!((c.statev[3] - L / v).abs() <= 1e-8 * L / v);
                }
            }
        }
    }
}

#[test]
fn velocity_step_follows_the_analytic_state_evolution() {
    let (v1, v2) = (1e-6, 1e-5);
    for evolution in [0.0, 1.0] {
        for form in [0.0, 1.0] {
            let regularized = form == 1.0;
            for per_l in [2.0, 20.0, 200.0] {
                let props = props(evolution, form);
                let mut c = point(1, &props);
                // Steady state at V₁ (60 L at 20 increments per L).
                let (dg1, n1) = (L / 20.0, 1200);
                for _ in 0..n1 {
                    step(&mut c, dg1, dg1 / v1);
                }
                assert!((tau_eq(&c) - mu_ss(v1, regularized) * P).abs() <= 1e-9 * P);
                let theta1 = c.statev[3];
                let dgam = L / per_l;
                let dtime = dgam / v2;
                let mut first = None;
                for k in 1..=(10.0 * per_l) as usize {
                    step(&mut c, dgam, dtime);
                    let t = k as f64 * dtime;
                    let want = mu(v2, theta_at(theta1, v2, t, evolution == 1.0), regularized);
                    let got = tau_eq(&c) / P;
                    assert!(
                        (got - want).abs() <= 1e-10,
                        "evolution {evolution} form {form}, {per_l}/L, increment {k}: μ {got} vs {want}"
                    );
                    first.get_or_insert(got);
                }
                // The jump: a·ln(V₂/V₁) plus the evolution over the first increment, which is
                // b·ln(θ(Δt)/θ₁) (0 as Δt → 0).
                let first = first.unwrap_or(f64::NAN);
                let evolved = theta_at(theta1, v2, dtime, evolution == 1.0);
                let jump = first - mu_ss(v1, regularized);
                if !regularized {
                    let want = A * (v2 / v1).ln() + B * (evolved / theta1).ln();
                    assert!((jump - want).abs() <= 1e-10, "{jump} vs {want}");
                }
                // After 10 L of slip, within the decayed distance from the new steady state:
                // b·ln(θ/θ_ss) with ln(V₂θ/L) = ln(V₂/V₁)·e^(−10) (slip law) or
                // V₂θ/L − 1 = (V₂/V₁ − 1)·e^(−10) (aging law).
                let to_ss = (tau_eq(&c) / P - mu_ss(v2, regularized)).abs();
                let decayed = if evolution == 1.0 {
                    (v2 / v1).ln()
                } else {
                    v2 / v1 - 1.0
                } * (-10.0f64).exp();
                assert!(to_ss <= 1.01 * B * decayed, "{to_ss} vs {}", B * decayed);
            }
        }
    }
}

/// Central differences of TAU in DGAM and in PRESS (with DPRESS, so that the start of the
/// increment is held fixed) against DDTDDG and DDTDDP.
#[test]
fn tangents_agree_with_central_differences() {
    for evolution in [0.0, 1.0] {
        for form in [0.0, 1.0] {
            for nfdir in [1, 2] {
                let props = props(evolution, form);
                // A start state: slid at 2e-6 for 5 L, then one increment of each kind.
                let mut base = point(nfdir, &props);
                for _ in 0..100 {
                    step(&mut base, L / 20.0, L / 20.0 / 2e-6);
                }
                // Stick (a small reversal) and slip (a large increment, off-axis in 3-D).
                for dgam in [[-0.5 * GAMMA_CRIT, -0.5 * GAMMA_CRIT], [3e-6, 1e-6]] {
                    let mut c = base.clone();
                    c.dgam = [dgam[0], dgam[1], 0.0];
                    c.dtime = 1.0;
                    c.dpress = 2.0;
                    c.press = P + 2.0;
                    let mut at = c.clone();
                    at.call();
                    assert_eq!(at.pnewdt, 1e36, "{}", FricCall::last_error());
                    let n = nfdir as usize;
                    for b in 0..n {
                        let h = 1e-7 * GAMMA_CRIT.max(dgam[0].abs());
                        let (plus, minus) = sides(&c, h, |c, h| c.dgam[b] += h);
                        for a in 0..n {
                            let fd = slope(&plus, &minus, a, h);
                            let an = at.ddtddg(a, b);
                            let scale = an.abs().max(P * 0.6 / GAMMA_CRIT * 1e-6);
                            assert!(
                                (an - fd).abs() <= 1e-5 * scale,
                                "DDTDDG({a},{b}) {an} vs {fd} (evolution {evolution} form {form} NFDIR {nfdir} dgam {dgam:?})"
                            );
                        }
                    }
                    let h = 1e-6 * P;
                    let (plus, minus) = sides(&c, h, move_press);
                    for a in 0..n {
                        let fd = slope(&plus, &minus, a, h);
                        assert!(
                            (at.ddtddp[a] - fd).abs() <= 1e-6 * fd.abs().max(1e-3),
                            "DDTDDP({a}) {} vs {fd}",
                            at.ddtddp[a]
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn bad_input_is_refused_by_name() {
    let good = props(0.0, 0.0);
    type Spoil = Box<dyn Fn(&mut FricCall)>;
    let cases: Vec<(&str, Spoil, &str)> = vec![
        ("a < 0", Box::new(|c| c.props[2] = -0.01), "PROPS(3)"),
        ("V₀ = 0", Box::new(|c| c.props[4] = 0.0), "PROPS(5)"),
        ("L < 0", Box::new(|c| c.props[5] = -1e-5), "PROPS(6)"),
        (
            "regularised with a = 0",
            Box::new(|c| {
                c.props[2] = 0.0;
                c.props[7] = 1.0;
            }),
            "PROPS(3)",
        ),
        ("θ < 0", Box::new(|c| c.statev[3] = -1.0), "STATEV(4)"),
        ("θ NaN", Box::new(|c| c.statev[3] = f64::NAN), "STATEV(4)"),
        ("NSTATV 3", Box::new(|c| c.nstatv = 3), "NSTATV = 3"),
        ("DTIME 0", Box::new(|c| c.dtime = 0.0), "DTIME"),
        ("PRESS NaN", Box::new(|c| c.press = f64::NAN), "PRESS"),
        (
            "a negative start rate after a slip",
            Box::new(|c| {
                c.statev[1] = -1e-3;
                c.statev[2] = 1.0;
            }),
            "STATEV(2)",
        ),
    ];
    for (what, spoil, word) in cases {
        let mut c = point(2, &good);
        step(&mut c, 1e-6, 1.0);
        c.dgam = [1e-6, 0.0, 0.0];
        c.dtime = 1.0;
        spoil(&mut c);
        c.set_guards();
        let before = c.clone();
        c.pnewdt = 1e36;
        c.call();
        let msg = FricCall::last_error();
        assert!(c.pnewdt < 1.0, "{what}: not refused");
        assert!(msg.contains(word) && msg.contains("FRIC"), "{what}: {msg}");
        assert_eq!(c.tau[..2], before.tau[..2], "{what}");
        assert!(c.guards_intact(), "{what}");
        for i in 0..4 {
            assert!(
                c.statev[i] == before.statev[i] || c.statev[i].is_nan(),
                "{what}: STATEV({}) changed",
                i + 1
            );
        }
    }
}

/// `NSTATV` below the Coulomb law's 3 is refused naming the rate-and-state law and its 4 (the
/// law checks its own need). Found by the `fric` fuzz target's law-3 arm.
#[test]
fn a_short_nstatv_names_the_rate_state_law() {
    for nstatv in [0, 2] {
        let mut c = point(1, &props(0.0, 0.0));
        c.nstatv = nstatv;
        c.dgam = [1e-6, 0.0, 0.0];
        c.pnewdt = 1e36;
        c.call();
        let msg = FricCall::last_error();
        assert!(c.pnewdt < 1.0, "NSTATV = {nstatv}: not refused");
        assert!(
            msg.contains("needs 4") && !msg.contains("Coulomb"),
            "NSTATV = {nstatv}: {msg}"
        );
    }
}

/// A μ(V, θ) out of f64's range is never taken as μ = 0: here (slip law, so θ stays near
/// θ₀ = 10⁻¹⁰⁰) b = 0 and V₀θ/L ≈ 10⁻⁴⁰⁰ underflows, where μ = μ₀ + a·ln(V/V₀) ≈ 7.4 (b = 0
/// drops the state term). Found by the `fric` fuzz target's law-3 arm. Either a refusal or the
/// slip at μ₀ + a·ln(V/V₀) passes.
#[test]
fn a_coefficient_out_of_range_is_not_taken_as_zero() {
    let props = RateStateBuilder::new()
        .mu0(MU0)
        .a(A)
        .b(0.0)
        .v0(1e-300)
        .l(1.0)
        .evolution(1.0)
        .gamma_crit(GAMMA_CRIT)
        .theta0(1e-100)
        .build();
    let mut c = point(1, &props);
    c.dgam = [1e-6, 0.0, 0.0];
    c.dtime = 1.0;
    c.pnewdt = 1e36;
    c.call();
    let v = (1e-6 - GAMMA_CRIT) / 1.0;
    let mu = MU0 + A * (v.ln() - 1e-300f64.ln());
    assert!(
        c.pnewdt < 1.0 || (tau_eq(&c) - mu * P).abs() <= 1e-9 * mu * P,
        "accepted with τ = {}, μ·p = {}",
        tau_eq(&c),
        mu * P
    );
}

/// A state so far below L/V₀ that the regularised stick strength at V₀ is subnormal
/// (e^(ψ/a) ≈ 10⁻³¹⁰; found by the law-selection property test): from rest (τ̄ = 0) the point
/// sticks with k_s = μ*·p/γ_crit, μ* = a·asinh(½·e^(ψ/a)), instead of forming the start's
/// elastic slip as 0·(γ_crit/τ̄_s) = 0·∞ = NaN and refusing the increment.
#[test]
fn a_subnormal_stick_strength_sticks_from_rest() {
    let (mu0, a, b, v0, l, theta0) = (0.0, 0.0189, 1.0, 1e-6, 2.0, 2.74);
    let props = RateStateBuilder::new()
        .mu0(mu0)
        .a(a)
        .b(b)
        .v0(v0)
        .l(l)
        .evolution(1.0)
        .form(1.0)
        .gamma_crit(1.0)
        .theta0(theta0)
        .build();
    let mu_stick = a * (0.5 * ((mu0 + b * (v0 * theta0 / l).ln()) / a).exp()).asinh();
    assert!(
        mu_stick > 0.0 && mu_stick * P < f64::MIN_POSITIVE,
        "a subnormal strength"
    );
    for nfdir in [1, 2] {
        let mut c = point(nfdir, &props);
        // In contact at P already at the start: the start's strength is the subnormal one.
        c.dpress = 0.0;
        step(&mut c, 0.01, 0.1);
        // |τ| without squares (τ² underflows to 0 here).
        let tau = c.tau[0].hypot(if nfdir == 2 { c.tau[1] } else { 0.0 });
        let expected = mu_stick * P * 0.01;
        assert!(
            (tau - expected).abs() <= 1e-6 * expected,
            "NFDIR {nfdir}: |τ| = {tau:e}, k_s·|Δγ| = {expected:e}"
        );
        assert_eq!(
            c.statev[..4],
            [0.0, 0.0, 0.0, theta0],
            "stick; the slip law keeps θ"
        );
    }
}
