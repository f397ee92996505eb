//! Closed-form checks: the friction, thermal and adhesive scenes of `docs/scene-definitions.md`
//! driven increment by increment through `fric_`, `gapcon_` and `uinter_` (the entry points a
//! Fortran host calls), one row per checked quantity, each compared with its closed-form answer.

use interfacial::abi::{IflConductance, IflStatus, ifl_gap_conductance};
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::{FricCall, GapconCall, UinterCall};

const MU: f64 = 0.3;
const P: f64 = 100.0;
const GAMMA_CRIT: f64 = 1e-3;
const TAU_MAX: f64 = 20.0;

/// One checked quantity.
pub struct Row {
    /// Scene id.
    pub scene: &'static str,
    /// Variant of the scene.
    pub case: String,
    /// What is compared.
    pub quantity: &'static str,
    /// Closed-form value.
    pub exact: f64,
    /// Computed value.
    pub computed: f64,
    /// Allowed |computed − exact|.
    pub tolerance: f64,
}

impl Row {
    /// |computed − exact|.
    pub fn error(&self) -> f64 {
        (self.computed - self.exact).abs()
    }
    /// Within tolerance.
    pub fn ok(&self) -> bool {
        self.error() <= self.tolerance
    }
}

/// The rows out of tolerance, one line each (scene, case, quantity, computed against the closed
/// form, tolerance): what tests/scenes_checks.rs and the other scene tests print when they fail.
#[allow(dead_code)]
pub fn failures(rows: &[Row]) -> Vec<String> {
    rows.iter()
        .filter(|r| !r.ok())
        .map(|r| {
            format!(
                "{} {} {}: {:e} against {:e} (tolerance {:e})",
                r.scene, r.case, r.quantity, r.computed, r.exact, r.tolerance
            )
        })
        .collect()
}

/// PROPS for the Coulomb law: γ_crit absolute or from the default tolerance × CHRLNGTH.
fn props(gamma_from_chrlngth: bool, tau_max: f64, stick: f64) -> Vec<f64> {
    let gc = if gamma_from_chrlngth { 0.0 } else { GAMMA_CRIT };
    CoulombBuilder::new()
        .mu(MU)
        .tau_max(tau_max)
        .gamma_crit(gc)
        .stick(stick)
        .build_first(7)
}

/// A quasi-static host increment: pass the converged stress and state, the motion and pressure
/// increments, take the answer as converged (FRIC is explicit in the imposed motion here).
fn step(c: &mut FricCall, dgam: &[f64], p_end: f64, p_start: f64) {
    c.dgam[..dgam.len()].copy_from_slice(dgam);
    c.press = p_end;
    c.dpress = p_end - p_start;
    c.pnewdt = 1e36;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
}

/// One increment of slip `dgam` along the first direction over `dtime` through `fric_`; a
/// cut-back is an error naming the scene and the library's message (R1, R2, F7).
pub fn slide(c: &mut FricCall, dgam: f64, dtime: f64, scene: &str) -> Result<(), String> {
    c.dgam[0] = dgam;
    c.dtime = dtime;
    c.pnewdt = 1e36;
    c.call();
    if c.pnewdt < 1.0 {
        return Err(format!(
            "{scene}: fric_ refused: {}",
            FricCall::last_error()
        ));
    }
    Ok(())
}

