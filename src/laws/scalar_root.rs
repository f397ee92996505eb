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
    f: impl FnMut(f64) -> (f64, f64),
    a: f64,
    b: f64,
    x0: f64,
    x_tol: f64,
    max_iterations: u32,
) -> Result<Root, RootFailure> {
    let mut f = without_curvature(f);
    let (low, high) = orient(&mut f, a, b)?;
    halley_on_known_bracket(f, low, high, x0, x_tol, 0.0, max_iterations)
}

/// As [`bracketed_newton`] for a bracket whose signs the caller knows, f(`low`) ≤ 0 ≤
/// f(`high`) (the two end evaluations are skipped), also stopping once |f(x)| ≤ `f_tol` (the
/// round-off level of the residual, below which Newton steps are noise).
pub fn newton_on_known_bracket(
    f: impl FnMut(f64) -> (f64, f64),
    low: f64,
    high: f64,
    x0: f64,
    x_tol: f64,
    f_tol: f64,
    max_iterations: u32,
) -> Result<Root, RootFailure> {
    halley_on_known_bracket(
        without_curvature(f),
        low,
        high,
        x0,
        x_tol,
        f_tol,
        max_iterations,
    )
}

/// Newton's method as Halley's with f'' = 0: the step 2ff'/(2f'² − f·0) is f/f'.
#[inline(always)]
fn without_curvature(mut f: impl FnMut(f64) -> (f64, f64)) -> impl FnMut(f64) -> (f64, f64, f64) {
    move |x| {
        let (v, d) = f(x);
        (v, d, 0.0)
    }
}

/// As [`newton_on_known_bracket`] with Halley's step δ = 2ff'/(2f'² − ff'') (cubic convergence)
/// when `f` also returns f''; the same safeguards (a step that leaves the bracket, or shrinks
/// too slowly, is replaced by bisection), so it cannot diverge either. Inlined, so that the
/// residual's captures stay in registers.
#[inline(always)]
pub fn halley_on_known_bracket(
    mut f: impl FnMut(f64) -> (f64, f64, f64),
    mut low: f64,
    mut high: f64,
    x0: f64,
    x_tol: f64,
    f_tol: f64,
    max_iterations: u32,
) -> Result<Root, RootFailure> {
    if low == high {
        return Ok(Root {
            x: low,
            iterations: 0,
        });
    }
    let (lo, hi) = (low.min(high), low.max(high));
    let mut x = if x0.is_finite() {
        x0.clamp(lo, hi)
    } else {
        0.5 * (low + high)
    };
    let mut step_before = (high - low).abs();
    let mut step = step_before;
    let (mut fx, mut dfx, mut ddfx) = f(x);
    for iteration in 1..=max_iterations {
        if !(fx.is_finite() && dfx.is_finite()) {
            return Err(RootFailure::NotConverged);
        }
        if fx.abs() <= f_tol {
            return Ok(Root {
                x,
                iterations: iteration - 1,
            });
        }
        if fx < 0.0 {
            low = x;
        } else {
            high = x;
        }
        // Halley's step δ = 2ff'/(2f'² − ff'') (Newton's f/f' when f'' = 0, and where the
        // curvature term would flip the step), one division per iteration.
        let denominator = 2.0 * dfx * dfx - fx * ddfx;
        let candidate = if denominator > 0.0 {
            2.0 * fx * dfx / denominator
        } else {
            fx / dfx
        };
        let target = x - candidate;
        let inside = target >= low.min(high) && target <= low.max(high);
        // Accept it when it stays inside the bracket and at least halves the step before last.
        let fast_enough = 2.0 * candidate.abs() <= step_before.abs();
        if inside && fast_enough {
            step_before = step;
            step = candidate;
            x = target;
        } else {
            step_before = step;
            step = 0.5 * (high - low);
            x = low + step;
        }
        if step.abs() <= x_tol {
            return Ok(Root {
                x,
                iterations: iteration,
            });
        }
        (fx, dfx, ddfx) = f(x);
    }
    Err(RootFailure::NotConverged)
}

/// Evaluates f at both ends and returns them as (low, high) with f(low) < 0 < f(high); a zero
/// at an end returns that end twice.
fn orient(
    f: &mut impl FnMut(f64) -> (f64, f64, f64),
    a: f64,
    b: f64,
) -> Result<(f64, f64), RootFailure> {
    let (fa, _, _) = f(a);
    let (fb, _, _) = f(b);
    if !(fa.is_finite() && fb.is_finite()) {
        return Err(RootFailure::NotBracketed);
    }
    if fa == 0.0 {
        return Ok((a, a));
    }
    if fb == 0.0 {
        return Ok((b, b));
    }
    if (fa > 0.0) == (fb > 0.0) {
        return Err(RootFailure::NotBracketed);
    }
    Ok(if fa < 0.0 { (a, b) } else { (b, a) })
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
    fn orients_a_decreasing_bracket_and_takes_a_root_at_an_end() {
        // f(x) = 3 − x², decreasing on [0, 3]: f(0) > 0 > f(3); root √3, from either end.
        for (a, b) in [(0.0, 3.0), (3.0, 0.0)] {
            let r = bracketed_newton(|x| (3.0 - x * x, -2.0 * x), a, b, 2.5, 1e-15, 50).unwrap();
            assert!((r.x - 3f64.sqrt()).abs() < 4e-16, "{r:?}");
        }
        // f(2) = 0 exactly at an end of the bracket: that end, without iterating.
        let r = bracketed_newton(|x| (x - 2.0, 1.0), -1.0, 2.0, 0.0, 1e-15, 50).unwrap();
        assert_eq!((r.x, r.iterations), (2.0, 0));
    }

    #[test]
    fn known_bracket_stops_at_the_residual_tolerance() {
        // f(x) = 1 − x: f(2) < 0 < f(0).
        let r =
            newton_on_known_bracket(|x| (1.0 - x, -1.0), 2.0, 0.0, 0.3, 0.0, 1e-12, 10).unwrap();
        assert!((r.x - 1.0).abs() <= 1e-12);
        assert!(r.iterations <= 2);
    }

    #[test]
    fn halley_converges_faster_than_newton() {
        // f(x) = e^{-x} − 0.1 on [0, 10], root ln 10, started far away.
        let f3 = |x: f64| ((-x).exp() - 0.1, -(-x).exp(), (-x).exp());
        let f2 = |x: f64| ((-x).exp() - 0.1, -(-x).exp());
        let h = halley_on_known_bracket(f3, 10.0, 0.0, 0.5, 1e-15, 0.0, 50).unwrap();
        let n = newton_on_known_bracket(f2, 10.0, 0.0, 0.5, 1e-15, 0.0, 50).unwrap();
        assert!((h.x - 10f64.ln()).abs() < 1e-14 && (n.x - 10f64.ln()).abs() < 1e-14);
        assert!(h.iterations < n.iterations, "{h:?} vs {n:?}");
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
