//! The adhesive interface (seed 004) as a whole: normal behaviour, separation adhesion and the
//! tangential law of [`super::adhesive`], for hosts that hand the library the full interface
//! (Abaqus UINTER).
//!
//! Normal behaviour, with h the overclosure (positive for penetration) and K_n a penalty
//! stiffness ("hard" contact made slightly soft):
//! - closed, h > 0: p = K_n·h, and the surfaces are bonded again (adhesion is reversible: seed
//!   004, "they will stick with the same adhesive strengths when the surfaces come back into
//!   contact"); tangential law of [`super::adhesive::Adhesive::slide`] at pressure p;
//! - apart, h ≤ 0, bonded at the start of the increment and both S_a, N_a > 0: the bond is an
//!   elastic spring in tension, N = K_n·|h| (p = K_n·h ≤ 0), and in shear, S = k_s·|γ^pr| with
//!   k_s = S_a/γ_crit (the stick stiffness at p = 0); the surfaces "continue to stick as long as
//!   (S/S_a)² + (N/N_a)² < 1" (seed 004), else the bond breaks in this increment;
//! - apart and not bonded (broken, or no separation adhesion): free, zero stress.
//!
//! Energy released by a breaking bond ([`InterfaceResponse::spd`], UINTER's `SPD`): the elastic
//! energy the bond held at the start of the increment (the last converged state: with backward
//! Euler the break point inside the increment is unknown) and that the separation does not
//! give back as work, ½|τ̄|²/k̄_s + ½N̄²/K_n with N̄ = max(−p̄, 0); a compressive penalty energy
//! ½p̄²/K_n is returned as the surfaces unload through h = 0, so it is not dissipated.
//!
//! State (`STATEV(1..3)`): accumulated slip, slip rate, and the status below.

use super::adhesive::Adhesive;
use super::contact::{PointState, StatusCode, Traction, elastic_start_slip, elastic_stick_stress};
use super::friction_coefficient::RateFormulation;
use super::interface_heat::MechanicalAnswer;
use super::parameter_range::positive;
use super::small_vec::{add, all_finite, norm, scale};
use crate::LawError;

/// What the interface point did in the increment (`STATEV(3)`). The numbers 0 and 1 are the
/// Coulomb law's; 2 (exact stick) does not occur here.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum InterfaceStatus {
    /// Closed, elastic stick.
    #[default]
    Stick = 0,
    /// Closed, sliding.
    Slip = 1,
    /// Apart but bonded: carrying tension and shear.
    Bonded = 3,
    /// Apart and free (bond broken, or no separation adhesion).
    Open = 4,
}

/// The interface's state: three scalars in `STATEV(1..3)`, as the Coulomb law's with the
/// interface's statuses.
pub type InterfaceState = PointState<InterfaceStatus>;

impl StatusCode for InterfaceStatus {
    const LAW: &'static str = "the adhesive interface";
    const STICK: Self = InterfaceStatus::Stick;
    const SLIP: Self = InterfaceStatus::Slip;

    /// A code other than 1, 3 or 4 reads as stick (0).
    #[inline(always)]
    fn from_code(code: f64) -> Self {
        match code {
            1.0 => InterfaceStatus::Slip,
            3.0 => InterfaceStatus::Bonded,
            4.0 => InterfaceStatus::Open,
            _ => InterfaceStatus::Stick,
        }
    }

    #[inline(always)]
    fn code(self) -> f64 {
        f64::from(self as i32)
    }
}

/// One increment of an interface point with N tangential directions (NDIR = N + 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InterfaceIncrement<const N: usize> {
    /// Normal stress at the start (positive in compression).
    pub normal_stress_start: f64,
    /// Shear stress at the start.
    pub shear_start: [f64; N],
    /// Overclosure h at the end of the increment (positive for penetration).
    pub overclosure: f64,
    /// Tangential relative motion of the increment Δγ.
    pub dgam: [f64; N],
    /// Δt.
    pub dtime: f64,
    /// Characteristic contact length (for γ_crit as a tolerance).
    pub characteristic_length: f64,
}

/// The interface's answer for one increment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InterfaceResponse<const N: usize> {
    /// Normal stress p (positive in compression, negative in bonded tension).
    pub normal_stress: f64,
    /// ∂p/∂h.
    pub dp_dh: f64,
    /// Shear stress, ∂τ/∂Δγ, ∂τ/∂p (multiply by ∂p/∂h for ∂τ/∂h), slip, SED and SFD of the
    /// tangential part.
    pub shear: Traction<N>,
    /// Elastic energy density, normal and tangential.
    pub sed: f64,
    /// State at the end of the increment.
    pub state: InterfaceState,
    /// True when the interface transmits stress (closed or bonded): `LOPENCLOSE = 1`.
    pub closed: bool,
    /// ∂SFD/∂Δγ: the frictional dissipation's derivative (for the frictional heat flux).
    pub dsfd_dgam: [f64; N],
    /// ∂SFD/∂h.
    pub dsfd_dh: f64,
    /// Energy per unit area dissipated by a bond breaking in this increment (`SPD`): 0 unless
    /// the point was bonded or closed at the start, the surfaces are apart and the separation
    /// criterion fails. An output only: it enters no tangent.
    pub spd: f64,
}

