//! Invariants over at least 10⁵ random inputs per law and mode, through the ABI as a host calls
//! it (issue 7, item 6):
//! - every output finite, and no cut-back, for finite inputs in the laws' range;
//! - |τ_eq| ≤ τ_crit(p) + round-off, with τ_crit = min(μ·max(p, 0), τ_max);
//! - SFD ≥ 0 and SED ≥ 0; STATEV(1) grows by exactly |DSLIP|;
//! - along random paths, Σ SFD equals the plastic work Σ τₙ₊₁·Δγ^sl, where the inelastic slip
//!   is computed independently of DSLIP from the additive split Δγ = Δγ^el + Δγ^sl with the
//!   elastic slip γ^el = τ/k_s(p) of each end of the increment (elastic stick), or is all of Δγ
//!   (exact stick, where nothing is elastic);
//! - the gap conductance is finite, ≥ 0 and inside the range of its table.
//!
//! The inputs come from a fixed-seed generator, so a failure names a reproducible path.

use interfacial::laws::gap_conductance::{ConductanceResponse, Conduction, GapLaw};
use interfacial::laws::gap_radiation::Radiation;
use interfacial::laws::table::TemperatureTable;
use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;

/// SplitMix64: small, fast and good enough to spread test inputs.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Log-uniform in [lo, hi], lo > 0.
    fn log_range(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp()
    }
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
}

/// One random Coulomb parameter set: (μ, τ_max or 0, γ_crit from PROPS(5) or from the slip
/// tolerance and CHRLNGTH).
struct Params {
    mu: f64,
    tau_max: f64,
    gamma_crit: f64,
    props: Vec<f64>,
    chrlngth: f64,
}

fn random_params(rng: &mut Rng, stick_mode: f64) -> Params {
    let mu = if rng.chance(0.05) {
        0.0
    } else {
        rng.range(0.01, 1.0)
    };
    let tau_max = if rng.chance(0.3) {
        rng.range(1.0, 80.0)
    } else {
        0.0
    };
    let chrlngth = rng.log_range(0.01, 10.0);
    let (gamma_crit, p5, p6) = if rng.chance(0.5) {
        let g = rng.log_range(1e-5, 1e-2);
        (g, g, 0.0)
    } else if rng.chance(0.5) {
        let tol = rng.log_range(1e-4, 0.05);
        (tol * chrlngth, 0.0, tol)
    } else {
        (0.005 * chrlngth, 0.0, 0.0)
    };
    Params {
        mu,
        tau_max,
        gamma_crit,
        props: CoulombBuilder::new()
            .mu(mu)
            .tau_max(tau_max)
            .gamma_crit(p5)
            .slip_tolerance(p6)
            .stick(stick_mode)
            .build_first(7),
        chrlngth,
    }
}

impl Params {
    fn tau_crit(&self, p: f64) -> f64 {
        let t = self.mu * p.max(0.0);
        if self.tau_max > 0.0 {
            t.min(self.tau_max)
        } else {
            t
        }
    }
    /// Elastic slip that carries τ at pressure p: τ/k_s with k_s = τ_crit/γ_crit (none when
    /// τ_crit = 0, where τ = 0 too).
    fn elastic_slip(&self, tau: &[f64], p: f64) -> Vec<f64> {
        let tc = self.tau_crit(p);
        tau.iter()
            .map(|t| {
                if tc > 0.0 {
                    t * self.gamma_crit / tc
                } else {
                    0.0
                }
            })
            .collect()
    }
}

