//! The complete extended Coulomb model of seed 000 / 003, section 5.2.3, on top of the
//! isotropic constant-μ law of [`super::coulomb`]:
//!
//! - anisotropic friction (μ₁ ≠ μ₂): the problem is solved in the scaled stresses
//!   τ̄_i = (μ̄/μ_i)·τ_i and scaled slips γ̄_i = (μ_i/μ̄)·γ_i (Eq. 5.2.3-10, 5.2.3-11), where it is
//!   isotropic with μ̄ = sqrt((μ₁² + μ₂²)/2); τ_max applies to the scaled stresses; the stick
//!   stiffnesses are k_i = (μ_i/μ̄)²·k̄_s; tangents are scaled back with the same factors;
//! - μ(γ̇_eq, p, θ̄) ([`super::friction_coefficient`]), with the slip rate taken at the end of
//!   the increment, γ̇_eq = Δγ_eq^sl/Δt (backward Euler). In elastic stick the stick stiffness
//!   follows the rate-dependent strength (seed 000 after Eq. 5.2.3-1), k_s = τ_crit(γ̇₀, p, θ̄)/γ_crit
//!   at the start-of-increment rate γ̇₀ = `STATEV(2)` at both ends of the increment; stick while
//!   |γ^pr| ≤ γ_crit; in slip the elastic slip stays γ_crit, s = Δγ_eq^sl = γ_eq^pr − γ_crit and
//!   τ = τ_crit(s/Δt, p, θ̄)·n (Eq. 5.2.3-2), explicit; tangent Eq. 5.2.3-3 (docs/props.md, "The
//!   rate-dependent formulation"). The earlier formulation (rate-free k_s, s from
//!   k_s·(γ_eq^pr − s) = τ_crit(s/Δt), a bracketed Halley solve, [`super::scalar_root`]) stays
//!   for comparisons ([`RateFormulation::RateFreeStiffness`]). Optionally μ is frozen at its
//!   start-of-increment value;
//! - exact stick with rate-dependent slip (Eq. 5.2.3-7 to 5.2.3-9);
//! - Hilber-Hughes-Taylor dynamics: the time increment used for rates is β·Δt/γ;
//! - viscous tangential damping τ_v = c·γ̇ (seed 003), added to the friction stress;
//! - viscous stick for steady-state transport (seed 000): τ = κ_s·γ̇^v, κ_s = τ_crit/γ̇_crit,
//!   γ̇_crit = 2·F_f·ω·R, with R the distance of the point from the spinning axis, or seed 003's
//!   variant γ̇_crit = F_f·ω·R (a fraction of the relative tangential velocity ω·R).
//!
//! Every increment takes the cheapest exact path: isotropic friction skips the scaling, a μ
//! that does not depend on the slip rate skips the local solve, NFDIR = 1 is scalar code.

#![allow(clippy::needless_range_loop)] // index loops mirror the i, j of the seed's equations

use super::contact::{Conditions, Contact, EntryFlag, Increment, Traction, elastic_start_slip};
use super::coulomb::{Coulomb, CoulombState, EXACT_STICK_TANGENT_FLOOR, StickMode};
use super::friction_coefficient::{
    CoefficientLaw, Factor, RateFormulation, RateLaw, STICK_TEST_ROUNDING, decay_phi,
};
use super::parameter_range::positive;
use super::point_law::{Needs, PointAnswer, PointInput, PointLaw, PointResult};
use super::scalar_root::{RootFailure, bracketed_newton, halley_on_known_bracket};
use super::small_vec::{all_finite, diagonal, dot, norm, scale, unit, unit_or_zero};
use crate::{LawError, Outcome};

mod damping;
mod decay;
#[cfg(test)]
mod general_path_tests;
mod steady_transport;

pub use damping::Damping;
pub use steady_transport::{SteadyTransport, ViscousSlipReference};

/// Most iterations the local solve may take before the call asks for a cut-back.
pub const MAX_LOCAL_ITERATIONS: u32 = 100;

/// Hilber-Hughes-Taylor parameters of the host's time integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hht {
    /// α ∈ [−1/2, 0].
    pub alpha: f64,
    /// β > 0.
    pub beta: f64,
    /// γ > 0.
    pub gamma: f64,
}

impl Hht {
    /// HHT parameters; β = 0 and γ = 0 take Abaqus's relations β = (1 − α)²/4, γ = 1/2 − α.
    pub fn new(alpha: f64, beta: f64, gamma: f64) -> Result<Self, LawError> {
        if !(alpha.is_finite() && (-0.5..=0.0).contains(&alpha)) {
            return Err(LawError::Parameter(format!(
                "HHT α = {alpha} must be in [−1/2, 0]"
            )));
        }
        let beta = if beta == 0.0 {
            Hht::default_beta(alpha)
        } else {
            beta
        };
        let gamma = if gamma == 0.0 {
            Hht::default_gamma(alpha)
        } else {
            gamma
        };
        if !(beta.is_finite() && beta > 0.0 && gamma.is_finite() && gamma > 0.0) {
            return Err(LawError::Parameter(format!(
                "HHT β = {beta} and γ = {gamma} must be finite and > 0"
            )));
        }
        Ok(Hht { alpha, beta, gamma })
    }

    /// β when none is given: Abaqus's β = (1 − α)²/4, the one place this default is written
    /// (the `PROPS` schema's entry for `PROPS(15)` names this function).
    #[inline]
    #[must_use]
    pub const fn default_beta(alpha: f64) -> f64 {
        0.25 * (1.0 - alpha) * (1.0 - alpha)
    }

    /// γ when none is given: Abaqus's γ = 1/2 − α (named by the schema's `PROPS(16)`).
    #[inline]
    #[must_use]
    pub const fn default_gamma(alpha: f64) -> f64 {
        0.5 - alpha
    }

    /// The time increment that turns a displacement increment into a velocity: with Newmark's
    /// update ∂v/∂u = γ/(β·Δt), so Δt_rate = β·Δt/γ.
    #[must_use]
    pub fn rate_increment(&self, dtime: f64) -> f64 {
        self.beta * dtime / self.gamma
    }
}

/// The extended Coulomb law. Built from a validated [`Coulomb`] (μ₁, τ_max, γ_crit, stick mode)
/// with the `with_*` methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExtendedCoulomb {
    base: Coulomb,
    mu2: f64,
    coefficient: CoefficientLaw,
    frozen: bool,
    hht: Option<Hht>,
    damping: Option<Damping>,
    transport: Option<SteadyTransport>,
    /// Unit-test hook (`ExtendedCoulomb::with_general_path`): the general path (scaling,
    /// local solve) even where a cheaper one is exact; always false outside this crate's tests.
    general: bool,
    /// How a rate-dependent μ enters the return map (the earlier one only for comparisons).
    formulation: RateFormulation,
}

/// State of the extended law: the Coulomb state plus, with damping, the viscous stress of the
/// last increment (kept so that the friction part of the incoming `TAU` can be recovered).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExtendedState<const N: usize> {
    /// `STATEV(1..3)`.
    pub coulomb: CoulombState,
    /// `STATEV(4..3+NFDIR)` with damping: τ_v at the end of the last increment.
    pub viscous: [f64; N],
}

impl<const N: usize> Default for ExtendedState<N> {
    fn default() -> Self {
        ExtendedState {
            coulomb: CoulombState::default(),
            viscous: [0.0; N],
        }
    }
}

