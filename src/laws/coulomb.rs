//! Extended Coulomb friction (seed 000, section 5.2.3): isotropic μ, optional shear limit
//! τ_max, and the three ways of enforcing stick — elastic stick (penalty, Abaqus's default),
//! exact stick (Lagrange multipliers, `LM = 1`) and rough friction (always stuck while closed).
//!
//! Symbols as in the seed: p contact pressure, τ_crit = min(μp, τ_max) critical stress,
//! γ_crit allowable elastic slip, k_s = τ_crit/γ_crit stiffness in stick, γ^el elastic slip,
//! γ^pr elastic predictor, Δγ^sl slip increment.
//!
//! Conventions of an increment (the Abaqus FRIC ones): `pressure` is the pressure at the end of
//! the increment and `dpressure` its increment, so the increment starts at `p − Δp`; `tau` is
//! the stress at the start of the increment; `dgam` the relative tangential motion of the
//! increment. Tangents are derivatives of the end-of-increment stress with the start of the
//! increment held fixed.

use super::contact::{
    Contact, EntryFlag, Increment, PointState, StatusCode, Traction, corrupt_statev, name_bad_input,
};
use super::coulomb_extended::ExtendedCoulomb;
use super::parameter_range::{nonnegative, positive};
use super::point_law::{PointAnswer, PointInput, PointLaw, PointResult};
use super::small_vec::{
    add, diagonal, divided, dot, is_positive_normal, length_beyond, norm, scale, sum,
    transverse_projection, unit_or_zero, unit_unless_infinite,
};
use crate::{LawError, Outcome};

/// Default slip tolerance: γ_crit = 0.005 × characteristic contact length (seed 000: "0.5% of
/// the average length of all contact elements").
pub const DEFAULT_SLIP_TOLERANCE: f64 = 0.005;

/// In exact stick, the transverse tangent τ_crit/Δγ_eq (Eq. 5.2.3-8) uses
/// `max(Δγ_eq, EXACT_STICK_TANGENT_FLOOR · γ_crit)`: the stress stays exact, only the tangent
/// is bounded (at most 1000·k_s) when the slip increment vanishes.
pub const EXACT_STICK_TANGENT_FLOOR: f64 = 1e-3;

/// How the no-relative-motion condition is enforced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StickMode {
    /// Stiff elastic behaviour with k_s = τ_crit/γ_crit (penalty; `PROPS(7) = 0`).
    Elastic,
    /// Lagrange multipliers: the law answers `LM = 1` while sticking (`PROPS(7) = 1`).
    Exact,
    /// Rough friction: no bound on the shear stress, always `LM = 1` while closed (`PROPS(7) = 2`).
    Rough,
}

/// Where the allowable elastic slip γ_crit comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CriticalSlip {
    /// An absolute length.
    Absolute(f64),
    /// A fraction of the characteristic contact length (`CHRLNGTH`) given with each increment.
    Tolerance(f64),
    /// No γ_crit: a constant stick stiffness k_s (stress/length) instead, elastic stick only
    /// (`PROPS(7) = 4`): τ = τ̄ + k_s·Δγ while |τ| ≤ τ_crit (CalculiX's stick slope λ).
    Stiffness(f64),
}

/// The validated parameters of the Coulomb law. Construct with [`Coulomb::new`] and the
/// `with_*` methods; each validates its argument.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coulomb {
    mu: f64,
    /// `f64::INFINITY` when there is no shear limit.
    tau_max: f64,
    critical_slip: CriticalSlip,
    stick: StickMode,
}

/// What the point did in the increment (stored as `STATEV(3)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FrictionStatus {
    /// Elastic stick (no slip in the increment).
    #[default]
    Stick = 0,
    /// Slip.
    Slip = 1,
    /// Held by Lagrange multipliers (`LM = 1`).
    ExactStick = 2,
}

impl StatusCode for FrictionStatus {
    const LAW: &'static str = "the Coulomb law";
    const STICK: Self = FrictionStatus::Stick;
    const SLIP: Self = FrictionStatus::Slip;

    #[inline(always)]
    fn from_code(code: f64) -> Self {
        match code {
            1.0 => FrictionStatus::Slip,
            2.0 => FrictionStatus::ExactStick,
            _ => FrictionStatus::Stick,
        }
    }

    #[inline(always)]
    fn code(self) -> f64 {
        f64::from(self as i32)
    }
}

/// The Coulomb laws' state: stick, slip or exact stick in the last increment.
pub type CoulombState = PointState<FrictionStatus>;

impl CoulombState {
    /// The state after an increment held by Lagrange multipliers (`LM = 1`): no slip, no rate.
    #[inline(always)]
    #[must_use]
    pub(crate) fn held(&self) -> Self {
        CoulombState {
            accumulated_slip: self.accumulated_slip,
            slip_rate: 0.0,
            status: FrictionStatus::ExactStick,
        }
    }

    /// [`PointState::after_slide`] with the Coulomb laws' rate and status: the slip rate is
    /// `rate_slip`/`rate_dtime` (the return map's Δγ_eq^sl over the time increment of rates;
    /// 0 when that is ≤ 0), and the status is slip when `slip` > 0, else stick. The saturation
    /// at f64::MAX (one `minsd` each) counted 5 instructions per `fric_` call fewer than the
    /// compare-and-select used before (scripts/count-instructions.sh).
    #[inline(always)]
    #[must_use]
    pub(crate) fn after_motion(&self, slip: f64, rate_slip: f64, rate_dtime: f64) -> Self {
        let rate = if rate_dtime > 0.0 {
            rate_slip / rate_dtime
        } else {
            0.0
        };
        let status = if slip > 0.0 {
            FrictionStatus::Slip
        } else {
            FrictionStatus::Stick
        };
        self.after_slide(slip, rate, status)
    }
}

/// Result of [`Coulomb::update`], and with the law's own end state `S` of the other friction
/// laws' `update` (law 3's keeps θ beside the three scalars).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Update<const N: usize, S = CoulombState> {
    /// Stress and tangents, or exact stick.
    pub contact: Contact<N>,
    /// State at the end of the increment.
    pub state: S,
    /// Reliability and suggested step ratio.
    pub outcome: Outcome,
}

impl Coulomb {
    /// Isotropic Coulomb friction with coefficient μ ≥ 0, no shear limit, elastic stick with
    /// γ_crit = 0.005 × characteristic length.
    pub fn new(mu: f64) -> Result<Self, LawError> {
        Ok(Coulomb {
            mu: nonnegative("friction coefficient μ", mu)?,
            tau_max: f64::INFINITY,
            critical_slip: CriticalSlip::Tolerance(DEFAULT_SLIP_TOLERANCE),
            stick: StickMode::Elastic,
        })
    }

    /// From `PROPS` entries already checked by the caller: 0 means "off" / "default" for
    /// τ_max, γ_crit and the tolerance, every other value is finite and positive.
    #[inline]
    pub(crate) fn from_validated(
        mu: f64,
        tau_max: f64,
        gamma_crit: f64,
        tolerance: f64,
        stick: StickMode,
    ) -> Self {
        Coulomb {
            mu,
            tau_max: if tau_max > 0.0 {
                tau_max
            } else {
                f64::INFINITY
            },
            critical_slip: if gamma_crit > 0.0 {
                CriticalSlip::Absolute(gamma_crit)
            } else if tolerance > 0.0 {
                CriticalSlip::Tolerance(tolerance)
            } else {
                CriticalSlip::Tolerance(DEFAULT_SLIP_TOLERANCE)
            },
            stick,
        }
    }

