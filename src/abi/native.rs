//! The native C API (`ifl_*`): version and error text. Law-specific native calls join here.

use std::ffi::{CStr, c_char};

use crate::report::{clear_last_error, with_last_error};

/// The library version as a NUL-terminated string: `"0.1.0"` for the default build,
/// `"0.1.0+calculix"` for the CalculiX variant (`gapcon_` with `AREA`), so a host can tell
/// which one it loaded. Static storage: never free it.
#[unsafe(no_mangle)]
pub extern "C" fn ifl_version() -> *const c_char {
    #[cfg(not(feature = "calculix"))]
    const TEXT: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");
    #[cfg(feature = "calculix")]
    const TEXT: &str = concat!(env!("CARGO_PKG_VERSION"), "+calculix\0");
    const VERSION: &CStr = match CStr::from_bytes_with_nul(TEXT.as_bytes()) {
        Ok(v) => v,
        Err(_) => c"unknown",
    };
    VERSION.as_ptr()
}

/// The last error message reported on the calling thread, NUL-terminated; `""` when there has
/// been none since the last `ifl_clear_error`. A successful call does not clear it (like
/// `errno`): only the next failure on this thread replaces it, only `ifl_clear_error` empties
/// it. The pointer stays valid until the next call into the library on the same thread; copy
/// the text if you need it longer. Never free it.
#[unsafe(no_mangle)]
pub extern "C" fn ifl_last_error() -> *const c_char {
    // The thread-local buffer outlives this call; it is only replaced by a later report or clear
    // on this same thread, which the doc comment rules out while the pointer is in use.
    with_last_error(|e| e.as_ptr())
}

/// Copies the calling thread's last error message into `buf` (capacity `len` bytes, always
/// NUL-terminated when `len > 0`, truncated if needed) and returns the full message length in
/// bytes without the NUL. For Fortran callers, which cannot follow a returned pointer easily.
/// `buf` may be NULL (with any `len`) to ask for the length only.
///
/// # Safety
/// `buf` is NULL or points to `len` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ifl_last_error_copy(buf: *mut c_char, len: usize) -> usize {
    with_last_error(|e| {
        let bytes = e.as_bytes();
        if !buf.is_null() && len > 0 {
            let n = bytes.len().min(len - 1);
            // SAFETY: n + 1 ≤ len writable bytes; the source is our own buffer, not overlapping.
            unsafe {
                std::ptr::copy_nonoverlapping(bytes.as_ptr().cast::<c_char>(), buf, n);
                buf.add(n).write(0);
            }
        }
        bytes.len()
    })
}

/// Forgets the calling thread's last error message (successful calls keep it, so clear before
/// a call whose own failure you want to read).
#[unsafe(no_mangle)]
pub extern "C" fn ifl_clear_error() {
    clear_last_error();
}

/// Status of a native call. The numbers are stable.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IflStatus {
    /// Success.
    Ok = 0,
    /// A parameter or the configuration file is wrong (see `ifl_last_error`).
    BadParameter = 1,
    /// An input of this call is unusable (NaN, infinite, NULL pointer, …).
    BadInput = 2,
    /// The computation failed.
    NumericalFailure = 3,
    /// A bug in the library (a caught panic).
    InternalError = 4,
}

impl From<Result<(), super::Fault>> for IflStatus {
    fn from(r: Result<(), super::Fault>) -> Self {
        match r {
            Ok(()) => IflStatus::Ok,
            Err(super::Fault::Parameter | super::Fault::Config) => IflStatus::BadParameter,
            Err(super::Fault::Input) => IflStatus::BadInput,
            Err(super::Fault::Numerical) => IflStatus::NumericalFailure,
            Err(super::Fault::Internal) => IflStatus::InternalError,
        }
    }
}

/// Gap conductance and its derivatives, as the native calls write them: the law's own
/// [`ConductanceResponse`] (`#[repr(C)]`),
/// named `IflConductance` in the header (cbindgen.toml's `[export.rename]`).
pub use crate::laws::gap_conductance::ConductanceResponse as IflConductance;
use crate::laws::gap_conductance::ConductanceResponse;

