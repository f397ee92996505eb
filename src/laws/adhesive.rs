//! Adhesive friction (seed 004): velocity-dependent Coulomb friction with a smooth static →
//! dynamic transition, a linear velocity term and shear adhesion, integrated inside the
//! elastic-stick return map of the Coulomb law (seed 000, Eq. 5.2.3-2).
//!
//! Symbols as in the seeds: p contact pressure, μ_s and μ_d static and dynamic coefficients
//! (`coeffStatic`, `coeff`), v_½ the slip rate at which the transition is half done (`vhalf`),
//! k_μ the slope of μ against the slip rate (`kmu`), S_a and N_a the shear and normal adhesive
//! strengths (`Sa`, `Na`), γ_crit the allowable elastic slip, Δv the slip rate.
//!
//! - Static strength (the stick limit from rest): τ_s(p) = μ_s·p⁺ + S_a, p⁺ = max(p, 0); elastic
//!   stick with k_s = τ_s/γ_crit, so a point starts to slide exactly when its stick stress
//!   exceeds μ_s·p + S_a (seed 004, first equation, condition S_stick > μ_s N + S_a).
//! - Sliding strength: g(Δv) = ((μ_s·v_½ + μ_d·Δv)/(v_½ + Δv) + k_μ·Δv)·p⁺ + S_a
//!   (seed 004, first equation), with Δv the end-of-increment slip rate Δs/Δt (backward Euler).
//!   With v_½ = 0 the leading term is μ_d for every Δv > 0: the instantaneous drop.
//! - The return map (default, [`RateFormulation::RateFollowingStiffness`], docs/props.md): after
//!   a slip at Δv₀ the stick stiffness is g(Δv₀)/γ_crit, otherwise τ_s/γ_crit; stick while
//!   |γ^pr| ≤ γ_crit; sliding with Δs = |γ^pr| − γ_crit and τ = g(Δs/Δt) (the elastic slip stays
//!   γ_crit), explicit.
//! - The earlier return map ([`RateFormulation::RateFreeStiffness`], kept for comparisons)
//!   solves τ = k_s(|γ^pr| − Δs) = g(Δs/Δt) for the slip increment Δs ≥ 0.
//!   Multiplied by (v_½ + Δv) it is the quadratic
//!   a·Δs² − b·Δs − c = 0 with a = k_s + p⁺k_μ/Δt, b = T − S_a − μ_d p⁺ − a·v_½Δt,
//!   c = (T − τ_s)·v_½Δt, T = k_s|γ^pr| the trial stress. Sliding means T > τ_s, so c ≥ 0 and
//!   the product of the roots −c/a ≤ 0: exactly one root is ≥ 0, and it is the admissible one
//!   (a slip increment against the trial direction is not slip). It is taken in the form that
//!   does not cancel.
//!
//! With S_a = k_μ = v_½ = 0 and μ_s = μ_d the law is plain Coulomb; [`Adhesive::coulomb_special_case`]
//! returns that law so the entry points run the Coulomb code itself (same results, same cost).

use super::contact::{Increment, StatusCode, Traction, elastic_start_slip, elastic_stick_stress};
use super::coulomb::{Coulomb, CoulombState, CriticalSlip, StickMode, Update};
use super::friction_coefficient::{RateFormulation, STICK_TEST_ROUNDING};
use super::parameter_range::nonnegative;
use super::point_law::{PointAnswer, PointInput, PointLaw, PointResult};
use super::small_vec::{add, diagonal, norm, radial_transverse, scale, unit};
use crate::{LawError, Outcome};

/// The seed's parameters by name (seed 004, "Properties"), before validation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdhesiveParameters {
    /// `coeff`: the dynamic coefficient μ_d, ≥ 0.
    pub coeff: f64,
    /// `coeffStatic`: the static coefficient μ_s; ≤ 0 (the seed's default −1) means none
    /// (μ_s = μ_d); a positive value must be ≥ `coeff`.
    pub coeff_static: f64,
    /// `Sa`: the shear adhesive strength, ≥ 0 (stress).
    pub sa: f64,
    /// `Na`: the normal adhesive strength, ≥ 0 (stress).
    pub na: f64,
    /// `kmu`: slope of the friction coefficient against the slip rate, ≥ 0 (1/velocity).
    pub kmu: f64,
    /// `vhalf`: slip rate at which the static → dynamic transition is half done, ≥ 0.
    pub vhalf: f64,
}

impl Default for AdhesiveParameters {
    /// The seed's defaults: μ_d = 0, no static coefficient, no adhesion, no rate dependence.
    fn default() -> Self {
        AdhesiveParameters {
            coeff: 0.0,
            coeff_static: -1.0,
            sa: 0.0,
            na: 0.0,
            kmu: 0.0,
            vhalf: 0.0,
        }
    }
}

/// The validated adhesive friction law (elastic stick).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adhesive {
    /// μ_d and the elastic-stick settings (γ_crit); its stick mode is always elastic.
    base: Coulomb,
    mu_static: f64,
    shear_adhesion: f64,
    normal_adhesion: f64,
    k_mu: f64,
    v_half: f64,
    /// How the rate-dependent strength enters the return map (the earlier one only for
    /// comparisons; docs/props.md).
    formulation: RateFormulation,
}

