//! Velocity-weakening friction through `fric_` and `uinter_` as a host calls them (issue 16):
//! the decay law (law 1, `PROPS(8) = 1`) and the adhesive law (law 2) slide steadily at
//! τ = μ(v)·p (law 2: seed 004's S_slide at v) for every increment size r·γ_crit and every
//! d_c·v; a stop keeps the stress; a reversal passes through stick; a velocity step settles at
//! once; from rest the stress still reaches the static strength before the first slip; the
//! tangents of every branch match central differences of the stresses `fric_` returns; a fresh
//! open point through `uinter_` is not bonded. Every expected value is a closed form of the law
//! (μ(v)·p, S_slide(v), μ_s·p + S_a) or a difference of our own outputs.

#[path = "common/central.rs"]
mod central;

use central::{move_press, sides, slope};
use interfacial::laws::contact::Conditions;
use interfacial::laws::contact::Increment;
use interfacial::laws::coulomb::Coulomb;
use interfacial::laws::coulomb_extended::{ExtendedCoulomb, ExtendedState};
use interfacial::laws::friction_coefficient::{CoefficientLaw, RateFormulation};
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::{FricCall, UinterCall};

const GAMMA_CRIT: f64 = 1e-3;
const P: f64 = 100.0;
const MU_S: f64 = 0.5;
const MU_K: f64 = 0.2;

/// Law 1 with the decay law: μ_s, μ_k, d_c (γ_crit absolute).
fn decay_law(d_c: f64) -> CoulombBuilder {
    CoulombBuilder::new()
        .mu(MU_S)
        .gamma_crit(GAMMA_CRIT)
        .mu_law(1.0)
        .mu_k(MU_K)
        .decay(d_c)
}

/// [`decay_law`], `PROPS(1..10)`.
fn decay_props(d_c: f64) -> Vec<f64> {
    decay_law(d_c).build_first(10)
}

fn decay_mu(d_c: f64, v: f64) -> f64 {
    MU_K + (MU_S - MU_K) * (-d_c * v).exp()
}

/// Law 2: μ_d, μ_s, S_a, N_a, k_μ, v_½, γ_crit.
#[derive(Clone, Copy)]
struct Adhesive {
    mu_d: f64,
    mu_s: f64,
    sa: f64,
    kmu: f64,
    vhalf: f64,
}

impl Adhesive {
    fn law(&self) -> AdhesiveBuilder {
        AdhesiveBuilder::new()
            .coeff(self.mu_d)
            .coeff_static(self.mu_s)
            .sa(self.sa)
            .kmu(self.kmu)
            .vhalf(self.vhalf)
            .gamma_crit(GAMMA_CRIT)
    }

    /// `PROPS(1..8)`, what `fric_` reads.
    fn props(&self) -> Vec<f64> {
        self.law().build_first(8)
    }

    /// With K_n = 10⁶ for `uinter_`, `PROPS(1..10)`.
    fn interface(&self) -> Vec<f64> {
        self.law().normal_stiffness(1e6).build_first(10)
    }
}

/// An adhesive interface with separation adhesion: μ_d 0.2, μ_s 0.5, S_a 3, N_a 5, K_n 10⁶,
/// `PROPS(1..10)`.
fn bonding_interface() -> Vec<f64> {
    AdhesiveBuilder::new()
        .coeff(0.2)
        .coeff_static(0.5)
        .sa(3.0)
        .na(5.0)
        .gamma_crit(GAMMA_CRIT)
        .normal_stiffness(1e6)
        .build_first(10)
}

impl Adhesive {
    /// Seed 004: S_slide = ((μ_s v_½ + μ_d v)/(v_½ + v) + k_μ v)·p + S_a.
    fn sliding(&self, v: f64, p: f64) -> f64 {
        ((self.mu_s * self.vhalf + self.mu_d * v) / (self.vhalf + v) + self.kmu * v) * p + self.sa
    }

    fn static_strength(&self, p: f64) -> f64 {
        self.mu_s * p + self.sa
    }
}

