//! # interfacial
//!
//! Contact-interface laws for finite-element codes: a safe Rust core (the laws) behind a thin
//! shell of Abaqus-compatible, Fortran-callable entry points (`fric_`, …) and a native C API
//! (`ifl_*`).
//!
//! The physics follows the source documents restated in `docs/source-model.md` (seed 000,
//! section 5.2.3 "Coulomb friction" for [`laws::coulomb`]). Each law lives in one file under
//! [`laws`]; the entry points live in `abi`, the only module allowed to use `unsafe`.
//!
//! ```
//! use interfacial::laws::contact::{Increment, Contact};
//! use interfacial::laws::coulomb::{Coulomb, CoulombState};
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

pub(crate) mod switch {
    //! The paths a unit test may force on its own thread, to compare a fast path with the one
    //! it stands in for on the same arguments: [`Path::Baseline`] (the batch's chunk loop in its
    //! baseline build, `abi::batch`) and [`Path::Careful`] (every fast `PROPS` reader declines,
    //! `props`). Outside `cargo test` of this crate no switch exists and [`forced`] is the
    //! constant `false`, so the fast paths compile as if it were not there.

    /// A path a test can force.
    #[derive(Clone, Copy, Debug)]
    pub(crate) enum Path {
        /// The baseline (SSE2) build of the batch's chunk loop, even on an AVX2 processor.
        Baseline = 1,
        /// The careful (checked) `PROPS` readers: the fast readers decline.
        Careful = 2,
    }

    #[cfg(test)]
    thread_local! {
        /// The forced paths of this thread, one bit per [`Path`].
        static FORCED: std::cell::Cell<u8> = const { std::cell::Cell::new(0) };
    }

    /// Whether this thread's tests force `path` (always `false` outside `cargo test`).
    #[inline(always)]
    pub(crate) fn forced(path: Path) -> bool {
        #[cfg(test)]
        {
            FORCED.get() & path as u8 != 0
        }
        #[cfg(not(test))]
        {
            let _ = path;
            false
        }
    }

    /// Unit tests only: force `path` on this thread while `on`.
    #[cfg(test)]
    pub(crate) fn force(path: Path, on: bool) {
        let bits = FORCED.get();
        FORCED.set(if on {
            bits | path as u8
        } else {
            bits & !(path as u8)
        });
    }
}

/// The library version, as `ifl_version` reports it.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

#[cfg(test)]
pub(crate) mod testing {
    //! Unit-test helpers, compiled only in `cargo test` builds of this crate: the hook that
    //! makes the core panic (to prove that the ABI boundary turns a panic into a cut-back), the
    //! tests' random stream and the f64 edge values.
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

    /// Marsaglia's xorshift64 generator (shifts 13, 7, 17): the unit tests' reproducible
    /// stream of numbers. Any seed but 0.
    pub(crate) struct XorShift(pub(crate) u64);

    impl XorShift {
        /// The next 64 bits.
        pub(crate) fn bits(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }

        /// The next number in [0, 1), from the top 53 bits.
        pub(crate) fn unit(&mut self) -> f64 {
            (self.bits() >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// The edges of f64 a comparison or a bit trick on signs and exponents must get right:
    /// both zeros, the smallest subnormals and normal, ±1, ±f64::MAX, ±∞ and NaNs of both signs
    /// (a quiet one and a signalling one).
    pub(crate) const EDGE_VALUES: [f64; 14] = [
        0.0,
        -0.0,
        5e-324,
        -5e-324,
        f64::MIN_POSITIVE,
        1.0,
        -1.0,
        f64::MAX,
        f64::MIN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        -f64::NAN,
        f64::from_bits(0x7FF0_0000_0000_0001),
    ];
}
