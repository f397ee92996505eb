//! Coulomb friction as a force, for Abaqus/Explicit's kinematic contact (the `VFRIC` entry).
//!
//! Seed 000, section 5.2.3: the critical stress is τ_crit = min(μp, τ_max), and "in
//! ABAQUS/Explicit the relative motion in the absence of slip is always equal to zero if the
//! kinematic contact algorithm is used": stick is exact, there is no elastic slip, no γ_crit
//! and no tangent. The host gives, per contact point, the normal force F_N and the stick force
//! F_stick (the tangential force that would stop the point's slip in the increment); the law
//! answers the magnitude of the friction force
//!
//! ```text
//! F = min(F_crit, F_stick),   F_crit = min(μ F_N, τ_max A)   (0 when F_N < 0),
//! ```
//!
//! with A the contact area of the point (only needed with a shear limit τ_max), and the host
//! applies it against the slip (`fTangential(1) = −F`). F < F_stick is slip, F = F_stick stick.
//! Rough friction (`PROPS(7) = 2`) has no bound: F = F_stick always.

use super::coulomb::{Coulomb, StickMode};
use crate::LawError;

/// The force form of a plain Coulomb law: μ, the shear limit, whether friction is rough.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KinematicCoulomb {
    mu: f64,
    /// `f64::INFINITY` without a shear limit.
    tau_max: f64,
    rough: bool,
}

impl KinematicCoulomb {
    /// The force form of `law`. γ_crit and the slip tolerance have no meaning in kinematic
    /// contact (stick is exact) and are ignored, as is the difference between elastic and
    /// exact stick.
    #[must_use]
    pub fn new(law: &Coulomb) -> Self {
        KinematicCoulomb {
            mu: law.mu(),
            tau_max: law.shear_limit().unwrap_or(f64::INFINITY),
            rough: law.stick() == StickMode::Rough,
        }
    }

    /// Whether the law needs the contact area (it has a shear limit τ_max).
    #[must_use]
    pub fn needs_area(&self) -> bool {
        self.tau_max.is_finite() && !self.rough
    }

    /// The magnitude F of the friction force at a point with normal force `f_normal`, stick
    /// force `f_stick` (≥ 0) and contact area `area` (read only when [`Self::needs_area`]).
    ///
    /// # Errors
    /// A non-finite `f_normal` or `f_stick`, a negative `f_stick`, or (with τ_max) a negative or
    /// non-finite `area`.
    pub fn force(&self, f_normal: f64, f_stick: f64, area: f64) -> Result<f64, LawError> {
        if !f_normal.is_finite() {
            return Err(LawError::Input(format!(
                "fNormal = {f_normal}; expected a finite force"
            )));
        }
        if !(f_stick.is_finite() && f_stick >= 0.0) {
            return Err(LawError::Input(format!(
                "fStickForce = {f_stick}; expected a finite force ≥ 0"
            )));
        }
        if self.rough {
            // Rough friction: no bound on the shear force, always stuck.
            return Ok(f_stick);
        }
        // τ_crit = min(μp, τ_max), 0 for p < 0 (seed 000, section 5.2.3), as forces.
        let critical = if f_normal < 0.0 {
            0.0
        } else {
            let mu_n = self.mu * f_normal;
            if self.needs_area() {
                if !(area.is_finite() && area >= 0.0) {
                    return Err(LawError::Input(format!(
                        "areaSlv = {area}; expected a finite area ≥ 0 (needed with τ_max = \
                         PROPS(4) > 0)"
                    )));
                }
                mu_n.min(self.tau_max * area)
            } else {
                mu_n
            }
        };
        // Kinematic stick is exact: the force never exceeds what stops the slip.
        Ok(critical.min(f_stick))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law() -> Coulomb {
        Coulomb::new(0.3).unwrap()
    }

    #[test]
    fn slip_gives_mu_fn_and_stick_the_stick_force() {
        let k = KinematicCoulomb::new(&law());
        // μF_N = 3 < F_stick = 5: slip at 3.
        assert_eq!(k.force(10.0, 5.0, 0.0).unwrap(), 0.3 * 10.0);
        // μF_N = 3 > F_stick = 2: stick at 2.
        assert_eq!(k.force(10.0, 2.0, 0.0).unwrap(), 2.0);
        // Tension: no friction.
        assert_eq!(k.force(-1.0, 2.0, 0.0).unwrap(), 0.0);
    }

    #[test]
    fn shear_limit_scales_with_area_and_rough_ignores_it() {
        let capped = law().with_shear_limit(2.0).unwrap();
        let k = KinematicCoulomb::new(&capped);
        // τ_max A = 2·0.5 = 1 < μF_N = 3 < F_stick = 5.
        assert_eq!(k.force(10.0, 5.0, 0.5).unwrap(), 1.0);
        assert!(k.force(10.0, 5.0, f64::NAN).is_err());
        let rough = KinematicCoulomb::new(&capped.with_stick(StickMode::Rough));
        assert!(!rough.needs_area());
        assert_eq!(rough.force(10.0, 5.0, f64::NAN).unwrap(), 5.0);
    }

    #[test]
    fn bad_forces_are_refused_and_huge_ones_stay_finite() {
        let k = KinematicCoulomb::new(&law());
        assert!(k.force(f64::NAN, 1.0, 0.0).is_err());
        assert!(k.force(1.0, -1.0, 0.0).is_err());
        assert!(k.force(1.0, f64::INFINITY, 0.0).is_err());
        // μF_N overflows nothing here, but F_N = f64::MAX with μ > 1 would: min keeps F_stick.
        let steep = KinematicCoulomb::new(&Coulomb::new(4.0).unwrap());
        assert_eq!(steep.force(f64::MAX, 7.0, 0.0).unwrap(), 7.0);
    }
}
