//! The ABI shell: every `extern "C"` function of the library, and nothing else. Pointers and
//! lengths are checked once here, through the few helpers below; the laws only ever see values,
//! slices and fixed-size arrays.
//!
//! Every exported body runs inside `boundary`, which catches unwinding, turns an error or a
//! panic into the routine's documented failure output, and reports it.

use std::cell::Cell;
use std::ffi::{c_char, c_int};
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::LawError;
use crate::report::{Site, report};

/// The one panic boundary of a Fortran export (`uinter_`, `fric_coef_`, `vfric_`) whose argument
/// view `$args` has `unsafe fn run(&self) -> Result<(), LawError>` and `unsafe fn fail(&self)`:
/// [`boundary`] with the site closure `$site`, the view's `run` as the body and its `fail` as
/// the safe outputs; the fault is dropped (these routines return nothing). A macro rather than
/// a trait method, so each export compiles as if it were written out: one trait for the views
/// cost `uinter_` 3.1 % (docs/architecture.md, "Written once, and the copies kept", its "Tried and
/// not kept").
macro_rules! fortran_boundary {
    ($args:ident, $site:expr) => {
        let _ = $crate::abi::boundary(
            $site,
            // SAFETY (both closures): the host's pointers, valid per the export's contract.
            || unsafe { $args.run() },
            || unsafe { $args.fail() },
        );
    };
}

pub mod batch;
pub mod forced_sliding;
pub mod fric;
pub mod fric_coef;
pub mod fric_point;
#[cfg(feature = "calculix")]
pub mod fricheat;
pub mod gapcon;
pub mod message_hook;
pub mod native;
pub mod pore_pressure;
pub mod props_query;
pub mod uinter;
pub mod vfric;

pub use batch::{FricBatch, fric_batch, ifl_fric_batch};
pub use forced_sliding::ifl_forced_sliding;
pub use fric::fric_;
pub use fric_coef::fric_coef_;
pub use fric_point::{IflFricInput, IflFricOutput, ifl_fric_point};
#[cfg(feature = "calculix")]
pub use fricheat::fricheat_;
pub use gapcon::gapcon_;
pub use message_hook::{IflMessageHandler, ifl_set_message_handler};
pub use native::{
    IflConductance, IflStatus, ifl_clear_error, ifl_gap_conductance, ifl_gap_conductance_n,
    ifl_last_error, ifl_last_error_copy, ifl_version,
};
pub use pore_pressure::{IflPorePressureVariant, ifl_pore_pressure, ifl_pore_pressure_n};
pub use props_query::{
    IflPropsEntry, ifl_props_check, ifl_props_entry, ifl_props_entry_count, ifl_props_law_code,
    ifl_props_law_count,
};
pub use uinter::uinter_;
pub use vfric::vfric_;

/// What went wrong in an entry point, for callers that return a status.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Fault {
    /// A parameter or `PROPS` entry is wrong.
    Parameter,
    /// The configuration file is missing or invalid (one cause for every interaction).
    Config,
    /// An input of this call is unusable.
    Input,
    /// The computation failed.
    Numerical,
    /// A panic (a bug in the library).
    Internal,
}

/// Runs an entry point's `body`. On an error or a panic it first calls `on_fault` (which writes
/// the routine's safe outputs, e.g. `PNEWDT`), then reports the cause at `site()`. Nothing
/// unwinds out of it.
pub(crate) fn boundary(
    site: impl FnOnce() -> Site,
    body: impl FnOnce() -> Result<(), LawError>,
    on_fault: impl FnOnce(),
) -> Result<(), Fault> {
    let (fault, cause) = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => return Ok(()),
        Ok(Err(e)) => {
            let fault = match e {
                LawError::Parameter(_) => Fault::Parameter,
                LawError::Config(_) => Fault::Config,
                LawError::Input(_) => Fault::Input,
                LawError::Numerical(_) => Fault::Numerical,
            };
            (fault, e.to_string())
        }
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown".into());
            (
                Fault::Internal,
                format!("internal error (panic: {what}); please report it"),
            )
        }
    };
    LAST_FAULT.set(Some(fault));
    // The failure path must not unwind either (a panic in a host-supplied name conversion, an
    // allocation failure while formatting): swallow it, the safe outputs are already written.
    let _ = catch_unwind(AssertUnwindSafe(|| {
        on_fault();
        report(&site(), &cause, fault != Fault::Config);
    }));
    Err(fault)
}

