//! Frictional heating at a contact point: which part of the frictional work becomes heat and how
//! it is shared between the two surfaces.
//!
//! The frictional power per unit area is |τ|·v (the friction stress times the sliding speed).
//! Of it, the fraction η goes into heat (the rest is stored in the surface layers or carried
//! away as wear debris); the slave surface takes the share f of that heat and the master 1 − f:
//!
//! q_slave = f·η·|τ|·v,   q_master = (1 − f)·η·|τ|·v.
//!
//! f is given, or follows from the thermal effusivities e = √(k·ρ·c) of the two bodies: for two
//! bodies in perfect thermal contact that see the same heat source for the same time, the
//! surface temperatures of both sides rise alike when f = e_s/(e_s + e_m) (Charron's partition,
//! the usual choice for two bodies that are both stationary with respect to the contact zone).
//!
//! The host multiplies: CalculiX's `fricheat` returns η, f and v, and CalculiX forms the flux from
//! them and the contact stress (docs/calculix.md).

use super::parameter_range::{nonnegative, positive};
use crate::LawError;

/// How the heat is shared between the surfaces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HeatShare {
    /// The slave's share f, 0 ≤ f ≤ 1, given.
    Given(f64),
    /// f = e_s/(e_s + e_m) from the two effusivities √(k·ρ·c), both > 0.
    Effusivities {
        /// The slave body's effusivity.
        slave: f64,
        /// The master body's effusivity.
        master: f64,
    },
}

/// The sliding speed v the frictional power is formed with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SlidingSpeed {
    /// A given speed v > 0 (a brake disc's ω·r, a belt's speed, an imposed drag rate).
    Given(f64),
    /// The host's own relative velocity of the surfaces (CalculiX: from the nodal velocities,
    /// which only dynamic steps have).
    FromHost,
}

/// A frictional heating law, validated on construction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionalHeat {
    fraction: f64,
    slave_share: f64,
    speed: SlidingSpeed,
}

impl FrictionalHeat {
    /// η in (0, 1] (`fraction`), the share (f in [0, 1], or two effusivities > 0), the speed
    /// (> 0 when given).
    pub fn new(fraction: f64, share: HeatShare, speed: SlidingSpeed) -> Result<Self, LawError> {
        if !(fraction.is_finite() && fraction > 0.0 && fraction <= 1.0) {
            return Err(LawError::Parameter(format!(
                "fraction = {fraction} (the part of the frictional work turned into heat) must \
                 be in (0, 1]"
            )));
        }
        let slave_share = match share {
            HeatShare::Given(f) => {
                if nonnegative("slave_share", f)? > 1.0 {
                    return Err(LawError::Parameter(format!(
                        "slave_share = {f} (the slave surface's part of the heat) must be in \
                         [0, 1]"
                    )));
                }
                f
            }
            HeatShare::Effusivities { slave, master } => {
                let s = positive("slave_effusivity", slave)?;
                let m = positive("master_effusivity", master)?;
                // s/(s + m) written as 1/(1 + m/s): no overflow of s + m for huge values.
                1.0 / (1.0 + m / s)
            }
        };
        if let SlidingSpeed::Given(v) = speed {
            positive("speed", v)?;
        }
        Ok(FrictionalHeat {
            fraction,
            slave_share,
            speed,
        })
    }

    /// η, the part of the frictional work turned into heat.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        self.fraction
    }

    /// f, the slave surface's part of the heat (the master takes 1 − f).
    #[must_use]
    pub fn slave_share(&self) -> f64 {
        self.slave_share
    }

    /// The sliding speed v.
    #[must_use]
    pub fn speed(&self) -> SlidingSpeed {
        self.speed
    }

    /// The heat fluxes (slave, master) into the two surfaces at friction stress magnitude
    /// `tau` ≥ 0 and sliding speed `v` ≥ 0: (f·η·|τ|·v, (1 − f)·η·|τ|·v). They add up to
    /// η·|τ|·v.
    #[must_use]
    pub fn fluxes(&self, tau: f64, v: f64) -> (f64, f64) {
        let q = self.fraction * tau * v;
        (self.slave_share * q, (1.0 - self.slave_share) * q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn charron_share_is_the_effusivity_ratio() {
        // Steel on cast iron, e = √(kρc): √(50·7850·470) and √(45·7200·500).
        let es = (50.0_f64 * 7850.0 * 470.0).sqrt();
        let em = (45.0_f64 * 7200.0 * 500.0).sqrt();
        let law = FrictionalHeat::new(
            0.95,
            HeatShare::Effusivities {
                slave: es,
                master: em,
            },
            SlidingSpeed::Given(2.0),
        )
        .unwrap();
        let f = law.slave_share();
        assert!((f - es / (es + em)).abs() <= 1e-15, "{f}");
        // Equal bodies share equally, whatever their effusivity.
        for e in [1e-3, 1.0, 1e300] {
            let eq = FrictionalHeat::new(
                1.0,
                HeatShare::Effusivities {
                    slave: e,
                    master: e,
                },
                SlidingSpeed::FromHost,
            )
            .unwrap();
            assert_eq!(eq.slave_share(), 0.5);
        }
    }

    #[test]
    fn fluxes_split_eta_tau_v() {
        let law =
            FrictionalHeat::new(0.8, HeatShare::Given(0.25), SlidingSpeed::Given(3.0)).unwrap();
        let (s, m) = law.fluxes(10.0, 3.0);
        assert!((s - 0.25 * 0.8 * 30.0).abs() <= 1e-14, "{s}");
        assert!((m - 0.75 * 0.8 * 30.0).abs() <= 1e-14, "{m}");
        assert!((s + m - 0.8 * 30.0).abs() <= 1e-14);
    }

    #[test]
    fn bad_parameters_name_the_key() {
        let v = SlidingSpeed::Given(1.0);
        for (fraction, share, speed, needle) in [
            (0.0, HeatShare::Given(0.5), v, "fraction = 0"),
            (1.5, HeatShare::Given(0.5), v, "fraction = 1.5"),
            (f64::NAN, HeatShare::Given(0.5), v, "fraction = NaN"),
            (1.0, HeatShare::Given(-0.1), v, "slave_share = -0.1"),
            (1.0, HeatShare::Given(1.01), v, "slave_share = 1.01"),
            (
                1.0,
                HeatShare::Effusivities {
                    slave: 0.0,
                    master: 1.0,
                },
                v,
                "slave_effusivity = 0",
            ),
            (
                1.0,
                HeatShare::Effusivities {
                    slave: 1.0,
                    master: f64::INFINITY,
                },
                v,
                "master_effusivity = inf",
            ),
            (
                1.0,
                HeatShare::Given(0.5),
                SlidingSpeed::Given(-2.0),
                "speed = -2",
            ),
        ] {
            let e = FrictionalHeat::new(fraction, share, speed)
                .unwrap_err()
                .to_string();
            assert!(e.contains(needle), "{e}");
        }
        // The ends of the ranges are valid.
        for f in [0.0, 1.0] {
            FrictionalHeat::new(1.0, HeatShare::Given(f), v).unwrap();
        }
    }
}
