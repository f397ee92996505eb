//! The rate law's fast path in `fric_` (issue 4): the exponential-decay law in its lean layout
//! ([`fast_decay_lean`]: isotropic, elastic stick, no HHT, damping or steady transport),
//! taken by `FricArgs::general` before the checked path. Like the plain law's `plain_fast`, it
//! tests every pointer and size with a few branches, never builds an error and writes nothing
//! unless it succeeds; anything else (`LM = 1` on entry, another layout, a NULL, a bad input, a
//! failed local solve) returns `false` and the checked path starts afresh, names the problem and
//! lowers `PNEWDT`. The law's arithmetic is `ExtendedCoulomb::update`'s own lean path, so both
//! paths give the same numbers (`fric_decay_fast_path_agrees_with_the_careful_path` in
//! src/props.rs compares them bit for bit on the same arguments).

use std::ffi::c_int;

use super::{FricArgs, get};
use crate::laws::contact::EntryFlag;
use crate::laws::contact::mean_surface_temperature;
use crate::laws::coulomb::CoulombState;
use crate::laws::coulomb_extended::{ExtendedCoulomb, ExtendedState};
use crate::props::{COULOMB_EXTENDED_NPROPS, fast_decay_lean};

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
            let Some(law) = fast_decay_lean(props) else {
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

    /// One point with N = NFDIR friction directions: the increment by the shell's one reader
    /// (quietly), TEMP only when μ depends on it (this layout has no damping or steady
    /// transport: no DROT or COORDS, and `STATEV(1..3)` only), the law's lean update, the
    /// shell's one writer.
    ///
    /// # Safety
    /// As `fric_`, with `NSTATV ≥ 3` checked.
    #[inline(always)]
    unsafe fn decay_point<const N: usize>(&self, law: &ExtendedCoulomb) -> bool {
        // SAFETY (whole body): each pointer is tested for NULL before it is read; arrays of N,
        // N·N, 2N, 2 (TEMP) and NSTATV ≥ 3 entries per the FRIC contract.
        unsafe {
            let Ok(inc) = self.increment::<N, ()>(EntryFlag::Motion) else {
                return false;
            };
            let theta = if law.reads_temperature() {
                let Some(temp) = get(self.temp.cast::<[f64; 2]>()) else {
                    return false;
                };
                mean_surface_temperature(temp)
            } else {
                0.0
            };
            let Some([s, rate, status]) = get(self.statev.cast::<[f64; 3]>()) else {
                return false;
            };
            let Some(coulomb) = CoulombState::from_values(s, rate, status) else {
                return false;
            };
            let state = ExtendedState::<N> {
                coulomb,
                viscous: [0.0; N],
            };
            // (Always `Some` for the laws of `fast_decay_lean`.) An error is named by the
            // checked path, which meets it again.
            let Some(decay) = law.lean_decay::<N>() else {
                return false;
            };
            let Ok(up) = law.isotropic_decay(&inc, theta, &state, decay) else {
                return false;
            };
            let mut end = [0.0; CoulombState::NSTATV];
            up.state.coulomb.write_statev(&mut end);
            self.write_answer(&up.contact, &end, &up.ddtddt_column());
            // (The lean path always converges with no opinion on the step: PNEWDT is left
            // alone, as the checked path leaves it.)
            debug_assert!(!up.outcome.step_ratio.is_finite());
            true
        }
    }
}
