//! The loading the tangent property tests draw for one point over one increment, shared by
//! tests/tangents.rs, tests/friction_extended.rs and tests/friction_table.rs (included there by
//! path): each adds its own law and state, and scales the fractions by its own strength and γ_crit.

use interfacial_test_hosts::FricCall;

/// One increment's loading: the pressure p₀ at the start and its change Δp (the end is
/// p₀ + Δp), the start stress per direction as a fraction of a strength the test picks, and
/// DGAM per direction in units of γ_crit.
#[derive(Clone, Copy, Debug)]
pub struct Loading {
    pub p0: f64,
    pub dp: f64,
    pub tau_frac: [f64; 2],
    pub dgam_frac: [f64; 2],
}

impl Loading {
    /// The pressure at the end of the increment.
    pub fn p_end(&self) -> f64 {
        self.p0 + self.dp
    }

    /// PRESS and DPRESS with the end pressure moved by `shift` and the start p₀ held (both move
    /// together), as the central differences in the pressure need.
    pub fn set_pressure(&self, c: &mut FricCall, shift: f64) {
        c.press = self.p_end() + shift;
        c.dpress = self.dp + shift;
    }
}
