//! The contact-interface laws, one per file, each in the field's words and free of `unsafe`.

pub mod adhesive;
pub mod adhesive_interface;
pub mod coulomb;
pub mod gap_conductance;
pub mod gap_radiation;
mod small_vec;
pub mod table;
