//! F4, velocity steps (`docs/scene-definitions.md`): constant pressure, slip driven at
//! piecewise-constant rates v₁, v₂, … (each held for `hold` time units, NFDIR = 1), with a
//! rate-dependent law. Rigid-stick closed form: τ(t) = τ_law(v(t)) at every instant, with
//!
//! - the exponential decay law of law 1 (`PROPS(8..10)`): τ = (μ_k + (μ_s − μ_k)·exp(−d_c v))·p;
//! - the adhesive law (law 2, seed 004): τ = ((μ_s v_½ + μ_d v)/(v_½ + v) + k_μ v)·p + S_a.
//!
//! Error = ∫|τ − τ_law(v(t))| dt over the history, divided by the history's length and by the
//! range of τ_law over the step rates: the mean stress error in units of the stress swing. The
//! law solved at the end-of-increment rate (implicit) follows a step within one increment, up
//! to the elastic slip γ_crit takes up; μ frozen at the start-of-increment rate (`PROPS(20) = 1`)
//! lags one increment behind every step, a first-order error in Δt/hold.

use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::FricCall;
use serde::Deserialize;

use crate::scene::Bound::{NonNegative, Positive};
use crate::scene::check_bounds;

/// The parameters of F4.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VelocitySteps {
    /// The slip rates, in order.
    pub rates: Vec<f64>,
    /// How long each rate is held.
    pub hold: f64,
    /// Contact pressure p.
    pub pressure: f64,
    /// Static coefficient μ_s (both laws).
    pub mu_static: f64,
    /// Kinetic (decay law) or dynamic (adhesive law) coefficient.
    pub mu_kinetic: f64,
    /// Decay coefficient d_c of the exponential law.
    pub decay: f64,
    /// Adhesive law: v_½.
    pub v_half: f64,
    /// Adhesive law: k_μ.
    pub k_mu: f64,
    /// Adhesive law: shear adhesive strength S_a.
    pub shear_adhesion: f64,
}

/// The rate laws of F4.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RateLaw {
    /// Law 1 with the exponential decay μ law, end-of-increment rate.
    Decay,
    /// Law 1 with the decay law, μ frozen at the start-of-increment rate (`PROPS(20) = 1`).
    DecayFrozen,
    /// Law 2, the adhesive law (seed 004), end-of-increment rate.
    Adhesive,
}

/// One F4 run.
#[derive(Clone, Copy, Debug)]
pub struct VelocityRun {
    /// Mean |τ − τ_law(v)| relative to the swing of τ_law over the rates.
    pub error: f64,
    /// |τ − τ_law(v)| / swing at the end of the last hold (the steady state).
    pub steady_error: f64,
    /// `fric_` calls.
    pub calls: usize,
    /// False when the library asked for a cut-back (`PNEWDT` < 1).
    pub ok: bool,
}

impl VelocitySteps {
    /// Checks the parameters.
    pub fn validate(&self) -> Result<(), String> {
        if self.rates.is_empty() || self.rates.iter().any(|v| !(v.is_finite() && *v > 0.0)) {
            return Err("rates must be a non-empty list of positive rates".into());
        }
        check_bounds(&[
            ("hold", self.hold, Positive),
            ("pressure", self.pressure, Positive),
            ("mu_static", self.mu_static, Positive),
            ("decay", self.decay, Positive),
            ("mu_kinetic", self.mu_kinetic, NonNegative),
            ("v_half", self.v_half, NonNegative),
            ("k_mu", self.k_mu, NonNegative),
            ("shear_adhesion", self.shear_adhesion, NonNegative),
        ])?;
        if self.mu_kinetic >= self.mu_static {
            return Err("mu_kinetic must be < mu_static".into());
        }
        Ok(())
    }

    /// The closed form: the law's steady stress at slip rate `v`.
    pub fn tau_law(&self, law: RateLaw, v: f64) -> f64 {
        let (s, k, p) = (self.mu_static, self.mu_kinetic, self.pressure);
        match law {
            // μ(v) = μ_k + (μ_s − μ_k)·exp(−d_c v) (docs/props.md, PROPS(8) = 1).
            RateLaw::Decay | RateLaw::DecayFrozen => (k + (s - k) * (-self.decay * v).exp()) * p,
            // Seed 004: τ = ((μ_s v_½ + μ_d v)/(v_½ + v) + k_μ v)·p + S_a.
            RateLaw::Adhesive => {
                ((s * self.v_half + k * v) / (self.v_half + v) + self.k_mu * v) * p
                    + self.shear_adhesion
            }
        }
    }