/// The thermal law of `interaction` (NUL-terminated; matched as `gapcon_` matches `CINAME`) from
/// the `INTERFACIAL_CONFIG` file, evaluated at clearance `d`, contact pressure `p` and surface
/// temperatures `theta_a`, `theta_b`. On success writes `*out` and returns `IFL_STATUS_OK`; on
/// failure writes `*out` as all zeros (when `out` is not NULL), reports, and returns the cause.
/// [`ifl_gap_conductance_n`] takes the name with its length instead (no NUL needed).
///
/// # Safety
/// `interaction` is NULL or a NUL-terminated string; `out` is NULL or writable.
#[unsafe(no_mangle)]
// Parameters a line per role (name / inputs / output), written out for cbindgen in both exports.
#[rustfmt::skip]
pub unsafe extern "C" fn ifl_gap_conductance(
    interaction: *const c_char,
    d: f64, p: f64, theta_a: f64, theta_b: f64,
    out: *mut ConductanceResponse,
) -> IflStatus {
    let name: Option<&[u8]> = if interaction.is_null() {
        None
    } else {
        // SAFETY: NUL-terminated per the contract.
        Some(unsafe { CStr::from_ptr(interaction) }.to_bytes())
    };
    gap_conductance("ifl_gap_conductance", name, d, p, theta_a, theta_b, out)
}

/// [`ifl_gap_conductance`] with the name given as `interaction_len` bytes at `interaction`, as
/// Fortran passes a `CHARACTER` (blank-padded, no NUL): nothing past `interaction_len` is read,
/// trailing blanks and NULs are ignored. For Fortran, the `interfacial` module's
/// `ifl_gap_conductance(name, ...)` calls it with `len(name)`.
///
/// # Safety
/// `interaction` is NULL or points to `interaction_len` readable bytes (any pointer when
/// `interaction_len` is 0); `out` is NULL or writable.
#[unsafe(no_mangle)]
// Parameters a line per role, as in `ifl_gap_conductance`.
#[rustfmt::skip]
pub unsafe extern "C" fn ifl_gap_conductance_n(
    interaction: *const c_char, interaction_len: usize,
    d: f64, p: f64, theta_a: f64, theta_b: f64,
    out: *mut ConductanceResponse,
) -> IflStatus {
    let name: Option<&[u8]> = if interaction_len == 0 {
        Some(&[])
    } else if interaction.is_null() {
        None
    } else {
        // SAFETY: `interaction_len` readable bytes per the contract.
        let bytes =
            unsafe { std::slice::from_raw_parts(interaction.cast::<u8>(), interaction_len) };
        let end = bytes.iter().rposition(|b| *b != 0).map_or(0, |i| i + 1);
        Some(&bytes[..end])
    };
    // Named as both: the Fortran module's ifl_gap_conductance(name, ...) is this call.
    let routine = "ifl_gap_conductance_n (or the Fortran module's ifl_gap_conductance)";
    gap_conductance(routine, name, d, p, theta_a, theta_b, out)
}

/// The body of both native conductance calls; `name` is `None` for a NULL pointer.
fn gap_conductance(
    routine: &'static str,
    name: Option<&[u8]>,
    d: f64,
    p: f64,
    theta_a: f64,
    theta_b: f64,
    out: *mut ConductanceResponse,
) -> IflStatus {
    super::boundary(
        || crate::report::Site {
            routine,
            interaction: super::shown_name(name.unwrap_or_default()),
            place: "native call".into(),
        },
        || {
            let Some(name) = name.filter(|_| !out.is_null()) else {
                return Err(crate::LawError::Input(
                    "interaction or out is a NULL pointer".into(),
                ));
            };
            let law = crate::config::gap_law_for(name)?;
            let r = law.evaluate(d, p, theta_a, theta_b)?;
            // SAFETY: checked non-NULL above; writable per the callers' contracts.
            unsafe {
                out.write(r);
            }
            Ok(())
        },
        || {
            if !out.is_null() {
                // SAFETY: writable per the callers' contracts.
                unsafe { out.write(ConductanceResponse::default()) };
            }
        },
    )
    .into()
}