const ADHESIVE: [Adhesive; 3] = [
    // v_½ = 0: the instantaneous drop μ_s → μ_d.
    Adhesive {
        mu_d: 0.2,
        mu_s: 0.5,
        sa: 3.0,
        kmu: 0.0,
        vhalf: 0.0,
    },
    // A smooth transition with a small v_½ (strong weakening) and a rate term.
    Adhesive {
        mu_d: 0.2,
        mu_s: 0.5,
        sa: 3.0,
        kmu: 0.5,
        vhalf: 1e-3,
    },
    // No adhesion, a larger v_½.
    Adhesive {
        mu_d: 0.1,
        mu_s: 0.6,
        sa: 0.0,
        kmu: 0.0,
        vhalf: 0.05,
    },
];

/// A point driven through `fric_`, carrying TAU and STATEV between increments as a host does.
struct Point {
    call: FricCall,
    /// Unit direction of the motion in the plane (NFDIR = 2), or 1 (NFDIR = 1).
    dir: [f64; 2],
}

/// One increment's outputs.
#[derive(Clone, Copy, Debug)]
struct Step {
    /// Stress along the driving direction.
    tau: f64,
    /// Stress across it (0 in 2-D).
    across: f64,
    status: f64,
    pnewdt: f64,
}

impl Point {
    fn new(props: &[f64], nfdir: i32) -> Self {
        let mut call = FricCall::new(nfdir, props);
        call.press = P;
        call.dpress = 0.0;
        // An off-axis direction in 3-D, so that both components and the projection count.
        let dir = if nfdir == 2 { [0.6, -0.8] } else { [1.0, 0.0] };
        Point { call, dir }
    }

    /// Moves by `dgam` along the direction in `dtime`.
    fn step(&mut self, dgam: f64, dtime: f64) -> Step {
        let c = &mut self.call;
        let n = c.nfdir as usize;
        for i in 0..n {
            c.dgam[i] = dgam * self.dir[i];
        }
        c.dtime = dtime;
        c.dpress = 0.0;
        c.pnewdt = 1e36;
        c.call();
        assert!(c.guards_intact());
        let (d, c) = (self.dir, &self.call);
        let (tau, across) = if n == 2 {
            (
                c.tau[0] * d[0] + c.tau[1] * d[1],
                -c.tau[0] * d[1] + c.tau[1] * d[0],
            )
        } else {
            (c.tau[0], 0.0)
        };
        Step {
            tau,
            across,
            status: c.statev[2],
            pnewdt: c.pnewdt,
        }
    }
}

/// Drives at slip velocity v with increments r·γ_crit for `n` increments.
fn drive(point: &mut Point, r: f64, v: f64, n: usize) -> Vec<Step> {
    let dgam = r * GAMMA_CRIT;
    (0..n).map(|_| point.step(dgam, dgam.abs() / v)).collect()
}

/// Increments enough to load from rest (1/r of them) and slide a while.
fn increments_for(r: f64) -> usize {
    (1.5 / r).ceil() as usize + 40
}

/// Steady driving: after the second sliding increment every increment slides at the closed
/// form (to round-off, well inside the issue's 1 %), whatever r and d_c·v; so does the mean.
fn assert_steady(steps: &[Step], expected: f64, what: &str) {
    let first_slip = steps
        .iter()
        .position(|s| s.status == 1.0)
        .unwrap_or_else(|| panic!("{what}: never slid"));
    let settled = &steps[first_slip + 2..];
    assert!(settled.len() >= 30, "{what}: too few sliding increments");
    for (i, s) in settled.iter().enumerate() {
        assert_eq!(
            s.status, 1.0,
            "{what}: increment {i} after settling is not slip"
        );
        assert_eq!(s.pnewdt, 1e36, "{what}: cut-back asked");
        assert!(
            (s.tau - expected).abs() <= 1e-9 * expected,
            "{what}: τ = {} vs {expected} at settled increment {i}",
            s.tau
        );
        assert!(
            s.across.abs() <= 1e-9 * expected,
            "{what}: across {}",
            s.across
        );
    }
    let mean = settled.iter().map(|s| s.tau).sum::<f64>() / settled.len() as f64;
    assert!(
        (mean - expected).abs() <= 0.01 * expected,
        "{what}: mean {mean}"
    );
}

const RATIOS: [f64; 9] = [0.01, 0.03, 0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 20.0];

#[test]
fn decay_law_slides_steadily_at_every_increment_and_rate() {
    let d_c = 200.0;
    for nfdir in [1, 2] {
        for x in [0.1, 1.0, 3.0, 10.0, 40.0] {
            let v = x / d_c;
            for r in RATIOS {
                let mut point = Point::new(&decay_props(d_c), nfdir);
                let steps = drive(&mut point, r, v, increments_for(r));
                let what = format!("decay NFDIR {nfdir} d_c·v {x} r {r}");
                assert_steady(&steps, decay_mu(d_c, v) * P, &what);
            }
        }
    }
}

