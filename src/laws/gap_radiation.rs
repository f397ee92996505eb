//! Radiation across a gap (seed 000, section 5.2.4): q = F·σ·((θ_A − θ_Z)⁴ − (θ_B − θ_Z)⁴), with F
//! the effective view factor (emissivities included), σ the Stefan–Boltzmann constant and θ_Z
//! absolute zero on the user's temperature scale. Returned as the equivalent conductance
//! k_rad = q/(θ_A − θ_B) = F·σ·(a + b)(a² + b²), a = θ_A − θ_Z, b = θ_B − θ_Z, which has no 0/0
//! at θ_A = θ_B.

use super::parameter_range::{nonnegative, positive};
use crate::LawError;

/// Gap radiation parameters, validated on construction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Radiation {
    view_factor: f64,
    stefan_boltzmann: f64,
    absolute_zero: f64,
}

/// k_rad and the exact flux derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadiationResponse {
    /// Equivalent conductance q/(θ_A − θ_B).
    pub k: f64,
    /// ∂k/∂θ̄ at fixed θ_A − θ_B.
    pub dk_dtheta_mean: f64,
    /// ∂q/∂θ_A = 4Fσa³.
    pub dq_dtheta_a: f64,
    /// ∂q/∂θ_B = −4Fσb³.
    pub dq_dtheta_b: f64,
}

impl Radiation {
    /// F ≥ 0 (0 switches radiation off), σ > 0 in the model's units, θ_Z finite.
    pub fn new(
        view_factor: f64,
        stefan_boltzmann: f64,
        absolute_zero: f64,
    ) -> Result<Self, LawError> {
        nonnegative("view_factor", view_factor)?;
        positive("stefan_boltzmann", stefan_boltzmann)?;
        if !absolute_zero.is_finite() {
            return Err(LawError::Parameter(format!(
                "absolute_zero = {absolute_zero} must be finite"
            )));
        }
        Ok(Radiation {
            view_factor,
            stefan_boltzmann,
            absolute_zero,
        })
    }

    /// Equivalent conductance and flux derivatives at surface temperatures θ_A, θ_B.
    pub fn evaluate(&self, theta_a: f64, theta_b: f64) -> Result<RadiationResponse, LawError> {
        let a = theta_a - self.absolute_zero;
        let b = theta_b - self.absolute_zero;
        if a < 0.0 || b < 0.0 {
            return Err(LawError::Input(format!(
                "surface temperatures {theta_a}, {theta_b} lie below absolute zero \
                 ({}) on the model's scale",
                self.absolute_zero
            )));
        }
        let fs = self.view_factor * self.stefan_boltzmann;
        // With m = (a + b)/2 and Δ = a − b: k = Fσ(4m³ + mΔ²), so ∂k/∂m = Fσ(12m² + Δ²).
        let m = 0.5 * (a + b);
        let delta = a - b;
        Ok(RadiationResponse {
            k: fs * (a + b) * (a * a + b * b),
            dk_dtheta_mean: fs * (12.0 * m * m + delta * delta),
            dq_dtheta_a: 4.0 * fs * a * a * a,
            dq_dtheta_b: -4.0 * fs * b * b * b,
        })
    }
}
