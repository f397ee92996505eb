//! `gapcon_`: the Abaqus/Standard GAPCON user subroutine (and, with the `calculix` feature,
//! CalculiX's variant of it).

use std::ffi::{c_char, c_int};

use super::{boundary, fortran_name_bytes, host_number, host_site, read_array, write};
use crate::LawError;
use crate::config;
use crate::report::Site;

/// `AK(1)` written when a call fails: no conductance. The failure is always reported (once per
/// cause), so this is never a silent default; `INTERFACIAL_STRICT=1` aborts instead.
pub const GAPCON_SAFE_CONDUCTANCE: f64 = 0.0;

/// Abaqus/Standard `GAPCON`: gap conductance `AK(1)` of one point, callable from Fortran as
/// `CALL GAPCON(...)` with no interface block. The heat flux is `AK(1)·(TEMP(1) − TEMP(2))`.
///
/// The law comes from the configuration file named by `INTERFACIAL_CONFIG` (TOML; read and
/// validated once, at the first call), entry `interactions.<CINAME>` matched exactly after
/// trimming trailing blanks and ignoring case, else the `"*"` entry (docs/config.md). Reads
/// `D(1)` (clearance), `D(2)` (contact pressure), `TEMP(1..2)` and `CINAME`; never reads
/// `FLOWM`, `PREDEF`, `NPRED`, `SLNAME`, `MSNAME`, `TIME`, `COORDS`, `KSTEP`, `KINC`. Writes
/// `AK(1)` only.
///
/// On failure (no or bad configuration file, interaction not configured, NaN or infinite
/// input, surface temperature below absolute zero with radiation, overflow, internal panic):
/// `AK(1) = 0` and one message per distinct cause (stderr or `$INTERFACIAL_LOG`;
/// `ifl_last_error` on the calling thread).
///
/// Called with CalculiX's argument list (`AREA` after `KINC`, so an address arrives as the
/// hidden length of `CINAME`: any value above 65535), it refuses: `AK(1) = 0`, nothing else
/// written, and a message that names the CalculiX variant, `libinterfacial_calculix`.
///
/// # Safety
/// Pointers valid for the GAPCON signature: `AK(5)`, `D(2)`, `TEMP(2)`, `CINAME` of the hidden
/// length `ciname_len`. The unread arguments may be anything.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
#[cfg(not(feature = "calculix"))]
// GAPCON's arguments several to a line in the manual's order, as a FORTRAN 77 listing continues
// them, then the names' hidden lengths: written out for cbindgen in both variants.
#[rustfmt::skip]
pub unsafe extern "C" fn gapcon_(
    ak: *mut f64, d: *const f64, flowm: *const f64, temp: *const f64, predef: *const f64,
    time: *const f64, ciname: *const c_char, slname: *const c_char, msname: *const c_char,
    coords: *const f64, noel: *const c_int, node: *const c_int, npred: *const c_int,
    kstep: *const c_int, kinc: *const c_int,
    ciname_len: usize, slname_len: usize, msname_len: usize,
) {
    let _ = (flowm, predef, time, slname, msname, coords, npred, kstep, kinc);
    let _ = msname_len;
    if ciname_len > super::MAX_NAME_LEN {
        // CalculiX's argument list: AREA's address sits where CINAME's length should be, and
        // CINAME's real length one slot later (docs/gapcon.md, "Which library").
        // SAFETY: the host's pointers; CINAME is read with a plausible length only.
        unsafe { wrong_variant(ak, ciname, slname_len, ciname_len, noel, node) };
        return;
    }
    // SAFETY: the host's pointers, valid per the contract above.
    unsafe { gap_conductance(ak, d, temp, ciname, ciname_len, noel, node) }
}

