//! The extended Coulomb model through `fric_` (PROPS(3), PROPS(8..20)): tangents against central
//! differences in every branch and law, the stress on the rate-dependent yield surface, the
//! closed forms of scenes F3 (ellipse), F4 (velocity steps), F5 (pressure-dependent μ with
//! τ_max), damping, HHT, cheap paths against the general one, and bad input.

#![allow(clippy::needless_range_loop)] // index loops mirror the a, b indices of the equations

#[path = "common/central.rs"]
mod central;
#[path = "common/laws.rs"]
mod laws;
#[path = "common/loading.rs"]
mod loading;
use central::{Shift, along_dgam, along_press, along_temp, central_tau, slide_steadily};
use laws::{every_mu_law, set_entry};
use loading::Loading;

use interfacial::laws::contact::Conditions;
use interfacial::laws::contact::{Contact, EntryFlag, Increment};
use interfacial::laws::coulomb::Coulomb;
use interfacial::laws::coulomb_extended::{
    Damping, ExtendedCoulomb, ExtendedState, Hht, MAX_LOCAL_ITERATIONS,
};
use interfacial::laws::friction_coefficient::CoefficientLaw;
use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;
use std::cell::Cell;

/// A law-1 parameter set, written the way a user writes PROPS.
#[derive(Clone, Debug)]
struct Params {
    mu1: f64,
    /// 0: isotropic.
    mu2: f64,
    tau_max: f64,
    gamma_crit: f64,
    exact: bool,
    /// (μ_k, d_c), or None for constant μ.
    decay: Option<(f64, f64)>,
    p_ref: f64,
    /// (b_θ, θ_ref), or None.
    temperature: Option<(f64, f64)>,
    /// α, or None for static.
    hht_alpha: Option<f64>,
    c0: f64,
    frozen: bool,
}

impl Params {
    fn props(&self) -> Vec<f64> {
        let mut p = coulomb(self.mu1, self.gamma_crit)
            .mu2(self.mu2)
            .tau_max(self.tau_max)
            .stick(if self.exact { 1.0 } else { 0.0 })
            .p_ref(self.p_ref)
            .damping(self.c0)
            .frozen(if self.frozen { 1.0 } else { 0.0 });
        if let Some((mu_k, dc)) = self.decay {
            p = p.mu_law(1.0).mu_k(mu_k).decay(dc);
        }
        if let Some((b, t)) = self.temperature {
            p = p.b_theta(b).theta_ref(t);
        }
        if let Some(a) = self.hht_alpha {
            // β and γ from α (Abaqus's relations), γ given to switch HHT on even for α = 0.
            p = p.hht_alpha(a).hht_gamma(0.5 - a);
        }
        p.build()
    }

    fn mbar(&self, nfdir: usize) -> f64 {
        if nfdir == 1 || self.mu2 == 0.0 {
            self.mu1
        } else {
            (0.5 * (self.mu1 * self.mu1 + self.mu2 * self.mu2)).sqrt()
        }
    }

    fn scaling(&self, nfdir: usize) -> [f64; 2] {
        if nfdir == 1 || self.mu2 == 0.0 {
            [1.0, 1.0]
        } else {
            let m = self.mbar(2);
            [self.mu1 / m, self.mu2 / m]
        }
    }

    /// Independent τ̄_crit(γ̇, p, θ̄) = min(μ̄ φ π Θ p, τ_max).
    fn critical(&self, nfdir: usize, rate: f64, p: f64, theta: f64) -> f64 {
        if p < 0.0 {
            return 0.0;
        }
        let mut mu = self.mbar(nfdir);
        if let Some((mu_k, dc)) = self.decay {
            let r = mu_k / self.mu1;
            mu *= r + (1.0 - r) * (-dc * rate).exp();
        }
        if self.p_ref > 0.0 {
            mu /= 1.0 + p / self.p_ref;
        }
        if let Some((b, t)) = self.temperature {
            mu *= (-b * (theta - t)).exp();
        }
        if self.tau_max > 0.0 {
            (mu * p).min(self.tau_max)
        } else {
            mu * p
        }
    }

    fn rate_dt(&self, dtime: f64) -> f64 {
        match self.hht_alpha {
            Some(a) => 0.25 * (1.0 - a) * (1.0 - a) * dtime / (0.5 - a),
            None => dtime,
        }
    }
}

/// One increment of a point: the law plus the start of the increment.
#[derive(Clone, Debug)]
struct Sample {
    nfdir: usize,
    law: Params,
    load: Loading,
    dtime: f64,
    start_rate: f64,
    theta: f64,
    viscous: [f64; 2],
}

fn params() -> impl Strategy<Value = Params> {
    (
        (
            0.1..0.8f64,
            prop_oneof![Just(0.0), 0.3..2.5f64],
            prop_oneof![Just(0.0), 0.2..1.5f64],
            1e-4..1e-2f64,
            prop::bool::ANY,
        ),
        (
            prop_oneof![Just(None), (0.2..1.5f64, 0.1..20.0f64).prop_map(Some)],
            prop_oneof![Just(0.0), 10.0..1000.0f64],
            prop_oneof![Just(None), (-0.02..0.02f64, 0.0..100.0f64).prop_map(Some)],
            prop_oneof![Just(None), (-0.3..0.0f64).prop_map(Some)],
            prop_oneof![Just(0.0), 0.01..10.0f64],
            prop::bool::ANY,
        ),
    )
        .prop_map(
            |(
                (mu1, ratio, cap, gamma_crit, exact),
                (decay, p_ref, temperature, hht, c0, frozen),
            )| {
                let decay = decay.map(|(r, d)| (r * mu1, d));
                Params {
                    mu1,
                    mu2: ratio * mu1,
                    // τ_max as a fraction of μ₁·100 (the order of μp in the samples).
                    tau_max: cap * mu1 * 100.0,
                    gamma_crit,
                    exact,
                    decay,
                    p_ref,
                    temperature,
                    hht_alpha: hht,
                    c0,
                    frozen: frozen && decay.is_some(),
                }
            },
        )
}

fn sample() -> impl Strategy<Value = Sample> {
    (
        1..=2usize,
        params(),
        (1.0..200.0f64, -0.5..1.0f64),
        prop::array::uniform2(-0.9..0.9f64),
        prop::array::uniform2(-5.0..5.0f64),
        (1e-3..1.0f64, 0.0..5.0f64, 0.0..150.0f64),
        prop::array::uniform2(-1.0..1.0f64),
    )
        .prop_map(
            |(nfdir, law, (p0, dpf), tau_frac, dgam_frac, (dtime, start_rate, theta), viscous)| {
                Sample {
                    nfdir,
                    law,
                    load: Loading {
                        p0,
                        dp: dpf * p0,
                        tau_frac,
                        dgam_frac,
                    },
                    dtime,
                    start_rate,
                    theta,
                    viscous,
                }
            },
        )
}

const NSTATV: usize = 5;

/// Calls `fric_` for the sample with perturbations of DGAM, the end pressure (start held fixed)
/// and the two surface temperatures.
fn call(s: &Sample, dgam_shift: [f64; 2], dp_shift: f64, temp_shift: [f64; 2]) -> FricCall {
    let mut c = prepare(s, dgam_shift, dp_shift, temp_shift);
    c.call();
    c
}