/// Which branch of the return map an increment took.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SlideBranch {
    /// Elastic stick: |γ^pr| ≤ γ_crit.
    Stick,
    /// Sliding: τ = g(Δv).
    Slip,
}

impl SlideBranch {
    /// The status a law with statuses `S` stores for the branch.
    #[must_use]
    pub fn status<S: StatusCode>(self) -> S {
        match self {
            SlideBranch::Stick => S::STICK,
            SlideBranch::Slip => S::SLIP,
        }
    }
}

/// The tangential answer of one increment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slide<const N: usize> {
    /// Stress, tangents (∂τ/∂Δγ, ∂τ/∂p), slip increment and energies.
    pub traction: Traction<N>,
    /// Stick or slip.
    pub branch: SlideBranch,
    /// The end-of-increment slip rate Δs/Δt (0 in stick or when Δt ≤ 0).
    pub slip_rate: f64,
    /// The stick stiffness k_s = τ_s/γ_crit used.
    pub stick_stiffness: f64,
}

impl Adhesive {
    /// Validates the seed's parameters; γ_crit defaults to 0.005 × characteristic length.
    pub fn new(p: &AdhesiveParameters) -> Result<Self, LawError> {
        let mu_d = nonnegative("coeff (dynamic friction coefficient μ_d)", p.coeff)?;
        if p.coeff_static.is_nan() || p.coeff_static.is_infinite() {
            return Err(LawError::Parameter(format!(
                "coeffStatic = {} must be finite (≤ 0 for none)",
                p.coeff_static
            )));
        }
        let mu_static = if p.coeff_static > 0.0 {
            if p.coeff_static < mu_d {
                return Err(LawError::Parameter(format!(
                    "coeffStatic = {} is below coeff = {mu_d}: the static coefficient μ_s must \
                     be ≥ the dynamic one (or ≤ 0 for none)",
                    p.coeff_static
                )));
            }
            p.coeff_static
        } else {
            mu_d
        };
        Ok(Adhesive {
            base: Coulomb::new(mu_d)?,
            mu_static,
            shear_adhesion: nonnegative("Sa (shear adhesive strength)", p.sa)?,
            normal_adhesion: nonnegative("Na (normal adhesive strength)", p.na)?,
            k_mu: nonnegative("kmu (friction slope against slip rate)", p.kmu)?,
            v_half: nonnegative("vhalf (half-transition slip rate)", p.vhalf)?,
            formulation: RateFormulation::RateFollowingStiffness,
        })
    }

