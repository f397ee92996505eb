//! The contact-interface laws, one per file, each in the field's words and free of `unsafe`.

/// Builder setters that only store their argument in the field of the same name:
/// `setters! { /// doc \n with_x(field: Type); … }` writes, per line, the documented
/// `#[must_use] pub fn with_x(mut self, field: Type) -> Self`. A setter that validates its
/// argument is written out.
macro_rules! setters {
    ($($(#[$attr:meta])* $name:ident($field:ident: $ty:ty);)*) => {
        $(
            $(#[$attr])*
            #[must_use]
            pub fn $name(mut self, $field: $ty) -> Self {
                self.$field = $field;
                self
            }
        )*
    };
}

pub mod adhesive;
pub mod adhesive_interface;
pub mod coulomb;
pub mod coulomb_batch;
pub mod coulomb_extended;
pub mod coulomb_kinematic;
pub mod friction_coefficient;
pub mod friction_table;
pub mod gap_conductance;
pub mod gap_radiation;
pub mod interface_heat;
mod parameter_range;
pub mod pore_pressure;
pub mod scalar_root;
mod small_vec;
pub mod table;
