//! The result of one integration of a law: how reliable it is and what time-step ratio it
//! suggests (MFront/MGIS style), and the error type of the core.

use std::fmt;

/// Time-step ratio requested on a failed call (`PNEWDT` through the Abaqus entry points).
/// Abaqus abandons the increment and retries it with `PNEWDT · Δt`.
pub const CUTBACK_RATIO: f64 = 0.25;

/// How far the caller can trust a successful update.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reliability {
    /// The update solved the law's equations to round-off.
    Converged,
    /// The update is usable but was obtained on a fallback path (for example a local solve that
    /// stopped at its iteration limit); the step ratio says how much to shrink the step.
    Unreliable,
}

/// Reliability and suggested time-step ratio of a successful update. A law may only lower the
/// ratio; `f64::INFINITY` means "no opinion", so a good call never lowers `PNEWDT`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// How far the result can be trusted.
    pub reliability: Reliability,
    /// Suggested ratio of the next to the current time increment (`PNEWDT`).
    pub step_ratio: f64,
}

impl Outcome {
    /// A converged update with no opinion on the step size.
    pub const CONVERGED: Outcome = Outcome {
        reliability: Reliability::Converged,
        step_ratio: f64::INFINITY,
    };
}

/// Why a law refused to integrate an increment. The entry points map every variant to a
/// cut-back (`PNEWDT = CUTBACK_RATIO`) with the state left at the start of the increment.
#[derive(Clone, Debug, PartialEq)]
pub enum LawError {
    /// A parameter is out of its documented range (reported at construction).
    Parameter(String),
    /// The configuration file is missing or invalid: one cause for the whole run, reported once
    /// whatever the interaction (the message names the file, line and key).
    Config(String),
    /// An input of this increment is unusable (NaN, infinite, inconsistent).
    Input(String),
    /// The computation produced a non-finite result or a local solve failed.
    Numerical(String),
}

impl fmt::Display for LawError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LawError::Parameter(m) | LawError::Config(m) => write!(f, "bad parameter: {m}"),
            LawError::Input(m) => write!(f, "bad input: {m}"),
            LawError::Numerical(m) => write!(f, "numerical failure: {m}"),
        }
    }
}

impl std::error::Error for LawError {}

impl LawError {
    /// The same error with `what` (the input that led to it) before its text.
    #[must_use]
    pub fn said_of(self, what: &str) -> Self {
        match self {
            LawError::Parameter(m) => LawError::Parameter(format!("{what}: {m}")),
            LawError::Config(m) => LawError::Config(format!("{what}: {m}")),
            LawError::Input(m) => LawError::Input(format!("{what}: {m}")),
            LawError::Numerical(m) => LawError::Numerical(format!("{what}: {m}")),
        }
    }
}
