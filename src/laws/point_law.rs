//! The interface `fric_` asks of a friction law for one contact point: what the law needs
//! (`NSTATV` per `NFDIR`, whether it answers exact stick), and one update from an increment and
//! the start state in `STATEV` to an answer (traction and tangents, `DDTDDT`, the end state,
//! a step ratio) or a refusal with its cause. The shell reads the host's arguments into an
//! [`Increment`], calls [`PointLaw::update_point`] through the law enum (static dispatch, no
//! `dyn`), and writes the answer; it knows no law. docs/architecture.md, "Adding a law", says
//! which laws are behind it and which still have their own arm in `fric_`.

use super::contact::{Contact, Increment};
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
        let mut all = [0.0; MAX_POINT_STATEV];
        all[..statev.len()].copy_from_slice(statev);
        PointAnswer {
            contact,
            statev: all,
            statev_len: statev.len(),
            dtau_dtheta: [0.0; N],
            step_ratio,
        }
    }
}

/// A friction law as `fric_` runs it at one point.
pub trait PointLaw {
    /// The law as messages name it ("the rate-and-state law").
    const NAME: &'static str;

    /// `STATEV` entries the law reads and writes with `NFDIR` = `nfdir` (at most
    /// [`MAX_POINT_STATEV`]).
    fn nstatv(&self, nfdir: usize) -> usize;

    /// Whether the law answers exact stick (`LM = 1`); when not (the default), an `LM = 1` on
    /// entry reads as 0 and the answer is always `LM = 0`.
    fn exact_stick(&self) -> bool {
        false
    }

    /// One increment: `statev` holds at least [`Self::nstatv`] entries (the start state).
    fn update_point<const N: usize>(
        &self,
        inc: &Increment<N>,
        statev: &[f64],
    ) -> Result<PointAnswer<N>, LawError>;
}
