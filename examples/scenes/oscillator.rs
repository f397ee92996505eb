//! F6, the stick-slip oscillator (`docs/scene-definitions.md`): a block of mass m on a belt moving
//! at v₀, a spring k to a wall, normal force N, static μ_s and kinetic μ_k. The friction force
//! comes from `fric_` (unit contact area, so τ is a force and PRESS = N); the host integrates
//! m·ẍ = −k·x + τ with the relative slip γ = v₀·t − x (belt minus block).
//!
//! Static and kinetic friction with the single-μ Coulomb law: the host passes μ_s while the point
//! stuck in the last converged increment and μ_k while it slipped (STATEV(3) = 1), i.e. μ frozen
//! at the start of the increment. γ_crit is scaled with μ (γ_crit·μ/μ_s) so that the stick
//! stiffness K_f = μ_s·N/γ_crit does not jump when μ does.

use std::time::Instant;

use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use serde::Deserialize;

use crate::scene::Bound::Positive;
use crate::scene::check_bounds;

/// The physical parameters of F6.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Oscillator {
    /// Block mass m.
    pub mass: f64,
    /// Spring stiffness k.
    pub spring: f64,
    /// Normal force N.
    pub normal_force: f64,
    /// Static friction coefficient μ_s.
    pub mu_static: f64,
    /// Kinetic friction coefficient μ_k < μ_s.
    pub mu_kinetic: f64,
    /// Belt speed v₀ > 0.
    pub belt_speed: f64,
    /// Stick-slip cycles simulated after the first slip.
    pub cycles: u32,
}

impl Oscillator {
    /// ω = sqrt(k/m).
    pub fn omega(&self) -> f64 {
        (self.spring / self.mass).sqrt()
    }
    /// A = (μ_s − μ_k)·N/k.
    pub fn amplitude(&self) -> f64 {
        (self.mu_static - self.mu_kinetic) * self.normal_force / self.spring
    }
    /// x_k = μ_k·N/k.
    pub fn x_kinetic(&self) -> f64 {
        self.mu_kinetic * self.normal_force / self.spring
    }
    /// x₁ = μ_s·N/k, where slip starts.
    pub fn x_slip_start(&self) -> f64 {
        self.mu_static * self.normal_force / self.spring
    }
    /// φ = atan2(v₀/ω, A).
    pub fn phase(&self) -> f64 {
        (self.belt_speed / self.omega()).atan2(self.amplitude())
    }
    /// t_slip = (π + 2φ)/ω.
    pub fn t_slip(&self) -> f64 {
        (std::f64::consts::PI + 2.0 * self.phase()) / self.omega()
    }
    /// t_stick = 2A/v₀.
    pub fn t_stick(&self) -> f64 {
        2.0 * self.amplitude() / self.belt_speed
    }
    /// T = t_slip + t_stick.
    pub fn period(&self) -> f64 {
        self.t_slip() + self.t_stick()
    }
    /// x₂ = x_k − A, where slip ends.
    pub fn x_slip_end(&self) -> f64 {
        self.x_kinetic() - self.amplitude()
    }
    /// Energy dissipated per cycle: μ_k·N times the slip of a cycle, v₀·t_slip − (x₂ − x₁).
    pub fn energy_per_cycle(&self) -> f64 {
        self.mu_kinetic
            * self.normal_force
            * (self.belt_speed * self.t_slip() + self.x_slip_start() - self.x_slip_end())
    }
    /// First slip, starting stuck at x = 0: t₀ = x₁/v₀.
    pub fn first_slip(&self) -> f64 {
        self.x_slip_start() / self.belt_speed
    }
    /// Stick stiffness K_f = μ_s·N/γ_crit.
    pub fn stick_stiffness(&self, gamma_crit: f64) -> f64 {
        self.mu_static * self.normal_force / gamma_crit
    }
    /// Explicit (central-difference) stability limit in stick: Δt < 2/sqrt((k + K_f)/m).
    pub fn explicit_limit(&self, gamma_crit: f64) -> f64 {
        2.0 / ((self.spring + self.stick_stiffness(gamma_crit)) / self.mass).sqrt()
    }
    /// Checks the parameters describe a stick-slip cycle.
    pub fn validate(&self) -> Result<(), String> {
        check_bounds(&[
            ("mass", self.mass, Positive),
            ("spring", self.spring, Positive),
            ("normal_force", self.normal_force, Positive),
            ("mu_kinetic", self.mu_kinetic, Positive),
            ("belt_speed", self.belt_speed, Positive),
        ])?;
        if !(self.mu_static.is_finite() && self.mu_static > self.mu_kinetic) {
            return Err(format!(
                "mu_static = {} must exceed mu_kinetic = {} for stick-slip",
                self.mu_static, self.mu_kinetic
            ));
        }
        if self.cycles == 0 || self.cycles > 1000 {
            return Err(format!("cycles = {} must be in 1..=1000", self.cycles));
        }
        Ok(())
    }
}

