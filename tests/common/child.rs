//! A test whose subject is read once per process (the environment, the set of causes already
//! reported) does its work in a child process of its own test binary. Shared by reporting.rs and
//! report_limit.rs (included there by path).

use std::process::{Command, Output};

/// Runs the test `child` of this binary alone in a child process, with `marker` set (the child
/// test does its work only then), `INTERFACIAL_STRICT` unset unless `envs` sets it, and `envs`.
pub fn run_child(child: &str, marker: &str, envs: &[(&str, &str)]) -> Output {
    let exe = std::env::current_exe().expect("test binary path");
    Command::new(exe)
        .args(["--exact", child, "--nocapture", "--test-threads=1"])
        .env(marker, "1")
        .env_remove("INTERFACIAL_STRICT")
        .envs(envs.iter().copied())
        .output()
        .expect("run child")
}

/// [`run_child`] with `INTERFACIAL_LOG` a fresh file (named after `tag` and this process):
/// asserts that the child succeeded, and returns its output and the text of the log (the file
/// removed).
pub fn run_child_with_log(child: &str, marker: &str, tag: &str) -> (Output, String) {
    let log = std::env::temp_dir().join(format!("interfacial-{tag}-{}.txt", std::process::id()));
    let _ = std::fs::remove_file(&log);
    let path = log.to_str().expect("a UTF-8 temporary directory");
    let out = run_child(child, marker, &[("INTERFACIAL_LOG", path)]);
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&log).expect("log written");
    let _ = std::fs::remove_file(&log);
    (out, text)
}