#[test]
fn the_issue_case_slides_at_mu_of_v() {
    // Issue 16: μ_s 0.5, μ_k 0.2, d_c 200, d_c·v = 3, r = 0.25 cycled 12.5 → 50 → 20 … to
    // increment 400. Now: 12.5, 25, 37.5, 50 (stick), then slip; τ = μ(v)·p = 21.49… after.
    let d_c = 200.0;
    let v = 3.0 / d_c;
    let mut point = Point::new(&decay_props(d_c), 1);
    let steps = drive(&mut point, 0.25, v, 400);
    for (i, s) in steps[..4].iter().enumerate() {
        assert_eq!(s.status, 0.0);
        assert!((s.tau - 12.5 * (i + 1) as f64).abs() < 1e-9);
    }
    let expected = decay_mu(d_c, v) * P;
    assert!((expected - 21.49).abs() < 0.01);
    assert_steady(&steps, expected, "issue case");
}

#[test]
fn adhesive_law_slides_steadily_at_the_seed_strength() {
    for (k, law) in ADHESIVE.iter().enumerate() {
        for nfdir in [1, 2] {
            for v in [1e-4, 1e-3, 1e-2, 0.3] {
                for r in RATIOS {
                    let mut point = Point::new(&law.props(), nfdir);
                    let steps = drive(&mut point, r, v, increments_for(r));
                    let what = format!("adhesive {k} NFDIR {nfdir} v {v} r {r}");
                    assert_steady(&steps, law.sliding(v, P), &what);
                }
            }
        }
    }
}

/// From rest the stress climbs with the static stiffness to the static strength, exactly, and
/// no increment before the first slip goes above it.
fn assert_onset(steps: &[Step], strength: f64, r: f64, what: &str) {
    let first_slip = steps.iter().position(|s| s.status == 1.0).unwrap();
    let peak = steps[..first_slip]
        .iter()
        .map(|s| s.tau)
        .fold(0.0f64, f64::max);
    assert!(
        peak <= strength * (1.0 + 1e-12),
        "{what}: peak {peak} above {strength}"
    );
    assert!(
        peak >= strength * (1.0 - r) - 1e-9,
        "{what}: peak {peak} short of {strength}"
    );
}

#[test]
fn from_rest_the_stress_reaches_the_static_strength_first() {
    let d_c = 200.0;
    for r in [0.01, 0.1, 0.25, 0.3] {
        let mut point = Point::new(&decay_props(d_c), 2);
        let steps = drive(&mut point, r, 3.0 / d_c, increments_for(r));
        assert_onset(&steps, MU_S * P, r, &format!("decay r {r}"));
        // r = 0.25 lands on γ_crit exactly: the peak is μ_s·p itself.
        if r == 0.25 {
            assert!((steps[3].tau - MU_S * P).abs() < 1e-9);
        }
        for law in ADHESIVE {
            let mut point = Point::new(&law.props(), 1);
            let steps = drive(&mut point, r, 1e-2, increments_for(r));
            assert_onset(
                &steps,
                law.static_strength(P),
                r,
                &format!("adhesive r {r}"),
            );
        }
    }
}

/// After steady sliding: increments without motion keep τ (stick, no jump to the static
/// strength); driving again loads from there to the static strength and slides again.
fn check_stop(props: &[f64], v: f64, sliding: f64, static_strength: f64, what: &str) {
    for nfdir in [1, 2] {
        let r = 0.1;
        let mut point = Point::new(props, nfdir);
        drive(&mut point, r, v, increments_for(r));
        let held = point.step(0.0, 0.1).tau;
        assert!(
            (held - sliding).abs() <= 1e-9 * sliding,
            "{what}: first stop {held}"
        );
        for _ in 0..5 {
            let s = point.step(0.0, 0.1);
            assert_eq!(s.status, 0.0, "{what}: stop is stick");
            assert!(
                (s.tau - sliding).abs() <= 1e-9 * sliding,
                "{what}: stop {}",
                s.tau
            );
        }
        // Restart: static stiffness from the held stress up to the static strength.
        let steps = drive(&mut point, r, v, increments_for(r));
        assert_onset(&steps, static_strength, r, what);
        assert!((steps.last().unwrap().tau - sliding).abs() <= 1e-9 * sliding);
    }
}

