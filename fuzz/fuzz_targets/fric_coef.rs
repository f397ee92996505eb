//! `fric_coef_` (FRIC_COEF) and `ifl_forced_sliding` on any bytes: see
//! `src/fric_coef_case.rs` for the decoding and the properties checked.
#![no_main]

use interfacial_fuzz::fric_coef_case::CoefCall;
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: {
        // Messages go nowhere: the fuzzer meets thousands of distinct causes.
        // SAFETY: before the first call into the library, on the only thread.
        unsafe { std::env::set_var("INTERFACIAL_LOG", "/dev/null") };
    },
    |data: &[u8]| {
        let call = CoefCall::decode(data);
        if let Err(e) = call.check() {
            panic!("fric_coef_/ifl_forced_sliding property violated: {e}\ninput: {call:?}");
        }
    }
);
