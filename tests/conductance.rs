//! Gap conductance laws: every derivative against central finite differences, in every table
//! segment and outside the tables; the flux derivatives against finite differences of
//! q = k(θ_A − θ_B); closed forms of each law.

use interfacial::laws::gap_conductance::{Conduction, GapLaw};
use interfacial::laws::gap_radiation::Radiation;
use interfacial::laws::table::{Table1, TemperatureTable};
use proptest::prelude::*;

fn pressure_table_law() -> GapLaw {
    // Three temperatures × four pressures, uneven spacing: 9 interior segments in p, 2 in θ̄.
    let mut rows = Vec::new();
    for (theta, scale) in [(250.0, 1.0), (300.0, 1.6), (420.0, 2.1)] {
        for (p, k) in [(0.0, 100.0), (10.0, 400.0), (35.0, 900.0), (80.0, 1000.0)] {
            rows.push((p, k * scale, theta));
        }
    }
    GapLaw::new(
        Some(Conduction::pressure_table(TemperatureTable::new(&rows).unwrap()).unwrap()),
        None,
    )
    .unwrap()
}

fn clearance_table_law() -> GapLaw {
    let t = Table1::new(&[(0.0, 5000.0), (1e-4, 800.0), (5e-4, 100.0), (2e-3, 20.0)]).unwrap();
    GapLaw::new(
        Some(Conduction::clearance_table(TemperatureTable::constant_in_temperature(t)).unwrap()),
        None,
    )
    .unwrap()
}

fn gas_law() -> GapLaw {
    GapLaw::new(Some(Conduction::gas_gap(0.026, 1e-5, 1e-6).unwrap()), None).unwrap()
}

fn cmy_law() -> GapLaw {
    GapLaw::new(
        Some(Conduction::solid_spot(1.25, 20.0, 0.1, 2e-6, 2e9).unwrap()),
        None,
    )
    .unwrap()
}

fn radiation_law(with_gas: bool) -> GapLaw {
    let gas = with_gas.then(|| Conduction::gas_gap(0.026, 1e-5, 1e-6).unwrap());
    GapLaw::new(
        gas,
        Some(Radiation::new(0.8, 5.670374419e-8, -273.15).unwrap()),
    )
    .unwrap()
}

/// Central difference of f at x with step h.
fn cd(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (f(x + h) - f(x - h)) / (2.0 * h)
}

fn close(an: f64, fd: f64, scale: f64) -> bool {
    (an - fd).abs() <= 1e-6 * scale + 1e-7 * an.abs()
}

/// Checks every derivative of `law` at (d, p, θ_A, θ_B) against central differences.
fn check(
    law: &GapLaw,
    d: f64,
    p: f64,
    ta: f64,
    tb: f64,
    hd: f64,
    hp: f64,
) -> Result<(), TestCaseError> {
    let r = law.evaluate(d, p, ta, tb).unwrap();
    let k = |d: f64, p: f64, ta: f64, tb: f64| law.evaluate(d, p, ta, tb).unwrap().k;
    let q = |ta: f64, tb: f64| k(d, p, ta, tb) * (ta - tb);
    let scale = r.k.abs().max(1e-12);
    let ht = 1e-4;
    let fd_d = cd(|x| k(x, p, ta, tb), d, hd);
    prop_assert!(
        close(r.dk_dd * hd, fd_d * hd, scale),
        "∂k/∂d {} vs {fd_d}",
        r.dk_dd
    );
    let fd_p = cd(|x| k(d, x, ta, tb), p, hp);
    prop_assert!(
        close(r.dk_dp * hp, fd_p * hp, scale),
        "∂k/∂p {} vs {fd_p}",
        r.dk_dp
    );
    // θ̄ moves both temperatures together, keeping θ_A − θ_B.
    let fd_t = cd(|x| k(d, p, ta + x, tb + x), 0.0, ht);
    prop_assert!(
        close(r.dk_dtheta_mean, fd_t, scale / 100.0),
        "∂k/∂θ̄ {} vs {fd_t}",
        r.dk_dtheta_mean
    );
    let qscale = scale * (1.0 + (ta - tb).abs());
    let fd_a = cd(|x| q(x, tb), ta, ht);
    prop_assert!(
        close(r.dq_dtheta_a, fd_a, qscale),
        "∂q/∂θ_A {} vs {fd_a}",
        r.dq_dtheta_a
    );
    let fd_b = cd(|x| q(ta, x), tb, ht);
    prop_assert!(
        close(r.dq_dtheta_b, fd_b, qscale),
        "∂q/∂θ_B {} vs {fd_b}",
        r.dq_dtheta_b
    );
    Ok(())
}

