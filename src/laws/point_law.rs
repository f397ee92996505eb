//! The interface the entry points ask of a friction law for one contact point: what the law needs
//! (`NSTATV` per `NFDIR`, whether it answers exact stick), and one update from an increment and
//! the start state in `STATEV` to an answer (traction and tangents, `DDTDDT`, the end state,
//! a step ratio) or a refusal with its cause, and `FRIC_COEF`'s μ where the law has one. The
//! shell reads the host's arguments into an [`Increment`] and the [`Conditions`] the law
//! [`Needs`], calls [`PointLaw::update_point`] through the law enum (static dispatch, no
//! `dyn`), and writes the answer; it knows no law. docs/architecture.md, "Adding a law".

use super::contact::{Conditions, Contact, Increment, PointState, StatusCode};
use super::coulomb::FrictionStatus;
use crate::{LawError, Outcome};

/// The largest `STATEV` a law behind [`PointLaw`] writes.
pub const MAX_POINT_STATEV: usize = 8;

/// One point's answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointAnswer<const N: usize> {
    /// Stress and tangents (`LM = 0`), or exact stick (`LM = 1`).
    pub contact: Contact<N>,
    /// The end state, `STATEV(1..statev_len)`.
    pub statev: [f64; MAX_POINT_STATEV],
    /// How many entries of `statev` the law writes.
    pub statev_len: usize,
    /// ∂τ/∂θ̄ (each of `DDTDDT(·,1)` and `DDTDDT(·,2)` is half of it; 0 without temperature).
    pub dtau_dtheta: [f64; N],
    /// Suggested ratio of the next time increment to this one (∞: no suggestion).
    pub step_ratio: f64,
}

impl<const N: usize> PointAnswer<N> {
    /// The answer of a law that does not depend on temperature (∂τ/∂θ̄ = 0), with the end
    /// state `state` and the step ratio of `outcome`.
    #[must_use]
    pub fn isothermal(contact: Contact<N>, state: &impl EndState, outcome: Outcome) -> Self {
        let mut statev = [0.0; MAX_POINT_STATEV];
        state.write_statev(&mut statev);
        PointAnswer {
            contact,
            statev,
            statev_len: state.statev_len(),
            dtau_dtheta: [0.0; N],
            step_ratio: outcome.step_ratio,
        }
    }

    /// The answer with ∂τ/∂θ̄ = `dtau_dtheta` and the end state's `STATEV` `statev` (at most
    /// [`MAX_POINT_STATEV`] entries).
    #[must_use]
    pub fn new(
        contact: Contact<N>,
        statev: &[f64],
        dtau_dtheta: [f64; N],
        step_ratio: f64,
    ) -> Self {
        let mut all = [0.0; MAX_POINT_STATEV];
        all[..statev.len()].copy_from_slice(statev);
        PointAnswer {
            contact,
            statev: all,
            statev_len: statev.len(),
            dtau_dtheta,
            step_ratio,
        }
    }
}

/// One point's input: the increment, the conditions the law [`PointLaw::needs`], and the start
/// state (`STATEV`, at least [`PointLaw::nstatv`] entries).
#[derive(Clone, Copy, Debug)]
pub struct PointInput<'a, const N: usize> {
    /// The increment.
    pub increment: &'a Increment<N>,
    /// What the law asked for besides the increment (defaults elsewhere).
    pub conditions: &'a Conditions,
    /// `STATEV(1..NSTATV)` at the start of the increment.
    pub statev: &'a [f64],
}

/// A point's answer, or the law's refusal with its cause.
pub type PointResult<const N: usize> = Result<PointAnswer<N>, LawError>;

/// A law's end state as `STATEV` holds it.
pub trait EndState {
    /// How many `STATEV` entries it writes (at most [`MAX_POINT_STATEV`]).
    fn statev_len(&self) -> usize;
    /// Writes them into `statev(1..)`.
    fn write_statev(&self, statev: &mut [f64]);
}

impl<S: StatusCode> EndState for PointState<S> {
    fn statev_len(&self) -> usize {
        Self::NSTATV
    }

    fn write_statev(&self, statev: &mut [f64]) {
        PointState::write_statev(self, statev);
    }
}

/// What a law reads at a point besides the increment: `fric_` reads exactly these into the
/// [`Conditions`] it passes (the rest keep their defaults), and `fric_coef_` asks for the
/// temperature block only when the law reads it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Needs {
    /// θ̄ = (`TEMP(1)` + `TEMP(2)`)/2.
    pub temperature: bool,
    /// `DROT`, the rotation of the tangent directions (in 3-D).
    pub rotation: bool,
    /// `COORDS(1..MCRD)`, the point's coordinates.
    pub coordinates: bool,
}

/// A friction law as the entry points run it at one point. Implemented by each law (in its own
/// file) and by the law enum `props::FrictionLaw`, which dispatches statically to its variant.
pub trait PointLaw {
    /// The law as messages name it ("the rate-and-state law").
    fn name(&self) -> &'static str;

    /// `STATEV` entries the law reads and writes with `NFDIR` = `nfdir` (at most
    /// [`MAX_POINT_STATEV`]); the default is the three scalars of a [`PointState`]
    /// (accumulated slip, slip rate, status) that most laws keep.
    fn nstatv(&self, _nfdir: usize) -> usize {
        PointState::<FrictionStatus>::NSTATV
    }

    /// Whether the law answers exact stick (`LM = 1`); when not (the default), an `LM = 1` on
    /// entry reads as 0 and the answer is always `LM = 0`.
    fn exact_stick(&self) -> bool {
        false
    }

    /// What the law reads besides the increment with `NFDIR` = `nfdir` (the default: nothing).
    fn needs(&self, _nfdir: usize) -> Needs {
        Needs::default()
    }

    /// One increment at the point `at`.
    fn update_point<const N: usize>(&self, at: &PointInput<'_, N>) -> PointResult<N>;

    /// `FRIC_COEF`'s answer at one point: `[μ, ∂μ/∂γ̇_eq, ∂μ/∂p, ∂μ/∂θ̄]`, each for the two
    /// directions, at slip rate `rate` ≥ 0, pressure `pressure` ≥ 0 and temperature
    /// `temperature`. `None` (the default): μ of the law is not a function of rate, pressure and
    /// temperature alone (adhesion, a state variable; `FRIC_COEF` has no `STATEV`), and
    /// `fric_coef_` refuses it by name.
    fn coefficients(&self, _rate: f64, _pressure: f64, _temperature: f64) -> Option<[[f64; 2]; 4]> {
        None
    }
}

/// Work to do with whichever law an enum of laws holds, as that law's own type: the enum's
/// `run_with` matches once and calls [`PointLawTask::run`] with the variant, so the work is
/// compiled once per law (static dispatch; `fric_`'s checked path is one such task). For work
/// that is not on a hot path, the enum implements [`PointLaw`] itself.
pub trait PointLawTask {
    /// What the work gives back.
    type Output;

    /// The work, with the law.
    fn run<L: PointLaw>(self, law: &L) -> Self::Output;
}
