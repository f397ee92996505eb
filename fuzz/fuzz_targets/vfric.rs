//! `vfric_` (Abaqus/Explicit VFRIC) on any bytes: see `src/vfric_case.rs` for the decoding and
//! the properties checked.
#![no_main]

use interfacial_fuzz::vfric_case::VfricCase;
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: {
        // Messages go nowhere: the fuzzer meets thousands of distinct causes.
        // SAFETY: before the first call into the library, on the only thread.
        unsafe { std::env::set_var("INTERFACIAL_LOG", "/dev/null") };
    },
    |data: &[u8]| {
        let call = VfricCase::decode(data);
        if let Err(e) = call.check() {
            panic!("vfric_ property violated: {e}\ninput: {call:?}");
        }
    }
);