    /// From `PROPS` entries already checked by the caller (every strength, slope and rate
    /// finite and ≥ 0, μ_s ≥ μ_d; γ_crit and the tolerance 0 for "default" or finite > 0).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_validated(
        mu_d: f64,
        mu_s: f64,
        sa: f64,
        na: f64,
        kmu: f64,
        vhalf: f64,
        gamma_crit: f64,
        tolerance: f64,
    ) -> Self {
        Adhesive {
            base: Coulomb::from_validated(mu_d, 0.0, gamma_crit, tolerance, StickMode::Elastic),
            mu_static: mu_s,
            shear_adhesion: sa,
            normal_adhesion: na,
            k_mu: kmu,
            v_half: vhalf,
            formulation: RateFormulation::RateFollowingStiffness,
        }
    }

    /// How the rate-dependent strength enters the return map: the default
    /// [`RateFormulation::RateFollowingStiffness`], or the earlier rate-free stick stiffness
    /// τ_s/γ_crit with the slip from the quadratic (for comparisons only; no `PROPS` entry
    /// selects it).
    #[must_use]
    pub fn with_rate_formulation(mut self, formulation: RateFormulation) -> Self {
        self.formulation = formulation;
        self
    }

    /// Sets γ_crit > 0 as an absolute length.
    pub fn with_critical_slip_absolute(mut self, gamma_crit: f64) -> Result<Self, LawError> {
        self.base = self.base.with_critical_slip_absolute(gamma_crit)?;
        Ok(self)
    }

    /// Sets γ_crit as `tolerance` × characteristic length, tolerance > 0.
    pub fn with_slip_tolerance(mut self, tolerance: f64) -> Result<Self, LawError> {
        self.base = self.base.with_slip_tolerance(tolerance)?;
        Ok(self)
    }

    /// μ_d.
    #[must_use]
    pub fn mu_dynamic(&self) -> f64 {
        self.base.mu()
    }

    /// μ_s (equal to μ_d when no static coefficient was given).
    #[must_use]
    pub fn mu_static(&self) -> f64 {
        self.mu_static
    }

    /// S_a.
    #[must_use]
    pub fn shear_adhesion(&self) -> f64 {
        self.shear_adhesion
    }

    /// N_a.
    #[must_use]
    pub fn normal_adhesion(&self) -> f64 {
        self.normal_adhesion
    }

    /// k_μ.
    #[must_use]
    pub fn k_mu(&self) -> f64 {
        self.k_mu
    }

    /// v_½.
    #[must_use]
    pub fn v_half(&self) -> f64 {
        self.v_half
    }

    /// The rate formulation in use.
    #[must_use]
    pub fn rate_formulation(&self) -> RateFormulation {
        self.formulation
    }

    /// How γ_crit is defined.
    #[must_use]
    pub fn critical_slip(&self) -> CriticalSlip {
        self.base.critical_slip()
    }

    /// γ_crit for a characteristic contact length.
    #[inline]
    pub fn critical_slip_for(&self, characteristic_length: f64) -> Result<f64, LawError> {
        self.base.critical_slip_for(characteristic_length)
    }

    /// True when the surfaces stay bonded while apart: both strengths non-zero (seed 004: "if
    /// either Sa or Na are zero, the surfaces will have no separation adhesion").
    #[must_use]
    pub fn separation_adhesion(&self) -> bool {
        self.shear_adhesion > 0.0 && self.normal_adhesion > 0.0
    }

    /// The plain Coulomb law this one reduces to when S_a = k_μ = v_½ = 0 and μ_s = μ_d (the
    /// seed: "the simple Coulomb friction contact law is a special case of this law"). N_a
    /// plays no part in the tangential law in contact.
    #[must_use]
    pub fn coulomb_special_case(&self) -> Option<Coulomb> {
        (self.shear_adhesion == 0.0
            && self.k_mu == 0.0
            && self.v_half == 0.0
            && self.mu_static == self.base.mu())
        .then_some(self.base)
    }

    /// Static strength τ_s = μ_s·p⁺ + S_a and ∂τ_s/∂p (the right derivative at p = 0).
    #[inline]
    #[must_use]
    pub fn static_strength(&self, p: f64) -> (f64, f64) {
        if p < 0.0 {
            (self.shear_adhesion, 0.0)
        } else {
            (self.mu_static * p + self.shear_adhesion, self.mu_static)
        }
    }

    /// The strength that sets the stick stiffness k_s = τ_k/γ_crit, and ∂τ_k/∂p: with the
    /// rate-following formulation and a point that slid in the previous increment at the rate
    /// `sliding = Some(Δv₀)`, the sliding strength g(Δv₀) (at Δv₀ = 0 with v_½ = 0 its limit
    /// from above, μ_d·p⁺ + S_a: the point was sliding, at a rate the host's Δt ≤ 0 did not
    /// give); otherwise the static strength τ_s.
    #[inline]
    #[must_use]
    pub fn stick_strength(&self, sliding: Option<f64>, p: f64) -> (f64, f64) {
        match sliding {
            Some(v) if self.formulation == RateFormulation::RateFollowingStiffness => {
                let (mu_s, mu_d, vh) = (self.mu_static, self.base.mu(), self.v_half);
                // μ_d + (μ_s − μ_d)·v_½/(v_½ + Δv₀), which cannot overflow.
                let transition = if vh + v > 0.0 {
                    mu_d + (mu_s - mu_d) * (vh / (vh + v))
                } else {
                    mu_d
                };
                let coefficient = transition + self.k_mu * v;
                if p < 0.0 {
                    (self.shear_adhesion, 0.0)
                } else {
                    (coefficient * p + self.shear_adhesion, coefficient)
                }
            }
            _ => self.static_strength(p),
        }
    }

    /// The seed's sliding strength g(Δv) = ((μ_s v_½ + μ_d Δv)/(v_½ + Δv) + k_μ Δv)·p⁺ + S_a,
    /// written exactly as in seed 004 (used to check the return map's residual). At Δv = 0 it
    /// is the static strength (also with v_½ = 0, where the quotient is 0/0).
    #[must_use]
    pub fn sliding_strength(&self, slip_rate: f64, p: f64) -> f64 {
        let p_plus = p.max(0.0);
        let (mu_s, mu_d, vh, v) = (self.mu_static, self.base.mu(), self.v_half, slip_rate);
        let transition = if vh + v > 0.0 {
            (mu_s * vh + mu_d * v) / (vh + v)
        } else {
            mu_s
        };
        (transition + self.k_mu * v) * p_plus + self.shear_adhesion
    }

    /// The return map's residual τ − g(Δs/Δt), relative to the trial stress
    /// T = |τ| + k_s·Δs (the largest stress in the computation, so round-off is ~1e-16 of it);
    /// ≈ 0 after every slip update (0 in stick, where the law does not apply).
    #[must_use]
    pub fn slide_residual<const N: usize>(&self, slide: &Slide<N>, p: f64) -> f64 {
        if slide.branch == SlideBranch::Stick {
            return 0.0;
        }
        let tau = norm(&slide.traction.tau);
        let g = self.sliding_strength(slide.slip_rate, p);
        let trial = tau + slide.stick_stiffness * norm(&slide.traction.dslip);
        (tau - g) / trial.max(g).max(f64::MIN_POSITIVE)
    }

    /// One increment of the tangential law: elastic predictor from the start stress (recovered
    /// with the start-of-increment stiffness, as in the Coulomb law), stick test |γ^pr| ≤ γ_crit
    /// (T ≤ τ_s), and on sliding the admissible root of the quadratic above with its consistent
    /// tangent.
    ///
    /// `sliding` is `Some(Δv₀)` for a point whose previous increment slid at the rate Δv₀
    /// (`STATEV(3)` = 1, Δv₀ = `STATEV(2)`), `None` for one that stuck or starts at rest. With
    /// the rate-following formulation (the default; docs/props.md) the stick stiffness is
    /// k_s = g(Δv₀)/γ_crit after a slip and τ_s/γ_crit otherwise, the same at both ends of the
    /// increment, the stick test is |γ^pr| ≤ γ_crit, and a sliding increment has
    /// Δs = |γ^pr| − γ_crit and τ = g(Δs/Δt) (seed 000, Eq. 5.2.3-2; seed 004's S_slide).
    ///
    /// `p_start` and `p` are the pressures at the start and the end of the increment; a Δt ≤ 0
    /// is refused when the law depends on the slip rate (k_μ or v_½ non-zero).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn slide<const N: usize>(
        &self,
        sliding: Option<f64>,
        tau_start: &[f64; N],
        dgam: &[f64; N],
        p_start: f64,
        p: f64,
        dtime: f64,
        gamma_crit: f64,
    ) -> Result<Slide<N>, LawError> {
        let rate_dependent = self.k_mu > 0.0 || self.v_half > 0.0;
        if rate_dependent && dtime.is_finite() && dtime <= 0.0 {
            return Err(LawError::Input(format!(
                "DTIME = {dtime} but the adhesive law depends on the slip rate (kmu or vhalf \
                 non-zero); it needs Δt > 0"
            )));
        }
        let (tau_s_start, _) = self.stick_strength(sliding, p_start);
        // Elastic slip at the start, γ̄^el = τ̄/k_s(p − Δp).
        let elastic_start = elastic_start_slip(tau_start, gamma_crit, tau_s_start);
        let predictor = add(&elastic_start, dgam);
        Ok(self.map(&predictor, sliding, p, dtime, gamma_crit))
    }

    /// The return map of either formulation from the elastic predictor.
    #[inline]
    fn map<const N: usize>(
        &self,
        predictor: &[f64; N],
        sliding: Option<f64>,
        p: f64,
        dtime: f64,
        gamma_crit: f64,
    ) -> Slide<N> {
        let trial = Trial {
            predictor,
            predictor_eq: norm(predictor),
            p,
            dtime,
            gamma_crit,
        };
        let strength = self.stick_strength(sliding, p);
        if strength.0 == 0.0 {
            return self.no_strength(&trial, sliding);
        }
        match self.formulation {
            RateFormulation::RateFollowingStiffness => self.following_map(&trial, strength),
            RateFormulation::RateFreeStiffness => self.return_map(&trial, strength),
        }
    }

    /// Elastic stick with k_s = τ_k/γ_crit: τ = k_s γ^pr, ∂τ/∂p = γ^pr (∂τ_k/∂p)/γ_crit
    /// (Eq. 5.2.3-1).
    /// `SED` is the elastic energy as the next increment reads the stress: ½|τ|²·γ_crit/τ_s
    /// with the static strength τ_s at p (a stick increment leaves the point at rest); it is
    /// ½k_s|γ^pr|² when k_s is the static stiffness.
    #[inline]
    fn stick<const N: usize>(&self, trial: &Trial<N>, (tau_k, dtau_k_dp): (f64, f64)) -> Slide<N> {
        let &Trial {
            predictor,
            predictor_eq,
            p,
            gamma_crit,
            ..
        } = trial;
        let (tau, k_s) = elastic_stick_stress(predictor, gamma_crit, tau_k);
        let (tau_s, _) = self.static_strength(p);
        let sed = if tau_s == tau_k || tau_s <= 0.0 {
            0.5 * k_s * predictor_eq * predictor_eq
        } else {
            let tau_eq = k_s * predictor_eq;
            0.5 * tau_eq * (tau_eq * (gamma_crit / tau_s))
        };
        Slide {
            traction: Traction::sticking(
                tau,
                diagonal(k_s),
                scale(predictor, dtau_k_dp / gamma_crit),
                sed,
            ),
            branch: SlideBranch::Stick,
            slip_rate: 0.0,
            stick_stiffness: k_s,
        }
    }

    /// The rate-following return map: stick while |γ^pr| ≤ γ_crit; sliding with the elastic
    /// slip held at γ_crit, Δs = |γ^pr| − γ_crit, τ = g(Δs/Δt)·n (explicit, one answer), and
    /// the tangent of Eq. 5.2.3-3: (δ − nn)·g/|γ^pr| + nn·∂g/∂Δs, ∂τ/∂p = n·∂g/∂p.
    #[inline]
    fn following_map<const N: usize>(&self, trial: &Trial<N>, strength: (f64, f64)) -> Slide<N> {
        let (predictor_eq, gamma_crit) = (trial.predictor_eq, trial.gamma_crit);
        if predictor_eq <= gamma_crit * (1.0 + STICK_TEST_ROUNDING) {
            let mut s = self.stick(trial, strength);
            if predictor_eq > gamma_crit {
                // Within the rounding allowance: on the strength, never above it.
                s.traction.tau = scale(&unit(trial.predictor, predictor_eq), strength.0);
            }
            return s;
        }
        let slip_eq = predictor_eq - gamma_crit;
        let p_plus = trial.p.max(0.0);
        let (mu_s, mu_d) = (self.mu_static, self.base.mu());
        // With Δt ≤ 0 (allowed only when k_μ = v_½ = 0) the sliding strength is μ_d·p⁺ + S_a.
        let (length_half, k_per_length) = self.slip_increment_form(trial.dtime);
        // Δs > 0, so V + Δs > 0: the transition μ_d + (μ_s − μ_d)·V/(V + Δs) (seed 004's
        // (μ_s v_½ + μ_d Δv)/(v_½ + Δv), in a form that cannot overflow).
        let denom = length_half + slip_eq;
        let share = length_half / denom;
        let transition = mu_d + (mu_s - mu_d) * share;
        let tau_eq =
            self.pressure_strength(transition, slip_eq, p_plus, trial.dtime) + self.shear_adhesion;
        // ∂g/∂Δs = ((μ_d − μ_s)·V/(V + Δs)² + K)·p⁺ and ∂g/∂p.
        let g_s = ((mu_d - mu_s) * (share / denom) + k_per_length) * p_plus;
        let g_p = if trial.p < 0.0 {
            0.0
        } else {
            transition + k_per_length * slip_eq
        };
        let n = unit(trial.predictor, predictor_eq);
        let transverse = tau_eq / predictor_eq;
        let ddtddg = radial_transverse(&n, g_s, transverse);
        // ½|τ|·γ_crit: the elastic slip is γ_crit.
        let sed = 0.5 * tau_eq * gamma_crit;
        let traction = Traction::sliding(&n, tau_eq, ddtddg, g_p, slip_eq, sed);
        sliding(traction, slip_eq, trial.dtime, tau_eq / gamma_crit)
    }

    #[inline]
    fn return_map<const N: usize>(&self, trial: &Trial<N>, strength: (f64, f64)) -> Slide<N> {
        let (tau_s, dtau_s_dp) = strength;
        let Trial {
            predictor,
            predictor_eq,
            p,
            dtime,
            gamma_crit,
        } = *trial;
        if predictor_eq <= gamma_crit {
            // Stick (Eq. 5.2.3-1) with the static stiffness: τ_s here is the static strength.
            return self.stick(trial, strength);
        }
        let k_s = tau_s / gamma_crit;
        let p_plus = p.max(0.0);
        let (mu_s, mu_d) = (self.mu_static, self.base.mu());
        let (length_half, k_per_length) = self.slip_increment_form(dtime);
        let trial = k_s * predictor_eq;
        let a = k_s + p_plus * k_per_length;
        let b = trial - self.shear_adhesion - mu_d * p_plus - a * length_half;
        let c = (trial - tau_s) * length_half;
        let root = (b * b + 4.0 * a * c).sqrt();
        // The root ≥ 0 of a·Δs² − b·Δs − c, without cancellation.
        let slip_eq = if b >= 0.0 {
            (b + root) / (2.0 * a)
        } else {
            2.0 * c / (root - b)
        };
        // ∂g/∂Δs and ∂g/∂p at the root (g as a function of Δs): g_p is the effective coefficient.
        let denom = length_half + slip_eq;
        // τ = g(Δs) at the root, evaluated from the seed's strength (a sum of non-negative
        // terms) rather than as T − k_s·Δs, whose cancellation loses ~ε·T: with T/g = 10⁶ that
        // put τ 4·10⁻¹¹ above the strength (fuzz target `uinter`, docs/fuzzing.md).
        // The transition written as μ_d + (μ_s − μ_d)·V/(V + Δs), which cannot overflow (the
        // seed's (μ_s V + μ_d Δs)/(V + Δs) does for Δs near f64::MAX).
        let transition = if denom > 0.0 {
            mu_d + (mu_s - mu_d) * (length_half / denom)
        } else {
            mu_s
        };
        let tau_eq = (self.pressure_strength(transition, slip_eq, p_plus, dtime)
            + self.shear_adhesion)
            .min(trial);
        let (g_s, g_p) = if denom > 0.0 {
            (
                ((mu_d - mu_s) * length_half / (denom * denom) + k_per_length) * p_plus,
                transition + k_per_length * slip_eq,
            )
        } else {
            (0.0, mu_s)
        };
        let g_p = if p < 0.0 { 0.0 } else { g_p };
        // r(Δs) = T − k_s Δs − g = 0: dΔs = (dT − Δs dk_s − g_p dp)/(k_s + g_s).
        // k_s + g_s = √disc/(V + Δs) > 0 at the admissible root; use the form that cannot be 0.
        let stiffness_sum = if denom > 0.0 && root > 0.0 {
            root / denom
        } else {
            a
        };
        let dk_s_dp = dtau_s_dp / gamma_crit;
        let dslip_dp = (dk_s_dp * (predictor_eq - slip_eq) - g_p) / stiffness_sum;
        // τ = g(Δs, p) at the root.
        let dtau_dgamma_eq = g_s * k_s / stiffness_sum;
        let dtau_dp = g_s * dslip_dp + g_p;
        let n = unit(predictor, predictor_eq);
        // d(τ n)/dγ^pr = τ'(n⊗n) + (τ/|γ^pr|)(I − n⊗n).
        let ddtddg = radial_transverse(&n, dtau_dgamma_eq, tau_eq / predictor_eq);
        let sed = 0.5 * tau_eq * tau_eq / k_s;
        let traction = Traction::sliding(&n, tau_eq, ddtddg, dtau_dp, slip_eq, sed);
        sliding(traction, slip_eq, dtime, k_s)
    }

    /// The rate terms in slip-increment form (Δv = Δs/Δt, backward Euler): V = v_½·Δt (a
    /// length) and K = k_μ/Δt (per length); both 0 when Δt ≤ 0 (then k_μ = v_½ = 0).
    #[inline(always)]
    fn slip_increment_form(&self, dtime: f64) -> (f64, f64) {
        if dtime > 0.0 {
            (self.v_half * dtime, self.k_mu / dtime)
        } else {
            (0.0, 0.0)
        }
    }

    /// The pressure part of the sliding strength (seed 004), (transition + k_μ·Δs/Δt)·p⁺, for
    /// the transition coefficient at the slip increment Δs; 0 at p⁺ = 0 even when k_μ·Δs/Δt is
    /// not finite. k_μ·Δs·p⁺/Δt is formed with the exponents kept apart ([`product_ratio`]):
    /// every fixed order of the product under- or overflows in some range (fuzz target `fric`,
    /// docs/fuzzing.md).
    #[inline(always)]
    fn pressure_strength(&self, transition: f64, slip_eq: f64, p_plus: f64, dtime: f64) -> f64 {
        if p_plus > 0.0 {
            let rate_term = if dtime > 0.0 && self.k_mu > 0.0 {
                product_ratio(self.k_mu, slip_eq, p_plus, dtime)
            } else {
                0.0
            };
            transition * p_plus + rate_term
        } else {
            0.0
        }
    }

    /// τ_s = 0 (no pressure and no adhesion): no shear is carried. At p = 0 with μ_s > 0 and
    /// S_a = 0 every stress is proportional to p, so ∂τ/∂p⁺ is the answer at p = 1.
    #[cold]
    fn no_strength<const N: usize>(&self, trial: &Trial<N>, sliding: Option<f64>) -> Slide<N> {
        let &Trial {
            predictor,
            predictor_eq,
            p,
            dtime,
            gamma_crit,
        } = trial;
        let unit_pressure = (p == 0.0 && self.stick_strength(sliding, 1.0).0 > 0.0)
            .then(|| self.map(predictor, sliding, 1.0, dtime, gamma_crit));
        let slip_eq = (predictor_eq - gamma_crit).max(0.0);
        let (ddtddp, dslip, branch) = match unit_pressure {
            Some(s) => (s.traction.tau, s.traction.dslip, s.branch),
            None if slip_eq > 0.0 => (
                [0.0; N],
                scale(&unit(predictor, predictor_eq), slip_eq),
                SlideBranch::Slip,
            ),
            None => ([0.0; N], [0.0; N], SlideBranch::Stick),
        };
        let slip_rate = if dtime > 0.0 && branch == SlideBranch::Slip {
            (norm(&dslip) / dtime).min(f64::MAX)
        } else {
            0.0
        };
        Slide {
            traction: Traction::stress_free(ddtddp, dslip),
            branch,
            slip_rate,
            stick_stiffness: 0.0,
        }
    }

    /// The `fric_` form: one closed point, start state in, end state out (the Coulomb law's
    /// three state variables: accumulated slip, slip rate, stick/slip).
    pub fn update<const N: usize>(
        &self,
        inc: &Increment<N>,
        state: &CoulombState,
    ) -> Result<Update<N>, LawError> {
        // Elastic stick reads no TAULM: the Coulomb law's naming, in the same order.
        inc.check_finite()?;
        // The memory of the rate-following formulation: the previous increment's slip.
        let sliding = state.sliding_rate()?;
        let gamma_crit = self.critical_slip_for(inc.characteristic_length)?;
        let s = self.slide(
            sliding,
            &inc.tau,
            &inc.dgam,
            inc.pressure - inc.dpressure,
            inc.pressure,
            inc.dtime,
            gamma_crit,
        )?;
        check_finite(&s.traction)?;
        let slip = norm(&s.traction.dslip);
        Ok(Update {
            contact: super::contact::Contact::Motion(s.traction),
            state: state.after_slide(slip, s.slip_rate, s.branch.status()),
            outcome: Outcome::CONVERGED,
        })
    }
}