impl<const N: usize> InterfaceResponse<N> {
    /// What the interface's heat exchange ([`super::interface_heat::InterfaceHeat`]) needs
    /// from this answer to the increment `inc`.
    #[must_use]
    pub fn mechanical_answer(&self, inc: &InterfaceIncrement<N>) -> MechanicalAnswer<N> {
        MechanicalAnswer {
            overclosure: inc.overclosure,
            normal_stress: self.normal_stress,
            dp_dh: self.dp_dh,
            sfd: self.shear.sfd,
            dsfd_dh: self.dsfd_dh,
            dsfd_dgam: self.dsfd_dgam,
            dtime: inc.dtime,
        }
    }
}

/// The adhesive law with a penalty normal stiffness K_n.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdhesiveInterface {
    law: Adhesive,
    normal_stiffness: f64,
}

impl AdhesiveInterface {
    /// K_n must be finite and > 0.
    pub fn new(law: Adhesive, normal_stiffness: f64) -> Result<Self, LawError> {
        positive("penalty normal stiffness K_n", normal_stiffness)?;
        Ok(AdhesiveInterface {
            law,
            normal_stiffness,
        })
    }

    /// The tangential law.
    #[must_use]
    pub fn law(&self) -> &Adhesive {
        &self.law
    }

    /// K_n.
    #[must_use]
    pub fn normal_stiffness(&self) -> f64 {
        self.normal_stiffness
    }

    /// Integrates one increment.
    pub fn update<const N: usize>(
        &self,
        inc: &InterfaceIncrement<N>,
        state: &InterfaceState,
    ) -> Result<InterfaceResponse<N>, LawError> {
        let finite = inc.normal_stress_start.is_finite()
            && inc.overclosure.is_finite()
            && inc.dtime.is_finite()
            && all_finite(&inc.shear_start)
            && all_finite(&inc.dgam);
        if !finite {
            return Err(name_bad_input(inc));
        }
        // The memory of the rate-following formulation: the previous increment's slip.
        let sliding = state.sliding_rate()?;
        let gamma_crit = self.law.critical_slip_for(inc.characteristic_length)?;
        let k_n = self.normal_stiffness;
        let h = inc.overclosure;
        // The bond's life cycle (docs/uinter.md): a point is bonded only after it has been in
        // contact. The state records it: slipping (1) or bonded (3) at the start, or stuck (0)
        // under a compressive start stress (a closed point has p̄ = K_n·h̄ > 0). A fresh point
        // (all-zero `STATEV` and `STRESS`) is bonded only where it touches (h = 0, the surfaces
        // of a model that starts in contact); with a gap it is free, as is a free one (4).
        let was_bonded = match state.status {
            InterfaceStatus::Slip | InterfaceStatus::Bonded => true,
            InterfaceStatus::Stick => inc.normal_stress_start > 0.0 || h >= 0.0,
            InterfaceStatus::Open => false,
        };
        let response = if h > 0.0 {
            let p = k_n * h;
            let s = self.law.slide(
                sliding,
                &inc.shear_start,
                &inc.dgam,
                inc.normal_stress_start,
                p,
                inc.dtime,
                gamma_crit,
            )?;
            let slip = norm(&s.traction.dslip);
            // One call per formulation, so that each inlines with its `rate_free` known.
            let (dsfd_dgam, dsfd_dp) = match self.law.rate_formulation() {
                RateFormulation::RateFollowingStiffness => {
                    dissipation_derivatives(&s.traction, None)
                }
                RateFormulation::RateFreeStiffness => {
                    let (_, dtau_s_dp) = self.law.static_strength(p);
                    let dk_s_dp = dtau_s_dp / gamma_crit;
                    dissipation_derivatives(&s.traction, Some((s.stick_stiffness, dk_s_dp)))
                }
            };
            InterfaceResponse {
                dsfd_dgam,
                dsfd_dh: dsfd_dp * k_n,
                normal_stress: p,
                dp_dh: k_n,
                sed: s.traction.sed + 0.5 * p * p / k_n,
                shear: s.traction,
                state: state.after_slide(slip, s.slip_rate, s.branch.status()),
                closed: true,
                spd: 0.0,
            }
        } else if was_bonded && self.law.separation_adhesion() {
            self.bonded(inc, state, sliding, gamma_crit)
        } else {
            self.open(state)
        };
        let t = &response.shear;
        // ∂τ_a/∂p·K_n is the host's DDSDDR(1+a,1): it can overflow where neither factor does
        // (a slip rate over a DTIME near f64::MIN_POSITIVE with k_μ > 0: fuzz target `uinter`).
        let ok = response.normal_stress.is_finite()
            && response.sed.is_finite()
            && t.is_finite()
            && t.ddtddp.iter().all(|d| (d * response.dp_dh).is_finite());
        if ok {
            Ok(response)
        } else {
            Err(LawError::Numerical(
                "the interface stress update overflowed (inputs too large for f64)".into(),
            ))
        }
    }

