//! `vfric_` (Abaqus/Explicit VFRIC) on any bytes: see `src/vfric_case.rs` for the decoding and
//! the properties checked.
#![no_main]

interfacial_fuzz::fuzz_case!(interfacial_fuzz::vfric_case::VfricCase, "vfric_");
