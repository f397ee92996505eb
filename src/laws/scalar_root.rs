//! A safeguarded Newton method for one scalar equation f(x) = 0 on a bracket [a, b] with
//! f(a)·f(b) ≤ 0: a Newton step is taken when it stays inside the current bracket and shrinks
//! the residual fast enough, a bisection step otherwise. The bracket shrinks at every step, so
//! the iteration cannot diverge; it converges quadratically near a simple root.
//!
//! Used by the return map of rate-dependent friction, where the slip increment solves a scalar
//! nonlinear equation (the critical stress depends on the end-of-increment slip rate).

/// A root and the number of function evaluations after the two at the bracket ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Root {
    /// The root.
    pub x: f64,
    /// Newton or bisection steps taken.
    pub iterations: u32,
}

/// Why no root was returned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RootFailure {
    /// f has the same sign at both ends of the bracket (or is not finite there).
    NotBracketed,
    /// The iteration limit was reached (or f became non-finite inside the bracket).
    NotConverged,
}

/// Solves f(x) = 0 for x in [a, b], starting from `x0` (clipped into the bracket). `f` returns
/// (f(x), f'(x)). Stops when the step is below `x_tol` or f(x) = 0 exactly.
pub fn bracketed_newton(
    mut f: impl FnMut(f64) -> (f64, f64),
    a: f64,
    b: f64,
    x0: f64,
    x_tol: f64,
    max_iterations: u32,
) -> Result<Root, RootFailure> {
    let (fa, _) = f(a);
    let (fb, _) = f(b);
    if !(fa.is_finite() && fb.is_finite()) {
        return Err(RootFailure::NotBracketed);
    }
    if fa == 0.0 {
        return Ok(Root {
            x: a,
            iterations: 0,
        });
    }
    if fb == 0.0 {
        return Ok(Root {
            x: b,
            iterations: 0,
        });
    }
    if (fa > 0.0) == (fb > 0.0) {
        return Err(RootFailure::NotBracketed);
    }
    // Orient the bracket so that f(low) < 0 < f(high).
    let (mut low, mut high) = if fa < 0.0 { (a, b) } else { (b, a) };
    let (lo, hi) = (a.min(b), a.max(b));
    let mut x = if x0.is_finite() {
        x0.clamp(lo, hi)
    } else {
        0.5 * (a + b)
    };
    let mut step_before = (b - a).abs();
    let mut step = step_before;
    let (mut fx, mut dfx) = f(x);
    for iteration in 1..=max_iterations {
        if !(fx.is_finite() && dfx.is_finite()) {
            return Err(RootFailure::NotConverged);
        }
        if fx == 0.0 {
            return Ok(Root {
                x,
                iterations: iteration - 1,
            });
        }
        let newton_leaves_bracket = ((x - high) * dfx - fx) * ((x - low) * dfx - fx) > 0.0;
        let newton_too_slow = (2.0 * fx).abs() > (step_before * dfx).abs();
        if newton_leaves_bracket || newton_too_slow || dfx == 0.0 {
            step_before = step;
            step = 0.5 * (high - low);
            x = low + step;
        } else {
            step_before = step;
            step = fx / dfx;
            x -= step;
        }
        if step.abs() <= x_tol {
            return Ok(Root {
                x,
                iterations: iteration,
            });
        }
        (fx, dfx) = f(x);
        if fx < 0.0 {
            low = x;
        } else {
            high = x;
        }
    }
    Err(RootFailure::NotConverged)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_simple_root_quadratically() {
        let r = bracketed_newton(|x| (x * x - 2.0, 2.0 * x), 0.0, 2.0, 1.0, 1e-15, 50).unwrap();
        assert!((r.x - 2f64.sqrt()).abs() < 1e-15);
        assert!(r.iterations <= 7, "{r:?}");
    }

    #[test]
    fn survives_a_bad_derivative() {
        // A wrong (zero, then tiny) derivative forces bisection; the bracket still holds.
        let r = bracketed_newton(|x| (x.powi(3) - 0.001, 0.0), -1.0, 1.0, 0.9, 1e-14, 200).unwrap();
        assert!((r.x - 0.1).abs() < 1e-13);
    }

    #[test]
    fn reports_no_bracket() {
        assert_eq!(
            bracketed_newton(|x| (x * x + 1.0, 2.0 * x), -1.0, 1.0, 0.0, 1e-12, 50),
            Err(RootFailure::NotBracketed)
        );
        assert_eq!(
            bracketed_newton(|x| (x - 0.3, 1.0), 0.0, 1.0, 0.5, 0.0, 1),
            Err(RootFailure::NotConverged)
        );
    }
}