const PATHS: usize = 5_000;
const STEPS: usize = 20;

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// Drives PATHS random paths of STEPS increments (10⁵ calls) through `fric_` and checks the
/// invariants after each call. Returns (calls, slipping calls) so the caller can check that
/// both branches were exercised.
fn drive(nfdir: usize, stick_mode: f64, seed: u64) -> (usize, usize) {
    let mut rng = Rng(seed);
    let (mut calls, mut slipping) = (0, 0);
    for path in 0..PATHS {
        let prm = random_params(&mut rng, stick_mode);
        let mut c = FricCall::new(nfdir as i32, &prm.props);
        c.chrlngth = prm.chrlngth;
        // Pressures mostly positive, sometimes negative (a point about to open).
        let mut p = rng.range(-10.0, 200.0);
        c.lm = 0;
        let (mut work, mut sfd_sum) = (0.0, 0.0);
        let mut scale_sum = 0.0;
        for step in 0..STEPS {
            let what = format!("NFDIR={nfdir} PROPS(7)={stick_mode} path {path} step {step}");
            let dp = if rng.chance(0.3) {
                0.0
            } else {
                rng.range(-20.0, 20.0)
            };
            let p_start = p;
            p += dp;
            c.press = p;
            c.dpress = dp;
            c.dtime = if rng.chance(0.1) {
                0.0
            } else {
                rng.log_range(1e-4, 10.0)
            };
            let amp = prm.gamma_crit * rng.log_range(0.01, 10.0);
            for a in 0..nfdir {
                c.dgam[a] = amp * rng.range(-1.0, 1.0);
                // The host's Lagrange stress while exactly stuck: anything near τ_crit.
                c.taulm[a] = prm.tau_crit(p) * rng.range(-1.5, 1.5);
            }
            let tau_in = c.tau[..nfdir].to_vec();
            let statev_in = c.statev[..3].to_vec();
            let lm_in = c.lm;
            c.pnewdt = 1.0;
            c.call();
            calls += 1;
            assert_eq!(
                c.pnewdt,
                1.0,
                "{what}: cut-back on valid input: {}",
                FricCall::last_error()
            );
            let lm = c.lm;
            if lm == 1 {
                // Exactly stuck: the host keeps its Lagrange stress; nothing else is ours.
                assert!(stick_mode != 0.0, "{what}: LM = 1 with elastic stick");
                assert_eq!(c.statev[0], statev_in[0], "{what}: slip while stuck");
                c.tau[..nfdir].copy_from_slice(&c.taulm[..nfdir]);
                continue;
            }
            let tau = c.tau[..nfdir].to_vec();
            let dslip = c.dslip[..nfdir].to_vec();
            let outs = tau
                .iter()
                .chain(&dslip)
                .chain(&c.ddtddp[..nfdir])
                .chain(&c.ddtddg[..nfdir * nfdir])
                .chain(&c.statev[..3])
                .chain([&c.sed, &c.sfd]);
            for v in outs {
                assert!(v.is_finite(), "{what}: non-finite output");
            }
            let tc = prm.tau_crit(p);
            assert!(
                norm(&tau) <= tc * (1.0 + 1e-12) + 1e-300,
                "{what}: |τ| = {} > τ_crit = {tc}",
                norm(&tau)
            );
            assert!(
                c.sfd >= 0.0 && c.sed >= 0.0,
                "{what}: SFD {} SED {}",
                c.sfd,
                c.sed
            );
            let slip = norm(&dslip);
            let acc = c.statev[0] - statev_in[0];
            assert!(
                (acc - slip).abs() <= 1e-12 * (statev_in[0] + slip),
                "{what}: STATEV(1) grew by {acc}, |DSLIP| = {slip}"
            );
            if slip > 0.0 {
                slipping += 1;
            }
            // The plastic work of the increment, from inputs and TAU alone.
            let dgam = &c.dgam[..nfdir];
            let inelastic: Vec<f64> = if stick_mode == 0.0 {
                let el_end = prm.elastic_slip(&tau, p);
                let el_start = prm.elastic_slip(&tau_in, p_start);
                (0..nfdir)
                    .map(|a| dgam[a] - (el_end[a] - el_start[a]))
                    .collect()
            } else {
                dgam.to_vec()
            };
            let w = dot(&tau, &inelastic);
            if stick_mode == 0.0 {
                work += w;
                sfd_sum += c.sfd;
                scale_sum += tc * (norm(dgam) + prm.gamma_crit);
                // Per increment too: the slip vector itself is that inelastic slip, wherever the
                // split is defined (τ_crit > 0 at the end; at τ_crit = 0, τ = 0 and any split
                // does no work).
                for a in (0..nfdir).filter(|_| tc > 0.0) {
                    assert!(
                        (dslip[a] - inelastic[a]).abs() <= 1e-9 * (norm(dgam) + prm.gamma_crit),
                        "{what}: DSLIP {dslip:?} vs Δγ − Δγ^el {inelastic:?}"
                    );
                }
            } else {
                // Exact stick: all motion is slip at |τ| = τ_crit, along the motion unless
                // released from the Lagrange stress; SFD is its positive part.
                assert!(
                    (c.sfd - w.max(0.0)).abs() <= 1e-12 * (tc * norm(dgam)).max(1e-300),
                    "{what}: SFD {} vs τ·Δγ {w}",
                    c.sfd
                );
                if lm_in == 0 && norm(dgam) > 0.0 {
                    assert!(
                        w >= -1e-12 * tc * norm(dgam),
                        "{what}: slip against the stress"
                    );
                }
            }
        }
        if stick_mode == 0.0 {
            assert!(
                (work - sfd_sum).abs() <= 1e-9 * scale_sum.max(1e-300),
                "path {path}: Σ SFD = {sfd_sum}, plastic work = {work}"
            );
        }
    }
    (calls, slipping)
}