    /// Elastic stick with a constant stick stiffness k_s > 0 (stress/length) in place of
    /// γ_crit: τ = τ̄ + k_s·Δγ in stick (CalculiX's `*FRICTION` stick slope λ).
    pub fn with_stick_stiffness(mut self, stiffness: f64) -> Result<Self, LawError> {
        self.critical_slip = CriticalSlip::Stiffness(positive("stick stiffness k_s", stiffness)?);
        self.stick = StickMode::Elastic;
        Ok(self)
    }

    /// Limits the critical stress: τ_crit = min(μp, τ_max), τ_max > 0.
    pub fn with_shear_limit(mut self, tau_max: f64) -> Result<Self, LawError> {
        self.tau_max = positive("shear limit τ_max", tau_max)?;
        Ok(self)
    }

    /// Sets the allowable elastic slip γ_crit > 0 as an absolute length.
    pub fn with_critical_slip_absolute(mut self, gamma_crit: f64) -> Result<Self, LawError> {
        self.critical_slip =
            CriticalSlip::Absolute(positive("allowable elastic slip γ_crit", gamma_crit)?);
        Ok(self)
    }

    /// Sets γ_crit as `tolerance` × characteristic length, tolerance > 0.
    pub fn with_slip_tolerance(mut self, tolerance: f64) -> Result<Self, LawError> {
        self.critical_slip = CriticalSlip::Tolerance(positive("slip tolerance", tolerance)?);
        Ok(self)
    }

    /// Chooses how stick is enforced.
    #[must_use]
    pub fn with_stick(mut self, stick: StickMode) -> Self {
        self.stick = stick;
        self
    }

    /// The friction coefficient μ.
    #[must_use]
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// The shear limit, if any.
    #[must_use]
    pub fn shear_limit(&self) -> Option<f64> {
        self.tau_max.is_finite().then_some(self.tau_max)
    }

    /// How γ_crit is defined.
    #[must_use]
    pub fn critical_slip(&self) -> CriticalSlip {
        self.critical_slip
    }

    /// How stick is enforced.
    #[must_use]
    pub fn stick(&self) -> StickMode {
        self.stick
    }

    /// τ_crit = min(μp, τ_max) and ∂τ_crit/∂p. A negative pressure (a point that is barely
    /// closed) carries no friction: τ_crit = 0. At p = 0 the derivative is the one from p > 0.
    #[inline]
    #[must_use]
    pub fn critical_stress(&self, p: f64) -> (f64, f64) {
        if p < 0.0 {
            return (0.0, 0.0);
        }
        let mu_p = self.mu * p;
        if mu_p >= self.tau_max {
            (self.tau_max, 0.0)
        } else {
            (mu_p, self.mu)
        }
    }

    /// γ_crit for a characteristic contact length.
    #[inline(always)]
    pub fn critical_slip_for(&self, characteristic_length: f64) -> Result<f64, LawError> {
        match self.critical_slip_if_defined(characteristic_length) {
            Some(g) => Ok(g),
            None => Err(bad_characteristic_length(
                characteristic_length,
                match self.critical_slip {
                    CriticalSlip::Absolute(_) | CriticalSlip::Stiffness(_) => 0.0,
                    CriticalSlip::Tolerance(t) => t,
                },
            )),
        }
    }

    /// γ_crit, or `None` when it is a tolerance and the characteristic length is not finite
    /// and positive, or when a constant stick stiffness stands instead (elastic stick only,
    /// which does not ask: [`Self::constant_stick`]).
    #[inline(always)]
    fn critical_slip_if_defined(&self, characteristic_length: f64) -> Option<f64> {
        match self.critical_slip {
            CriticalSlip::Absolute(g) => Some(g),
            CriticalSlip::Stiffness(_) => None,
            CriticalSlip::Tolerance(t) => {
                if characteristic_length > 0.0 && characteristic_length < f64::INFINITY {
                    Some(t * characteristic_length)
                } else {
                    None
                }
            }
        }
    }

    /// Integrates one increment (backward Euler) and returns the end-of-increment stress,
    /// consistent tangents, energies and state.
    #[inline(always)]
    pub fn update<const N: usize>(
        &self,
        inc: &Increment<N>,
        state: &CoulombState,
    ) -> Result<Update<N>, LawError> {
        match self.try_update(inc, state) {
            Some(up) => Ok(up),
            // By value: a reference would make the hot path keep the increment in memory.
            None => self.update_rare(*inc, *state),
        }
    }

    /// The increments [`Self::try_update`] leaves aside: every one of a constant stick
    /// stiffness ([`Self::constant_stick`]), and, by the careful tier of elastic stick,
    /// those beyond the one-pass tier's bound (magnitudes near the ends of the f64 range), a
    /// stiffness k_s = τ_crit/γ_crit below f64's normal range, where k_s·γ^pr keeps too few
    /// digits (the stick stress is then formed as τ_crit·(γ^pr/γ_crit)), and every failure,
    /// which [`Self::diagnose`] names.
    #[cold]
    #[inline(never)]
    #[allow(clippy::needless_pass_by_value)]
    fn update_rare<const N: usize>(
        &self,
        inc: Increment<N>,
        state: CoulombState,
    ) -> Result<Update<N>, LawError> {
        let answer = match self.critical_slip {
            CriticalSlip::Stiffness(k) if self.stick == StickMode::Elastic => {
                self.constant_stick(&inc, &state, k)
            }
            _ => self.integrate::<N, true>(&inc, &state),
        };
        match answer {
            Some(up) => Ok(up),
            None => Err(self.diagnose(inc, &state)),
        }
    }

    /// [`Self::update`] without naming what went wrong: `None` when an input is not finite,
    /// γ_crit cannot be formed from `CHRLNGTH`, or a result overflowed. The inputs and results
    /// are tested together, with one branch, after the arithmetic (which cannot fail on
    /// non-finite values, only carry them); [`Self::update`] then says which it was.
    /// Also `None` for elastic-stick increments outside the one-pass tier's bound, among them
    /// a subnormal k_s ([`Self::elastic_stick_bounded`]; [`Self::update`] answers them).
    #[inline(always)]
    pub(crate) fn try_update<const N: usize>(
        &self,
        inc: &Increment<N>,
        state: &CoulombState,
    ) -> Option<Update<N>> {
        self.integrate::<N, false>(inc, state)
    }