/// The arguments of [`call`], not yet passed to `fric_`.
fn prepare(s: &Sample, dgam_shift: [f64; 2], dp_shift: f64, temp_shift: [f64; 2]) -> FricCall {
    let n = s.nfdir;
    let mut c = FricCall::new(n as i32, &s.law.props());
    c.statev = vec![0.0; NSTATV + 2];
    c.nstatv = NSTATV as i32;
    c.set_guards();
    c.statev[1] = s.start_rate;
    c.statev[2] = 1.0;
    let a = s.law.scaling(n);
    let tc0 = s.law.critical(n, 0.0, s.load.p0, s.theta);
    for i in 0..n {
        // A start stress inside the (scaled) cone, plus the viscous part when damped.
        let visc = if s.law.c0 > 0.0 { s.viscous[i] } else { 0.0 };
        c.tau[i] = a[i] * s.load.tau_frac[i] * tc0 / (n as f64).sqrt() + visc;
        c.statev[3 + i] = visc;
        c.dgam[i] = s.load.dgam_frac[i] * s.law.gamma_crit + dgam_shift[i];
    }
    s.load.set_pressure(&mut c, dp_shift);
    c.dtime = s.dtime;
    c.temp = [s.theta + temp_shift[0], s.theta + temp_shift[1]];
    c
}

thread_local! {
    static SKIPPED: Cell<u32> = const { Cell::new(0) };
    static CHECKED: Cell<u32> = const { Cell::new(0) };
}

/// DDTDDG, DDTDDP and DDTDDT(·,1..2) against central differences of TAU, in every branch
/// (stick, slip, cap, exact-stick slip) and every law (constant, decay, frozen, pressure,
/// temperature, HHT, damping, anisotropy), NFDIR 1 and 2; and the invariants of each result.
/// Samples whose stencil crosses a kink (step h and 2h disagree) are skipped and counted: at
/// most a fifth may be.
#[test]
fn tangents_match_central_differences() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig {
        cases: 3000,
        failure_persistence: None,
        ..ProptestConfig::default()
    });
    if let Err(e) = runner.run(&sample(), check_tangents) {
        panic!("{e}");
    }
    let (skipped, checked) = (SKIPPED.with(Cell::get), CHECKED.with(Cell::get));
    println!("tangents: {checked} samples with LM = 0, {skipped} with a kink in some stencil");
    assert!(
        checked > 1000 && skipped * 5 < checked,
        "{skipped} of {checked} skipped"
    );
}

fn check_tangents(s: Sample) -> Result<(), TestCaseError> {
    let n = s.nfdir;
    let base = call(&s, [0.0; 2], 0.0, [0.0; 2]);
    prop_assert!(base.guards_intact());
    prop_assert!(base.pnewdt == 1e36, "{}: {s:?}", FricCall::last_error());
    if base.lm != 0 {
        return Ok(()); // exact stick (LM = 1): no tangent to check
    }
    let at = |(g, dp, dt): Shift| call(&s, g, dp, dt);
    let law = &s.law;
    let p = s.load.p_end();
    let mbar = law.mbar(n);
    let rate_dt = law.rate_dt(s.dtime);
    let k_scale = mbar * p.max(1.0) / law.gamma_crit + law.c0 / rate_dt;
    let gc = law.gamma_crit;
    let mut skipped = false;
    // DDTDDG(a,b).
    for b in 0..n {
        for a in 0..n {
            let h = 1e-6 * gc;
            let fd = central_tau(a, h, k_scale, along_dgam(b), at);
            match fd {
                Some(fd) => {
                    let an = base.ddtddg(a, b);
                    prop_assert!(
                        (fd - an).abs() <= 1e-6 * k_scale + 1e-6 * an.abs(),
                        "DDTDDG({a},{b}): analytic {an}, central difference {fd}, {s:?}"
                    );
                }
                None => skipped = true,
            }
        }
    }
    // DDTDDP(a): the end pressure moves, the start (PRESS − DPRESS) stays.
    let hp = 1e-6 * s.load.p0;
    for a in 0..n {
        match central_tau(a, hp, mbar.max(1.0), along_press, at) {
            Some(fd) => {
                let an = base.ddtddp[a];
                prop_assert!(
                    (fd - an).abs() <= 1e-6 * mbar.max(1.0) + 1e-6 * an.abs(),
                    "DDTDDP({a}): analytic {an}, central difference {fd}, {s:?}"
                );
            }
            None => skipped = true,
        }
    }
    // DDTDDT(a,k): TEMP(k) alone moves.
    let ht = 1e-4;
    let t_scale = mbar * p.abs().max(1.0) * 0.05;
    for k in 0..2 {
        for a in 0..n {
            let fd = central_tau(a, ht, t_scale, along_temp(k), at);
            match fd {
                Some(fd) => {
                    let an = base.ddtddt[a + k * n];
                    prop_assert!(
                        (fd - an).abs() <= 1e-6 * t_scale + 1e-6 * an.abs(),
                        "DDTDDT({a},{k}): analytic {an}, central difference {fd}, {s:?}"
                    );
                }
                None => skipped = true,
            }
        }
    }
    SKIPPED.with(|c| c.set(c.get() + u32::from(skipped)));
    CHECKED.with(|c| c.set(c.get() + 1));

    // Invariants: SFD ≥ 0; without damping the scaled stress is inside the cone of the
    // end-of-increment rate, and on it when slipping (status 1).
    prop_assert!(base.sfd >= 0.0);
    if law.c0 == 0.0 {
        let a = law.scaling(n);
        let tbar: f64 = (0..n)
            .map(|i| (base.tau[i] / a[i]).powi(2))
            .sum::<f64>()
            .sqrt();
        let rate = if law.frozen {
            s.start_rate
        } else {
            base.statev[1]
        };
        let crit_end = law.critical(n, rate, p, s.theta);
        // The stick cone: at the start rate when μ is frozen, and with a rate law in elastic
        // stick (the rate-following stiffness, docs/props.md: the sample starts from a slip at
        // `start_rate`); rate-free otherwise.
        let stick_rate = if law.frozen || (law.decay.is_some() && !law.exact) {
            s.start_rate
        } else {
            0.0
        };
        let crit_static = law.critical(n, stick_rate, p, s.theta);
        let tol = 1e-12 * crit_static.max(crit_end).max(1e-300) + 1e-300;
        if base.statev[2] == 1.0 {
            prop_assert!(
                (tbar - crit_end).abs() <= tol * 10.0,
                "slip off the yield surface: τ̄_eq = {tbar}, τ̄_crit(γ̇) = {crit_end}, {s:?}"
            );
        } else {
            prop_assert!(
                tbar <= crit_static + tol,
                "stick outside the cone: {tbar} > {crit_static}"
            );
        }
    }
    Ok(())
}

fn traction<const N: usize>(c: Contact<N>) -> interfacial::laws::contact::Traction<N> {
    match c {
        Contact::Motion(t) => t,
        Contact::ExactStick => panic!("expected LM = 0"),
    }
}

/// Law 1 with friction coefficient `mu` and elastic stick of slip tolerance `gamma_crit`, the
/// base the extended entries are added to.
fn coulomb(mu: f64, gamma_crit: f64) -> CoulombBuilder {
    CoulombBuilder::new().mu(mu).gamma_crit(gamma_crit)
}

/// A point of a law with damping: NFDIR 2, NSTATV = 5 (`STATEV(4..5)` the viscous stress) with
/// the state `statev` and two guarded entries past it, PRESS = 100, DTIME = 0.1.
fn damped_point(props: &[f64], statev: [f64; 5]) -> FricCall {
    let mut c = FricCall::new(2, props);
    c.statev = [&statev[..], &[0.0, 0.0]].concat();
    c.nstatv = 5;
    c.set_guards();
    c.press = 100.0;
    c.dtime = 0.1;
    c
}

