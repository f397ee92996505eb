//! The friction coefficient μ(γ̇_eq, p, θ̄) of the extended Coulomb model (seed 000, section
//! 5.2.3: "μ … can be defined as a function of the contact pressure, the slip rate, the average
//! surface temperature"), with its partial derivatives.
//!
//! μ is a product of a reference value and three dimensionless factors, each 1 when its feature
//! is off:
//!
//! μ(γ̇, p, θ̄) = μ_s · φ(γ̇) · π(p) · Θ(θ̄)
//!
//! - φ, slip rate: exponential decay μ = μ_k + (μ_s − μ_k)·exp(−d_c·γ̇) (the form of Abaqus's
//!   `*FRICTION, EXPONENTIAL DECAY`), i.e. φ = r + (1 − r)·exp(−d_c·γ̇) with r = μ_k/μ_s;
//! - π, pressure: π = 1/(1 + p/p_ref), a friction coefficient that falls as the pressure rises,
//!   so that μp saturates smoothly at μ_s·p_ref (a smooth counterpart of τ_max);
//! - Θ, temperature: Θ = exp(−b_θ·(θ̄ − θ_ref)), softening (b_θ > 0) or hardening (b_θ < 0).
//!
//! - or, replacing all three, a table μ_tab(γ̇, p, θ̄) from the configuration file
//!   ([`FrictionTable`], Abaqus `*FRICTION` data lines): f = μ_tab/μ_ref with μ_ref = `PROPS(2)`,
//!   so that direction 1 has μ₁ = μ_tab.
//!
//! With anisotropy every direction's coefficient is multiplied by the same factors, so the
//! ratio μ₁/μ₂ (and with it the scaling of Eq. 5.2.3-10/11) is constant.

use crate::LawError;
use crate::laws::friction_table::FrictionTable;
use crate::laws::parameter_range::{nonnegative, positive};

/// How a rate-dependent strength enters the elastic-stick return map (docs/props.md, "The
/// rate-dependent formulation"). Shared by the extended Coulomb law (law 1) and the adhesive
/// law (law 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum RateFormulation {
    /// The default. Seed 000 after Eq. 5.2.3-1: the stick stiffness follows the rate-dependent
    /// strength, k_s = τ_crit(γ̇)/γ_crit, so that in slip the elastic slip stays γ_crit and the
    /// slip of the increment is explicit, Δγ_eq^sl = γ_eq^pr − γ_crit (Eq. 5.2.3-2), with
    /// τ = τ_crit(Δγ_eq^sl/Δt)·n. The rate that sets k_s at the start of an increment, and in
    /// a stick increment, is the previous increment's slip rate (`STATEV(2)`): the memory that
    /// makes a sliding point keep sliding and a stopped point keep its stress.
    #[default]
    RateFollowingStiffness,
    /// The earlier formulation, kept for comparison (scene F7): a rate-free stick stiffness
    /// k_s = τ_crit(0)/γ_crit and the slip s solving k_s(γ_eq^pr − s) = τ_crit(s/Δt). It is a
    /// massless spring pulling a weakening slider: under velocity weakening it slides steadily
    /// only for large increments (r > 2c·x·e^(−x) for the decay law).
    RateFreeStiffness,
}

/// The rate-following stick test |γ^pr| ≤ γ_crit·(1 + this): the start elastic slip
/// γ̄^el = τ̄·γ_crit/τ_crit(γ̇₀) of a point that slid is γ_crit to a few roundings, and an
/// increment without motion must not read as a slip of a few ulps (at a vanishing rate, where
/// the strength is the static one, that would jump τ to μ_s·p).
pub const STICK_TEST_ROUNDING: f64 = 16.0 * f64::EPSILON;

/// How μ depends on the equivalent slip rate γ̇_eq.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RateLaw {
    /// μ does not depend on the slip rate.
    Constant,
    /// μ = μ_k + (μ_s − μ_k)·exp(−d_c·γ̇_eq), stored as r = μ_k/μ_s and d_c.
    ExponentialDecay {
        /// r = μ_k/μ_s (kinetic over static coefficient), ≥ 0.
        kinetic_ratio: f64,
        /// d_c > 0 (time per length).
        decay: f64,
    },
    /// μ = μ_tab(γ̇, p, θ̄) from the configuration file; f = μ_tab/μ_ref (replaces the pressure
    /// and temperature factors too).
    Table {
        /// The validated table (it lives as long as the process-wide configuration).
        table: &'static FrictionTable,
        /// 1/μ_ref, μ_ref = `PROPS(2)` > 0.
        inv_mu_ref: f64,
    },
}

