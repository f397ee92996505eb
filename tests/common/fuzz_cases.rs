//! The fuzz targets' decoders and property checks (`fuzz/src`), compiled into a test by path:
//! `#[path = "common/fuzz_cases.rs"] mod fuzz_cases;`, then `use fuzz_cases::fric_case::…`. The
//! case modules name each other by `super::`, so they build here as they do in the fuzz crate,
//! and a crash input replays as a plain `cargo test`.
// Each test uses its own subset.
#![allow(dead_code)]

#[path = "../../fuzz/src/args.rs"]
pub mod args;
#[path = "../../fuzz/src/at_exit.rs"]
pub mod at_exit;
#[path = "../../fuzz/src/batch_case.rs"]
pub mod batch_case;
#[path = "../../fuzz/src/bytes.rs"]
pub mod bytes;
#[path = "../../fuzz/src/contract.rs"]
pub mod contract;
#[path = "../../fuzz/src/fric_case.rs"]
pub mod fric_case;
#[path = "../../fuzz/src/fric_coef_case.rs"]
pub mod fric_coef_case;
#[path = "../../fuzz/src/gapcon_case.rs"]
pub mod gapcon_case;
#[path = "../../fuzz/src/uinter_case.rs"]
pub mod uinter_case;
// The decoder speaks the double-precision `vfric_` (tests/fuzz_regressions_vfric.rs).
#[cfg(not(feature = "explicit-single"))]
#[path = "../../fuzz/src/vfric_case.rs"]
pub mod vfric_case;