/// [`drive`], then: at least `min_calls` calls, more than a tenth of them slipping.
fn drive_at_least(nfdir: usize, stick_mode: f64, seed: u64, min_calls: usize) {
    let (calls, slipping) = drive(nfdir, stick_mode, seed);
    assert!(
        calls >= min_calls && slipping > calls / 10,
        "{calls} {slipping}"
    );
}

/// One test per law mode and NFDIR (separate, so they run in parallel): `name: (NFDIR,
/// PROPS(7), seed, at least this many calls)`.
macro_rules! drive_tests {
    ($($name:ident: ($nfdir:expr, $stick:expr, $seed:expr, $min:expr);)*) => {
        $(
            #[test]
            fn $name() {
                drive_at_least($nfdir, $stick, $seed, $min);
            }
        )*
    };
}

drive_tests! {
    elastic_stick_nfdir_1: (1, 0.0, 1, 100_000);
    elastic_stick_nfdir_2: (2, 0.0, 2, 100_000);
    exact_stick_nfdir_1: (1, 1.0, 3, 50_000);
    exact_stick_nfdir_2: (2, 1.0, 4, 50_000);
}

#[test]
fn rough_is_always_stuck() {
    let mut rng = Rng(5);
    for i in 0..100_000i32 {
        let nfdir = 1 + (i % 2);
        let prm = random_params(&mut rng, 2.0);
        let mut c = FricCall::new(nfdir, &prm.props);
        c.chrlngth = prm.chrlngth;
        c.press = rng.range(-10.0, 200.0);
        c.dpress = rng.range(-20.0, 20.0);
        c.dgam[0] = rng.range(-1.0, 1.0);
        c.lm = i % 2;
        c.pnewdt = 1.0;
        c.call();
        assert_eq!((c.lm, c.pnewdt), (1, 1.0), "call {i}");
    }
}

/// A random table of `rows` rows in x (strictly increasing), optionally at 1–3 temperatures.
fn random_table(rng: &mut Rng) -> (TemperatureTable, f64, f64) {
    let rows = 1 + (rng.next_u64() % 8) as usize;
    let temps = if rng.chance(0.5) {
        1
    } else {
        1 + (rng.next_u64() % 3) as usize
    };
    let mut data = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    let mut theta = rng.range(-50.0, 100.0);
    for _ in 0..temps {
        let mut x = rng.range(-20.0, 20.0);
        for _ in 0..rows {
            let k = if rng.chance(0.1) {
                0.0
            } else {
                rng.log_range(1e-3, 1e4)
            };
            lo = lo.min(k);
            hi = hi.max(k);
            data.push((x, k, theta));
            x += rng.log_range(1e-3, 50.0);
        }
        theta += rng.log_range(0.1, 200.0);
    }
    let table = if temps == 1 {
        let rows: Vec<(f64, f64)> = data.iter().map(|r| (r.0, r.1)).collect();
        TemperatureTable::constant_in_temperature(
            interfacial::laws::table::Table1::new(&rows).expect("valid rows"),
        )
    } else {
        TemperatureTable::new(&data).expect("valid rows")
    };
    (table, lo, hi)
}

