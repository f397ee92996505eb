//! The host's side of the library's Fortran entry points, for interfacial's tests, its main job
//! (`examples/scenes`) and its benchmarks: [`FricCall`] (`fric_`), [`UinterCall`] (`uinter_`)
//! and [`GapconCall`] (`gapcon_`) hold every argument in Fortran layout and pass it by reference
//! exactly as an FE code does, through the library's public API, so what they exercise is the
//! real entry point. Output arrays carry [`GUARD`] slots past what a call may write.
//!
//! A crate of its own (`publish = false`) that the library takes as a dev-dependency only: none
//! of this is compiled into the library a host links or into its package.

use std::ffi::CStr;

mod fric;
mod gapcon;
mod uinter;

pub use fric::FricCall;
pub use gapcon::GapconCall;
pub use uinter::UinterCall;

/// Sentinel written past the end of every output array, to prove nothing is written there.
pub const GUARD: f64 = -7.77e77;

/// `STATEV` of `n` zeros followed by four [`GUARD`] slots.
pub(crate) fn state_with_guards(n: usize) -> Vec<f64> {
    let mut statev = vec![0.0; n];
    statev.extend([GUARD; 4]);
    statev
}

/// The output arrays of a host call, each with the number of entries the call may write
/// (NFDIR, NDIR², NSTATV, …): every entry past that count is a guard slot. A count past the
/// array's end (a test's deliberately bad size) leaves that array without guard slots.
pub(crate) type Outputs<'a, const K: usize> = [(&'a mut [f64], usize); K];

/// Fills every guard slot of `outputs` with [`GUARD`].
pub(crate) fn fill_guards<const K: usize>(outputs: Outputs<'_, K>) {
    for (array, written) in outputs {
        if let Some(slots) = array.get_mut(written..) {
            slots.fill(GUARD);
        }
    }
}

/// True when every guard slot of `outputs` still holds [`GUARD`].
pub(crate) fn guards_hold<const K: usize>(outputs: Outputs<'_, K>) -> bool {
    outputs.into_iter().all(|(array, written)| {
        array
            .get(written..)
            .unwrap_or(&[])
            .iter()
            .all(|x| *x == GUARD)
    })
}

/// A `CHARACTER` argument as the host passes it: `name` blank-padded to `len` bytes (longer
/// names are kept whole; the hidden length says how much is read).
pub(crate) fn blank_padded(name: &str, len: usize) -> Vec<u8> {
    let mut bytes = name.as_bytes().to_vec();
    bytes.resize(len.max(bytes.len()), b' ');
    bytes
}

/// The calling thread's last error message (empty when none), read through `ifl_last_error`.
#[must_use]
pub fn last_error() -> String {
    // SAFETY: `ifl_last_error` returns the thread's NUL-terminated message, valid until the next
    // call into the library on this thread; it is copied before any such call.
    unsafe { CStr::from_ptr(interfacial::abi::ifl_last_error()) }
        .to_string_lossy()
        .into_owned()
}
