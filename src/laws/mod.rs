//! The contact-interface laws, one per file, each in the field's words and free of `unsafe`.

pub mod coulomb;
mod small_vec;
