//! `ifl_set_message_handler` (src/abi/message_hook.rs, src/report.rs): with a handler set,
//! every message reaches it instead of the `INTERFACIAL_LOG` file, whole and once, from any
//! thread; a message the handler itself causes goes to the file (no deadlock); a handler set
//! from inside the handler takes over when it returns; NULL sends messages to the file again.
//! Runs in a child process of this test binary, so the handler, the environment and the set
//! of causes already reported are its own.

#[path = "common/child.rs"]
mod child;
use child::run_child_with_log;

use std::ffi::{CStr, c_char, c_void};
use std::sync::Mutex;

use interfacial::abi::{IflPropsEntry, ifl_props_entry, ifl_set_message_handler};
use interfacial_test_hosts::FricCall;

const THREADS: usize = 8;
const PER_THREAD: usize = 400;

/// The child test, and the variable that makes it do its work.
const CHILD: &str = "child_messages_reach_the_handler";
const MARKER: &str = "IFL_MESSAGE_HOOK_CHILD";

/// What a handler received: each message and the length it was given.
type Received = Mutex<Vec<(String, usize)>>;

/// The handler: records the message and its length in the `Received` behind `user`.
unsafe extern "C" fn record(msg: *const c_char, len: usize, user: *mut c_void) {
    // SAFETY: the library passes a NUL-terminated text; `user` is the test's `Received`.
    let (text, received) = unsafe {
        (
            CStr::from_ptr(msg).to_string_lossy().into_owned(),
            &*user.cast::<Received>(),
        )
    };
    received.lock().unwrap().push((text, len));
}

/// A handler that calls the library (a refused `ifl_props_entry`, whose message must go to the
/// file), then replaces itself with `record` on the same `user`.
unsafe extern "C" fn reenter(msg: *const c_char, len: usize, user: *mut c_void) {
    let mut e = std::mem::MaybeUninit::<IflPropsEntry>::uninit();
    // SAFETY: a writable entry; law 99 is refused and reported from inside the handler.
    let _ = unsafe { ifl_props_entry(99, 0, e.as_mut_ptr()) };
    // SAFETY: as `record`; the replacement takes effect when this handler returns.
    unsafe {
        ifl_set_message_handler(Some(record), user);
        record(msg, len, user);
    }
}

/// A refused `fric_` call whose message names `tag` (μ = −tag), and that message.
fn bad_call(tag: usize) -> String {
    let mut c = FricCall::new(1, &[1.0, -(tag as f64)]);
    c.press = 10.0;
    c.call();
    assert!(c.pnewdt < 1.0);
    FricCall::last_error()
}

/// Child side: every step's messages, checked as they arrive.
#[test]
fn child_messages_reach_the_handler() {
    if std::env::var_os(MARKER).is_none() {
        return;
    }
    let received: &'static Received = Box::leak(Box::new(Mutex::new(Vec::new())));
    let user = std::ptr::from_ref(received).cast_mut().cast::<c_void>();

    // 1. Before any handler: to the file.
    bad_call(1);
    // 2. A handler, and many threads each reporting distinct causes at once.
    // SAFETY: `record` is thread-safe on `received`, which lives for the process.
    unsafe { ifl_set_message_handler(Some(record), user) };
    let sent: Vec<String> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..THREADS)
            .map(|t| {
                s.spawn(move || {
                    (0..PER_THREAD)
                        .map(|i| bad_call(1000 + t * PER_THREAD + i))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    {
        let got = received.lock().unwrap();
        assert_eq!(got.len(), THREADS * PER_THREAD, "every message, once");
        let mut got_texts: Vec<&str> = got.iter().map(|(m, _)| m.as_str()).collect();
        let mut sent_texts: Vec<&str> = sent.iter().map(String::as_str).collect();
        got_texts.sort_unstable();
        sent_texts.sort_unstable();
        // Whole: each is exactly the calling thread's own message, none cut or mixed.
        assert_eq!(got_texts, sent_texts);
        for (m, len) in got.iter() {
            assert_eq!(*len, m.len(), "{m}");
            assert!(!m.ends_with('\n'), "{m:?}");
        }
    }
    // 3. A handler that calls the library and replaces itself: no deadlock; its own call's
    //    message goes to the file; the replacement takes the next message.
    received.lock().unwrap().clear();
    // SAFETY: as above.
    unsafe { ifl_set_message_handler(Some(reenter), user) };
    // (The thread's last error after the first call is the handler's own failed call.)
    let first = bad_call(2);
    assert!(first.contains("law 99"), "{first}");
    let second = bad_call(3);
    {
        let got = received.lock().unwrap();
        let texts: Vec<&str> = got.iter().map(|(m, _)| m.as_str()).collect();
        assert_eq!(texts.len(), 2, "{texts:?}");
        assert!(
            texts[0].starts_with("interfacial: FRIC: interaction 'SI1'")
                && texts[0].contains("μ = -2 "),
            "{texts:?}"
        );
        assert_eq!(texts[1], second);
    }
    // 4. NULL: to the file again; the handler hears nothing more.
    // SAFETY: NULL is allowed.
    unsafe { ifl_set_message_handler(None, std::ptr::null_mut()) };
    received.lock().unwrap().clear();
    bad_call(4);
    assert!(received.lock().unwrap().is_empty());
}

#[test]
fn with_a_handler_messages_skip_the_file_and_come_back_without_one() {
    let (_, log) = run_child_with_log(CHILD, MARKER, "message-hook");
    let lines: Vec<&str> = log.lines().collect();
    // Step 1 (before the handler), step 3's own call from inside the handler, step 4 (after):
    // the file has those three and none of the handler's.
    assert_eq!(lines.len(), 3, "{log}");
    assert!(lines[0].contains("μ = -1 "), "{}", lines[0]);
    assert!(
        lines[1].contains("ifl_props_entry") && lines[1].contains("law 99"),
        "{}",
        lines[1]
    );
    assert!(lines[2].contains("μ = -4 "), "{}", lines[2]);
}
