//! `fric_` on any bytes: see `src/fric_case.rs` for the decoding and the properties checked.
#![no_main]

use interfacial_fuzz::fric_case::FricCase;
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: {
        // Messages go nowhere: the fuzzer meets thousands of distinct causes.
        // SAFETY: before the first call into the library, on the only thread.
        unsafe { std::env::set_var("INTERFACIAL_LOG", "/dev/null") };
    },
    |data: &[u8]| {
        let case = FricCase::decode(data);
        if let Err(e) = case.check() {
            panic!("fric_ property violated: {e}\ninput: {case:?}");
        }
    }
);
