//! A file removed when the process exits, for the configuration files that the fuzz targets and
//! the tests write once per process. Shared by the `gapcon` case (`super::at_exit`) and
//! tests/common/config_file.rs (included there by path).

/// Removes `path` when the process exits: C's `atexit`, which runs when the test harness (or
/// the fuzzer) returns from `main` or calls `exit`, so no configuration file is left behind in
/// the temporary directory (`scripts/test.sh` checks that). Once per process.
pub fn remove_at_exit(path: std::path::PathBuf) {
    static PATH: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
    unsafe extern "C" {
        fn atexit(f: extern "C" fn()) -> std::ffi::c_int;
    }
    extern "C" fn remove() {
        if let Some(p) = PATH.get() {
            let _ = std::fs::remove_file(p);
        }
    }
    if PATH.set(path).is_ok() {
        // SAFETY: `remove` is a plain function that only removes a file.
        unsafe { atexit(remove) };
    }
}
