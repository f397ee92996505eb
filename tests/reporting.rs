//! Reporting: one line per distinct cause in `INTERFACIAL_LOG`, whatever the number of calls and
//! threads; `INTERFACIAL_STRICT=1` (or yes, true, on, any case) aborts, an unknown value is
//! reported and does not. Each test runs in a child process of this test binary
//! so the environment (read once per process) is its own.

#[path = "common/child.rs"]
mod child;
use child::{run_child, run_child_with_log};

use interfacial_test_hosts::FricCall;

/// The child test, and the variable that makes it do its work.
const CHILD: &str = "child_many_bad_calls";
const MARKER: &str = "IFL_REPORTING_CHILD";

fn bad_call(mu: f64) {
    let mut c = FricCall::new(2, &[1.0, mu]);
    c.press = 10.0;
    c.call();
    assert!(c.pnewdt < 1.0);
}

/// Child side: many bad calls with two distinct causes from several threads.
#[test]
fn child_many_bad_calls() {
    if std::env::var_os(MARKER).is_none() {
        return;
    }
    std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| {
                for _ in 0..1000 {
                    bad_call(-1.0);
                    bad_call(-2.0);
                }
            });
        }
    });
}

#[test]
fn one_line_per_cause_in_the_log_file() {
    let (out, text) = run_child_with_log(CHILD, MARKER, "log");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "8000 bad calls, 2 causes: {text}");
    assert!(lines.iter().any(|l| l.contains("-1")) && lines.iter().any(|l| l.contains("-2")));
    assert!(
        lines
            .iter()
            .all(|l| l.starts_with("interfacial: FRIC: interaction 'SI1'"))
    );
    // Nothing went to stderr from the library when the log file works.
    assert!(!String::from_utf8_lossy(&out.stderr).contains("interfacial: FRIC"));
}

#[test]
fn strict_mode_aborts_on_the_first_error() {
    let out = run_child(CHILD, MARKER, &[("INTERFACIAL_STRICT", "1")]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("interfacial: FRIC") && err.contains("INTERFACIAL_STRICT"),
        "{err}"
    );
}

#[test]
fn strict_mode_takes_yes_true_on_in_any_case() {
    for value in ["yes", "TRUE", " On ", "1"] {
        let out = run_child(CHILD, MARKER, &[("INTERFACIAL_STRICT", value)]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success(),
            "INTERFACIAL_STRICT={value:?} did not abort: {err}"
        );
        assert!(
            err.contains("INTERFACIAL_STRICT is set, aborting"),
            "{value:?}: {err}"
        );
    }
}

#[test]
fn strict_mode_off_values_and_unknown_values_do_not_abort() {
    for value in ["0", "off", "No", "false", ""] {
        let out = run_child(CHILD, MARKER, &[("INTERFACIAL_STRICT", value)]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.success(),
            "INTERFACIAL_STRICT={value:?} aborted: {err}"
        );
        assert!(!err.contains("not understood"), "{value:?}: {err}");
    }
    // An unknown value is said once, not ignored silently.
    let out = run_child(CHILD, MARKER, &[("INTERFACIAL_STRICT", "maybe")]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert_eq!(
        err.matches("INTERFACIAL_STRICT=\"maybe\" is not understood")
            .count(),
        1,
        "{err}"
    );
}
