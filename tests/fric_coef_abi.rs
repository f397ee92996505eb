//! `fric_coef_` (Abaqus FRIC_COEF, current form) through its C ABI: μ of a block of points for
//! every μ law of PROPS law 1, its derivatives against central differences, agreement with the
//! steady sliding stress of `fric_`, and bad input.

#[path = "common/fric_coef.rs"]
mod fric_coef_common;
use fric_coef_common::fric_coef_call;
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;

const GUARD: f64 = -7.77e77;

/// One FRIC_COEF call's arrays, with guard slots after each output.
struct Block {
    coef: Vec<f64>,
    deriv: Vec<f64>,
    n: usize,
}

impl Block {
    fn mu(&self, k: usize, d: usize) -> f64 {
        self.coef[k + self.n * d]
    }
    fn deriv(&self, k: usize, j: usize, d: usize) -> f64 {
        self.deriv[k + self.n * (j + 20 * d)]
    }
    fn guards_intact(&self) -> bool {
        self.coef[2 * self.n..].iter().all(|x| *x == GUARD)
            && self.deriv[40 * self.n..].iter().all(|x| *x == GUARD)
    }
}

fn fric_coef(props: &[f64], rate: &[f64], p: &[f64], temp: &[f64]) -> Block {
    let n = rate.len();
    let mut coef = vec![GUARD; 2 * n + 3];
    let mut deriv = vec![GUARD; 40 * n + 3];
    let mut slip = vec![0.0; 6 * n];
    slip[..n].copy_from_slice(rate);
    let name = *b"SI1                                                                             ";
    fric_coef_call(&mut coef, &mut deriv, props, &slip, p, temp, &name);
    Block { coef, deriv, n }
}

/// Law 1 with γ_crit = 10⁻³ and these μ-law entries, `PROPS(1..13)` (what `fric_coef_` reads).
fn props(
    mu: f64,
    mu2: f64,
    decay: Option<(f64, f64)>,
    p_ref: f64,
    temp: Option<(f64, f64)>,
) -> Vec<f64> {
    let mut v = CoulombBuilder::new()
        .mu(mu)
        .mu2(mu2)
        .gamma_crit(1e-3)
        .p_ref(p_ref);
    if let Some((mk, dc)) = decay {
        v = v.mu_law(1.0).mu_k(mk).decay(dc);
    }
    if let Some((b, t)) = temp {
        v = v.b_theta(b).theta_ref(t);
    }
    v.build_first(13)
}

#[test]
fn closed_form_values_both_directions() {
    // μ = (μ_k + (μ_s − μ_k) e^{−d v})/(1 + p/p_ref) · e^{−b(θ − θ_ref)}.
    let pr = props(0.6, 0.3, Some((0.2, 2.0)), 100.0, Some((0.01, 20.0)));
    let b = fric_coef(
        &pr,
        &[0.0, 0.5, 3.0],
        &[0.0, 100.0, 50.0],
        &[20.0, 120.0, 20.0],
    );
    assert!(b.guards_intact());
    let expected = |v: f64, p: f64, t: f64| {
        (0.2 + 0.4 * (-2.0 * v).exp()) / (1.0 + p / 100.0) * (-0.01 * (t - 20.0)).exp()
    };
    for (k, (v, p, t)) in [(0.0, 0.0, 20.0), (0.5, 100.0, 120.0), (3.0, 50.0, 20.0)]
        .into_iter()
        .enumerate()
    {
        let m = expected(v, p, t);
        assert!((b.mu(k, 0) - m).abs() < 1e-15, "{k}");
        assert!((b.mu(k, 1) - 0.5 * m).abs() < 1e-15, "{k}");
        for j in 3..20 {
            assert_eq!(b.deriv(k, j, 0), 0.0);
            assert_eq!(b.deriv(k, j, 1), 0.0);
        }
    }
    // Isotropic, constant: μ in both columns, zero derivatives.
    let b = fric_coef(
        &CoulombBuilder::new().mu(0.4).build_first(2),
        &[1.0],
        &[10.0],
        &[0.0],
    );
    assert_eq!((b.mu(0, 0), b.mu(0, 1)), (0.4, 0.4));
    assert!((0..40).all(|i| b.deriv[i] == 0.0));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, failure_persistence: None, ..ProptestConfig::default() })]

    /// fCoefDeriv(k,1..3,d) against central differences of fCoef in rate, pressure and
    /// temperature, for every law combination.
    #[test]
    fn derivatives_match_central_differences(
        mu in 0.05..1.0f64,
        ratio in prop_oneof![Just(0.0), 0.2..3.0f64],
        decay in prop_oneof![Just(None), (0.0..2.0f64, 0.1..20.0f64).prop_map(Some)],
        p_ref in prop_oneof![Just(0.0), 5.0..500.0f64],
        temp in prop_oneof![Just(None), (-0.05..0.05f64, -50.0..100.0f64).prop_map(Some)],
        v in 0.0..5.0f64,
        p in 0.0..300.0f64,
        t in -50.0..200.0f64,
    ) {
        let pr = props(mu, ratio * mu, decay.map(|(r, d)| (r * mu, d)), p_ref, temp);
        let b = fric_coef(&pr, &[v], &[p], &[t]);
        prop_assert!(b.guards_intact());
        let steps = [1e-6 * (1.0 + v), 1e-6 * (1.0 + p), 1e-5];
        for (j, h) in steps.into_iter().enumerate() {
            let shift = |s: f64| {
                let mut x = [v, p, t];
                x[j] += s;
                x
            };
            let (up, dn) = (shift(h), shift(-h));
            // Stay on the documented domain (rate ≥ 0, p ≥ 0).
            if dn[0] < 0.0 || dn[1] < 0.0 {
                continue;
            }
            let bu = fric_coef(&pr, &[up[0]], &[up[1]], &[up[2]]);
            let bd = fric_coef(&pr, &[dn[0]], &[dn[1]], &[dn[2]]);
            for d in 0..2 {
                let fd = (bu.mu(0, d) - bd.mu(0, d)) / (2.0 * h);
                let an = b.deriv(0, j, d);
                let scale = b.mu(0, d).max(1e-3) * (1.0 + 20.0 / (1.0 + p));
                prop_assert!((fd - an).abs() <= 1e-6 * scale,
                    "fCoefDeriv(1,{},{}): analytic {an}, central difference {fd}", j + 1, d + 1);
            }
        }
    }
}