/// Scene F3: steady slip along d at angle θ with μ₁ ≠ μ₂: the stress sits on the friction
/// ellipse (τ₁/μ₁)² + (τ₂/μ₂)² = p², with τ_i ∝ μ_i²·d_i.
#[test]
fn f3_ellipse() {
    let (mu1, mu2, p, gc) = (0.5, 0.2, 100.0, 1e-3);
    let ellipse = coulomb(mu1, gc).mu2(mu2).build_first(5);
    for k in 0..12 {
        let angle = f64::from(k) * std::f64::consts::PI / 6.0 + 0.1;
        let d = [angle.cos(), angle.sin()];
        let mut c = FricCall::new(2, &ellipse);
        c.press = p;
        for _ in 0..60 {
            c.dgam = [d[0] * 0.3 * gc, d[1] * 0.3 * gc, 0.0];
            c.call();
            assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
            c.dpress = 0.0;
        }
        let t = [c.tau[0], c.tau[1]];
        let on_ellipse = (t[0] / mu1).powi(2) + (t[1] / mu2).powi(2);
        assert!((on_ellipse.sqrt() - p).abs() < 1e-12 * p, "{angle}: {t:?}");
        // τ ∝ (μ₁² d₁, μ₂² d₂): the cross product vanishes.
        let w = [mu1 * mu1 * d[0], mu2 * mu2 * d[1]];
        let cross = t[0] * w[1] - t[1] * w[0];
        assert!(
            cross.abs() < 1e-10 * p * mu1 * mu1,
            "{angle}: {t:?} vs {w:?}"
        );
        assert!(t[0] * w[0] + t[1] * w[1] > 0.0);
    }
    // Stick stiffnesses k_i = (μ_i/μ̄)² k̄_s.
    let mut c = FricCall::new(2, &ellipse);
    c.press = p;
    c.dpress = p;
    c.dgam = [1e-6, 1e-6, 0.0];
    c.call();
    let mbar2 = 0.5 * (mu1 * mu1 + mu2 * mu2);
    let kbar = mbar2.sqrt() * p / gc;
    assert!((c.ddtddg(0, 0) - mu1 * mu1 / mbar2 * kbar).abs() < 1e-10 * kbar);
    assert!((c.ddtddg(1, 1) - mu2 * mu2 / mbar2 * kbar).abs() < 1e-10 * kbar);
    assert_eq!(c.ddtddg(0, 1), 0.0);
}

/// Scene F4: slip at piecewise-constant rates; once steady τ = μ(v)·p with
/// μ(v) = μ_k + (μ_s − μ_k)·exp(−d_c·v), for NFDIR 1 and 2, elastic and exact stick, and with
/// μ frozen at the start of the increment (which lags, then reaches the same steady value).
#[test]
fn f4_velocity_steps() {
    let (mu_s, mu_k, dc, p, gc, dt) = (0.6, 0.3, 4.0, 50.0, 1e-3, 0.01);
    for nfdir in [1usize, 2] {
        for exact in [false, true] {
            for frozen in [false, true] {
                let props = coulomb(mu_s, gc)
                    .stick(if exact { 1.0 } else { 0.0 })
                    .mu_law(1.0)
                    .mu_k(mu_k)
                    .decay(dc)
                    .frozen(if frozen { 1.0 } else { 0.0 })
                    .build();
                let mut c = FricCall::new(nfdir as i32, &props);
                c.press = p;
                c.dtime = dt;
                let dir = if nfdir == 1 { [1.0, 0.0] } else { [0.6, 0.8] };
                for v in [0.05, 0.5, 0.2, 1.5] {
                    let tau_eq = slide_steadily(&mut c, nfdir, dir, v, 40);
                    let expected = (mu_k + (mu_s - mu_k) * (-dc * v).exp()) * p;
                    assert!(
                        (tau_eq - expected).abs() < 1e-12 * expected,
                        "NFDIR {nfdir} exact {exact} frozen {frozen} v {v}: {tau_eq} vs {expected}"
                    );
                    assert!((c.statev[1] - v).abs() < 1e-12 * v);
                }
            }
        }
    }
}

/// Scene F5 with a pressure-dependent μ = μ₀/(1 + p/p_ref) and a shear limit: during steady
/// slip τ = min(μ(p)·p, τ_max), DDTDDP = d(μp)/dp = μ₀/(1 + p/p_ref)² below the cap, 0 on it.
#[test]
fn f5_pressure_dependent_mu_with_cap() {
    let (mu0, p_ref, tau_max, gc) = (0.5, 100.0, 30.0, 1e-3);
    let props = coulomb(mu0, gc)
        .tau_max(tau_max)
        .p_ref(p_ref)
        .build_first(11);
    let mut c = FricCall::new(1, &props);
    let mut p_before = 0.0;
    for k in 1..=200 {
        let p = 2.0 * f64::from(k);
        c.press = p;
        c.dpress = p - p_before;
        p_before = p;
        c.dgam[0] = 0.5 * gc;
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        let mu_p = mu0 * p / (1.0 + p / p_ref);
        if k > 5 {
            let expected = mu_p.min(tau_max);
            assert!((c.tau[0] - expected).abs() < 1e-12 * expected, "p {p}");
            let slope = if mu_p < tau_max {
                mu0 / (1.0 + p / p_ref).powi(2)
            } else {
                0.0
            };
            assert!(
                (c.ddtddp[0] - slope).abs() < 1e-14,
                "p {p}: {}",
                c.ddtddp[0]
            );
        }
    }
}

/// Viscous tangential damping (seed 003): τ = τ_friction + c₀·Δγ/Δt statically and
/// c₀·γ·Δγ/(β·Δt) with HHT; the tangent gains c₀/Δt (resp. c₀·γ/(β·Δt)); the viscous stress is
/// kept in STATEV(4..) and removed from the next increment's TAU, so steady sliding stays at
/// μp + c₀·v.
#[test]
fn damping_closed_forms() {
    let (mu, p, gc, c0, dt, v) = (0.3, 100.0, 1e-3, 2.0, 0.05, 0.4);
    for hht in [None, Some(-0.1)] {
        let mut props = coulomb(mu, gc).damping(c0);
        let rate_dt = if let Some(a) = hht {
            props = props.hht_alpha(a);
            0.25 * (1.0 - a) * (1.0 - a) * dt / (0.5 - a)
        } else {
            dt
        };
        let props = props.build_first(17);
        let mut c = FricCall::new(2, &props);
        c.statev = vec![0.0; 5 + 2];
        c.nstatv = 5;
        c.set_guards();
        c.press = p;
        c.dtime = dt;
        // A slow stick step: τ = k_s Δγ + c₀ Δγ/Δt.
        c.dpress = p;
        c.dgam = [1e-5, 0.0, 0.0];
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        let ks = mu * p / gc;
        let cv = c0 / rate_dt;
        assert!((c.tau[0] - (ks + cv) * 1e-5).abs() < 1e-12 * ks * 1e-5);
        assert!((c.ddtddg(0, 0) - (ks + cv)).abs() < 1e-9 * ks);
        assert!((c.statev[3] - cv * 1e-5).abs() < 1e-15);
        assert!(c.guards_intact());
        c.dpress = 0.0;
        for _ in 0..50 {
            c.dgam = [0.6 * v * dt, 0.8 * v * dt, 0.0];
            c.call();
        }
        let rate = v * dt / rate_dt;
        let tau_eq = (c.tau[0].powi(2) + c.tau[1].powi(2)).sqrt();
        assert!(
            (tau_eq - (mu * p + c0 * rate)).abs() < 1e-12 * tau_eq,
            "{tau_eq}"
        );
        // Dissipation per increment: (μp + c₀ γ̇)·|Δγ| in steady sliding (all motion is slip).
        assert!((c.sfd - (mu * p + c0 * rate) * v * dt).abs() < 1e-10 * c.sfd);
        // Slip: the tangent along the slip direction is the damping term alone.
        let n = [0.6, 0.8];
        let along: f64 = (0..2)
            .flat_map(|a| (0..2).map(move |b| (a, b)))
            .map(|(a, b)| n[a] * c.ddtddg(a, b) * n[b])
            .sum();
        assert!((along - cv).abs() < 1e-9 * cv, "{along} vs {cv}");
    }
}