/// The dimensionless factor f = φ(γ̇)·π(p)·Θ(θ̄) of μ and its partial derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Factor {
    /// f.
    pub value: f64,
    /// ∂f/∂γ̇_eq.
    pub d_rate: f64,
    /// ∂²f/∂γ̇_eq² (used by the local solve's Halley step).
    pub d_rate2: f64,
    /// ∂f/∂p.
    pub d_pressure: f64,
    /// ∂f/∂θ̄.
    pub d_temperature: f64,
}

/// (φ, φ', φ''), (π, π'), (Θ, Θ'): the three factors of the closed-form laws with their
/// derivatives.
type FactorParts = ((f64, f64, f64), (f64, f64), (f64, f64));

/// The validated factor laws (everything except the reference coefficients).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoefficientLaw {
    rate: RateLaw,
    /// p_ref > 0, or `f64::INFINITY` when μ does not depend on pressure.
    pressure_ref: f64,
    /// b_θ (0 when μ does not depend on temperature).
    temperature_slope: f64,
    /// θ_ref.
    temperature_ref: f64,
}

impl Default for CoefficientLaw {
    fn default() -> Self {
        CoefficientLaw {
            rate: RateLaw::Constant,
            pressure_ref: f64::INFINITY,
            temperature_slope: 0.0,
            temperature_ref: 0.0,
        }
    }
}

impl CoefficientLaw {
    /// From `PROPS` entries already checked by the caller (`props.rs`): the decay law when
    /// `decay` is `Some((μ_k/μ_s ≥ 0, d_c > 0))`, p_ref > 0 or 0 (off), b_θ and θ_ref finite.
    #[inline]
    #[must_use]
    pub(crate) fn from_validated(
        decay: Option<(f64, f64)>,
        pressure_ref: f64,
        temperature_slope: f64,
        temperature_ref: f64,
    ) -> Self {
        CoefficientLaw {
            rate: match decay {
                Some((kinetic_ratio, decay)) => RateLaw::ExponentialDecay {
                    kinetic_ratio,
                    decay,
                },
                None => RateLaw::Constant,
            },
            pressure_ref: if pressure_ref > 0.0 {
                pressure_ref
            } else {
                f64::INFINITY
            },
            temperature_slope,
            temperature_ref: if temperature_slope != 0.0 {
                temperature_ref
            } else {
                0.0
            },
        }
    }

    /// The μ table of `PROPS(8) = 2`, from entries already checked by the caller (`props.rs`):
    /// μ_ref = `PROPS(2)` > 0 and no pressure or temperature factor (the table carries them),
    /// what [`CoefficientLaw::with_table`] checks.
    #[inline]
    #[must_use]
    pub(crate) fn table_from_validated(table: &'static FrictionTable, mu_ref: f64) -> Self {
        CoefficientLaw {
            rate: RateLaw::Table {
                table,
                inv_mu_ref: 1.0 / mu_ref,
            },
            ..CoefficientLaw::default()
        }
    }

    /// Exponential decay with r = μ_k/μ_s ≥ 0 and d_c > 0.
    pub fn with_exponential_decay(
        mut self,
        kinetic_ratio: f64,
        decay: f64,
    ) -> Result<Self, LawError> {
        nonnegative("kinetic coefficient ratio μ_k/μ_s", kinetic_ratio)?;
        positive("decay coefficient d_c", decay)?;
        self.rate = RateLaw::ExponentialDecay {
            kinetic_ratio,
            decay,
        };
        Ok(self)
    }

    /// μ from a table: f = μ_tab(γ̇, p, θ̄)/μ_ref, μ_ref > 0 (the μ the direction-1 coefficient is
    /// given as). The pressure and temperature factors must be off.
    pub fn with_table(
        mut self,
        table: &'static FrictionTable,
        mu_ref: f64,
    ) -> Result<Self, LawError> {
        if !(mu_ref.is_finite() && mu_ref > 0.0) {
            return Err(LawError::Parameter(format!(
                "reference coefficient μ_ref = {mu_ref} must be finite and > 0 with a μ table"
            )));
        }
        if self.pressure_ref.is_finite() || self.temperature_slope != 0.0 {
            return Err(LawError::Parameter(
                "a μ table carries its own pressure and temperature dependence; the pressure \
                 and temperature factors must be off"
                    .into(),
            ));
        }
        self.rate = RateLaw::Table {
            table,
            inv_mu_ref: 1.0 / mu_ref,
        };
        Ok(self)
    }

