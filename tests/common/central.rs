//! The central difference that the tangent tests compare `fric_`'s derivatives with, shared by
//! tests/friction_extended.rs and tests/friction_table.rs (included there by path).

use interfacial::abi::host::FricCall;

/// (TAU(a)(+h) − TAU(a)(−h)) / 2h, where `call_at(h)` is the `fric_` call with the input moved
/// by h; `None` when a side was refused or stuck exactly (`PNEWDT` lowered, `LM` ≠ 0), when the
/// two sides are in different branches (`STATEV(3)` differs), or when the steps h and 2h
/// disagree by more than 10⁻⁷·`scale` (the stencil crosses a kink).
pub fn central_tau(a: usize, h: f64, scale: f64, call_at: impl Fn(f64) -> FricCall) -> Option<f64> {
    let fd = |h: f64| {
        let up = call_at(h);
        let dn = call_at(-h);
        if up.pnewdt != 1e36 || dn.pnewdt != 1e36 || up.lm != 0 || dn.lm != 0 {
            return None;
        }
        if up.statev[2] != dn.statev[2] {
            return None;
        }
        Some((up.tau[a] - dn.tau[a]) / (2.0 * h))
    };
    let (f1, f2) = (fd(h)?, fd(2.0 * h)?);
    ((f1 - f2).abs() <= 1e-7 * scale).then_some(f1)
}
