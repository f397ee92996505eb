//! Viscous tangential damping (seed 003, section 5.2.3): τ_v = c(h)·γ̇, with the damping
//! coefficient c a function of the overclosure h — c₀ at zero overclosure, constant over the
//! documented fraction of the clearance interval, then falling linearly to zero. The law adds
//! τ_v to the friction stress ([`super::ExtendedCoulomb`]); this file holds its parameters.

use crate::LawError;
use crate::laws::parameter_range::{nonnegative, positive};

/// Viscous tangential damping (seed 003): τ_v = c(h)·γ̇ with c = c₀ at zero overclosure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Damping {
    /// c₀ > 0: stress per relative tangential velocity at zero overclosure.
    pub c0: f64,
    /// g₀ ≥ 0: the clearance at which c vanishes (0: c = c₀ while closed, 0 when open).
    pub clearance: f64,
    /// f ∈ [0, 1): the fraction of [0, g₀] over which c = c₀.
    pub fraction: f64,
}

impl Damping {
    /// Validated damping parameters.
    pub fn new(c0: f64, clearance: f64, fraction: f64) -> Result<Self, LawError> {
        positive("tangential damping c₀", c0)?;
        nonnegative("damping clearance g₀", clearance)?;
        if !(fraction.is_finite() && (0.0..1.0).contains(&fraction)) {
            return Err(LawError::Parameter(format!(
                "damping clearance fraction f = {fraction} must be in [0, 1)"
            )));
        }
        Ok(Damping {
            c0,
            clearance,
            fraction,
        })
    }

    /// c(h) for the overclosure h (positive when the surfaces penetrate, −h is the clearance):
    /// c₀ for h ≥ −f·g₀, falling linearly to 0 at h = −g₀, 0 beyond (seed 003). `fric_` is
    /// called for closed points only (h ≥ 0), so it always uses c₀.
    #[must_use]
    pub fn coefficient(&self, overclosure: f64) -> f64 {
        let clearance = -overclosure;
        let flat = self.fraction * self.clearance;
        if clearance <= flat {
            self.c0
        } else if clearance >= self.clearance {
            0.0
        } else {
            self.c0 * (self.clearance - clearance) / (self.clearance - flat)
        }
    }
}
