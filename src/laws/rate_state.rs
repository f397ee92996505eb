//! Rate-and-state friction (Dieterich–Ruina), `PROPS(1) = 3` (docs/props.md, "Law 3").
//!
//! The friction coefficient depends on the slip rate V and on a state variable θ (a contact
//! age, units of time) that evolves with slip:
//!
//! - logarithmic form: μ(V, θ) = μ₀ + a·ln(V/V₀) + b·ln(V₀θ/L) (Dieterich 1979, Ruina 1983);
//! - regularised form, finite at V → 0 (Rice & Ben-Zion 1996, Lapusta et al. 2000):
//!   μ(V, θ) = a·asinh(V/(2V₀)·exp(ψ/a)), ψ = μ₀ + b·ln(V₀θ/L), which equals the logarithmic
//!   form to within a·e^(−2ψ/a)(V₀/V)²/4 once V ≫ V₀·e^(−ψ/a);
//! - aging law dθ/dt = 1 − Vθ/L, or slip law dθ/dt = −(Vθ/L)·ln(Vθ/L).
//!
//! At constant V both evolution laws integrate exactly, so θ is advanced over the increment
//! in closed form at the end-of-increment slip rate V = Δs/Δt (backward Euler in the rate,
//! exact in θ given the rate): with w = VΔt/L,
//!
//! - aging: θ(t + Δt) = L/V + (θ − L/V)·e^(−w) = θ·e^(−w) + Δt·(1 − e^(−w))/w, → θ + Δt as
//!   V → 0;
//! - slip: ln(Vθ/L) decays as e^(−w), θ(t + Δt) = θ·exp(ln(Vθ/L)·(e^(−w) − 1)), → θ as V → 0.
//!
//! The steady state at constant V is θ_ss = L/V (both laws), so μ_ss = μ₀ + (a − b)·ln(V/V₀).
//!
//! The return map is law 1's elastic stick in its rate-following form (docs/props.md, "The
//! rate-dependent formulation"): the stick stiffness k_s = τ_s/γ_crit follows the strength
//! τ_s = μ(V*, θ)·p⁺ at the start-of-increment rate V* (the previous increment's slip rate after
//! a slip, V₀ after a stick), the same at both ends of the increment; a sliding increment keeps
//! the elastic slip at γ_crit, so Δs = |γ^pr| − γ_crit and τ = μ(Δs/Δt, θ(Δs/Δt))·p⁺·n with no
//! local solve, and the consistent tangent (Eq. 5.2.3-3 of the source model) carries
//! dμ/dV = ∂μ/∂V + ∂μ/∂θ·dθ/dV. `LM` is always 0 (no exact stick).

use super::contact::{Contact, Increment, Traction, elastic_start_slip, elastic_stick_stress};
use super::coulomb::{Coulomb, CoulombState, FrictionStatus, Update};
use super::friction_coefficient::STICK_TEST_ROUNDING;
use super::point_law::{EndState, PointAnswer, PointInput, PointLaw, PointResult};
use super::small_vec::{diagonal, norm, radial_transverse, scale, unit};
use crate::{LawError, Outcome};

/// How the state θ evolves with slip.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StateEvolution {
    /// Dieterich's aging law, dθ/dt = 1 − Vθ/L (θ grows in stationary contact).
    Aging,
    /// Ruina's slip law, dθ/dt = −(Vθ/L)·ln(Vθ/L) (θ changes only with slip).
    Slip,
}

/// Which expression gives μ(V, θ).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoefficientForm {
    /// μ₀ + a·ln(V/V₀) + b·ln(V₀θ/L): −∞ as V → 0 (the strength is then taken as 0).
    Logarithmic,
    /// a·asinh(V/(2V₀)·exp((μ₀ + b·ln(V₀θ/L))/a)): 0 at V = 0, smooth, needs a > 0.
    Regularized,
}

/// The parameters of the law, named as in the rate-and-state literature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RateStateParameters {
    /// μ₀, the steady-state coefficient at the reference rate V₀.
    pub mu0: f64,
    /// a, the direct-effect coefficient (≥ 0; > 0 for the regularised form).
    pub a: f64,
    /// b, the evolution-effect coefficient (any finite value; b > a is velocity weakening).
    pub b: f64,
    /// V₀, the reference slip rate (> 0).
    pub v0: f64,
    /// L (also D_c), the characteristic slip distance of the state evolution (> 0).
    pub l: f64,
    /// Aging or slip law.
    pub evolution: StateEvolution,
    /// Logarithmic or regularised μ.
    pub form: CoefficientForm,
}