/// Time integration of the host.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Integrator {
    /// Central differences (explicit), penalty stick only.
    Explicit,
    /// HHT-α (α = 0: Newmark average acceleration), Newton with the tangents `fric_` returns.
    Implicit {
        /// α ∈ [−1/3, 0].
        alpha: f64,
    },
}

/// How stick is enforced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stick {
    /// Penalty with allowable elastic slip γ_crit (`PROPS(7) = 0`).
    Elastic {
        /// γ_crit.
        gamma_crit: f64,
    },
    /// Lagrange multiplier held by the host (`PROPS(7) = 1`, `LM = 1`).
    Exact,
}

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Ran to the end; see the error and the flips.
    Completed,
    /// |x| grew past 1000 × the cycle's size, or became non-finite.
    Diverged,
    /// The host's Newton iteration did not converge (or cycled between stick and slip).
    NewtonFailed,
    /// The library asked for a cut-back (PNEWDT < 1).
    CutBack,
}

/// The outcome of one simulation.
#[derive(Clone, Debug)]
pub struct Run {
    /// How it ended.
    pub verdict: Verdict,
    /// Time steps taken.
    pub steps: usize,
    /// `fric_` calls (Newton iterations for the implicit methods).
    pub calls: usize,
    /// Wall time of the whole run, seconds.
    pub wall: f64,
    /// Times at which the block started to slip.
    pub onsets: Vec<f64>,
    /// Positions at which slip ended.
    pub slip_ends: Vec<f64>,
    /// Dissipation between consecutive onsets (Σ SFD).
    pub energies: Vec<f64>,
    /// Stick/slip changes of status.
    pub flips: usize,
    /// Spurious phases: a stick shorter than t_stick/10 or a slip shorter than t_slip/10.
    pub short_phases: usize,
    /// Cycles simulated after the first slip.
    pub cycles: usize,
    /// Steps at which the friction force changed sign (the belt always drags the block forward:
    /// never in the closed form).
    pub reversals: usize,
    /// Relative errors in T, x₂ (relative to A) and the energy per cycle; ∞ when unmeasurable.
    pub errors: [f64; 3],
    /// Increments the library refused (`PNEWDT` < 1) and the unguarded host redid smaller.
    pub cutbacks: usize,
    /// Largest |x| over the run relative to the cycle's size (∞ once not finite).
    pub peak: f64,
    /// The library's message for the first refusal.
    pub refused: String,
}

impl Run {
    /// The largest of the three relative errors.
    pub fn error(&self) -> f64 {
        self.errors.iter().copied().fold(0.0, f64::max)
    }
    /// The first stick phase, which starts consistent (τ = 0, ẋ = v₀, no ringing), ended
    /// before 90% of its closed-form length x₁/v₀: the stick mode grew from round-off, i.e. the
    /// step is beyond the stability limit of the integrator in stick.
    pub fn stick_unstable(&self, o: &Oscillator) -> bool {
        self.onsets
            .first()
            .is_some_and(|t| *t < 0.9 * o.first_slip())
    }

    /// Spurious stick/slip flips: the friction force reversing (twice or more), or more than
    /// three phases per cycle far shorter than the closed form's. (A penalty that rings after each stick onset starts the next slip early and may
    /// add one short slip per cycle; a stick mode that grows step by step, as explicit stepping
    /// beyond its limit does, chops every phase.)
    pub fn chattering(&self) -> bool {
        self.reversals >= 2 || self.short_phases > 3 * (self.cycles + 1)
    }
}