/// Result of [`ExtendedCoulomb::update`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExtendedUpdate<const N: usize> {
    /// Stress (friction + damping) and tangents, or exact stick.
    pub contact: Contact<N>,
    /// ∂τ_a/∂θ̄ (DDTDDT(a,1) = DDTDDT(a,2) = half of it).
    pub ddtdtheta: [f64; N],
    /// State at the end of the increment.
    pub state: ExtendedState<N>,
    /// Reliability and step ratio.
    pub outcome: Outcome,
    /// Iterations of the local solve (0 when none was needed).
    pub iterations: u32,
}

/// Forced sliding in static analysis (seed 003): the stress for a prescribed slip velocity and
/// its linearization split the way complex eigenvalue extraction uses it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForcedSliding<const N: usize> {
    /// τ = τ_crit(|v|, p, θ̄)·v/|v| (0 when v = 0).
    pub tau: [f64; N],
    /// Damping part, `damping[a][b]` = ∂τ_a/∂v_b: τ_crit/|v|·(δ − nn), from the friction forces
    /// perpendicular to the slip, plus nn·∂τ_crit/∂γ̇ when μ depends on the slip rate.
    pub damping: [[f64; N]; N],
    /// Stiffness part, ∂τ_a/∂p = n_a·∂τ_crit/∂p (the host multiplies by the normal stiffness).
    pub stiffness_pressure: [f64; N],
    /// ∂τ_a/∂θ̄.
    pub temperature: [f64; N],
}

/// τ_crit(γ̇, p, θ̄) = min(μ̄·p, τ_max) in the scaled variables, with its partials.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
struct Critical {
    value: f64,
    d_rate: f64,
    d_rate2: f64,
    d_pressure: f64,
    d_temperature: f64,
}

impl Critical {
    /// τ_crit on the shear limit (τ_crit = min(μ̄·p, τ_max), seed 000 §5.2.3): τ_max, which
    /// depends on neither the rate, the pressure nor the temperature.
    #[inline(always)]
    fn at_shear_limit(tau_max: f64) -> Self {
        Critical {
            value: tau_max,
            ..Critical::default()
        }
    }
}

/// The elastic slip at the start of the increment, γ̄^el = τ̄/k̄_s(p₀) = τ̄·γ_crit/τ̄_crit(p₀), and
/// (with `with_theta`) its θ̄-derivative −γ̄^el·(∂τ̄_crit/∂θ̄)/τ̄_crit(p₀); zero when τ̄_crit(p₀) = 0.
/// The derivative is formed without τ̄_crit², which underflows for τ̄_crit below 1.5·10⁻¹⁵⁴ (it
/// gave 0/0 = NaN there, and the increment was refused as an overflow); where γ_crit/τ̄_crit
/// overflows, γ̄^el is (τ̄/τ̄_crit)·γ_crit, finite for a stress within the start cone.
#[inline(always)]
fn elastic_start<const N: usize>(
    tau: &[f64; N],
    gamma_crit: f64,
    start: &Critical,
    with_theta: bool,
) -> ([f64; N], [f64; N]) {
    let elastic = elastic_start_slip(tau, gamma_crit, start.value);
    let d_theta = if with_theta && start.value > 0.0 {
        scale(&elastic, -(start.d_temperature / start.value))
    } else {
        [0.0; N]
    };
    (elastic, d_theta)
}

/// The isotropic problem in scaled variables, as seen by one increment: what every stick mode
/// reads besides the host's increment.
struct Scaled<const N: usize> {
    /// Friction stress at the start (scaled).
    tau: [f64; N],
    /// Relative motion increment (scaled).
    dgam: [f64; N],
    /// Lagrange stress (scaled).
    taulm: [f64; N],
    /// μ̄, the coefficient of the scaled (isotropic) problem.
    mbar: f64,
    /// θ̄, the temperature μ reads.
    theta: f64,
    /// The time increment of rates: Δt statically, β·Δt/γ with HHT.
    rate_dt: f64,
    /// γ̇₀ = `STATEV(2)`, the slip rate of the previous increment.
    start_rate: f64,
}

/// The scaled answer before unscaling.
struct ScaledTraction<const N: usize> {
    traction: Traction<N>,
    ddtdtheta: [f64; N],
    /// Scaled equivalent slip increment (the s of the μ law).
    slip_eq: f64,
    iterations: u32,
}

impl<const N: usize> ScaledTraction<N> {
    /// An answer in closed form (no iteration): stick, frictionless slip, exact stick and
    /// steady transport's viscous answers.
    #[inline(always)]
    fn closed_form(traction: Traction<N>, ddtdtheta: [f64; N], slip_eq: f64) -> Self {
        ScaledTraction {
            traction,
            ddtdtheta,
            slip_eq,
            iterations: 0,
        }
    }
}

impl ExtendedCoulomb {
    /// The extended law with everything off: behaves exactly as `base`. The one struct
    /// literal: the parts are switched on by the `with_*` setters (`PROPS` readers, whose
    /// entries are already validated, use the ones that only store their argument).
    #[must_use]
    pub fn new(base: Coulomb) -> Self {
        // Isotropic (μ₂ = μ₁), constant μ, not frozen, no HHT, no damping.
        ExtendedCoulomb {
            base,
            mu2: base.mu(),
            coefficient: CoefficientLaw::default(),
            frozen: false,
            hht: None,
            damping: None,
            transport: None,
            general: false,
            formulation: RateFormulation::RateFollowingStiffness,
        }
    }

    /// Viscous stick for steady-state transport instead of elastic or exact stick.
    #[must_use]
    pub fn with_steady_transport(mut self, transport: Option<SteadyTransport>) -> Self {
        self.transport = transport;
        self
    }

    /// μ₂ already validated by the caller (a `PROPS` reader: μ₂ = μ₁ when isotropic);
    /// [`Self::with_second_coefficient`] checks it.
    #[must_use]
    pub(crate) fn with_validated_mu2(mut self, mu2: f64) -> Self {
        self.mu2 = mu2;
        self
    }

    /// The steady-transport parameters, if that mode is on.
    #[must_use]
    pub fn steady_transport(&self) -> Option<SteadyTransport> {
        self.transport
    }

    /// Anisotropic friction: μ₂ > 0 in direction 2 (μ₁ = the base μ, which must be > 0).
    pub fn with_second_coefficient(mut self, mu2: f64) -> Result<Self, LawError> {
        positive("μ₂", mu2)?;
        if mu2 != self.base.mu() && self.base.mu() <= 0.0 {
            return Err(LawError::Parameter(format!(
                "anisotropic friction needs μ₁ > 0 as well (μ₁ = {}, μ₂ = {mu2})",
                self.base.mu()
            )));
        }
        self.mu2 = mu2;
        Ok(self)
    }

    /// μ(γ̇, p, θ̄) factors.
    #[must_use]
    pub fn with_coefficient_law(mut self, coefficient: CoefficientLaw) -> Self {
        self.coefficient = coefficient;
        self
    }

    /// Freeze μ at its start-of-increment value (explicit in the slip rate).
    #[must_use]
    pub fn with_frozen_coefficient(mut self, frozen: bool) -> Self {
        self.frozen = frozen;
        self
    }

    /// Dynamics with HHT time integration.
    #[must_use]
    pub fn with_hht(mut self, hht: Option<Hht>) -> Self {
        self.hht = hht;
        self
    }

    /// Viscous tangential damping.
    #[must_use]
    pub fn with_damping(mut self, damping: Option<Damping>) -> Self {
        self.damping = damping;
        self
    }

