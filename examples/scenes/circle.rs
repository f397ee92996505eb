//! F2, the circle (`docs/scene-definitions.md`): constant pressure, slip imposed along a circle of
//! radius R ≫ γ_crit with N increments per turn (NFDIR = 2). In the steady state |τ| = μp and τ
//! lags behind the slip direction by φ, sin φ = γ_crit/R; the backward-Euler return map reaches
//! it at first order in the step Δθ = 2π/N.

use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use serde::Deserialize;

use crate::scene::Bound::Positive;
use crate::scene::check_bounds;

/// The parameters of F2.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Circle {
    /// Friction coefficient μ.
    pub mu: f64,
    /// Contact pressure p.
    pub pressure: f64,
    /// Radius R of the imposed slip path.
    pub radius: f64,
    /// Turns before the lag is measured (the transient dies out in well under one turn).
    pub turns: u32,
}

/// One F2 run: the lag error and `fric_` calls.
#[derive(Clone, Copy, Debug)]
pub struct CircleRun {
    /// |φ − asin(γ_crit/R)|, φ measured from the end-of-step tangent of the circle.
    pub error: f64,
    /// The same with φ measured from the chord of the last step (the direction of `DGAM`).
    pub chord_error: f64,
    /// Largest ||τ| − μp| over the last turn.
    pub magnitude_error: f64,
    /// `fric_` calls.
    pub calls: usize,
    /// False when the library asked for a cut-back.
    pub ok: bool,
}

impl Circle {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), String> {
        check_bounds(&[
            ("mu", self.mu, Positive),
            ("pressure", self.pressure, Positive),
            ("radius", self.radius, Positive),
        ])?;
        if self.turns == 0 || self.turns > 100 {
            return Err(format!("turns = {} must be in 1..=100", self.turns));
        }
        Ok(())
    }

    /// Runs `per_turn` increments per turn with allowable elastic slip `gamma_crit` (< R).
    pub fn run(&self, gamma_crit: f64, per_turn: usize) -> CircleRun {
        let exact = (gamma_crit / self.radius).asin();
        let props = CoulombBuilder::new()
            .mu(self.mu)
            .gamma_crit(gamma_crit)
            .build_first(7);
        let mut c = FricCall::new(2, &props);
        c.press = self.pressure;
        let dtheta = 2.0 * std::f64::consts::PI / per_turn as f64;
        let mut prev = [self.radius, 0.0];
        let total = self.turns as usize * per_turn;
        let mut magnitude_error = 0.0f64;
        let mut ok = true;
        let mut theta = 0.0;
        for k in 1..=total {
            theta = dtheta * k as f64;
            let now = [self.radius * theta.cos(), self.radius * theta.sin()];
            c.dgam[0] = now[0] - prev[0];
            c.dgam[1] = now[1] - prev[1];
            c.dpress = 0.0;
            c.pnewdt = 1e36;
            c.call();
            if c.pnewdt < 1.0 {
                ok = false;
                break;
            }
            prev = now;
            if k + per_turn > total {
                let mag = c.tau[0].hypot(c.tau[1]);
                magnitude_error = magnitude_error.max((mag - self.mu * self.pressure).abs());
            }
        }
        // The lag between τ and the end-of-step slip direction (the tangent).
        let tangent = [-theta.sin(), theta.cos()];
        let cross = tangent[0] * c.tau[1] - tangent[1] * c.tau[0];
        let dot = tangent[0] * c.tau[0] + tangent[1] * c.tau[1];
        let lag = cross.atan2(dot).abs();
        // The lag from the chord of the last step, the direction the increment DGAM moved along
        // (the tangent at the step's midpoint angle θ − Δθ/2).
        let mid = theta - 0.5 * dtheta;
        let chord = [-mid.sin(), mid.cos()];
        let chord_lag = (chord[0] * c.tau[1] - chord[1] * c.tau[0])
            .atan2(chord[0] * c.tau[0] + chord[1] * c.tau[1])
            .abs();
        CircleRun {
            error: if ok {
                (lag - exact).abs()
            } else {
                f64::INFINITY
            },
            chord_error: if ok {
                (chord_lag - exact).abs()
            } else {
                f64::INFINITY
            },
            magnitude_error,
            calls: total,
            ok,
        }
    }
}