/// With damping, the viscous stress kept in STATEV(4..5) is rotated by DROT before it is taken
/// out of the incoming TAU: a TAU that is exactly the rotated viscous stress leaves no friction
/// stress, so with DGAM = 0 the answer is zero (identity DROT would leave a residual stress).
#[test]
fn damping_state_is_rotated_by_drot() {
    let props = coulomb(0.3, 1e-3).damping(2.0).build_first(17);
    let setup = |drot: [f64; 4]| {
        let mut c = damped_point(&props, [0.0, 0.0, 1.0, 1.5, -0.5]);
        // DROT = 90° rotation (column-major): (1.5, −0.5) → (0.5, 1.5).
        c.drot = drot;
        c.tau = [0.5, 1.5, c.tau[2], c.tau[3]];
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        c
    };
    let rotated = setup([0.0, 1.0, -1.0, 0.0]);
    assert!(
        rotated.tau[0].abs() < 1e-15 && rotated.tau[1].abs() < 1e-15,
        "{:?}",
        rotated.tau
    );
    assert_eq!(&rotated.statev[3..5], &[0.0, 0.0]);
    let identity = setup([1.0, 0.0, 0.0, 1.0]);
    // Friction start stress (0.5, 1.5) − (1.5, −0.5) = (−1, 2), inside the cone: kept.
    assert!((identity.tau[0] + 1.0).abs() < 1e-12 && (identity.tau[1] - 2.0).abs() < 1e-12);
}

/// The damping coefficient as a function of overclosure (seed 003): c₀ at zero overclosure and
/// over the fraction f of the clearance interval, linear to 0 at clearance g₀.
#[test]
fn damping_coefficient_of_overclosure() {
    let d = Damping::new(4.0, 0.1, 0.25).unwrap();
    assert_eq!(d.coefficient(0.0), 4.0);
    assert_eq!(d.coefficient(0.5), 4.0);
    assert_eq!(d.coefficient(-0.025), 4.0);
    assert!((d.coefficient(-0.0625) - 2.0).abs() < 1e-15);
    assert_eq!(d.coefficient(-0.1), 0.0);
    assert_eq!(d.coefficient(-1.0), 0.0);
}

/// HHT: with μ depending on the slip rate, the rate is Δγ/(β·Δt/γ).
#[test]
fn hht_scales_the_rate_increment() {
    let (alpha, dt) = (-0.2, 0.01);
    let hht = Hht::new(alpha, 0.0, 0.0).unwrap();
    let beta = 0.25 * (1.2f64).powi(2);
    let gamma = 0.7;
    assert!((hht.rate_increment(dt) - beta * dt / gamma).abs() < 1e-18);
    let props = coulomb(0.5, 1e-3)
        .mu_law(1.0)
        .mu_k(0.2)
        .decay(3.0)
        .hht_alpha(alpha)
        .hht_beta(beta)
        .hht_gamma(gamma)
        .build_first(16);
    let mut c = FricCall::new(1, &props);
    c.press = 10.0;
    c.dtime = dt;
    for _ in 0..30 {
        c.dgam[0] = 0.002;
        c.call();
        c.dpress = 0.0;
    }
    let rate = 0.002 * gamma / (beta * dt);
    let mu = 0.2 + 0.3 * (-3.0 * rate).exp();
    assert!(
        (c.tau[0] - mu * 10.0).abs() < 1e-12,
        "{} vs {}",
        c.tau[0],
        mu * 10.0
    );
    assert!((c.statev[1] - rate).abs() < 1e-10 * rate);
}

/// The local solve over a sweep of rates and step sizes: it always converges, within a few
/// iterations, and never asks for a cut-back. Prints the counts (cargo test -- --nocapture).
#[test]
fn local_solve_iterations_over_a_sweep() {
    let base = Coulomb::new(0.6)
        .unwrap()
        .with_critical_slip_absolute(1e-3)
        .unwrap();
    let mut total = 0u64;
    let mut calls = 0u64;
    let mut worst = 0;
    let mut failures = 0;
    for (mu_k, dc) in [(0.3, 1.0), (0.3, 50.0), (0.05, 1000.0), (1.2, 10.0)] {
        let law = ExtendedCoulomb::new(base).with_coefficient_law(
            CoefficientLaw::default()
                .with_exponential_decay(mu_k / 0.6, dc)
                .unwrap(),
        );
        for dt_exp in -6..=1 {
            let dt = 10f64.powi(dt_exp);
            for v_exp in -4..=3 {
                let dgam = 10f64.powi(v_exp) * dt + 2e-3;
                let inc = Increment::<2> {
                    dgam: [dgam * 0.6, dgam * 0.8],
                    pressure: 100.0,
                    dpressure: 100.0,
                    dtime: dt,
                    entry: EntryFlag::Motion,
                    ..Increment::default()
                };
                match law.update(&inc, &Conditions::default(), &ExtendedState::default()) {
                    Ok(u) => {
                        total += u64::from(u.iterations);
                        calls += 1;
                        worst = worst.max(u.iterations);
                        let t = traction(u.contact);
                        assert!(t.tau.iter().all(|x| x.is_finite()));
                    }
                    Err(_) => failures += 1,
                }
            }
        }
    }
    println!(
        "local solve: {calls} slipping calls, {failures} failures, mean {:.2} iterations, worst {worst}",
        total as f64 / calls as f64
    );
    assert_eq!(failures, 0);
    assert!(worst < MAX_LOCAL_ITERATIONS / 2, "worst {worst}");

    // Steady sliding: the first guess is the slip at the start-of-increment rate (STATEV(2)),
    // so once steady the solve stops at once.
    let law = ExtendedCoulomb::new(base).with_coefficient_law(
        CoefficientLaw::default()
            .with_exponential_decay(0.5, 20.0)
            .unwrap(),
    );
    let mut st = ExtendedState::<2>::default();
    let mut tau = [0.0; 2];
    let mut last = u32::MAX;
    for k in 0..12 {
        let inc = Increment::<2> {
            tau,
            dgam: [3e-3, 4e-3],
            pressure: 100.0,
            dpressure: if k == 0 { 100.0 } else { 0.0 },
            dtime: 0.01,
            ..Increment::default()
        };
        let u = law.update(&inc, &Conditions::default(), &st).unwrap();
        tau = traction(u.contact).tau;
        st = u.state;
        last = u.iterations;
    }
    println!("local solve in steady sliding: {last} iteration(s)");
    assert!(last <= 1, "{last}");
}

