//! The interface `fric_` asks of a friction law for one contact point: what the law needs
//! (`NSTATV` per `NFDIR`, whether it answers exact stick), and one update from an increment and
//! the start state in `STATEV` to an answer (traction and tangents, `DDTDDT`, the end state,
//! a step ratio) or a refusal with its cause, and `FRIC_COEF`'s μ where the law has one. The
//! shell reads the host's arguments into an [`Increment`] and the [`Conditions`] the law
//! [`Needs`], calls [`PointLaw::update_point`] through the law enum (static dispatch, no
//! `dyn`), and writes the answer; it knows no law. docs/architecture.md, "Adding a law".

use super::contact::{Conditions, Contact, Increment};
use crate::LawError;

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
    /// The answer of a law that does not depend on temperature: `statev` is the end state's
    /// `STATEV` (at most [`MAX_POINT_STATEV`] entries, a law's own constant).
    #[must_use]
    pub fn isothermal(contact: Contact<N>, statev: &[f64], step_ratio: f64) -> Self {
        Self::new(contact, statev, [0.0; N], step_ratio)
    }

    /// The answer with ∂τ/∂θ̄ = `dtau_dtheta`; `statev` as in [`Self::isothermal`].
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
    /// [`MAX_POINT_STATEV`]).
    fn nstatv(&self, nfdir: usize) -> usize;

    /// Whether the law answers exact stick (`LM = 1`); when not (the default), an `LM = 1` on
    /// entry reads as 0 and the answer is always `LM = 0`.
    fn exact_stick(&self) -> bool {
        false
    }

    /// What the law reads besides the increment with `NFDIR` = `nfdir` (the default: nothing).
    fn needs(&self, _nfdir: usize) -> Needs {
        Needs::default()
    }

    /// One increment: `statev` holds at least [`Self::nstatv`] entries (the start state);
    /// `conditions` holds what [`Self::needs`] asked for.
    fn update_point<const N: usize>(
        &self,
        inc: &Increment<N>,
        conditions: &Conditions,
        statev: &[f64],
    ) -> Result<PointAnswer<N>, LawError>;

    /// `FRIC_COEF`'s answer at one point: `[μ, ∂μ/∂γ̇_eq, ∂μ/∂p, ∂μ/∂θ̄]`, each for the two
    /// directions, at slip rate `rate` ≥ 0, pressure `pressure` ≥ 0 and temperature
    /// `temperature`. `None` (the default): μ of the law is not a function of rate, pressure and
    /// temperature alone (adhesion, a state variable; `FRIC_COEF` has no `STATEV`), and
    /// `fric_coef_` refuses it by name.
    fn coefficients(&self, _rate: f64, _pressure: f64, _temperature: f64) -> Option<[[f64; 2]; 4]> {
        None
    }
}