/// F1: pull to plateau and back, NFDIR 1 and 2, γ_crit from PROPS(5) or CHRLNGTH, with and
/// without τ_max.
fn f1(rows: &mut Vec<Row>) {
    for nfdir in [1usize, 2] {
        for from_chrlngth in [false, true] {
            for tau_max in [0.0, TAU_MAX] {
                let mut c = FricCall::new(nfdir as i32, &props(from_chrlngth, tau_max, 0.0));
                // 0.005 × 0.2 = 1e-3: the same γ_crit either way.
                c.chrlngth = 0.2;
                let dir: Vec<f64> = if nfdir == 1 {
                    vec![1.0]
                } else {
                    vec![30f64.to_radians().cos(), 30f64.to_radians().sin()]
                };
                let tau_c = if tau_max > 0.0 {
                    (MU * P).min(tau_max)
                } else {
                    MU * P
                };
                let ks = tau_c / GAMMA_CRIT;
                let per_gc = 10;
                let ds = GAMMA_CRIT / f64::from(per_gc);
                // Path: s = 0 → 20γc (loading), 20γc → −20γc (unloading, reversed plateau).
                let mut s = 0.0f64;
                let mut max_err = 0.0f64;
                let mut sfd_sum = 0.0;
                let mut sfd_min = f64::INFINITY;
                for k in 0..(60 * per_gc) {
                    let sign = if k < 20 * per_gc { 1.0 } else { -1.0 };
                    s += sign * ds;
                    let dg: Vec<f64> = dir.iter().map(|d| d * sign * ds).collect();
                    step(&mut c, &dg, P, P);
                    // Closed form along the path (elastic-perfectly-plastic in s).
                    let exact = if k < 20 * per_gc {
                        (ks * s).min(tau_c)
                    } else {
                        (tau_c - ks * (20.0 * GAMMA_CRIT - s)).max(-tau_c)
                    };
                    let along: f64 = (0..nfdir).map(|i| c.tau[i] * dir[i]).sum();
                    max_err = max_err.max((along - exact).abs());
                    sfd_sum += c.sfd;
                    sfd_min = sfd_min.min(c.sfd);
                }
                let case = format!(
                    "NFDIR={nfdir} γc from {}{}",
                    if from_chrlngth {
                        "CHRLNGTH"
                    } else {
                        "PROPS(5)"
                    },
                    if tau_max > 0.0 { ", τ_max" } else { "" }
                );
                let tol = 1e-9 * tau_c;
                rows.push(Row {
                    scene: "F1",
                    case: case.clone(),
                    quantity: "max |τ − τ_exact| on path",
                    exact: 0.0,
                    computed: max_err,
                    tolerance: tol,
                });
                let plateau: f64 = (0..nfdir).map(|i| c.tau[i] * c.tau[i]).sum::<f64>().sqrt();
                rows.push(Row {
                    scene: "F1",
                    case: case.clone(),
                    quantity: "plateau |τ| = min(μp, τ_max)",
                    exact: tau_c,
                    computed: plateau,
                    tolerance: tol,
                });
                // Slip 19γc on loading, 38γc on unloading, all at |τ| = τ_crit.
                rows.push(Row {
                    scene: "F1",
                    case: case.clone(),
                    quantity: "Σ SFD = 57·τ_crit·γ_crit",
                    exact: 57.0 * tau_c * GAMMA_CRIT,
                    computed: sfd_sum,
                    tolerance: 1e-9 * 57.0 * tau_c * GAMMA_CRIT,
                });
                rows.push(Row {
                    scene: "F1",
                    case: case.clone(),
                    quantity: "SED = τ²/(2k_s) at the end",
                    exact: tau_c * tau_c / (2.0 * ks),
                    computed: c.sed,
                    tolerance: 1e-9 * tau_c * GAMMA_CRIT,
                });
                rows.push(Row {
                    scene: "F1",
                    case,
                    quantity: "min SFD over increments (≥ 0)",
                    exact: 0.0,
                    computed: sfd_min.min(0.0),
                    tolerance: 0.0,
                });
            }
        }
    }
}

/// F1 with exact stick: a spring K pulls the slider, its far end driven by u(t). The host
/// enforces stick with a Lagrange multiplier (TAULM = spring force) and solves equilibrium
/// K(u − γ) = τ while slipping.
fn f1_exact(rows: &mut Vec<Row>) {
    let k_spring = 1e4;
    let tau_c = MU * P;
    let mut c = FricCall::new(1, &props(false, 0.0, 1.0));
    c.lm = 1;
    let (mut gamma, mut tau) = (0.0f64, 0.0f64);
    let du = 1e-4;
    let mut u = 0.0f64;
    let mut max_err = 0.0f64;
    let mut first_slip_u = f64::NAN;
    let mut u_peak = 0.0f64;
    for k in 0..400 {
        let sign = if k < 100 { 1.0 } else { -1.0 };
        u += sign * du;
        // Newton iterations of the host, LM from the previous iteration.
        let tau_start = tau;
        let mut lm = c.lm;
        let mut dg = 0.0f64;
        for _ in 0..10 {
            c.lm = lm;
            c.tau[0] = tau_start;
            c.taulm[0] = k_spring * (u - gamma);
            step(&mut c, &[if lm == 1 { 0.0 } else { dg }], P, P);
            if c.lm == 1 {
                if lm == 1 {
                    dg = 0.0;
                    tau = k_spring * (u - gamma);
                    break;
                }
                lm = 1;
                dg = 0.0;
                continue;
            }
            let r = k_spring * (u - gamma - dg) - c.tau[0];
            if lm == 0 && r.abs() <= 1e-12 * tau_c {
                tau = c.tau[0];
                break;
            }
            lm = 0;
            dg += r / (k_spring + c.ddtddg[0]);
        }
        gamma += dg;
        c.lm = lm;
        if first_slip_u.is_nan() && dg != 0.0 {
            first_slip_u = u;
        }
        // Closed form: stuck until |K(u − γ)| reaches τ_crit, then γ follows at that force.
        if sign > 0.0 {
            u_peak = u;
        }
        let g_peak = (u_peak - tau_c / k_spring).max(0.0);
        let exact = if sign > 0.0 {
            (u - tau_c / k_spring).max(0.0)
        } else {
            g_peak.min(u + tau_c / k_spring)
        };
        max_err = max_err.max((gamma - exact).abs());
    }
    rows.push(Row {
        scene: "F1",
        case: "exact stick (LM=1), spring host".into(),
        quantity: "max |γ − γ_exact| on path",
        exact: 0.0,
        computed: max_err,
        tolerance: 1e-12,
    });
    rows.push(Row {
        scene: "F1",
        case: "exact stick (LM=1), spring host".into(),
        quantity: "first slip at u = μp/K (tol Δu)",
        exact: tau_c / k_spring,
        computed: first_slip_u,
        // The first increment whose spring force exceeds τ_crit: within one Δu (plus round-off).
        tolerance: du * (1.0 + 1e-9),
    });
}

