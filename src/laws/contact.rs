//! The contact point as every friction law sees it: the increment the host gives
//! ([`Increment`], with its entry flag), the answer a law returns ([`Contact`] and its
//! [`Traction`]), and the three-scalar state most laws keep in `STATEV(1..3)` ([`PointState`],
//! over a law's own [`StatusCode`]). No law lives here; `coulomb.rs` and the others import it.

use super::small_vec::{all_finite, scale};
use crate::LawError;

/// The stick flag the host passes in (`LM` on entry): the previous iteration's answer, or at the
/// start of an increment the converged state.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum EntryFlag {
    /// `LM = 0`: relative motion was allowed (slipping, or elastic stick).
    #[default]
    Motion,
    /// `LM = 1`: the point was held by Lagrange multipliers; `taulm` holds their stress.
    ExactStick,
}

/// One increment at one contact point, in the host's terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Increment<const N: usize> {
    /// Frictional stress at the start of the increment (already rotated by the host).
    pub tau: [f64; N],
    /// Relative tangential motion increment Δγ.
    pub dgam: [f64; N],
    /// Lagrange-multiplier stress, read only when `entry` is [`EntryFlag::ExactStick`].
    pub taulm: [f64; N],
    /// Contact pressure at the end of the increment.
    pub pressure: f64,
    /// Pressure increment; the increment starts at `pressure − dpressure`.
    pub dpressure: f64,
    /// Time increment (used for the slip rate kept in the state).
    pub dtime: f64,
    /// Characteristic contact face length (`CHRLNGTH`), used when γ_crit is a tolerance.
    pub characteristic_length: f64,
    /// The host's stick flag on entry.
    pub entry: EntryFlag,
}

impl<const N: usize> Default for Increment<N> {
    fn default() -> Self {
        Increment {
            tau: [0.0; N],
            dgam: [0.0; N],
            taulm: [0.0; N],
            pressure: 0.0,
            dpressure: 0.0,
            dtime: 1.0,
            characteristic_length: 0.0,
            entry: EntryFlag::Motion,
        }
    }
}

impl<const N: usize> Increment<N> {
    /// ±0 when `PRESS`, `DPRESS`, `DTIME`, `TAU` and `DGAM` are finite, NaN otherwise (x·0 is
    /// ±0 for finite x: one test for them all on the common path; [`name_bad_input`] names the
    /// culprit on failure).
    #[inline(always)]
    pub(crate) fn motion_probe(&self) -> f64 {
        let mut probe = self.pressure * 0.0 + self.dpressure * 0.0 + self.dtime * 0.0;
        for i in 0..N {
            probe += self.tau[i] * 0.0 + self.dgam[i] * 0.0;
        }
        probe
    }

    /// Refuses a non-finite `PRESS`, `DPRESS`, `DTIME`, `TAU` or `DGAM`, naming the first (a
    /// law that reads no `TAULM`).
    #[inline(always)]
    pub(crate) fn check_finite(&self) -> Result<(), LawError> {
        if self.motion_probe() == 0.0 {
            Ok(())
        } else {
            Err(name_bad_input(*self, false))
        }
    }
}

/// Names the first non-finite input of `inc` (`TAULM` only when `reads_taulm`): the slow path
/// of the laws' input probes.
#[cold]
#[inline(never)]
#[allow(clippy::needless_pass_by_value)]
pub(crate) fn name_bad_input<const N: usize>(inc: Increment<N>, reads_taulm: bool) -> LawError {
    let what = if !inc.pressure.is_finite() {
        "PRESS"
    } else if !inc.dpressure.is_finite() {
        "DPRESS"
    } else if !all_finite(&inc.dgam) {
        "DGAM"
    } else if !all_finite(&inc.tau) {
        "TAU"
    } else if reads_taulm && !all_finite(&inc.taulm) {
        "TAULM"
    } else {
        "DTIME"
    };
    LawError::Input(format!("{what} is NaN or infinite"))
}

