//! The contact-interface laws, one per file, each in the field's words and free of `unsafe`.

pub mod adhesive;
pub mod adhesive_interface;
pub mod contact;
pub mod coulomb;
pub mod coulomb_batch;
pub mod coulomb_extended;
pub mod coulomb_kinematic;
pub mod friction_coefficient;
pub mod friction_table;
pub mod frictional_heat;
pub mod gap_conductance;
pub mod gap_radiation;
pub mod interface_heat;
mod parameter_range;
pub mod point_law;
pub mod pore_pressure;
pub mod rate_state;
pub mod scalar_root;
mod small_vec;
pub mod table;
