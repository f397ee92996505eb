//! F1 with a host (`docs/scene-definitions.md`, pull to plateau): a spring of stiffness K pulls
//! the slider, its far end driven quasi-statically to u = +U and back to −U, at constant pressure
//! p. The host solves equilibrium K(u − γ) = τ(γ) for the slider displacement γ each increment
//! (Newton with `DDTDDG` for elastic stick; Lagrange multiplier = spring force for exact stick).
//!
//! Closed form (rigid stick, τ_c = μp): the slider stays until |K(u − γ)| reaches τ_c, then
//! follows at that force: γ = max(0, u − τ_c/K) on loading; on the way back it stays at its peak
//! until u < γ_peak − τ_c/K and then follows γ = u + τ_c/K. Elastic stick adds the elastic slip
//! |γ_el| ≤ γ_crit, which moves γ by up to 2γ_crit after a reversal.

use std::time::Instant;

use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use serde::Deserialize;

use crate::oscillator::Stick;
use crate::scene::Bound::Positive;
use crate::scene::check_bounds;

/// The parameters of the pull scene.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pull {
    /// Friction coefficient μ.
    pub mu: f64,
    /// Contact pressure p (unit area: a force).
    pub pressure: f64,
    /// Stiffness K of the pulling spring.
    pub spring: f64,
    /// Travel U of the spring's end, in units of the stick stretch τ_c/K.
    pub travel: f64,
}

/// One run: the largest |γ − γ_exact| relative to τ_c/K, `fric_` calls, wall time.
#[derive(Clone, Copy, Debug)]
pub struct PullRun {
    /// Error relative to τ_c/K.
    pub error: f64,
    /// `fric_` calls (Newton iterations included).
    pub calls: usize,
    /// Wall time, seconds.
    pub wall: f64,
    /// False when the host's Newton iteration failed or the library asked for a cut-back.
    pub ok: bool,
}

/// Host Newton iterations per increment.
const MAX_NEWTON: usize = 30;

impl Pull {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), String> {
        check_bounds(&[
            ("mu", self.mu, Positive),
            ("pressure", self.pressure, Positive),
            ("spring", self.spring, Positive),
        ])?;
        if !(self.travel.is_finite() && self.travel > 1.0 && self.travel < 1e4) {
            return Err(format!(
                "travel = {} must be in (1, 1e4) stick stretches",
                self.travel
            ));
        }
        Ok(())
    }

    /// τ_c/K, the spring stretch at which the slider starts to slip.
    pub fn stretch(&self) -> f64 {
        self.mu * self.pressure / self.spring
    }

    /// Drives the spring's end with `per_stretch` increments per τ_c/K.
    pub fn run(&self, stick: Stick, per_stretch: usize) -> PullRun {
        let start = Instant::now();
        let (gamma_crit, code) = match stick {
            Stick::Elastic { gamma_crit } => (gamma_crit, 0.0),
            Stick::Exact => (1e-6 * self.stretch(), 1.0),
        };
        let props = CoulombBuilder::new()
            .mu(self.mu)
            .gamma_crit(gamma_crit)
            .stick(code)
            .build_first(7);
        let mut c = FricCall::new(1, &props);
        c.press = self.pressure;
        if stick == Stick::Exact {
            // Start held by the multiplier.
            c.lm = 1;
            c.statev[2] = 2.0;
        }
        let (k, tau_c, s) = (self.spring, self.mu * self.pressure, self.stretch());
        let du = s / per_stretch.max(1) as f64;
        let n_out = (self.travel * per_stretch as f64).round() as usize;
        let mut run = PullRun {
            error: 0.0,
            calls: 0,
            wall: 0.0,
            ok: true,
        };
        let (mut u, mut gamma, mut tau) = (0.0f64, 0.0f64, 0.0f64);
        let mut peak = 0.0f64;
        let tol = 1e-12 * tau_c;
        // Out to +U, back to −U.
        for step in 0..3 * n_out {
            let sign = if step < n_out { 1.0 } else { -1.0 };
            u += sign * du;
            let sv = [c.statev[0], c.statev[1], c.statev[2]];
            let lm_start = c.lm;
            let mut lm = lm_start;
            let mut dg = 0.0f64;
            let mut converged = false;
            for _ in 0..MAX_NEWTON {
                c.statev[..3].copy_from_slice(&sv);
                c.tau[0] = tau;
                c.pnewdt = 1e36;
                c.dpress = 0.0;
                if lm == 1 {
                    // Held: the multiplier is the spring force.
                    c.lm = 1;
                    c.taulm[0] = k * (u - gamma);
                    c.dgam[0] = 0.0;
                } else {
                    c.lm = 0;
                    c.dgam[0] = dg;
                }
                c.call();
                run.calls += 1;
                if c.pnewdt < 1.0 {
                    run.ok = false;
                    break;
                }
                if c.lm == 1 {
                    if lm == 1 {
                        dg = 0.0;
                        c.tau[0] = k * (u - gamma);
                        converged = true;
                        break;
                    }
                    lm = 1;
                    continue;
                }
                let r = k * (u - gamma - dg) - c.tau[0];
                if lm == 0 && r.abs() <= tol {
                    converged = true;
                    break;
                }
                if lm == 1 {
                    // Released: start the slip iteration from the stuck position.
                    lm = 0;
                }
                dg += r / (k + c.ddtddg[0]);
            }
            if !converged || !run.ok {
                run.ok = false;
                break;
            }
            gamma += dg;
            tau = c.tau[0];
            // The closed form along the path.
            if sign > 0.0 {
                peak = u;
            }
            let g_peak = (peak - s).max(0.0);
            let exact = if sign > 0.0 {
                (u - s).max(0.0)
            } else {
                g_peak.min(u + s)
            };
            run.error = run.error.max((gamma - exact).abs() / s);
        }
        if !run.ok {
            run.error = f64::INFINITY;
        }
        run.wall = start.elapsed().as_secs_f64();
        run
    }
}
