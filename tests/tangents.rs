//! DDTDDG and DDTDDP against central finite differences of TAU, through `fric_`, over random
//! states in every branch: elastic stick, slip, the τ_max cap, exact-stick slip; NFDIR 1 and 2.

#![allow(clippy::needless_range_loop)] // index loops mirror the a, b indices of the equations

#[path = "common/loading.rs"]
mod loading;
use loading::Loading;

use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;

/// Which branch a sample is meant to exercise; samples too close to a kink are discarded.
#[derive(Clone, Copy, Debug)]
enum Branch {
    Stick,
    Slip,
    ExactSlip,
}

#[derive(Clone, Debug)]
struct Sample {
    nfdir: i32,
    mu: f64,
    tau_max: f64,
    gamma_crit: f64,
    load: Loading,
    branch: Branch,
}

fn sample() -> impl Strategy<Value = Sample> {
    (
        1..=2i32,
        0.05..1.0f64,
        prop_oneof![Just(0.0), 1.0..100.0f64],
        1e-4..1e-2f64,
        1.0..200.0f64,
        -0.5..1.0f64,
        prop::array::uniform2(-0.7..0.7f64),
        prop::array::uniform2(-3.0..3.0f64),
        prop_oneof![
            Just(Branch::Stick),
            Just(Branch::Slip),
            Just(Branch::ExactSlip)
        ],
    )
        .prop_map(
            |(nfdir, mu, tau_max, gamma_crit, p0, dp_frac, tau_frac, dgam_frac, branch)| Sample {
                nfdir,
                mu,
                tau_max,
                gamma_crit,
                load: Loading {
                    p0,
                    dp: dp_frac * p0,
                    tau_frac,
                    dgam_frac,
                },
                branch,
            },
        )
}

fn tau_crit(s: &Sample, p: f64) -> f64 {
    let mp = s.mu * p.max(0.0);
    if s.tau_max > 0.0 {
        mp.min(s.tau_max)
    } else {
        mp
    }
}

fn call_at(s: &Sample, dgam: [f64; 2], dp_shift: f64) -> FricCall {
    let stick_mode = if matches!(s.branch, Branch::ExactSlip) {
        1.0
    } else {
        0.0
    };
    let props = CoulombBuilder::new()
        .mu(s.mu)
        .tau_max(s.tau_max)
        .gamma_crit(s.gamma_crit)
        .stick(stick_mode)
        .build_first(7);
    let mut c = FricCall::new(s.nfdir, &props);
    let n = s.nfdir as usize;
    let tc0 = tau_crit(s, s.load.p0);
    for i in 0..n {
        c.tau[i] = s.load.tau_frac[i] * tc0;
        c.dgam[i] = dgam[i];
    }
    // The start of the increment (p0, TAU) is held fixed: PRESS and DPRESS move together.
    s.load.set_pressure(&mut c, dp_shift);
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(c.lm, 0);
    assert!(c.guards_intact());
    c
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, max_global_rejects: 100_000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn tangents_match_central_differences(s in sample()) {
        let n = s.nfdir as usize;
        let p = s.load.p_end();
        let tc0 = tau_crit(&s, s.load.p0);
        let tc = tau_crit(&s, p);
        prop_assume!(p > 0.0 && tc > 0.0);
        // Keep away from the τ_max kink.
        if s.tau_max > 0.0 {
            prop_assume!((s.mu * p - s.tau_max).abs() > 1e-3 * s.tau_max);
        }
        let gc = s.gamma_crit;
        // Start elastic slip γ̄ = τ̄/k_s(p0); place the predictor in the wanted branch.
        let start: Vec<f64> = (0..n).map(|i| s.load.tau_frac[i] * tc0 * gc / tc0.max(f64::MIN_POSITIVE)).collect();
        let mut dgam = [0.0; 2];
        for i in 0..n {
            dgam[i] = s.load.dgam_frac[i] * gc;
        }
        let pred: f64 = (0..n).map(|i| (start[i] + dgam[i]).powi(2)).sum::<f64>().sqrt();
        match s.branch {
            Branch::Stick => prop_assume!(pred < gc * 0.999),
            Branch::Slip => prop_assume!(pred > gc * 1.001),
            Branch::ExactSlip => {
                // Slipping on entry (LM = 0) and moving with the start stress: Δγ·τ(t) > 0.
                let along: f64 = (0..n).map(|i| dgam[i] * s.load.tau_frac[i]).sum();
                let size: f64 = (0..n).map(|i| dgam[i] * dgam[i]).sum::<f64>().sqrt();
                prop_assume!(along > 1e-3 * size * 0.7 && size > 1e-2 * gc);
            }
        }
        let base = call_at(&s, dgam, 0.0);
        let k_scale = tc / gc;
        // DDTDDG(a,b) against central differences in DGAM(b).
        let h = 1e-7 * gc;
        for b in 0..n {
            let mut up = dgam;
            let mut dn = dgam;
            up[b] += h;
            dn[b] -= h;
            let cu = call_at(&s, up, 0.0);
            let cd = call_at(&s, dn, 0.0);
            for a in 0..n {
                let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * h);
                let an = base.ddtddg(a, b);
                prop_assert!((fd - an).abs() <= 1e-5 * k_scale + 1e-6 * an.abs(),
                    "DDTDDG({a},{b}): analytic {an}, central difference {fd}, {s:?}");
            }
        }
        // DDTDDP(a) against central differences in the end pressure.
        let hp = 1e-6 * s.load.p0;
        let cu = call_at(&s, dgam, hp);
        let cd = call_at(&s, dgam, -hp);
        for a in 0..n {
            let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * hp);
            let an = base.ddtddp[a];
            prop_assert!((fd - an).abs() <= 1e-6 * s.mu.max(1e-3) + 1e-6 * an.abs(),
                "DDTDDP({a}): analytic {an}, central difference {fd}, {s:?}");
        }
    }
}