thread_local! {
    /// The fault of the last [`boundary`] that failed on this thread, until [`take_fault`]
    /// takes it: how `ifl_fric_point` learns the status of the `fric_` call it made.
    static LAST_FAULT: Cell<Option<Fault>> = const { Cell::new(None) };
}

/// Takes (and forgets) the fault of the last failed [`boundary`] on this thread.
pub(crate) fn take_fault() -> Option<Fault> {
    LAST_FAULT.take()
}

/// [`boundary`] in a function of its own, never inlined into its caller: for an export whose
/// body is only a call to it (`fric_general`). Inlined there, the catch and the whole law came
/// into the caller's frame, whose prologue then cost ~34 instructions per call (`bench_rate`
/// decay +2.8 %, issue 19); `#[inline(never)]` on `boundary` itself cost `uinter_` +4.5 %, so
/// the choice is made per call site.
#[inline(never)]
pub(crate) fn boundary_outlined(
    site: impl FnOnce() -> Site,
    body: impl FnOnce() -> Result<(), LawError>,
    on_fault: impl FnOnce(),
) -> Result<(), Fault> {
    boundary(site, body, on_fault)
}

#[cold]
#[inline(never)]
pub(crate) fn null_pointer(name: &str) -> LawError {
    LawError::Input(format!("{name} is a NULL pointer"))
}

/// A count the host passed (`NPROPS`, `nBlock`, …) as a length; a negative one is refused with
/// the message every entry point gives, "`name` = … is negative".
#[inline]
pub(crate) fn count(name: &str, value: c_int) -> Result<usize, LawError> {
    usize::try_from(value).map_err(|_| negative(name, value))
}

/// The refusal of an `NSTATV` = `given` below the `needed` state variables of `law` (as the law
/// names itself), saying where the host sets it (`set_by`): one message for every entry point.
#[cold]
#[inline(never)]
pub(crate) fn short_nstatv(given: i64, needed: usize, law: &str, set_by: &str) -> LawError {
    LawError::Parameter(format!(
        "NSTATV = {given} but {law} needs {needed} state variables ({set_by})"
    ))
}

#[cold]
#[inline(never)]
fn negative(name: &str, value: c_int) -> LawError {
    LawError::Parameter(format!("{name} = {value} is negative"))
}

/// The refusal of an `LM` on entry other than 0, 1 or 2 (`fric_` and the batch).
#[cold]
#[inline(never)]
pub(crate) fn bad_lm(lm: c_int) -> LawError {
    LawError::Input(format!("LM = {lm} on entry; expected 0, 1 or 2"))
}

/// Where a message of a Fortran entry point comes from: `routine`, the interaction's
/// `CHARACTER` name (`name`, `name_len`) and `place`. Built on the error path only.
///
/// # Safety
/// `name` is NULL or points to `name_len` readable bytes.
pub(crate) unsafe fn host_site(
    routine: &'static str,
    name: *const c_char,
    name_len: usize,
    place: String,
) -> Site {
    Site {
        routine,
        // SAFETY: the hidden length the host passed (never exceeded; implausible ones not read).
        interaction: unsafe { fortran_string(name, name_len) },
        place,
    }
}

/// An `INTEGER` argument as shown in a message: its value, or "?" for NULL.
///
/// # Safety
/// `p` is NULL or points to a readable `c_int` (unaligned reads are fine).
pub(crate) unsafe fn host_number(p: *const c_int) -> String {
    if p.is_null() {
        "?".to_string()
    } else {
        // SAFETY: non-NULL and readable by contract.
        unsafe { p.read_unaligned() }.to_string()
    }
}

/// Reads a scalar argument passed by reference.
///
/// # Safety
/// `p` is NULL or points to a readable `T`.
#[inline]
pub(crate) unsafe fn read<T: Copy>(p: *const T, name: &str) -> Result<T, LawError> {
    if p.is_null() {
        Err(null_pointer(name))
    } else {
        // SAFETY: non-NULL, and the caller guarantees it points to a T.
        Ok(unsafe { p.read() })
    }
}