/// Every new PROPS entry out of range, and Δt ≤ 0 with a rate law or damping, NaN TEMP with a
/// temperature law, too short a STATEV with damping: one message naming the entry, PNEWDT < 1,
/// LM, TAU and STATEV unchanged, nothing written past the arrays.
#[test]
fn bad_extended_input_is_refused_cleanly() {
    let good = every_mu_law(0.4, 0.2).gamma_crit(1e-3).damping(1.0).build();
    type Spoil = fn(&mut FricCall);
    let cases: &[(&str, Spoil, &str)] = &[
        ("μ₂ < 0", |c| set_entry(c, 3, -0.2), "PROPS(3)"),
        ("μ law 3", |c| set_entry(c, 8, 3.0), "PROPS(8)"),
        ("μ_k < 0", |c| set_entry(c, 9, -0.1), "PROPS(9)"),
        ("μ_k NaN", |c| set_entry(c, 9, f64::NAN), "PROPS(9)"),
        ("d_c < 0", |c| set_entry(c, 10, -2.0), "PROPS(10)"),
        ("d_c = 0", |c| set_entry(c, 10, 0.0), "PROPS(10)"),
        (
            "μ_s = 0 with decay",
            |c| {
                set_entry(c, 2, 0.0);
                set_entry(c, 3, 0.0);
            },
            "PROPS(2)",
        ),
        ("p_ref < 0", |c| set_entry(c, 11, -1.0), "PROPS(11)"),
        (
            "b_θ = Inf",
            |c| set_entry(c, 12, f64::INFINITY),
            "PROPS(12)",
        ),
        ("HHT α > 0", |c| set_entry(c, 14, 0.2), "PROPS(14)"),
        ("HHT β < 0", |c| set_entry(c, 15, -0.2), "PROPS(15)"),
        ("c₀ < 0", |c| set_entry(c, 17, -1.0), "PROPS(17)"),
        ("f ≥ 1", |c| set_entry(c, 19, 1.0), "PROPS(19)"),
        ("freeze 2", |c| set_entry(c, 20, 2.0), "PROPS(20)"),
        (
            "PROPS(21)",
            |c| {
                c.props.push(1.0);
                c.nprops = 21;
            },
            "PROPS(21)",
        ),
        ("DTIME = 0", |c| c.dtime = 0.0, "DTIME"),
        ("DTIME < 0", |c| c.dtime = -0.1, "DTIME"),
        ("TEMP NaN", |c| c.temp[1] = f64::NAN, "TEMP"),
        ("NSTATV 4 with damping", |c| c.nstatv = 4, "NSTATV = 4"),
        ("viscous STATEV NaN", |c| c.statev[4] = f64::NAN, "STATEV"),
    ];
    for (what, spoil, word) in cases {
        let mut c = damped_point(&good, [0.5, 0.1, 1.0, 0.01, -0.02]);
        c.dpress = 10.0;
        c.tau = [3.0, -1.0, c.tau[2], c.tau[3]];
        c.dgam = [1e-3, 2e-3, 0.0];
        // The good call works.
        let mut ok = c.clone();
        ok.call();
        assert_eq!(ok.pnewdt, 1e36, "{what}: {}", FricCall::last_error());
        spoil(&mut c);
        c.set_guards();
        let before = c.clone();
        c.call();
        assert!(c.pnewdt < 1.0, "{what}: not refused");
        let msg = FricCall::last_error();
        assert!(msg.contains(word) && msg.contains("FRIC"), "{what}: {msg}");
        assert_eq!(c.lm, before.lm);
        assert_eq!(&c.tau[..2], &before.tau[..2], "{what}");
        let ns = c.nstatv.max(0) as usize;
        for i in 0..ns {
            assert!(
                c.statev[i] == before.statev[i]
                    || (c.statev[i].is_nan() && before.statev[i].is_nan()),
                "{what}: STATEV({}) changed",
                i + 1
            );
        }
        assert!(c.guards_intact(), "{what}");
    }
}

/// Viscous stick for steady-state transport (PROPS(7) = 3): γ̇_crit = 2·F_f·ω·R (seed 000,
/// PROPS(16) = 0) or F_f·ω·R (seed 003, PROPS(16) = 1) with R the distance of COORDS from the
/// axis; viscous stick τ = κ_s·v (κ_s = μp/γ̇_crit, v = DGAM/DTIME, tangent κ_s/DTIME), slip
/// τ = μ(v − γ̇_crit)·p·n, STATEV(1..3) = (slip path, slip rate, status); tangents against
/// central differences in stick and in slip, NFDIR 1 and 2, constant and decaying μ, both
/// variants; no memory of the start stress.
#[test]
fn steady_transport_viscous_stick() {
    let (mu, p, ff, omega, dt) = (0.4, 50.0, 0.01, 20.0, 0.1);
    let decays = [None, Some((0.2, 3.0))];
    // PROPS(16) = 0: γ̇_crit = 2·F_f·ω·R; PROPS(16) = 1: F_f·ω·R.
    for (variant, factor, decay) in [(0.0, 2.0), (1.0, 1.0)]
        .into_iter()
        .flat_map(|(v, f)| decays.map(|d| (v, f, d)))
    {
        for nfdir in [1usize, 2] {
            let mut props = CoulombBuilder::new()
                .mu(mu)
                .slip_tolerance(ff)
                .stick(3.0)
                .omega(omega)
                .axis(3.0) // z
                .viscous_reference(variant);
            if let Some((mk, dc)) = decay {
                props = props.mu_law(1.0).mu_k(mk).decay(dc);
            }
            let props = props.build_first(16);
            let at = |dgam: [f64; 2], press: f64| {
                let mut c = FricCall::new(nfdir as i32, &props);
                c.coords = [0.3, 0.4, 7.0]; // R = 0.5 about z
                c.press = press;
                c.dpress = press;
                c.dtime = dt;
                // A start stress, ignored: viscous stick has no memory.
                c.tau[..nfdir].copy_from_slice(&[123.0, -45.0][..nfdir]);
                c.dgam[..nfdir].copy_from_slice(&dgam[..nfdir]);
                c.call();
                assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
                assert!(c.guards_intact());
                c
            };
            let rate_crit = factor * ff * omega * 0.5;
            let kappa = mu * p / rate_crit;
            let dir = if nfdir == 1 { [1.0, 0.0] } else { [0.6, -0.8] };
            let mu_of = |v: f64| match decay {
                None => mu,
                Some((mk, dc)) => mk + (mu - mk) * (-dc * v).exp(),
            };
            for (speed, sticks) in [(0.5 * rate_crit, true), (3.0 * rate_crit, false)] {
                let dgam = [dir[0] * speed * dt, dir[1] * speed * dt];
                let c = at(dgam, p);
                let tau_eq = (0..nfdir).map(|i| c.tau[i].powi(2)).sum::<f64>().sqrt();
                let expected = if sticks {
                    kappa * speed
                } else {
                    mu_of(speed - rate_crit) * p
                };
                assert!(
                    (tau_eq - expected).abs() < 1e-12 * expected,
                    "{tau_eq} vs {expected}"
                );
                assert_eq!(c.statev[2], if sticks { 0.0 } else { 1.0 });
                // STATEV(1) from 0: the slip of the increment (v − γ̇_crit)Δt; STATEV(2) its rate.
                let slip_rate = if sticks { 0.0 } else { speed - rate_crit };
                assert!(
                    (c.statev[1] - slip_rate).abs() <= 1e-12 * speed,
                    "{}",
                    c.statev[1]
                );
                assert!((c.statev[0] - slip_rate * dt).abs() <= 1e-12 * speed * dt);
                // DDTDDG and DDTDDP against central differences.
                let h = 1e-7 * speed * dt;
                assert_smooth_tangents(&c, nfdir, (dgam, p), h, 1e-6 * (kappa / dt), at, "");
            }
        }
    }
}