/// F2: slip along a circle of radius R; steady lag angle asin(γ_crit/R) between τ and the slip
/// direction, backward Euler converging at first order in the step.
fn f2(rows: &mut Vec<Row>) {
    let radius = 0.01;
    let exact = (GAMMA_CRIT / radius).asin();
    for n in [100usize, 1000, 5000] {
        let mut c = FricCall::new(2, &props(false, 0.0, 0.0));
        let dtheta = 2.0 * std::f64::consts::PI / n as f64;
        let mut prev = [radius, 0.0];
        let mut theta = 0.0f64;
        c.press = P;
        // Start on the circle with no stress; three turns reach the steady state.
        for k in 1..=(3 * n) {
            theta = dtheta * k as f64;
            let now = [radius * theta.cos(), radius * theta.sin()];
            step(&mut c, &[now[0] - prev[0], now[1] - prev[1]], P, P);
            prev = now;
        }
        let tangent = [-theta.sin(), theta.cos()];
        let cross = tangent[0] * c.tau[1] - tangent[1] * c.tau[0];
        let dot = tangent[0] * c.tau[0] + tangent[1] * c.tau[1];
        let lag = cross.atan2(dot).abs();
        rows.push(Row {
            scene: "F2",
            case: format!("circle, {n} increments/turn"),
            quantity: "lag angle φ → asin(γc/R) (tol Δθ)",
            exact,
            computed: lag,
            tolerance: dtheta,
        });
        let mag = (c.tau[0].powi(2) + c.tau[1].powi(2)).sqrt();
        rows.push(Row {
            scene: "F2",
            case: format!("circle, {n} increments/turn"),
            quantity: "|τ| = μp",
            exact: MU * P,
            computed: mag,
            tolerance: 1e-12 * MU * P,
        });
    }
}

/// F5: pressure ramp while sliding: τ = min(μp(t), τ_max) and DDTDDP = d(min(μp, τ_max))/dp.
fn f5(rows: &mut Vec<Row>) {
    for tau_max in [0.0, 35.0] {
        let mut c = FricCall::new(1, &props(false, tau_max, 0.0));
        let pressure = |t: f64| 100.0 + 50.0 * (3.0 * t).sin();
        let crit = |p: f64| {
            if tau_max > 0.0 {
                (MU * p).min(tau_max)
            } else {
                MU * p
            }
        };
        let dcrit = |p: f64| {
            if tau_max > 0.0 && MU * p >= tau_max {
                0.0
            } else {
                MU
            }
        };
        let (mut max_err, mut max_derr) = (0.0f64, 0.0f64);
        let steps = 400;
        let mut p_prev = pressure(0.0);
        // Slide at 0.2 γ_crit per increment from first contact.
        for k in 1..=steps {
            let t = k as f64 / steps as f64;
            let p = pressure(t);
            step(&mut c, &[0.2 * GAMMA_CRIT], p, p_prev);
            p_prev = p;
            if k > 10 {
                max_err = max_err.max((c.tau[0] - crit(p)).abs());
                max_derr = max_derr.max((c.ddtddp[0] - dcrit(p)).abs());
            }
        }
        let case = if tau_max > 0.0 {
            "p(t) ramp, τ_max = 35"
        } else {
            "p(t) ramp"
        };
        rows.push(Row {
            scene: "F5",
            case: case.into(),
            quantity: "max |τ − min(μp, τ_max)| sliding",
            exact: 0.0,
            computed: max_err,
            tolerance: 1e-12 * 50.0,
        });
        rows.push(Row {
            scene: "F5",
            case: case.into(),
            quantity: "max |DDTDDP − d τ_crit/dp|",
            exact: 0.0,
            computed: max_derr,
            tolerance: 1e-15,
        });
    }
}

