//! `ifl_fric_batch` on any bytes: see `src/batch_case.rs` for the decoding and the properties.
#![no_main]

interfacial_fuzz::fuzz_case!(interfacial_fuzz::batch_case::BatchCase, "ifl_fric_batch");