/// How a point's status is stored in `STATEV(3)`:
/// [`FrictionStatus`](crate::laws::coulomb::FrictionStatus) for the Coulomb laws,
/// `InterfaceStatus` for the adhesive interface (which adds bonded and open).
pub trait StatusCode: Copy + PartialEq {
    /// The law, as messages about its state (too short a `STATEV` or `NSTATV`) name it.
    const LAW: &'static str;
    /// The status of a point that held by elastic stick in the increment.
    const STICK: Self;
    /// The status of a point that slid in the increment: its slip rate is the rate memory
    /// ([`PointState::sliding_rate`]).
    const SLIP: Self;
    /// The status stored as `code`; an unknown code reads as stick.
    fn from_code(code: f64) -> Self;
    /// The code stored for the status.
    fn code(self) -> f64;
}

/// A point's state: three scalars, stored in `STATEV(1..3)`. No vector is kept, so the
/// rotation `DROT` of the tangent directions needs no treatment (the host rotates `TAU`
/// itself). The laws differ only in the statuses `S` they record.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PointState<S> {
    /// Accumulated equivalent slip Σ|Δγ^sl| (path length of inelastic slip); saturates at
    /// f64::MAX.
    pub accumulated_slip: f64,
    /// Equivalent slip rate of the last increment, |Δγ^sl|/Δt (0 when Δt ≤ 0); saturates at
    /// f64::MAX.
    pub slip_rate: f64,
    /// What the point did in the last increment (stick, slip, …).
    pub status: S,
}

impl<S: StatusCode> PointState<S> {
    /// Number of `STATEV` entries the law uses.
    pub const NSTATV: usize = 3;

    /// The law whose statuses `S` are, as messages name it.
    pub const LAW: &'static str = S::LAW;

    /// Reads the state from `STATEV`; `statev` must hold at least [`Self::NSTATV`] entries.
    #[inline(always)]
    pub fn from_statev(statev: &[f64]) -> Result<Self, LawError> {
        let [s, rate, status, ..] = statev else {
            return Err(short_statev(statev.len(), S::LAW));
        };
        Self::from_values(*s, *rate, *status).ok_or_else(corrupt_statev)
    }

    /// The slip rate of the last increment when the point slid in it (the memory of the
    /// rate-following formulation and of the rate-and-state law's stick stiffness), `None`
    /// after anything else. A slide's rate is ≥ 0 (and finite: [`Self::from_statev`] refuses
    /// NaN and ∞); a negative one is refused as a corrupted state.
    pub fn sliding_rate(&self) -> Result<Option<f64>, LawError> {
        if self.status != S::SLIP {
            return Ok(None);
        }
        if self.slip_rate < 0.0 {
            return Err(LawError::Input(format!(
                "STATEV(2) (slip rate) = {} must be ≥ 0 (state corrupted by the caller?)",
                self.slip_rate
            )));
        }
        Ok(Some(self.slip_rate))
    }

    /// The state from `STATEV(1..3)`; `None` when `STATEV(1)` or `STATEV(2)` is not finite.
    /// An unknown status code reads as stick.
    #[inline(always)]
    #[must_use]
    pub fn from_values(accumulated_slip: f64, slip_rate: f64, status: f64) -> Option<Self> {
        let state = Self::from_values_unchecked(accumulated_slip, slip_rate, status);
        state.is_finite().then_some(state)
    }

    /// [`Self::from_values`] without the finiteness test, for a caller whose update tests the
    /// state with its inputs (`Coulomb::try_update` does).
    #[inline(always)]
    #[must_use]
    pub(crate) fn from_values_unchecked(
        accumulated_slip: f64,
        slip_rate: f64,
        status: f64,
    ) -> Self {
        PointState {
            accumulated_slip,
            slip_rate,
            status: S::from_code(status),
        }
    }

    /// The state after an increment with relative motion (`LM = 0`): the path of inelastic
    /// slip grows by `slip` = |Δγ^sl|, the slip rate becomes `slip_rate` and the status
    /// `status`. Both scalars saturate at f64::MAX rather than overflow: a finite slip over a
    /// subnormal `DTIME`, or a sum near f64::MAX, would otherwise store ∞ in `STATEV`, which
    /// the next increment refuses as corrupted (fuzz targets `fric` and `uinter`). `slip` and
    /// `slip_rate` are finite and ≥ 0 (the callers test their answers first), so each
    /// `f64::min` with the constant f64::MAX is one `minsd`.
    #[inline(always)]
    #[must_use]
    pub(crate) fn after_slide(&self, slip: f64, slip_rate: f64, status: S) -> Self {
        PointState {
            accumulated_slip: (self.accumulated_slip + slip).min(f64::MAX),
            slip_rate: slip_rate.min(f64::MAX),
            status,
        }
    }