/// Reads a Fortran array of exactly N reals.
///
/// # Safety
/// `p` is NULL or points to at least N readable `f64`.
#[inline]
pub(crate) unsafe fn read_array<const N: usize>(
    p: *const f64,
    name: &str,
) -> Result<[f64; N], LawError> {
    if p.is_null() {
        return Err(null_pointer(name));
    }
    let mut out = [0.0; N];
    for (i, x) in out.iter_mut().enumerate() {
        // SAFETY: i < N and the caller guarantees N readable entries.
        *x = unsafe { p.add(i).read() };
    }
    Ok(out)
}

/// Borrows a Fortran array of `len` reals (`len` already checked ≥ 0 by the caller).
///
/// # Safety
/// `p` is NULL or points to `len` readable `f64` that outlive the borrow and are not written
/// through another pointer meanwhile.
#[inline]
pub(crate) unsafe fn slice<'a>(
    p: *const f64,
    len: usize,
    name: &str,
) -> Result<&'a [f64], LawError> {
    if len == 0 {
        Ok(&[])
    } else if p.is_null() {
        Err(null_pointer(name))
    } else {
        // SAFETY: as documented above.
        Ok(unsafe { std::slice::from_raw_parts(p, len) })
    }
}

/// Writes N reals to a Fortran array; a NULL pointer (an optional output the host left out) is
/// skipped.
///
/// # Safety
/// `p` is NULL or points to at least N writable `f64`.
#[inline]
pub(crate) unsafe fn write_array<const N: usize>(p: *mut f64, v: &[f64; N]) {
    if !p.is_null() {
        for (i, x) in v.iter().enumerate() {
            // SAFETY: i < N writable entries.
            unsafe { p.add(i).write(*x) };
        }
    }
}

/// Writes an N×N matrix `m[a][b]` in Fortran (column-major) order: `A(a,b)` at `a + b·N`.
///
/// # Safety
/// `p` is NULL or points to at least N·N writable `f64`.
#[inline]
pub(crate) unsafe fn write_matrix<const N: usize>(p: *mut f64, m: &[[f64; N]; N]) {
    if !p.is_null() {
        for (a, row) in m.iter().enumerate() {
            for (b, x) in row.iter().enumerate() {
                // SAFETY: a + b·N < N·N.
                unsafe { p.add(a + b * N).write(*x) };
            }
        }
    }
}

/// Writes `count` zeros to a Fortran array; NULL is skipped.
///
/// # Safety
/// `p` is NULL or points to at least `count` writable `f64`.
#[inline]
pub(crate) unsafe fn write_zeros(p: *mut f64, count: usize) {
    if !p.is_null() {
        for i in 0..count {
            // SAFETY: i < count writable entries.
            unsafe { p.add(i).write(0.0) };
        }
    }
}

/// Writes a scalar output; NULL is skipped.
///
/// # Safety
/// `p` is NULL or points to a writable `T`.
#[inline]
pub(crate) unsafe fn write<T>(p: *mut T, v: T) {
    if !p.is_null() {
        // SAFETY: non-NULL and writable by contract.
        unsafe { p.write(v) };
    }
}

/// A failed call's `PNEWDT`: lowered to [`crate::CUTBACK_RATIO`] (a NaN is replaced), never
/// raised; NULL is left alone.
///
/// # Safety
/// `pnewdt` is NULL or a valid, writable double.
pub(crate) unsafe fn cut_back(pnewdt: *mut f64) {
    if pnewdt.is_null() {
        return;
    }
    // SAFETY: non-NULL and valid by the caller's contract.
    unsafe {
        let current = pnewdt.read();
        if current.is_nan() || current > crate::CUTBACK_RATIO {
            pnewdt.write(crate::CUTBACK_RATIO);
        }
    }
}

/// The largest hidden length taken as a name length. Abaqus names have at most 80 characters,
/// and on Linux no object lives below `vm.mmap_min_addr` (65536 by default), so a larger
/// "length" is an address that landed in the hidden-length slot: a caller with a different
/// argument list (CalculiX's `gapcon` with `AREA` calling the Abaqus build).
pub(crate) const MAX_NAME_LEN: usize = 65535;