    /// The increment. Elastic stick has two tiers, chosen when the caller compiles
    /// (`CAREFUL`): the one-pass tier answers when a few cheap bounds show that it may (else
    /// `None`), the careful tier decides exactly which increments have finite answers and forms
    /// the stick stress for a subnormal k_s; where both answer, they give the same bits
    /// ([`Self::elastic_stick_bounded`]).
    #[inline(always)]
    fn integrate<const N: usize, const CAREFUL: bool>(
        &self,
        inc: &Increment<N>,
        state: &CoulombState,
    ) -> Option<Update<N>> {
        #[cfg(test)]
        crate::testing::maybe_panic();
        // x·0 is ±0 for finite x and NaN otherwise: one sum tests every value at once. The
        // state (STATEV) is tested with the inputs.
        let exact_inputs = || state.probe() + (inc.pressure * 0.0 + inc.dpressure * 0.0);
        let (contact, slip, probe) = match self.stick {
            StickMode::Rough => (Contact::ExactStick, 0.0, exact_inputs()),
            StickMode::Elastic => {
                // `None` for a constant stick stiffness: [`Self::update_rare`] answers it, so
                // the hot path stays as it was.
                let gamma_crit = self.critical_slip_if_defined(inc.characteristic_length)?;
                let trial = self.elastic_trial(inc, gamma_crit, CAREFUL);
                let (t, slip, probe) = if CAREFUL {
                    let (t, slip, results) = self.elastic_stick_checked(&trial);
                    // Δγ is not tested on its own: it enters γ^pr, and a non-finite γ^pr takes
                    // the slip branch with a non-finite Δγ_eq^sl, which the results' test
                    // refuses.
                    let mut inputs = inc.dtime * 0.0;
                    for x in &inc.tau {
                        inputs += x * 0.0;
                    }
                    (t, slip, exact_inputs() + (inputs + results))
                } else {
                    // A sum is finite only if every term is (±∞ and NaN propagate; ∞ − ∞ is
                    // NaN); it can also overflow for finite terms, which then go to the
                    // careful tier. Δγ enters γ^pr, which the bound tests.
                    let inputs = ((inc.pressure + inc.dpressure)
                        + (state.accumulated_slip + state.slip_rate))
                        + (sum(&inc.tau) + inc.dtime);
                    let (t, slip, bound) = self.elastic_stick_bounded(&trial);
                    (t, slip, (inputs + bound) * 0.0)
                };
                (Contact::Motion(t), slip, probe)
            }
            StickMode::Exact => {
                let inputs = exact_inputs() + input_probe(inc, StickMode::Exact);
                let gamma_crit = self.critical_slip_if_defined(inc.characteristic_length)?;
                match self.exact_stick(inc, gamma_crit) {
                    Some((t, slip)) => (Contact::Motion(t), slip, inputs + traction_probe(&t)),
                    None => (Contact::ExactStick, 0.0, inputs),
                }
            }
        };
        if probe != 0.0 {
            return None;
        }
        let state = match &contact {
            Contact::ExactStick => state.held(),
            // `slip` is the return map's Δγ_eq^sl (= |Δγ^sl|).
            Contact::Motion(_) => state.after_motion(slip, slip, inc.dtime),
        };
        Some(Update {
            contact,
            state,
            outcome: Outcome::CONVERGED,
        })
    }

    /// Elastic stick with the constant stiffness k_s (`PROPS(7) = 4`): the trial stress
    /// τ^tr = τ̄ + k_s·Δγ; stick while |τ^tr| ≤ τ_crit(p) (τ = τ^tr, ∂τ/∂Δγ = k_s·δ, ∂τ/∂p = 0,
    /// SED = |τ|²/(2k_s)); otherwise slip along n = τ^tr/|τ^tr| by the return map (Eq. 5.2.3-2
    /// with γ^pr = τ^tr/k_s): τ = τ_crit·n, Δγ_eq^sl = (|τ^tr| − τ_crit)/k_s, ∂τ/∂Δγ =
    /// (δ − nn)·k_s·τ_crit/|τ^tr| (Eq. 5.2.3-3), ∂τ/∂p = n·∂τ_crit/∂p, SED = τ_crit²/(2k_s).
    /// `None` when an input or a result is not finite ([`Self::diagnose`] names it).
    #[inline(never)]
    fn constant_stick<const N: usize>(
        &self,
        inc: &Increment<N>,
        state: &CoulombState,
        k: f64,
    ) -> Option<Update<N>> {
        let (tau_crit, dtau_crit_dp) = self.critical_stress_of_finite(inc.pressure);
        let trial: [f64; N] = std::array::from_fn(|i| inc.tau[i] + k * inc.dgam[i]);
        let length = dot(&trial, &trial).sqrt();
        let (t, slip_eq) = if length <= tau_crit {
            let sed = 0.5 * dot(&trial, &trial) / k;
            (Traction::sticking(trial, diagonal(k), [0.0; N], sed), 0.0)
        } else {
            let n = if N == 1 {
                [1.0f64.copysign(trial[0]); N]
            } else {
                divided(&trial, length)
            };
            let ddtddg = if N == 1 {
                [[0.0; N]; N]
            } else {
                transverse_projection(&n, k * tau_crit / length)
            };
            let slip_eq = (length - tau_crit) / k;
            let sed = 0.5 * tau_crit * tau_crit / k;
            (
                Traction::sliding(&n, tau_crit, ddtddg, dtau_crit_dp, slip_eq, sed),
                slip_eq,
            )
        };
        let probe = state.probe()
            + input_probe(inc, StickMode::Elastic)
            + traction_probe(&t)
            + slip_eq * 0.0;
        if probe != 0.0 {
            return None;
        }
        Some(Update {
            contact: Contact::Motion(t),
            state: state.after_motion(slip_eq, slip_eq, inc.dtime),
            outcome: Outcome::CONVERGED,
        })
    }

    /// Why [`Self::try_update`] gave `None`, tested in the order a user fixes things: a
    /// non-finite state or input, then `CHRLNGTH`, then an overflow of the results.
    #[cold]
    #[inline(never)]
    #[allow(clippy::needless_pass_by_value)]
    fn diagnose<const N: usize>(&self, inc: Increment<N>, state: &CoulombState) -> LawError {
        if !state.is_finite() {
            return corrupt_statev();
        }
        if input_probe(&inc, self.stick) != 0.0 {
            return name_bad_input(inc, self.stick == StickMode::Exact);
        }
        if self.stick != StickMode::Rough
            && !matches!(self.critical_slip, CriticalSlip::Stiffness(_))
        {
            if let Err(e) = self.critical_slip_for(inc.characteristic_length) {
                return e;
            }
        }
        overflowed()
    }

    /// The elastic predictor of elastic stick and the end-of-increment critical stress.
    ///
    /// γ̄^el = τ̄·(γ_crit/τ_crit(p − Δp)); where that factor overflows (a start stress below
    /// γ_crit/f64::MAX, e.g. first contact at a vanishing pressure) the careful tier forms
    /// (τ̄/τ_crit)·γ_crit instead, finite for a host stress within the start cone (the one-pass
    /// tier's bound declines such increments: 0·∞ or ∞ in γ^pr).
    #[inline(always)]
    fn elastic_trial<const N: usize>(
        &self,
        inc: &Increment<N>,
        gamma_crit: f64,
        careful: bool,
    ) -> Trial<N> {
        // Elastic slip at the start, from the start-of-increment stiffness: γ̄^el = τ̄/k_s(p − Δp).
        let (tau_crit_start, _) = self.critical_stress_of_finite(inc.pressure - inc.dpressure);
        let factor = gamma_crit / tau_crit_start;
        let elastic_start = if tau_crit_start > 0.0 {
            if careful && factor == f64::INFINITY {
                std::array::from_fn(|i| inc.tau[i] / tau_crit_start * gamma_crit)
            } else {
                scale(&inc.tau, factor)
            }
        } else {
            [0.0; N]
        };
        let (tau_crit, dtau_crit_dp) = self.critical_stress_of_finite(inc.pressure);
        Trial {
            // Elastic predictor γ^pr = γ̄^el + Δγ.
            predictor: add(&elastic_start, &inc.dgam),
            gamma_crit,
            tau_crit,
            dtau_crit_dp,
        }
    }

