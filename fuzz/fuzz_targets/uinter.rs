//! `uinter_` on any bytes: see `src/uinter_case.rs` for the decoding and the properties checked.
#![no_main]

use interfacial_fuzz::gapcon_case::setup;
use interfacial_fuzz::uinter_case::UinterCase;

interfacial_fuzz::fuzz_case!(UinterCase, "uinter_", init: setup());