#[test]
fn a_stop_keeps_the_stress() {
    let d_c = 200.0;
    for x in [1.0, 3.0] {
        let v = x / d_c;
        check_stop(
            &decay_props(d_c),
            v,
            decay_mu(d_c, v) * P,
            MU_S * P,
            &format!("decay x {x}"),
        );
    }
    // v = 0.015 with NFDIR = 2 read a stop as a slip of a few ulps (τ jumped to μ_s·p + S_a)
    // before the stick test allowed for the rounding of γ̄^el.
    for law in ADHESIVE {
        for v in [1e-2, 1.5e-2, 0.3] {
            check_stop(
                &law.props(),
                v,
                law.sliding(v, P),
                law.static_strength(P),
                "adhesive",
            );
        }
    }
}

/// After steady sliding, driving the other way: the first increments stick (the stress falls
/// with the stick stiffness), the stress changes sign, and the point slides the other way at
/// the closed form.
fn check_reversal(props: &[f64], v: f64, sliding: f64, what: &str) {
    for nfdir in [1, 2] {
        for r in [0.05, 0.3] {
            let mut point = Point::new(props, nfdir);
            drive(&mut point, r, v, increments_for(r));
            let back = drive(&mut point, -r, v, increments_for(r) * 2);
            assert_eq!(back[0].status, 0.0, "{what}: reversal starts in stick");
            assert!(
                back[0].tau < sliding && back[0].tau > 0.0,
                "{what}: {:?}",
                back[0]
            );
            let through_zero = back.iter().position(|s| s.tau < 0.0).unwrap();
            assert!(
                back[..through_zero].iter().all(|s| s.status == 0.0),
                "{what}: slid before the stress changed sign"
            );
            assert_steady(
                &back
                    .iter()
                    .map(|s| Step { tau: -s.tau, ..*s })
                    .collect::<Vec<_>>(),
                sliding,
                &format!("{what} reversed NFDIR {nfdir} r {r}"),
            );
        }
    }
}

#[test]
fn a_reversal_passes_through_stick() {
    let d_c = 200.0;
    let v = 3.0 / d_c;
    check_reversal(&decay_props(d_c), v, decay_mu(d_c, v) * P, "decay");
    for law in ADHESIVE {
        check_reversal(&law.props(), 1e-2, law.sliding(1e-2, P), "adhesive");
    }
}

/// A step of the driving velocity settles within 3 increments (here: the first).
fn check_velocity_step(props: &[f64], v1: f64, v2: f64, mu_p: &dyn Fn(f64) -> f64, what: &str) {
    for nfdir in [1, 2] {
        for r in [0.02, 0.25, 2.0] {
            let mut point = Point::new(props, nfdir);
            drive(&mut point, r, v1, increments_for(r));
            let after = drive(&mut point, r, v2, 10);
            let expected = mu_p(v2);
            for s in &after[..] {
                assert_eq!(s.status, 1.0);
                assert!(
                    (s.tau - expected).abs() <= 0.01 * expected,
                    "{what} {v1} → {v2} r {r}: {} vs {expected}",
                    s.tau
                );
            }
        }
    }
}

#[test]
fn a_velocity_step_settles_at_once() {
    let d_c = 200.0;
    for (x1, x2) in [(1.0, 3.0), (3.0, 1.0), (0.5, 10.0), (10.0, 0.1)] {
        check_velocity_step(
            &decay_props(d_c),
            x1 / d_c,
            x2 / d_c,
            &|v| decay_mu(d_c, v) * P,
            "decay",
        );
    }
    for law in ADHESIVE {
        for (v1, v2) in [(1e-3, 1e-2), (1e-2, 1e-4)] {
            check_velocity_step(&law.props(), v1, v2, &|v| law.sliding(v, P), "adhesive");
        }
    }
}

