//! `gapcon_` on any bytes: see `src/gapcon_case.rs` for the configuration, the decoding and the
//! properties checked.
#![no_main]

use interfacial_fuzz::gapcon_case::{GapconCase, setup};

interfacial_fuzz::fuzz_case!(GapconCase, "gapcon_", init: setup());
