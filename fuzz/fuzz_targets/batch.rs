//! `ifl_fric_batch` on any bytes: see `src/batch_case.rs` for the decoding and the properties.
#![no_main]

use interfacial_fuzz::batch_case::BatchCase;
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: {
        // Messages go nowhere: the fuzzer meets thousands of distinct causes.
        // SAFETY: before the first call into the library, on the only thread.
        unsafe { std::env::set_var("INTERFACIAL_LOG", "/dev/null") };
    },
    |data: &[u8]| {
        let case = BatchCase::decode(data);
        if let Err(e) = case.check() {
            panic!("ifl_fric_batch property violated: {e}\ninput: {case:?}");
        }
    }
);