/// Maximum host Newton iterations per increment.
pub const MAX_NEWTON: usize = 30;

/// How the host watches its own motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Host {
    /// Stops the run as diverged once |x| passes 1000 × the cycle's size.
    Guarded,
    /// No check of its own (as a host that trusts the library to flag a failed increment): it
    /// passes whatever motion it computed to `fric_`, and when `fric_` answers `PNEWDT` < 1 it
    /// redoes the increment from the last converged state with Δt·`PNEWDT`, giving up after
    /// [`MAX_CUTBACKS`] cut-backs in a row.
    Unguarded,
}

/// Cut-backs in a row after which the unguarded host gives up.
pub const MAX_CUTBACKS: usize = 4;

/// Simulates F6 from stuck at x = 0 through `cycles` cycles after the first slip.
pub fn simulate(o: &Oscillator, integrator: Integrator, stick: Stick, dt: f64) -> Run {
    simulate_host(o, integrator, stick, dt, Host::Guarded)
}

/// [`simulate`] with the host's own divergence check on or off.
pub fn simulate_host(
    o: &Oscillator,
    integrator: Integrator,
    stick: Stick,
    dt: f64,
    host: Host,
) -> Run {
    let start = Instant::now();
    let (gamma_crit, stick_code) = match stick {
        Stick::Elastic { gamma_crit } => (gamma_crit, 0.0),
        // γ_crit only bounds the exact-stick transverse tangent here.
        Stick::Exact => (1e-6 * o.x_slip_start(), 1.0),
    };
    let props = |mu: f64| {
        CoulombBuilder::new()
            .mu(mu)
            .gamma_crit(gamma_crit * mu / o.mu_static)
            .stick(stick_code)
            .build_first(7)
    };
    let (props_s, props_k) = (props(o.mu_static), props(o.mu_kinetic));
    let mut c = FricCall::new(1, &props_s);
    c.press = o.normal_force;
    c.dpress = 0.0;
    c.dtime = dt;
    if stick == Stick::Exact {
        // Start held by the multiplier.
        c.lm = 1;
        c.statev[2] = 2.0;
    }
    let t_end = o.first_slip() + (f64::from(o.cycles) + 0.5) * o.period();
    let steps = (t_end / dt).ceil() as usize;
    let scale = o.x_slip_start() + o.amplitude() + o.belt_speed / o.omega();
    let (m, k, v0) = (o.mass, o.spring, o.belt_speed);
    // Converged state: position, velocity (v_{n+½} for explicit), acceleration, friction force.
    let (mut x, mut v, mut a, mut tau) = (0.0f64, v0, 0.0f64, 0.0f64);
    let mut stuck = true;
    let mut run = Run {
        verdict: Verdict::Completed,
        steps: 0,
        calls: 0,
        wall: 0.0,
        onsets: Vec::new(),
        slip_ends: Vec::new(),
        energies: Vec::new(),
        flips: 0,
        short_phases: 0,
        cycles: o.cycles as usize,
        reversals: 0,
        errors: [f64::INFINITY; 3],
        cutbacks: 0,
        peak: 0.0,
        refused: String::new(),
    };
    let mut dt_now = dt;
    let mut t_now = 0.0f64;
    let mut in_a_row = 0;
    let mut dissipated = 0.0;
    let mut phase_start = 0.0;
    for n in 0..steps {
        // μ frozen at the start of the increment: kinetic after a slipping increment.
        let kinetic = c.statev[2] == 1.0;
        c.props
            .copy_from_slice(if kinetic { &props_k } else { &props_s });
        let sv = [c.statev[0], c.statev[1], c.statev[2]];
        let lm_start = c.lm;
        let step = match integrator {
            Integrator::Explicit => loop {
                let x_new = x + dt_now * v;
                c.tau[0] = tau;
                c.lm = 0;
                c.statev[..3].copy_from_slice(&sv);
                c.dgam[0] = v0 * dt_now - (x_new - x);
                c.pnewdt = 1e36;
                c.call();
                run.calls += 1;
                if c.pnewdt >= 1.0 {
                    in_a_row = 0;
                    let a_new = (-k * x_new + c.tau[0]) / m;
                    break Ok((x_new, v + dt_now * a_new, a_new, c.tau[0]));
                }
                if host == Host::Guarded {
                    break Err(Verdict::CutBack);
                }
                // The library refused the increment: cut back as it asks and redo it.
                run.cutbacks += 1;
                in_a_row += 1;
                if run.refused.is_empty() {
                    run.refused = FricCall::last_error();
                }
                if in_a_row > MAX_CUTBACKS {
                    break Err(Verdict::CutBack);
                }
                dt_now *= c.pnewdt;
            },
            Integrator::Implicit { alpha } => {
                implicit_step(&mut c, o, alpha, dt, (x, v, a, tau), sv, lm_start, &mut run)
            }
        };
        run.steps += 1;
        let (x_new, v_new, a_new, tau_new) = match step {
            Ok(s) => s,
            Err(verdict) => {
                run.verdict = verdict;
                break;
            }
        };
        run.peak = if x_new.is_finite() {
            run.peak.max(x_new.abs() / scale)
        } else {
            f64::INFINITY
        };
        if host == Host::Guarded && (!x_new.is_finite() || x_new.abs() > 1e3 * scale) {
            run.verdict = Verdict::Diverged;
            break;
        }
        if c.lm == 0 {
            dissipated += c.sfd;
        }
        let now_stuck = match stick {
            Stick::Elastic { .. } => c.statev[2] != 1.0,
            Stick::Exact => c.lm == 1,
        };
        t_now += if integrator == Integrator::Explicit {
            dt_now
        } else {
            dt
        };
        let t_new = if host == Host::Guarded {
            (n + 1) as f64 * dt
        } else {
            t_now
        };
        if tau_new * tau < 0.0 {
            run.reversals += 1;
        }
        if stuck != now_stuck {
            // The phase that just ended (the first stick, from x = 0, is longer than t_stick).
            let shortest = if stuck { o.t_stick() } else { o.t_slip() } / 10.0;
            if t_new - phase_start < shortest {
                run.short_phases += 1;
                if run.short_phases > 10 * (run.cycles + 1) {
                    // Chattering for good: no need to go on.
                    break;
                }
            }
            phase_start = t_new;
        }
        if stuck && !now_stuck {
            run.flips += 1;
            if !run.onsets.is_empty() {
                run.energies.push(dissipated);
            }
            dissipated = 0.0;
            run.onsets.push(t_new);
        } else if !stuck && now_stuck {
            run.flips += 1;
            run.slip_ends.push(x_new);
        }
        stuck = now_stuck;
        (x, v, a, tau) = (x_new, v_new, a_new, tau_new);
    }
    run.wall = start.elapsed().as_secs_f64();
    if run.verdict == Verdict::Completed && run.onsets.len() >= 2 && !run.slip_ends.is_empty() {
        let n = run.onsets.len();
        let period = (run.onsets[n - 1] - run.onsets[0]) / (n - 1) as f64;
        let x2 = run.slip_ends.iter().sum::<f64>() / run.slip_ends.len() as f64;
        let energy = run.energies.iter().sum::<f64>() / run.energies.len().max(1) as f64;
        run.errors = [
            (period - o.period()).abs() / o.period(),
            (x2 - o.x_slip_end()).abs() / o.amplitude(),
            (energy - o.energy_per_cycle()).abs() / o.energy_per_cycle(),
        ];
    }
    run
}