impl PointLaw for Adhesive {
    fn name(&self) -> &'static str {
        "the adhesive law"
    }

    fn update_point<const N: usize>(&self, at: &PointInput<'_, N>) -> PointResult<N> {
        let up = self.update(at.increment, &CoulombState::from_statev(at.statev)?)?;
        Ok(PointAnswer::isothermal(up.contact, &up.state, up.outcome))
    }
}

/// The sliding answer of either return map (seed 004's S_slide): the traction along the slip
/// ([`Traction::sliding`], Eq. 5.2.3-2), the slip rate Δs/Δt and the formulation's stick
/// stiffness.
#[inline(always)]
fn sliding<const N: usize>(
    traction: Traction<N>,
    slip_eq: f64,
    dtime: f64,
    stick_stiffness: f64,
) -> Slide<N> {
    Slide {
        traction,
        branch: SlideBranch::Slip,
        slip_rate: end_slip_rate(slip_eq, dtime),
        stick_stiffness,
    }
}

/// The end-of-increment slip rate Δs/Δt of a sliding increment (0 when Δt ≤ 0); saturates at
/// f64::MAX (a slip over a subnormal Δt), as in the Coulomb law.
#[inline(always)]
fn end_slip_rate(slip_eq: f64, dtime: f64) -> f64 {
    if dtime > 0.0 {
        (slip_eq / dtime).min(f64::MAX)
    } else {
        0.0
    }
}