/// F3: the friction ellipse (μ₁ = 0.5, μ₂ = 0.2 in PROPS(3)), steady slip along twelve
/// directions d: τ on (τ₁/μ₁)² + (τ₂/μ₂)² = p², parallel to (μ₁²d₁, μ₂²d₂).
fn f3(rows: &mut Vec<Row>) {
    let (mu1, mu2) = (0.5, 0.2);
    let props = CoulombBuilder::new()
        .mu(mu1)
        .mu2(mu2)
        .gamma_crit(GAMMA_CRIT)
        .build_first(5);
    let (mut ellipse_err, mut angle_err) = (0.0f64, 0.0f64);
    for k in 0..12 {
        let angle = f64::from(k) * std::f64::consts::PI / 6.0 + 0.1;
        let d = [angle.cos(), angle.sin()];
        let mut c = FricCall::new(2, &props);
        let mut p_prev = 0.0;
        for _ in 0..60 {
            step(
                &mut c,
                &[0.3 * GAMMA_CRIT * d[0], 0.3 * GAMMA_CRIT * d[1]],
                P,
                p_prev,
            );
            p_prev = P;
        }
        let (t1, t2) = (c.tau[0], c.tau[1]);
        ellipse_err = ellipse_err.max(((t1 / mu1).hypot(t2 / mu2) - P).abs());
        let w = [mu1 * mu1 * d[0], mu2 * mu2 * d[1]];
        angle_err = angle_err.max((t2.atan2(t1) - w[1].atan2(w[0])).abs());
    }
    rows.push(Row {
        scene: "F3",
        case: "μ₁ = 0.5, μ₂ = 0.2, 12 slip directions".into(),
        quantity: "max |sqrt((τ₁/μ₁)²+(τ₂/μ₂)²) − p|",
        exact: 0.0,
        computed: ellipse_err,
        tolerance: 1e-12 * P,
    });
    rows.push(Row {
        scene: "F3",
        case: "μ₁ = 0.5, μ₂ = 0.2, 12 slip directions".into(),
        quantity: "max angle(τ) − angle(μ_i² d_i)",
        exact: 0.0,
        computed: angle_err,
        tolerance: 1e-12,
    });
}

/// F4: velocity steps with the exponential decay law μ(v) = μ_k + (μ_s − μ_k)·exp(−d_c v)
/// (PROPS(8..10)), once steady τ = μ(v)·p; μ at the end-of-increment rate and frozen.
fn f4(rows: &mut Vec<Row>) {
    let (mu_s, mu_k, dc, dt) = (0.6, 0.3, 4.0, 0.01);
    for frozen in [false, true] {
        let props = CoulombBuilder::new()
            .mu(mu_s)
            .gamma_crit(GAMMA_CRIT)
            .mu_law(1.0)
            .mu_k(mu_k)
            .decay(dc)
            .frozen(if frozen { 1.0 } else { 0.0 })
            .build();
        let mut c = FricCall::new(1, &props);
        c.dtime = dt;
        let mut p_prev = 0.0;
        for v in [0.05, 0.5, 0.2, 1.5] {
            for _ in 0..40 {
                step(&mut c, &[v * dt], P, p_prev);
                p_prev = P;
            }
            let exact = (mu_k + (mu_s - mu_k) * (-dc * v).exp()) * P;
            rows.push(Row {
                scene: "F4",
                case: format!("decay, v = {v}{}", if frozen { ", μ frozen" } else { "" }),
                quantity: "steady τ = μ(v)·p",
                exact,
                computed: c.tau[0],
                tolerance: 1e-12 * exact,
            });
        }
    }
}

/// T2's plates: emissivities of the two facing surfaces, gap, gas, plate thicknesses and
/// conductivities (SI, °C).
const T2_EPS: [f64; 2] = [0.6, 0.7];
const T2_GAP: f64 = 1e-3;
const T2_K_GAS: f64 = 0.026;
const T2_G0: f64 = 2e-6;
const T2_PLATES: [(f64, f64); 2] = [(0.01, 15.0), (0.02, 45.0)];

