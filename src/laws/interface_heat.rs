//! Heat across a contact interface, as a host that hands the library the whole interface
//! (Abaqus UINTER) asks for it: the flux into each surface and its derivatives with respect to
//! the surface temperatures and the relative motion (docs/uinter.md, "Heat flux").
//!
//! - Gap conduction (seed 000, 5.2.4): q = k(θ_A − θ_B) crosses the interface from the slave
//!   (A) to the master (B), with k from a GAPCON law ([`GapLaw`]) at the clearance max(−h, 0)
//!   and the pressure max(p, 0); the law's ∂q/∂θ_A, ∂q/∂θ_B include ∂k/∂θ̄.
//! - Frictional heating: the fraction η of the frictional dissipation SFD becomes heat, η·SFD/Δt
//!   per unit time, a part f into the slave and 1 − f into the master.
//!
//! Any UINTER law that reports a normal stress, its derivative ∂p/∂h and a frictional
//! dissipation with its derivatives can use it; the adhesive interface does.

use super::gap_conductance::GapLaw;
use crate::LawError;

/// Conduction across the gap: the interaction's GAPCON law and the two surface temperatures.
#[derive(Clone, Copy, Debug)]
pub struct GapConduction<'a> {
    /// The thermal law of the interaction.
    pub law: &'a GapLaw,
    /// θ_A, the slave surface's temperature (`TEMP(1)`).
    pub theta_slave: f64,
    /// θ_B, the master surface's temperature (`TEMP(2)`).
    pub theta_master: f64,
}

/// How the frictional dissipation becomes heat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionalHeating {
    /// η, the fraction of the frictional dissipation converted into heat (0 = none).
    pub heat_fraction: f64,
    /// f, the part of that heat flowing into the slave surface (1 − f into the master).
    pub slave_fraction: f64,
}

/// What the heat depends on from the mechanical answer of one increment with N tangential
/// directions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MechanicalAnswer<const N: usize> {
    /// Overclosure h (positive for penetration).
    pub overclosure: f64,
    /// Normal stress p at the end of the increment (positive in compression).
    pub normal_stress: f64,
    /// ∂p/∂h.
    pub dp_dh: f64,
    /// Frictional dissipation SFD of the increment.
    pub sfd: f64,
    /// ∂SFD/∂h.
    pub dsfd_dh: f64,
    /// ∂SFD/∂Δγ.
    pub dsfd_dgam: [f64; N],
    /// Δt.
    pub dtime: f64,
}

/// The heat exchanged at one point: `FLUX(2)` (into the slave, into the master),
/// `DDFDDT(2,2)` = −∂FLUX(i)/∂θ_j column-major, `DDFDDR(2,NDIR)` as rows
/// `[∂/∂h, ∂/∂Δγ₁, ∂/∂Δγ₂]` (the first 1 + N used).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InterfaceHeat {
    /// Flux into the slave and into the master surface.
    pub flux: [f64; 2],
    /// −∂FLUX(i)/∂θ_j, column-major (i fastest).
    pub ddfddt: [f64; 4],
    /// ∂FLUX(i)/∂(h, Δγ…), one row per surface.
    pub ddfddr: [[f64; 3]; 2],
}

impl InterfaceHeat {
    /// Conduction (when given) plus frictional heating. Fails when an input makes a result
    /// overflow, or the GAPCON law refuses its arguments.
    pub fn exchange<const N: usize>(
        conduction: Option<GapConduction<'_>>,
        heating: FrictionalHeating,
        m: &MechanicalAnswer<N>,
    ) -> Result<Self, LawError> {
        let mut out = InterfaceHeat {
            flux: [0.0; 2],
            ddfddt: [0.0; 4],
            ddfddr: [[0.0; 3]; 2],
        };
        if let Some(g) = conduction {
            let (theta_s, theta_m) = (g.theta_slave, g.theta_master);
            let clearance = (-m.overclosure).max(0.0);
            let pressure = m.normal_stress.max(0.0);
            let c = g.law.evaluate(clearance, pressure, theta_s, theta_m)?;
            // Seed 000, 5.2.4: q = k(θ_A − θ_B) leaves the slave and enters the master.
            let q = c.k * (theta_s - theta_m);
            out.flux = [-q, q];
            // DDFDDT(i,j) = −∂FLUX(i)/∂θ_j with ∂q/∂θ_A, ∂q/∂θ_B of seed 000, 5.2.4.
            out.ddfddt = [
                c.dq_dtheta_a,
                -c.dq_dtheta_a,
                c.dq_dtheta_b,
                -c.dq_dtheta_b,
            ];
            // ∂k/∂h: through the clearance −h when apart, through p(h) when closed.
            let dk_dh = if m.overclosure < 0.0 {
                -c.dk_dd
            } else if m.normal_stress > 0.0 {
                c.dk_dp * m.dp_dh
            } else {
                0.0
            };
            out.ddfddr[0][0] = -dk_dh * (theta_s - theta_m);
            out.ddfddr[1][0] = dk_dh * (theta_s - theta_m);
        }
        if heating.heat_fraction > 0.0 && m.dtime > 0.0 {
            // η·SFD/Δt, a part f into the slave and 1 − f into the master.
            let eta = heating.heat_fraction / m.dtime;
            let f = heating.slave_fraction;
            out.flux[0] += f * eta * m.sfd;
            out.flux[1] += (1.0 - f) * eta * m.sfd;
            for (i, part) in [f, 1.0 - f].into_iter().enumerate() {
                out.ddfddr[i][0] += part * eta * m.dsfd_dh;
                for b in 0..N {
                    out.ddfddr[i][1 + b] += part * eta * m.dsfd_dgam[b];
                }
            }
        }
        let finite = out.flux.iter().all(|v| v.is_finite())
            && out.ddfddt.iter().all(|v| v.is_finite())
            && out.ddfddr.iter().flatten().all(|v| v.is_finite());
        if finite {
            Ok(out)
        } else {
            Err(LawError::Numerical(
                "the heat flux overflowed (inputs too large for f64)".into(),
            ))
        }
    }
}