    /// [`Self::critical_stress`] for a finite p, as two selects (`minsd` and a mask) instead of
    /// a branch: the same values; for a NaN p it gives τ_max where `critical_stress` gives NaN
    /// (the callers refuse a NaN pressure through their input tests).
    #[inline(always)]
    fn critical_stress_of_finite(&self, p: f64) -> (f64, f64) {
        let mu_p = self.mu * p;
        let below_limit = mu_p < self.tau_max;
        if p < 0.0 {
            (0.0, 0.0)
        } else {
            (
                if below_limit { mu_p } else { self.tau_max },
                if below_limit { self.mu } else { 0.0 },
            )
        }
    }

    /// Elastic stick with the backward-Euler return map (Eq. 5.2.3-2) and its consistent
    /// linearization (Eq. 5.2.3-1 in stick, Eq. 5.2.3-3 in slip), the careful tier: also the
    /// slip increment Δγ_eq^sl (0 in stick) and a probe that is ±0 exactly when every result
    /// is finite (for finite inputs).
    ///
    /// The probe tests a few scalars instead of the results (6 of them for NFDIR = 1, 12 for
    /// NFDIR = 2): in stick |γ^pr_i| ≤ γ_eq^pr ≤ γ_crit and in slip |n_i| ≤ 1, each up to a few
    /// roundings, so every result is bounded by τ_crit, k_s, ∂τ_crit/∂p or Δγ_eq^sl times
    /// 1 + (a few ε) — τ = τ_crit γ^pr/γ_crit ≤ τ_crit, (∂τ_crit/∂p/γ_crit) γ^pr ≤ ∂τ_crit/∂p,
    /// (δ − nn) τ_crit/γ_eq^pr ≤ k_s since γ_eq^pr > γ_crit in slip — or it is SED or SFD.
    /// Those scalars times [`HEADROOM`] finite, γ_crit, k_s and ∂τ_crit/∂p/γ_crit finite (a
    /// product with an infinite factor and a zero one is NaN), SED and SFD finite: every result
    /// is finite. Stick is decided on the squares where it can be (`small_vec::length_beyond`):
    /// |γ^pr| ≤ γ_crit·(1 + 2ε), within the same roundings.
    ///
    /// Where k_s = τ_crit/γ_crit is subnormal, k_s·γ^pr keeps too few digits (τ_max near
    /// f64::MIN_POSITIVE: fuzz target `fric`): the stick stress is then τ_crit·(γ^pr/γ_crit)
    /// (γ^pr/γ_crit ≤ 1: within τ_crit to round-off). Only this tier pays for that division.
    #[inline(always)]
    fn elastic_stick_checked<const N: usize>(&self, trial: &Trial<N>) -> (Traction<N>, f64, f64) {
        let Trial {
            predictor,
            gamma_crit,
            tau_crit,
            dtau_crit_dp,
        } = *trial;
        let stiffness = tau_crit / gamma_crit;
        // x·0 is ±0 for finite x and NaN otherwise.
        let bounds = (gamma_crit * 0.0 + (tau_crit * HEADROOM) * 0.0)
            + ((stiffness * HEADROOM) * 0.0 + (dtau_crit_dp * HEADROOM) * 0.0);
        match length_beyond(&predictor, gamma_crit) {
            None => {
                let tau = if is_subnormal(stiffness) {
                    std::array::from_fn(|i| predictor[i] / gamma_crit * tau_crit)
                } else {
                    scale(&predictor, stiffness)
                };
                let t = trial.stick(stiffness, tau);
                let probe = bounds + (t.ddtddp_factor * 0.0 + t.traction.sed * 0.0);
                (t.traction, 0.0, probe)
            }
            Some(predictor_eq) => {
                let (t, slip_eq) = trial.slip(predictor_eq, true);
                // Δγ_eq^sl finite also means γ_eq^pr finite (not NaN): the slip branch is then the
                // γ_eq^pr > γ_crit of the test above.
                let probe = bounds + ((slip_eq * HEADROOM) * 0.0 + (t.sed * 0.0 + t.sfd * 0.0));
                (t, slip_eq, probe)
            }
        }
    }

    /// [`Self::elastic_stick_checked`] in one pass, the tier `fric_` tries first: the same
    /// decisions and formulas, hence the same bits, wherever it answers. It answers when the
    /// returned bound is finite; the bound is a few operations on values that are ready before
    /// the square root of the slip branch, so the call does not wait on it.
    ///
    /// It requires (else the bound is NaN or ∞, and the careful tier decides):
    /// 1. γ_crit² a normal number, i.e. 2⁻⁵¹¹ ≤ γ_crit < 2⁵¹²: the squares decide stick, and
    ///    in slip |γ^pr| > γ_crit ≥ 2⁻⁵¹¹, so γ^pr/|γ^pr| needs no scaling (as in the careful
    ///    tier, which then takes the same plain quotient);
    /// 2. B = ((τ_crit + ∂τ_crit/∂p)·2⁵¹²)·(X + γ_crit) finite, with X = |γ^pr| for N = 1 and
    ///    X = γ^pr·γ^pr + 1 ≥ |γ^pr| for N = 2. All terms are ≥ 0, so B finite means each is:
    ///    τ_crit and ∂τ_crit/∂p below 2⁵¹², hence k_s = τ_crit/γ_crit and (∂τ_crit/∂p)/γ_crit
    ///    below 2¹⁰²³; γ^pr·γ^pr finite, so |γ^pr| < 2⁵¹² and the norm is the plain square root
    ///    (as in the careful tier); τ_crit·γ_crit and τ_crit·|γ^pr| at most B·2⁻⁵¹². Every
    ///    result is one of these or bounded by one of them times 1 + (a few ε), as in the
    ///    careful tier's argument (SED by τ_crit γ_crit, SFD by τ_crit|γ^pr|, Δγ^sl by |γ^pr|):
    ///    all finite, far from overflow;
    /// 3. in stick, k_s zero or normal (a subnormal k_s is the careful tier's case).
    #[inline(always)]
    fn elastic_stick_bounded<const N: usize>(&self, trial: &Trial<N>) -> (Traction<N>, f64, f64) {
        let (predictor, gamma_crit, tau_crit) = (trial.predictor, trial.gamma_crit, trial.tau_crit);
        let squares = dot(&predictor, &predictor);
        let gamma_crit_sq = gamma_crit * gamma_crit;
        let extent = if N == 1 {
            predictor[0].abs()
        } else {
            squares + 1.0
        };
        let bound = ((tau_crit + trial.dtau_crit_dp) * TWO_POW_512) * (extent + gamma_crit)
            + if is_positive_normal(gamma_crit_sq) {
                0.0
            } else {
                f64::NAN
            };
        // |γ^pr| when beyond γ_crit: for N = 2 on the squares first, as `length_beyond` with
        // γ_crit² normal (requirement 1), and the plain square root (requirement 2).
        let beyond = if N == 1 {
            Some(predictor[0].abs())
        } else if squares <= gamma_crit_sq {
            None
        } else {
            Some(squares.sqrt())
        };
        match beyond.filter(|&length| length > gamma_crit) {
            None => {
                let stiffness = tau_crit / gamma_crit;
                let t = trial.stick(stiffness, scale(&predictor, stiffness));
                let declined = if is_subnormal(stiffness) {
                    f64::NAN
                } else {
                    0.0
                };
                (t.traction, 0.0, bound + declined)
            }
            Some(predictor_eq) => {
                // γ_eq^pr > γ_crit ≥ 2⁻⁵¹¹: the plain quotient for the direction.
                let (t, slip_eq) = trial.slip(predictor_eq, false);
                (t, slip_eq, bound)
            }
        }
    }