    /// The range of τ_law over the rates (the error's unit).
    pub fn swing(&self, law: RateLaw) -> f64 {
        let taus = self.rates.iter().map(|&v| self.tau_law(law, v));
        let (lo, hi) = taus.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| {
            (a.min(t), b.max(t))
        });
        (hi - lo).max(f64::MIN_POSITIVE)
    }

    /// dτ_law/dv at slip rate `v` (closed form of the law's derivative).
    pub fn slope(&self, law: RateLaw, v: f64) -> f64 {
        let (s, k, p) = (self.mu_static, self.mu_kinetic, self.pressure);
        match law {
            RateLaw::Decay | RateLaw::DecayFrozen => {
                -(s - k) * self.decay * (-self.decay * v).exp() * p
            }
            RateLaw::Adhesive => {
                ((k - s) * self.v_half / (self.v_half + v).powi(2) + self.k_mu) * p
            }
        }
    }

    /// The stick stiffness k_s: μ_s p/γ_crit (law 1), (μ_s p + S_a)/γ_crit (law 2).
    pub fn stick_stiffness(&self, law: RateLaw, gamma_crit: f64) -> f64 {
        let adhesion = if law == RateLaw::Adhesive {
            self.shear_adhesion
        } else {
            0.0
        };
        (self.mu_static * self.pressure + adhesion) / gamma_crit
    }

    /// The smallest stable step of steady sliding. A velocity-weakening law (dτ/dv < 0) on the
    /// stick spring k_s: linearised about the steady rate, with a = |dτ/dv|/(k_s Δt), the
    /// rate error e obeys
    /// - implicit (end-of-increment rate): k_s Δt e_{n+1} = |dτ/dv|(e_{n+1} − e_n), so
    ///   e_{n+1} = a/(a − 1)·e_n, stable for a < ½: Δt > 2|dτ/dv|/k_s;
    /// - μ frozen (start-of-increment rate): e_{n+1} = a(e_n − e_{n−1}), roots of z² − az + a,
    ///   stable for a < 1: Δt > |dτ/dv|/k_s.
    ///
    /// The worst rate of the history sets the limit; 0 when the law is not weakening.
    ///
    /// The implicit laws (`Decay`, `Adhesive`) run the library's default rate-following stick
    /// stiffness (docs/props.md), which slides steadily at every step: their limit is 0. The
    /// implicit formula above is that of the earlier rate-free stiffness
    /// ([`Self::rate_free_stiffness_limit`]; scene F7 compares the two).
    pub fn rate_stability_limit(&self, law: RateLaw, gamma_crit: f64) -> f64 {
        if law == RateLaw::DecayFrozen {
            self.rate_free_stiffness_limit(law, gamma_crit)
        } else {
            0.0
        }
    }

    /// The limit of the earlier rate-free stick stiffness (and of frozen μ), as derived above.
    pub fn rate_free_stiffness_limit(&self, law: RateLaw, gamma_crit: f64) -> f64 {
        let weakening = self
            .rates
            .iter()
            .map(|&v| (-self.slope(law, v)).max(0.0))
            .fold(0.0, f64::max);
        let factor = if law == RateLaw::DecayFrozen {
            1.0
        } else {
            2.0
        };
        factor * weakening / self.stick_stiffness(law, gamma_crit)
    }

    /// The `PROPS` of a law with allowable elastic slip `gamma_crit`.
    pub fn props(&self, law: RateLaw, gamma_crit: f64) -> Vec<f64> {
        let (s, k) = (self.mu_static, self.mu_kinetic);
        match law {
            RateLaw::Decay | RateLaw::DecayFrozen => {
                let frozen = if law == RateLaw::DecayFrozen {
                    1.0
                } else {
                    0.0
                };
                CoulombBuilder::new()
                    .mu(s)
                    .gamma_crit(gamma_crit)
                    .mu_law(1.0)
                    .mu_k(k)
                    .decay(self.decay)
                    .frozen(frozen)
                    .build()
            }
            RateLaw::Adhesive => AdhesiveBuilder::new()
                .coeff(k)
                .coeff_static(s)
                .sa(self.shear_adhesion)
                .kmu(self.k_mu)
                .vhalf(self.v_half)
                .gamma_crit(gamma_crit)
                .build_first(8),
        }
    }

    /// Runs the history with increments `dt` (each hold rounded to whole increments).
    pub fn run(&self, law: RateLaw, gamma_crit: f64, dt: f64) -> VelocityRun {
        let per_hold = (self.hold / dt).round().max(1.0) as usize;
        let dt = self.hold / per_hold as f64;
        let mut c = FricCall::new(1, &self.props(law, gamma_crit));
        c.dtime = dt;
        c.press = self.pressure;
        let mut l1 = 0.0;
        let mut calls = 0;
        let mut ok = true;
        let mut steady_error = 0.0;
        'history: for &v in &self.rates {
            let exact = self.tau_law(law, v);
            for _ in 0..per_hold {
                c.dgam[0] = v * dt;
                c.dpress = 0.0;
                c.pnewdt = 1e36;
                c.call();
                calls += 1;
                if c.pnewdt < 1.0 {
                    ok = false;
                    break 'history;
                }
                c.time[0] += dt;
                c.time[1] += dt;
                // τ is the end-of-increment stress: it stands for the whole increment.
                l1 += (c.tau[0] - exact).abs() * dt;
            }
            steady_error = (c.tau[0] - exact).abs();
        }
        let swing = self.swing(law);
        let total = self.hold * self.rates.len() as f64;
        VelocityRun {
            error: if ok {
                l1 / (total * swing)
            } else {
                f64::INFINITY
            },
            steady_error: steady_error / swing,
            calls,
            ok,
        }
    }
}
