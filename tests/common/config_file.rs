//! The configuration file of a test binary: the library reads `INTERFACIAL_CONFIG` once per
//! process, so a binary whose tests need interactions writes its file and sets the variable once,
//! before its first call into the library. Shared by bad_input.rs, friction_table.rs,
//! gapcon_abi.rs, last_error.rs and uinter_thermal.rs (included there by path).

use std::sync::Once;

// The same removal the fuzz targets' configuration file takes.
#[path = "../../fuzz/src/at_exit.rs"]
mod at_exit;
use at_exit::remove_at_exit;

/// Writes `toml` to `interfacial-TAG-PID.toml` in the temporary directory and points
/// `INTERFACIAL_CONFIG` at it, the first time it is called in this process; later calls (from
/// other tests, on other threads) wait for the first and do nothing. The file is removed when
/// the process exits. Every test of the binary that reaches the library calls it first.
pub fn config_once(tag: &str, toml: &str) {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let path =
            std::env::temp_dir().join(format!("interfacial-{tag}-{}.toml", std::process::id()));
        std::fs::write(&path, toml).expect("cannot write the test's configuration file");
        // SAFETY: set once, before any thread of this binary calls into the library: every test
        // calls config_once first, and Once blocks the others until it is done.
        unsafe { std::env::set_var("INTERFACIAL_CONFIG", &path) };
        remove_at_exit(path);
    });
}
