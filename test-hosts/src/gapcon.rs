//! A host's side of `gapcon_`: the GAPCON arguments a test varies, and a `call` that passes them
//! by reference as an FE code does, with the variant's argument list (`AREA` after `KINC` with
//! the `calculix` feature, as the library's own `gapcon_`).

use std::ffi::c_char;

use interfacial::abi::gapcon_;

use crate::{GUARD, blank_padded};

/// All GAPCON arguments of one point, passed to `gapcon_` as a Fortran host does.
#[derive(Clone, Debug)]
pub struct GapconCall {
    /// `AK(5)`; `AK(2..5)` hold [`GUARD`] to prove they are not written.
    pub ak: [f64; 5],
    /// `D(2)`: clearance, contact pressure.
    pub d: [f64; 2],
    /// `TEMP(2)`: surface temperatures θ_A, θ_B.
    pub temp: [f64; 2],
    /// `CINAME` (blank-padded to `name_len` at the call).
    pub ciname: String,
    /// Hidden length of `CINAME`.
    pub name_len: usize,
    /// `NOEL`.
    pub noel: i32,
    /// `NODE`.
    pub node: i32,
}

impl GapconCall {
    /// A point of interaction `name` at clearance `d`, pressure `p`, temperatures θ_A, θ_B.
    #[must_use]
    pub fn new(name: &str, d: f64, p: f64, theta_a: f64, theta_b: f64) -> Self {
        GapconCall {
            ak: [GUARD; 5],
            d: [d, p],
            temp: [theta_a, theta_b],
            ciname: name.into(),
            name_len: 80,
            noel: 1,
            node: 1,
        }
    }

    /// Calls `gapcon_` (the variant this crate was built with) and returns `AK(1)`.
    pub fn call(&mut self) -> f64 {
        let len = self.name_len;
        let name = blank_padded(&self.ciname, len);
        let blank = [b' '; 80];
        let zeros = [0.0f64; 4];
        let (one, zero) = (1i32, 0i32);
        // SAFETY: every pointer refers to a field of `self` or a local that outlives the call,
        // sized as GAPCON's contract requires.
        unsafe {
            gapcon_(
                self.ak.as_mut_ptr(),
                self.d.as_ptr(),
                zeros.as_ptr(),
                self.temp.as_ptr(),
                zeros.as_ptr(),
                zeros.as_ptr(),
                name.as_ptr().cast::<c_char>(),
                blank.as_ptr().cast::<c_char>(),
                blank.as_ptr().cast::<c_char>(),
                zeros.as_ptr(),
                &self.noel,
                &self.node,
                &zero,
                &one,
                &one,
                #[cfg(feature = "calculix")]
                &1.0,
                len,
                80,
                80,
            );
        }
        self.ak[0]
    }
}