/// The decay law μ_s → `mu_k` over `d_c` (γ_crit absolute, an optional shear limit τ_max) in
/// the earlier formulation, the rate-free stick stiffness (Rust API only).
fn earlier_formulation(mu_k: f64, d_c: f64, tau_max: Option<f64>) -> ExtendedCoulomb {
    let mut base = Coulomb::new(MU_S)
        .and_then(|c| c.with_critical_slip_absolute(GAMMA_CRIT))
        .unwrap();
    if let Some(tau_max) = tau_max {
        base = base.with_shear_limit(tau_max).unwrap();
    }
    ExtendedCoulomb::new(base)
        .with_coefficient_law(
            CoefficientLaw::default()
                .with_exponential_decay(mu_k / MU_S, d_c)
                .unwrap(),
        )
        .with_rate_formulation(RateFormulation::RateFreeStiffness)
}

/// The earlier formulation (kept only for comparison, Rust API): with the rate-free stick
/// stiffness the issue's case cycles instead of sliding. This is the behaviour the tests above
/// would catch if it came back as the default.
#[test]
fn the_earlier_formulation_cycles_on_the_issue_case() {
    let d_c = 200.0;
    let v = 3.0 / d_c;
    let law = earlier_formulation(MU_K, d_c, None);
    let dgam = 0.25 * GAMMA_CRIT;
    let mut tau = 0.0;
    let mut state = ExtendedState::<1>::default();
    let mut taus = vec![];
    for _ in 0..400 {
        let inc = Increment::<1> {
            tau: [tau],
            dgam: [dgam],
            pressure: P,
            dpressure: 0.0,
            dtime: dgam / v,
            characteristic_length: 1.0,
            ..Increment::default()
        };
        let up = law.update(&inc, &Conditions::default(), &state).unwrap();
        let interfacial::laws::contact::Contact::Motion(t) = up.contact else {
            panic!("no exact stick here")
        };
        tau = t.tau[0];
        state = up.state;
        taus.push(tau);
    }
    let last = &taus[300..];
    let (lo, hi) = last
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), t| (a.min(*t), b.max(*t)));
    // The issue's cycle: 20.0 → 32.5 → 45.0 → 20.0 …, far from μ(v)·p = 21.5.
    assert!(hi - lo > 20.0, "{lo} … {hi}");
    assert!(hi > 44.0 && lo < 21.0);
}

/// Central differences of `fric_`'s own stresses in Δγ_b and p (p₀ held: `DPRESS` moves with
/// `PRESS`), against `DDTDDG` and `DDTDDP`.
fn check_tangents(call: &FricCall, what: &str) {
    let n = call.nfdir as usize;
    let mut base = call.clone();
    base.call();
    assert_eq!(base.pnewdt, 1e36, "{what}: refused");
    let scale = (0..n).map(|a| base.tau[a].abs()).fold(1.0f64, f64::max);
    for b in 0..n {
        let h = 1e-7 * GAMMA_CRIT;
        let (plus, minus) = sides(call, h, |c, h| c.dgam[b] += h);
        assert_eq!(plus.statev[2], base.statev[2], "{what}: branch changed");
        assert_eq!(minus.statev[2], base.statev[2], "{what}: branch changed");
        for a in 0..n {
            let fd = slope(&plus, &minus, a, h);
            let k_scale = scale / GAMMA_CRIT;
            assert!(
                (fd - base.ddtddg(a, b)).abs() <= 1e-5 * k_scale,
                "{what}: DDTDDG({a},{b}) = {} vs FD {fd}",
                base.ddtddg(a, b)
            );
        }
    }
    let h = 1e-6 * P;
    let (plus, minus) = sides(call, h, move_press);
    for a in 0..n {
        let fd = slope(&plus, &minus, a, h);
        assert!(
            (fd - base.ddtddp[a]).abs() <= 1e-6 * (scale / P).max(1.0),
            "{what}: DDTDDP({a}) = {} vs FD {fd}",
            base.ddtddp[a]
        );
    }
}

/// The call a point would make next after `warm` increments at r, v, with `dgam` (along the
/// direction, plus a sideways part in 3-D) and a pressure change.
fn next_call(props: &[f64], nfdir: i32, warm: usize, v: f64, dgam: f64) -> FricCall {
    let mut point = Point::new(props, nfdir);
    let r = 0.2;
    drive(&mut point, r, v, warm);
    let mut c = point.call.clone();
    for i in 0..nfdir as usize {
        c.dgam[i] = dgam * point.dir[i];
    }
    if nfdir == 2 {
        c.dgam[0] += 0.1 * dgam.abs().max(1e-5 * GAMMA_CRIT);
    }
    c.dtime = (r * GAMMA_CRIT) / v;
    c.dpress = -5.0;
    c.press = P - 5.0 + 5.0;
    c.pnewdt = 1e36;
    c
}

