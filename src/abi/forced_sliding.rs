//! `ifl_forced_sliding`: forced sliding in static analysis (seed 003) through the native API —
//! the frictional stress for a prescribed slip velocity and the stiffness/damping split of its
//! linearization used by complex eigenvalue extraction.

use std::ffi::c_int;

use super::native::IflStatus;
use super::{boundary, count, read_array, slice, write_array, write_matrix};
use crate::LawError;
use crate::laws::coulomb_extended::ExtendedCoulomb;
use crate::props::friction_law;
use crate::report::Site;

/// Forced sliding for the law-1 `PROPS` of `fric_` (docs/props.md; μ₁, μ₂, the μ laws, τ_max):
/// given the prescribed tangential slip velocity `velocity[nfdir]` (in the friction directions),
/// the contact pressure and the mean surface temperature, writes
/// - `tau[nfdir]`: τ = τ_crit(|v|, p, θ̄)·v/|v| (scaled as Eq. 5.2.3-10/11 when anisotropic);
/// - `damping[nfdir*nfdir]` (column-major, `(a,b)` at `a + b*nfdir`): ∂τ_a/∂v_b, the
///   τ_crit/|v|·(δ − nn) term of the friction forces perpendicular to the slip plus the
///   nn·∂τ_crit/∂γ̇ term of a rate-dependent μ — both feed the damping matrix;
/// - `stiffness[nfdir]`: ∂τ_a/∂p = n_a·∂τ_crit/∂p, the part that feeds the stiffness matrix.
///
/// A zero velocity gives zeros. Returns `IflStatus::Ok`, or an error status with the message in
/// `ifl_last_error` (outputs then zero when `nfdir` is 1 or 2).
///
/// # Safety
/// `props` holds `nprops` reals; `velocity`, `tau`, `stiffness` hold `nfdir` reals and
/// `damping` `nfdir²` (outputs may not be NULL).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ifl_forced_sliding(
    props: *const f64,
    nprops: c_int,
    nfdir: c_int,
    velocity: *const f64,
    pressure: f64,
    temperature: f64,
    tau: *mut f64,
    damping: *mut f64,
    stiffness: *mut f64,
) -> IflStatus {
    let out = Outputs {
        tau,
        damping,
        stiffness,
    };
    let run = || -> Result<(), LawError> {
        if tau.is_null() || damping.is_null() || stiffness.is_null() {
            return Err(LawError::Input("an output pointer is NULL".into()));
        }
        let nprops = count("nprops", nprops)?;
        // SAFETY: `props` holds `nprops` reals by contract.
        let law = friction_law(unsafe { slice(props, nprops, "props") }?)?
            .into_coulomb_extended("only law 1 (Coulomb) is provided here")?;
        // SAFETY (both arms): arrays of nfdir and nfdir² entries by contract.
        unsafe {
            match nfdir {
                1 => out.slide::<1>(&law, velocity, pressure, temperature),
                2 => out.slide::<2>(&law, velocity, pressure, temperature),
                other => Err(LawError::Parameter(format!(
                    "nfdir = {other}; expected 1 or 2"
                ))),
            }
        }
    };
    let on_fault = || {
        // SAFETY: as above; only for a valid nfdir.
        unsafe {
            match nfdir {
                1 => out.write::<1>(&[0.0], &[[0.0]], &[0.0]),
                2 => out.write::<2>(&[0.0; 2], &[[0.0; 2]; 2], &[0.0; 2]),
                _ => {}
            }
        }
    };
    boundary(
        || Site {
            routine: "ifl_forced_sliding",
            interaction: String::new(),
            place: String::new(),
        },
        run,
        on_fault,
    )
    .into()
}

/// The outputs of [`ifl_forced_sliding`].
struct Outputs {
    tau: *mut f64,
    damping: *mut f64,
    stiffness: *mut f64,
}

impl Outputs {
    /// Forced sliding with N = `nfdir` directions: reads `velocity[N]`, writes the answer.
    ///
    /// # Safety
    /// As [`ifl_forced_sliding`], N = `nfdir`.
    unsafe fn slide<const N: usize>(
        &self,
        law: &ExtendedCoulomb,
        velocity: *const f64,
        pressure: f64,
        temperature: f64,
    ) -> Result<(), LawError> {
        // SAFETY: `velocity` holds N reals by contract; the outputs as `write`.
        unsafe {
            let v = read_array::<N>(velocity, "velocity")?;
            let f = law.forced_sliding(&v, pressure, temperature)?;
            self.write(&f.tau, &f.damping, &f.stiffness_pressure);
        }
        Ok(())
    }

    /// The one writer: `tau[N]`, `damping[N·N]` (column-major), `stiffness[N]`; NULL skipped.
    ///
    /// # Safety
    /// Each pointer is NULL or holds N, N·N and N writable reals.
    unsafe fn write<const N: usize>(
        &self,
        tau: &[f64; N],
        damping: &[[f64; N]; N],
        stiffness: &[f64; N],
    ) {
        // SAFETY: as documented.
        unsafe {
            write_array(self.tau, tau);
            write_matrix(self.damping, damping);
            write_array(self.stiffness, stiffness);
        }
    }
}