/// The refusal of the Abaqus `gapcon_` called with CalculiX's argument list: `AK(1) = 0`, nothing
/// else written, and a message naming the library to link instead.
///
/// # Safety
/// `AK(1)` writable or NULL; `ciname` NULL or readable for `real_ciname_len` bytes when that is
/// a plausible length.
#[cfg(not(feature = "calculix"))]
#[cold]
#[inline(never)]
unsafe fn wrong_variant(
    ak: *mut f64,
    ciname: *const c_char,
    real_ciname_len: usize,
    hidden_len: usize,
    noel: *const c_int,
    node: *const c_int,
) {
    let name_len = if real_ciname_len <= super::MAX_NAME_LEN {
        real_ciname_len
    } else {
        0
    };
    let _ = boundary(
        // SAFETY: CINAME read with its real length (the slot after), or not at all.
        || unsafe { site(ciname, name_len, noel, node) },
        || {
            Err(LawError::Parameter(format!(
                "called with CalculiX's gapcon argument list (the hidden length of CINAME is \
                 {hidden_len}, an address: AREA after KINC), but this is the Abaqus build of \
                 libinterfacial; link the CalculiX variant instead: libinterfacial_calculix.a \
                 or libinterfacial_calculix.so (CMake Interfacial::interfacial_calculix, \
                 pkg-config interfacial_calculix; docs/install.md)"
            )))
        },
        // SAFETY: AK(1) writable (or NULL, then skipped).
        || unsafe { write(ak, GAPCON_SAFE_CONDUCTANCE) },
    );
}

/// CalculiX's `gapcon`: the Abaqus argument list plus `AREA` after `KINC` (built with
/// `--features calculix`). Same law and outputs as the Abaqus variant; `FLOWM`, `PREDEF`,
/// `NPRED`, `SLNAME`, `MSNAME` and `AREA` are never read (CalculiX may pass them
/// uninitialised).
///
/// # Safety
/// As for the Abaqus variant.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
#[cfg(feature = "calculix")]
// The arguments as in the Abaqus variant, `AREA` after `KINC`.
#[rustfmt::skip]
pub unsafe extern "C" fn gapcon_(
    ak: *mut f64, d: *const f64, flowm: *const f64, temp: *const f64, predef: *const f64,
    time: *const f64, ciname: *const c_char, slname: *const c_char, msname: *const c_char,
    coords: *const f64, noel: *const c_int, node: *const c_int, npred: *const c_int,
    kstep: *const c_int, kinc: *const c_int, area: *const f64,
    ciname_len: usize, slname_len: usize, msname_len: usize,
) {
    let _ = (flowm, predef, time, slname, msname, coords, npred, kstep, kinc, area);
    let _ = (slname_len, msname_len);
    // SAFETY: the host's pointers, valid per the contract above.
    unsafe { gap_conductance(ak, d, temp, ciname, ciname_len, noel, node) }
}

/// The body shared by both variants.
#[inline(always)]
unsafe fn gap_conductance(
    ak: *mut f64,
    d: *const f64,
    temp: *const f64,
    ciname: *const c_char,
    ciname_len: usize,
    noel: *const c_int,
    node: *const c_int,
) {
    let _ = boundary(
        // SAFETY: CINAME has the hidden length the host passed; NOEL/NODE may be NULL.
        || unsafe { site(ciname, ciname_len, noel, node) },
        // SAFETY: D(2), TEMP(2) readable, AK(1) writable per the GAPCON contract.
        || unsafe {
            let law = config::gap_law_for(fortran_name_bytes(ciname, ciname_len))?;
            let [clearance, pressure] = read_array::<2>(d, "D")?;
            let [theta_a, theta_b] = read_array::<2>(temp, "TEMP")?;
            let r = law.evaluate(clearance, pressure, theta_a, theta_b)?;
            if ak.is_null() {
                return Err(LawError::Input("AK is a NULL pointer".into()));
            }
            write(ak, r.k);
            Ok(())
        },
        // SAFETY: AK(1) writable (or NULL, then skipped).
        || unsafe { write(ak, GAPCON_SAFE_CONDUCTANCE) },
    );
}

/// Where a GAPCON message comes from, read only on the error path.
unsafe fn site(
    ciname: *const c_char,
    ciname_len: usize,
    noel: *const c_int,
    node: *const c_int,
) -> Site {
    // SAFETY: the host's pointers: CINAME of its hidden length, NOEL, NODE or NULL.
    unsafe {
        let place = format!("element {}, node {}", host_number(noel), host_number(node));
        host_site("GAPCON", ciname, ciname_len, place)
    }
}