#[test]
fn tangents_match_central_differences_in_every_branch() {
    let d_c = 200.0;
    let v = 3.0 / d_c;
    let laws: Vec<(String, Vec<f64>, f64)> =
        std::iter::once(("decay".to_string(), decay_props(d_c), v))
            .chain(
                ADHESIVE
                    .iter()
                    .enumerate()
                    .map(|(k, l)| (format!("adhesive {k}"), l.props(), 1e-2)),
            )
            .collect();
    for (name, props, v) in &laws {
        for nfdir in [1, 2] {
            let r = 0.2 * GAMMA_CRIT;
            for (branch, warm, dgam) in [
                ("stick from rest", 1, 0.5 * r),
                ("onset", 4, 1.5 * r),
                ("sliding", 30, r),
                ("sliding faster", 30, 3.0 * r),
                ("stick after sliding (reversal)", 30, -0.5 * r),
                ("stop after sliding", 30, 1e-3 * r),
            ] {
                let c = next_call(props, nfdir, warm, *v, dgam);
                check_tangents(&c, &format!("{name} NFDIR {nfdir} {branch}"));
            }
        }
    }
}

#[test]
fn a_fresh_open_point_is_not_bonded() {
    // Adhesive interface with separation adhesion; K_n = 1e6.
    let props = bonding_interface();
    for ndir in [2, 3] {
        let mut c = UinterCall::new(ndir, &props);
        // Never touched, a small gap: h = −1 µm (tension K_n·|h| = 1 < N_a would hold a bond).
        c.rdisp[0] = -1e-6;
        c.drdisp[0] = -1e-6;
        c.drdisp[1] = 1e-5;
        c.call();
        assert_eq!(c.pnewdt, 1e36);
        assert!(
            c.stress[..ndir as usize].iter().all(|s| *s == 0.0),
            "{:?}",
            c.stress
        );
        assert_eq!(c.statev[2], 4.0);
        assert_eq!(c.lopenclose, 0);
        assert!(c.guards_intact());
        // Close it: h = +1 µm, p = 1.
        c.rdisp[0] = 1e-6;
        c.drdisp = [2e-6, 0.0, 0.0];
        c.call();
        assert_eq!(c.statev[2], 0.0);
        assert!((c.stress[0] - 1.0).abs() < 1e-9);
        // Open again slightly: now bonded, pulling with K_n·|h| = 1 (< N_a = 5).
        c.rdisp[0] = -1e-6;
        c.drdisp = [-2e-6, 0.0, 0.0];
        c.call();
        assert_eq!(c.statev[2], 3.0);
        assert_eq!(c.lopenclose, 1);
        assert!((c.stress[0] + 1.0).abs() < 1e-9, "{:?}", c.stress);
        // Pulled past N_a: the bond breaks, and stays broken while apart.
        c.rdisp[0] = -1e-5;
        c.drdisp = [-9e-6, 0.0, 0.0];
        c.call();
        assert_eq!(c.statev[2], 4.0);
        c.rdisp[0] = -1e-6;
        c.drdisp = [9e-6, 0.0, 0.0];
        c.call();
        assert_eq!(c.statev[2], 4.0);
        assert_eq!(c.stress[0], 0.0);
    }
}

#[test]
fn uinter_slides_steadily_and_keeps_the_stress_at_a_stop() {
    // The same steady-sliding answer through uinter_ (closed at constant overclosure).
    for law in ADHESIVE {
        let props = law.interface();
        let (v, r) = (1e-2, 0.1);
        let mut c = UinterCall::new(2, &props);
        c.rdisp[0] = P / 1e6;
        c.drdisp[0] = P / 1e6;
        let dgam = r * GAMMA_CRIT;
        c.dtime = dgam / v;
        let mut taus = vec![];
        for _ in 0..increments_for(r) {
            c.drdisp[1] = dgam;
            c.rdisp[1] += dgam;
            c.call();
            assert_eq!(c.pnewdt, 1e36);
            c.drdisp[0] = 0.0;
            taus.push((c.stress[1], c.statev[2]));
        }
        let expected = law.sliding(v, P);
        for (t, status) in &taus[taus.len() - 20..] {
            assert_eq!(*status, 1.0);
            assert!((t - expected).abs() <= 1e-9 * expected, "{t} vs {expected}");
        }
        c.drdisp[1] = 0.0;
        c.call();
        assert_eq!(c.statev[2], 0.0);
        assert!((c.stress[1] - expected).abs() <= 1e-9 * expected);
    }
}