/// Rate-and-state friction with elastic stick; construct with [`RateState::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RateState {
    p: RateStateParameters,
    /// γ_crit's source (absolute or a tolerance of `CHRLNGTH`), as law 1 has it.
    stick: Coulomb,
    /// θ for a point whose `STATEV(4)` is 0 (not yet started): L/V₀ unless given.
    theta_initial: f64,
}

/// The point's state: law 1's three values (accumulated slip, last slip rate, stick/slip) and
/// θ, in `STATEV(1..4)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RateStateState {
    /// `STATEV(1..3)`.
    pub point: CoulombState,
    /// θ, the state variable (time), `STATEV(4)`.
    pub theta: f64,
}

/// μ with its partial derivatives ∂μ/∂V and ∂μ/∂θ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coefficient {
    /// μ(V, θ), never below 0 (a negative logarithmic μ is taken as 0, with zero partials);
    /// NaN when the parameters and state take it out of f64's range.
    pub mu: f64,
    /// ∂μ/∂V.
    pub d_rate: f64,
    /// ∂μ/∂θ.
    pub d_theta: f64,
}

/// Above this ln z, asinh(z) = ln(2z) to within 1/(4z²) < 1e-18 (regularised form).
const LN_Z_LOGARITHMIC: f64 = 20.0;

/// Below this w = VΔt/L the aging law's (1 − e^(−w))/w and its derivative are taken from
/// their Taylor series (truncation below 1e-18, relative), above it from `exp_m1`.
const W_SERIES: f64 = 1e-2;

impl RateStateState {
    /// Number of `STATEV` entries the law uses.
    pub const NSTATV: usize = 4;

    /// Reads `STATEV(1..4)`; `STATEV(4)` = 0 reads as `theta_initial` (a point that has not
    /// started), a negative, NaN or infinite θ is refused.
    pub fn from_statev(statev: &[f64], theta_initial: f64) -> Result<Self, LawError> {
        let point = CoulombState::from_statev(statev)?;
        let theta = match statev.get(3) {
            Some(&0.0) => theta_initial,
            Some(&t) if t.is_finite() && t > 0.0 => t,
            Some(&t) => {
                return Err(LawError::Input(format!(
                    "STATEV(4) (rate-and-state θ) = {t} must be finite and > 0, or 0 before \
                     the first increment (state corrupted by the caller?)"
                )));
            }
            None => {
                return Err(LawError::Parameter(format!(
                    "NSTATV = {} but rate-and-state friction needs {} (STATEV(4) keeps θ)",
                    statev.len(),
                    Self::NSTATV
                )));
            }
        };
        Ok(RateStateState { point, theta })
    }

    /// Writes `STATEV(1..4)` into `out` (at least [`Self::NSTATV`] entries).
    pub fn write_statev(&self, out: &mut [f64]) {
        self.point.write_statev(out);
        out[3] = self.theta;
    }
}