    /// `STATEV(1)` and `STATEV(2)` finite.
    #[inline(always)]
    pub(super) fn is_finite(&self) -> bool {
        self.probe() == 0.0
    }

    /// ±0 when both scalars are finite, NaN otherwise (x·0).
    #[inline(always)]
    pub(super) fn probe(&self) -> f64 {
        self.accumulated_slip * 0.0 + self.slip_rate * 0.0
    }

    /// Writes the state into the first [`Self::NSTATV`] entries of `statev` (nothing else).
    #[inline(always)]
    pub fn write_statev(&self, statev: &mut [f64]) {
        if let [s, rate, status, ..] = statev {
            *s = self.accumulated_slip;
            *rate = self.slip_rate;
            *status = self.status.code();
        }
    }
}

/// The elastic slip at the start of an increment, γ̄^el = τ̄/k̄_s = τ̄·γ_crit/τ̄_s, for the start
/// stress `tau` held by the strength `strength` = τ̄_s (so k̄_s = τ̄_s/γ_crit); zero when there
/// is no strength to hold a stress. Where γ_crit/τ̄_s overflows (a subnormal strength), it is
/// formed as (τ̄/τ̄_s)·γ_crit: finite for a stress within the strength, 0 for τ̄ = 0 (the product
/// would be 0·∞ = NaN).
#[inline(always)]
pub fn elastic_start_slip<const N: usize>(
    tau: &[f64; N],
    gamma_crit: f64,
    strength: f64,
) -> [f64; N] {
    if strength > 0.0 {
        let factor = gamma_crit / strength;
        if factor == f64::INFINITY {
            std::array::from_fn(|i| tau[i] / strength * gamma_crit)
        } else {
            scale(tau, factor)
        }
    } else {
        [0.0; N]
    }
}

/// Elastic stick's stress τ = k_s·γ^pr with k_s = τ_s/γ_crit (Eq. 5.2.3-1), and k_s. Where
/// k_s is subnormal (few significant digits: a strength near f64::MIN_POSITIVE over a large
/// γ_crit), k_s·γ^pr can come out above τ_s by far more than round-off for |γ^pr| ≤ γ_crit; τ
/// is then formed as τ_s·(γ^pr/γ_crit), within τ_s to round-off (as the Coulomb law's careful
/// tier forms it).
#[inline(always)]
pub fn elastic_stick_stress<const N: usize>(
    predictor: &[f64; N],
    gamma_crit: f64,
    strength: f64,
) -> ([f64; N], f64) {
    let k_s = strength / gamma_crit;
    let tau = if k_s > 0.0 && k_s < f64::MIN_POSITIVE {
        std::array::from_fn(|i| predictor[i] / gamma_crit * strength)
    } else {
        scale(predictor, k_s)
    };
    (tau, k_s)
}

/// Stress, tangents and energies of an increment that allows relative motion (`LM = 0`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Traction<const N: usize> {
    /// Frictional stress τ at the end of the increment.
    pub tau: [f64; N],
    /// `ddtddg[a][b]` = ∂τ_a/∂Δγ_b.
    pub ddtddg: [[f64; N]; N],
    /// ∂τ_a/∂p with the start of the increment held fixed.
    pub ddtddp: [f64; N],
    /// Inelastic slip increment Δγ^sl.
    pub dslip: [f64; N],
    /// Elastic energy density |τ|²/(2k_s) (0 in exact stick, which has no elastic slip).
    pub sed: f64,
    /// Frictional dissipation of the increment, τ·Δγ^sl (backward Euler), never negative.
    pub sfd: f64,
}

impl<const N: usize> Traction<N> {
    /// Every stress, tangent, slip and energy is finite: the test a law makes of its answer
    /// before it stores it (an overflow from finite inputs is refused, never written).
    #[must_use]
    pub fn is_finite(&self) -> bool {
        let mut finite = self.sed.is_finite() && self.sfd.is_finite();
        for a in 0..N {
            finite &= self.tau[a].is_finite()
                && self.ddtddp[a].is_finite()
                && self.dslip[a].is_finite()
                && all_finite(&self.ddtddg[a]);
        }
        finite
    }