/// docs/bad-input.md rows 84–85: after a slip (`STATEV(3)` = 1) the adhesive law reads the
/// start slip rate `STATEV(2)` as its stick-stiffness memory, so a negative one is refused
/// (cut-back, stress and state unchanged, a message naming `STATEV(2)`); after a stick it is
/// not read.
#[test]
fn a_negative_start_rate_after_a_slip_is_refused() {
    let law = ADHESIVE[1];
    for nfdir in [1, 2] {
        let mut c = FricCall::new(nfdir, &law.props());
        c.press = P;
        c.tau[0] = 30.0;
        c.dgam[0] = 1e-5;
        c.statev[..3].copy_from_slice(&[0.5, -1e-3, 1.0]);
        let before = c.clone();
        c.call();
        assert_rate_refused(c.pnewdt, "FRIC");
        assert_eq!(c.tau, before.tau);
        assert_eq!(c.statev, before.statev);
        // After a stick the rate is not read: the same call succeeds.
        let mut c = before.clone();
        c.statev[2] = 0.0;
        c.call();
        assert_eq!(c.pnewdt, 1e36);
    }
    let props = law.interface();
    let mut u = UinterCall::new(2, &props);
    u.rdisp[0] = 1e-4;
    u.stress[..2].copy_from_slice(&[P, 30.0]);
    u.statev[..3].copy_from_slice(&[0.5, -1e-3, 1.0]);
    u.drdisp[1] = 1e-5;
    let before = u.clone();
    u.call();
    assert_rate_refused(u.pnewdt, "UINTER");
    assert_eq!(u.stress, before.stress);
    assert_eq!(u.statev, before.statev);
}

/// A call of `routine` refused for its start rate: a cut-back and a message naming `STATEV(2)`.
fn assert_rate_refused(pnewdt: f64, routine: &str) {
    assert_eq!(pnewdt, interfacial::CUTBACK_RATIO);
    let message = FricCall::last_error();
    assert!(
        message.contains("STATEV(2)") && message.contains(routine),
        "{message}"
    );
}

/// τ_max between μ_k·p and μ_s·p under strong weakening (issue 16, item 4): the earlier slip
/// equation could have three roots; the rate-following slip is explicit, so every increment has
/// one answer: from rest the stress climbs to τ_max (the stick stiffness is τ_max/γ_crit) and
/// slides there while μ(v)·p ≥ τ_max, and slides at μ(v)·p below it; the tangent on the cap has
/// no rate term, off the cap it has (∂τ/∂γ̇)/Δt (checked against differences).
#[test]
fn tau_max_between_the_kinetic_and_static_strength() {
    let d_c = 200.0;
    let tau_max = 35.0;
    let props = decay_law(d_c).tau_max(tau_max).build_first(10);
    for nfdir in [1, 2] {
        for x in [0.2, 1.0, 3.0, 10.0] {
            let v = x / d_c;
            let expected = (decay_mu(d_c, v) * P).min(tau_max);
            for r in [0.01, 0.3, 3.0] {
                let mut point = Point::new(&props, nfdir);
                let steps = drive(&mut point, r, v, increments_for(r));
                let what = format!("τ_max NFDIR {nfdir} x {x} r {r}");
                assert_onset(&steps, tau_max, r, &what);
                assert_steady(&steps, expected, &what);
            }
            let c = next_call(&props, nfdir, 30, v, 0.2 * GAMMA_CRIT);
            check_tangents(&c, &format!("τ_max NFDIR {nfdir} x {x}"));
        }
    }
}