    /// Exact stick (Lagrange multipliers) with the seed's switching tests: a sticking point
    /// whose Lagrange stress exceeds τ_crit starts to slip; a slipping point whose motion
    /// reverses against the stress of the start of the increment sticks (Δγ_i τ_i(t) < 0).
    /// `None` is exact stick (`LM = 1`); otherwise the slip stress and the slip Δγ_eq.
    #[inline(always)]
    fn exact_stick<const N: usize>(
        &self,
        inc: &Increment<N>,
        gamma_crit: f64,
    ) -> Option<(Traction<N>, f64)> {
        let (tau_crit, dtau_crit_dp) = self.critical_stress(inc.pressure);
        let direction_source = match inc.entry {
            EntryFlag::ExactStick => {
                if norm(&inc.taulm) <= tau_crit {
                    return None;
                }
                // Release: slip along the Lagrange stress, the direction the host pushes.
                inc.taulm
            }
            EntryFlag::Motion => {
                if dot(&inc.dgam, &inc.tau) < 0.0 {
                    return None;
                }
                if norm(&inc.dgam) > 0.0 {
                    inc.dgam
                } else {
                    inc.tau
                }
            }
        };
        let n = unit_or_zero(&direction_source);
        let slip_eq = norm(&inc.dgam);
        let tau = scale(&n, tau_crit);
        let floor = EXACT_STICK_TANGENT_FLOOR * gamma_crit;
        let t = Traction {
            // Eq. 5.2.3-7: τ_i = τ_crit Δγ_i/Δγ_eq.
            tau,
            // Eq. 5.2.3-8.
            ddtddg: transverse_projection(&n, tau_crit / slip_eq.max(floor)),
            ddtddp: scale(&n, dtau_crit_dp),
            // With exact stick every relative motion is slip.
            dslip: inc.dgam,
            sed: 0.0,
            sfd: dot(&tau, &inc.dgam).max(0.0),
        };
        Some((t, slip_eq))
    }
}

/// 1 + 2⁻²⁰: a bound x with x·HEADROOM finite leaves room for the few roundings (each a
/// relative 2⁻⁵³) between x and the results it bounds ([`Coulomb::elastic_stick_checked`]).
pub(crate) const HEADROOM: f64 = 1.0 + 1.0 / 1_048_576.0;

/// 2⁵¹²: the headroom of [`Coulomb::elastic_stick_bounded`]'s bound.
const TWO_POW_512: f64 = f64::from_bits((1023 + 512) << 52);

/// The elastic predictor of one increment and what the return map needs with it.
#[derive(Clone, Copy)]
struct Trial<const N: usize> {
    /// γ^pr = γ̄^el + Δγ.
    predictor: [f64; N],
    gamma_crit: f64,
    /// τ_crit and ∂τ_crit/∂p at the end of the increment.
    tau_crit: f64,
    dtau_crit_dp: f64,
}

/// A stick answer with the factor of its pressure tangent (for the careful tier's test).
struct StickAnswer<const N: usize> {
    traction: Traction<N>,
    ddtddp_factor: f64,
}

impl<const N: usize> Trial<N> {
    /// Stick with stress `tau` (= k_s γ^pr): dτ = k_s dγ + (τ/τ_crit)(∂τ_crit/∂p) dp
    /// (Eq. 5.2.3-1), written as γ^pr (∂τ_crit/∂p)/γ_crit so it stays right at p = 0.
    #[inline(always)]
    fn stick(&self, stiffness: f64, tau: [f64; N]) -> StickAnswer<N> {
        let pressure_factor = self.dtau_crit_dp / self.gamma_crit;
        StickAnswer {
            traction: Traction::sticking(
                tau,
                diagonal(stiffness),
                scale(&self.predictor, pressure_factor),
                // k_s|γ^pr|²/2 as τ·γ^pr/2: no square root in stick.
                0.5 * dot(&tau, &self.predictor),
            ),
            ddtddp_factor: pressure_factor,
        }
    }

    /// Slip along n = γ^pr/γ_eq^pr: Δγ_eq^sl = γ_eq^pr − γ_crit, τ = n τ_crit
    /// (Eq. 5.2.3-2), and the slip increment Δγ_eq^sl. n is scaled for a subnormal γ_eq^pr
    /// when `scaled_direction` (the careful tier; its caller refuses an infinite one), else
    /// the plain quotient (the same bits for γ_eq^pr ≥ f64::MIN_POSITIVE).
    #[inline(always)]
    fn slip(&self, predictor_eq: f64, scaled_direction: bool) -> (Traction<N>, f64) {
        // In 2-D n = ±1, the sign of γ^pr: γ^pr/|γ^pr| for every γ^pr this branch can answer
        // (finite, beyond γ_crit > 0), without the division.
        let n = if N == 1 {
            [1.0f64.copysign(self.predictor[0]); N]
        } else if scaled_direction {
            unit_unless_infinite(&self.predictor, predictor_eq)
        } else {
            divided(&self.predictor, predictor_eq)
        };
        let slip_eq = predictor_eq - self.gamma_crit;
        let transverse = self.tau_crit / predictor_eq;
        // Eq. 5.2.3-3: (δ_ij − n_i n_j) τ_crit/γ_eq^pr dγ_j + n_i ∂τ_crit/∂p dp; in 2-D exactly
        // 0 (n² = 1).
        let ddtddg = if N == 1 {
            [[0.0; N]; N]
        } else {
            transverse_projection(&n, transverse)
        };
        // SED = |τ|²/(2k_s) with |τ| = τ_crit.
        let sed = 0.5 * self.tau_crit * self.gamma_crit;
        let t = Traction::sliding(&n, self.tau_crit, ddtddg, self.dtau_crit_dp, slip_eq, sed);
        (t, slip_eq)
    }
}

/// 0 < x < f64::MIN_POSITIVE (for x ≥ 0: k_s).
#[inline(always)]
fn is_subnormal(x: f64) -> bool {
    x > 0.0 && x < f64::MIN_POSITIVE
}

/// ±0 when every input the stick mode reads is finite, NaN otherwise (x·0 is NaN exactly for
/// x = ±∞ or NaN). Partial sums, as in [`traction_probe`].
#[inline(always)]
fn input_probe<const N: usize>(inc: &Increment<N>, stick: StickMode) -> f64 {
    let mut a = inc.pressure * 0.0;
    let mut b = inc.dpressure * 0.0;
    if stick != StickMode::Rough {
        a += inc.dtime * 0.0;
        for i in 0..N {
            a += inc.tau[i] * 0.0;
            b += inc.dgam[i] * 0.0;
        }
        if stick == StickMode::Exact && inc.entry == EntryFlag::ExactStick {
            for x in &inc.taulm {
                b += x * 0.0;
            }
        }
    }
    a + b
}

