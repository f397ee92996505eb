//! `uinter_` on any bytes: see `src/uinter_case.rs` for the decoding and the properties checked.
#![no_main]

use interfacial_fuzz::gapcon_case::setup;
use interfacial_fuzz::uinter_case::UinterCase;
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: setup(),
    |data: &[u8]| {
        let case = UinterCase::decode(data);
        if let Err(e) = case.check() {
            panic!("uinter_ property violated: {e}\ninput: {case:?}");
        }
    }
);
