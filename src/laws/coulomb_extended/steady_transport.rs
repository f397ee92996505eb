//! Viscous stick for steady-state transport (seed 000, and seed 003's γ̇_crit): the viscous
//! slip rate, not the elastic slip, carries the stick; τ = κ_s·γ̇^v with κ_s = τ_crit/γ̇_crit.
//! The parameters and the return map of [`super::ExtendedCoulomb`] in this formulation.

#![allow(clippy::needless_range_loop)] // index loops mirror the i, j of the seed's equations

use super::*;

/// Which edition of the seed sets the allowable viscous slip rate γ̇_crit of steady-state
/// transport (`PROPS(16)` when `PROPS(7) = 3`, docs/props.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ViscousSlipReference {
    /// Seed 000: "a fraction of the circumferential velocity", γ̇_crit = 2·F_f·ω·R.
    #[default]
    Circumferential,
    /// Seed 003: "a fraction of the relative tangential velocity", γ̇_crit = F_f·ω·R, the
    /// relative velocity being the transport velocity ω·R of the spinning surface against a
    /// partner that does not spin (docs/props.md gives the reasons for this reading).
    RelativeVelocity,
}

/// Viscous stick for steady-state transport (seed 000): the allowable viscous slip rate is
/// γ̇_crit = 2·F_f·ω·R, R the distance of the contact point (`COORDS`) from the spinning axis;
/// seed 003's variant γ̇_crit = F_f·ω·R with [`ViscousSlipReference::RelativeVelocity`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyTransport {
    /// F_f > 0, the slip tolerance.
    pub tolerance: f64,
    /// ω > 0, the angular spinning velocity.
    pub omega: f64,
    /// The spinning axis: the global axis 0 (x), 1 (y) or 2 (z) through the origin.
    pub axis: usize,
    /// The velocity γ̇_crit is a fraction of (seed 000 or seed 003).
    pub reference: ViscousSlipReference,
}

impl SteadyTransport {
    /// Validated steady-transport parameters.
    pub fn new(tolerance: f64, omega: f64, axis: usize) -> Result<Self, LawError> {
        positive("slip tolerance F_f", tolerance)?;
        if !(omega.is_finite() && omega > 0.0) {
            return Err(LawError::Parameter(format!(
                "angular velocity ω = {omega} must be finite and > 0 for steady-state transport"
            )));
        }
        if axis > 2 {
            return Err(LawError::Parameter(format!(
                "spinning axis {} must be 1 (x), 2 (y) or 3 (z)",
                axis + 1
            )));
        }
        Ok(SteadyTransport {
            tolerance,
            omega,
            axis,
            reference: ViscousSlipReference::Circumferential,
        })
    }

    /// The same parameters with γ̇_crit taken as seed `reference` defines it.
    #[must_use]
    pub fn with_reference(mut self, reference: ViscousSlipReference) -> Self {
        self.reference = reference;
        self
    }

    /// γ̇_crit at the distance `radius` from the axis: 2·F_f·ω·R (seed 000) or F_f·ω·R
    /// (seed 003, a fraction F_f of the relative tangential velocity ω·R).
    #[inline]
    #[must_use]
    pub fn critical_rate(&self, radius: f64) -> f64 {
        match self.reference {
            ViscousSlipReference::Circumferential => 2.0 * self.tolerance * self.omega * radius,
            ViscousSlipReference::RelativeVelocity => self.tolerance * self.omega * radius,
        }
    }

    /// R: the distance of `coords` from the axis (only the first `coords.len()` coordinates).
    #[must_use]
    pub fn radius(&self, coords: &[f64]) -> f64 {
        coords
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != self.axis)
            .map(|(_, x)| x * x)
            .sum::<f64>()
            .sqrt()
    }
}

impl ExtendedCoulomb {
    /// Viscous stick for steady-state transport (seed 000; γ̇_crit of seed 000 or 003, see
    /// [`SteadyTransport::critical_rate`]), in scaled variables: the predictor
    /// is the relative velocity γ̇^pr = Δγ̄/Δt; viscous stick τ̄ = κ_s γ̇^pr while
    /// |γ̇^pr| ≤ γ̇_crit (κ_s = τ̄_crit(0)/γ̇_crit), else slip with |γ̇^v| = γ̇_crit, so the
    /// slip rate is |γ̇^pr| − γ̇_crit and τ̄ = τ̄_crit(|γ̇^pr| − γ̇_crit)·n. No memory: the stress
    /// of the start of the increment is not used.
    pub(super) fn viscous_stick<const N: usize>(
        &self,
        inc: &Increment<N>,
        s: &Scaled<N>,
        conditions: &Conditions,
    ) -> Result<ScaledTraction<N>, LawError> {
        let &Scaled {
            mbar,
            theta,
            rate_dt: dt,
            start_rate,
            ..
        } = s;
        let Some(tr) = self.transport else {
            return Err(LawError::Numerical(
                "steady transport not configured".into(),
            ));
        };
        let radius = tr.radius(&conditions.coords[..conditions.ncoords.min(3)]);
        // γ̇_crit = 2 F_f ω R (seed 000) or F_f ω R (seed 003).
        let rate_crit = tr.critical_rate(radius);
        if !(rate_crit > 0.0 && rate_crit.is_finite()) {
            return Err(LawError::Input(format!(
                "COORDS = {:?} is on the spinning axis (R = {radius}): the allowable viscous slip \
                 rate {}F_f·ω·R must be > 0",
                &conditions.coords[..conditions.ncoords.min(3)],
                match tr.reference {
                    ViscousSlipReference::Circumferential => "2·",
                    ViscousSlipReference::RelativeVelocity => "",
                }
            )));
        }
        let p = inc.pressure;
        let k = self.critical(mbar, 0.0, p, theta);
        let viscosity = k.value / rate_crit;
        let predictor = scale(&s.dgam, 1.0 / dt);
        let v = norm(&predictor);
        if v <= rate_crit {
            // Viscous stick: τ̄ = κ_s γ̇^pr, dτ̄/dΔγ̄ = κ_s/Δt.
            return Ok(ScaledTraction::closed_form(
                Traction::sticking(
                    scale(&predictor, viscosity),
                    diagonal(viscosity / dt),
                    scale(&predictor, k.d_pressure / rate_crit),
                    0.0,
                ),
                scale(&predictor, k.d_temperature / rate_crit),
                0.0,
            ));
        }
        let n = unit(&predictor, v);
        let slip_rate = v - rate_crit;
        let frozen = self.frozen && self.coefficient.is_rate_dependent();
        let crit = self.critical(mbar, if frozen { start_rate } else { slip_rate }, p, theta);
        let t = crit.value;
        let t_r = if frozen { 0.0 } else { crit.d_rate };
        let mut ddtddg = [[0.0; N]; N];
        for i in 0..N {
            for j in 0..N {
                let delta = if i == j { 1.0 } else { 0.0 };
                let proj = if N == 1 { 0.0 } else { delta - n[i] * n[j] };
                // ∂γ̇^pr/∂Δγ̄ = I/Δt; the slip rate |γ̇^pr| − γ̇_crit moves with n/Δt.
                ddtddg[i][j] = (t / v * proj + n[i] * n[j] * t_r) / dt;
            }
        }
        let slip_eq = slip_rate * dt;
        Ok(ScaledTraction::closed_form(
            // No elastic slip in viscous stick: SED = 0.
            Traction::sliding(&n, t, ddtddg, crit.d_pressure, slip_eq, 0.0),
            scale(&n, crit.d_temperature),
            slip_eq,
        ))
    }
}
