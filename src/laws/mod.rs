//! The contact-interface laws, one per file, each in the field's words and free of `unsafe`.

/// The [`coulomb::StatusCode`] of a status enum: the law a short `STATEV` message names, and
/// the codes other than 0 (stick, also what an unknown code reads as):
/// `status_codes!(Enum, "the law", 1.0 => Variant, …)`. The stored code is the discriminant.
macro_rules! status_codes {
    ($status:ident, $law:literal, $($code:literal => $variant:ident),+) => {
        impl StatusCode for $status {
            const LAW: &'static str = $law;

            #[inline(always)]
            fn from_code(code: f64) -> Self {
                match code {
                    $($code => $status::$variant,)+
                    _ => $status::Stick,
                }
            }

            #[inline(always)]
            fn code(self) -> f64 {
                f64::from(self as i32)
            }
        }
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