#[cold]
#[inline(never)]
fn bad_characteristic_length(length: f64, tolerance: f64) -> LawError {
    LawError::Input(format!(
        "CHRLNGTH = {length} but γ_crit is {tolerance} × CHRLNGTH; give a positive CHRLNGTH or \
         an absolute γ_crit (PROPS(5) > 0)"
    ))
}

/// ±0 when every output of the increment is finite, NaN otherwise. Four partial sums, so that
/// the test is a short chain of additions rather than one as long as the outputs are many (a
/// long chain holds the end of each call back and keeps the next from overlapping it).
#[inline(always)]
fn traction_probe<const N: usize>(t: &Traction<N>) -> f64 {
    let mut a = t.sed * 0.0;
    let mut b = t.sfd * 0.0;
    let mut c = 0.0;
    let mut d = 0.0;
    for i in 0..N {
        a += t.tau[i] * 0.0;
        b += t.ddtddp[i] * 0.0;
        c += t.dslip[i] * 0.0;
        for j in 0..N {
            d += t.ddtddg[i][j] * 0.0;
        }
    }
    (a + b) + (c + d)
}

#[cold]
#[inline(never)]
fn overflowed() -> LawError {
    LawError::Numerical("the stress update overflowed (inputs too large for f64)".into())
}