impl RateState {
    /// The law with γ_crit = `PROPS`-style absolute value or tolerance (`stick`, law 1's
    /// critical-slip source) and θ = `theta_initial` for points not yet started (0: L/V₀, the
    /// steady state at V₀). Refuses a < 0, a = 0 with the regularised form, V₀ ≤ 0, L ≤ 0,
    /// non-finite μ₀ or b, and a negative initial θ.
    pub fn new(
        p: RateStateParameters,
        stick: Coulomb,
        theta_initial: f64,
    ) -> Result<Self, LawError> {
        let bad = |what: &str, v: f64| {
            Err(LawError::Parameter(format!(
                "rate-and-state friction: {what} = {v}"
            )))
        };
        if !p.mu0.is_finite() {
            return bad("μ₀ must be finite; μ₀", p.mu0);
        }
        if !(p.a.is_finite() && p.a >= 0.0) {
            return bad("a must be finite and ≥ 0; a", p.a);
        }
        if p.form == CoefficientForm::Regularized && p.a == 0.0 {
            return bad("the regularised form needs a > 0; a", p.a);
        }
        if !p.b.is_finite() {
            return bad("b must be finite; b", p.b);
        }
        if !(p.v0.is_finite() && p.v0 > 0.0) {
            return bad("V₀ must be finite and > 0; V₀", p.v0);
        }
        if !(p.l.is_finite() && p.l > 0.0) {
            return bad("L must be finite and > 0; L", p.l);
        }
        if !(theta_initial.is_finite() && theta_initial >= 0.0) {
            return bad("the initial θ must be finite and ≥ 0; θ", theta_initial);
        }
        let theta_initial = if theta_initial > 0.0 {
            theta_initial
        } else {
            p.l / p.v0
        };
        if !(theta_initial.is_finite() && theta_initial > 0.0) {
            return bad(
                "the initial θ = L/V₀ is not a positive number; θ",
                theta_initial,
            );
        }
        Ok(RateState {
            p,
            stick,
            theta_initial,
        })
    }

    /// The parameters.
    #[must_use]
    pub fn parameters(&self) -> &RateStateParameters {
        &self.p
    }

    /// θ of a point not yet started (`STATEV(4)` = 0).
    #[must_use]
    pub fn theta_initial(&self) -> f64 {
        self.theta_initial
    }

    /// μ(V, θ) and its partials, V ≥ 0, θ > 0.
    #[must_use]
    pub fn coefficient(&self, v: f64, theta: f64) -> Coefficient {
        let RateStateParameters {
            mu0, a, b, v0, l, ..
        } = self.p;
        // ψ = μ₀ + b·ln(V₀θ/L), the state's part (none when b = 0, also where V₀θ/L is 0
        // or ∞ in f64).
        let psi = if b == 0.0 {
            mu0
        } else {
            mu0 + b * (v0 * theta / l).ln()
        };
        let (mu, d_rate, d_psi) = match self.p.form {
            CoefficientForm::Logarithmic => (psi + a * (v / v0).ln(), a / v, 1.0),
            CoefficientForm::Regularized => {
                // z = V/(2V₀)·e^(ψ/a), in logarithms so that e^(ψ/a) cannot overflow.
                let ln_z = (v / (2.0 * v0)).ln() + psi / a;
                if ln_z > LN_Z_LOGARITHMIC {
                    // asinh z = ln 2z: the logarithmic form.
                    (a * (std::f64::consts::LN_2 + ln_z), a / v, 1.0)
                } else {
                    let z = ln_z.exp();
                    let root = z.hypot(1.0);
                    // ∂μ/∂V = a·(z/V)/√(1 + z²); z/V = e^(ψ/a)/(2V₀) at V = 0.
                    let z_per_v = if v > 0.0 {
                        z / v
                    } else {
                        (psi / a).exp() / (2.0 * v0)
                    };
                    (a * z.asinh(), a * z_per_v / root, z / root)
                }
            }
        };
        if mu > 0.0 || mu.is_nan() {
            // (A NaN μ, out of f64's range, is passed on: the update refuses it.)
            Coefficient {
                mu,
                d_rate,
                d_theta: d_psi * b / theta,
            }
        } else {
            Coefficient {
                mu: 0.0,
                d_rate: 0.0,
                d_theta: 0.0,
            }
        }
    }