    /// How a rate-dependent μ enters the return map: the default
    /// [`RateFormulation::RateFollowingStiffness`], or the earlier rate-free stick stiffness
    /// (for comparisons only: it is unstable under velocity weakening, docs/props.md). No
    /// `PROPS` entry selects it.
    #[must_use]
    pub fn with_rate_formulation(mut self, formulation: RateFormulation) -> Self {
        self.formulation = formulation;
        self
    }

    /// The rate formulation in use.
    #[must_use]
    pub fn rate_formulation(&self) -> RateFormulation {
        self.formulation
    }

    /// Unit tests only: takes the general path (scaling even when isotropic, the local solve
    /// even when μ is constant), so a test compares the cheap paths with it on the same law
    /// (`coulomb_extended/general_path_tests.rs`); like `props::force_careful_path`, it does not
    /// exist outside `cargo test` of this crate.
    #[cfg(test)]
    #[must_use]
    pub(crate) fn with_general_path(mut self) -> Self {
        self.general = true;
        self
    }

    /// The base parameters (μ₁, τ_max, γ_crit, stick mode).
    #[must_use]
    pub fn base(&self) -> &Coulomb {
        &self.base
    }

    /// μ₂ (equal to μ₁ when isotropic).
    #[must_use]
    pub fn mu2(&self) -> f64 {
        self.mu2
    }

    /// The μ factors.
    #[must_use]
    pub fn coefficient_law(&self) -> &CoefficientLaw {
        &self.coefficient
    }

    /// The damping, if any.
    #[must_use]
    pub fn damping(&self) -> Option<Damping> {
        self.damping
    }

    /// True when the law reads the temperature.
    #[must_use]
    pub fn reads_temperature(&self) -> bool {
        self.coefficient.is_temperature_dependent()
    }

    /// `STATEV` entries needed for NFDIR = `nfdir`.
    #[must_use]
    pub fn nstatv(&self, nfdir: usize) -> usize {
        CoulombState::NSTATV + if self.damping.is_some() { nfdir } else { 0 }
    }

    /// True when nothing beyond the base law is switched on.
    #[must_use]
    pub fn is_plain(&self) -> bool {
        self.mu2 == self.base.mu()
            && self.coefficient.is_constant()
            && self.damping.is_none()
            && self.transport.is_none()
            && !self.general
    }

    /// μ in directions 1 and 2 and their derivatives with respect to γ̇_eq, p and θ̄ (for
    /// FRIC_COEF): (μ₁, μ₂, ∂/∂γ̇ of each, ∂/∂p of each, ∂/∂θ̄ of each).
    #[must_use]
    pub fn coefficients(&self, rate: f64, pressure: f64, temperature: f64) -> [[f64; 2]; 4] {
        // μ_i·f with μ_i multiplied in first (`CoefficientLaw::scaled`).
        let f1 = self
            .coefficient
            .scaled(self.base.mu(), rate, pressure, temperature);
        let f2 = if self.mu2 == self.base.mu() {
            f1
        } else {
            self.coefficient
                .scaled(self.mu2, rate, pressure, temperature)
        };
        [
            [f1.value, f2.value],
            [f1.d_rate, f2.d_rate],
            [f1.d_pressure, f2.d_pressure],
            [f1.d_temperature, f2.d_temperature],
        ]
    }

    /// Scaling factors a_i = μ_i/μ̄ and μ̄ (Eq. 5.2.3-10). NFDIR = 1 has direction 1 only: μ₁.
    fn scaling<const N: usize>(&self) -> ([f64; N], f64) {
        let m1 = self.base.mu();
        if N == 1 || (self.mu2 == m1 && !self.general) {
            return ([1.0; N], m1);
        }
        let mbar = (0.5 * (m1 * m1 + self.mu2 * self.mu2)).sqrt();
        let mut a = [1.0; N];
        a[0] = m1 / mbar;
        a[1] = self.mu2 / mbar;
        (a, mbar)
    }

    /// τ_crit = min(μ̄·f(γ̇, p, θ̄)·p, τ_max) and its partials; 0 for p < 0.
    #[inline(always)]
    fn critical(&self, mbar: f64, rate: f64, p: f64, theta: f64) -> Critical {
        if p < 0.0 {
            return Critical::default();
        }
        // μ̄·f with μ̄ multiplied in first, so that f cannot underflow where μ̄·f is a normal
        // number (finding C3, docs/fuzzing.md).
        let Factor {
            value,
            d_rate,
            d_rate2,
            d_pressure,
            d_temperature,
        } = self.coefficient.scaled(mbar, rate, p, theta);
        let mu = value;
        let tau_max = self.base.shear_limit().unwrap_or(f64::INFINITY);
        if mu * p >= tau_max {
            Critical::at_shear_limit(tau_max)
        } else {
            Critical {
                value: mu * p,
                d_rate: d_rate * p,
                d_rate2: d_rate2 * p,
                d_pressure: mu + d_pressure * p,
                d_temperature: d_temperature * p,
            }
        }
    }

    /// Forced sliding (seed 003): the frictional stress for the prescribed slip velocity `v`
    /// (independent of the displacements), and its linearization split into the damping part
    /// (∂τ/∂v) and the stiffness part (∂τ/∂p). With anisotropy the scaled velocity of
    /// Eq. 5.2.3-11 sets the direction and the rate. A zero velocity gives zero stress and
    /// zero parts (no direction).
    pub fn forced_sliding<const N: usize>(
        &self,
        velocity: &[f64; N],
        pressure: f64,
        temperature: f64,
    ) -> Result<ForcedSliding<N>, LawError> {
        if !(all_finite(velocity) && pressure.is_finite() && temperature.is_finite()) {
            return Err(LawError::Input(
                "slip velocity, pressure or temperature is NaN or infinite".into(),
            ));
        }
        let (a, mbar) = self.scaling::<N>();
        let v = multiply(velocity, &a);
        let speed = norm(&v);
        let zero = ForcedSliding {
            tau: [0.0; N],
            damping: [[0.0; N]; N],
            stiffness_pressure: [0.0; N],
            temperature: [0.0; N],
        };
        if speed == 0.0 {
            return Ok(zero);
        }
        let n = unit(&v, speed);
        let rate = if self.frozen { 0.0 } else { speed };
        let c = self.critical(mbar, rate, pressure, temperature);
        let d_rate = if self.frozen { 0.0 } else { c.d_rate };
        let mut out = zero;
        for i in 0..N {
            out.tau[i] = a[i] * n[i] * c.value;
            out.stiffness_pressure[i] = a[i] * n[i] * c.d_pressure;
            out.temperature[i] = a[i] * n[i] * c.d_temperature;
            for j in 0..N {
                let delta = if i == j { 1.0 } else { 0.0 };
                let proj = if N == 1 { 0.0 } else { delta - n[i] * n[j] };
                out.damping[i][j] = a[i] * a[j] * (c.value / speed * proj + n[i] * n[j] * d_rate);
            }
        }
        let finite = all_finite(&out.tau)
            && all_finite(&out.stiffness_pressure)
            && all_finite(&out.temperature)
            && out.damping.iter().all(all_finite);
        if finite {
            Ok(out)
        } else {
            Err(LawError::Numerical("forced sliding overflowed".into()))
        }
    }

