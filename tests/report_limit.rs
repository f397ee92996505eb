//! The once-per-cause message set is bounded: after 10 000 distinct causes the library prints
//! one "further messages suppressed" line and nothing more, however many new causes follow;
//! `ifl_last_error` still gives each call's own message. Runs in a child process of this test
//! binary, so the environment (read once per process) and the set of causes are its own.

#[path = "common/child.rs"]
mod child;
use child::run_child_with_log;
use std::ffi::CStr;

use interfacial::abi::ifl_last_error;
use interfacial_test_hosts::FricCall;

const LIMIT: usize = 10_000;

/// The child test, and the variable that makes it do its work.
const CHILD: &str = "child_many_distinct_causes";
const MARKER: &str = "IFL_REPORT_LIMIT_CHILD";

/// A refused call whose cause is distinct for each `i`: μ = −(i + 1) is named in the message.
fn bad_call(i: usize) -> String {
    let mut c = FricCall::new(1, &[1.0, -((i + 1) as f64)]);
    c.press = 10.0;
    c.call();
    assert!(c.pnewdt < 1.0);
    // SAFETY: the library's NUL-terminated buffer, read before the next call on this thread.
    unsafe { CStr::from_ptr(ifl_last_error()) }
        .to_string_lossy()
        .into_owned()
}

/// Child side: 2.5 × LIMIT distinct causes, then the first causes again.
#[test]
fn child_many_distinct_causes() {
    if std::env::var_os(MARKER).is_none() {
        return;
    }
    for i in 0..LIMIT * 5 / 2 {
        let message = bad_call(i);
        // Past the limit the calling thread still gets its own message.
        assert!(
            message.contains(&format!("μ = -{}", i + 1)),
            "{i}: {message}"
        );
    }
    for i in 0..10 {
        bad_call(i);
    }
}

#[test]
fn messages_stop_after_ten_thousand_causes_with_one_line_saying_so() {
    let (_, text) = run_child_with_log(CHILD, MARKER, "limit");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), LIMIT + 1, "{LIMIT} causes, then one line");
    // The first LIMIT causes, in order, each once.
    for (i, line) in lines[..LIMIT].iter().enumerate() {
        assert!(
            line.starts_with("interfacial: FRIC: interaction 'SI1'")
                && line.contains(&format!("μ = -{} ", i + 1)),
            "line {i}: {line}"
        );
    }
    let last = lines[LIMIT];
    assert!(
        last.contains("10000 distinct error causes") && last.contains("suppressed"),
        "{last}"
    );
}