/// A Fortran `CHARACTER` argument as bytes, without copying, for name lookups: empty for NULL,
/// a zero length or a length above [`MAX_NAME_LEN`] (an address, not a length: never read).
///
/// # Safety
/// `p` is NULL or points to `len` readable bytes that outlive the borrow.
pub(crate) unsafe fn fortran_name_bytes<'a>(p: *const c_char, len: usize) -> &'a [u8] {
    if p.is_null() || len == 0 || len > MAX_NAME_LEN {
        &[]
    } else {
        // SAFETY: as documented.
        unsafe { std::slice::from_raw_parts(p.cast::<u8>(), len) }
    }
}

/// A Fortran `CHARACTER` argument: `len` bytes, blank-padded, not NUL-terminated. Trailing
/// blanks (and NULs, which some C callers leave) are trimmed; nothing past `len` is read.
///
/// # Safety
/// `p` is NULL or points to `len` readable bytes.
pub(crate) unsafe fn fortran_string(p: *const c_char, len: usize) -> String {
    if p.is_null() || len == 0 {
        return String::new();
    }
    if len > MAX_NAME_LEN {
        // Not a length but a shifted argument (an address): reading would crash.
        return format!("? (hidden length {len})");
    }
    // SAFETY: `len` readable bytes by contract (the hidden length is trusted, never exceeded).
    shown_name(unsafe { std::slice::from_raw_parts(p.cast::<u8>(), len) })
}

/// A name's bytes as shown in messages: trailing blanks and NULs dropped, invalid UTF-8
/// replaced.
pub(crate) fn shown_name(bytes: &[u8]) -> String {
    let end = bytes
        .iter()
        .rposition(|b| *b != b' ' && *b != 0)
        .map_or(0, |i| i + 1);
    String::from_utf8_lossy(&bytes[..end]).into_owned()
}

/// Unit tests only: one `ifl_fric_point` call (`fric_` itself) for the unit tests outside this
/// layer that must call an entry point with a switch of this build on (a forced panic, the
/// careful `PROPS` path), which the test hosts (test-hosts/, a crate that links its own copy of
/// the library) cannot do.
#[cfg(test)]
pub(crate) mod test_point {
    /// What a unit test writes past the end of an array it passes, to prove nothing is written
    /// there.
    pub(crate) const UNWRITTEN: f64 = -7.77e77;

    /// One closed `fric_` point for `ifl_fric_point` (which is `fric_` itself): `nfdir`
    /// directions, `props`, the first `nstatv` entries of `statev` (read and written), pressure
    /// 0, Δt = 1, identity `DROT`, θ = 20 on both sides, interaction `"SI1"`.
    pub(crate) fn fric_point_input(
        nfdir: i32,
        props: &[f64],
        statev: &mut [f64],
        nstatv: i32,
    ) -> super::IflFricInput {
        assert!(statev.len() >= nstatv.max(0) as usize);
        super::IflFricInput {
            lm: 0,
            nfdir,
            tau: [0.0; 2],
            dgam: [0.0; 2],
            taulm: [0.0; 2],
            press: 0.0,
            dpress: 0.0,
            dtime: 1.0,
            chrlngth: 1.0,
            temp: [20.0; 2],
            drot: [1.0, 0.0, 0.0, 1.0],
            coords: [0.0; 3],
            mcrd: 3,
            noel: 0,
            npt: 1,
            node: 1,
            interaction: c"SI1".as_ptr(),
            props: props.as_ptr(),
            nprops: i32::try_from(props.len()).unwrap_or(i32::MAX),
            statev: statev.as_mut_ptr(),
            nstatv,
            pnewdt: 1e36,
        }
    }

    /// `ifl_fric_point` on `input`: its status and outputs.
    pub(crate) fn fric_point(
        input: &super::IflFricInput,
    ) -> (super::IflStatus, super::IflFricOutput) {
        let mut output = super::IflFricOutput::default();
        // SAFETY: `input` comes from `fric_point_input`, whose arrays the caller keeps alive.
        let status = unsafe { super::ifl_fric_point(input, &mut output) };
        (status, output)
    }
}

