//! `ifl_set_message_handler`: a host's function receives every message instead of stderr or the
//! `INTERFACIAL_LOG` file (src/report.rs sends them; docs/c-api.md).

use std::ffi::{CString, c_char, c_void};

use crate::report::set_sink;

/// A host's receiver of messages: `msg` is one whole message, NUL-terminated UTF-8 without a
/// newline, `len` its length in bytes without the NUL, `user` the pointer given to
/// `ifl_set_message_handler`. `msg` is valid only during the call: copy it to keep it.
pub type IflMessageHandler =
    Option<unsafe extern "C" fn(msg: *const c_char, len: usize, user: *mut c_void)>;

/// The host's function and its data, sent to whichever thread reports.
struct Handler {
    f: unsafe extern "C" fn(*const c_char, usize, *mut c_void),
    user: *mut c_void,
}

// SAFETY: `ifl_set_message_handler`'s contract: the handler may be called from any thread that
// calls into the library, with the same `user`; the library never reads or writes `*user`.
unsafe impl Send for Handler {}
// SAFETY: as above; the calls are made one at a time (report.rs holds a lock around each).
unsafe impl Sync for Handler {}

impl Handler {
    fn send(&self, line: &str) {
        // Our messages hold no NUL; a host's name with one shows it as a blank.
        let text = CString::new(line.replace('\0', " ")).unwrap_or_default();
        // SAFETY: the host's function per the contract of `ifl_set_message_handler`, given a
        // NUL-terminated text that lives through the call.
        unsafe { (self.f)(text.as_ptr(), text.as_bytes().len(), self.user) };
    }
}

/// Sends every later message of the library (each failure's line, the "further messages
/// suppressed" line, `INTERFACIAL_STRICT`'s last words) to `handler(msg, len, user)` instead of
/// stderr or the `INTERFACIAL_LOG` file; `handler` NULL sends them there again. `ifl_last_error`
/// is kept as before, whatever the handler.
///
/// The handler is called on the thread that reports, one call at a time across all threads
/// (the library holds a lock around each call), with one whole message per call: messages from
/// several threads all arrive, none cut or mixed. When `ifl_set_message_handler` returns, the
/// previous handler is not running and is never called again, so its `user` data may be freed.
/// Calling it from inside the handler takes effect when the handler returns. A message that the
/// handler itself causes (by calling the library) goes to stderr or the file, not back to the
/// handler.
///
/// # Safety
/// `handler` is NULL or a function safe to call from any thread that calls the library, with
/// `user` (any value, never dereferenced by the library), until it is replaced; it must not
/// unwind.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ifl_set_message_handler(handler: IflMessageHandler, user: *mut c_void) {
    set_sink(handler.map(|f| {
        let h = Handler { f, user };
        Box::new(move |line: &str| h.send(line)) as crate::report::Sink
    }));
}
