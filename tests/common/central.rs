//! The central differences that the tangent tests compare `fric_`'s derivatives with, and the
//! steady sliding of scene F4, shared by tests/friction_extended.rs and tests/friction_table.rs
//! (included there by path), and the two-sided calls of tests/fric_weakening.rs and
//! tests/rate_state.rs.
// Each test uses its own subset.
#![allow(dead_code)]
#![allow(clippy::needless_range_loop)] // index loops mirror the a, b indices of the equations

use interfacial_test_hosts::FricCall;

/// A move of the increment's inputs: (ΔDGAM(1..2), ΔPRESS, ΔTEMP(1..2)).
pub type Shift = ([f64; 2], f64, [f64; 2]);

/// DGAM(b) moved by h: the column b of DDTDDG.
pub fn along_dgam(b: usize) -> impl Fn(f64) -> Shift {
    move |h| {
        let mut g = [0.0; 2];
        g[b] = h;
        (g, 0.0, [0.0; 2])
    }
}

/// The end pressure moved by h (`PRESS` and `DPRESS` together, the start stays): DDTDDP.
pub fn along_press(h: f64) -> Shift {
    ([0.0; 2], h, [0.0; 2])
}

/// TEMP(k) moved by h: the column k of DDTDDT.
pub fn along_temp(k: usize) -> impl Fn(f64) -> Shift {
    move |h| {
        let mut t = [0.0; 2];
        t[k] = h;
        ([0.0; 2], 0.0, t)
    }
}

/// (TAU(a)(+h) − TAU(a)(−h)) / 2h along `shift`, `call_at` making the `fric_` call with the
/// inputs moved; `None` when a side was refused or stuck exactly (`PNEWDT` lowered, `LM` ≠ 0),
/// when the two sides are in different branches (`STATEV(3)` differs), or when the steps h and
/// 2h disagree by more than 10⁻⁷·`scale` (the stencil crosses a kink).
pub fn central_tau(
    a: usize,
    h: f64,
    scale: f64,
    shift: impl Fn(f64) -> Shift,
    call_at: impl Fn(Shift) -> FricCall,
) -> Option<f64> {
    let fd = |h: f64| {
        let up = call_at(shift(h));
        let dn = call_at(shift(-h));
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

/// `call` made twice, its inputs moved by +h and by −h (`shift(call, ±h)`): the two sides of a
/// central difference, (plus, minus).
pub fn sides(call: &FricCall, h: f64, shift: impl Fn(&mut FricCall, f64)) -> (FricCall, FricCall) {
    let (mut plus, mut minus) = (call.clone(), call.clone());
    shift(&mut plus, h);
    shift(&mut minus, -h);
    plus.call();
    minus.call();
    (plus, minus)
}

/// The `shift` of [`sides`] for DDTDDP: the end pressure moved (`PRESS` and `DPRESS` together,
/// the start stays).
pub fn move_press(c: &mut FricCall, h: f64) {
    c.press += h;
    c.dpress += h;
}

/// (TAU(a) of `plus` − TAU(a) of `minus`) / 2h, the sides of [`sides`].
pub fn slope(plus: &FricCall, minus: &FricCall, a: usize, h: f64) -> f64 {
    (plus.tau[a] - minus.tau[a]) / (2.0 * h)
}

/// Slides the point `c` (`nfdir` directions) along `dir` at the slip velocity `v` for `n`
/// increments of `c.dtime`, each one answered in slip (`LM` = 0, no cut-back); |τ| at the end.
pub fn slide_steadily(c: &mut FricCall, nfdir: usize, dir: [f64; 2], v: f64, n: usize) -> f64 {
    for _ in 0..n {
        for i in 0..nfdir {
            c.dgam[i] = dir[i] * v * c.dtime;
        }
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        assert_eq!(c.lm, 0);
    }
    (0..nfdir).map(|i| c.tau[i].powi(2)).sum::<f64>().sqrt()
}
