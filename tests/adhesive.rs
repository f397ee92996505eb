//! The adhesive friction law (seed 004, `PROPS(1) = 2`) through `fric_` and `uinter_`:
//! - tangents against central finite differences of our own outputs in every branch (stick,
//!   slip with each of the 16 combinations of μ_s ≠ μ_d, S_a, k_μ, v_½; bonded; re-contact),
//!   NFDIR / NDIR in 2-D and 3-D;
//! - the law's residual τ − g(Δs/Δt) ≈ 0 after every slip update;
//! - with S_a = N_a = k_μ = v_½ = 0 the results are bit-for-bit those of the Coulomb law, and
//!   the general path agrees with them to round-off;
//! - bad input gives one message and PNEWDT < 1.

#![allow(clippy::needless_range_loop)] // index loops mirror the a, b indices of the equations

use interfacial::laws::adhesive::{Adhesive, AdhesiveParameters, SlideBranch};
use interfacial::laws::contact::{Contact, Increment};
use interfacial::laws::coulomb::{Coulomb, CoulombState};
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::{FricCall, UinterCall};
use proptest::prelude::*;

#[path = "common/threads.rs"]
mod threads;
use threads::map_on_threads;

const GAMMA_CRIT: f64 = 1e-3;

/// Option combination `mask`: bit 0 μ_s > μ_d, bit 1 S_a, bit 2 k_μ, bit 3 v_½.
fn params(mask: u32, mu: f64) -> AdhesiveParameters {
    AdhesiveParameters {
        coeff: mu,
        coeff_static: if mask & 1 != 0 { 1.6 * mu } else { -1.0 },
        sa: if mask & 2 != 0 { 7.0 } else { 0.0 },
        na: 20.0,
        kmu: if mask & 4 != 0 { 0.4 } else { 0.0 },
        vhalf: if mask & 8 != 0 { 0.02 } else { 0.0 },
    }
}

/// The law `p` with γ_crit = [`GAMMA_CRIT`] as `PROPS`; `fric_` reads `PROPS(1..8)`.
fn adhesive(p: &AdhesiveParameters) -> AdhesiveBuilder {
    AdhesiveBuilder::new()
        .coeff(p.coeff)
        .coeff_static(p.coeff_static)
        .sa(p.sa)
        .na(p.na)
        .kmu(p.kmu)
        .vhalf(p.vhalf)
        .gamma_crit(GAMMA_CRIT)
}

fn fric_props(p: &AdhesiveParameters) -> Vec<f64> {
    adhesive(p).build_first(8)
}

#[derive(Clone, Debug)]
struct Sample {
    nfdir: i32,
    mask: u32,
    mu: f64,
    p0: f64,
    dp: f64,
    tau_frac: [f64; 2],
    dgam: [f64; 2],
    dtime: f64,
}

fn sample() -> impl Strategy<Value = Sample> {
    (
        1..=2i32,
        0..16u32,
        0.05..0.8f64,
        1.0..200.0f64,
        -0.5..1.0f64,
        prop::array::uniform2(-0.7..0.7f64),
        prop::array::uniform2(-8.0..8.0f64),
        prop_oneof![Just(1.0), 0.01..2.0f64],
    )
        .prop_map(
            |(nfdir, mask, mu, p0, dp_frac, tau_frac, dgam, dtime)| Sample {
                nfdir,
                mask,
                mu,
                p0,
                dp: dp_frac * p0,
                tau_frac,
                dgam: [dgam[0] * GAMMA_CRIT, dgam[1] * GAMMA_CRIT],
                dtime,
            },
        )
}

fn fric_at(s: &Sample, dgam: [f64; 2], dp_shift: f64) -> FricCall {
    let p = params(s.mask, s.mu);
    let mut c = FricCall::new(s.nfdir, &fric_props(&p));
    let n = s.nfdir as usize;
    // Start stress inside the static strength at the start pressure.
    let start = p.coeff_static.max(p.coeff) * (s.p0 - s.dp).max(0.0) + p.sa;
    for a in 0..n {
        c.tau[a] = s.tau_frac[a] * start;
        c.dgam[a] = dgam[a];
    }
    // The start of the increment, p − Δp, is held fixed: shift PRESS and DPRESS together.
    c.press = s.p0 + dp_shift;
    c.dpress = s.dp + dp_shift;
    c.dtime = s.dtime;
    c.set_guards();
    c.call();
    c
}