/// Law 1's plain form behind the law interface (`fric_`'s checked path; its plain fast path
/// calls `Coulomb::try_update` directly).
impl PointLaw for Coulomb {
    fn name(&self) -> &'static str {
        "the Coulomb law"
    }

    fn exact_stick(&self) -> bool {
        true
    }

    fn update_point<const N: usize>(&self, at: &PointInput<'_, N>) -> PointResult<N> {
        let up = self.update(at.increment, &CoulombState::from_statev(at.statev)?)?;
        // μ does not depend on temperature: ∂τ/∂θ̄ = 0.
        Ok(PointAnswer::isothermal(up.contact, &up.state, up.outcome))
    }

    fn coefficients(&self, rate: f64, pressure: f64, temperature: f64) -> Option<[[f64; 2]; 4]> {
        Some(ExtendedCoulomb::new(*self).coefficients(rate, pressure, temperature))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::XorShift;

    fn law() -> Coulomb {
        Coulomb::new(0.5)
            .and_then(|c| c.with_critical_slip_absolute(0.01))
            .unwrap()
    }

    fn motion<const N: usize>(c: Contact<N>) -> Traction<N> {
        match c {
            Contact::Motion(t) => t,
            Contact::ExactStick => panic!("expected LM = 0"),
        }
    }

    /// The traction of `l` for one increment from a point at rest (the default state).
    fn from_rest<const N: usize>(l: &Coulomb, inc: &Increment<N>) -> Traction<N> {
        motion(l.update(inc, &CoulombState::default()).unwrap().contact)
    }

    /// An increment with relative motion (Δt = 1): start stress `tau`, slip `dgam`, end
    /// pressure `pressure` after the change `dpressure`.
    fn moving<const N: usize>(
        tau: [f64; N],
        dgam: [f64; N],
        pressure: f64,
        dpressure: f64,
    ) -> Increment<N> {
        Increment {
            tau,
            dgam,
            pressure,
            dpressure,
            ..Increment::default()
        }
    }

    #[test]
    fn first_contact_gives_stick_stiffness_times_slip() {
        // p = 10, μ = 0.5 → τ_crit = 5, k_s = 500; Δγ = 0.004 < γ_crit → τ = 2.
        let t = from_rest(&law(), &moving([0.0], [0.004], 10.0, 10.0));
        assert!((t.tau[0] - 2.0).abs() < 1e-14);
        assert!((t.ddtddg[0][0] - 500.0).abs() < 1e-11);
        // ∂τ/∂p = γ^pr μ/γ_crit = 0.004·0.5/0.01 = 0.2.
        assert!((t.ddtddp[0] - 0.2).abs() < 1e-14);
    }

    #[test]
    fn start_elastic_slip_uses_start_pressure() {
        // Start: p = 10, τ = 2 → γ̄^el = 2/500 = 0.004. End: p = 20 (k_s = 1000), Δγ = 0.
        // τ = 1000·0.004 = 4. Recovering γ̄^el with the end pressure would give τ = 2.
        let t = from_rest(&law(), &moving([2.0], [0.0], 20.0, 10.0));
        assert!((t.tau[0] - 4.0).abs() < 1e-13);
    }

    #[test]
    fn slip_sits_on_the_cone_and_dissipates() {
        let inc = moving([0.0; 2], [0.03, 0.04], 10.0, 10.0);
        let up = law().update(&inc, &CoulombState::default()).unwrap();
        let t = motion(up.contact);
        // |γ^pr| = 0.05 → n = (0.6, 0.8), τ = 5 n, Δγ_eq^sl = 0.04, SFD = 5·0.04.
        assert!((t.tau[0] - 3.0).abs() < 1e-14 && (t.tau[1] - 4.0).abs() < 1e-14);
        assert!((t.sfd - 0.2).abs() < 1e-14);
        assert!((up.state.accumulated_slip - 0.04).abs() < 1e-15);
        assert_eq!(up.state.status, FrictionStatus::Slip);
    }

    #[test]
    fn shear_limit_caps_and_zeroes_the_pressure_tangent() {
        let l = law().with_shear_limit(3.0).unwrap();
        let t = from_rest(&l, &moving([0.0], [1.0], 10.0, 0.0));
        assert_eq!(t.tau[0], 3.0);
        assert_eq!(t.ddtddp[0], 0.0);
    }

    #[test]
    fn exact_stick_switching() {
        let l = law().with_stick(StickMode::Exact);
        let stuck = Increment::<2> {
            taulm: [3.0, 0.0],
            pressure: 10.0,
            entry: EntryFlag::ExactStick,
            ..Increment::default()
        };
        let st = CoulombState::default();
        assert_eq!(l.update(&stuck, &st).unwrap().contact, Contact::ExactStick);
        // Lagrange stress 6 > τ_crit = 5, DGAM = 0: slip along TAULM, finite.
        let release = Increment::<2> {
            taulm: [0.0, -6.0],
            ..stuck
        };
        let t = motion(l.update(&release, &st).unwrap().contact);
        assert_eq!(t.tau, [0.0, -5.0]);
        // Slipping, motion reverses against τ(t): stick again.
        let reverse = Increment::<2> {
            tau: [5.0, 0.0],
            dgam: [-1e-3, 0.0],
            pressure: 10.0,
            ..Increment::default()
        };
        assert_eq!(
            l.update(&reverse, &st).unwrap().contact,
            Contact::ExactStick
        );
    }

    #[test]
    fn rough_always_sticks() {
        let l = law().with_stick(StickMode::Rough);
        let inc = Increment::<1> {
            dgam: [10.0],
            pressure: 1.0,
            ..Increment::default()
        };
        assert_eq!(
            l.update(&inc, &CoulombState::default()).unwrap().contact,
            Contact::ExactStick
        );
    }

    /// The one-pass update tests Δγ through the results and the state with the inputs: every
    /// non-finite Δγ (in stick and slip, 2-D and 3-D) and state is still refused, and named.
    #[test]
    fn non_finite_slip_increment_and_state_are_refused_and_named() {
        let law = law();
        let state = CoulombState::default();
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for tau in [0.0, 1.0] {
                let inc = Increment::<2> {
                    tau: [tau, 0.0],
                    dgam: [bad, 1e-9],
                    pressure: 10.0,
                    dpressure: 0.0,
                    ..Default::default()
                };
                let e = law.update(&inc, &state).unwrap_err().to_string();
                assert!(e.contains("DGAM"), "{bad}: {e}");
                let inc = Increment::<1> {
                    tau: [tau],
                    dgam: [bad],
                    pressure: 10.0,
                    ..Default::default()
                };
                let e = law.update(&inc, &state).unwrap_err().to_string();
                assert!(e.contains("DGAM"), "{bad}: {e}");
            }
            let inc = Increment::<2> {
                dgam: [1e-9, 0.0],
                pressure: 10.0,
                ..Default::default()
            };
            for corrupt in [
                CoulombState {
                    accumulated_slip: bad,
                    ..state
                },
                CoulombState {
                    slip_rate: bad,
                    ..state
                },
            ] {
                let e = law.update(&inc, &corrupt).unwrap_err().to_string();
                assert!(e.contains("STATEV"), "{bad}: {e}");
            }
        }
    }

    #[test]
    fn parameters_are_validated() {
        assert!(Coulomb::new(-0.1).is_err());
        assert!(Coulomb::new(f64::NAN).is_err());
        assert!(law().with_shear_limit(0.0).is_err());
        assert!(law().with_critical_slip_absolute(-1.0).is_err());
        assert!(law().with_slip_tolerance(f64::INFINITY).is_err());
    }

    #[test]
    fn statev_round_trip_and_short_array() {
        let s = CoulombState {
            accumulated_slip: 1.5,
            slip_rate: 0.25,
            status: FrictionStatus::Slip,
        };
        let mut v = [9.0; 4];
        s.write_statev(&mut v);
        assert_eq!(v[3], 9.0);
        assert_eq!(CoulombState::from_statev(&v).unwrap(), s);
        assert!(CoulombState::from_statev(&v[..2]).is_err());
    }

    /// A value anywhere in the f64 range (both signs, subnormals, near f64::MAX), or zero, or an
    /// ordinary one.
    fn wide(rng: &mut XorShift) -> f64 {
        let bits = rng.bits();
        let u = (bits >> 11) as f64 / (1u64 << 53) as f64;
        let sign = if bits & 1 == 0 { 1.0 } else { -1.0 };
        match bits % 4 {
            0 => sign * 2f64.powf(-1074.0 + u * 2097.9),
            1 => 0.0,
            _ => sign * 2.0 * u,
        }
    }

    /// The finiteness test of elastic stick looks at the scalars that bound the results, not at
    /// the results: whatever the magnitudes, an answer has only finite results, every stress
    /// within τ_crit to round-off, and the state is finite. (The `fric` fuzz target checks the
    /// same through `fric_`; this runs the whole range in every `cargo test`.)
    #[test]
    fn elastic_stick_answers_are_finite_over_the_whole_range() {
        let mut rng = XorShift(0x9e37_79b9_7f4a_7c15);
        let mut answered = [0usize; 2];
        for case in 0..200_000 {
            let mu = wide(&mut rng).abs();
            let tau_max = if case % 3 == 0 {
                wide(&mut rng).abs()
            } else {
                0.0
            };
            let gamma = wide(&mut rng).abs();
            let Ok(law) = Coulomb::new(mu).and_then(|l| {
                let l = l.with_critical_slip_absolute(if gamma > 0.0 { gamma } else { 1e-3 })?;
                if tau_max > 0.0 {
                    l.with_shear_limit(tau_max)
                } else {
                    Ok(l)
                }
            }) else {
                continue;
            };
            let inc = Increment::<2> {
                tau: [wide(&mut rng), wide(&mut rng)],
                dgam: [wide(&mut rng), wide(&mut rng)],
                pressure: wide(&mut rng),
                dpressure: wide(&mut rng),
                dtime: wide(&mut rng).abs(),
                ..Increment::default()
            };
            let start = CoulombState::default();
            let Ok(up) = law.update(&inc, &start) else {
                continue;
            };
            let Contact::Motion(t) = up.contact else {
                panic!("elastic stick answered LM = 1");
            };
            let values = [t.sed, t.sfd, up.state.accumulated_slip, up.state.slip_rate];
            let all = t
                .tau
                .iter()
                .chain(&t.ddtddp)
                .chain(&t.dslip)
                .chain(t.ddtddg.iter().flatten());
            assert!(
                all.chain(&values).all(|x| x.is_finite()),
                "case {case}: {law:?} {inc:?} gave {t:?}"
            );
            let (tau_crit, _) = law.critical_stress(inc.pressure);
            let stress = t.tau[0].hypot(t.tau[1]);
            assert!(
                stress <= tau_crit * (1.0 + 1e-12) + f64::from_bits(1),
                "case {case}: |τ| = {stress} above τ_crit = {tau_crit}: {law:?} {inc:?}"
            );
            answered[usize::from(up.state.status == FrictionStatus::Slip)] += 1;
        }
        // Both branches were reached often enough for the test to mean something.
        assert!(answered[0] > 1000 && answered[1] > 1000, "{answered:?}");
    }

    /// Every bit of an update, for comparisons that tell −0 from +0.
    fn update_bits<const N: usize>(up: &Update<N>) -> Vec<u64> {
        let mut v = vec![
            up.state.accumulated_slip.to_bits(),
            up.state.slip_rate.to_bits(),
            up.state.status as u64,
        ];
        if let Contact::Motion(t) = &up.contact {
            let all = t
                .tau
                .iter()
                .chain(&t.ddtddp)
                .chain(&t.dslip)
                .chain(t.ddtddg.iter().flatten())
                .chain([&t.sed, &t.sfd]);
            v.extend(all.map(|x| x.to_bits()));
        }
        v
    }

    /// Runs both tiers of elastic stick on one increment: the one-pass tier may decline what the
    /// careful tier answers, never the reverse, and where both answer the bits are the same.
    /// Returns (one-pass answered, careful answered).
    fn tiers_agree<const N: usize>(
        law: &Coulomb,
        inc: &Increment<N>,
        start: &CoulombState,
    ) -> (bool, bool) {
        let fast = law.integrate::<N, false>(inc, start);
        let careful = law.integrate::<N, true>(inc, start);
        if let Some(f) = &fast {
            let Some(c) = &careful else {
                panic!(
                    "one-pass tier answered what the careful tier refuses: {law:?} {inc:?} {start:?}"
                );
            };
            assert_eq!(update_bits(f), update_bits(c), "{law:?} {inc:?} {start:?}");
        }
        (fast.is_some(), careful.is_some())
    }

    fn law_of(mu: f64, gamma_crit: f64, tau_max: f64) -> Option<Coulomb> {
        let law = Coulomb::new(mu)
            .ok()?
            .with_critical_slip_absolute(gamma_crit)
            .ok()?;
        if tau_max > 0.0 {
            law.with_shear_limit(tau_max).ok()
        } else {
            Some(law)
        }
    }

    /// The one-pass tier over the whole f64 range (magnitudes, signs, zeros, non-finite state)
    /// against the careful tier.
    #[test]
    fn one_pass_tier_gives_the_careful_tiers_bits_or_declines() {
        fn run<const N: usize>(seed: u64) -> [usize; 3] {
            let mut rng = XorShift(seed);
            // [both answered, only the careful tier, neither]
            let mut seen = [0usize; 3];
            for case in 0..100_000 {
                let mut draw = || wide(&mut rng);
                let tau_max = if case % 3 == 0 { draw().abs() } else { 0.0 };
                let Some(law) = law_of(draw().abs(), draw().abs(), tau_max) else {
                    continue;
                };
                let mut inc = Increment::<N> {
                    tau: std::array::from_fn(|_| draw()),
                    dgam: std::array::from_fn(|_| draw()),
                    pressure: draw(),
                    dpressure: draw(),
                    dtime: draw().abs(),
                    ..Increment::default()
                };
                // One input in eleven made ±∞ or NaN.
                if case % 11 == 0 {
                    let bad = [f64::INFINITY, f64::NEG_INFINITY, f64::NAN][case % 3];
                    match (case / 11) % 5 {
                        0 => inc.tau[N - 1] = bad,
                        1 => inc.dgam[0] = bad,
                        2 => inc.pressure = bad,
                        3 => inc.dpressure = bad,
                        _ => inc.dtime = bad,
                    }
                }
                let start = CoulombState {
                    accumulated_slip: if case % 50 == 0 {
                        f64::INFINITY
                    } else {
                        draw().abs()
                    },
                    slip_rate: if case % 70 == 0 {
                        f64::NAN
                    } else {
                        draw().abs()
                    },
                    status: FrictionStatus::Stick,
                };
                match tiers_agree(&law, &inc, &start) {
                    (true, _) => seen[0] += 1,
                    (false, true) => seen[1] += 1,
                    (false, false) => seen[2] += 1,
                }
            }
            seen
        }
        for seen in [
            run::<1>(0x2545_f491_4f6c_dd1d),
            run::<2>(0x9e37_79b9_7f4a_7c15),
        ] {
            // Each kind of outcome occurred often enough for the comparison to mean something.
            assert!(seen.iter().all(|&n| n > 1000), "{seen:?}");
        }
    }

    /// Where the one-pass tier declines on purpose (the bound's edges), the careful tier still
    /// answers; and increments of ordinary magnitude never leave the one-pass tier.
    #[test]
    fn one_pass_tier_declines_only_at_the_edges_of_the_range() {
        let start = CoulombState::default();
        let edge = |law: Coulomb, tau: f64, dgam: f64, pressure: f64| {
            let inc = Increment::<2> {
                tau: [tau, 0.0],
                dgam: [dgam, 0.5 * dgam],
                pressure,
                dtime: 1.0,
                ..Increment::default()
            };
            tiers_agree(&law, &inc, &start)
        };
        let law = |mu, gamma_crit| law_of(mu, gamma_crit, 0.0).unwrap();
        let two = |e: i32| 2f64.powi(e);
        // γ_crit² normal (γ_crit = 2⁻⁵¹¹) is the one-pass tier's; just below it, not.
        assert_eq!(edge(law(0.3, two(-511)), 0.0, two(-509), 1.0), (true, true));
        assert_eq!(
            edge(law(0.3, two(-512)), 0.0, two(-510), 1.0),
            (false, true)
        );
        // At the top, sticking (the bound also holds |γ^pr|² + 1 and γ_crit).
        assert_eq!(edge(law(0.3, two(510)), 0.0, two(200), 1.0), (true, true));
        assert_eq!(edge(law(0.3, two(512)), 0.0, two(200), 1.0), (false, true));
        // τ_crit at 2⁵¹² and a slip whose square overflows: finite answers, careful tier.
        assert_eq!(edge(law(1.0, 1e-3), 0.0, 1e-2, two(513)), (false, true));
        assert_eq!(edge(law(0.3, 1e-3), 0.0, 1e160, 1e6), (false, true));
        // A subnormal stick stiffness: the careful tier forms τ_crit·(γ^pr/γ_crit).
        let soft = law_of(0.3, 1.0, 1e-308).unwrap();
        assert_eq!(edge(soft, 0.0, 0.25, 1.0), (false, true));

        // Ordinary increments (SI units, γ_crit from μm to cm, stick and slip, loading and
        // unloading): always the one-pass tier.
        let mut rng = XorShift(0x5851_f42d_4c95_7f2d);
        let mut uniform = move |lo: f64, hi: f64| lo + (hi - lo) * rng.unit();
        for case in 0..20_000 {
            let gamma_crit = 10f64.powf(uniform(-6.0, -2.0));
            let tau_max = if case % 2 == 0 {
                uniform(1e3, 1e8)
            } else {
                0.0
            };
            let law = law_of(uniform(0.0, 1.2), gamma_crit, tau_max).unwrap();
            let pressure = uniform(-1e6, 1e9);
            let inc = Increment::<2> {
                tau: [uniform(-1e8, 1e8), uniform(-1e8, 1e8)],
                dgam: [
                    uniform(-3.0, 3.0) * gamma_crit,
                    uniform(-3.0, 3.0) * gamma_crit,
                ],
                pressure,
                dpressure: uniform(-1.0, 1.0) * pressure.abs(),
                dtime: uniform(1e-6, 1.0),
                ..Increment::default()
            };
            let start = CoulombState {
                accumulated_slip: uniform(0.0, 1.0),
                slip_rate: uniform(0.0, 10.0),
                status: FrictionStatus::Slip,
            };
            assert_eq!(
                tiers_agree(&law, &inc, &start),
                (true, true),
                "{law:?} {inc:?}"
            );
        }
    }

    /// A start stress so small that γ_crit/τ_crit(p − Δp) overflows (here a pressure of
    /// 10⁻³¹² with γ_crit = 10⁻³): the elastic start slip is still τ̄/k_s(p − Δp), formed as
    /// (τ̄/τ_crit)·γ_crit. Before, 0·∞ made the first-contact predictor NaN and the increment was
    /// refused as an overflow.
    #[test]
    fn a_vanishing_start_stress_keeps_its_elastic_slip() {
        let law = Coulomb::new(0.3)
            .unwrap()
            .with_critical_slip_absolute(1e-3)
            .unwrap();
        let p = 1e-312;
        let tau_crit = 0.3 * p;
        assert!(
            1e-3 / tau_crit == f64::INFINITY,
            "the case needs an overflowing factor"
        );
        for tau_start in [0.0, 0.5 * tau_crit, -tau_crit] {
            let inc = Increment::<1> {
                tau: [tau_start],
                dgam: [2e-4],
                pressure: p,
                dtime: 1.0,
                ..Increment::default()
            };
            let up = law
                .update(&inc, &CoulombState::default())
                .unwrap_or_else(|e| panic!("τ̄ = {tau_start}: {e}"));
            let Contact::Motion(t) = up.contact else {
                panic!("elastic stick answered LM = 1");
            };
            // γ^pr = γ_crit τ̄/τ_crit + Δγ, within γ_crit here: τ = τ_crit γ^pr/γ_crit (a
            // subnormal stress: a few digits fewer than usual).
            let predictor = 1e-3 * tau_start / tau_crit + 2e-4;
            let expected = tau_crit * predictor / 1e-3;
            assert!(
                (t.tau[0] - expected).abs() <= 1e-6 * tau_crit,
                "τ̄ = {tau_start}: τ = {} against {expected}",
                t.tau[0]
            );
        }
    }
}
