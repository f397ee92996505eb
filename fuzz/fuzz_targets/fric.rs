//! `fric_` on any bytes: see `src/fric_case.rs` for the decoding and the properties checked.
#![no_main]

interfacial_fuzz::fuzz_case!(interfacial_fuzz::fric_case::FricCase, "fric_");