    /// A sliding answer along the unit slip direction n (Eq. 5.2.3-2): τ = t·n with the
    /// strength t, ∂τ/∂p = n·∂t/∂p, Δγ^sl = Δγ_eq^sl·n and `SFD` = t·Δγ_eq^sl (backward Euler);
    /// the tangent ∂τ/∂Δγ and the elastic energy `SED` as the caller's formulation has them.
    #[inline(always)]
    #[must_use]
    pub(crate) fn sliding(
        n: &[f64; N],
        t: f64,
        ddtddg: [[f64; N]; N],
        dt_dp: f64,
        slip_eq: f64,
        sed: f64,
    ) -> Self {
        Traction {
            tau: scale(n, t),
            ddtddg,
            ddtddp: scale(n, dt_dp),
            dslip: scale(n, slip_eq),
            sed,
            sfd: t * slip_eq,
        }
    }

    /// An answer without slip (elastic or viscous stick, a bonded shear): Δγ^sl = 0 and
    /// `SFD` = 0; the stress, its tangents and `SED` as the caller's law has them.
    #[inline(always)]
    #[must_use]
    pub(crate) fn sticking(
        tau: [f64; N],
        ddtddg: [[f64; N]; N],
        ddtddp: [f64; N],
        sed: f64,
    ) -> Self {
        Traction {
            tau,
            ddtddg,
            ddtddp,
            dslip: [0.0; N],
            sed,
            sfd: 0.0,
        }
    }

    /// An answer without stress (no friction to carry it, or an open interface): τ = 0,
    /// ∂τ/∂Δγ = 0, nothing stored or dissipated; the motion counted as slip `dslip` and
    /// ∂τ/∂p (the strength's right derivative at p = 0 where friction starts) as the caller
    /// has them.
    #[inline(always)]
    #[must_use]
    pub(crate) fn stress_free(ddtddp: [f64; N], dslip: [f64; N]) -> Self {
        Traction {
            tau: [0.0; N],
            ddtddg: [[0.0; N]; N],
            ddtddp,
            dslip,
            sed: 0.0,
            sfd: 0.0,
        }
    }
}

/// The answer of the law for one increment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Contact<const N: usize> {
    /// `LM = 0`: relative motion allowed; stress and tangents given.
    Motion(Traction<N>),
    /// `LM = 1`: the host holds the point with Lagrange multipliers.
    ExactStick,
}

#[cold]
#[inline(never)]
fn short_statev(n: usize, law: &str) -> LawError {
    LawError::Input(format!("NSTATV = {n} but {law} needs 3"))
}

#[cold]
#[inline(never)]
pub(super) fn corrupt_statev() -> LawError {
    LawError::Input("STATEV(1..2) are not finite (state corrupted by the caller?)".into())
}

/// What a law may read at a point besides the increment ([`crate::laws::point_law::Needs`]
/// says which): the mean surface temperature, the rotation of the tangent directions and the
/// point's coordinates. Defaults: 0, no rotation, no coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conditions {
    /// Average surface temperature θ̄ = (TEMP(1) + TEMP(2))/2 (read only with a temperature law).
    pub temperature: f64,
    /// Rotation increment of the tangent directions, `drot[a][b]` = DROT(a+1, b+1); applied to
    /// the viscous stress kept in the state.
    pub drot: [[f64; 2]; 2],
    /// Coordinates of the contact point (`COORDS`, the first MCRD used); read only in
    /// steady-state transport, for the radius R.
    pub coords: [f64; 3],
    /// How many of `coords` the host gave (MCRD, at most 3).
    pub ncoords: usize,
}

impl Default for Conditions {
    fn default() -> Self {
        Conditions {
            temperature: 0.0,
            drot: [[1.0, 0.0], [0.0, 1.0]],
            coords: [0.0; 3],
            ncoords: 0,
        }
    }
}

/// θ̄, the temperature μ depends on: the mean of the two surfaces' temperatures
/// (`TEMP(1)`, `TEMP(2)`), so each carries half of ∂τ/∂θ̄ (`ExtendedUpdate::ddtddt_column`).
#[inline(always)]
#[must_use]
pub fn mean_surface_temperature([slave, master]: [f64; 2]) -> f64 {
    0.5 * (slave + master)
}