/// F = 1/(1/ε_A + 1/ε_B − 1): two parallel grey plates, view factor 1.
fn t2_view_factor() -> f64 {
    1.0 / (1.0 / T2_EPS[0] + 1.0 / T2_EPS[1] - 1.0)
}

/// The configuration file's text: examples/scenes/thermal.toml, then T2's radiation with the
/// view factor computed from the emissivities.
fn thermal_config() -> String {
    format!(
        "{}\n[interactions.T2PAR.radiation]\nview_factor = {:e}\n\
         stefan_boltzmann = 5.670374419e-8\nabsolute_zero = -273.15\n",
        include_str!("thermal.toml"),
        t2_view_factor()
    )
}

/// T1: two bars (L_A/k_A, L_B/k_B) between θ_H and θ_C with gap conductance h at the interface,
/// solved for the interface temperatures by Newton as a host would: AK(1) from gapcon_,
/// derivatives from ifl_gap_conductance (seed 000, 5.2.4) or, for comparison, without ∂h/∂θ̄.
fn t1(rows: &mut Vec<Row>) {
    let (la, ka, lb, kb, th, tc) = (0.1, 50.0, 0.2, 15.0, 400.0, 300.0);
    let (ga, gb) = (ka / la, kb / lb);
    let p = 50.0;
    let solve = |name: &str, seed_derivative: bool| -> (f64, f64, usize) {
        let (mut a, mut b) = (th, tc);
        for it in 1..=60 {
            let h = GapconCall::new(name, 0.0, p, a, b).call();
            let q = h * (a - b);
            // Residuals: flux into the interface from each bar minus the gap flux.
            let r1 = ga * (th - a) - q;
            let r2 = q - gb * (b - tc);
            let c = std::ffi::CString::new(name).unwrap_or_default();
            let mut d = IflConductance::default();
            // SAFETY: valid name and output.
            let st = unsafe { ifl_gap_conductance(c.as_ptr(), 0.0, p, a, b, &mut d) };
            assert_eq!(st, IflStatus::Ok);
            let (qa, qb) = if seed_derivative {
                (d.dq_dtheta_a, d.dq_dtheta_b)
            } else {
                (h, -h)
            };
            // J = ∂(r1, r2)/∂(a, b).
            let (j11, j12, j21, j22) = (-ga - qa, -qb, qa, qb - gb);
            let det = j11 * j22 - j12 * j21;
            let da = -(r1 * j22 - j12 * r2) / det;
            let db = -(j11 * r2 - r1 * j21) / det;
            a += da;
            b += db;
            if da.abs().max(db.abs()) < 1e-12 * th {
                return (a, b, it);
            }
        }
        (a, b, 60)
    };
    // Constant h: q = (θ_H − θ_C)/(L_A/k_A + 1/h + L_B/k_B).
    let (a, b, _) = solve("T1CONST", true);
    let q = 2000.0 * (a - b);
    rows.push(Row {
        scene: "T1",
        case: "two bars, constant h".into(),
        quantity: "flux q",
        exact: (th - tc) / (1.0 / ga + 1.0 / 2000.0 + 1.0 / gb),
        computed: q,
        tolerance: 1e-9 * q.abs(),
    });
    // Temperature-dependent table: the same formula with h* = h(p, θ̄*) at the converged θ̄*,
    // interpolated here by hand (bilinear in p and θ̄).
    for seed in [true, false] {
        let (a, b, iterations) = solve("T1TEMP", seed);
        let tm = 0.5 * (a + b);
        let w = ((tm - 300.0) / 100.0).clamp(0.0, 1.0);
        let h_star = (1.0 - w) * (20.0 + 0.4 * p) + w * (60.0 + 1.4 * p);
        let q = GapconCall::new("T1TEMP", 0.0, p, a, b).call() * (a - b);
        rows.push(Row {
            scene: "T1",
            case: format!(
                "h(p, θ̄) table, Newton {} ({iterations} it.)",
                if seed {
                    "with ∂h/∂θ̄"
                } else {
                    "without ∂h/∂θ̄"
                }
            ),
            quantity: "flux q",
            exact: (th - tc) / (1.0 / ga + 1.0 / h_star + 1.0 / gb),
            computed: q,
            tolerance: 1e-8 * q.abs(),
        });
    }
}