/// Outcome of one finite-difference check.
#[derive(Debug, PartialEq)]
enum Fd {
    /// Every tangent matched; the status (`STATEV(3)`) of the point.
    Matched(f64),
    /// A perturbation changed the branch (too close to a kink to difference).
    Kink,
}

/// A finite-difference check as a property: a match passes, a kink discards the sample, a
/// mismatch fails with its message.
fn as_property(check: Result<Fd, String>) -> Result<(), TestCaseError> {
    match check {
        Ok(Fd::Matched(_)) => Ok(()),
        Ok(Fd::Kink) => Err(TestCaseError::reject("a perturbation changed the branch")),
        Err(e) => Err(TestCaseError::fail(e)),
    }
}

/// DDTDDG and DDTDDP of `fric_` against central differences of TAU.
fn fric_fd(s: &Sample) -> Result<Fd, String> {
    let n = s.nfdir as usize;
    let base = fric_at(s, s.dgam, 0.0);
    if base.pnewdt != 1e36 || !base.guards_intact() {
        return Err(format!("call failed: {}", FricCall::last_error()));
    }
    let status = base.statev[2];
    let scale = base.ddtddg(0, 0).abs().max(1.0);
    let h = 1e-7 * GAMMA_CRIT;
    // Round-off of TAU divided by the step.
    let noise = 8.0 * f64::EPSILON * (base.tau[0].abs() + base.tau[1].abs() + 1.0) / h;
    for b in 0..n {
        let (mut up, mut down) = (s.dgam, s.dgam);
        up[b] += h;
        down[b] -= h;
        let (cu, cd) = (fric_at(s, up, 0.0), fric_at(s, down, 0.0));
        if cu.statev[2] != status || cd.statev[2] != status {
            return Ok(Fd::Kink);
        }
        for a in 0..n {
            let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * h);
            if (fd - base.ddtddg(a, b)).abs() > 1e-5 * scale + noise {
                return Err(format!(
                    "DDTDDG({},{}) = {} vs FD {fd} (status {status})",
                    a + 1,
                    b + 1,
                    base.ddtddg(a, b)
                ));
            }
        }
    }
    let hp = 1e-6 * s.p0;
    let (cu, cd) = (fric_at(s, s.dgam, hp), fric_at(s, s.dgam, -hp));
    if cu.statev[2] != status || cd.statev[2] != status {
        return Ok(Fd::Kink);
    }
    for a in 0..n {
        let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * hp);
        if (fd - base.ddtddp[a]).abs() > 1e-5 * (1.0 + base.ddtddp[a].abs()) {
            return Err(format!(
                "DDTDDP({}) = {} vs FD {fd} (status {status})",
                a + 1,
                base.ddtddp[a]
            ));
        }
    }
    Ok(Fd::Matched(status))
}