#[test]
fn gap_conductance_is_finite_non_negative_and_inside_its_table() {
    let mut rng = Rng(6);
    let mut calls = 0;
    for law in 0..2_000 {
        let (table, lo, hi) = random_table(&mut rng);
        let by_pressure = rng.chance(0.5);
        let conduction = if by_pressure {
            Conduction::pressure_table(table)
        } else {
            Conduction::clearance_table(table)
        }
        .expect("valid table");
        let gap = GapLaw::new(Some(conduction), None).expect("one part");
        for _ in 0..50 {
            let (d, p) = (rng.range(-50.0, 600.0), rng.range(-50.0, 600.0));
            let (ta, tb) = (rng.range(-100.0, 800.0), rng.range(-100.0, 800.0));
            let r = gap.evaluate(d, p, ta, tb).expect("finite input");
            calls += 1;
            let all = outputs(&r);
            assert!(all.iter().all(|v| v.is_finite()), "law {law}: {r:?}");
            assert!(
                r.k >= lo * (1.0 - 1e-12) && r.k <= hi * (1.0 + 1e-12),
                "law {law}: k = {} outside [{lo}, {hi}]",
                r.k
            );
        }
    }
    assert!(calls >= 100_000);
}

#[test]
fn analytic_gap_laws_and_radiation_are_finite_and_non_negative() {
    let mut rng = Rng(7);
    for i in 0..100_000 {
        // The solid-spot correlation's hardness H_c (its last parameter): P/H_c > 1 is refused
        // (docs/config.md), so those cases must come back as a refusal, not a number.
        let hardness = rng.log_range(1e8, 1e10);
        let conduction = match i % 3 {
            0 => Conduction::constant(rng.log_range(1e-3, 1e5)),
            1 => Conduction::gas_gap(
                rng.log_range(1e-3, 10.0),
                rng.range(0.0, 1e-3),
                rng.log_range(1e-9, 1e-3),
            ),
            _ => Conduction::solid_spot(
                rng.range(0.5, 2.0),
                rng.log_range(1.0, 400.0),
                rng.range(0.01, 0.5),
                rng.log_range(1e-7, 1e-4),
                hardness,
            ),
        }
        .expect("valid parameters");
        let zero = if rng.chance(0.5) { 0.0 } else { -273.15 };
        let radiation = rng
            .chance(0.5)
            .then(|| Radiation::new(rng.range(0.0, 1.0), 5.670374419e-8, zero).expect("valid"));
        let gap = GapLaw::new(Some(conduction), radiation).expect("one part");
        let (d, p) = (rng.range(-1e-3, 1e-2), rng.range(-1e6, 1e9));
        let (ta, tb) = (zero + rng.range(0.0, 2000.0), zero + rng.range(0.0, 2000.0));
        let over_hardness = i % 3 == 2 && p > hardness;
        let r = match gap.evaluate(d, p, ta, tb) {
            Ok(r) => {
                assert!(
                    !over_hardness,
                    "case {i}: P/H_c = {} > 1 answered",
                    p / hardness
                );
                r
            }
            Err(e) if over_hardness => {
                assert!(e.to_string().contains("H_c"), "case {i}: {e}");
                continue;
            }
            Err(e) => panic!("case {i}: finite input refused: {e}"),
        };
        let all = outputs(&r);
        assert!(
            all.iter().all(|v| v.is_finite()) && r.k >= 0.0,
            "case {i}: {r:?}"
        );
    }
}

/// Every output of a gap law: k and its partial derivatives.
fn outputs(r: &ConductanceResponse) -> [f64; 6] {
    [
        r.k,
        r.dk_dd,
        r.dk_dp,
        r.dk_dtheta_mean,
        r.dq_dtheta_a,
        r.dq_dtheta_b,
    ]
}