    /// Integrates one increment.
    pub fn update<const N: usize>(
        &self,
        inc: &Increment<N>,
        conditions: &Conditions,
        state: &ExtendedState<N>,
    ) -> Result<ExtendedUpdate<N>, LawError> {
        if let Some(decay) = self.lean_decay::<N>() {
            return self.isotropic_decay(inc, conditions.temperature, state, decay);
        }
        if self.is_plain() && self.hht.is_none() {
            // Cheapest path: the isotropic constant-μ law itself.
            let up = self.base.update(inc, &state.coulomb)?;
            return Ok(ExtendedUpdate {
                contact: up.contact,
                ddtdtheta: [0.0; N],
                state: ExtendedState {
                    coulomb: up.state,
                    viscous: [0.0; N],
                },
                outcome: up.outcome,
                iterations: 0,
            });
        }
        self.check_inputs(inc, conditions, state)?;
        let stick = self.base.stick();
        let rate_dt = self.rate_increment(inc.dtime)?;
        let theta = conditions.temperature;

        // Friction part of the incoming stress: TAU minus the (rotated) viscous stress.
        let mut tau_friction = inc.tau;
        if self.damping.is_some() {
            let v = rotate(&conditions.drot, &state.viscous);
            for i in 0..N {
                tau_friction[i] -= v[i];
            }
        }
        let (a, mbar) = self.scaling::<N>();
        // Isotropic friction skips the scaling (a = 1).
        let anisotropic = a.iter().any(|x| *x != 1.0);
        let (tau, dgam, taulm) = if anisotropic {
            (
                divide(&tau_friction, &a),
                multiply(&inc.dgam, &a),
                divide(&inc.taulm, &a),
            )
        } else {
            (tau_friction, inc.dgam, inc.taulm)
        };
        let scaled = Scaled {
            tau,
            dgam,
            taulm,
            mbar,
            theta,
            rate_dt,
            start_rate: state.coulomb.slip_rate,
        };

        let answer = match stick {
            _ if self.transport.is_some() => Some(self.viscous_stick(inc, &scaled, conditions)?),
            StickMode::Rough => None,
            StickMode::Elastic => {
                let gamma_crit = self.base.critical_slip_for(inc.characteristic_length)?;
                Some(self.elastic_stick(inc, &scaled, gamma_crit)?)
            }
            StickMode::Exact => {
                let gamma_crit = self.base.critical_slip_for(inc.characteristic_length)?;
                self.exact_stick(inc, &scaled, gamma_crit)
            }
        };

        let Some(scaled_answer) = answer else {
            return Ok(ExtendedUpdate {
                contact: Contact::ExactStick,
                ddtdtheta: [0.0; N],
                state: ExtendedState {
                    coulomb: state.coulomb.held(),
                    viscous: [0.0; N],
                },
                outcome: Outcome::CONVERGED,
                iterations: 0,
            });
        };
        let ScaledTraction {
            traction: t,
            ddtdtheta,
            slip_eq,
            iterations,
        } = scaled_answer;
        // Back to the actual stresses and slips: τ_i = a_i τ̄_i, Δγ_i^sl = Δγ̄_i^sl/a_i, and the
        // linearized equations scaled with the same factors.
        let (mut out, ddtdtheta) = if anisotropic {
            let mut out = Traction {
                tau: multiply(&t.tau, &a),
                ddtddg: t.ddtddg,
                ddtddp: multiply(&t.ddtddp, &a),
                dslip: divide(&t.dslip, &a),
                sed: t.sed,
                sfd: t.sfd,
            };
            for i in 0..N {
                for j in 0..N {
                    out.ddtddg[i][j] *= a[i] * a[j];
                }
            }
            (out, multiply(&ddtdtheta, &a))
        } else {
            (t, ddtdtheta)
        };
        // Viscous damping: τ_v = c γ̇ = c Δγ/Δt_rate, tangent c/Δt_rate (seed 003).
        let mut viscous = [0.0; N];
        if let Some(d) = self.damping {
            let c = d.c0 / rate_dt;
            viscous = scale(&inc.dgam, c);
            for i in 0..N {
                out.tau[i] += viscous[i];
                out.ddtddg[i][i] += c;
            }
            out.sfd += dot(&viscous, &inc.dgam);
        }
        check_outputs(&out, &ddtdtheta)?;
        // |Δγ^sl| of the actual (unscaled) slip for the path, the scaled Δγ̄_eq^sl for the rate;
        // both saturate at f64::MAX (docs/props.md), as the plain law's do.
        let coulomb = state
            .coulomb
            .after_motion(norm(&out.dslip), slip_eq, rate_dt);
        Ok(ExtendedUpdate {
            contact: Contact::Motion(out),
            ddtdtheta,
            state: ExtendedState { coulomb, viscous },
            outcome: Outcome::CONVERGED,
            iterations,
        })
    }

    /// The time increment used for slip rates: Δt statically, β·Δt/γ with HHT. A rate law
    /// (not frozen) or damping needs it positive.
    fn rate_increment(&self, dtime: f64) -> Result<f64, LawError> {
        let dt = match self.hht {
            Some(h) => h.rate_increment(dtime),
            None => dtime,
        };
        let needs_rate = (self.coefficient.is_rate_dependent() && !self.frozen)
            || self.damping.is_some()
            || self.transport.is_some();
        if needs_rate && (dt.is_nan() || dt <= 0.0) {
            return Err(no_rate_increment(dtime));
        }
        Ok(dt)
    }

    fn check_inputs<const N: usize>(
        &self,
        inc: &Increment<N>,
        conditions: &Conditions,
        state: &ExtendedState<N>,
    ) -> Result<(), LawError> {
        // x·0 is ±0 for finite x and NaN otherwise: one test for every input on the common
        // path (TAULM, TEMP and DROT are 0/identity when not read); the names only on failure.
        let mut probe = inc.pressure * 0.0 + inc.dpressure * 0.0 + inc.dtime * 0.0;
        for i in 0..N {
            probe += inc.tau[i] * 0.0 + inc.dgam[i] * 0.0 + state.viscous[i] * 0.0;
        }
        if self.base.stick() == StickMode::Exact && inc.entry == EntryFlag::ExactStick {
            for x in &inc.taulm {
                probe += x * 0.0;
            }
        }
        probe += conditions.temperature * 0.0;
        for x in conditions.drot.iter().flatten() {
            probe += x * 0.0;
        }
        if probe == 0.0 && state.coulomb.slip_rate >= 0.0 {
            return Ok(());
        }
        // An input the law does not read (TEMP without a temperature law, DROT without damping)
        // may be what upset the probe: then there is nothing to refuse.
        self.name_bad_input(inc, conditions, state)
            .map_or(Ok(()), Err)
    }

    /// The first input the law reads that is NaN, infinite or out of range, as the refusal.
    #[cold]
    #[inline(never)]
    fn name_bad_input<const N: usize>(
        &self,
        inc: &Increment<N>,
        conditions: &Conditions,
        state: &ExtendedState<N>,
    ) -> Option<LawError> {
        let named = [
            ("PRESS", inc.pressure.is_finite()),
            ("DPRESS", inc.dpressure.is_finite()),
            ("DGAM", all_finite(&inc.dgam)),
            ("TAU", all_finite(&inc.tau)),
            (
                "TAULM",
                !(self.base.stick() == StickMode::Exact && inc.entry == EntryFlag::ExactStick)
                    || all_finite(&inc.taulm),
            ),
            ("DTIME", inc.dtime.is_finite()),
            (
                "TEMP",
                !self.reads_temperature() || conditions.temperature.is_finite(),
            ),
            (
                "DROT",
                self.damping.is_none() || conditions.drot.iter().flatten().all(|x| x.is_finite()),
            ),
            ("STATEV(4..) (viscous stress)", all_finite(&state.viscous)),
            (
                "STATEV(2) (slip rate, must be ≥ 0)",
                state.coulomb.slip_rate >= 0.0,
            ),
        ];
        named
            .iter()
            .find(|(_, ok)| !ok)
            .map(|(what, _)| LawError::Input(format!("{what} is NaN, infinite or out of range")))
    }