#[cfg(test)]
mod tests {
    use super::test_point::{UNWRITTEN, fric_point, fric_point_input};
    use super::{IflFricOutput, IflStatus, count, host_number, host_site, shown_name};
    use crate::report::with_last_error;
    use crate::testing::{force_panic, forced_panics};
    use crate::{CUTBACK_RATIO, LawError};

    #[test]
    fn a_count_is_a_length_or_the_one_negative_message() {
        assert_eq!(count("NPROPS", 0).ok(), Some(0));
        assert_eq!(count("NPROPS", i32::MAX).ok(), Some(i32::MAX as usize));
        for (name, v) in [("nBlock", -1), ("NPROPS", i32::MIN)] {
            match count(name, v) {
                Err(LawError::Parameter(m)) => assert_eq!(m, format!("{name} = {v} is negative")),
                other => panic!("{name} = {v}: {other:?}"),
            }
        }
    }

    #[test]
    fn sites_show_numbers_and_trimmed_names_without_reading_past_them() {
        assert_eq!(unsafe { host_number(std::ptr::null()) }, "?");
        // An INTEGER at an odd address (a packed host array) reads as its value.
        let mut bytes = [0u8; 8];
        bytes[1..5].copy_from_slice(&(-12i32).to_ne_bytes());
        let odd = bytes[1..].as_ptr().cast::<std::ffi::c_int>();
        assert_eq!(unsafe { host_number(odd) }, "-12");
        assert_eq!(shown_name(b"SI1  \0\0"), "SI1");
        assert_eq!(shown_name(b" A B "), " A B");
        assert_eq!(shown_name(b"\0 "), "");
        assert_eq!(shown_name(b"X\xff"), "X\u{fffd}");
        let name = b"CONTACT-1   ";
        let site = unsafe { host_site("GAPCON", name.as_ptr().cast(), 9, "node 3".into()) };
        assert_eq!(
            (site.routine, site.interaction.as_str(), site.place.as_str()),
            ("GAPCON", "CONTACT-1", "node 3")
        );
        // A hidden length that is an address (a caller with another argument list) is shown,
        // not used: the dangling pointer is never read.
        let site = unsafe { host_site("GAPCON", std::ptr::dangling(), 1 << 40, String::new()) };
        assert_eq!(
            site.interaction,
            format!("? (hidden length {})", 1u64 << 40)
        );
    }

    #[test]
    fn a_panic_in_the_core_becomes_a_cut_back() {
        let props = [1.0, 0.3, 0.0, 0.0, 1e-3];
        let mut statev = [0.5, 0.0, 1.0, UNWRITTEN, UNWRITTEN, UNWRITTEN, UNWRITTEN];
        let mut input = fric_point_input(2, &props, &mut statev, 3);
        input.press = 100.0;
        input.tau = [1.0, 2.0];
        input.dgam[0] = 1e-4;
        let before = forced_panics();
        force_panic(true);
        let (status, out) = fric_point(&input);
        force_panic(false);
        // The plain path's panic is reported by the export's one boundary, not swallowed and
        // the call run again on the checked path (which would panic a second time).
        assert_eq!(forced_panics() - before, 1);
        assert_eq!(status, IflStatus::InternalError);
        // Only PNEWDT is written: TAU keeps the start stress, every other output stays unset.
        let cut_back = IflFricOutput {
            lm: 0,
            tau: [1.0, 2.0],
            pnewdt: CUTBACK_RATIO,
            ..IflFricOutput::default()
        };
        assert_eq!(out, cut_back);
        assert_eq!(
            statev,
            [0.5, 0.0, 1.0, UNWRITTEN, UNWRITTEN, UNWRITTEN, UNWRITTEN]
        );
        let msg = with_last_error(|e| e.to_string_lossy().into_owned());
        assert!(msg.contains("FRIC") && msg.contains("panic"), "{msg}");
        // The library keeps working on this thread afterwards.
        let (status, out) = fric_point(&input);
        assert_eq!(status, IflStatus::Ok);
        assert_eq!(out.pnewdt, 1e36);
        assert_eq!(out.lm, 0);
    }
}