/// docs/uinter.md, the bond's life cycle: a point sliding at the start carries the elastic
/// slip γ_crit into the bond (S = S_a), so it separates freely; a stuck point (here: after a
/// stop) carries less and bonds.
#[test]
fn a_sliding_point_separates_freely_a_stuck_one_bonds() {
    // μ_d 0.2, μ_s 0.5, S_a 3, N_a 5, K_n 1e6; closed at p = 100.
    let props = bonding_interface();
    for stop_first in [false, true] {
        let mut c = UinterCall::new(2, &props);
        c.rdisp[0] = P / 1e6;
        c.drdisp[0] = P / 1e6;
        c.dtime = 0.01;
        for _ in 0..30 {
            c.drdisp[1] = 0.2 * GAMMA_CRIT;
            c.call();
            c.drdisp[0] = 0.0;
        }
        assert_eq!(c.statev[2], 1.0);
        assert!((c.stress[1] - (0.2 * P + 3.0)).abs() < 1e-9);
        if stop_first {
            c.drdisp[1] = 0.0;
            c.call();
            assert_eq!(c.statev[2], 0.0);
        }
        // Apart by 1 µm: tension K_n·|h| = 1 < N_a.
        c.rdisp[0] = -1e-6;
        c.drdisp = [-1e-6 - P / 1e6, 0.0, 0.0];
        c.call();
        assert_eq!(c.pnewdt, 1e36);
        if stop_first {
            // γ̄^el = τ̄·γ_crit/τ_s(p̄) with τ_s = 53: S = S_a·23/53, (23·3/53/3)² + 0.04 < 1.
            assert_eq!(c.statev[2], 3.0);
            assert!(
                (c.stress[1] - 3.0 * 23.0 / 53.0).abs() < 1e-9,
                "{:?}",
                c.stress
            );
            assert!((c.stress[0] + 1.0).abs() < 1e-9);
        } else {
            assert_eq!(c.statev[2], 4.0);
            assert_eq!(c.stress[..2], [0.0, 0.0]);
        }
    }
}

/// The earlier formulation's several-root case, τ_max between A·r and A (r = μ_k/μ_s < 1,
/// A = μ_s·p): the strength is capped at τ_max up to the slip s* where A·φ(s*/Δt) = τ_max,
/// φ(v) = r + (1 − r)·e^(−d_c·v), and the return map takes the smallest root of
/// F(s) = k_s·(G − s) − min(τ_max, A·φ(s/Δt)). With d_c/Δt = 15 (not 1, so s* depends on which
/// of d_c and Δt divides): one trial slip G whose root is on the cap (G − τ_max/k_s ≤ s*) and
/// one whose root lies past s*, each against the smallest root found here by a scan and
/// bisection of F, with k_s measured from a sticking increment.
#[test]
fn the_earlier_formulation_takes_the_smallest_root_under_a_cap() {
    let (mu_k, d_c, dtime, tau_max) = (0.25, 3.0, 0.2, 40.0);
    let law = earlier_formulation(mu_k, d_c, Some(tau_max));
    let from_rest = |g: f64| {
        let inc = Increment::<1> {
            tau: [0.0],
            dgam: [g],
            pressure: P,
            dpressure: 0.0,
            dtime,
            characteristic_length: 1.0,
            ..Increment::default()
        };
        let up = law
            .update(&inc, &Conditions::default(), &ExtendedState::<1>::default())
            .unwrap();
        let interfacial::laws::contact::Contact::Motion(t) = up.contact else {
            panic!("no exact stick here")
        };
        t.tau[0]
    };
    let (a, r) = (MU_S * P, mu_k / MU_S);
    assert!(a * r < tau_max && tau_max < a, "the several-root case");
    let k_s = from_rest(1e-6) / 1e-6;
    let strength = |s: f64| tau_max.min(a * (r + (1.0 - r) * (-d_c * s / dtime).exp()));
    let s_star = -((tau_max / a - r) / (1.0 - r)).ln() * dtime / d_c;
    for (g, on_cap) in [(0.02, true), (0.1, false)] {
        let f = |s: f64| k_s * (g - s) - strength(s);
        // The first sign change of F on a fine grid, then bisection.
        let n = 200_000;
        let h = g / n as f64;
        let i = (1..=n).find(|&i| f(i as f64 * h) <= 0.0).unwrap();
        let (mut lo, mut hi) = ((i - 1) as f64 * h, i as f64 * h);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 { lo = mid } else { hi = mid }
        }
        let s = 0.5 * (lo + hi);
        assert_eq!(s <= s_star, on_cap, "G = {g}: s = {s}, s* = {s_star}");
        let want = strength(s);
        let got = from_rest(g);
        assert!(
            (got - want).abs() <= 1e-9 * want,
            "G = {g}: τ = {got}, smallest root {want}"
        );
    }
}