    /// Elastic stick with the rate-dependent return map, in scaled variables.
    fn elastic_stick<const N: usize>(
        &self,
        inc: &Increment<N>,
        s: &Scaled<N>,
        gamma_crit: f64,
    ) -> Result<ScaledTraction<N>, LawError> {
        let &Scaled {
            mbar,
            theta,
            rate_dt,
            start_rate,
            ..
        } = s;
        let p = inc.pressure;
        let p0 = inc.pressure - inc.dpressure;
        let frozen = self.frozen && self.coefficient.is_rate_dependent();
        let rate_law = self.coefficient.is_rate_dependent() && !frozen;
        // The rate-following stick stiffness (docs/props.md): k̄_s = τ̄_crit(γ̇₀, ·)/γ_crit at the
        // start-of-increment rate γ̇₀ = `STATEV(2)` (seed 000 after Eq. 5.2.3-1: k_s follows
        // τ_crit), the same rate at both ends of a stick increment, so that an increment without
        // motion leaves τ̄ as it was. The earlier formulation: the rate-free τ̄_crit(0, ·).
        let following = rate_law && self.formulation == RateFormulation::RateFollowingStiffness;
        let stiffness_rate = if following { start_rate } else { 0.0 };
        // Stick stiffness k̄_s = τ̄_crit(γ̇_k, p, θ̄)/γ_crit at the end and at the start.
        let k = self.critical(mbar, stiffness_rate, p, theta);
        let k0 = self.critical(mbar, stiffness_rate, p0, theta);
        // γ̄^el = τ̄/k̄_s(p₀); its θ̄-derivative (the start uses the same θ̄: FRIC has no ΔTEMP).
        let trial = ElasticTrial::new(&s.tau, &s.dgam, gamma_crit, &k0, true);
        let g = trial.g;
        let stiffness = k.value / gamma_crit;
        let (stiffness_p, stiffness_theta) =
            (k.d_pressure / gamma_crit, k.d_temperature / gamma_crit);
        // The critical stress the stick test uses: at zero rate, or frozen at the start rate.
        let stick_crit = if frozen {
            self.critical(mbar, start_rate, p, theta)
        } else {
            k
        };
        if trial.sticks(following, stiffness, stick_crit.value) || stiffness <= 0.0 {
            let rest = || {
                (following && start_rate > 0.0).then(|| self.critical(mbar, 0.0, p, theta).value)
            };
            return Ok(trial.no_slip(following, &k, rest));
        }

        // Slip: k̄_s (γ̄_eq^pr − s) = τ̄_crit(s/Δt, p, θ̄).
        let n = unit(&trial.predictor, g);
        let (slip_eq, crit, iterations) = if following {
            // Eq. 5.2.3-2: the elastic slip stays γ_crit, Δγ̄_eq^sl = γ̄_eq^pr − γ_crit, and
            // τ̄ = τ̄_crit(Δγ̄_eq^sl/Δt, p, θ̄)·n: explicit, one answer (also with τ_max).
            let s_eq = g - gamma_crit;
            (s_eq, self.critical(mbar, s_eq / rate_dt, p, theta), 0)
        } else if rate_law {
            // One division per solve, not three per iteration.
            let per_dt = 1.0 / rate_dt;
            // F(0) = k̄_s γ̄_eq^pr − τ̄_crit(0) > 0 (slip) and F(γ̄_eq^pr) = −τ̄_crit ≤ 0: the
            // root is bracketed. Start from the slip at the start-of-increment rate (exact in
            // steady sliding), else from the rate-free answer s = γ̄_eq^pr − γ_crit; stop at the
            // round-off level of F.
            let guess = if start_rate > 0.0 {
                start_rate * rate_dt
            } else {
                g - gamma_crit
            };
            let x_tol = 4.0 * f64::EPSILON * g;
            let f_tol = 8.0 * f64::EPSILON * (stiffness * g + k.value);
            let split = if p >= 0.0 {
                self.coefficient.split_decay(p, theta)
            } else {
                None
            };
            if let Some((factor, law)) = split {
                self.solve_decay(
                    factor,
                    law,
                    mbar,
                    p,
                    g,
                    (stiffness, 1.0 / stiffness),
                    1.0 / rate_dt,
                    guess,
                    f_tol,
                )
                .map_err(|e| local_solve_failed(e, g, rate_dt))?
            } else {
                // The last evaluation is kept: the solve usually stops at an evaluated point.
                let mut last = (f64::NAN, Critical::default());
                let residual = |x: f64| {
                    let c = self.critical(mbar, x * per_dt, p, theta);
                    last = (x, c);
                    (
                        stiffness * (g - x) - c.value,
                        -stiffness - c.d_rate * per_dt,
                        -c.d_rate2 * per_dt * per_dt,
                    )
                };
                let root = halley_on_known_bracket(
                    residual,
                    g,
                    0.0,
                    guess,
                    x_tol,
                    f_tol,
                    MAX_LOCAL_ITERATIONS,
                )
                .map_err(|e| local_solve_failed(e, g, rate_dt))?;
                let c = if last.0 == root.x {
                    last.1
                } else {
                    self.critical(mbar, root.x * per_dt, p, theta)
                };
                (root.x, c, root.iterations)
            }
        } else if self.general {
            // The general path with a rate-free μ: the same solve (converges in one step).
            let c = stick_crit;
            let root = bracketed_newton(
                |x| (stiffness * (g - x) - c.value, -stiffness),
                0.0,
                g,
                g,
                4.0 * f64::EPSILON * g,
                MAX_LOCAL_ITERATIONS,
            )
            .map_err(|e| local_solve_failed(e, g, rate_dt))?;
            (root.x, Critical { d_rate: 0.0, ..c }, root.iterations)
        } else {
            // Rate-free (constant or frozen μ): s = γ̄_eq^pr − τ̄_crit/k̄_s, explicit.
            let c = Critical {
                d_rate: 0.0,
                ..stick_crit
            };
            let s_eq = if frozen {
                g - c.value / stiffness
            } else {
                g - gamma_crit
            };
            (s_eq, c, 0)
        };
        let t = crit.value;
        // Rate term per unit slip: ∂τ̄_crit/∂s = (∂τ̄_crit/∂γ̇)/Δt.
        let t_s = if rate_law { crit.d_rate / rate_dt } else { 0.0 };
        let (ds_dg, ds_dp, ds_dtheta) = if following {
            // s = G − γ_crit.
            (1.0, 0.0, 0.0)
        } else {
            let d = slip_stiffness(stiffness, t_s)?;
            // Implicit derivatives of s from k̄_s (G − s) = τ̄_crit(s/Δt, p, θ̄).
            (
                stiffness / d,
                (stiffness_p * (g - slip_eq) - crit.d_pressure) / d,
                (stiffness_theta * (g - slip_eq) - crit.d_temperature) / d,
            )
        };
        let transverse = t / g;
        // Eq. 5.2.3-3 in this formulation: (δ − nn) τ̄_crit/γ̄_eq^pr + nn (∂τ̄_crit/∂s) ∂s/∂G.
        let ddtddg = rate_slip_tangent(&n, transverse, t_s, ds_dg);
        let dtau_dp = t_s * ds_dp + crit.d_pressure;
        let ddtdtheta = trial.slip_temperature_tangent(
            &n,
            transverse,
            t_s,
            (ds_dg, ds_dtheta),
            crit.d_temperature,
        );
        let sed = slip_energy(t, following, gamma_crit, stiffness);
        Ok(ScaledTraction {
            traction: Traction::sliding(&n, t, ddtddg, dtau_dp, slip_eq, sed),
            ddtdtheta,
            slip_eq,
            iterations,
        })
    }