    /// Pressure dependence π = 1/(1 + p/p_ref), p_ref > 0.
    pub fn with_pressure_reference(mut self, p_ref: f64) -> Result<Self, LawError> {
        self.pressure_ref = positive("reference pressure p_ref", p_ref)?;
        Ok(self)
    }

    /// Temperature dependence Θ = exp(−b_θ·(θ̄ − θ_ref)).
    pub fn with_temperature(mut self, slope: f64, reference: f64) -> Result<Self, LawError> {
        if !(slope.is_finite() && reference.is_finite()) {
            return Err(LawError::Parameter(format!(
                "temperature coefficients b_θ = {slope}, θ_ref = {reference} must be finite"
            )));
        }
        self.temperature_slope = slope;
        self.temperature_ref = reference;
        Ok(self)
    }

    /// The rate law.
    #[must_use]
    pub fn rate(&self) -> RateLaw {
        self.rate
    }

    /// True when μ depends on the slip rate.
    #[must_use]
    pub fn is_rate_dependent(&self) -> bool {
        self.rate != RateLaw::Constant
    }

    /// True when μ depends on the temperature (TEMP is read).
    #[must_use]
    pub fn is_temperature_dependent(&self) -> bool {
        self.temperature_slope != 0.0
            || matches!(self.rate, RateLaw::Table { table, .. } if table.depends_on_temperature())
    }

    /// True when the temperature factor Θ(θ̄) is on (b_θ ≠ 0): for the closed-form laws, the
    /// same as [`Self::is_temperature_dependent`].
    #[inline(always)]
    #[must_use]
    pub(crate) fn has_temperature_factor(&self) -> bool {
        self.temperature_slope != 0.0
    }

    /// True when every factor is 1 (μ is the constant reference value).
    #[must_use]
    pub fn is_constant(&self) -> bool {
        *self == CoefficientLaw::default()
    }

    /// The rate-free part of the factor for the decay law, split for the local solve: when μ
    /// follows the exponential decay law, `Some(((π·Θ, ∂(π·Θ)/∂p, ∂(π·Θ)/∂θ̄), (r, d_c)))`
    /// (π and Θ do not change while the solve varies the rate, so they are evaluated once);
    /// `None` for the other laws. `factor` = φ(γ̇)·π·Θ with φ from [`decay_phi`].
    #[inline]
    #[must_use]
    pub fn split_decay(&self, pressure: f64, temperature: f64) -> Option<([f64; 3], (f64, f64))> {
        let RateLaw::ExponentialDecay {
            kinetic_ratio,
            decay,
        } = self.rate
        else {
            return None;
        };
        let f = CoefficientLaw {
            rate: RateLaw::Constant,
            ..*self
        }
        .factor(0.0, pressure, temperature);
        Some((
            [f.value, f.d_pressure, f.d_temperature],
            (kinetic_ratio, decay),
        ))
    }

    /// The rate-free part of the factor, π(p)·Θ(θ̄), with ∂/∂p and ∂/∂θ̄: the same numbers as
    /// `factor(0, p, θ̄)` gives for the closed-form laws (φ(0) = 1 exactly), without the rate
    /// law. For the stick stiffness k_s = τ_crit(0, p, θ̄)/γ_crit of the decay law, whose
    /// local solve uses the same three numbers ([`Self::split_decay`]).
    #[inline(always)]
    #[must_use]
    pub(crate) fn rate_free(&self, pressure: f64, temperature: f64) -> [f64; 3] {
        let (pi, dpi) = self.pressure_factor(pressure);
        let (theta, dtheta) = self.temperature_factor(temperature);
        // As `factor` with φ = 1: 1·π·Θ = π·Θ, 1·π'·Θ = π'·Θ, 1·π·Θ' = π·Θ' (exact products).
        [pi * theta, dpi * theta, pi * dtheta]
    }