/// One HHT-α increment with the host's Newton iteration on x_{n+1}:
/// m·a_{n+1} + (1+α)(k·x_{n+1} − τ_{n+1}) − α(k·x_n − τ_n) = 0, Newmark β = (1−α)²/4,
/// γ = ½ − α, dτ/dx = −DDTDDG (γ = v₀t − x). Exact stick: x_{n+1} = x_n + v₀Δt and the
/// multiplier τ from the same equation, passed as TAULM.
#[allow(clippy::too_many_arguments)]
fn implicit_step(
    c: &mut FricCall,
    o: &Oscillator,
    alpha: f64,
    dt: f64,
    (x, v, a, tau): (f64, f64, f64, f64),
    sv: [f64; 3],
    lm_start: i32,
    run: &mut Run,
) -> Result<(f64, f64, f64, f64), Verdict> {
    let (m, k, v0) = (o.mass, o.spring, o.belt_speed);
    let beta = 0.25 * (1.0 - alpha) * (1.0 - alpha);
    let gam = 0.5 - alpha;
    let pred = x + dt * v + dt * dt * (0.5 - beta) * a;
    let accel = |x_new: f64| (x_new - pred) / (beta * dt * dt);
    let velocity = |a_new: f64| v + dt * ((1.0 - gam) * a + gam * a_new);
    let old = k * x - tau;
    let tol = 1e-10 * o.mu_static * o.normal_force;
    let mut lm = lm_start;
    let mut flips = 0;
    let mut x_new = if lm == 1 { x + v0 * dt } else { x + dt * v };
    for _ in 0..MAX_NEWTON {
        c.tau[0] = tau;
        c.statev[..3].copy_from_slice(&sv);
        c.pnewdt = 1e36;
        if lm == 1 {
            // Stick is a constraint on the velocity: the block moves with the belt, ẋ = v₀,
            // ẍ = 0, and the multiplier balances the spring (HHT-weighted equilibrium). Taking
            // Newmark's a and v here instead would carry the jump of acceleration at the
            // slip-to-stick transition into every later step (an undamped oscillation of the
            // multiplier that releases the block again).
            x_new = x + v0 * dt;
            let taulm = ((1.0 + alpha) * k * x_new - alpha * old) / (1.0 + alpha);
            c.lm = 1;
            c.taulm[0] = taulm;
            c.dgam[0] = 0.0;
            c.call();
            run.calls += 1;
            if c.pnewdt < 1.0 {
                return Err(Verdict::CutBack);
            }
            // The law releases as soon as |TAULM| > μp, also by round-off. After the point has
            // gone stick → slip → stick within this increment, the host accepts stick when
            // the multiplier exceeds μp by no more than round-off (otherwise it keeps
            // iterating, and a real stick/slip cycle ends as a Newton failure).
            let round_off = flips >= 2 && taulm.abs() <= c.props[1] * c.press * (1.0 + 1e-9);
            if c.lm == 1 || round_off {
                // fric_ does not write TAU in exact stick: the multiplier is the stress.
                c.tau[0] = taulm;
                c.lm = 1;
                c.statev[..3].copy_from_slice(&[sv[0], 0.0, 2.0]);
                return Ok((x_new, v0, 0.0, taulm));
            }
            // Released: fric_ returned the slip stress and its tangent; a Newton update from
            // the stick position gives the first slip iterate (Δγ = 0 there is ambiguous).
            lm = 0;
            flips += 1;
            let r = m * accel(x_new) + (1.0 + alpha) * (k * x_new - c.tau[0]) - alpha * old;
            x_new -= r / (m / (beta * dt * dt) + (1.0 + alpha) * (k + c.ddtddg[0]));
            continue;
        }
        c.lm = 0;
        c.dgam[0] = v0 * dt - (x_new - x);
        c.call();
        run.calls += 1;
        if c.pnewdt < 1.0 {
            return Err(Verdict::CutBack);
        }
        if c.lm == 1 {
            // The motion reversed against the stress: stick (exact-stick switching test).
            lm = 1;
            flips += 1;
            continue;
        }
        let a_new = accel(x_new);
        let tau_new = c.tau[0];
        let r = m * a_new + (1.0 + alpha) * (k * x_new - tau_new) - alpha * old;
        let jacobian = m / (beta * dt * dt) + (1.0 + alpha) * (k + c.ddtddg[0]);
        let dx = r / jacobian;
        // Converged: residual small against the friction force, or the correction below the
        // round-off of x (m·a = m(x − x_pred)/(βΔt²) amplifies that round-off at small Δt).
        if r.abs() <= tol || dx.abs() <= 4.0 * f64::EPSILON * x_new.abs().max(o.amplitude()) {
            return Ok((x_new, velocity(a_new), a_new, tau_new));
        }
        x_new -= dx;
    }
    Err(Verdict::NewtonFailed)
}