/// T2: radiating gap between plates at fixed temperatures (°C):
/// q = Fσ((θ_A − θ_Z)⁴ − (θ_B − θ_Z)⁴).
fn t2(rows: &mut Vec<Row>) {
    for (ta, tb) in [(500.0, 100.0), (20.0, 900.0), (250.0, 250.0 + 1e-3)] {
        let k = GapconCall::new("RADC", 1e-3, 0.0, ta, tb).call();
        let (a, b) = (ta + 273.15f64, tb + 273.15f64);
        let exact = 0.8 * 5.670374419e-8 * (a.powi(4) - b.powi(4));
        rows.push(Row {
            scene: "T2",
            case: format!("radiation, θ_A = {ta}, θ_B = {tb} °C"),
            quantity: "flux q",
            exact,
            computed: k * (ta - tb),
            // a⁴ − b⁴ loses digits when a ≈ b: allow round-off relative to a⁴.
            tolerance: 1e-12 * 0.8 * 5.670374419e-8 * a.powi(4).max(b.powi(4)),
        });
    }
}

/// T2, steady two-plate problem: plate A (L_A, k_A) held at θ_H on its outer face, plate B
/// (L_B, k_B) at θ_C, an open gap d between them carrying gas conduction k_gas/(d + g₀) and
/// grey-body radiation F·σ·((θ_A − θ_Z)⁴ − (θ_B − θ_Z)⁴) in parallel (one interaction with both
/// laws; their conductances add). Closed form: for interface temperatures θ_A*, θ_B* the flux is
/// q* = k_gas/(d + g₀)·(θ_A* − θ_B*) + F·σ·(a⁴ − b⁴), and the outer temperatures that hold it are
/// θ_H = θ_A* + q*·L_A/k_A, θ_C = θ_B* − q*·L_B/k_B. The host is given θ_H and θ_C only and solves
/// for the interface temperatures by Newton with AK(1) from gapcon_ and ∂q/∂θ from
/// ifl_gap_conductance, as T1 does; rows: q, θ_A, θ_B, and the radiative share of q.
fn t2_plates(rows: &mut Vec<Row>) {
    let sigma = 5.670374419e-8;
    let f = t2_view_factor();
    let h_gas = T2_K_GAS / (T2_GAP + T2_G0);
    let [(la, ka), (lb, kb)] = T2_PLATES;
    let (ga, gb) = (ka / la, kb / lb);
    for (ta_star, tb_star) in [(600.0, 150.0), (80.0, 20.0)] {
        let (a, b) = (ta_star + 273.15f64, tb_star + 273.15f64);
        let q_rad = f * sigma * (a.powi(4) - b.powi(4));
        let q_star = h_gas * (ta_star - tb_star) + q_rad;
        let th = ta_star + q_star / ga;
        let tc = tb_star - q_star / gb;
        // The host: Newton on the two interface balances, started from the outer temperatures.
        let (mut ta, mut tb) = (th, tc);
        let name = std::ffi::CString::new("T2PAR").unwrap_or_default();
        let mut iterations = 0;
        for it in 1..=60 {
            iterations = it;
            let k = GapconCall::new("T2PAR", T2_GAP, 0.0, ta, tb).call();
            let q = k * (ta - tb);
            let (r1, r2) = (ga * (th - ta) - q, q - gb * (tb - tc));
            let mut d = IflConductance::default();
            // SAFETY: valid name and output.
            let st = unsafe { ifl_gap_conductance(name.as_ptr(), T2_GAP, 0.0, ta, tb, &mut d) };
            assert_eq!(st, IflStatus::Ok);
            let (qa, qb) = (d.dq_dtheta_a, d.dq_dtheta_b);
            let (j11, j12, j21, j22) = (-ga - qa, -qb, qa, qb - gb);
            let det = j11 * j22 - j12 * j21;
            let da = -(r1 * j22 - j12 * r2) / det;
            let db = -(j11 * r2 - r1 * j21) / det;
            // The interface temperatures lie between the outer ones: keep the iterates there
            // (a full step from the outer temperatures can overshoot below absolute zero).
            ta = (ta + da).clamp(tc, th);
            tb = (tb + db).clamp(tc, th);
            if da.abs().max(db.abs()) < 1e-13 * th.abs().max(1.0) {
                break;
            }
        }
        let k = GapconCall::new("T2PAR", T2_GAP, 0.0, ta, tb).call();
        let q = k * (ta - tb);
        let case = format!("2 plates, gas ∥ rad., θ_H {th:.1}, θ_C {tc:.1} °C");
        rows.push(Row {
            scene: "T2",
            case: format!("{case} ({iterations} it.)"),
            quantity: "flux q",
            exact: q_star,
            computed: q,
            tolerance: 1e-10 * q_star,
        });
        for (quantity, exact, computed) in [
            ("interface θ_A", ta_star, ta),
            ("interface θ_B", tb_star, tb),
        ] {
            rows.push(Row {
                scene: "T2",
                case: case.clone(),
                quantity,
                exact,
                computed,
                tolerance: 1e-10 * (th - tc).abs(),
            });
        }
        // The radiative part of the converged flux, F·σ·(a⁴ − b⁴) at the computed θ_A, θ_B.
        let (ac, bc) = (ta + 273.15, tb + 273.15);
        rows.push(Row {
            scene: "T2",
            case,
            quantity: "radiative share of q",
            exact: q_rad / q_star,
            computed: f * sigma * (ac.powi(4) - bc.powi(4)) / q,
            tolerance: 1e-9,
        });
    }
}

