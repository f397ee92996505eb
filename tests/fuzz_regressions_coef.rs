//! Every crash the `fric_coef` fuzz target found (docs/fuzzing.md), replayed as a plain test
//! through the real `fric_coef_` / `ifl_forced_sliding` symbols with exactly sized arrays, plus
//! the closed-form answers the fixes give.
//!
//! The target's decoder and property checks are compiled in from `fuzz/src` by path, so a
//! replayed input is checked for exactly the properties the fuzzer checked. The explicit cases
//! do not depend on the byte encoding and stay meaningful if it changes.

#[path = "common/fuzz_cases.rs"]
mod fuzz_cases;
use fuzz_cases::fric_coef_case;

use fric_coef_case::{CoefCall, CoefNull, Coefficients, FricCoefCase};
use interfacial::props::CoulombBuilder;

/// Crash C1 (first seconds of fuzzing): a valid block of 2 points with `fCoef` NULL. The call
/// computed μ and wrote it through the NULL pointer: SIGSEGV inside the library (no panic to
/// catch). Fixed by refusing NULL output arrays before any work.
const CRASH_C1: [u8; 4] = [52, 15, 52, 122];

/// Crash C2: μ_s = 1.05e-12, μ_k = 9.8e12 (r = μ_k/μ_s ≈ 9e24): at rest μ came out 0 instead
/// of μ_s, because φ = r + (1 − r)·e cancels to 0 for r ≫ 1/ε. Fixed by φ = e + r(1 − e).
const CRASH_C2: [u8; 25] = [
    126, 3, 121, 134, 96, 163, 44, 74, 187, 121, 1, 0, 249, 249, 249, 249, 249, 249, 249, 249, 249,
    249, 249, 249, 33,
];

/// Crash C3 (random-seed run, 2026-11-23 evening): μ_s = 1.0e272 with μ_k/μ_s = 3·10⁻²⁷⁵, a
/// slip rate that takes e = exp(−d_c·γ̇) to 0 and a temperature law with Θ = exp(−427): μ
/// came out 0 instead of μ_k·Θ ≈ 5.4·10⁻¹⁸⁹, because f = φ·π·Θ underflowed before μ_s
/// multiplied it. Fixed by multiplying μ in first (`CoefficientLaw::scaled`).
const CRASH_C3: [u8; 202] = [
    1, 32, 0, 32, 0, 9, 0, 36, 134, 2, 0, 122, 134, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59,
    59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 59, 13, 59,
    59, 59, 59, 42, 40, 0, 61, 0, 0, 5, 0, 0, 16, 254, 196, 138, 138, 138, 138, 138, 138, 138, 138,
    138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138,
    130, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 146, 138, 138, 138,
    138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 142, 138, 138, 138, 138, 138, 138, 138, 138,
    138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 138, 118, 159, 61, 128,
    254, 7, 11, 42, 42, 42, 255, 0, 64, 115, 138, 138, 138, 7, 245, 208, 42, 42, 59, 59, 59, 59,
    59, 59, 245, 208, 42, 61, 128, 254, 0, 0, 0, 0, 87, 7, 11, 42, 140, 42, 140, 140, 140, 140,
    140, 140, 140, 140, 140, 140, 140, 140, 140, 255,
];

fn replay(data: &[u8]) -> CoefCall {
    let call = CoefCall::decode(data);
    if let Err(e) = call.check() {
        panic!("{e}\ninput: {call:?}");
    }
    call
}

#[test]
fn crash_c1_replays_clean() {
    let CoefCall::Coef(case) = replay(&CRASH_C1) else {
        panic!("the decoder changed: not a fric_coef_ call");
    };
    assert_eq!(case.null, CoefNull::FCoef, "the decoder changed: {case:?}");
}

#[test]
fn null_output_arrays_are_refused_and_the_other_array_zeroed() {
    let props = CoulombBuilder::new().mu(0.3).build_first(2);
    for null in [CoefNull::FCoef, CoefNull::FCoefDeriv] {
        let mut case = FricCoefCase::block(&props, &[0.1, 0.2], &[1.0, 2.0], &[0.0, 0.0]);
        case.null = null;
        let out = case.check().unwrap_or_else(|e| panic!("{e}"));
        let name = if null == CoefNull::FCoef {
            "fCoef is a NULL pointer"
        } else {
            "fCoefDeriv is a NULL pointer"
        };
        assert!(out.message.contains(name), "{}", out.message);
        let other = if null == CoefNull::FCoef {
            &out["fCoefDeriv"]
        } else {
            &out["fCoef"]
        };
        assert!(other.iter().all(|x| *x == 0.0), "{other:?}");
    }
}

