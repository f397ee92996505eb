//! Law 1's constant stick stiffness (`PROPS(7) = 4`, `PROPS(5)` = k_s), through `fric_`:
//! the closed form of the elastic predictor and return map (τ^tr = τ̄ + k_s·Δγ, stick while
//! |τ^tr| ≤ μp, else τ = μp·τ^tr/|τ^tr|), its tangents against central differences, and the
//! refusals (k_s missing, with anisotropy or a μ law).

#[path = "common/central.rs"]
mod central;
#[path = "common/refusal.rs"]
mod refusal;

use central::{along_dgam, along_press, central_tau};
use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;

const MU: f64 = 0.3;
const K: f64 = 5.0e3;

fn props() -> Vec<f64> {
    CoulombBuilder::new()
        .mu(MU)
        .stick(4.0)
        .stick_stiffness(K)
        .build()
}

/// One `fric_` call, NFDIR 2, with start stress `tau`, motion `dgam`, end pressure `p` and
/// start pressure `p0`.
fn call(tau: [f64; 2], dgam: [f64; 2], p: f64, p0: f64) -> FricCall {
    let mut c = FricCall::new(2, &props());
    c.tau[..2].copy_from_slice(&tau);
    c.dgam[..2].copy_from_slice(&dgam);
    c.press = p;
    c.dpress = p - p0;
    c.dtime = 0.1;
    c.chrlngth = 1.0;
    c.call();
    c
}

/// The closed form: (τ, Δγ^sl, stick?).
fn closed_form(tau: [f64; 2], dgam: [f64; 2], p: f64) -> ([f64; 2], [f64; 2], bool) {
    let tr = [tau[0] + K * dgam[0], tau[1] + K * dgam[1]];
    let len = (tr[0] * tr[0] + tr[1] * tr[1]).sqrt();
    let crit = MU * p;
    if len <= crit {
        (tr, [0.0; 2], true)
    } else {
        let n = [tr[0] / len, tr[1] / len];
        let s = (len - crit) / K;
        ([crit * n[0], crit * n[1]], [s * n[0], s * n[1]], false)
    }
}

#[test]
fn stress_and_slip_follow_the_closed_form_in_stick_and_slip() {
    // (start stress, motion, end pressure, start pressure): stick, stick with a pressure
    // change (the stress does not follow p), slip, slip against the start stress.
    let cases = [
        ([0.0, 0.0], [1e-4, -5e-5], 10.0, 10.0),
        ([1.0, -0.5], [1e-4, 2e-4], 12.0, 8.0),
        ([0.0, 0.0], [2e-3, 1e-3], 10.0, 10.0),
        ([2.0, 1.0], [-3e-3, 5e-4], 9.0, 10.0),
    ];
    for (tau, dgam, p, p0) in cases {
        let c = call(tau, dgam, p, p0);
        assert_eq!(
            c.pnewdt,
            1e36,
            "{tau:?} {dgam:?}: {}",
            FricCall::last_error()
        );
        let (t, slip, stick) = closed_form(tau, dgam, p);
        for a in 0..2 {
            assert!(
                (c.tau[a] - t[a]).abs() <= 1e-12 * (1.0 + t[a].abs()),
                "TAU({a}): {} vs {}",
                c.tau[a],
                t[a]
            );
            assert!(
                (c.dslip[a] - slip[a]).abs() <= 1e-15,
                "DSLIP({a}): {} vs {}",
                c.dslip[a],
                slip[a]
            );
        }
        assert_eq!(c.statev[2], if stick { 0.0 } else { 1.0 }, "STATEV(3)");
        // Stick stress independent of the pressure; in slip on the cone.
        if stick {
            assert_eq!(c.ddtddp[..2], [0.0, 0.0]);
        } else {
            let len = (c.tau[0] * c.tau[0] + c.tau[1] * c.tau[1]).sqrt();
            assert!((len - MU * p).abs() <= 1e-12 * MU * p);
        }
    }
}

#[test]
fn nfdir_1_clamps_the_trial_stress() {
    // (start stress, motion, pressure): stick, slip forwards, slip backwards.
    for (tau, dgam, p) in [(1.0, 2e-4, 10.0), (2.0, 5e-3, 10.0), (-1.0, -4e-3, 8.0)] {
        let mut c = FricCall::new(1, &props());
        c.tau[0] = tau;
        c.dgam[0] = dgam;
        c.press = p;
        c.dpress = 0.0;
        c.dtime = 0.1;
        c.chrlngth = 1.0;
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        let trial = tau + K * dgam;
        let want = trial.clamp(-MU * p, MU * p);
        assert!(
            (c.tau[0] - want).abs() <= 1e-12 * want.abs(),
            "TAU {} vs {want}",
            c.tau[0]
        );
        let want_slip = (trial - want) / K;
        assert!(
            (c.dslip[0] - want_slip).abs() <= 1e-15,
            "DSLIP {} vs {want_slip}",
            c.dslip[0]
        );
        let want_k = if trial.abs() <= MU * p { K } else { 0.0 };
        assert_eq!(c.ddtddg(0, 0), want_k, "DDTDDG");
    }
}

#[test]
fn tangents_match_central_differences() {
    let cases = [
        ([1.0, -0.5], [1e-4, 2e-4], 12.0, 8.0),
        ([0.0, 0.0], [2e-3, 1e-3], 10.0, 10.0),
        ([2.0, 1.0], [-3e-3, 5e-4], 9.0, 10.0),
    ];
    for (tau, dgam, p, p0) in cases {
        let base = call(tau, dgam, p, p0);
        let at = |shift: central::Shift| {
            let (g, dp, _) = shift;
            call(tau, [dgam[0] + g[0], dgam[1] + g[1]], p + dp, p0)
        };
        for a in 0..2 {
            for b in 0..2 {
                let fd = central_tau(a, 1e-7, K, along_dgam(b), at).expect("no kink");
                let d = base.ddtddg(a, b);
                assert!((fd - d).abs() <= 1e-5 * K, "DDTDDG({a},{b}): {d} vs {fd}");
            }
            let fd = central_tau(a, 1e-5, 1.0, along_press, at).expect("no kink");
            assert!(
                (fd - base.ddtddp[a]).abs() <= 1e-6,
                "DDTDDP({a}): {} vs {fd}",
                base.ddtddp[a]
            );
        }
    }
}

#[test]
fn refusals_name_the_entry() {
    // k_s missing (PROPS(5) = 0 under PROPS(7) = 4).
    let p = CoulombBuilder::new().mu(MU).stick(4.0).build();
    let c = FricCall::new(2, &p);
    refusal::assert_fric_refused(c, "k_s missing", "PROPS(5)");
    // With a μ law: the plain law only.
    let p = CoulombBuilder::new()
        .mu(MU)
        .stick(4.0)
        .stick_stiffness(K)
        .mu_law(1.0)
        .mu_k(0.1)
        .decay(1.0)
        .build();
    let c = FricCall::new(2, &p);
    refusal::assert_fric_refused(c, "with a decay law", "PROPS(7)");
}