    /// θ after an increment Δt slid at the constant rate V ≥ 0 from θ_n (exact), and dθ/dV.
    #[must_use]
    pub fn evolve(&self, theta: f64, v: f64, dtime: f64) -> (f64, f64) {
        let l = self.p.l;
        let w = v * dtime / l;
        let decay = (-w).exp();
        // g(w) = (1 − e^(−w))/w, g(0) = 1.
        let g = if w < W_SERIES {
            // Σ (−w)^k/(k + 1)!, k ≤ 6.
            1.0 - w
                * (1.0 / 2.0
                    - w * (1.0 / 6.0
                        - w * (1.0 / 24.0 - w * (1.0 / 120.0 - w * (1.0 / 720.0 - w / 5040.0)))))
        } else {
            -(-w).exp_m1() / w
        };
        match self.p.evolution {
            StateEvolution::Aging => {
                // θ = θ_n·e^(−w) + Δt·g(w); g'(w) = (e^(−w)(1 + w) − 1)/w².
                let dg = if w < W_SERIES {
                    // Σ k·(−1)^k·w^(k−1)/(k + 1)!, k ≤ 6.
                    -1.0 / 2.0
                        + w * (1.0 / 3.0
                            - w * (1.0 / 8.0 - w * (1.0 / 30.0 - w * (1.0 / 144.0 - w / 840.0))))
                } else {
                    ((-w).exp_m1() * (1.0 + w) + w) / (w * w)
                };
                let end = theta * decay + dtime * g;
                (end, dtime / l * (-theta * decay + dtime * dg))
            }
            StateEvolution::Slip => {
                if v == 0.0 {
                    // θ does not change without slip (the rate derivative is unbounded here and
                    // left out).
                    return (theta, 0.0);
                }
                // x = ln(Vθ_n/L); θ = θ_n·exp(x·(e^(−w) − 1)), e^(−w) − 1 = −w·g(w).
                let x = (v * theta / l).ln();
                let end = theta * (-x * w * g).exp();
                // d ln θ/dV = (e^(−w) − 1)/V − x·e^(−w)·Δt/L = −(Δt/L)·(g + x·e^(−w)).
                (end, -end * dtime / l * (g + x * decay))
            }
        }
    }

    /// The strength's rate at which the stick stiffness is read: the last slip rate after a
    /// slip (`sliding`, when > 0), V₀ after a stick or at rest (docs/props.md, "Law 3").
    fn stiffness_rate(&self, sliding: Option<f64>) -> f64 {
        match sliding {
            Some(rate) if rate > 0.0 => rate,
            _ => self.p.v0,
        }
    }

    /// One increment of a closed point: the start state in, the end state out (always motion,
    /// `LM = 0`, and converged: there is no local solve).
    pub fn update<const N: usize>(
        &self,
        inc: &Increment<N>,
        state: &RateStateState,
    ) -> Result<Update<N, RateStateState>, LawError> {
        inc.check_finite()?;
        if inc.dtime.is_nan() || inc.dtime <= 0.0 {
            return Err(LawError::Input(format!(
                "DTIME = {}: rate-and-state friction needs a time increment > 0",
                inc.dtime
            )));
        }
        let sliding = state.point.sliding_rate()?;
        let gamma_crit = self.stick.critical_slip_for(inc.characteristic_length)?;
        let (p, dt) = (inc.pressure, inc.dtime);
        let (p_end, p_start) = (p.max(0.0), (p - inc.dpressure).max(0.0));
        // The stick strength per unit pressure, the same at both ends of the increment.
        let mu_stick = self
            .coefficient(self.stiffness_rate(sliding), state.theta)
            .mu;
        // The elastic slip at the start, γ̄^el = τ̄/k_s(p₀) = τ̄·γ_crit/(μ*·p₀⁺) (0 with no
        // strength to hold a stress).
        let start_strength = mu_stick * p_start;
        let elastic_start = elastic_start_slip(&inc.tau, gamma_crit, start_strength);
        let mut trial = elastic_start;
        for (t, d) in trial.iter_mut().zip(&inc.dgam) {
            *t += d;
        }
        let length = norm(&trial);
        let traction;
        let end;
        if length <= gamma_crit * (1.0 + STICK_TEST_ROUNDING) {
            // Elastic stick, Eq. 5.2.3-1: τ = k_s·γ^pr, k_s = μ*·p⁺/γ_crit.
            let per_slip = mu_stick / gamma_crit;
            let (tau, k_s) = elastic_stick_stress(&trial, gamma_crit, mu_stick * p_end);
            let dp = if p > 0.0 {
                scale(&trial, per_slip)
            } else {
                [0.0; N]
            };
            let sed = 0.5 * k_s * length * length;
            traction = Traction::sticking(tau, diagonal(k_s), dp, sed);
            let (theta, _) = self.evolve(state.theta, 0.0, dt);
            end = RateStateState {
                point: state.point.after_slide(0.0, 0.0, FrictionStatus::Stick),
                theta,
            };
        } else {
            // Slip, Eq. 5.2.3-2: the elastic slip stays γ_crit, Δs = |γ^pr| − γ_crit at the
            // end-of-increment rate V = Δs/Δt, τ = μ(V, θ(V))·p⁺ along n.
            let n = unit(&trial, length);
            let slip = length - gamma_crit;
            let rate = slip / dt;
            let (theta, dtheta_drate) = self.evolve(state.theta, rate, dt);
            let c = self.coefficient(rate, theta);
            let strength = c.mu * p_end;
            // dτ_s/dV = p⁺·(∂μ/∂V + ∂μ/∂θ·dθ/dV); Eq. 5.2.3-3 with ∂Δs/∂|γ^pr| = 1.
            let dstrength_drate = p_end * (c.d_rate + c.d_theta * dtheta_drate);
            let ddtddg = radial_transverse(&n, dstrength_drate / dt, strength / length);
            let dt_dp = if p > 0.0 { c.mu } else { 0.0 };
            traction = Traction::sliding(
                &n,
                strength,
                ddtddg,
                dt_dp,
                slip,
                0.5 * strength * gamma_crit,
            );
            end = RateStateState {
                point: state.point.after_slide(slip, rate, FrictionStatus::Slip),
                theta,
            };
        }
        if !(traction.is_finite() && end.theta.is_finite() && end.theta > 0.0) {
            return Err(LawError::Numerical(format!(
                "the rate-and-state update is not finite (θ = {} → {}, pressure {p}): inputs \
                 or parameters out of f64's range",
                state.theta, end.theta
            )));
        }
        Ok(Update {
            contact: Contact::Motion(traction),
            state: end,
            outcome: Outcome::CONVERGED,
        })
    }
}