/// Every stress, tangent and energy is finite (the inputs were; an overflow is refused).
/// a·b·c/d for finite a, b, c ≥ 0 and d > 0, rounded a few times but never through a subnormal
/// or an infinite intermediate unless the result itself is one: each factor is split into a
/// mantissa in [1, 2) and a power of two, the mantissas multiplied, the powers added, and the
/// result scaled once at the end (in two halves, so that 2^e itself cannot overflow).
fn product_ratio(a: f64, b: f64, c: f64, d: f64) -> f64 {
    fn split(x: f64) -> (f64, i32) {
        if x == 0.0 {
            return (0.0, 0);
        }
        // Subnormals: scale into the normal range first (exact).
        let (x, shift) = if x < f64::MIN_POSITIVE {
            (x * 2f64.powi(64), -64)
        } else {
            (x, 0)
        };
        let bits = x.to_bits();
        let exponent = ((bits >> 52) & 0x7ff) as i32 - 1023;
        let mantissa = f64::from_bits((bits & !(0x7ff << 52)) | (1023 << 52));
        (mantissa, exponent + shift)
    }
    let (ma, ea) = split(a);
    let (mb, eb) = split(b);
    let (mc, ec) = split(c);
    let (md, ed) = split(d);
    let m = ma * mb * mc / md;
    if m == 0.0 {
        return 0.0;
    }
    let e = ea + eb + ec - ed;
    let half = e / 2;
    m * 2f64.powi(half) * 2f64.powi(e - half)
}

