//! The two ranges most law parameters are checked against when a law is built: finite and ≥ 0
//! (a coefficient, a strength, a clearance) or finite and > 0 (a stiffness, a length, a
//! reference value that divides). One message shape for every law, naming the parameter in the
//! seeds' words: "`name` = value must be finite and ≥ 0" (or "> 0").

use crate::LawError;

/// `v` when it is finite and ≥ 0; otherwise a [`LawError::Parameter`] naming `name`.
#[inline]
pub(crate) fn nonnegative(name: &str, v: f64) -> Result<f64, LawError> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(out_of_range(name, v, "≥ 0"))
    }
}

/// `v` when it is finite and > 0; otherwise a [`LawError::Parameter`] naming `name`.
#[inline]
pub(crate) fn positive(name: &str, v: f64) -> Result<f64, LawError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(out_of_range(name, v, "> 0"))
    }
}

#[cold]
#[inline(never)]
fn out_of_range(name: &str, v: f64, bound: &str) -> LawError {
    LawError::Parameter(format!("{name} = {v} must be finite and {bound}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accepts_the_range_and_names_the_parameter_outside_it() {
        assert_eq!(nonnegative("μ", 0.0).unwrap(), 0.0);
        assert_eq!(positive("k_s", 2.5).unwrap(), 2.5);
        for (v, bound) in [(-1.0, "≥ 0"), (f64::NAN, "≥ 0"), (f64::INFINITY, "≥ 0")] {
            let e = nonnegative("coeff", v).unwrap_err().to_string();
            assert!(
                e.contains(&format!("coeff = {v} must be finite and {bound}")),
                "{e}"
            );
        }
        for v in [0.0, -0.0, -2.0, f64::NAN, f64::NEG_INFINITY] {
            let e = positive("γ_crit", v).unwrap_err().to_string();
            assert!(
                e.contains(&format!("γ_crit = {v} must be finite and > 0")),
                "{e}"
            );
        }
    }
}