/// DDTDDG and DDTDDP of `c`, the call `at` makes at `(dgam, p)`, against plain central
/// differences of TAU in a smooth branch: steps `h` on each DGAM(b) (within `tol` of DDTDDG) and
/// 10⁻⁵·p on the pressure (within 10⁻⁸ of DDTDDP).
fn assert_smooth_tangents(
    c: &FricCall,
    nfdir: usize,
    (dgam, p): ([f64; 2], f64),
    h: f64,
    tol: f64,
    at: impl Fn([f64; 2], f64) -> FricCall,
    context: &str,
) {
    for b in 0..nfdir {
        let (mut up, mut dn) = (dgam, dgam);
        up[b] += h;
        dn[b] -= h;
        let (cu, cd) = (at(up, p), at(dn, p));
        for a in 0..nfdir {
            let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * h);
            let an = c.ddtddg(a, b);
            assert!(
                (fd - an).abs() <= tol,
                "DDTDDG({a},{b}) {an} vs {fd} {context}"
            );
        }
    }
    let hp = 1e-5 * p;
    let (cu, cd) = (at(dgam, p + hp), at(dgam, p - hp));
    for a in 0..nfdir {
        let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * hp);
        let an = c.ddtddp[a];
        assert!((fd - an).abs() <= 1e-8, "DDTDDP {fd} vs {an} {context}");
    }
}

/// Steady transport bad input: ω ≤ 0, a bad axis, γ_crit given, a point on the axis, DTIME ≤ 0.
#[test]
fn steady_transport_bad_input() {
    let good = CoulombBuilder::new()
        .mu(0.4)
        .slip_tolerance(0.01)
        .stick(3.0)
        .omega(20.0)
        .build_first(16);
    type Spoil = fn(&mut FricCall);
    let cases: &[(&str, Spoil, &str)] = &[
        ("ω = 0", |c| set_entry(c, 14, 0.0), "PROPS(14)"),
        ("ω < 0", |c| set_entry(c, 14, -1.0), "PROPS(14)"),
        ("axis 4", |c| set_entry(c, 15, 4.0), "PROPS(15)"),
        ("γ_crit given", |c| set_entry(c, 5, 1e-3), "PROPS(5)"),
        (
            "PROPS(16) = 0.5",
            |c| set_entry(c, 16, 0.5),
            "PROPS(16) = 0.5 must select",
        ),
        (
            "PROPS(16) = 2",
            |c| set_entry(c, 16, 2.0),
            "PROPS(16) = 2 must select",
        ),
        (
            "PROPS(16) = -1",
            |c| set_entry(c, 16, -1.0),
            "PROPS(16) = -1 must select",
        ),
        (
            "PROPS(16) NaN",
            |c| set_entry(c, 16, f64::NAN),
            "PROPS(16) = NaN must select",
        ),
        (
            "on the axis, seed 003",
            |c| {
                set_entry(c, 16, 1.0);
                c.coords = [0.0, 0.0, 3.0];
            },
            "F_f·ω·R must be > 0",
        ),
        ("on the axis", |c| c.coords = [0.0, 0.0, 3.0], "R = 0"),
        ("COORDS NaN", |c| c.coords[1] = f64::NAN, "COORDS"),
        ("MCRD 0", |c| c.mcrd = 0, "MCRD"),
        ("DTIME = 0", |c| c.dtime = 0.0, "DTIME"),
    ];
    for (what, spoil, word) in cases {
        let mut c = FricCall::new(2, &good);
        c.coords = [1.0, 0.0, 0.0];
        c.press = 10.0;
        c.dgam = [1e-3, 0.0, 0.0];
        c.dtime = 0.1;
        c.statev[..3].copy_from_slice(&[0.5, 0.1, 1.0]);
        c.tau[..2].copy_from_slice(&[2.0, -1.0]);
        let mut ok = c.clone();
        ok.call();
        assert_eq!(ok.pnewdt, 1e36, "{what}: {}", FricCall::last_error());
        spoil(&mut c);
        c.call();
        assert!(c.pnewdt < 1.0, "{what}: not refused");
        let msg = FricCall::last_error();
        assert!(msg.contains(word) && msg.contains("FRIC"), "{what}: {msg}");
        assert_eq!(&c.statev[..3], &[0.5, 0.1, 1.0], "{what}");
        assert_eq!(&c.tau[..2], &[2.0, -1.0], "{what}");
        assert!(c.guards_intact(), "{what}");
    }
}

/// Anisotropic steady transport with seed 003's γ̇_crit = F_f·ω·R (PROPS(16) = 1): in the scaled
/// variables of Eq. 5.2.3-10/11 (a_i = μ_i/μ̄, γ̇̄_i = a_i·γ̇_i) viscous stick is
/// τ_i = a_i²·κ_s·γ̇_i with κ_s = μ̄p/γ̇_crit while |γ̇̄| ≤ γ̇_crit, and slip τ_i = a_i·μ̄(r)·p·n̄_i
/// with n̄ = γ̇̄/|γ̇̄| and r = |γ̇̄| − γ̇_crit; STATEV(2) = r; DDTDDG and DDTDDP against central
/// differences, constant and decaying μ.
#[test]
fn steady_transport_anisotropic_seed_003() {
    let (mu1, mu2, p, ff, omega, dt): (f64, f64, f64, f64, f64, f64) =
        (0.5, 0.2, 40.0, 0.02, 10.0, 0.05);
    let mbar = (0.5 * (mu1 * mu1 + mu2 * mu2)).sqrt();
    let a = [mu1 / mbar, mu2 / mbar];
    let rate_crit = ff * omega * 2.0; // R = 2 about y
    for decay in [None, Some((0.1, 2.0))] {
        let mut props = CoulombBuilder::new()
            .mu(mu1)
            .mu2(mu2)
            .slip_tolerance(ff)
            .stick(3.0)
            .omega(omega)
            .axis(2.0) // y
            .viscous_reference(1.0); // seed 003
        if let Some((mk, dc)) = decay {
            props = props.mu_law(1.0).mu_k(mk).decay(dc);
        }
        let props = props.build_first(16);
        // μ̄(r): every μ law multiplies μ₁ and μ₂ by the same factor.
        let mbar_of = |r: f64| match decay {
            None => mbar,
            Some((mk, dc)) => mbar * (mk / mu1 + (1.0 - mk / mu1) * (-dc * r).exp()),
        };
        let at = |dgam: [f64; 2], press: f64| {
            let mut c = FricCall::new(2, &props);
            c.coords = [1.2, -9.0, -1.6]; // R = 2 about y
            c.press = press;
            c.dtime = dt;
            c.dgam[..2].copy_from_slice(&dgam);
            c.call();
            assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
            assert!(c.guards_intact());
            c
        };
        let dir = [0.8, 0.6];
        // Scaled speed |γ̇̄| = speed·|(a₁d₁, a₂d₂)|.
        let scaled = ((a[0] * dir[0]).powi(2) + (a[1] * dir[1]).powi(2)).sqrt();
        for (scaled_speed, sticks) in [(0.6 * rate_crit, true), (2.5 * rate_crit, false)] {
            let speed = scaled_speed / scaled;
            let dgam = [dir[0] * speed * dt, dir[1] * speed * dt];
            let c = at(dgam, p);
            let kappa = mbar * p / rate_crit;
            for i in 0..2 {
                let expected = if sticks {
                    a[i] * a[i] * kappa * speed * dir[i]
                } else {
                    let r = scaled_speed - rate_crit;
                    a[i] * mbar_of(r) * p * a[i] * dir[i] / scaled
                };
                assert!(
                    (c.tau[i] - expected).abs() <= 1e-12 * mu1 * p,
                    "τ_{i} {} vs {expected} (stick {sticks}, decay {decay:?})",
                    c.tau[i]
                );
            }
            let r = if sticks {
                0.0
            } else {
                scaled_speed - rate_crit
            };
            assert!((c.statev[1] - r).abs() <= 1e-12 * scaled_speed);
            assert_eq!(c.statev[2], if sticks { 0.0 } else { 1.0 });
            let h = 1e-7 * speed * dt;
            let context = format!("(stick {sticks}, decay {decay:?})");
            assert_smooth_tangents(&c, 2, (dgam, p), h, 1e-6 * (kappa / dt), at, &context);
        }
    }
}