    /// f(γ̇, p, θ̄) and its partials. `rate` is the equivalent slip rate (≥ 0), `pressure` the
    /// contact pressure (≥ 0; the caller handles p < 0), `temperature` θ̄ (ignored when the law
    /// does not depend on it). The result may overflow for extreme temperatures; the caller
    /// checks its outputs.
    #[inline]
    #[must_use]
    pub fn factor(&self, rate: f64, pressure: f64, temperature: f64) -> Factor {
        // 1·x = x exactly: the same numbers as φ·π·Θ.
        self.scaled(1.0, rate, pressure, temperature)
    }

    /// μ·f(γ̇, p, θ̄) and its partials for a reference coefficient μ, multiplied as
    /// ((μ·φ)·π)·Θ: μ·φ is the coefficient at the rate, a value of the law's own range, so
    /// that no intermediate product under- or overflows where μ·f itself does not (the order
    /// μ·(φ·π·Θ) lost μ_k·Θ = 5·10⁻¹⁸⁹ to an underflow of φ·Θ with
    /// μ_s = 10²⁷², μ_k/μ_s = 3·10⁻²⁷⁵: fuzz target `fric_coef`, docs/fuzzing.md).
    #[inline]
    #[must_use]
    pub fn scaled(&self, mu: f64, rate: f64, pressure: f64, temperature: f64) -> Factor {
        if let RateLaw::Table { table, inv_mu_ref } = self.rate {
            let f = table_factor(table, inv_mu_ref, rate, pressure, temperature);
            return Factor {
                value: mu * f.value,
                d_rate: mu * f.d_rate,
                d_rate2: mu * f.d_rate2,
                d_pressure: mu * f.d_pressure,
                d_temperature: mu * f.d_temperature,
            };
        }
        let ((phi, dphi, ddphi), (pi, dpi), (theta, dtheta)) =
            self.closed_form_parts(rate, pressure, temperature);
        let (m, dm, ddm) = (mu * phi, mu * dphi, mu * ddphi);
        Factor {
            value: m * pi * theta,
            d_rate: dm * pi * theta,
            d_rate2: ddm * pi * theta,
            d_pressure: m * dpi * theta,
            d_temperature: m * pi * dtheta,
        }
    }

    /// π(p) = 1/(1 + p/p_ref) and π' = −(1/p_ref)·π²; (1, 0) without a reference pressure.
    #[inline(always)]
    fn pressure_factor(&self, pressure: f64) -> (f64, f64) {
        if self.pressure_ref.is_finite() {
            let pi = 1.0 / (1.0 + pressure / self.pressure_ref);
            (pi, -pi * pi / self.pressure_ref)
        } else {
            (1.0, 0.0)
        }
    }

    /// Θ(θ̄) = exp(−b_θ·(θ̄ − θ_ref)) and Θ' = −b_θ·Θ; (1, 0) without a temperature slope.
    #[inline(always)]
    fn temperature_factor(&self, temperature: f64) -> (f64, f64) {
        if self.temperature_slope != 0.0 {
            let t = (-self.temperature_slope * (temperature - self.temperature_ref)).exp();
            (t, -self.temperature_slope * t)
        } else {
            (1.0, 0.0)
        }
    }

    /// (φ, φ', φ''), (π, π'), (Θ, Θ') of the closed-form laws (not the table).
    #[inline(always)]
    fn closed_form_parts(&self, rate: f64, pressure: f64, temperature: f64) -> FactorParts {
        // φ(γ̇) = r + (1 − r)·exp(−d_c γ̇), φ' = −d_c (1 − r) exp(−d_c γ̇).
        let phi = match self.rate {
            RateLaw::Constant | RateLaw::Table { .. } => (1.0, 0.0, 0.0),
            RateLaw::ExponentialDecay {
                kinetic_ratio: r,
                decay: d,
            } => {
                // exp(−0) = 1 exactly: the rate-free value (stick stiffness) needs no exp.
                let (e, one_minus_e) = decay_terms(-d * rate);
                // φ = e + r(1 − e): two terms ≥ 0, no cancellation. The form r + (1 − r)e
                // lost φ(0) = 1 to round-off when r ≫ 1 (μ_k ≫ μ_s: μ = 0 at rest; fuzz
                // target fric_coef, crash C2, docs/fuzzing.md).
                (
                    e + r * one_minus_e,
                    -d * (1.0 - r) * e,
                    d * d * (1.0 - r) * e,
                )
            }
        };
        let (pi, dpi) = self.pressure_factor(pressure);
        let (theta, dtheta) = self.temperature_factor(temperature);
        (phi, (pi, dpi), (theta, dtheta))
    }
}

