//! The TOML configuration parser on any bytes: see `src/config_case.rs`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(e) = interfacial_fuzz::config_case::check(data) {
        panic!("configuration parser property violated: {e}");
    }
});
