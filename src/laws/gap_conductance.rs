//! Gap conductance across a thermal interface (seed 000, section 5.2.4): the flux is
//! q = k·(θ_A − θ_B) with k a function of the clearance d, the contact pressure p and the mean
//! surface temperature θ̄ = (θ_A + θ_B)/2, so that
//! ∂q/∂θ_A = k + ½(∂k/∂θ̄)(θ_A − θ_B) and ∂q/∂θ_B = −k + ½(∂k/∂θ̄)(θ_A − θ_B).
//!
//! A [`GapLaw`] is one conduction law plus optional [`Radiation`]; their conductances add.

use super::gap_radiation::Radiation;
use super::parameter_range::{nonnegative, positive};
use super::table::TemperatureTable;
use crate::LawError;

/// Exponent of the Cooper–Mikic–Yovanovich plastic contact correlation.
pub const CMY_EXPONENT: f64 = 0.95;

/// A conduction law k(d, p, θ̄).
#[derive(Clone, Debug, PartialEq)]
pub enum Conduction {
    /// k constant.
    Constant(f64),
    /// k(d, θ̄) tabulated in the clearance d.
    ClearanceTable(TemperatureTable),
    /// k(p, θ̄) tabulated in the contact pressure p.
    PressureTable(TemperatureTable),
    /// Conduction through the gas in the gap: k = k_gas/(max(d, d_min) + g₀).
    GasGap {
        /// Gas thermal conductivity.
        k_gas: f64,
        /// Temperature-jump distance added to the gap (rarefaction), ≥ 0.
        g0: f64,
        /// Smallest gap used (closed or overclosed points use it).
        min_gap: f64,
    },
    /// Solid-spot conductance of plastically deforming rough surfaces (Cooper–Mikic–Yovanovich;
    /// the correlation h = 1.25·k_s·(m/σ)·(p/H_c)^0.95 of M. M. Yovanovich, "Thermal contact
    /// correlations", AIAA Paper 81-1164, 1981, in Progress in Astronautics and Aeronautics
    /// vol. 83, 1982): h = c·(k_s·m/σ)·(p/H_c)^0.95 for 0 < p ≤ H_c, 0 for p ≤ 0; p > H_c is
    /// refused (the real contact area fraction p/H_c of the plastic model would exceed 1).
    SolidSpot {
        /// Correlation coefficient (1.25 in the correlation).
        c: f64,
        /// Harmonic mean conductivity of the two solids, 2k₁k₂/(k₁ + k₂).
        k_s: f64,
        /// Effective mean absolute profile slope, sqrt(m₁² + m₂²) of the two surfaces' mean
        /// |dz/dx| (not the RMS slope: for a Gaussian profile the RMS slope is sqrt(π/2) ≈ 1.25
        /// times larger and would overpredict h by that factor).
        m: f64,
        /// Effective RMS roughness sqrt(σ₁² + σ₂²).
        sigma: f64,
        /// Microhardness of the softer surface.
        h_c: f64,
    },
}

// The native C API writes it as it is (`IflConductance` in include/interfacial.h: cbindgen.toml
// renames it), so its layout is C's and its doc comments are the header's.
/// Gap conductance and its derivatives (seed 000, section 5.2.4): q = k·(θ_A − θ_B).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ConductanceResponse {
    /// Conductance k (conduction plus radiation's equivalent conductance).
    pub k: f64,
    /// ∂k/∂d (clearance).
    pub dk_dd: f64,
    /// ∂k/∂p (contact pressure).
    pub dk_dp: f64,
    /// ∂k/∂θ̄, θ̄ = (θ_A + θ_B)/2 (for radiation: at fixed θ_A − θ_B).
    pub dk_dtheta_mean: f64,
    /// ∂q/∂θ_A = k + ½(∂k/∂θ̄)(θ_A − θ_B) for conduction, exact for radiation.
    pub dq_dtheta_a: f64,
    /// ∂q/∂θ_B = −k + ½(∂k/∂θ̄)(θ_A − θ_B) for conduction, exact for radiation.
    pub dq_dtheta_b: f64,
}

impl Conduction {
    /// Constant k ≥ 0.
    pub fn constant(k: f64) -> Result<Self, LawError> {
        Ok(Conduction::Constant(nonnegative("k", k)?))
    }

    /// k tabulated in clearance (and θ̄); every tabulated k must be ≥ 0.
    pub fn clearance_table(table: TemperatureTable) -> Result<Self, LawError> {
        check_table(&table)?;
        Ok(Conduction::ClearanceTable(table))
    }

    /// k tabulated in pressure (and θ̄); every tabulated k must be ≥ 0.
    pub fn pressure_table(table: TemperatureTable) -> Result<Self, LawError> {
        check_table(&table)?;
        Ok(Conduction::PressureTable(table))
    }

    /// Gas-gap conduction; needs g₀ + d_min > 0 so that k stays finite.
    pub fn gas_gap(k_gas: f64, g0: f64, min_gap: f64) -> Result<Self, LawError> {
        let k_gas = nonnegative("k_gas", k_gas)?;
        let g0 = nonnegative("g0", g0)?;
        let min_gap = nonnegative("min_gap", min_gap)?;
        if g0 + min_gap <= 0.0 {
            return Err(LawError::Parameter(
                "g0 + min_gap must be > 0 (k_gas/(d + g0) is infinite at d = 0)".into(),
            ));
        }
        Ok(Conduction::GasGap { k_gas, g0, min_gap })
    }

    /// Cooper–Mikic–Yovanovich solid-spot conductance.
    pub fn solid_spot(c: f64, k_s: f64, m: f64, sigma: f64, h_c: f64) -> Result<Self, LawError> {
        Ok(Conduction::SolidSpot {
            c: positive("c", c)?,
            k_s: positive("k_s", k_s)?,
            m: positive("m", m)?,
            sigma: positive("sigma", sigma)?,
            h_c: positive("H_c", h_c)?,
        })
    }