/// Seed 003's γ̇_crit = F_f·ω·R is seed 000's 2·F_f·ω·R with half the tolerance: the same
/// call with PROPS(16) = 1 and F_f = 2f answers as PROPS(16) = 0 with F_f = f, bit for bit, in
/// stick and in slip, isotropic and anisotropic; and PROPS(16) = 1 alone changes the answer.
#[test]
fn steady_transport_seed_003_is_seed_000_with_twice_the_tolerance() {
    let (f, omega, dt, p) = (0.004, 30.0, 0.05, 80.0);
    let call = |mu2: f64, tolerance: f64, variant: f64, dgam: [f64; 2]| {
        let props = CoulombBuilder::new()
            .mu(0.3)
            .mu2(mu2)
            .slip_tolerance(tolerance)
            .stick(3.0)
            .omega(omega)
            .axis(1.0) // x
            .viscous_reference(variant)
            .build_first(16);
        let mut c = FricCall::new(2, &props);
        c.coords = [5.0, 0.6, -0.8]; // R = 1 about x
        c.press = p;
        c.dtime = dt;
        c.dgam[..2].copy_from_slice(&dgam);
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        c
    };
    // γ̇_crit = 2fω = 0.24 with R = 1: speeds 0.12 (stick) and 0.6 (slip).
    for mu2 in [0.0, 0.5] {
        for speed in [0.12, 0.6] {
            let dgam = [0.6 * speed * dt, 0.8 * speed * dt];
            let a = call(mu2, f, 0.0, dgam);
            let b = call(mu2, 2.0 * f, 1.0, dgam);
            assert_eq!(&a.tau[..2], &b.tau[..2]);
            assert_eq!(a.ddtddg, b.ddtddg);
            assert_eq!(&a.ddtddp[..2], &b.ddtddp[..2]);
            assert_eq!(&a.statev[..3], &b.statev[..3]);
            assert_eq!((a.sfd, a.sed), (b.sfd, b.sed));
            let c = call(mu2, f, 1.0, dgam);
            // Stick: κ_s doubles; slip (constant μ, same τ): the slip rate v − γ̇_crit grows.
            assert!(
                a.tau[..2] != c.tau[..2] && a.statev[..2] == c.statev[..2]
                    || a.statev[1] < c.statev[1],
                "PROPS(16) = 1 ignored"
            );
        }
    }
}

/// Forced sliding through the native API (`ifl_forced_sliding`, seed 003): τ = τ_crit·v/|v|,
/// the damping part ∂τ/∂v and the stiffness part ∂τ/∂p against central differences of τ, for
/// constant and decaying μ, isotropic and anisotropic, with and without τ_max; zero velocity
/// gives zeros; bad input gives an error status and zeroed outputs.
#[test]
fn forced_sliding_split() {
    use interfacial::abi::{IflStatus, ifl_forced_sliding};
    let call = |props: &[f64], nfdir: i32, v: [f64; 2], p: f64| {
        let (mut tau, mut damping, mut stiffness) = ([9.0; 2], [9.0; 4], [9.0; 2]);
        // SAFETY: arrays sized for nfdir ≤ 2.
        let status = unsafe {
            ifl_forced_sliding(
                props.as_ptr(),
                props.len() as i32,
                nfdir,
                v.as_ptr(),
                p,
                20.0,
                tau.as_mut_ptr(),
                damping.as_mut_ptr(),
                stiffness.as_mut_ptr(),
            )
        };
        (status, tau, damping, stiffness)
    };
    let plain = CoulombBuilder::new().mu(0.5);
    let decay = plain
        .clone()
        .gamma_crit(1e-3)
        .mu_law(1.0)
        .mu_k(0.2)
        .decay(3.0);
    let aniso = decay.clone().mu2(0.25).build_first(10);
    let capped = plain.clone().tau_max(30.0).build_first(4);
    let (plain, decay) = (plain.build_first(2), decay.build_first(10));
    for props in [&plain[..], &decay[..], &aniso[..], &capped[..]] {
        for nfdir in [1, 2] {
            let n = nfdir as usize;
            let v = [0.3, -0.4];
            let p = if props.len() == 4 { 100.0 } else { 40.0 };
            let (status, tau, damping, stiffness) = call(props, nfdir, v, p);
            assert_eq!(status, IflStatus::Ok, "{}", FricCall::last_error());
            if props.len() == 2 {
                // τ = μp v/|v|.
                let speed = (0..n).map(|i| v[i] * v[i]).sum::<f64>().sqrt();
                for i in 0..n {
                    assert!((tau[i] - 0.5 * p * v[i] / speed).abs() < 1e-14);
                }
            }
            if props.len() == 4 {
                // On the cap: |τ| = τ_max and no pressure part.
                let t = (0..n).map(|i| tau[i] * tau[i]).sum::<f64>().sqrt();
                assert!((t - 30.0).abs() < 1e-12 && stiffness[..n].iter().all(|x| *x == 0.0));
            }
            let h = 1e-6;
            for b in 0..n {
                let (mut up, mut dn) = (v, v);
                up[b] += h;
                dn[b] -= h;
                let (_, tu, _, _) = call(props, nfdir, up, p);
                let (_, td, _, _) = call(props, nfdir, dn, p);
                for a in 0..n {
                    let fd = (tu[a] - td[a]) / (2.0 * h);
                    let an = damping[a + b * n];
                    assert!((fd - an).abs() < 1e-6 * p, "damping({a},{b}) {an} vs {fd}");
                }
            }
            let hp = 1e-4;
            let (_, tu, _, _) = call(props, nfdir, v, p + hp);
            let (_, td, _, _) = call(props, nfdir, v, p - hp);
            for a in 0..n {
                let fd = (tu[a] - td[a]) / (2.0 * hp);
                assert!(
                    (fd - stiffness[a]).abs() < 1e-8,
                    "stiffness({a}) {} vs {fd}",
                    stiffness[a]
                );
            }
        }
    }
    let (status, tau, damping, stiffness) = call(&plain, 2, [0.0, 0.0], 10.0);
    assert_eq!(status, IflStatus::Ok);
    assert!(tau == [0.0; 2] && damping == [0.0; 4] && stiffness == [0.0; 2]);
    for (props, nfdir, v, word) in [
        (&[1.0, -0.5][..], 2, [0.1, 0.0], "PROPS(2)"),
        (&plain[..], 3, [0.1, 0.0], "nfdir = 3"),
        (&plain[..], 2, [f64::NAN, 0.0], "NaN"),
    ] {
        let (status, tau, _, _) = call(props, nfdir, v, 10.0);
        assert_ne!(status, IflStatus::Ok);
        let msg = FricCall::last_error();
        assert!(
            msg.contains(word) && msg.contains("ifl_forced_sliding"),
            "{msg}"
        );
        if nfdir == 2 {
            assert_eq!(tau, [0.0; 2]);
        }
    }
}

