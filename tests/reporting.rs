//! Reporting: one line per distinct cause in `INTERFACIAL_LOG`, whatever the number of calls and
//! threads; `INTERFACIAL_STRICT=1` aborts. Each test runs in a child process of this test binary
//! so the environment (read once per process) is its own.

use std::process::Command;

use interfacial::abi::host::FricCall;

fn bad_call(mu: f64) {
    let mut c = FricCall::new(2, &[1.0, mu]);
    c.press = 10.0;
    c.call();
    assert!(c.pnewdt < 1.0);
}

/// Child side: many bad calls with two distinct causes from several threads.
#[test]
fn child_many_bad_calls() {
    if std::env::var_os("IFL_REPORTING_CHILD").is_none() {
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

fn run_child(envs: &[(&str, &str)]) -> std::process::Output {
    let exe = std::env::current_exe().expect("test binary path");
    let mut cmd = Command::new(exe);
    cmd.args([
        "--exact",
        "child_many_bad_calls",
        "--nocapture",
        "--test-threads=1",
    ])
    .env("IFL_REPORTING_CHILD", "1");
    for (k, v) in envs {
        cmd.env(k, v);
    }
    cmd.output().expect("run child")
}

#[test]
fn one_line_per_cause_in_the_log_file() {
    let log = std::env::temp_dir().join(format!("interfacial-log-{}.txt", std::process::id()));
    let _ = std::fs::remove_file(&log);
    let out = run_child(&[("INTERFACIAL_LOG", log.to_str().unwrap())]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&log).expect("log written");
    let _ = std::fs::remove_file(&log);
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
    let out = run_child(&[("INTERFACIAL_STRICT", "1")]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("interfacial: FRIC") && err.contains("INTERFACIAL_STRICT"),
        "{err}"
    );
}