    /// Exact stick (LM = 1) with rate-dependent slip, Eq. 5.2.3-7 to 5.2.3-9, scaled.
    fn exact_stick<const N: usize>(
        &self,
        inc: &Increment<N>,
        s: &Scaled<N>,
        gamma_crit: f64,
    ) -> Option<ScaledTraction<N>> {
        let p = inc.pressure;
        let frozen = self.frozen && self.coefficient.is_rate_dependent();
        let stick_crit = self.critical(s.mbar, if frozen { s.start_rate } else { 0.0 }, p, s.theta);
        let direction_source = match inc.entry {
            EntryFlag::ExactStick => {
                if norm(&s.taulm) <= stick_crit.value {
                    return None;
                }
                s.taulm
            }
            EntryFlag::Motion => {
                // Δγ·τ(t) < 0 is scale-invariant: Σ a_i Δγ_i τ_i/a_i.
                if dot(&s.dgam, &s.tau) < 0.0 {
                    return None;
                }
                if norm(&s.dgam) > 0.0 { s.dgam } else { s.tau }
            }
        };
        let n = unit_or_zero(&direction_source);
        // All relative motion is slip: s = |Δγ̄|, γ̇ = s/Δt.
        let slip_eq = norm(&s.dgam);
        let rate_law = self.coefficient.is_rate_dependent() && !frozen;
        let crit = if rate_law {
            self.critical(s.mbar, slip_eq / s.rate_dt, p, s.theta)
        } else {
            stick_crit
        };
        let t = crit.value;
        let t_s = if rate_law {
            crit.d_rate / s.rate_dt
        } else {
            0.0
        };
        let m = if slip_eq > 0.0 {
            unit(&s.dgam, slip_eq)
        } else {
            [0.0; N]
        };
        let floor = EXACT_STICK_TANGENT_FLOOR * gamma_crit;
        let transverse = t / slip_eq.max(floor);
        let mut ddtddg = [[0.0; N]; N];
        for i in 0..N {
            for j in 0..N {
                let delta = if i == j { 1.0 } else { 0.0 };
                let proj = if N == 1 { 0.0 } else { delta - n[i] * n[j] };
                // Eq. 5.2.3-8: τ_crit/Δγ_eq (δ − nn) + n n (p/Δt) ∂μ/∂γ̇.
                ddtddg[i][j] = transverse * proj + n[i] * m[j] * t_s;
            }
        }
        let tau = scale(&n, t);
        Some(ScaledTraction::closed_form(
            Traction {
                tau,
                ddtddg,
                ddtddp: scale(&n, crit.d_pressure),
                dslip: s.dgam,
                sed: 0.0,
                sfd: dot(&tau, &s.dgam).max(0.0),
            },
            scale(&n, crit.d_temperature),
            slip_eq,
        ))
    }
}

/// `SED` of the slip answer τ̄ = t·n (Eq. 5.2.3-2): |τ̄|²/(2k̄_s), with k̄_s = t/γ_crit at the end
/// when rate-following (the elastic slip stays γ_crit), the start stiffness otherwise.
#[inline(always)]
fn slip_energy(t: f64, following: bool, gamma_crit: f64, stiffness: f64) -> f64 {
    if following {
        0.5 * t * gamma_crit
    } else {
        0.5 * t * t / stiffness
    }
}

/// No friction (τ̄_crit = 0: p ≤ 0) and |γ̄^pr| > γ_crit: zero stress, all motion beyond γ_crit
/// is slip along γ̄^pr; ∂τ̄/∂p = n·∂τ̄_crit/∂p (`dcrit_dp`, the right derivative at p = 0).
#[inline(always)]
fn frictionless_slip<const N: usize>(
    predictor: &[f64; N],
    g: f64,
    gamma_crit: f64,
    dcrit_dp: f64,
) -> ScaledTraction<N> {
    let n = unit(predictor, g);
    let slip_eq = g - gamma_crit;
    ScaledTraction::closed_form(
        Traction::stress_free(scale(&n, dcrit_dp), scale(&n, slip_eq)),
        [0.0; N],
        slip_eq,
    )
}

/// The elastic predictor of the scaled problem, γ̄^pr = γ̄^el + Δγ̄ with γ̄^el from the start
/// stress ([`elastic_start`]), its length `g` = |γ̄^pr| and ∂γ̄^el/∂θ̄; what the stick test and
/// the answers without slip read (the general and the decay paths). `Copy`, and the answers take
/// it by value: by reference it was kept in a stack slot of its own (a few instructions per
/// call on the rate law's hot path, docs/architecture.md).
#[derive(Clone, Copy)]
struct ElasticTrial<const N: usize> {
    predictor: [f64; N],
    g: f64,
    d_elastic_dtheta: [f64; N],
    gamma_crit: f64,
}

impl<const N: usize> ElasticTrial<N> {
    /// γ̄^pr from the start stress `tau` (with k̄_s(p₀) = `start`/γ_crit) and the motion `dgam`.
    #[inline(always)]
    fn new(
        tau: &[f64; N],
        dgam: &[f64; N],
        gamma_crit: f64,
        start: &Critical,
        with_theta: bool,
    ) -> Self {
        let (elastic_start, d_elastic_dtheta) = elastic_start(tau, gamma_crit, start, with_theta);
        let mut predictor = elastic_start;
        for i in 0..N {
            predictor[i] += dgam[i];
        }
        ElasticTrial {
            g: norm(&predictor),
            predictor,
            d_elastic_dtheta,
            gamma_crit,
        }
    }

    /// The stick test with k̄_s = `stiffness`. Rate-following: τ̄_eq ≤ τ̄_crit ⇔ |γ̄^el| ≤ γ_crit,
    /// tested on the slips (exact: the slip of the increment is then γ̄_eq^pr − γ_crit > 0,
    /// never a rounded 0 or below); otherwise k̄_s·|γ̄^pr| ≤ `stick_crit` (τ̄_crit at zero rate,
    /// or frozen at the start rate).
    #[inline(always)]
    fn sticks(&self, following: bool, stiffness: f64, stick_crit: f64) -> bool {
        if following {
            self.g <= self.gamma_crit * (1.0 + STICK_TEST_ROUNDING)
        } else {
            stiffness * self.g <= stick_crit
        }
    }