/// True when x is within `margin` of a breakpoint (derivatives jump there).
fn near(x: f64, points: &[f64], margin: f64) -> bool {
    points.iter().any(|b| (x - b).abs() < margin)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, max_global_rejects: 100_000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn pressure_table_derivatives(p in -20.0..110.0f64, tm in 200.0..470.0f64, dt in -30.0..30.0f64) {
        prop_assume!(!near(p, &[0.0, 10.0, 35.0, 80.0], 1e-3));
        // θ_A, θ_B ± 1e-4 must stay on one side of a tabulated temperature.
        prop_assume!(!near(tm, &[250.0, 300.0, 420.0], 1e-3));
        check(&pressure_table_law(), 0.0, p, tm + dt / 2.0, tm - dt / 2.0, 1e-9, 1e-6)?;
    }

    #[test]
    fn clearance_table_derivatives(d in -1e-4..3e-3f64, dt in -30.0..30.0f64) {
        prop_assume!(!near(d, &[0.0, 1e-4, 5e-4, 2e-3], 1e-9));
        check(&clearance_table_law(), d, 10.0, 300.0 + dt, 300.0, 1e-12, 1e-6)?;
    }

    #[test]
    fn gas_gap_derivatives(d in -1e-4..1e-2f64) {
        prop_assume!(!near(d, &[1e-6], 1e-9));
        check(&gas_law(), d, 5.0, 320.0, 300.0, 1e-12, 1e-6)?;
    }

    #[test]
    fn cmy_derivatives(p in -1e6..5e8f64) {
        prop_assume!(p.abs() > 1e3);
        check(&cmy_law(), 0.0, p, 320.0, 300.0, 1e-9, 1e-2)?;
    }

    #[test]
    fn radiation_derivatives(ta in -200.0..1500.0f64, tb in -200.0..1500.0f64, gas in any::<bool>()) {
        check(&radiation_law(gas), 1e-4, 0.0, ta, tb, 1e-12, 1e-6)?;
    }
}

#[test]
fn closed_forms() {
    let r = |law: &GapLaw, d: f64, p: f64, ta: f64, tb: f64| law.evaluate(d, p, ta, tb).unwrap();
    // Pressure table at θ̄ = 300 (second temperature, scale 1.6): between 10 and 35 →
    // k = 1.6·(400 + (p − 10)·500/25); outside: the first / last row.
    let pt = pressure_table_law();
    assert!((r(&pt, 0.0, 20.0, 300.0, 300.0).k - 1.6 * 600.0).abs() < 1e-9);
    assert_eq!(r(&pt, 0.0, -5.0, 300.0, 300.0).k, 1.6 * 100.0);
    assert_eq!(r(&pt, 0.0, 500.0, 300.0, 300.0).k, 1.6 * 1000.0);
    // Halfway between 250 and 300: the mean of the two tables.
    assert!((r(&pt, 0.0, 20.0, 275.0, 275.0).k - 1.3 * 600.0).abs() < 1e-9);
    // Gas gap: k_gas/(d + g0), and min_gap below it.
    let g = gas_law();
    assert!((r(&g, 1e-4, 0.0, 0.0, 0.0).k - 0.026 / 1.1e-4).abs() < 1e-9);
    assert!((r(&g, -1.0, 0.0, 0.0, 0.0).k - 0.026 / 1.1e-5).abs() < 1e-9);
    // CMY: 1.25·(20·0.1/2e-6)·(p/2e9)^0.95.
    let c = cmy_law();
    let p = 1e8;
    assert!((r(&c, 0.0, p, 0.0, 0.0).k - 1.25 * 1e6 * (p / 2e9f64).powf(0.95)).abs() < 1e-6);
    assert_eq!(r(&c, 0.0, -1.0, 0.0, 0.0).k, 0.0);
    // Radiation in °C: q = Fσ(a⁴ − b⁴) with a = θ_A + 273.15.
    let rad = radiation_law(false);
    let (ta, tb) = (500.0, 100.0);
    let (a, b) = (ta + 273.15f64, tb + 273.15f64);
    let q = r(&rad, 0.0, 0.0, ta, tb).k * (ta - tb);
    let exact = 0.8 * 5.670374419e-8 * (a.powi(4) - b.powi(4));
    assert!((q - exact).abs() < 1e-12 * exact);
    // Equal temperatures: k = 4Fσa³ (no 0/0).
    let k_eq = r(&rad, 0.0, 0.0, ta, ta).k;
    assert!((k_eq - 4.0 * 0.8 * 5.670374419e-8 * a.powi(3)).abs() < 1e-12 * k_eq);
}