/// The adhesive law of A1 (seed 004) through `uinter_`: μ_d = 0.3, μ_s = 0.5, S_a = 4, N_a = 10,
/// γ_crit = 10⁻³, K_n = 10⁴ (`PROPS` layout of docs/props.md, law 2).
fn a1_props() -> Vec<f64> {
    AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(0.5)
        .sa(4.0)
        .na(10.0)
        .gamma_crit(1e-3)
        .normal_stiffness(1e4)
        .build_first(10)
}

/// One quasi-static `uinter_` increment (NDIR = 3) to the normal position `h` (overclosure,
/// positive in contact) with the tangential motion `dg` along direction 2.
fn a1_step(u: &mut UinterCall, h: f64, dg: f64) {
    u.rdisp[0] = h;
    u.drdisp = [0.0, 0.0, dg];
    u.pnewdt = 1e36;
    u.call();
    assert_eq!(u.pnewdt, 1e36, "{}", FricCall::last_error());
}

/// A1 adhesive pull-off through `uinter_`: bonded with a held shear S₀, pulled apart in steps
/// until the bond breaks at N = N_a·sqrt(1 − (S₀/S_a)²) (located as a host would: coarse steps,
/// then a cut back to the last bonded state and fine steps), the energy the bond held released
/// as SPD, re-bonding on re-contact with the full strength; and, closed, the onset of sliding at
/// μ_s·p + S_a.
fn a1(rows: &mut Vec<Row>) {
    let (s_a, n_a, k_n, gc, mu_s): (f64, f64, f64, f64, f64) = (4.0, 10.0, 1e4, 1e-3, 0.5);
    let s0: f64 = 3.0;
    let k_s = s_a / gc;
    let n_break = n_a * (1.0 - (s0 / s_a) * (s0 / s_a)).sqrt();
    let mut u = UinterCall::new(3, &a1_props());
    // Touching (p = 0) and sheared by S₀ along direction 2: bonded, k_s = S_a/γ_crit.
    a1_step(&mut u, 0.0, s0 / k_s);
    rows.push(Row {
        scene: "A1",
        case: "bonded at p = 0, shear held".into(),
        quantity: "shear stress S₀",
        exact: s0,
        computed: u.stress[2],
        tolerance: 1e-12 * s0,
    });
    // Pull: coarse steps of 10⁻² in N, then back to the last bonded state and steps of 10⁻⁵.
    let mut last_bonded = u.clone();
    let mut n_last = 0.0;
    for (start, step) in [(0.0, 1e-2), (f64::NAN, 1e-5)] {
        let from = if start.is_nan() { n_last } else { start };
        u = last_bonded.clone();
        for k in 1..=2000 {
            let n = from + step * f64::from(k);
            a1_step(&mut u, -n / k_n, 0.0);
            if u.lopenclose != 1 {
                break;
            }
            last_bonded = u.clone();
            n_last = n;
        }
    }
    rows.push(Row {
        scene: "A1",
        case: format!("pull-off with S₀ = {s0}, steps 10⁻⁵"),
        quantity: "tension at the last bonded step",
        exact: n_break,
        computed: n_last,
        tolerance: 1e-5,
    });
    rows.push(Row {
        scene: "A1",
        case: "broken bond".into(),
        quantity: "SPD = ½S₀²/k_s + ½N²/K_n",
        exact: 0.5 * s0 * s0 / k_s + 0.5 * n_last * n_last / k_n,
        computed: u.energies[2],
        tolerance: 1e-12,
    });
    // Re-contact bonds again with the full strengths: no shear now, so it holds up to N_a.
    a1_step(&mut u, 1e-4, 0.0);
    a1_step(&mut u, -0.99 * n_a / k_n, 0.0);
    rows.push(Row {
        scene: "A1",
        case: "re-bonded after re-contact, pulled to 0.99 N_a".into(),
        quantity: "normal stress −N",
        exact: -0.99 * n_a,
        computed: if u.lopenclose == 1 { u.stress[0] } else { 0.0 },
        tolerance: 1e-12 * n_a,
    });
    a1_step(&mut u, -1.01 * n_a / k_n, 0.0);
    rows.push(Row {
        scene: "A1",
        case: "re-bonded, pulled to 1.01 N_a".into(),
        quantity: "normal stress (broken: 0)",
        exact: 0.0,
        computed: u.stress[0],
        tolerance: 0.0,
    });
    // Sliding onset in contact at p = 100: shear ramped in steps of 1.23·10⁻²·γ_crit (not a
    // divisor of the onset slip, so the last stick is strictly inside one step) sticks with
    // τ = k_s·γ up to μ_s·p + S_a.
    let p = 100.0;
    let mut u = UinterCall::new(3, &a1_props());
    let step = 1.23e-2 * gc;
    let k_stick = (mu_s * p + s_a) / gc;
    let mut last_stick = 0.0;
    for _ in 0..1000 {
        a1_step(&mut u, p / k_n, step);
        if u.statev[2] != 0.0 {
            break;
        }
        last_stick = u.stress[2];
    }
    rows.push(Row {
        scene: "A1",
        case: format!("onset of sliding at p = {p}"),
        quantity: "last stick stress, μ_s·p + S_a",
        exact: mu_s * p + s_a,
        computed: last_stick,
        tolerance: k_stick * step,
    });
}

