//! The native C API (`ifl_*`): version and error text. Law-specific native calls join here.

use std::ffi::{CStr, c_char};

use crate::report::{clear_last_error, with_last_error};

/// The library version as a NUL-terminated string, e.g. `"0.1.0"`. Static storage: never free it.
#[unsafe(no_mangle)]
pub extern "C" fn ifl_version() -> *const c_char {
    const VERSION: &CStr =
        match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
            Ok(v) => v,
            Err(_) => c"unknown",
        };
    VERSION.as_ptr()
}

/// The last error message reported on the calling thread, NUL-terminated; `""` when there has
/// been none since the last `ifl_clear_error`. The pointer stays valid until the next call into
/// the library on the same thread; copy the text if you need it longer. Never free it.
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

/// Forgets the calling thread's last error message.
#[unsafe(no_mangle)]
pub extern "C" fn ifl_clear_error() {
    clear_last_error();
}