#[cfg(test)]
mod tests {
    use super::{PointState, Traction, elastic_start_slip, elastic_stick_stress};
    use crate::laws::coulomb::FrictionStatus;

    /// The path of slip adds up, and saturates at f64::MAX where the sum overflows, as does the
    /// rate; the status is the one given.
    #[test]
    fn the_state_after_a_slide_adds_the_slip_and_saturates() {
        let start = PointState {
            accumulated_slip: 1.5,
            slip_rate: 7.0,
            status: FrictionStatus::Stick,
        };
        let end = start.after_slide(0.25, 3.0, FrictionStatus::Slip);
        assert_eq!(
            (end.accumulated_slip, end.slip_rate, end.status),
            (1.75, 3.0, FrictionStatus::Slip)
        );
        let far = PointState {
            accumulated_slip: f64::MAX,
            ..start
        };
        let end = far.after_slide(f64::MAX, f64::INFINITY, FrictionStatus::Stick);
        assert_eq!((end.accumulated_slip, end.slip_rate), (f64::MAX, f64::MAX));
        assert_eq!(end.status, FrictionStatus::Stick);
    }

    /// A traction is finite only if every one of its numbers is: each set to NaN or ±∞ in
    /// turn is caught.
    #[test]
    fn a_traction_with_any_non_finite_number_is_not_finite() {
        let t = Traction::sliding(&[0.6, 0.8], 2.0, [[1.0, 0.0], [0.0, 1.0]], 0.3, 0.1, 0.5);
        assert!(t.is_finite());
        let spoilt: [fn(&mut Traction<2>, f64); 6] = [
            |t, x| t.tau[1] = x,
            |t, x| t.ddtddg[1][0] = x,
            |t, x| t.ddtddp[1] = x,
            |t, x| t.dslip[1] = x,
            |t, x| t.sed = x,
            |t, x| t.sfd = x,
        ];
        for (i, spoil) in spoilt.iter().enumerate() {
            for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut u = t;
                spoil(&mut u, x);
                assert!(!u.is_finite(), "field {i} = {x} passed");
            }
        }
    }

    /// γ̄^el = τ̄·γ_crit/τ̄_s, also where γ_crit/τ̄_s overflows (a subnormal strength: then
    /// (τ̄/τ̄_s)·γ_crit, and 0 rather than 0·∞ = NaN for τ̄ = 0), and 0 without a strength.
    #[test]
    fn the_start_elastic_slip_is_finite_for_a_subnormal_strength() {
        let strength: f64 = 1e-310;
        assert!((1.0 / strength).is_infinite() && strength < f64::MIN_POSITIVE);
        assert_eq!(elastic_start_slip(&[0.0, 0.0], 1.0, strength), [0.0, 0.0]);
        let within = elastic_start_slip(&[0.6 * strength, -0.8 * strength], 2.0, strength);
        for (got, want) in within.iter().zip([1.2, -1.6]) {
            assert!((got - want).abs() <= 1e-9, "{within:?}");
        }
        assert_eq!(elastic_start_slip(&[3.0], 0.5, 0.0), [0.0]);
        assert_eq!(elastic_start_slip(&[3.0], 0.5, 2.0), [0.75]);
    }

    /// τ = k_s·γ^pr, and for a subnormal k_s = τ_s/γ_crit still within τ_s to round-off on the
    /// stick limit |γ^pr| = γ_crit (k_s·γ^pr there is τ_s to eight digits only).
    #[test]
    fn the_stick_stress_keeps_its_digits_for_a_subnormal_stiffness() {
        let (strength, gamma_crit) = (f64::MIN_POSITIVE, 3.9e10);
        let on_limit = [0.6 * gamma_crit, 0.8 * gamma_crit];
        let (tau, k_s) = elastic_stick_stress(&on_limit, gamma_crit, strength);
        assert!(k_s > 0.0 && k_s < f64::MIN_POSITIVE);
        let magnitude = tau[0].hypot(tau[1]);
        assert!(
            (magnitude - strength).abs() <= 1e-12 * strength,
            "|τ| = {magnitude:e}, τ_s = {strength:e}"
        );
        // A plain k_s: the product itself.
        assert_eq!(
            elastic_stick_stress(&[2.0, -1.0], 4.0, 8.0),
            ([4.0, -2.0], 2.0)
        );
    }
}