/// Finding C3 (docs/fuzzing.md) through `fric_`: μ̄·f is formed with μ̄ multiplied in first.
/// μ₁ = 10¹⁵⁰, μ₂ = μ₁/2 (the anisotropic, general path), the decay law frozen at the start
/// rate `STATEV(2)` = 10³ (e = exp(−1000) = 0 in f64, so f = μ_k/μ_s·Θ with μ_k = 10⁻³) and
/// Θ = exp(−427): slipping along direction 1, τ₁ = μ₁·f·p = μ_k·Θ·p ≈ 3.6·10⁻¹⁸⁹·p, a normal
/// number, while f = 10⁻¹⁵³·Θ alone underflows to 0.
#[test]
fn friction_stress_of_a_huge_coefficient_times_a_tiny_factor_is_kept() {
    let props = coulomb(1e150, 1e-3)
        .mu2(0.5e150)
        .mu_law(1.0)
        .mu_k(1e-3)
        .decay(1.0)
        .b_theta(1.0)
        .frozen(1.0)
        .build();
    let mut c = FricCall::new(2, &props);
    c.press = 1.0;
    c.dpress = 0.0;
    c.statev = vec![0.0, 1e3, 1.0];
    c.temp = [427.0, 427.0];
    c.dgam = [1.0, 0.0, 0.0];
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    let expected = 1e-3 * (-427.0f64).exp();
    assert!(expected.is_normal() && (1e-153 * (-427.0f64).exp()) == 0.0);
    assert!(
        (c.tau[0] - expected).abs() <= 1e-12 * expected,
        "τ₁ = {:e}, expected {expected:e}",
        c.tau[0]
    );
    assert_eq!(c.tau[1], 0.0);
}

/// A start pressure so small that τ̄_crit(p₀)² underflows (and, at 10⁻³¹², that γ_crit/τ̄_crit
/// overflows): the extended law still answers, with the first-contact stress of the closed
/// form and a temperature tangent that matches central differences of `TAU` in `TEMP`. Before,
/// the θ̄-derivative of the elastic start slip was 0/0 and every such increment was refused as
/// an overflow — the general path (temperature law, pressure law) and the decay law's lean path
/// alike.
#[test]
fn a_vanishing_start_pressure_is_answered() {
    const B_THETA: f64 = 0.01;
    const THETA_REF: f64 = 20.0;
    const P_REF: f64 = 1e6;
    let (mu, gc) = (0.3, 1e-3);
    let props = coulomb(mu, gc);
    // (name, the μ law's PROPS(8..13), μ at θ̄ = 25 and p → 0)
    let laws = [
        (
            "temperature",
            props.clone().b_theta(B_THETA).theta_ref(THETA_REF),
            mu * (-B_THETA * (25.0 - THETA_REF)).exp(),
        ),
        ("pressure", props.clone().p_ref(P_REF), mu),
        // Decay law at rest (first contact, γ̇ = 0 in stick): μ = μ_s.
        ("decay", props.mu_law(1.0).mu_k(0.1).decay(4.0), mu),
    ];
    for (name, law, mu_eff) in laws {
        let law = law.build();
        for p in [1e-200, 1e-312] {
            let run = |temp: f64| {
                let mut c = FricCall::new(1, &law);
                c.press = p;
                c.dpress = 0.0;
                c.tau[0] = 0.0;
                c.dgam[0] = 2e-4;
                c.temp = [temp, temp];
                c.call();
                c
            };
            let c = run(25.0);
            assert_eq!(
                c.pnewdt,
                1e36,
                "{name}, p = {p}: {}",
                FricCall::last_error()
            );
            // Stick from τ̄ = 0: τ = k_s Δγ = (μ p/γ_crit) Δγ (a subnormal stress at 10⁻³¹²:
            // fewer digits).
            let expected = mu_eff * p / gc * 2e-4;
            assert!(
                (c.tau[0] - expected).abs() <= 1e-9 * expected + 1e-320,
                "{name}, p = {p}: τ = {} against {expected}",
                c.tau[0]
            );
            if name == "temperature" && p == 1e-200 {
                // ∂τ/∂TEMP(1), one column of DDTDDT, against a central difference.
                let h = 1e-3;
                let (up, down) = (run(25.0 + h), run(25.0 - h));
                let moved = |t1: f64| {
                    let mut c = FricCall::new(1, &law);
                    c.press = p;
                    c.dgam[0] = 2e-4;
                    c.temp = [t1, 25.0];
                    c.call();
                    c.tau[0]
                };
                let fd = (moved(25.0 + h) - moved(25.0 - h)) / (2.0 * h);
                assert!(
                    (c.ddtddt[0] - fd).abs() <= 1e-6 * fd.abs(),
                    "DDTDDT(1,1) = {} against {fd}",
                    c.ddtddt[0]
                );
                // Both temperatures moved: the two columns add up.
                let both = (up.tau[0] - down.tau[0]) / (2.0 * h);
                assert!((c.ddtddt[0] + c.ddtddt[1] - both).abs() <= 1e-6 * both.abs());
            }
        }
    }
}

/// The decay law with a temperature-dependent μ on its lean path (isotropic, elastic stick,
/// `NPROPS = 20`, no damping: `fric_`'s rate fast path): a NaN or infinite temperature is
/// refused by name (`TEMP`), with PNEWDT < 1 and TAU, STATEV unchanged — not reported as a
/// numerical failure of the local solve.
#[test]
fn decay_law_names_a_bad_temperature() {
    let props = coulomb(0.5, 1e-3)
        .mu_law(1.0)
        .mu_k(0.2)
        .decay(2.0)
        .b_theta(0.01)
        .theta_ref(20.0)
        .build_first(20);
    for bad in [f64::NAN, f64::INFINITY] {
        for nfdir in [1, 2] {
            let mut c = FricCall::new(nfdir, &props);
            c.press = 100.0;
            c.dpress = 0.0;
            c.dgam = [2e-3, 1e-3, 0.0];
            c.dtime = 0.1;
            let mut ok = c.clone();
            ok.call();
            assert_eq!(ok.pnewdt, 1e36, "{}", FricCall::last_error());
            c.temp[1] = bad;
            let before = c.clone();
            c.call();
            let msg = FricCall::last_error();
            assert!(c.pnewdt < 1.0, "TEMP {bad} not refused");
            assert!(msg.contains("TEMP") && msg.contains("FRIC"), "{msg}");
            assert_eq!(c.tau, before.tau);
            assert_eq!(c.statev[..3], before.statev[..3]);
        }
    }
}

/// μ(θ̄) out of f64's range (b_θ = 1 at θ̄ = −1000: e^{1000} overflows, the CalculiX cut-back
/// deck's case) is refused as an overflow, never as a rate softening that cancels the stick
/// stiffness (the law has no rate dependence), whatever the pressure and slip.
#[test]
fn an_overflowing_temperature_factor_is_named_an_overflow() {
    let props = coulomb(0.3, 1e-3).b_theta(1.0).build_first(13);
    for nfdir in [1, 2] {
        for press in [0.0, 1e-3, 1.0, 100.0] {
            for dgam in [0.0, 1e-6, 1e-2] {
                let mut c = FricCall::new(nfdir, &props);
                c.press = press;
                c.dpress = press.min(1.0);
                c.temp = [-1000.0, -1000.0];
                c.dgam = [dgam, dgam, 0.0];
                interfacial::abi::ifl_clear_error();
                c.call();
                let msg = FricCall::last_error();
                let case = format!("NFDIR {nfdir}, p {press}, Δγ {dgam}");
                assert!(c.pnewdt < 1.0, "{case}: refused");
                assert!(!msg.contains("rate softening"), "{case}: {msg}");
                assert!(
                    msg.contains("out of f64's range") || msg.contains("overflowed"),
                    "{case}: {msg}"
                );
            }
        }
    }
}
