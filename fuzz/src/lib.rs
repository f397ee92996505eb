//! Decoders and property checks of the fuzz targets. The modules are also compiled into
//! `tests/fuzz_regressions.rs` by path, so a crash input replays as a plain `cargo test`.

pub mod batch_case;
pub mod bytes;
pub mod config_case;
pub mod fric_case;
pub mod fric_coef_case;
pub mod gapcon_case;
pub mod uinter_case;
pub mod vfric_case;
