//! The `fric_` body of the adhesive friction law (`PROPS(1) = 2`) outside its Coulomb special
//! case: elastic stick only, so the answer is always `LM = 0`.

use super::super::{read, read_array, slice, write, write_array, write_matrix, write_zeros};
use super::{FricArgs, bad_nfdir, short_nstatv};
use crate::LawError;
use crate::laws::adhesive::Adhesive;
use crate::laws::coulomb::{Contact, CoulombState, Increment};

impl FricArgs {
    /// Checks NSTATV and NFDIR, then runs the NFDIR-specific code. `LM = 1` on entry (a host
    /// that starts the increment "sticking") reads as `LM = 0`: the law has no exact stick.
    pub(super) unsafe fn adhesive(&self, law: &Adhesive) -> Result<(), LawError> {
        // SAFETY: pointers valid per the FRIC contract; sizes checked before use.
        unsafe {
            let nstatv = read(self.nstatv, "NSTATV")?;
            let nstatv = match usize::try_from(nstatv) {
                Ok(n) if n >= CoulombState::NSTATV => n,
                _ => return Err(short_nstatv(nstatv)),
            };
            match read(self.nfdir, "NFDIR")? {
                1 => self.adhesive_point::<1>(law, nstatv),
                2 => self.adhesive_point::<2>(law, nstatv),
                other => Err(bad_nfdir(other)),
            }
        }
    }

    /// One point; everything is computed before the first output is written.
    unsafe fn adhesive_point<const N: usize>(
        &self,
        law: &Adhesive,
        nstatv: usize,
    ) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of N, N·N and NSTATV entries per the FRIC contract.
        unsafe {
            let inc = Increment::<N> {
                tau: read_array(self.tau, "TAU")?,
                dgam: read_array(self.dgam, "DGAM")?,
                pressure: read(self.press, "PRESS")?,
                dpressure: read(self.dpress, "DPRESS")?,
                dtime: read(self.dtime, "DTIME")?,
                characteristic_length: read(self.chrlngth, "CHRLNGTH")?,
                ..Increment::default()
            };
            let state = CoulombState::from_statev(slice(self.statev, nstatv, "STATEV")?)?;
            let up = law.update(&inc, &state)?;
            let Contact::Motion(t) = up.contact else {
                return Err(LawError::Numerical(
                    "the adhesive law answered exact stick (a bug; please report it)".into(),
                ));
            };
            let mut end_state = [0.0; CoulombState::NSTATV];
            up.state.write_statev(&mut end_state);
            write_array(self.statev, &end_state);
            write(self.lm, 0);
            write_array(self.tau, &t.tau);
            write_matrix(self.ddtddg, &t.ddtddg);
            write_array(self.ddtddp, &t.ddtddp);
            write_array(self.dslip, &t.dslip);
            write(self.sed, t.sed);
            write(self.sfd, t.sfd);
            // DDTDDT(NFDIR,2): the law does not depend on temperature.
            write_zeros(self.ddtddt, 2 * N);
            Ok(())
        }
    }
}
