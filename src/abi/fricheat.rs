//! `fricheat_`: CalculiX's user routine for frictional heating (`*GAP HEAT GENERATION, USER`),
//! in the CalculiX variant of the library only (`--features calculix`), as its `gapcon_`.

use std::ffi::{c_char, c_int};

use super::{boundary, fortran_name_bytes, host_number, host_site, write};
use crate::LawError;
use crate::config;
use crate::laws::frictional_heat::SlidingSpeed;
use crate::report::Site;

/// `ET` (η) written when a call fails: no heat. The failure is always reported (once per cause),
/// never a silent default; `INTERFACIAL_STRICT=1` aborts instead.
pub const FRICHEAT_SAFE_FRACTION: f64 = 0.0;

/// `F` written when a call fails (nothing to share: η is 0).
pub const FRICHEAT_SAFE_SHARE: f64 = 0.0;

/// `VNORM` written when a call fails: 0, neither a speed (> 0) nor CalculiX's request to compute
/// one (< −0.5), so CalculiX adds no heat at the point.
pub const FRICHEAT_SAFE_SPEED: f64 = 0.0;

/// `VNORM` for "the relative velocity from the nodal velocities": CalculiX computes it when the
/// routine returns a value below −0.5.
pub const FRICHEAT_HOST_SPEED: f64 = -1.0;

/// CalculiX 2.20's `fricheat`: η (`ET`), the slave's share `F` and the sliding speed `VNORM` of
/// one face-to-face contact point, from `[interactions.CINAME.heat]` of the configuration file
/// named by `INTERFACIAL_CONFIG` (docs/config.md): `ET = fraction`, `F = slave_share` (or
/// e_s/(e_s + e_m) from the effusivities), `VNORM = speed`, or −1 without `speed` (CalculiX then
/// takes the relative velocity of the surfaces from its nodal velocities: in a `STEADY STATE`
/// step each converged increment's mean velocity, so an increment uses the one before).
/// CalculiX forms the fluxes F·ET·VNORM·UM·PRESSURE into the slave face and
/// (1 − F)·ET·VNORM·UM·PRESSURE into the master face; with `*FRICTION, USER` the host's edit of
/// `frictionheating.f` makes `UM·PRESSURE` the friction stress |τ| of the library's FRIC
/// (docs/calculix.md).
///
/// Reads `CINAME` (matched as for GAPCON) and, in messages only, `NOEL`; never reads `TIME`,
/// `NELEMS`, `JFACES`, `NELEMM`, `JFACEM`, `UM`, `KSTEP`, `KINC`, `AREA`, `PRESSURE`, `COORDS`.
/// Writes `ET`, `F` and `VNORM` only.
///
/// On failure (no or bad configuration file, interaction without a `heat` table and no `"*"`
/// entry, a NULL output, internal panic): `ET = F = VNORM = 0` (no heat at the point) and one
/// message per distinct cause naming FRICHEAT, the interaction and the contact element (stderr
/// or `$INTERFACIAL_LOG`; `ifl_last_error` on the calling thread).
///
/// # Safety
/// Pointers valid for CalculiX's signature: `ET`, `F`, `VNORM` writable doubles, `CINAME` of
/// the hidden length `ciname_len`, `NOEL` an integer or NULL. The unread arguments may be
/// anything.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fricheat_(
    et: *mut f64,
    f: *mut f64,
    vnorm: *mut f64,
    time: *const f64,
    ciname: *const c_char,
    noel: *const c_int,
    nelems: *const c_int,
    jfaces: *const c_int,
    nelemm: *const c_int,
    jfacem: *const c_int,
    um: *const f64,
    kstep: *const c_int,
    kinc: *const c_int,
    area: *const f64,
    pressure: *const f64,
    coords: *const f64,
    ciname_len: usize,
) {
    let _ = (
        time, nelems, jfaces, nelemm, jfacem, um, kstep, kinc, area, pressure, coords,
    );
    let _ = boundary(
        // SAFETY: CINAME has the hidden length the host passed; NOEL may be NULL.
        || unsafe { site(ciname, ciname_len, noel) },
        // SAFETY: ET, F, VNORM writable per the contract; CINAME readable for its length.
        || unsafe {
            let law = config::frictional_heat_for(fortran_name_bytes(ciname, ciname_len))?;
            for (p, name) in [(et, "ET"), (f, "F"), (vnorm, "VNORM")] {
                if p.is_null() {
                    return Err(LawError::Input(format!("{name} is a NULL pointer")));
                }
            }
            write(et, law.fraction());
            write(f, law.slave_share());
            write(
                vnorm,
                match law.speed() {
                    SlidingSpeed::Given(v) => v,
                    SlidingSpeed::FromHost => FRICHEAT_HOST_SPEED,
                },
            );
            Ok(())
        },
        // SAFETY: the outputs writable (or NULL, then skipped).
        || unsafe {
            write(et, FRICHEAT_SAFE_FRACTION);
            write(f, FRICHEAT_SAFE_SHARE);
            write(vnorm, FRICHEAT_SAFE_SPEED);
        },
    );
}

/// Where a FRICHEAT message comes from, read only on the error path.
unsafe fn site(ciname: *const c_char, ciname_len: usize, noel: *const c_int) -> Site {
    // SAFETY: the host's pointers: CINAME of its hidden length, NOEL or NULL.
    unsafe {
        let place = format!("contact element {}", host_number(noel));
        host_site("FRICHEAT", ciname, ciname_len, place)
    }
}
