//! # interfacial
//!
//! Contact-interface laws for finite-element codes: a safe Rust core (the laws) behind a thin
//! shell of Abaqus-compatible, Fortran-callable entry points (`fric_`, …) and a native C API
//! (`ifl_*`).
//!
//! The physics follows the source documents in `shared/seeds/` (section 5.2.3 "Coulomb
//! friction" for [`laws::coulomb`]). Each law lives in one file under [`laws`]; the entry points
//! live in `abi`, the only module allowed to use `unsafe`.
//!
//! ```
//! use interfacial::laws::coulomb::{Coulomb, CoulombState, Increment, Contact};
//!
//! // μ = 0.3, allowable elastic slip γ_crit = 1e-3 (elastic stick, Abaqus's default).
//! let law = Coulomb::new(0.3)?.with_critical_slip_absolute(1e-3)?;
//! // First contact at p = 100: the increment starts at p − Δp = 0 with no stress.
//! let inc = Increment::<1> { dgam: [5e-4], pressure: 100.0, dpressure: 100.0, ..Increment::default() };
//! let up = law.update(&inc, &CoulombState::default())?;
//! match up.contact {
//!     // k_s = μp/γ_crit = 3e4, so τ = k_s·Δγ = 15 (still sticking: 15 < μp = 30).
//!     Contact::Motion(t) => assert!((t.tau[0] - 15.0).abs() < 1e-12),
//!     Contact::ExactStick => unreachable!(),
//! }
//! # Ok::<(), interfacial::LawError>(())
//! ```
#![deny(unsafe_code)]
#![warn(missing_docs)]

#[allow(unsafe_code)]
pub mod abi;
pub mod config;
pub mod laws;
mod outcome;
pub mod props;
mod report;

pub use outcome::{CUTBACK_RATIO, LawError, Outcome, Reliability};

/// The library version, as `ifl_version` reports it.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

#[cfg(test)]
pub(crate) mod testing {
    //! Test-only hook that makes the core panic, to prove that the ABI boundary turns a panic
    //! into a cut-back. Compiled only in `cargo test` builds of this crate.
    use std::cell::Cell;
    thread_local! {
        static FORCE_PANIC: Cell<bool> = const { Cell::new(false) };
        static FORCED_PANICS: Cell<u32> = const { Cell::new(0) };
    }
    pub(crate) fn force_panic(on: bool) {
        FORCE_PANIC.with(|f| f.set(on));
    }
    /// How many forced panics this thread has raised so far.
    pub(crate) fn forced_panics() -> u32 {
        FORCED_PANICS.get()
    }
    pub(crate) fn maybe_panic() {
        if FORCE_PANIC.with(|f| f.get()) {
            FORCED_PANICS.set(FORCED_PANICS.get() + 1);
            panic!("forced panic (test hook)");
        }
    }
}
