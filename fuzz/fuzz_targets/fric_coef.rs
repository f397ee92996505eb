//! `fric_coef_` (FRIC_COEF) and `ifl_forced_sliding` on any bytes: see
//! `src/fric_coef_case.rs` for the decoding and the properties checked.
#![no_main]

interfacial_fuzz::fuzz_case!(
    interfacial_fuzz::fric_coef_case::CoefCall,
    "fric_coef_/ifl_forced_sliding"
);
