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
            out.ddfddt = [c.dq_dtheta_a, -c.dq_dtheta_a, c.dq_dtheta_b, -c.dq_dtheta_b];
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laws::gap_conductance::Conduction;

    fn answer(h: f64, k_n: f64) -> MechanicalAnswer<2> {
        MechanicalAnswer {
            overclosure: h,
            normal_stress: k_n * h,
            dp_dh: k_n,
            sfd: 0.0,
            dsfd_dh: 0.0,
            dsfd_dgam: [0.0; 2],
            dtime: 0.1,
        }
    }

    const NO_HEATING: FrictionalHeating = FrictionalHeating {
        heat_fraction: 0.0,
        slave_fraction: 0.5,
    };

    /// η·SFD/Δt split f / 1 − f, and its derivatives the same split of η·∂SFD/∂(h, Δγ)/Δt;
    /// nothing with Δt = 0 or η = 0; the two fluxes add up to η·SFD/Δt.
    #[test]
    fn frictional_heat_is_split_between_the_surfaces() {
        let (eta, f, dt) = (0.8, 0.25, 0.5);
        let m = MechanicalAnswer::<2> {
            sfd: 3.0,
            dsfd_dh: 7.0,
            dsfd_dgam: [11.0, -13.0],
            dtime: dt,
            ..answer(1e-3, 1e4)
        };
        let heating = FrictionalHeating {
            heat_fraction: eta,
            slave_fraction: f,
        };
        let out = InterfaceHeat::exchange(None, heating, &m).unwrap();
        let q = eta * 3.0 / dt;
        assert!((out.flux[0] - f * q).abs() <= 1e-15 * q);
        assert!((out.flux[1] - (1.0 - f) * q).abs() <= 1e-15 * q);
        assert!((out.flux[0] + out.flux[1] - q).abs() <= 1e-15 * q);
        for (i, part) in [f, 1.0 - f].into_iter().enumerate() {
            let want = [7.0, 11.0, -13.0].map(|d| part * eta * d / dt);
            for (got, w) in out.ddfddr[i].iter().zip(want) {
                assert!((got - w).abs() <= 1e-14 * w.abs(), "{got} against {w}");
            }
        }
        assert_eq!(out.ddfddt, [0.0; 4]);
        for m in [MechanicalAnswer { dtime: 0.0, ..m }, m] {
            let h = if m.dtime == 0.0 { heating } else { NO_HEATING };
            let none = InterfaceHeat::exchange(None, h, &m).unwrap();
            assert_eq!(none.flux, [0.0; 2]);
            assert_eq!(none.ddfddr, [[0.0; 3]; 2]);
        }
    }

    /// Constant k: q = k(θ_A − θ_B) out of the slave into the master (seed 000, 5.2.4),
    /// DDFDDT = −∂FLUX/∂θ = [[k, −k], [−k, k]], no dependence on h.
    #[test]
    fn constant_conductance_closed_form() {
        let k = 2.5;
        let law = GapLaw::new(Some(Conduction::Constant(k)), None).unwrap();
        let g = GapConduction {
            law: &law,
            theta_slave: 80.0,
            theta_master: 20.0,
        };
        let out = InterfaceHeat::exchange(Some(g), NO_HEATING, &answer(-1e-3, 1e4)).unwrap();
        assert_eq!(out.flux, [-k * 60.0, k * 60.0]);
        assert_eq!(out.ddfddt, [k, -k, -k, k]);
        assert_eq!(out.ddfddr, [[0.0; 3]; 2]);
    }

    /// ∂FLUX/∂h against central differences of FLUX itself: apart (gas-gap k through the
    /// clearance −h) and closed (solid-spot k through p = K_n·h).
    #[test]
    fn ddfddr_h_matches_central_differences() {
        let k_n = 1e4;
        let laws = [
            (
                Conduction::GasGap {
                    k_gas: 0.03,
                    g0: 1e-5,
                    min_gap: 1e-6,
                },
                -2e-4,
            ),
            (
                Conduction::SolidSpot {
                    c: 1.25,
                    k_s: 40.0,
                    m: 0.1,
                    sigma: 1e-6,
                    h_c: 1e9,
                },
                3e-3,
            ),
        ];
        for (conduction, h) in laws {
            let law = GapLaw::new(Some(conduction), None).unwrap();
            let g = GapConduction {
                law: &law,
                theta_slave: 120.0,
                theta_master: 35.0,
            };
            let at = |h: f64| InterfaceHeat::exchange(Some(g), NO_HEATING, &answer(h, k_n));
            let out = at(h).unwrap();
            let step = 1e-6 * h.abs();
            let (up, down) = (at(h + step).unwrap(), at(h - step).unwrap());
            for i in 0..2 {
                let fd = (up.flux[i] - down.flux[i]) / (2.0 * step);
                assert!(fd != 0.0, "the case must depend on h");
                assert!(
                    (out.ddfddr[i][0] - fd).abs() <= 1e-6 * fd.abs(),
                    "{i}: {} against {fd}",
                    out.ddfddr[i][0]
                );
            }
        }
    }

    /// A heat flux too large for f64 is refused, not returned as ∞.
    #[test]
    fn overflow_is_refused() {
        let m = MechanicalAnswer::<2> {
            sfd: 1e300,
            dtime: 1e-10,
            ..answer(1e-3, 1e4)
        };
        let heating = FrictionalHeating {
            heat_fraction: 1.0,
            slave_fraction: 0.5,
        };
        let e = InterfaceHeat::exchange(None, heating, &m).unwrap_err();
        assert!(e.to_string().contains("heat flux overflowed"), "{e}");
    }
}