    /// Apart and bonded at the start: elastic in tension and shear while
    /// (S/S_a)² + (N/N_a)² < 1 (seed 004), else the bond breaks.
    fn bonded<const N: usize>(
        &self,
        inc: &InterfaceIncrement<N>,
        state: &InterfaceState,
        sliding: Option<f64>,
        gamma_crit: f64,
    ) -> InterfaceResponse<N> {
        let (s_a, n_a, k_n) = (
            self.law.shear_adhesion(),
            self.law.normal_adhesion(),
            self.normal_stiffness,
        );
        // The stiffness the start shear was built with (after a slip: the sliding strength).
        let (tau_s_start, _) = self.law.stick_strength(sliding, inc.normal_stress_start);
        let elastic_start = elastic_start_slip(&inc.shear_start, gamma_crit, tau_s_start);
        let predictor = add(&elastic_start, &inc.dgam);
        // k_s = τ_s(0)/γ_crit = S_a/γ_crit.
        let (shear, k_s) = elastic_stick_stress(&predictor, gamma_crit, s_a);
        let tension = -k_n * inc.overclosure;
        let s_eq = norm(&shear);
        let measure = (s_eq / s_a).powi(2) + (tension / n_a).powi(2);
        if measure >= 1.0 {
            let mut broken = self.open(state);
            broken.spd = released_energy(
                norm(&inc.shear_start),
                tau_s_start,
                gamma_crit,
                -inc.normal_stress_start,
                k_n,
            );
            return broken;
        }
        let mut ddtddg = [[0.0; N]; N];
        for (i, row) in ddtddg.iter_mut().enumerate() {
            row[i] = k_s;
        }
        InterfaceResponse {
            normal_stress: -tension,
            dp_dh: k_n,
            shear: Traction::sticking(
                shear,
                ddtddg,
                [0.0; N],
                0.5 * k_s * norm(&predictor).powi(2),
            ),
            sed: 0.5 * k_s * norm(&predictor).powi(2) + 0.5 * tension * tension / k_n,
            state: InterfaceState {
                accumulated_slip: state.accumulated_slip,
                slip_rate: 0.0,
                status: InterfaceStatus::Bonded,
            },
            closed: true,
            dsfd_dgam: [0.0; N],
            dsfd_dh: 0.0,
            spd: 0.0,
        }
    }

    fn open<const N: usize>(&self, state: &InterfaceState) -> InterfaceResponse<N> {
        InterfaceResponse {
            normal_stress: 0.0,
            dp_dh: 0.0,
            shear: Traction::stress_free([0.0; N], [0.0; N]),
            sed: 0.0,
            state: InterfaceState {
                accumulated_slip: state.accumulated_slip,
                slip_rate: 0.0,
                status: InterfaceStatus::Open,
            },
            closed: false,
            dsfd_dgam: [0.0; N],
            dsfd_dh: 0.0,
            spd: 0.0,
        }
    }
}

/// The elastic energy a breaking bond held at the start of the increment and does not return
/// (docs/uinter.md): ½|τ̄|²/k̄_s, with k̄_s = τ_s(p̄)/γ_crit the stick stiffness the start stress
/// was built with (S_a/γ_crit while bonded), plus ½N̄²/K_n for a start tension N̄ > 0 (the
/// spring snaps). A start compression contributes nothing: the penalty spring unloads through
/// h = 0 and gives its energy back. Written as τ̄·(τ̄·γ_crit/τ_s) and N̄·(N̄/K_n) so that they
/// overflow only when the energy does; then it saturates at f64::MAX (as the accumulated slip
/// does) rather than reporting ∞ (`f64::min` also maps the NaN of ∞·0, possible only for
/// |τ̄| beyond f64, to f64::MAX).
fn released_energy(
    tau_start: f64,
    tau_s_start: f64,
    gamma_crit: f64,
    tension: f64,
    k_n: f64,
) -> f64 {
    // Start shear energy ½|τ̄|·|γ̄^el|, with γ̄^el = τ̄·γ_crit/τ_s(p̄) (the elastic slip the
    // tangential law recovers from τ̄).
    let shear = if tau_start > 0.0 && tau_s_start > 0.0 {
        0.5 * tau_start * (tau_start * (gamma_crit / tau_s_start))
    } else {
        0.0
    };
    let normal = if tension > 0.0 {
        0.5 * tension * (tension / k_n)
    } else {
        0.0
    };
    (shear + normal).min(f64::MAX)
}