    /// The answer without frictional slip, where the stick test passes or k̄_s ≤ 0: with
    /// k̄_s ≤ 0 and |γ̄^pr| > γ_crit, [`frictionless_slip`]; otherwise elastic stick
    /// (Eq. 5.2.3-1) with k̄_s = τ̄_crit(γ̇_k, p, θ̄)/γ_crit, `k` = τ̄_crit and its partials:
    /// τ̄ = k̄_s·γ̄^pr ([`on_strength`], on the strength beyond γ_crit when `following`),
    /// ∂τ̄/∂Δγ̄ = k̄_s·δ, ∂τ̄/∂p = γ̄^pr·∂k̄_s/∂p and ∂τ̄/∂θ̄ = γ̄^pr·∂k̄_s/∂θ̄ + k̄_s·∂γ̄^el/∂θ̄.
    /// `SED` = ½k̄_s|γ̄^pr|², or with `rest()` = Some(τ̄_crit at rest) as the next increment
    /// reads τ̄ ([`rest_energy`]: the point ends at rest but k̄_s is not the rate-free
    /// stiffness); `rest` is called only for a stick answer.
    #[inline(always)]
    fn no_slip(
        self,
        following: bool,
        k: &Critical,
        rest: impl FnOnce() -> Option<f64>,
    ) -> ScaledTraction<N> {
        let (predictor, g, gamma_crit) = (&self.predictor, self.g, self.gamma_crit);
        let stiffness = k.value / gamma_crit;
        if stiffness <= 0.0 && g > gamma_crit {
            return frictionless_slip(predictor, g, gamma_crit, k.d_pressure);
        }
        let (stiffness_p, stiffness_theta) =
            (k.d_pressure / gamma_crit, k.d_temperature / gamma_crit);
        let sed = match rest() {
            Some(rest_strength) => rest_energy(stiffness * g, rest_strength, gamma_crit),
            None => 0.5 * stiffness * g * g,
        };
        let beyond = following && g > gamma_crit;
        let mut ddtdtheta = scale(predictor, stiffness_theta);
        for i in 0..N {
            ddtdtheta[i] += stiffness * self.d_elastic_dtheta[i];
        }
        ScaledTraction::closed_form(
            Traction::sticking(
                on_strength(predictor, beyond, stiffness, k.value),
                diagonal(stiffness),
                scale(predictor, stiffness_p),
                sed,
            ),
            ddtdtheta,
            0.0,
        )
    }

    /// ∂τ̄/∂θ̄ of the slip answer τ̄ = t·n: through the start elastic slip, v = ∂γ̄^pr/∂θ̄
    /// (`d_elastic_dtheta`), which turns n (the transverse part (t/γ̄_eq^pr)·(v − n(n·v)), 0 in
    /// 2-D), and through t = τ̄_crit(s, θ̄) along n:
    /// dt/dθ̄ = (∂τ̄_crit/∂s)·(∂s/∂G·n·v + ∂s/∂θ̄) + ∂τ̄_crit/∂θ̄.
    #[inline(always)]
    fn slip_temperature_tangent(
        self,
        n: &[f64; N],
        transverse: f64,
        t_s: f64,
        (ds_dg, ds_dtheta): (f64, f64),
        dcrit_dtheta: f64,
    ) -> [f64; N] {
        let v = &self.d_elastic_dtheta;
        let nv = dot(n, v);
        let dt_dtheta = t_s * (ds_dg * nv + ds_dtheta) + dcrit_dtheta;
        let mut ddtdtheta = [0.0; N];
        for i in 0..N {
            let proj_v = if N == 1 { 0.0 } else { v[i] - n[i] * nv };
            ddtdtheta[i] = transverse * proj_v + n[i] * dt_dtheta;
        }
        ddtdtheta
    }
}

/// The stick stress k̄_s·γ̄^pr; with `beyond` (rate-following, |γ̄^pr| within the rounding
/// allowance above γ_crit, `STICK_TEST_ROUNDING`) the strength itself along γ̄^pr, so that a
/// stick stress is never above τ̄_crit. (Frozen μ sticks beyond γ_crit when it strengthens.)
#[inline(always)]
pub(super) fn on_strength<const N: usize>(
    predictor: &[f64; N],
    beyond: bool,
    stiffness: f64,
    strength: f64,
) -> [f64; N] {
    if beyond {
        scale(&unit(predictor, norm(predictor)), strength)
    } else {
        scale(predictor, stiffness)
    }
}

/// `SED` of a stick increment after a slip (rate-following): the elastic energy as the next
/// increment reads the stress, ½|τ̄|²·γ_crit/τ̄_crit(0), since a stick increment leaves the
/// point at rest (`STATEV(2)` = 0) and the next one recovers γ̄^el with the rate-free stiffness.
#[cold]
fn rest_energy(tau_eq: f64, rest_strength: f64, gamma_crit: f64) -> f64 {
    if rest_strength > 0.0 {
        0.5 * tau_eq * (tau_eq * (gamma_crit / rest_strength))
    } else {
        0.0
    }
}

/// The law's `STATEV` layout: `STATEV(1..3)` the Coulomb state ([`CoulombState`]); with
/// tangential damping `STATEV(4..3+N)` the viscous stress τ_v at the end of the last increment
/// ([`ExtendedCoulomb::nstatv`] entries in all).
impl<const N: usize> ExtendedState<N> {
    /// Reads the state; `statev` holds at least `law.nstatv(N)` entries (fewer is an error).
    pub fn from_statev(law: &ExtendedCoulomb, statev: &[f64]) -> Result<Self, LawError> {
        let mut state = ExtendedState {
            coulomb: CoulombState::from_statev(statev)?,
            viscous: [0.0; N],
        };
        if law.damping.is_some() {
            match statev.get(CoulombState::NSTATV..CoulombState::NSTATV + N) {
                Some(v) => state.viscous.copy_from_slice(v),
                None => {
                    return Err(LawError::Parameter(format!(
                        "STATEV holds {} entries; the Coulomb law with tangential damping needs {}",
                        statev.len(),
                        law.nstatv(N)
                    )));
                }
            }
        }
        Ok(state)
    }

    /// Writes the state to `out[..law.nstatv(N)]` and returns that many entries (N = NFDIR,
    /// 1 or 2).
    pub fn to_statev<'a>(&self, law: &ExtendedCoulomb, out: &'a mut [f64; 5]) -> &'a [f64] {
        self.coulomb.write_statev(out);
        if law.damping.is_some() {
            out[CoulombState::NSTATV..CoulombState::NSTATV + N].copy_from_slice(&self.viscous);
        }
        &out[..law.nstatv(N)]
    }
}

impl<const N: usize> ExtendedUpdate<N> {
    /// One column of `DDTDDT(NFDIR,2)`: θ̄ = (θ_slave + θ_master)/2, so each surface
    /// temperature carries half of ∂τ/∂θ̄ (both columns are this one).
    #[inline(always)]
    #[must_use]
    pub fn ddtddt_column(&self) -> [f64; N] {
        let mut out = self.ddtdtheta;
        for x in &mut out {
            *x *= 0.5;
        }
        out
    }
}

/// k̄_s + ∂τ̄_crit/∂s, the slope of the slip equation k̄_s (G − s) = τ̄_crit(s/Δt, p, θ̄) in s (up
/// to sign), which the implicit derivatives of s divide by; refused when a rate softening
/// cancels the stick stiffness (0) or it overflowed.
#[inline(always)]
fn slip_stiffness(stiffness: f64, t_s: f64) -> Result<f64, LawError> {
    let d = stiffness + t_s;
    if d == 0.0 {
        return Err(rate_softening_cancels(t_s, stiffness));
    }
    if !d.is_finite() {
        return Err(slip_stiffness_overflowed(t_s, stiffness));
    }
    Ok(d)
}

#[cold]
#[inline(never)]
fn rate_softening_cancels(t_s: f64, stiffness: f64) -> LawError {
    LawError::Numerical(format!(
        "the rate softening of μ (∂τ_crit/∂γ̇/Δt = {t_s}) cancels the stick stiffness \
         {stiffness}: the slip increment is not a function of the motion"
    ))
}