/// f = μ_tab/μ_ref of a table (piecewise linear: no second derivative). Out of line, so that
/// the table lookup does not make [`CoefficientLaw::factor`] too large to inline for the
/// closed-form laws.
#[inline(never)]
fn table_factor(
    table: &FrictionTable,
    inv_mu_ref: f64,
    rate: f64,
    pressure: f64,
    temperature: f64,
) -> Factor {
    let v = table.eval(rate, pressure, temperature);
    Factor {
        value: v.mu * inv_mu_ref,
        d_rate: v.d_rate * inv_mu_ref,
        d_rate2: 0.0,
        d_pressure: v.d_pressure * inv_mu_ref,
        d_temperature: v.d_temperature * inv_mu_ref,
    }
}

/// φ(γ̇) = r + (1 − r)·exp(−d_c γ̇) of the decay law with φ' and φ'' (the same expression as
/// [`CoefficientLaw::factor`] uses).
#[inline(always)]
#[must_use]
pub fn decay_phi(kinetic_ratio: f64, decay: f64, rate: f64) -> (f64, f64, f64) {
    let (r, d) = (kinetic_ratio, decay);
    let (e, one_minus_e) = if rate > 0.0 {
        decay_terms(-d * rate)
    } else {
        (1.0, 0.0)
    };
    let a = (1.0 - r) * e;
    // φ = e + r(1 − e) as in `factor` (no cancellation when r ≫ 1).
    (e + r * one_minus_e, -d * a, d * d * a)
}

/// (e^x, 1 − e^x) for x ≤ 0, each to a few ulps with one exponential: near 0 through
/// `exp_m1` (1 − e^x would cancel), elsewhere 1 − e^x ≥ 0.39 is exact enough. (1, 0) at x = 0.
#[inline]
fn decay_terms(x: f64) -> (f64, f64) {
    if x == 0.0 {
        (1.0, 0.0)
    } else if x > -0.5 {
        let m = x.exp_m1();
        (1.0 + m, -m)
    } else {
        let e = x.exp();
        (e, 1.0 - e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decay_limits_and_derivatives() {
        let law = CoefficientLaw::default()
            .with_exponential_decay(0.5, 2.0)
            .unwrap();
        assert_eq!(law.factor(0.0, 1.0, 0.0).value, 1.0);
        assert!((law.factor(1e3, 1.0, 0.0).value - 0.5).abs() < 1e-15);
        // μ(γ̇) = μ_k + (μ_s − μ_k) e^{−d γ̇}: at γ̇ = ln 2/2, halfway.
        let f = law.factor(std::f64::consts::LN_2 / 2.0, 1.0, 0.0);
        assert!((f.value - 0.75).abs() < 1e-15);
        assert!((f.d_rate - (-2.0 * 0.5 * 0.5)).abs() < 1e-15);
    }

    #[test]
    fn pressure_and_temperature_factors() {
        let law = CoefficientLaw::default()
            .with_pressure_reference(100.0)
            .unwrap()
            .with_temperature(0.01, 20.0)
            .unwrap();
        let f = law.factor(0.0, 100.0, 20.0);
        assert!((f.value - 0.5).abs() < 1e-15);
        assert!((f.d_pressure + 0.25 / 100.0).abs() < 1e-18);
        assert!((f.d_temperature + 0.01 * 0.5).abs() < 1e-16);
        let g = law.factor(0.0, 0.0, 120.0);
        assert!((g.value - (-1.0f64).exp()).abs() < 1e-15);
    }

    #[test]
    fn bad_parameters() {
        let l = CoefficientLaw::default();
        assert!(l.with_exponential_decay(-0.1, 1.0).is_err());
        assert!(l.with_exponential_decay(0.5, -1.0).is_err());
        assert!(l.with_exponential_decay(0.5, 0.0).is_err());
        assert!(l.with_pressure_reference(-1.0).is_err());
        assert!(l.with_temperature(f64::NAN, 0.0).is_err());
    }
}