#[test]
fn crash_c2_replays_clean() {
    let CoefCall::Coef(case) = replay(&CRASH_C2) else {
        panic!("the decoder changed: not a fric_coef_ call");
    };
    assert_eq!(case.args["props"][7], 1.0, "the decoder changed: {case:?}");
    assert!(
        case.args["props"][8] / case.args["props"][1] > 1e20,
        "the decoder changed: {case:?}"
    );
    assert!(
        case.args["props"][9] > 0.0 && case.args["slipData"][0] == 0.0,
        "the decoder changed: {case:?}"
    );
}

#[test]
fn decay_law_with_a_kinetic_coefficient_far_above_the_static_one() {
    // μ = μ_s·e + μ_k·(1 − e), e = exp(−d_c·γ̇) (docs/props.md, PROPS(8) = 1).
    // μ_s = 1e-3, μ_k = 1e20, d_c = 1.
    let props = CoulombBuilder::new()
        .mu(1e-3)
        .mu_law(1.0)
        .mu_k(1e20)
        .decay(1.0)
        .build_first(13);
    let rates = [0.0, 1e-30, 1e-20, 50.0];
    let case = FricCoefCase::block(&props, &rates, &[1.0; 4], &[0.0; 4]);
    let out = case.check().unwrap_or_else(|e| panic!("{e}"));
    assert!(out.message.is_empty(), "{}", out.message);
    let n = rates.len();
    // At rest: μ_s exactly (was 0).
    assert_eq!(out.mu(n, 0, 0), 1e-3);
    // γ̇ = 1e-30: e = 1 − 1e-30 to within 1e-60, μ = 1e-3 + 1e20·1e-30 = 1e-3 + 1e-10.
    let m = 1e-3 + 1e-10;
    assert!(
        (out.mu(n, 1, 0) - m).abs() <= 1e-15 * m,
        "{}",
        out.mu(n, 1, 0)
    );
    // γ̇ = 1e-20: μ = 1e-3 + 1 (to 1e-15).
    assert!(
        (out.mu(n, 2, 0) - 1.001).abs() <= 1e-15,
        "{}",
        out.mu(n, 2, 0)
    );
    // γ̇ = 50: e = e^{-50} ≈ 1.9e-22, μ = μ_k to round-off.
    assert!((out.mu(n, 3, 0) - 1e20).abs() <= 1e20 * 1e-15);
    // ∂μ/∂γ̇ = d_c(μ_k − μ_s)e: at rest 1e20 − 1e-3.
    assert!((out.deriv(n, 0, 0, 0) - 1e20).abs() <= 1e20 * 1e-15);
    // Isotropic: μ₂ = μ₁ bit for bit.
    for k in 0..n {
        assert_eq!(out.mu(n, k, 0).to_bits(), out.mu(n, k, 1).to_bits());
    }
}

#[test]
fn crash_c3_replays_clean() {
    let CoefCall::Coef(case) = replay(&CRASH_C3) else {
        panic!("the decoder changed: not a fric_coef_ call");
    };
    assert!(
        case.args["props"][1] > 1e270
            && case.args["props"][7] == 1.0
            && case.args["props"][11] > 0.0,
        "the decoder changed: {case:?}"
    );
}

#[test]
fn kinetic_coefficient_far_below_a_huge_static_one_with_a_small_temperature_factor() {
    // μ = (μ_s·e + μ_k·(1 − e))·Θ (docs/props.md), μ_s = 1e272, μ_k = 3e-3, d_c = 1, γ̇ = 1e3:
    // e = exp(−1000) = 0 in f64, so μ = μ_k·Θ; Θ = exp(−b_θ(θ̄ − θ_ref)) = exp(−427).
    let props = CoulombBuilder::new()
        .mu(1e272)
        .mu_law(1.0)
        .mu_k(3e-3)
        .decay(1.0)
        .b_theta(1.0)
        .build_first(13);
    let case = FricCoefCase::block(&props, &[1e3], &[1.0], &[427.0]);
    let out = case.check().unwrap_or_else(|e| panic!("{e}"));
    assert!(out.message.is_empty(), "{}", out.message);
    let expected = 3e-3 * (-427.0f64).exp();
    assert!(expected > 1e-190 && expected.is_normal());
    for d in 0..2 {
        let mu = out.mu(1, 0, d);
        assert!(
            (mu - expected).abs() <= 1e-14 * expected,
            "direction {d}: μ = {mu:e}, expected {expected:e}"
        );
    }
}