#[cold]
#[inline(never)]
fn slip_stiffness_overflowed(t_s: f64, stiffness: f64) -> LawError {
    LawError::Numerical(format!(
        "the stick stiffness k̄_s = {stiffness} plus ∂τ_crit/∂γ̇/Δt = {t_s} is out of f64's range \
         (μ, its factors or the pressure too large)"
    ))
}

#[cold]
#[inline(never)]
fn no_rate_increment(dtime: f64) -> LawError {
    LawError::Input(format!(
        "DTIME = {dtime} but the friction law needs a slip rate (rate-dependent μ, steady \
         transport or tangential damping): DTIME must be > 0"
    ))
}

#[cold]
#[inline(never)]
fn local_solve_failed(e: RootFailure, g: f64, rate_dt: f64) -> LawError {
    LawError::Numerical(format!(
        "the rate-dependent return map did not converge ({e:?}, γ_eq^pr = {g}, Δt = {rate_dt}); \
         cutting back"
    ))
}

fn check_outputs<const N: usize>(t: &Traction<N>, ddtdtheta: &[f64; N]) -> Result<(), LawError> {
    let ok = t.sed.is_finite()
        && t.sfd.is_finite()
        && all_finite(&t.tau)
        && all_finite(&t.ddtddp)
        && all_finite(&t.dslip)
        && all_finite(ddtdtheta)
        && t.ddtddg.iter().all(all_finite);
    if ok {
        Ok(())
    } else {
        Err(LawError::Numerical(
            "the stress update overflowed (inputs too large for f64)".into(),
        ))
    }
}

fn multiply<const N: usize>(v: &[f64; N], a: &[f64; N]) -> [f64; N] {
    let mut out = *v;
    for i in 0..N {
        out[i] *= a[i];
    }
    out
}

fn divide<const N: usize>(v: &[f64; N], a: &[f64; N]) -> [f64; N] {
    let mut out = *v;
    for i in 0..N {
        out[i] /= a[i];
    }
    out
}

/// `DROT`·v in 3-D; the identity in 2-D (NFDIR = 1).
fn rotate<const N: usize>(drot: &[[f64; 2]; 2], v: &[f64; N]) -> [f64; N] {
    if N != 2 {
        return *v;
    }
    let mut out = [0.0; N];
    for i in 0..2 {
        out[i] = drot[i][0] * v[0] + drot[i][1] * v[1];
    }
    out
}

/// The slip tangent of a rate-dependent μ (Eq. 5.2.3-3): (δ_ij − n_i n_j)·τ_crit/γ_eq^pr +
/// n_i n_j·(∂τ_crit/∂s)·(∂s/∂G), the first term 0 in 2-D; shared by the general path and the
/// decay law's lean path.
#[inline(always)]
pub(super) fn rate_slip_tangent<const N: usize>(
    n: &[f64; N],
    transverse: f64,
    t_s: f64,
    ds_dg: f64,
) -> [[f64; N]; N] {
    let mut ddtddg = [[0.0; N]; N];
    for i in 0..N {
        for j in 0..N {
            let delta = if i == j { 1.0 } else { 0.0 };
            let proj = if N == 1 { 0.0 } else { delta - n[i] * n[j] };
            ddtddg[i][j] = transverse * proj + n[i] * n[j] * t_s * ds_dg;
        }
    }
    ddtddg
}

/// Law 1's extended form behind the law interface (`fric_`'s checked and extended fast
/// paths, `fric_coef_`).
impl PointLaw for ExtendedCoulomb {
    fn name(&self) -> &'static str {
        if self.damping.is_some() {
            "the Coulomb law with tangential damping"
        } else {
            "the Coulomb law"
        }
    }

    fn nstatv(&self, nfdir: usize) -> usize {
        ExtendedCoulomb::nstatv(self, nfdir)
    }

    fn exact_stick(&self) -> bool {
        true
    }

    fn needs(&self, nfdir: usize) -> Needs {
        Needs {
            temperature: self.reads_temperature(),
            // The viscous stress kept in STATEV turns with the tangent directions (3-D only).
            rotation: self.damping.is_some() && nfdir == 2,
            // Steady transport's radius R comes from the point's coordinates.
            coordinates: self.transport.is_some(),
        }
    }

    fn update_point<const N: usize>(&self, at: &PointInput<'_, N>) -> PointResult<N> {
        let state = ExtendedState::<N>::from_statev(self, at.statev)?;
        let up = self.update(at.increment, at.conditions, &state)?;
        let mut end = [0.0; 5];
        let end = up.state.to_statev(self, &mut end);
        Ok(PointAnswer::new(
            up.contact,
            end,
            up.ddtdtheta,
            up.outcome.step_ratio,
        ))
    }

    fn coefficients(&self, rate: f64, pressure: f64, temperature: f64) -> Option<[[f64; 2]; 4]> {
        Some(ExtendedCoulomb::coefficients(
            self,
            rate,
            pressure,
            temperature,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn base() -> Coulomb {
        Coulomb::new(0.4)
            .and_then(|c| c.with_critical_slip_absolute(1e-3))
            .unwrap()
    }

    fn traction<const N: usize>(u: &ExtendedUpdate<N>) -> Traction<N> {
        match u.contact {
            Contact::Motion(t) => t,
            Contact::ExactStick => panic!("expected motion"),
        }
    }

    #[test]
    fn anisotropic_stick_stiffnesses() {
        // μ₁ = 0.4, μ₂ = 0.2: μ̄² = 0.1, k_i = (μ_i/μ̄)² μ̄ p/γ_crit.
        let law = ExtendedCoulomb::new(base())
            .with_second_coefficient(0.2)
            .unwrap();
        let inc = Increment::<2> {
            dgam: [1e-5, 1e-5],
            pressure: 100.0,
            dpressure: 100.0,
            ..Increment::default()
        };
        let u = law
            .update(&inc, &Conditions::default(), &ExtendedState::default())
            .unwrap();
        let t = traction(&u);
        let mbar = 0.1f64.sqrt();
        let kbar = mbar * 100.0 / 1e-3;
        let k1 = 0.16 / 0.1 * kbar;
        let k2 = 0.04 / 0.1 * kbar;
        assert!((t.ddtddg[0][0] - k1).abs() < 1e-9 * k1);
        assert!((t.ddtddg[1][1] - k2).abs() < 1e-9 * k1);
        assert!((t.tau[0] - k1 * 1e-5).abs() < 1e-9);
    }

    #[test]
    fn decay_law_steady_slip_gives_mu_of_rate() {
        let law = ExtendedCoulomb::new(base()).with_coefficient_law(
            CoefficientLaw::default()
                .with_exponential_decay(0.5, 3.0)
                .unwrap(),
        );
        // Steady slip at v = 0.2 (Δγ = 0.02 per Δt = 0.1), from a steady start.
        let mut st = ExtendedState::<1>::default();
        let mut tau = [0.0];
        for _ in 0..20 {
            let inc = Increment::<1> {
                tau,
                dgam: [0.02],
                pressure: 10.0,
                dpressure: 0.0,
                dtime: 0.1,
                ..Increment::default()
            };
            let u = law.update(&inc, &Conditions::default(), &st).unwrap();
            tau = traction(&u).tau;
            st = u.state;
        }
        let mu = 0.2 + 0.2 * (-3.0f64 * 0.2).exp();
        assert!((tau[0] - mu * 10.0).abs() < 1e-12 * mu * 10.0, "{tau:?}");
    }
}
