//! The rate law's fast path in `fric_` (issue 4): the exponential-decay law in its lean layout
//! ([`extended_decay_lean`]: isotropic, elastic stick, no HHT, damping or steady transport),
//! taken by `fric_general` before the checked path. Like the plain law's `plain_fast`, it
//! tests every pointer and size with a few branches, never builds an error and writes nothing
//! unless it succeeds; anything else (`LM = 1` on entry, another layout, a NULL, a bad input, a
//! failed local solve) returns `false` and the checked path starts afresh, names the problem and
//! lowers `PNEWDT`. The law's arithmetic is `ExtendedCoulomb::update`'s own lean path, so both
//! paths give the same numbers (`tests/friction_extended.rs`,
//! `fric_decay_fast_path_agrees_with_the_checked_path`, compares them).

use std::ffi::c_int;

use super::{FricArgs, get, scale_half};
use crate::laws::coulomb::{CoulombState, EntryFlag, Increment};
use crate::laws::coulomb_extended::{ExtendedCoulomb, ExtendedState};
use crate::props::{COULOMB_EXTENDED_NPROPS, extended_decay_lean};

impl FricArgs {
    /// `true` when the call is done (the outputs written), `false` with nothing written.
    ///
    /// # Safety
    /// As `fric_`.
    #[inline(always)]
    pub(super) unsafe fn decay_fast(&self) -> bool {
        // SAFETY (whole body): every pointer is tested for NULL before it is read; PROPS is
        // read as 20 entries only when NPROPS = 20.
        unsafe {
            // (LM = 2 never comes here: `plain_fast` answers it.)
            if get(self.lm) != Some(0)
                || get(self.nprops) != Some(COULOMB_EXTENDED_NPROPS as c_int)
                || self.props.is_null()
            {
                return false;
            }
            let props = &*self.props.cast::<[f64; COULOMB_EXTENDED_NPROPS]>();
            let Some(law) = extended_decay_lean(props) else {
                return false;
            };
            match get(self.nstatv) {
                Some(n) if n >= CoulombState::NSTATV as c_int => {}
                _ => return false,
            }
            match get(self.nfdir) {
                Some(1) => self.decay_point::<1>(&law),
                Some(2) => self.decay_point::<2>(&law),
                _ => false,
            }
        }
    }

    /// One point with N = NFDIR friction directions: the reads of `point_extended` for this
    /// layout (no TAULM with `LM = 0`, TEMP only when μ depends on it, no DROT or COORDS), the
    /// law's lean update, the writes of `point_extended`.
    ///
    /// # Safety
    /// As `fric_`, with `NSTATV ≥ 3` checked.
    #[inline(always)]
    unsafe fn decay_point<const N: usize>(&self, law: &ExtendedCoulomb) -> bool {
        // SAFETY (whole body): each pointer is tested for NULL before it is read; arrays of N,
        // N·N, 2N, 2 (TEMP) and NSTATV ≥ 3 entries per the FRIC contract.
        unsafe {
            let Some(pressure) = get(self.press) else {
                return false;
            };
            let Some(dpressure) = get(self.dpress) else {
                return false;
            };
            let Some(tau) = get(self.tau.cast::<[f64; N]>()) else {
                return false;
            };
            let Some(dgam) = get(self.dgam.cast::<[f64; N]>()) else {
                return false;
            };
            let Some(dtime) = get(self.dtime) else {
                return false;
            };
            let Some(characteristic_length) = get(self.chrlngth) else {
                return false;
            };
            let theta = if law.reads_temperature() {
                let Some([t1, t2]) = get(self.temp.cast::<[f64; 2]>()) else {
                    return false;
                };
                0.5 * (t1 + t2)
            } else {
                0.0
            };
            let Some([s, rate, status]) = get(self.statev.cast::<[f64; 3]>()) else {
                return false;
            };
            let Some(coulomb) = CoulombState::from_values(s, rate, status) else {
                return false;
            };
            let inc = Increment::<N> {
                tau,
                dgam,
                taulm: [0.0; N],
                pressure,
                dpressure,
                dtime,
                characteristic_length,
                entry: EntryFlag::Motion,
            };
            let state = ExtendedState::<N> {
                coulomb,
                viscous: [0.0; N],
            };
            // (Always `Some` for the laws of `extended_decay_lean`.) An error is named by the
            // checked path, which meets it again.
            let Some(decay) = law.lean_decay::<N>() else {
                return false;
            };
            let Ok(up) = law.isotropic_decay(&inc, theta, &state, decay) else {
                return false;
            };
            // DDTDDT(a,1) and DDTDDT(a,2): each surface temperature carries half of ∂τ/∂θ̄.
            self.outputs()
                .write_answer(&up.contact, &up.state.coulomb, &scale_half(&up.ddtdtheta));
            // (The lean path always converges with no opinion on the step: PNEWDT is left
            // alone, as `point_extended` leaves it.)
            debug_assert!(!up.outcome.step_ratio.is_finite());
            true
        }
    }
}