    /// k(d, p, θ̄) with ∂k/∂d, ∂k/∂p, ∂k/∂θ̄.
    #[inline]
    #[must_use]
    pub fn evaluate(&self, d: f64, p: f64, theta_mean: f64) -> (f64, f64, f64, f64) {
        match self {
            Conduction::Constant(k) => (*k, 0.0, 0.0, 0.0),
            Conduction::ClearanceTable(t) => {
                let (k, dk_dd, dk_dt) = t.eval(d, theta_mean);
                (k, dk_dd, 0.0, dk_dt)
            }
            Conduction::PressureTable(t) => {
                let (k, dk_dp, dk_dt) = t.eval(p, theta_mean);
                (k, 0.0, dk_dp, dk_dt)
            }
            Conduction::GasGap { k_gas, g0, min_gap } => {
                if d > *min_gap {
                    let gap = d + g0;
                    (k_gas / gap, -k_gas / (gap * gap), 0.0, 0.0)
                } else {
                    (k_gas / (min_gap + g0), 0.0, 0.0, 0.0)
                }
            }
            Conduction::SolidSpot {
                c,
                k_s,
                m,
                sigma,
                h_c,
            } => {
                if p > 0.0 {
                    let h = c * (k_s * m / sigma) * (p / h_c).powf(CMY_EXPONENT);
                    (h, 0.0, CMY_EXPONENT * h / p, 0.0)
                } else {
                    (0.0, 0.0, 0.0, 0.0)
                }
            }
        }
    }
}

/// The CMY correlation outside its model: the plastic real-area fraction p/H_c above 1.
#[cold]
#[inline(never)]
fn pressure_above_hardness(p: f64, h_c: f64) -> LawError {
    LawError::Input(format!(
        "contact pressure D(2) = {p} exceeds the microhardness H_c = {h_c} of the cmy law \
         (P/H_c = {}): the solid-spot correlation needs P/H_c ≤ 1 (docs/config.md)",
        p / h_c
    ))
}

fn check_table(t: &TemperatureTable) -> Result<(), LawError> {
    let least = t.min_value();
    if least < 0.0 {
        Err(LawError::Parameter(format!(
            "the table holds a negative conductance ({least})"
        )))
    } else {
        Ok(())
    }
}

/// The thermal law of one interaction: conduction, radiation, or both (conductances add).
#[derive(Clone, Debug, PartialEq)]
pub struct GapLaw {
    conduction: Option<Conduction>,
    radiation: Option<Radiation>,
}

impl GapLaw {
    /// At least one of the two parts must be given.
    pub fn new(
        conduction: Option<Conduction>,
        radiation: Option<Radiation>,
    ) -> Result<Self, LawError> {
        if conduction.is_none() && radiation.is_none() {
            return Err(LawError::Parameter(
                "neither a conductance law nor radiation is given".into(),
            ));
        }
        Ok(GapLaw {
            conduction,
            radiation,
        })
    }

    /// The conduction part.
    #[must_use]
    pub fn conduction(&self) -> Option<&Conduction> {
        self.conduction.as_ref()
    }

    /// The radiation part.
    #[must_use]
    pub fn radiation(&self) -> Option<&Radiation> {
        self.radiation.as_ref()
    }

    /// k and its derivatives at clearance d, pressure p and surface temperatures θ_A, θ_B.
    pub fn evaluate(
        &self,
        d: f64,
        p: f64,
        theta_a: f64,
        theta_b: f64,
    ) -> Result<ConductanceResponse, LawError> {
        for (name, v) in [
            ("D(1)", d),
            ("D(2)", p),
            ("TEMP(1)", theta_a),
            ("TEMP(2)", theta_b),
        ] {
            if !v.is_finite() {
                return Err(LawError::Input(format!("{name} is NaN or infinite")));
            }
        }
        let theta_mean = 0.5 * (theta_a + theta_b);
        let jump = theta_a - theta_b;
        let mut out = ConductanceResponse::default();
        if let Some(c) = &self.conduction {
            if let Conduction::SolidSpot { h_c, .. } = c {
                if p > *h_c {
                    return Err(pressure_above_hardness(p, *h_c));
                }
            }
            let (k, dk_dd, dk_dp, dk_dt) = c.evaluate(d, p, theta_mean);
            // Seed 000, 5.2.4: ∂q/∂θ_A = k + ½ k' (θ_A − θ_B), ∂q/∂θ_B = −k + ½ k' (θ_A − θ_B).
            out = ConductanceResponse {
                k,
                dk_dd,
                dk_dp,
                dk_dtheta_mean: dk_dt,
                dq_dtheta_a: k + 0.5 * dk_dt * jump,
                dq_dtheta_b: -k + 0.5 * dk_dt * jump,
            };
        }
        if let Some(r) = &self.radiation {
            let rad = r.evaluate(theta_a, theta_b)?;
            out.k += rad.k;
            out.dk_dtheta_mean += rad.dk_dtheta_mean;
            out.dq_dtheta_a += rad.dq_dtheta_a;
            out.dq_dtheta_b += rad.dq_dtheta_b;
        }
        let all = [
            out.k * jump,
            out.k,
            out.dk_dd,
            out.dk_dp,
            out.dk_dtheta_mean,
            out.dq_dtheta_a,
            out.dq_dtheta_b,
        ];
        if all.iter().all(|v| v.is_finite()) {
            Ok(out)
        } else {
            Err(LawError::Numerical(
                "the conductance or the flux overflowed (inputs too large for f64)".into(),
            ))
        }
    }
}