fn check_finite<const N: usize>(t: &Traction<N>) -> Result<(), LawError> {
    if t.is_finite() {
        Ok(())
    } else {
        Err(LawError::Numerical(
            "the adhesive stress update overflowed (inputs too large for f64)".into(),
        ))
    }
}

/// What the stick test and both return maps read: the elastic predictor γ^pr and its length
/// |γ^pr|, the pressure at the end of the increment, Δt and γ_crit (one list for the two
/// maps and the stick answer).
#[derive(Clone, Copy)]
struct Trial<'a, const N: usize> {
    predictor: &'a [f64; N],
    predictor_eq: f64,
    p: f64,
    dtime: f64,
    gamma_crit: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(p: AdhesiveParameters) -> Adhesive {
        Adhesive::new(&p)
            .and_then(|l| l.with_critical_slip_absolute(1e-3))
            .unwrap()
    }

    /// μ_d = 0.3, μ_s = 0.5, S_a = 2, k_μ = 0.05, v_½ = 0.1 (no normal adhesion).
    const RATE_DEPENDENT: AdhesiveParameters = AdhesiveParameters {
        coeff: 0.3,
        coeff_static: 0.5,
        sa: 2.0,
        na: 0.0,
        kmu: 0.05,
        vhalf: 0.1,
    };

    #[test]
    fn steady_sliding_stress_is_the_seed_formula() {
        // Steady sliding at rate v: the elastic slip is constant, every Δγ is slip, τ = g(v).
        let l = law(RATE_DEPENDENT);
        let (p, dt, v) = (100.0, 0.5, 0.4);
        let g = ((0.5 * 0.1 + 0.3 * v) / (0.1 + v) + 0.05 * v) * p + 2.0;
        // After a slip at v the elastic slip of τ̄ = g(v) is γ_crit: all of Δγ slides.
        let s = l.slide(Some(v), &[g], &[v * dt], p, p, dt, 1e-3).unwrap();
        assert_eq!(s.branch, SlideBranch::Slip);
        assert!((s.traction.tau[0] - g).abs() < 1e-12 * g, "{s:?} vs {g}");
        assert!((s.slip_rate - v).abs() < 1e-12);
        // The earlier formulation has the same fixed point (its trial stress less k_s·vΔt is
        // g(v)); what differs is whether driving converges to it (docs/props.md, scene F7).
        let old = l.with_rate_formulation(RateFormulation::RateFreeStiffness);
        let s = old.slide(Some(v), &[g], &[v * dt], p, p, dt, 1e-3).unwrap();
        assert!((s.traction.tau[0] - g).abs() < 1e-12 * g, "{s:?} vs {g}");
        assert!((s.slip_rate - v).abs() < 1e-12);
    }

    #[test]
    fn rate_free_stick_is_the_static_stiffness() {
        // μ_s = 0.5, S_a = 2, p = 10: τ_s = 7, k_s = 7/γ_crit = 7000; γ^pr = (3, 4)·1e-4,
        // |γ^pr| = 5e-4 < γ_crit: τ = k_s γ^pr, ∂τ/∂p = γ^pr·μ_s/γ_crit, SED = ½k_s|γ^pr|².
        let l = law(RATE_DEPENDENT).with_rate_formulation(RateFormulation::RateFreeStiffness);
        let s = l
            .slide(None, &[0.0, 0.0], &[3e-4, 4e-4], 10.0, 10.0, 0.5, 1e-3)
            .unwrap();
        assert_eq!(s.branch, SlideBranch::Stick);
        for (a, g) in [3e-4, 4e-4].into_iter().enumerate() {
            assert!((s.traction.tau[a] - 7000.0 * g).abs() < 1e-12);
            assert!((s.traction.ddtddp[a] - g * 0.5 / 1e-3).abs() < 1e-15);
            assert!((s.traction.ddtddg[a][a] - 7000.0).abs() < 1e-9);
        }
        assert_eq!(s.traction.ddtddg[0][1], 0.0);
        assert!((s.traction.sed - 0.5 * 7000.0 * 25e-8).abs() < 1e-15);
        assert_eq!((s.traction.dslip, s.slip_rate), ([0.0; 2], 0.0));
    }

    #[test]
    fn onset_at_static_strength() {
        let l = law(AdhesiveParameters {
            coeff: 0.3,
            coeff_static: 0.5,
            sa: 2.0,
            ..AdhesiveParameters::default()
        });
        // k_s = (0.5·10 + 2)/1e-3 = 7000; γ^pr = γ_crit exactly: still stick at τ = 7.
        let s = l
            .slide(None, &[0.0], &[1e-3], 10.0, 10.0, 1.0, 1e-3)
            .unwrap();
        assert_eq!(s.branch, SlideBranch::Stick);
        assert!((s.traction.tau[0] - 7.0).abs() < 1e-12);
        // Just past it: slides at the dynamic strength 0.3·10 + 2 (v_½ = 0, instantaneous drop).
        let s = l
            .slide(None, &[0.0], &[1.001e-3], 10.0, 10.0, 1.0, 1e-3)
            .unwrap();
        assert_eq!(s.branch, SlideBranch::Slip);
        assert!((s.traction.tau[0] - 5.0).abs() < 1e-12);
    }

    #[test]
    fn product_ratio_keeps_every_digit_across_the_range() {
        // Against the straightforward product where it cannot under- or overflow.
        for (a, b, c, d) in [
            (0.3, 2.5, 7.0, 0.1),
            (1e-3, 1e5, 3.0, 2e-2),
            (5.0, 0.0, 1.0, 1.0),
        ] {
            let r = product_ratio(a, b, c, d);
            assert!((r - a * b * c / d).abs() <= 1e-15 * (a * b * c / d));
        }
        // The fuzz case: k_μ/Δt subnormal, Δs huge; exact value by scaling powers of ten.
        let r = product_ratio(
            4.902993940401848e-306,
            3.5369057121380733e251,
            50590.0,
            4.8e10,
        );
        let expected =
            4.902993940401848 * 3.5369057121380733 * 5.059 / 4.8 * 1e-306 * 1e251 * 1e4 / 1e10;
        assert!((r / expected - 1.0).abs() < 1e-14, "{r} vs {expected}");
        // Results in the subnormal or overflow range come out as such, not as NaN.
        assert_eq!(product_ratio(1e-200, 1e-200, 1.0, 1.0), 0.0);
        assert_eq!(product_ratio(1e200, 1e200, 1.0, 1.0), f64::INFINITY);
    }

    #[test]
    fn validation() {
        let base = AdhesiveParameters {
            coeff: 0.3,
            ..AdhesiveParameters::default()
        };
        for (p, needle) in [
            (
                AdhesiveParameters {
                    coeff_static: 0.2,
                    ..base
                },
                "coeffStatic",
            ),
            (AdhesiveParameters { sa: -1.0, ..base }, "Sa"),
            (AdhesiveParameters { na: -1.0, ..base }, "Na"),
            (AdhesiveParameters { kmu: -1.0, ..base }, "kmu"),
            (
                AdhesiveParameters {
                    vhalf: f64::NAN,
                    ..base
                },
                "vhalf",
            ),
            (
                AdhesiveParameters {
                    coeff_static: f64::NAN,
                    ..base
                },
                "coeffStatic",
            ),
            (
                AdhesiveParameters {
                    coeff: -0.1,
                    ..base
                },
                "coeff",
            ),
        ] {
            let e = Adhesive::new(&p).unwrap_err().to_string();
            assert!(e.contains(needle), "{e}");
        }
        // coeffStatic ≤ 0 means none; equal to coeff is allowed.
        assert_eq!(
            Adhesive::new(&AdhesiveParameters {
                coeff_static: -1.0,
                ..base
            })
            .unwrap()
            .mu_static(),
            0.3
        );
        assert!(
            Adhesive::new(&AdhesiveParameters {
                coeff_static: 0.3,
                ..base
            })
            .unwrap()
            .coulomb_special_case()
            .is_some()
        );
    }
}