#[test]
fn bad_inputs_and_parameters() {
    let law = pressure_table_law();
    for (d, p, ta, tb) in [
        (f64::NAN, 0.0, 300.0, 300.0),
        (0.0, f64::INFINITY, 300.0, 300.0),
        (0.0, 0.0, f64::NAN, 300.0),
        (0.0, 0.0, 300.0, f64::NEG_INFINITY),
    ] {
        assert!(law.evaluate(d, p, ta, tb).is_err());
    }
    // Below absolute zero with radiation.
    assert!(
        radiation_law(false)
            .evaluate(0.0, 0.0, -300.0, 20.0)
            .is_err()
    );
    assert!(Conduction::constant(-1.0).is_err());
    assert!(Conduction::gas_gap(0.026, 0.0, 0.0).is_err());
    assert!(Conduction::solid_spot(1.25, 0.0, 0.1, 1e-6, 1e9).is_err());
    assert!(Radiation::new(0.5, 0.0, 0.0).is_err());
    assert!(GapLaw::new(None, None).is_err());
    let negative = TemperatureTable::constant_in_temperature(Table1::new(&[(0.0, -1.0)]).unwrap());
    assert!(Conduction::pressure_table(negative).is_err());
}

/// docs/config.md, bad-input row 27a: the CMY law holds up to P/H_c = 1 and refuses beyond it
/// (the plastic real-area fraction P/H_c cannot exceed 1), naming P/H_c.
#[test]
fn cmy_refuses_pressure_above_the_microhardness() {
    let c = cmy_law();
    let h_c = 2e9;
    // At P = H_c: 1.25·k_s·m/σ·1.
    let at = c.evaluate(0.0, h_c, 300.0, 300.0).unwrap();
    assert!((at.k - 1.25 * 20.0 * 0.1 / 2e-6).abs() < 1e-9 * at.k);
    let above = h_c * (1.0 + 1e-12);
    let e = c
        .evaluate(0.0, above, 300.0, 300.0)
        .unwrap_err()
        .to_string();
    assert!(e.contains("P/H_c") && e.contains("microhardness"), "{e}");
    // The cmy law with radiation in parallel refuses the same way.
    let both = GapLaw::new(
        Some(Conduction::solid_spot(1.25, 20.0, 0.1, 2e-6, h_c).unwrap()),
        Some(Radiation::new(0.8, 5.670374419e-8, -273.15).unwrap()),
    )
    .unwrap();
    assert!(both.evaluate(0.0, above, 300.0, 300.0).is_err());
}

/// docs/config.md: the correlation's m is the mean absolute slope; an RMS slope overpredicts h
/// by RMS/mean|·| = sqrt(π/2) ≈ 1.25 for a Gaussian profile (h is linear in m). The ratio from a
/// numerical integral of E|X| for X ~ N(0, 1), against the closed form sqrt(2/π).
#[test]
fn rms_slope_overpredicts_cmy_conductance_by_a_quarter_for_a_gaussian_profile() {
    let n = 200_000;
    let (a, b) = (-12.0f64, 12.0f64);
    let h = (b - a) / n as f64;
    let pdf = |x: f64| (-0.5 * x * x).exp() / (2.0 * std::f64::consts::PI).sqrt();
    // Trapezoidal rule for E|X| = ∫|x| φ(x) dx.
    let mean_abs: f64 = (0..=n)
        .map(|i| {
            let x = a + h * i as f64;
            let w = if i == 0 || i == n { 0.5 } else { 1.0 };
            w * x.abs() * pdf(x)
        })
        .sum::<f64>()
        * h;
    assert!((mean_abs - (2.0 / std::f64::consts::PI).sqrt()).abs() < 1e-8);
    let c = cmy_law();
    let k_mean = c.evaluate(0.0, 1e7, 0.0, 0.0).unwrap().k;
    let rms_law = GapLaw::new(
        Some(Conduction::solid_spot(1.25, 20.0, 0.1 / mean_abs, 2e-6, 2e9).unwrap()),
        None,
    )
    .unwrap();
    let over = rms_law.evaluate(0.0, 1e7, 0.0, 0.0).unwrap().k / k_mean - 1.0;
    assert!(
        (0.24..0.26).contains(&over),
        "RMS slope overpredicts by {over}"
    );
}