/// Every option combination in stick and in slip, NFDIR 1 and 2, each hit on purpose.
#[test]
fn fric_tangents_in_every_named_branch() {
    for nfdir in [1, 2] {
        for mask in 0..16 {
            for (dgam, want) in [([0.3, 0.2], 0.0), ([4.0, -2.5], 1.0)] {
                let s = Sample {
                    nfdir,
                    mask,
                    mu: 0.4,
                    p0: 50.0,
                    dp: 10.0,
                    tau_frac: [0.2, -0.1],
                    dgam: [dgam[0] * GAMMA_CRIT, dgam[1] * GAMMA_CRIT],
                    dtime: 0.3,
                };
                assert_eq!(fric_fd(&s), Ok(Fd::Matched(want)), "{s:?}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// DDTDDG and DDTDDP against central differences of TAU, in stick and in slip for every
    /// option combination; samples whose perturbations change the branch are discarded.
    #[test]
    fn fric_tangents_match_finite_differences(s in sample()) {
        as_property(fric_fd(&s))?;
    }

    /// After every slip update the seed's law holds at the end-of-increment slip rate:
    /// |τ| = ((μ_s v_½ + μ_d Δv)/(v_½ + Δv) + k_μ Δv)·p + S_a, to round-off.
    #[test]
    fn residual_is_zero_after_every_slip_update(
        mask in 0..16u32, mu in 0.0..1.0f64, p in 0.0..500.0f64,
        gpr in 1.0..1e4f64, angle in 0.0..6.3f64, dtime in prop_oneof![Just(1.0), 1e-4..1e3f64],
    ) {
        let law = Adhesive::new(&params(mask, mu)).unwrap().with_critical_slip_absolute(GAMMA_CRIT).unwrap();
        let dgam = [gpr * GAMMA_CRIT * angle.cos(), gpr * GAMMA_CRIT * angle.sin()];
        let s = law.slide(None, &[0.0, 0.0], &dgam, p, p, dtime, GAMMA_CRIT).unwrap();
        if s.branch == SlideBranch::Slip && s.stick_stiffness > 0.0 {
            let r = law.slide_residual(&s, p);
            prop_assert!(r.abs() < 1e-12, "residual {r:e} for {s:?}");
            // The admissible root: slip along the trial direction, no more than the predictor.
            let slip: f64 = s.traction.dslip.iter().zip(&dgam).map(|(a, b)| a * b).sum();
            prop_assert!(slip >= 0.0);
            let eq = (s.traction.dslip[0].powi(2) + s.traction.dslip[1].powi(2)).sqrt();
            prop_assert!(eq <= gpr * GAMMA_CRIT * (1.0 + 1e-12));
        }
    }

    /// S_a = N_a = k_μ = v_½ = 0 and no static coefficient: PROPS(1) = 2 gives bit-for-bit the
    /// results of PROPS(1) = 1 (the same code runs), whatever N_a.
    #[test]
    fn coulomb_special_case_is_identical(s in sample(), na in prop_oneof![Just(0.0), 1.0..10.0f64],
                                         static_entry in prop_oneof![Just(-1.0), Just(0.0)]) {
        let adhesive = AdhesiveBuilder::new().coeff(s.mu).coeff_static(static_entry).na(na)
            .gamma_crit(GAMMA_CRIT).build_first(8);
        let coulomb = CoulombBuilder::new().mu(s.mu).gamma_crit(GAMMA_CRIT).build_first(5);
        let run = |props: &[f64]| {
            let mut c = FricCall::new(s.nfdir, props);
            for a in 0..s.nfdir as usize {
                c.tau[a] = s.tau_frac[a] * s.mu * (s.p0 - s.dp).max(0.0);
                c.dgam[a] = s.dgam[a];
            }
            c.press = s.p0;
            c.dpress = s.dp;
            c.dtime = s.dtime;
            c.set_guards();
            c.call();
            c
        };
        let (a, c) = (run(&adhesive), run(&coulomb));
        prop_assert_eq!(a.tau.map(f64::to_bits), c.tau.map(f64::to_bits));
        prop_assert_eq!(a.ddtddg.map(f64::to_bits), c.ddtddg.map(f64::to_bits));
        prop_assert_eq!(a.ddtddp.map(f64::to_bits), c.ddtddp.map(f64::to_bits));
        prop_assert_eq!(a.dslip.map(f64::to_bits), c.dslip.map(f64::to_bits));
        prop_assert_eq!((a.sed.to_bits(), a.sfd.to_bits(), a.lm), (c.sed.to_bits(), c.sfd.to_bits(), c.lm));
        prop_assert_eq!(&a.statev, &c.statev);
    }

    /// The general adhesive path with the Coulomb parameters agrees with the Coulomb law to
    /// round-off (so the special-case shortcut changes cost, not answers).
    #[test]
    fn general_path_agrees_with_coulomb(s in sample()) {
        let law = Adhesive::new(&params(0, s.mu)).unwrap().with_critical_slip_absolute(GAMMA_CRIT).unwrap();
        let coulomb = Coulomb::new(s.mu).unwrap().with_critical_slip_absolute(GAMMA_CRIT).unwrap();
        let start = s.mu * (s.p0 - s.dp).max(0.0);
        let tau = [s.tau_frac[0] * start, s.tau_frac[1] * start];
        let g = law
            .slide(None, &tau, &s.dgam, s.p0 - s.dp, s.p0, s.dtime, GAMMA_CRIT)
            .unwrap();
        let inc = Increment::<2> { tau, dgam: s.dgam, pressure: s.p0, dpressure: s.dp, dtime: s.dtime, ..Increment::default() };
        let Contact::Motion(c) = coulomb.update(&inc, &CoulombState::default()).unwrap().contact else {
            panic!("elastic stick answers LM = 0");
        };
        let scale = s.mu * s.p0.max(1.0);
        for a in 0..2 {
            prop_assert!((g.traction.tau[a] - c.tau[a]).abs() <= 1e-12 * scale);
            prop_assert!((g.traction.ddtddp[a] - c.ddtddp[a]).abs() <= 1e-12 * (1.0 + s.mu));
            prop_assert!((g.traction.dslip[a] - c.dslip[a]).abs() <= 1e-12 * GAMMA_CRIT * 10.0);
            for b in 0..2 {
                prop_assert!((g.traction.ddtddg[a][b] - c.ddtddg[a][b]).abs() <= 1e-9 * scale / GAMMA_CRIT);
            }
        }
    }
}

// ---- UINTER ---------------------------------------------------------------------------------

const K_N: f64 = 1e5;

fn uinter(p: &AdhesiveParameters, heat_fraction: f64) -> AdhesiveBuilder {
    adhesive(p)
        .normal_stiffness(K_N)
        .heat_fraction(heat_fraction)
        .slave_fraction(0.3)
}

fn uinter_props(p: &AdhesiveParameters, heat_fraction: f64) -> Vec<f64> {
    uinter(p, heat_fraction).build()
}

#[derive(Clone, Debug)]
struct InterfaceSample {
    ndir: i32,
    mask: u32,
    mu: f64,
    /// Status at the start: 0 stick, 3 bonded (apart), 4 open.
    start_status: f64,
    p_start: f64,
    h: f64,
    tau_frac: [f64; 2],
    dgam: [f64; 2],
    dtime: f64,
}

fn interface_sample() -> impl Strategy<Value = InterfaceSample> {
    (
        2..=3i32,
        0..16u32,
        0.05..0.8f64,
        prop_oneof![Just(0.0), Just(3.0), Just(4.0)],
        -15.0..150.0f64,
        -3e-4..2e-3f64,
        prop::array::uniform2(-0.7..0.7f64),
        prop::array::uniform2(-6.0..6.0f64),
        0.01..2.0f64,
    )
        .prop_map(
            |(ndir, mask, mu, start_status, p_start, h, tau_frac, dgam, dtime)| InterfaceSample {
                ndir,
                // Separation adhesion needs S_a: half the samples have it.
                mask,
                mu,
                start_status,
                p_start,
                h,
                tau_frac,
                dgam: [dgam[0] * GAMMA_CRIT, dgam[1] * GAMMA_CRIT],
                dtime,
            },
        )
}

fn uinter_at(s: &InterfaceSample, h: f64, dgam: [f64; 2]) -> UinterCall {
    let p = params(s.mask, s.mu);
    let mut c = UinterCall::new(s.ndir, &uinter_props(&p, 0.8));
    let n = s.ndir as usize - 1;
    let strength = p.coeff_static.max(p.coeff) * s.p_start.max(0.0) + p.sa;
    c.stress[0] = s.p_start;
    for a in 0..n {
        c.stress[1 + a] = s.tau_frac[a] * strength;
        c.drdisp[1 + a] = dgam[a];
    }
    c.rdisp[0] = h;
    c.statev[2] = s.start_status;
    c.dtime = s.dtime;
    c.set_guards();
    c.call();
    c
}

/// DDSDDR against central differences of STRESS over RDISP(1) and DRDISP(2..), and DDFDDR
/// (frictional heat, η = 0.8, f = 0.3) against differences of FLUX.
fn uinter_fd(s: &InterfaceSample) -> Result<Fd, String> {
    let ndir = s.ndir as usize;
    let base = uinter_at(s, s.h, s.dgam);
    if base.pnewdt != 1e36 || !base.guards_intact() {
        return Err(format!("call failed: {}", FricCall::last_error()));
    }
    let status = base.statev[2];
    let scale = base
        .ddsddr(0, 0)
        .abs()
        .max(base.ddsddr(1, 1).abs())
        .max(1.0);
    let fscale = (base.ddfddr(0, 0).abs() + base.ddfddr(1, 0).abs()) * GAMMA_CRIT
        + base.flux[0].abs()
        + base.flux[1].abs()
        + 1.0;
    for j in 0..ndir {
        let step = if j == 0 {
            1e-6 * s.h.abs().max(1e-5)
        } else {
            1e-7 * GAMMA_CRIT
        };
        let (mut hu, mut hd, mut gu, mut gd) = (s.h, s.h, s.dgam, s.dgam);
        if j == 0 {
            hu += step;
            hd -= step;
        } else {
            gu[j - 1] += step;
            gd[j - 1] -= step;
        }
        let (cu, cd) = (uinter_at(s, hu, gu), uinter_at(s, hd, gd));
        if cu.statev[2] != status || cd.statev[2] != status {
            return Ok(Fd::Kink);
        }
        for i in 0..ndir {
            let fd = (cu.stress[i] - cd.stress[i]) / (2.0 * step);
            if (fd - base.ddsddr(i, j)).abs() > 1e-5 * scale {
                return Err(format!(
                    "DDSDDR({},{}) = {} vs FD {fd} (status {status})",
                    i + 1,
                    j + 1,
                    base.ddsddr(i, j)
                ));
            }
        }
        for i in 0..2 {
            let fd = (cu.flux[i] - cd.flux[i]) / (2.0 * step);
            if (fd - base.ddfddr(i, j)).abs() * GAMMA_CRIT > 1e-5 * fscale {
                return Err(format!(
                    "DDFDDR({},{}) = {} vs FD {fd} (status {status})",
                    i + 1,
                    j + 1,
                    base.ddfddr(i, j)
                ));
            }
        }
    }
    Ok(Fd::Matched(status))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The tangents of `uinter_` in every branch: closed stick and slip (each option
    /// combination), bonded in tension, open, re-contact.
    #[test]
    fn uinter_tangents_match_finite_differences(s in interface_sample()) {
        as_property(uinter_fd(&s))?;
    }
}

/// The branches the property test must reach, each hit on purpose (so that none is covered
/// only by luck): re-contact from open, stick, slip for all 16 option combinations in 2-D and
/// 3-D, bonded in tension, open.
#[test]
fn uinter_tangents_in_every_named_branch() {
    let base = InterfaceSample {
        ndir: 3,
        mask: 0,
        mu: 0.4,
        start_status: 0.0,
        p_start: 50.0,
        h: 6e-3,
        tau_frac: [0.2, -0.1],
        dgam: [0.3 * GAMMA_CRIT, 0.1 * GAMMA_CRIT],
        dtime: 0.3,
    };
    let mut cases = vec![
        (base.clone(), 0.0),
        // Re-contact: open at the start, closed at the end.
        (
            InterfaceSample {
                start_status: 4.0,
                p_start: 0.0,
                tau_frac: [0.0, 0.0],
                ..base.clone()
            },
            0.0,
        ),
        // Bonded (S_a, N_a > 0), pulled to N = 3 < N_a = 20.
        (
            InterfaceSample {
                mask: 2,
                h: -3.0 / K_N,
                ..base.clone()
            },
            3.0,
        ),
        // Open: no separation adhesion.
        (
            InterfaceSample {
                h: -3.0 / K_N,
                ..base.clone()
            },
            4.0,
        ),
    ];
    for ndir in [2, 3] {
        for mask in 0..16 {
            cases.push((
                InterfaceSample {
                    ndir,
                    mask,
                    dgam: [4.0 * GAMMA_CRIT, -2.5 * GAMMA_CRIT],
                    ..base.clone()
                },
                1.0,
            ));
        }
    }
    for (s, want) in cases {
        assert_eq!(uinter_fd(&s), Ok(Fd::Matched(want)), "{s:?}");
    }
}

fn interface() -> AdhesiveBuilder {
    // μ_d = 0.3, μ_s = 0.5, S_a = 4, N_a = 10.
    let p = AdhesiveParameters {
        coeff: 0.3,
        coeff_static: 0.5,
        sa: 4.0,
        na: 10.0,
        ..AdhesiveParameters::default()
    };
    uinter(&p, 0.0)
}

fn interface_props() -> Vec<f64> {
    interface().build()
}

#[test]
fn uinter_pull_off_and_rebond() {
    // Closed at p = 50 with shear S₀ = 2 held, then pulled apart: the bond breaks when
    // N = N_a·sqrt(1 − (S₀/S_a)²) = 10·sqrt(0.75); re-contact bonds again.
    let s0 = 2.0;
    let mut c = UinterCall::new(2, &interface_props());
    c.rdisp[0] = 50.0 / K_N;
    // k_s = (0.5·50 + 4)/γ_crit; Δγ gives S₀.
    c.drdisp[1] = s0 / ((0.5 * 50.0 + 4.0) / GAMMA_CRIT);
    c.call();
    assert_eq!(c.lopenclose, 1);
    assert!((c.stress[0] - 50.0).abs() < 1e-9 && (c.stress[1] - s0).abs() < 1e-12);
    c.drdisp[1] = 0.0;
    // Release the pressure to 0: the elastic slip is kept, S = S_a·γ^el/γ_crit.
    c.rdisp[0] = 0.0;
    c.call();
    let s_apart = c.stress[1];
    assert!((s_apart - s0 * 4.0 / 29.0).abs() < 1e-12);
    let n_break = 10.0 * (1.0 - (s_apart / 4.0).powi(2)).sqrt();
    let mut last_n = 0.0;
    for k in 1..=2000 {
        let n = 9.0 * f64::from(k) / 1000.0;
        c.rdisp[0] = -n / K_N;
        c.call();
        if c.lopenclose == 0 {
            assert!(
                last_n < n_break && n_break <= n * (1.0 + 1e-12),
                "broke at {n}, expected {n_break}"
            );
            assert_eq!((c.stress[0], c.stress[1], c.statev[2]), (0.0, 0.0, 4.0));
            break;
        }
        assert_eq!(c.statev[2], 3.0);
        assert!((c.stress[0] + n).abs() < 1e-9 * n.max(1.0));
        last_n = n;
    }
    assert_eq!(c.lopenclose, 0);
    // Apart again but nearer: still free (the bond re-forms only on contact).
    c.rdisp[0] = -1e-6;
    c.call();
    assert_eq!((c.lopenclose, c.stress[0]), (0, 0.0));
    // Re-contact, then pull: the full strength N_a again (no shear left).
    c.rdisp[0] = 1e-5;
    c.call();
    assert_eq!((c.lopenclose, c.statev[2]), (1, 0.0));
    c.rdisp[0] = -9.99 / K_N;
    c.call();
    assert_eq!((c.lopenclose, c.statev[2]), (1, 3.0));
    assert!((c.stress[0] + 9.99).abs() < 1e-9);
}

#[test]
fn uinter_bad_input_cuts_back() {
    // A valid interface (μ_d = 0.3, γ_crit, K_n) but for the one entry each needle names.
    let good = AdhesiveBuilder::new()
        .coeff(0.3)
        .gamma_crit(1e-3)
        .normal_stiffness(1e5);
    for (props, needle) in [
        (good.clone().sa(-1.0).build_first(10), "PROPS(4): Sa"),
        (good.clone().na(-2.0).build_first(10), "PROPS(5): Na"),
        (
            good.clone().coeff(0.5).coeff_static(0.3).build_first(10),
            "PROPS(3): coeffStatic",
        ),
        (good.clone().coeff(f64::NAN).build_first(10), "PROPS(2)"),
        (good.clone().build_first(8), "PROPS(10) = 0"),
        (CoulombBuilder::new().mu(0.3).build_first(2), "PROPS(1) = 2"),
    ] {
        let mut c = UinterCall::new(3, &props);
        c.stress = [5.0, 1.0, 2.0, c.stress[3]];
        c.rdisp[0] = 1e-4;
        c.call();
        assert_eq!(c.pnewdt, 0.25, "{props:?}");
        assert_eq!(&c.stress[..3], &[5.0, 1.0, 2.0]);
        assert_eq!((c.lopenclose, c.lstate), (-1, -1));
        assert!(c.guards_intact());
        let msg = FricCall::last_error();
        assert!(msg.contains("UINTER") && msg.contains(needle), "{msg}");
    }
    // NaN overclosure.
    let mut c = UinterCall::new(2, &interface_props());
    c.rdisp[0] = f64::NAN;
    c.call();
    assert_eq!(c.pnewdt, 0.25);
    assert!(FricCall::last_error().contains("RDISP(1) is NaN"));
    // Rate-dependent law with DTIME = 0.
    let props = interface().vhalf(0.1).build();
    let mut c = UinterCall::new(2, &props);
    c.rdisp[0] = 1e-4;
    c.dtime = 0.0;
    c.call();
    assert_eq!(c.pnewdt, 0.25);
    assert!(FricCall::last_error().contains("DTIME = 0"));
    // The same through fric_.
    let mut f = FricCall::new(1, &props[..8]);
    f.press = 10.0;
    f.dgam[0] = 1e-2;
    f.dtime = 0.0;
    f.call();
    assert_eq!(f.pnewdt, 0.25);
    assert!(FricCall::last_error().contains("DTIME = 0"));
    // NDIR and NSTATV.
    for (ndir, nstatv, needle) in [
        (1, 3, "NDIR = 1"),
        (-1, 3, "NDIR = -1"),
        (2, 2, "NSTATV = 2"),
    ] {
        let mut c = UinterCall::new(ndir, &interface_props());
        c.nstatv = nstatv;
        c.set_guards();
        c.rdisp[0] = 1e-4;
        c.call();
        assert_eq!(c.pnewdt, 0.25);
        assert!(c.guards_intact());
        let msg = FricCall::last_error();
        assert!(msg.contains(needle), "{msg}");
    }
}

#[test]
fn fric_bad_input_cuts_back() {
    for (props, needle) in [
        (
            AdhesiveBuilder::new().coeff(0.3).sa(-1.0).build_first(4),
            "PROPS(4): Sa",
        ),
        (
            AdhesiveBuilder::new()
                .coeff(0.5)
                .coeff_static(0.3)
                .build_first(3),
            "PROPS(3): coeffStatic = 0.3 is below coeff = 0.5",
        ),
        (
            AdhesiveBuilder::new()
                .coeff(0.3)
                .kmu(f64::NAN)
                .build_first(6),
            "PROPS(6): kmu",
        ),
    ] {
        let mut c = FricCall::new(2, &props);
        c.press = 10.0;
        c.tau[0] = 1.0;
        c.dgam[0] = 1e-3;
        c.call();
        assert_eq!(c.pnewdt, 0.25, "{props:?}");
        assert_eq!(c.tau[0], 1.0);
        let msg = FricCall::last_error();
        assert!(msg.contains("FRIC") && msg.contains(needle), "{msg}");
    }
}

/// Reentrancy: the same 2000 interface points through `uinter_` on 8 threads give bit for bit
/// the serial results (no shared mutable state).
#[test]
fn uinter_results_do_not_depend_on_the_number_of_threads() {
    let points: Vec<InterfaceSample> = (0..2000u32)
        .map(|k| {
            let x = f64::from(k);
            InterfaceSample {
                ndir: 2 + (k % 2) as i32,
                mask: k % 16,
                mu: 0.1 + 0.5 * (0.37 * x).sin().abs(),
                start_status: [0.0, 3.0, 4.0][(k % 3) as usize],
                p_start: 100.0 * (0.11 * x).cos(),
                h: 2e-3 * (0.23 * x).sin(),
                tau_frac: [0.5 * (0.7 * x).sin(), 0.5 * (0.3 * x).cos()],
                dgam: [5e-3 * (0.13 * x).sin(), 5e-3 * (0.17 * x).cos()],
                dtime: 0.1 + (0.05 * x).sin().abs(),
            }
        })
        .collect();
    let run = |s: &InterfaceSample| {
        let c = uinter_at(s, s.h, s.dgam);
        let mut bits: Vec<u64> = c
            .stress
            .iter()
            .chain(&c.ddsddr)
            .chain(&c.flux)
            .map(|v| v.to_bits())
            .collect();
        bits.extend(c.statev.iter().chain(&c.energies).map(|v| v.to_bits()));
        bits.push(c.lopenclose as u64);
        bits
    };
    let serial: Vec<Vec<u64>> = points.iter().map(run).collect();
    let parallel = map_on_threads(&points, 250, run);
    assert_eq!(serial, parallel);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    /// Through `fric_`, over random points of every option combination: finite outputs, no
    /// cut-back, SED ≥ 0, SFD = |τ|·|Δs| ≥ 0, and after every slip update the seed's law at the
    /// slip rate the state reports (STATEV(2)): |τ| = ((μ_s v_½ + μ_d v)/(v_½ + v) + k_μ v) p + S_a.
    #[test]
    fn fric_invariants_and_residual_through_the_abi(s in sample()) {
        let c = fric_at(&s, s.dgam, 0.0);
        prop_assert_eq!(c.pnewdt, 1e36);
        prop_assert!(c.guards_intact());
        let n = s.nfdir as usize;
        let all = c.tau[..n].iter().chain(&c.ddtddp[..n]).chain(&c.dslip[..n]).chain(&c.ddtddg[..n * n]);
        prop_assert!(all.copied().chain([c.sed, c.sfd]).all(f64::is_finite));
        prop_assert!(c.sed >= 0.0 && c.sfd >= 0.0);
        let tau = c.tau[..n].iter().map(|t| t * t).sum::<f64>().sqrt();
        let slip = c.dslip[..n].iter().map(|t| t * t).sum::<f64>().sqrt();
        prop_assert!((c.sfd - tau * slip).abs() <= 1e-12 * (tau * slip).max(1e-300));
        if c.statev[2] == 1.0 && s.p0 > 0.0 {
            let p = params(s.mask, s.mu);
            let mu_s = if p.coeff_static > 0.0 { p.coeff_static } else { p.coeff };
            let v = c.statev[1];
            let transition = if p.vhalf + v > 0.0 { (mu_s * p.vhalf + p.coeff * v) / (p.vhalf + v) } else { mu_s };
            let g = (transition + p.kmu * v) * s.p0 + p.sa;
            // Relative to the trial stress |τ| + k_s|Δs| (the round-off scale of the update).
            let k_s = (mu_s * s.p0 + p.sa) / GAMMA_CRIT;
            prop_assert!((tau - g).abs() <= 1e-12 * (tau + k_s * slip), "|τ| = {tau}, g = {g}");
        }
    }
}

/// A subnormal static strength (μ_d = 10⁻³²⁰, p = 50, so τ̄_s ≈ 5·10⁻³¹⁹ and γ_crit/τ̄_s
/// overflows): from rest (τ̄ = 0) the point sticks with τ = μ_d·p·Δγ/γ_crit, instead of forming
/// the start's elastic slip as 0·∞ = NaN and refusing the increment.
#[test]
fn a_subnormal_strength_sticks_from_rest() {
    let mu = 1e-320;
    // A rate-dependent μ (kmu, vhalf), so that the adhesive law itself answers (not its
    // Coulomb special case).
    let props = AdhesiveBuilder::new()
        .coeff(mu)
        .kmu(0.4)
        .vhalf(0.02)
        .gamma_crit(GAMMA_CRIT)
        .build_first(8);
    for nfdir in [1, 2] {
        let mut c = FricCall::new(nfdir, &props);
        c.press = 50.0;
        c.dpress = 0.0;
        c.dgam = [GAMMA_CRIT / 4.0, 0.0, 0.0];
        c.call();
        assert_eq!(c.pnewdt, 1e36, "refused: {}", FricCall::last_error());
        let expected = mu * 50.0 / GAMMA_CRIT * (GAMMA_CRIT / 4.0);
        assert!(
            (c.tau[0] - expected).abs() <= 1e-3 * expected,
            "NFDIR {nfdir}: τ = {:e}, k_s·Δγ = {expected:e}",
            c.tau[0]
        );
    }
}