/// Derivatives of SFD = |τ|·Δs (sliding; 0 otherwise) with respect to Δγ and p, from the
/// consistent tangents: dSFD = Δs·d|τ| + |τ|·dΔs with d|τ| = n·dτ. In the rate-following
/// formulation (`rate_free = None`) Δs = |γ^pr| − γ_crit, so dΔs = n·dγ and ∂Δs/∂p = 0; in the
/// earlier one (`rate_free = Some((k_s, ∂k_s/∂p))`) Δs = |γ^pr| − |τ|/k_s, so
/// dΔs = n·dγ − d|τ|/k_s + |τ| dk_s/k_s².
#[inline(always)]
fn dissipation_derivatives<const N: usize>(
    t: &Traction<N>,
    rate_free: Option<(f64, f64)>,
) -> ([f64; N], f64) {
    let slip = norm(&t.dslip);
    if slip == 0.0 || rate_free.is_some_and(|(k_s, _)| k_s == 0.0) {
        return ([0.0; N], 0.0);
    }
    let n = scale(&t.dslip, 1.0 / slip);
    let tau = norm(&t.tau);
    let mut dsfd_dgam = [0.0; N];
    for (b, d) in dsfd_dgam.iter_mut().enumerate() {
        let dtau_b: f64 = (0..N).map(|a| n[a] * t.ddtddg[a][b]).sum();
        let dslip_b = match rate_free {
            None => n[b],
            Some((k_s, _)) => n[b] - dtau_b / k_s,
        };
        *d = slip * dtau_b + tau * dslip_b;
    }
    let dtau_dp: f64 = (0..N).map(|a| n[a] * t.ddtddp[a]).sum();
    match rate_free {
        None => (dsfd_dgam, slip * dtau_dp),
        Some((k_s, dk_s_dp)) => {
            let dslip_dp = -dtau_dp / k_s + tau * dk_s_dp / (k_s * k_s);
            (dsfd_dgam, slip * dtau_dp + tau * dslip_dp)
        }
    }
}

#[cold]
#[inline(never)]
fn name_bad_input<const N: usize>(inc: &InterfaceIncrement<N>) -> LawError {
    let what = if !inc.overclosure.is_finite() {
        "RDISP(1)"
    } else if !all_finite(&inc.dgam) {
        "DRDISP"
    } else if !inc.normal_stress_start.is_finite() || !all_finite(&inc.shear_start) {
        "STRESS"
    } else {
        "DTIME"
    };
    LawError::Input(format!("{what} is NaN or infinite"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laws::adhesive::AdhesiveParameters;

    fn interface() -> AdhesiveInterface {
        let law = Adhesive::new(&AdhesiveParameters {
            coeff: 0.3,
            sa: 4.0,
            na: 10.0,
            ..AdhesiveParameters::default()
        })
        .and_then(|l| l.with_critical_slip_absolute(1e-3))
        .unwrap();
        AdhesiveInterface::new(law, 1e4).unwrap()
    }

    #[test]
    fn pull_off_at_the_ellipse() {
        // Bonded with S₀ = 2 (half of S_a = 4): breaks at N = N_a·sqrt(1 − 1/4) = 8.660…
        let i = interface();
        let s0 = 2.0;
        let n_break = 10.0 * (1.0f64 - 0.25).sqrt();
        let st = InterfaceState {
            status: InterfaceStatus::Bonded,
            ..InterfaceState::default()
        };
        for (n, holds) in [
            (n_break * (1.0 - 1e-9), true),
            (n_break * (1.0 + 1e-9), false),
        ] {
            let inc = InterfaceIncrement::<1> {
                normal_stress_start: 0.0,
                shear_start: [s0],
                overclosure: -n / 1e4,
                dgam: [0.0],
                dtime: 1.0,
                characteristic_length: 1.0,
            };
            let r = i.update(&inc, &st).unwrap();
            assert_eq!(r.closed, holds, "N = {n}");
            if holds {
                assert!((r.shear.tau[0] - s0).abs() < 1e-12);
                assert!((r.normal_stress + n).abs() < 1e-9);
            }
        }
    }
}
