//! `gapcon_` on any bytes: see `src/gapcon_case.rs` for the configuration, the decoding and the
//! properties checked.
#![no_main]

use interfacial_fuzz::gapcon_case::{GapconCase, setup};
use libfuzzer_sys::fuzz_target;

fuzz_target!(
    init: setup(),
    |data: &[u8]| {
        let case = GapconCase::decode(data);
        if let Err(e) = case.check() {
            panic!("gapcon_ property violated: {e}\ninput: {case:?}");
        }
    }
);