/// FRIC_COEF and FRIC agree: steady sliding at rate v through `fric_` gives τ = μ(v)·p with the
/// μ that `fric_coef_` returns for that rate and pressure.
#[test]
fn agrees_with_steady_sliding_through_fric() {
    // NPROPS = 20: the whole law-1 layout, as fric_ reads it.
    let mut pr = props(0.5, 0.0, Some((0.25, 3.0)), 200.0, None);
    pr.resize(20, 0.0);
    let (p, v, dt) = (80.0, 0.7, 0.01);
    let mut c = FricCall::new(1, &pr);
    c.press = p;
    c.dtime = dt;
    for _ in 0..40 {
        c.dgam[0] = v * dt;
        c.call();
        c.dpress = 0.0;
    }
    let b = fric_coef(&pr, &[v], &[p], &[0.0]);
    assert!((c.tau[0] - b.mu(0, 0) * p).abs() < 1e-12 * c.tau[0]);
}

/// Bad input: one message naming FRIC_COEF and the cause, μ = 0 and zero derivatives for the
/// whole block, nothing written past the arrays.
#[test]
fn bad_input_is_refused_cleanly() {
    let good = props(0.5, 0.0, Some((0.25, 3.0)), 0.0, Some((0.01, 0.0)));
    /// (what, PROPS, slip rates, pressures, temperatures, word in the message)
    type Case = (
        &'static str,
        Vec<f64>,
        [f64; 2],
        [f64; 2],
        [f64; 2],
        &'static str,
    );
    let cases: &[Case] = &[
        (
            "μ_s < 0",
            props(-0.5, 0.0, None, 0.0, None),
            [0.1; 2],
            [1.0; 2],
            [0.0; 2],
            "PROPS(2)",
        ),
        (
            "d_c < 0",
            props(0.5, 0.0, Some((0.2, -1.0)), 0.0, None),
            [0.1; 2],
            [1.0; 2],
            [0.0; 2],
            "PROPS(10)",
        ),
        (
            "negative rate",
            good.clone(),
            [0.1, -0.1],
            [1.0; 2],
            [0.0; 2],
            "slipData(2, 1)",
        ),
        (
            "NaN pressure",
            good.clone(),
            [0.1; 2],
            [f64::NAN, 1.0],
            [0.0; 2],
            "pressure(1)",
        ),
        (
            "adhesive law",
            AdhesiveBuilder::new()
                .coeff(0.3)
                .coeff_static(0.5)
                .sa(1.0)
                .vhalf(0.1)
                .gamma_crit(1e-3)
                .build_first(8),
            [0.1; 2],
            [1.0; 2],
            [0.0; 2],
            "PROPS(1) = 2",
        ),
        (
            "Inf temperature",
            good.clone(),
            [0.1; 2],
            [1.0; 2],
            [0.0, f64::INFINITY],
            "tempAvg(2)",
        ),
    ];
    for (what, pr, rate, p, t, word) in cases {
        let b = fric_coef(pr, rate, p, t);
        let msg = FricCall::last_error();
        assert!(
            msg.contains("FRIC_COEF") && msg.contains(word),
            "{what}: {msg}"
        );
        assert!(b.coef[..4].iter().all(|x| *x == 0.0), "{what}");
        assert!(b.deriv[..80].iter().all(|x| *x == 0.0), "{what}");
        assert!(b.guards_intact(), "{what}");
    }
}