/// Runs every check (the thermal ones through a configuration file written to the temporary
/// directory and named by INTERFACIAL_CONFIG before the first `gapcon_` call).
pub fn run() -> Result<Vec<Row>, String> {
    let config =
        std::env::temp_dir().join(format!("interfacial-scenes-{}.toml", std::process::id()));
    std::fs::write(&config, thermal_config())
        .map_err(|e| format!("cannot write {}: {e}", config.display()))?;
    // SAFETY: called from main before any other thread exists and before the first call into
    // the library.
    unsafe { std::env::set_var("INTERFACIAL_CONFIG", &config) };
    let mut rows = Vec::new();
    f1(&mut rows);
    f1_exact(&mut rows);
    f2(&mut rows);
    f3(&mut rows);
    f4(&mut rows);
    f5(&mut rows);
    t1(&mut rows);
    t2(&mut rows);
    t2_plates(&mut rows);
    a1(&mut rows);
    let _ = std::fs::remove_file(&config);
    Ok(rows)
}

/// Prints the rows; returns the number of failures.
/// Prints the rows under `title` (only the failing ones unless `verbose`); returns how many
/// fail.
pub fn print(rows: &[Row], verbose: bool, title: &str) -> usize {
    let header = format!(
        "{:<5} {:<46} {:<36} {:>14} {:>14} {:>10}  ok",
        "scene", "case", "quantity", "closed form", "computed", "error"
    );
    print_table(title, &header, rows, Row::ok, verbose, |r| {
        let Row {
            scene,
            case,
            quantity,
            exact,
            computed,
            ..
        } = r;
        let (error, ok) = (r.error(), if r.ok() { "yes" } else { "NO" });
        format!(
            "{scene:<5} {case:<46} {quantity:<36} {exact:>14.8e} {computed:>14.8e} {error:>10.2e}  {ok}"
        )
    })
}

/// Prints `title`, `header`, then one `line` per item (per failing item unless `verbose`; nothing
/// when none fails); returns how many items are not `ok`.
pub fn print_table<T>(
    title: &str,
    header: &str,
    items: &[T],
    ok: impl Fn(&T) -> bool,
    verbose: bool,
    line: impl Fn(&T) -> String,
) -> usize {
    let failed = items.iter().filter(|item| !ok(item)).count();
    if !verbose && failed == 0 {
        return 0;
    }
    println!(
        "{title}{}\n\n{header}",
        if verbose { "" } else { ": the failing lines" }
    );
    for item in items.iter().filter(|item| verbose || !ok(item)) {
        println!("{}", line(item));
    }
    println!();
    failed
}