impl PointLaw for RateState {
    fn name(&self) -> &'static str {
        "the rate-and-state law"
    }

    fn nstatv(&self, _nfdir: usize) -> usize {
        RateStateState::NSTATV
    }

    fn update_point<const N: usize>(&self, at: &PointInput<'_, N>) -> PointResult<N> {
        let start = RateStateState::from_statev(at.statev, self.theta_initial)?;
        let up = self.update(at.increment, &start)?;
        Ok(PointAnswer::isothermal(up.contact, &up.state, up.outcome))
    }
}

impl EndState for RateStateState {
    fn statev_len(&self) -> usize {
        Self::NSTATV
    }

    fn write_statev(&self, statev: &mut [f64]) {
        RateStateState::write_statev(self, statev);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(evolution: StateEvolution, form: CoefficientForm) -> RateState {
        law_with_a(evolution, form, 0.01)
    }

    fn law_with_a(evolution: StateEvolution, form: CoefficientForm, a: f64) -> RateState {
        RateState::new(
            RateStateParameters {
                mu0: 0.6,
                a,
                b: 0.015,
                v0: 1e-6,
                l: 1e-5,
                evolution,
                form,
            },
            Coulomb::new(0.6)
                .and_then(|c| c.with_critical_slip_absolute(1e-7))
                .unwrap(),
            0.0,
        )
        .unwrap()
    }

    const LAWS: [(StateEvolution, CoefficientForm); 4] = [
        (StateEvolution::Aging, CoefficientForm::Logarithmic),
        (StateEvolution::Slip, CoefficientForm::Logarithmic),
        (StateEvolution::Aging, CoefficientForm::Regularized),
        (StateEvolution::Slip, CoefficientForm::Regularized),
    ];

    /// θ's closed form against a fine explicit integration of the evolution law at constant V
    /// (RK4 over 20 000 steps), and dθ/dV against central differences of `evolve`.
    #[test]
    fn state_evolution_is_exact_at_constant_rate() {
        for (evolution, form) in LAWS {
            let law = law(evolution, form);
            let l = law.p.l;
            for (theta0, v, dt) in [(10.0, 1e-6, 3.0), (1.0, 1e-4, 0.5), (50.0, 3e-7, 40.0)] {
                let rhs = |th: f64| match evolution {
                    StateEvolution::Aging => 1.0 - v * th / l,
                    StateEvolution::Slip => -(v * th / l) * (v * th / l).ln(),
                };
                let steps = 20_000;
                let h = dt / f64::from(steps);
                let mut th = theta0;
                for _ in 0..steps {
                    let k1 = rhs(th);
                    let k2 = rhs(th + 0.5 * h * k1);
                    let k3 = rhs(th + 0.5 * h * k2);
                    let k4 = rhs(th + h * k3);
                    th += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
                }
                let (exact, dtheta) = law.evolve(theta0, v, dt);
                assert!(
                    (exact - th).abs() <= 1e-9 * th,
                    "{evolution:?}: {exact} vs {th}"
                );
                let e = 1e-6 * v;
                let fd =
                    (law.evolve(theta0, v + e, dt).0 - law.evolve(theta0, v - e, dt).0) / (2.0 * e);
                assert!(
                    (dtheta - fd).abs() <= 1e-6 * fd.abs().max(1e-300),
                    "{dtheta} vs {fd}"
                );
            }
            // No slip: aging heals θ + Δt, the slip law keeps θ.
            let (t, _) = law.evolve(7.0, 0.0, 2.0);
            let want = if evolution == StateEvolution::Aging {
                9.0
            } else {
                7.0
            };
            assert_eq!(t, want);
        }
    }

    /// The aging law's series and exp_m1 branches meet at w = W_SERIES: θ and dθ/dV continuous.
    #[test]
    fn aging_series_meets_the_closed_form() {
        let law = law(StateEvolution::Aging, CoefficientForm::Logarithmic);
        let (dt, theta) = (1.0, 3.0);
        let v_edge = W_SERIES * law.p.l / dt;
        let (v_below, v_above) = (v_edge * (1.0 - 1e-9), v_edge * (1.0 + 1e-9));
        let below = law.evolve(theta, v_below, dt);
        let above = law.evolve(theta, v_above, dt);
        // θ across the edge along its own slope: no jump above round-off.
        let across = below.0 + below.1 * (v_above - v_below);
        assert!(
            (across - above.0).abs() <= 1e-14 * below.0,
            "{across} vs {}",
            above.0
        );
        assert!((below.1 - above.1).abs() <= 1e-9 * below.1.abs());
    }

    /// μ's partials against central differences; the regularised form matches the logarithmic
    /// one far above V₀·e^(−ψ/a) and is 0 at V = 0.
    #[test]
    fn coefficient_and_partials() {
        // a = 0.01: ψ/a ≈ 60, the regularised form in its logarithmic branch; a = 0.1 and 0.5:
        // asinh itself (ln z < 20).
        for ((evolution, form), a) in LAWS
            .into_iter()
            .flat_map(|l| [(l, 0.01), (l, 0.1), (l, 0.5)])
        {
            let law = law_with_a(evolution, form, a);
            for (v, theta) in [(1e-6, 10.0), (3e-5, 0.2), (1e-9, 1e3), (1e-8, 1.0)] {
                let c = law.coefficient(v, theta);
                let (ev, et) = (1e-6 * v, 1e-6 * theta);
                let dv = (law.coefficient(v + ev, theta).mu - law.coefficient(v - ev, theta).mu)
                    / (2.0 * ev);
                let dth = (law.coefficient(v, theta + et).mu - law.coefficient(v, theta - et).mu)
                    / (2.0 * et);
                assert!(
                    (c.d_rate - dv).abs() <= 1e-6 * dv.abs(),
                    "{form:?} {v}: {} vs {dv}",
                    c.d_rate
                );
                assert!(
                    (c.d_theta - dth).abs() <= 1e-6 * dth.abs(),
                    "{} vs {dth}",
                    c.d_theta
                );
            }
        }
        let plain = law(StateEvolution::Aging, CoefficientForm::Logarithmic);
        let reg = law(StateEvolution::Aging, CoefficientForm::Regularized);
        let (v, theta) = (1e-6, 10.0);
        // ψ/a = 60 + 1.5·ln(1): e^(−ψ/a)-scale corrections are far below round-off.
        assert!((plain.coefficient(v, theta).mu - reg.coefficient(v, theta).mu).abs() < 1e-15);
        assert_eq!(reg.coefficient(0.0, theta).mu, 0.0);
        // μ₀ at V₀ and θ = L/V₀.
        assert!((plain.coefficient(1e-6, 10.0).mu - 0.6).abs() < 1e-15);
    }
}
