//! `ifl_forced_sliding`: forced sliding in static analysis (seed 003) through the native API —
//! the frictional stress for a prescribed slip velocity and the stiffness/damping split of its
//! linearization used by complex eigenvalue extraction.

use std::ffi::c_int;

use super::native::IflStatus;
use super::{boundary, read_array, slice, write_array, write_matrix};
use crate::LawError;
use crate::laws::coulomb_extended::ExtendedCoulomb;
use crate::props::{FrictionLaw, friction_law};
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
    let run = || -> Result<(), LawError> {
        if tau.is_null() || damping.is_null() || stiffness.is_null() {
            return Err(LawError::Input("an output pointer is NULL".into()));
        }
        let Ok(nprops) = usize::try_from(nprops) else {
            return Err(LawError::Parameter(format!(
                "nprops = {nprops} is negative"
            )));
        };
        // SAFETY: `props` holds `nprops` reals by contract.
        let law = match friction_law(unsafe { slice(props, nprops, "props") }?)? {
            FrictionLaw::Coulomb(base) => ExtendedCoulomb::new(base),
            FrictionLaw::CoulombExtended(law) => law,
            FrictionLaw::Adhesive(_) => {
                return Err(LawError::Parameter(
                    "PROPS(1) = 2 (adhesive): only law 1 (Coulomb) is provided here".into(),
                ));
            }
        };
        // SAFETY (both arms): arrays of nfdir and nfdir² entries by contract.
        unsafe {
            match nfdir {
                1 => {
                    let v = read_array::<1>(velocity, "velocity")?;
                    let f = law.forced_sliding(&v, pressure, temperature)?;
                    write_array(tau, &f.tau);
                    write_matrix(damping, &f.damping);
                    write_array(stiffness, &f.stiffness_pressure);
                }
                2 => {
                    let v = read_array::<2>(velocity, "velocity")?;
                    let f = law.forced_sliding(&v, pressure, temperature)?;
                    write_array(tau, &f.tau);
                    write_matrix(damping, &f.damping);
                    write_array(stiffness, &f.stiffness_pressure);
                }
                other => {
                    return Err(LawError::Parameter(format!(
                        "nfdir = {other}; expected 1 or 2"
                    )));
                }
            }
        }
        Ok(())
    };
    let on_fault = || {
        // SAFETY: as above; only for a valid nfdir.
        unsafe {
            match nfdir {
                1 => {
                    write_array::<1>(tau, &[0.0]);
                    write_matrix::<1>(damping, &[[0.0]]);
                    write_array::<1>(stiffness, &[0.0]);
                }
                2 => {
                    write_array::<2>(tau, &[0.0; 2]);
                    write_matrix::<2>(damping, &[[0.0; 2]; 2]);
                    write_array::<2>(stiffness, &[0.0; 2]);
                }
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
