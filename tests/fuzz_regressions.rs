//! Every crash the fuzz targets found (docs/fuzzing.md), replayed as a plain test through the
//! real `fric_` symbol with exactly sized arrays, plus the closed-form answers the fixes give.
//!
//! The fuzz targets' decoders and property checks are compiled in from `fuzz/src` by path, so
//! a replayed input is checked for exactly the properties the fuzzer checked. The explicit
//! cases below do not depend on the byte encoding and stay meaningful if it changes.

#[path = "common/fuzz_cases.rs"]
mod fuzz_cases;
use fuzz_cases::{batch_case, fric_case, gapcon_case, uinter_case};

use fric_case::FricCase;
use fuzz_cases::args::Outputs;
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};

/// Runs the fuzzer's property check and returns the outputs; fails the test with the property
/// that was violated.
fn checked(case: &FricCase) -> Outputs {
    case.check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"))
}

/// A recorded `fric` input that must still decode with `name(i + 1) = value`, through the
/// property check.
fn replay(bytes: &[u8], name: &str, i: usize, value: f64) -> (FricCase, Outputs) {
    let case = FricCase::decode(bytes);
    assert_eq!(case.args[name][i], value, "the decoder changed: {case:?}");
    let out = checked(&case);
    (case, out)
}

/// A recorded `fric` input that must still decode to the adhesive law (`PROPS(1) = 2`), through
/// the property check.
fn adhesive_replay(bytes: &[u8]) -> (FricCase, Outputs) {
    replay(bytes, "PROPS", 0, 2.0)
}

fn succeeded(case: &FricCase, out: &Outputs) {
    assert!(out.message.is_empty(), "refused: {}", out.message);
    assert_eq!(
        out.real("PNEWDT").to_bits(),
        case.args["PNEWDT"][0].to_bits()
    );
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// Crash 1 (fric, first minute of fuzzing): a finite slip over a subnormal DTIME made the slip
/// rate STATEV(2) = ∞ on a call that reported success; the next increment then refuses the
/// state as corrupted. Fixed by saturating the slip rate (and the accumulated slip) at f64::MAX.
const CRASH_SLIP_RATE: [u8; 46] = [
    46, 0, 10, 37, 255, 1, 0, 0, 0, 0, 0, 0, 105, 255, 255, 4, 4, 4, 65, 65, 65, 65, 65, 65, 4, 4,
    4, 1, 0, 0, 0, 0, 0, 0, 0, 4, 4, 4, 4, 4, 65, 65, 65, 65, 65, 65,
];

#[test]
fn crash_1_replays_clean() {
    let (case, out) = replay(&CRASH_SLIP_RATE, "DTIME", 0, f64::MIN_POSITIVE);
    succeeded(&case, &out);
    assert_eq!(out["STATEV"][1], f64::MAX);
}

#[test]
fn slip_rate_over_a_subnormal_dtime_saturates_and_the_state_stays_usable() {
    // μ = 0.3, γ_crit = 1e-3, p = 10: slip of 1 − 1e-3 in 2-D over Δt = 5e-324.
    let props = CoulombBuilder::new().mu(0.3).gamma_crit(1e-3);
    let mut c = FricCase::coulomb(2, &props.build_first(7));
    c.args["PRESS"][0] = 10.0;
    c.args["DGAM"] = vec![0.6, 0.8];
    c.args["DTIME"][0] = 5e-324;
    let out = checked(&c);
    succeeded(&c, &out);
    assert!(close(out["STATEV"][0], 1.0 - 1e-3, 1e-15));
    assert_eq!(out["STATEV"][1], f64::MAX);
    assert_eq!(out["STATEV"][2], 1.0);
    // The next increment accepts the state it was given.
    let mut next = c.clone();
    next.args["STATEV"] = out["STATEV"].clone();
    next.args["DTIME"][0] = 1.0;
    succeeded(&next, &checked(&next));
}

#[test]
fn accumulated_slip_near_f64_max_saturates() {
    let props = CoulombBuilder::new().mu(0.3).gamma_crit(1e-3);
    let mut c = FricCase::coulomb(1, &props.build_first(5));
    c.args["PRESS"][0] = 10.0;
    c.args["DGAM"] = vec![1e300];
    c.args["STATEV"] = vec![f64::MAX, 0.0, 1.0];
    let out = checked(&c);
    succeeded(&c, &out);
    assert_eq!(out["STATEV"][0], f64::MAX);
    // Slip rate 1e300 − 1e-3 over Δt = 1: finite, unchanged by the saturation.
    assert_eq!(out["STATEV"][1], 1e300);
}

/// Crash 2 (fric, found again in 3 minutes with the norm fix reverted): in 2-D the predictor
/// (5.7e-270, 5.7e-270) has a norm whose square underflows to 0, so the point was taken as
/// sticking with γ_crit = 5.6e-311 and |τ| came out 1.4e41 × τ_crit, outside the friction cone.
/// Fixed by the scaled norm in src/laws/small_vec.rs.
const CRASH_NORM_UNDERFLOW: [u8; 181] = [
    1, 215, 41, 32, 10, 37, 10, 0, 110, 0, 126, 156, 154, 37, 0, 156, 154, 1, 128, 0, 156, 154, 37,
    32, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 38, 8, 8,
    8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8,
    8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8,
    8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 225, 8, 46, 8, 8, 8,
    8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 0, 0, 0, 0, 0, 255, 8, 8, 255, 239, 194, 0, 33, 0, 0,
    1, 1, 0,
];

#[test]
fn crash_2_replays_clean() {
    let case = FricCase::decode(&CRASH_NORM_UNDERFLOW);
    assert_eq!(case.args.int("NFDIR"), 2, "the decoder changed: {case:?}");
    let out = checked(&case);
    succeeded(&case, &out);
    // It slips now: the predictor is far longer than γ_crit.
    assert_eq!(out["STATEV"][2], 1.0);
}

/// 2-D slip at 45° with τ_crit = μp = p/2: the expected answer at every scale of Δγ.
fn slip_at_45_degrees(dgam: f64, gamma_crit: f64, p: f64) -> Outputs {
    let props = CoulombBuilder::new().mu(0.5).gamma_crit(gamma_crit);
    let mut c = FricCase::coulomb(2, &props.build_first(5));
    c.args["PRESS"][0] = p;
    c.args["DGAM"] = vec![dgam, dgam];
    let out = checked(&c);
    succeeded(&c, &out);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert_eq!(out.int("LM"), 0);
    assert_eq!(out["STATEV"][2], 1.0, "slipping");
    for a in 0..2 {
        assert!(close(out["TAU"][a], 0.5 * p * h, 1e-15), "{out:?}");
    }
    out
}

#[test]
fn tiny_slip_whose_square_underflows_sits_on_the_cone() {
    // |Δγ| = √2·1e-170 > γ_crit = 1e-300; (1e-170)² underflows.
    let out = slip_at_45_degrees(1e-170, 1e-300, 1.0);
    assert!(close(out["DSLIP"][0], 1e-170, 1e-15));
    assert!(close(out["STATEV"][0], 2f64.sqrt() * 1e-170, 1e-15));
}

#[test]
fn huge_slip_whose_square_overflows_is_accepted_and_exact() {
    // |Δγ| = √2·1e200: the squares overflow, the norm does not. Was refused as an overflow.
    let out = slip_at_45_degrees(1e200, 1e-3, 1.0);
    assert!(close(out["DSLIP"][1], 1e200, 1e-15));
    let slip = 2f64.sqrt() * 1e200;
    assert!(close(out["STATEV"][0], slip, 1e-15));
    assert!(close(out.real("SFD"), 0.5 * slip, 1e-15));
}

#[test]
fn subnormal_slip_direction_has_unit_length() {
    // Δγ = (2, 2) units of 5e-324: |Δγ| = 2.83 units rounds to 3, so dividing by it gave a
    // direction of length 0.94 and |τ| = 0.94 τ_crit while slipping. p = 1e-300 keeps the
    // tangent τ_crit/|Δγ| finite.
    slip_at_45_degrees(1e-323, 5e-324, 1e-300);
}

#[test]
fn gapcon_checker_accepts_every_configured_law() {
    // The gapcon target found nothing; this proves its check passes on good calls of each law.
    for (i, name) in gapcon_case::NAMES.iter().enumerate() {
        let mut case = gapcon_case::GapconCase::decode(&[i as u8]);
        case.args["D"] = vec![1e-4, 50.0];
        case.args["TEMP"] = vec![300.0, 290.0];
        let k = case.check().unwrap_or_else(|e| panic!("{name}: {e}"));
        if *name == "NONE" {
            assert_eq!(k, 0.0);
        } else {
            assert!(k > 0.0, "{name}: k = {k}");
        }
    }
}

/// Found by fuzz target `fric` on the merged adhesive law: PROPS(1) = 2 with
/// μ_s = μ_d (coeffStatic = 0, "none") and v_½ = 1, a slip predictor about 10²⁶ times the
/// stress it returns. τ was computed as T − k_s·Δs, which cancelled and came out 5·10⁻⁷
/// (relative) above μp. The sliding stress is now evaluated from the law itself.
const CRASH_ADHESIVE_CANCELLATION: [u8; 77] = [
    85, 93, 230, 50, 195, 195, 195, 11, 2, 52, 52, 52, 52, 52, 52, 85, 172, 25, 205, 60, 254, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 97, 97, 97, 97, 97, 97, 97, 97, 97, 255, 0, 255,
    255, 255, 195, 250, 195, 11, 2, 2, 60, 254, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    97, 97, 97, 97, 97, 97, 97, 97, 97, 247, 2, 2, 255, 2,
];

#[test]
fn fric_adhesive_cancellation_replays_clean() {
    let (case, out) = adhesive_replay(&CRASH_ADHESIVE_CANCELLATION);
    succeeded(&case, &out);
    // Seed 004 with μ_s = μ_d = μ, S_a = k_μ = 0: sliding stress μp whatever the rate.
    let mu_p = case.args["PROPS"][1] * case.args["PRESS"][0];
    assert_eq!(out.int("LM"), 0);
    assert!(
        close(out["TAU"][0].abs(), mu_p, 1e-13),
        "{} vs {mu_p}",
        out["TAU"][0]
    );
}

/// Found by fuzz target `fric` on the merged extended law: anisotropic law 1 (μ₂ ≠ μ in
/// PROPS(3)) slipping over DTIME = f64::MIN_POSITIVE stored STATEV(2) = ∞. The extended law
/// now saturates its slip rate and accumulated slip at f64::MAX like the plain law.
const CRASH_EXTENDED_SLIP_RATE: [u8; 96] = [
    176, 42, 49, 14, 0, 0, 0, 70, 82, 4, 0, 31, 31, 98, 97, 100, 32, 112, 97, 114, 97, 109, 101,
    116, 101, 114, 58, 32, 80, 82, 79, 80, 83, 40, 50, 41, 58, 32, 102, 114, 105, 99, 116, 105,
    255, 255, 255, 255, 111, 99, 111, 32, 110, 101, 102, 102, 105, 99, 105, 101, 110, 116, 32, 206,
    188, 32, 61, 32, 45, 48, 46, 48, 48, 48, 48, 43, 10, 49, 43, 14, 10, 4, 7, 14, 10, 12, 36, 42,
    49, 0, 10, 12, 36, 42, 49, 17,
];

#[test]
fn fric_extended_slip_rate_replays_clean() {
    let case = FricCase::decode(&CRASH_EXTENDED_SLIP_RATE);
    assert_eq!(
        (case.args.int("NFDIR"), case.args["DTIME"][0]),
        (2, f64::MIN_POSITIVE),
        "the decoder changed: {case:?}"
    );
    assert!(case.args["PROPS"][2] != 0.0 && case.args["PROPS"][2] != case.args["PROPS"][1]);
    let out = checked(&case);
    succeeded(&case, &out);
    assert_eq!(out["STATEV"][1], f64::MAX);
}

/// Found by fuzz target `fric`: the adhesive law (PROPS(1) = 2) slipping over
/// DTIME = 5·10⁻³²⁴ from an accumulated slip of f64::MAX stored ∞ in STATEV(1..2); it now
/// saturates at f64::MAX like the Coulomb laws.
const CRASH_ADHESIVE_SLIP_RATE: [u8; 65] = [
    17, 100, 100, 226, 30, 215, 59, 10, 10, 10, 0, 30, 30, 30, 30, 50, 30, 100, 104, 100, 100, 100,
    100, 100, 255, 100, 255, 5, 5, 5, 5, 5, 5, 5, 5, 5, 100, 255, 255, 100, 0, 43, 90, 90, 90, 3,
    0, 0, 0, 0, 0, 0, 0, 90, 6, 0, 90, 90, 90, 90, 90, 42, 255, 100, 10,
];

#[test]
fn fric_adhesive_slip_rate_replays_clean() {
    let (case, out) = adhesive_replay(&CRASH_ADHESIVE_SLIP_RATE);
    succeeded(&case, &out);
    assert_eq!((out["STATEV"][0], out["STATEV"][1]), (f64::MAX, f64::MAX));
}

/// Found by fuzz target `fric`: the adhesive law with μ_d = 0, k_μ = 2, p = Δt = f64::MAX.
/// k_μ/Δt·Δs was subnormal (seven digits lost) before the multiplication by p, so τ came out
/// 6·10⁻⁸ (relative) above the seed's k_μ·Δv·p + S_a. Now evaluated as (k_μ/Δt·p)·Δs.
const CRASH_ADHESIVE_SUBNORMAL_RATE: [u8; 114] = [
    17, 100, 100, 226, 30, 215, 59, 10, 10, 10, 0, 65, 30, 30, 30, 30, 50, 30, 100, 30, 215, 59,
    10, 10, 10, 0, 65, 30, 30, 30, 30, 50, 30, 100, 104, 100, 100, 100, 100, 100, 255, 68, 255, 5,
    5, 5, 5, 5, 5, 5, 5, 5, 100, 255, 255, 100, 0, 43, 90, 90, 90, 3, 0, 0, 0, 0, 0, 0, 90, 90, 42,
    255, 100, 10, 104, 100, 100, 100, 100, 100, 255, 68, 255, 5, 5, 5, 5, 5, 5, 5, 5, 5, 100, 255,
    255, 100, 0, 43, 90, 90, 90, 3, 0, 0, 0, 0, 0, 0, 90, 90, 42, 255, 100, 10,
];

#[test]
fn fric_adhesive_subnormal_rate_replays_clean() {
    let (case, out) = adhesive_replay(&CRASH_ADHESIVE_SUBNORMAL_RATE);
    succeeded(&case, &out);
    // Seed 004 with μ_s = μ_d = 0: τ = k_μ·(Δs/Δt)·p + S_a.
    let (s_a, k_mu) = (case.args["PROPS"][3], case.args["PROPS"][5]);
    let expected =
        k_mu * out["DSLIP"][0].abs() * (case.args["PRESS"][0] / case.args["DTIME"][0]) + s_a;
    assert!(
        close(out["TAU"][0].abs(), expected, 1e-13),
        "{} vs {expected}",
        out["TAU"][0]
    );
}

/// Crash 4 (uinter, first 30 s): sliding with a trial stress 10⁶ times the strength, the shear
/// stress came out as T − k_s·Δs and lost ~ε·T to cancellation: |τ| = 9.9648437503674e-4
/// against the strength μp + S_a = 9.9648437500001e-4. Fixed by evaluating τ from the seed's
/// strength at the root (`src/laws/adhesive.rs`).
const CRASH_UINTER_STRENGTH: [u8; 61] = [
    0, 0, 0, 0, 0, 0, 1, 255, 0, 18, 0, 255, 2, 10, 1, 9, 0, 0, 9, 237, 158, 0, 0, 3, 0, 0, 158,
    158, 245, 236, 65, 158, 97, 97, 0, 0, 0, 158, 158, 158, 245, 236, 158, 97, 97, 0, 0, 0, 158,
    158, 245, 236, 189, 158, 97, 245, 236, 189, 158, 97, 10,
];

#[test]
fn crash_4_replays_clean() {
    let case = uinter_case::UinterCase::decode(&CRASH_UINTER_STRENGTH);
    assert_eq!(case.args.int("NDIR"), 2, "the decoder changed: {case:?}");
    let out = case
        .check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"));
    assert!(out.message.is_empty(), "refused: {}", out.message);
    assert_eq!(out["STATEV"][2], 1.0, "slipping");
}

/// A sliding point far past the stick limit (trial stress 10⁶·g and 10¹²·g): the shear
/// stress is the seed's strength μ_d·p + S_a to a few ulps, never above it.
#[test]
fn uinter_shear_far_past_the_stick_limit_is_the_strength() {
    for ratio in [1e6, 1e12] {
        // μ_d = 0.5, S_a = 2, K_n = 1000, γ_crit = 1e-6 (absolute), h = 0.01: p = 10.
        let props = sliding_uinter_law(0.5).sa(2.0).build_first(10);
        let mut c = uinter_case::UinterCase::decode(&[]);
        c.args.set_int("NDIR", 3);
        c.args.set_int("NSTATV", 3);
        c.args.set_int("NPROPS", 10);
        c.args["PROPS"] = props.to_vec();
        c.args["STRESS"] = vec![10.0, 0.0, 0.0];
        c.args["STATEV"] = vec![0.0; 3];
        c.args["RDISP"] = vec![0.01, 0.0, 0.0];
        let g = 0.5 * 10.0 + 2.0;
        c.args["DRDISP"] = vec![0.0, 0.6 * ratio * 1e-6, 0.8 * ratio * 1e-6];
        c.args["DTIME"][0] = 1.0;
        c.args["CHRLNGTH"][0] = 1.0;
        c.args["PNEWDT"][0] = 1e36;
        let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
        assert!(out.message.is_empty(), "refused: {}", out.message);
        let tau = out["STRESS"][1].hypot(out["STRESS"][2]);
        assert!(tau <= g * (1.0 + 4.0 * f64::EPSILON), "{tau} above {g}");
        assert!((tau - g).abs() <= 4.0 * f64::EPSILON * g, "{tau} != {g}");
        assert_eq!(out["STATEV"][2], 1.0);
        assert_eq!(out["STRESS"][0], 10.0);
    }
}

/// Crashes 5 and 6 (uinter, first minutes): a successful call stored ∞ in `STATEV`: the
/// accumulated slip summed past f64::MAX, and the slip rate of a frictionless point
/// (μ = S_a = 0) over a tiny `DTIME` overflowed. Both saturate at f64::MAX now, as in the
/// Coulomb law (crash 1).
const CRASH_UINTER_STATE: [&[u8]; 2] = [
    &[
        59, 32, 0, 0, 0, 0, 0, 97, 97, 0, 0, 201, 231, 10, 61, 10, 5, 5, 5, 5, 61, 10, 5, 5, 5,
        126, 5, 5, 5, 5, 5, 5, 5, 5, 99, 111, 99, 111, 101, 102, 102, 83, 116, 97, 116, 105, 99, 5,
        5, 5, 5,
    ],
    &[
        9, 0, 0, 0, 0, 0, 0, 0, 0, 0, 19, 19, 19, 19, 19, 58, 5, 5, 5, 5, 5, 7, 7, 7, 7, 7, 5, 5,
        5, 94, 94, 55, 126, 4, 4, 4, 4, 46, 46, 46, 46, 46, 46, 46, 46, 46, 46, 46, 46, 46, 46, 46,
        19, 19, 19, 19, 58, 5, 5, 5, 5, 5, 5, 5, 5, 5, 46, 4, 4, 4, 4, 4, 74, 74, 104, 4, 4, 95,
        255, 5,
    ],
];

#[test]
fn crashes_5_and_6_replay_clean() {
    for bytes in CRASH_UINTER_STATE {
        let case = uinter_case::UinterCase::decode(bytes);
        case.check()
            .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"));
    }
}

/// The adhesive law of [`sliding_uinter`]: μ_d = `mu`, K_n = 1000, γ_crit = 1e-6.
fn sliding_uinter_law(mu: f64) -> AdhesiveBuilder {
    AdhesiveBuilder::new()
        .coeff(mu)
        .gamma_crit(1e-6)
        .normal_stiffness(1000.0)
}

/// A closed, sliding `uinter_` point: μ_d = 0.5, K_n = 1000, h = 0.01 (p = 10), γ_crit = 1e-6.
fn sliding_uinter(mu: f64) -> uinter_case::UinterCase {
    let mut c = uinter_case::UinterCase::decode(&[]);
    c.args.set_int("NDIR", 2);
    c.args.set_int("NSTATV", 3);
    c.args.set_int("NPROPS", 10);
    c.args["PROPS"] = sliding_uinter_law(mu).build_first(10);
    c.args["STRESS"] = vec![10.0, 0.0];
    c.args["STATEV"] = vec![0.0; 3];
    c.args["RDISP"] = vec![0.01, 0.0];
    c.args["DRDISP"] = vec![0.0, 1.0];
    c.args["DTIME"][0] = 1.0;
    c.args["CHRLNGTH"][0] = 1.0;
    c.args["PNEWDT"][0] = 1e36;
    c
}

#[test]
fn uinter_accumulated_slip_near_f64_max_saturates() {
    let mut c = sliding_uinter(0.5);
    c.args["STATEV"][0] = f64::MAX;
    let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
    assert!(out.message.is_empty(), "refused: {}", out.message);
    assert_eq!(out["STATEV"][0], f64::MAX);
    assert_eq!(out["STATEV"][2], 1.0);
    // Δs = 1 − γ_crit: the rate is Δs/Δt.
    assert!((out["STATEV"][1] - (1.0 - 1e-6)).abs() < 1e-15);
}

#[test]
fn uinter_slip_rate_over_a_subnormal_dtime_saturates() {
    for mu in [0.0, 0.5] {
        let mut c = sliding_uinter(mu);
        c.args["DTIME"][0] = 5e-324;
        let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
        assert!(out.message.is_empty(), "refused: {}", out.message);
        assert_eq!(out["STATEV"][1], f64::MAX, "μ = {mu}");
        assert!((out["STATEV"][0] - (1.0 - 1e-6)).abs() < 1e-15);
        // The next increment accepts the state.
        let mut next = sliding_uinter(mu);
        next.args["STATEV"] = out["STATEV"].clone();
        let again = next.check().unwrap_or_else(|e| panic!("{e}"));
        assert!(again.message.is_empty(), "refused: {}", again.message);
    }
}

/// Not a library defect (the CI run of `fric`, after the adhesive law joined `fric_`): the
/// target's cone check was the Coulomb law's, τ_crit = min(μp, τ_max) = 0 for p < 0, and
/// flagged an adhesive point (`PROPS(1) = 2`) sliding at p < 0 with |τ| = S_a = 2, which is
/// the seed's law. The check now uses the adhesive strength for law 2.
const FRIC_ADHESIVE_NEGATIVE_PRESSURE: [u8; 87] = [
    255, 65, 2, 255, 255, 23, 255, 10, 10, 10, 0, 255, 255, 255, 58, 255, 10, 10, 10, 0, 18, 18,
    18, 18, 228, 237, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 210, 93, 18, 18, 18,
    18, 18, 18, 18, 18, 18, 18, 18, 18, 255, 2, 255, 18, 65, 49, 255, 7, 255, 255, 255, 255, 255,
    255, 23, 255, 10, 10, 255, 65, 19, 250, 1, 10, 5, 114, 49, 5, 42, 5, 5, 1, 5,
];

#[test]
fn fric_adhesive_at_negative_pressure_replays_clean() {
    let (case, out) = adhesive_replay(&FRIC_ADHESIVE_NEGATIVE_PRESSURE);
    succeeded(&case, &out);
    // Sliding at p < 0: the stress is the shear adhesive strength S_a = PROPS(4).
    assert_eq!(out["STATEV"][2], 1.0);
    assert_eq!(out["TAU"][0].abs(), case.args["PROPS"][3]);
}

/// Crash 7 (`fric`, adhesive law, 60 s run): a slip increment near f64::MAX with γ_crit near
/// 10³⁰⁶ gave Δs ≈ 1.8·10³⁰⁸, and the transition (μ_s V + μ_d Δs)/(V + Δs) overflowed to ∞;
/// at p < 0, ∞·0 = NaN, and the stress came out as the trial stress 2.4e-5 instead of
/// S_a = 1.2e-7. The transition is now μ_d + (μ_s − μ_d)·V/(V + Δs) and the pressure part is
/// skipped at p⁺ = 0 (`src/laws/adhesive.rs`).
const CRASH_ADHESIVE_TRANSITION: [u8; 96] = [
    65, 63, 166, 166, 10, 2, 255, 10, 2, 255, 10, 2, 5, 2, 21, 5, 5, 5, 5, 5, 0, 0, 0, 0, 0, 0, 0,
    0, 5, 48, 5, 42, 42, 42, 42, 42, 42, 42, 37, 42, 42, 42, 42, 42, 42, 42, 42, 42, 42, 42, 42,
    42, 42, 42, 42, 42, 42, 42, 204, 42, 42, 42, 255, 162, 255, 255, 255, 255, 255, 42, 42, 42, 42,
    42, 42, 5, 166, 93, 5, 5, 44, 5, 61, 5, 5, 5, 5, 5, 177, 177, 158, 177, 177, 1, 1, 5,
];

#[test]
fn crash_7_replays_clean() {
    let (case, out) = adhesive_replay(&CRASH_ADHESIVE_TRANSITION);
    if out.message.is_empty() && out.int("LM") == 0 && case.args["PRESS"][0] < 0.0 {
        // Sliding at p < 0: the stress is S_a.
        let tau = out["TAU"].iter().fold(0.0f64, |s, x| s.hypot(*x));
        assert!(tau <= case.args["PROPS"][3] * (1.0 + 1e-12), "{tau}");
    }
}

/// Found by fuzz target `batch` after the extended law 1 was merged: an anisotropic `PROPS`
/// (μ₂ in `PROPS(3)` ≠ μ) that `fric_` runs and the batch refuses as a whole (its kernel is the
/// plain law's). The check now accepts that refusal, as for the adhesive law; the batch must
/// write nothing but `pnewdt` and name the cause.
const BATCH_EXTENDED_LAW: [u8; 13] = [26, 255, 255, 49, 0, 255, 0, 0, 255, 255, 40, 255, 255];

#[test]
fn batch_refuses_the_extended_law_as_a_whole() {
    let case = batch_case::BatchCase::decode(&BATCH_EXTENDED_LAW);
    assert!(
        case.args["props"][0] == 1.0
            && case.args["props"][2] != 0.0
            && case.args["props"][2] != case.args["props"][1],
        "the decoder changed: {case:?}"
    );
    let out = case
        .check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"));
    assert!(
        out.message.contains("extended law-1 PROPS"),
        "{}",
        out.message
    );
    assert_eq!(out.real("pnewdt"), 0.25);
}

/// Found by fuzz target `fric` on a clean checkout (seed 1, ~274 000 inputs): the adhesive law
/// with k_μ = 5·10⁻³⁰⁶, Δt = 4.8·10¹⁰ (k_μ/Δt subnormal) and a slip of 3.5·10²⁵¹ returned τ
/// 1.9·10⁻⁸ above k_μ·Δv·p. The rate term is now formed with its exponents kept apart.
#[test]
fn fric_adhesive_subnormal_rate_coefficient_replays_clean() {
    let (case, out) = adhesive_replay(include_bytes!(
        "../fuzz/regressions/fric-adhesive-subnormal-rate"
    ));
    succeeded(&case, &out);
    // μ_d = 0, v_½ = 0: sliding stress k_μ·(Δs/Δt)·p + S_a, with the exact slip rate.
    let slip = out["DSLIP"][0].hypot(out["DSLIP"][1]);
    let expected = case.args["PROPS"][5] * (slip / case.args["DTIME"][0]) * case.args["PRESS"][0]
        + case.args["PROPS"][3];
    let tau = out["TAU"][0].hypot(out["TAU"][1]);
    assert!(close(tau, expected, 1e-13), "{tau} vs {expected}");
}

/// The `uinter` property check on a bond breaking (SPD > 0, allowed only then) and on the same
/// call from an open start (SPD must be 0): bonded with S̄ = 3, N̄ = 8, pulled to N = 9
/// (S_a = 4, N_a = 10, γ_crit = 1e-3, K_n = 1e4), SPD = ½·9·1e-3/4 + ½·64/1e4.
#[test]
fn uinter_breaking_bond_passes_the_spd_property() {
    let mut c = uinter_case::UinterCase::decode(&[]);
    c.args.set_int("NDIR", 2);
    c.args.set_int("NSTATV", 3);
    c.args.set_int("NPROPS", 10);
    c.args["PROPS"] = AdhesiveBuilder::new()
        .coeff(0.3)
        .sa(4.0)
        .na(10.0)
        .gamma_crit(1e-3)
        .normal_stiffness(1e4)
        .build_first(10);
    c.args["STRESS"] = vec![-8.0, 3.0];
    c.args["STATEV"] = vec![0.0, 0.0, 3.0];
    c.args["RDISP"] = vec![-9.0 / 1e4, 0.0];
    c.args["DRDISP"] = vec![0.0, 0.0];
    c.args["DTIME"][0] = 1.0;
    c.args["CHRLNGTH"][0] = 1.0;
    c.args["PNEWDT"][0] = 1e36;
    c.null_optional = false;
    let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
    let want = 0.5 * 9.0 * 1e-3 / 4.0 + 0.5 * 64.0 / 1e4;
    assert!(close(out.real("SPD"), want, 1e-14), "{out:?}");
    c.args["STATEV"][2] = 4.0;
    let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
    assert_eq!(out.real("SPD"), 0.0);
}

/// Crash 15 (uinter, CI run of 2026-11-23 after the decoder learnt SPD): sliding with k_μ > 0
/// over a `DTIME` of f64::MIN_POSITIVE; ∂τ/∂p is finite but DDSDDR(1+a,1) = ∂τ_a/∂p·K_n
/// overflowed to ∞ on a call that succeeded. Now refused as an overflow (cut-back).
const CRASH_UINTER_TANGENT_OVERFLOW: [u8; 83] = [
    255, 1, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 68, 4, 4, 4, 4, 4, 4, 4,
    243, 251, 251, 251, 4, 0, 85, 0, 2, 0, 0, 103, 0, 0, 0, 0, 4, 4, 4, 4, 4, 4, 4, 85, 0, 4, 14,
    4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 248, 251, 253, 255, 5, 83, 0,
];

#[test]
fn uinter_tangent_overflow_is_refused() {
    let case = uinter_case::UinterCase::decode(&CRASH_UINTER_TANGENT_OVERFLOW);
    let out = case
        .check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"));
    assert!(out.message.contains("overflowed"), "{}", out.message);
    assert!(out.real("PNEWDT") < 1.0);
}

/// The same defect without the byte encoding: a start shear of 1000 against a strength
/// S_a = 1 (start elastic slip τ̄·γ_crit/τ_s = 1), k_μ = 1, K_n = 10¹⁰ at h = 10⁻³¹⁰ (p = 10⁻³⁰⁰)
/// and Δt = 10⁻³⁰⁰: the slip ≈ 1 gives Δv ≈ 10³⁰⁰, so ∂τ/∂p ≈ k_μ·Δv ≈ 10³⁰⁰ is finite while
/// ∂τ/∂p·K_n ≈ 10³¹⁰ is not.
#[test]
fn uinter_tangent_overflow_of_the_pressure_column_is_a_cut_back() {
    let mut c = sliding_uinter(0.5);
    c.args["PROPS"] = AdhesiveBuilder::new()
        .coeff(0.5)
        .sa(1.0)
        .kmu(1.0)
        .gamma_crit(1e-3)
        .normal_stiffness(1e10)
        .build_first(10);
    c.args["RDISP"] = vec![1e-310, 0.0];
    c.args["STRESS"] = vec![1e-300, 1000.0];
    c.args["DRDISP"] = vec![0.0, 0.0];
    c.args["DTIME"][0] = 1e-300;
    let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
    assert!(out.message.contains("overflowed"), "{}", out.message);
    assert!(out.real("PNEWDT") < 1.0);
    assert_eq!(out["STATEV"], c.args["STATEV"], "STATEV unchanged");
    // With an ordinary step the same point is computed.
    c.args["DTIME"][0] = 1.0;
    let out = c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"));
    assert!(out.message.is_empty(), "{}", out.message);
}

/// Finding 14 (`fric`, a 3-minute run with a random seed, 2026-11-23): elastic stick with
/// τ_max = f64::MIN_POSITIVE and γ_crit ≈ 4.4·10⁹, so k_s = τ_crit/γ_crit ≈ 5·10⁻³¹⁸ is subnormal
/// and kept only five digits: τ = k_s·γ^pr came out 4.4·10⁻⁷ (relative) above τ_crit. The stick
/// stress is now formed as τ_crit·(γ^pr/γ_crit), with γ^pr/γ_crit ≤ 1.
const FRIC_SUBNORMAL_STIFFNESS: [u8; 98] = [
    0, 0, 2, 50, 7, 0, 0, 7, 7, 91, 7, 7, 30, 191, 4, 175, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96,
    96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 91, 7, 7, 30, 191, 4, 175,
    96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96, 96,
    96, 58, 229, 229, 229, 96, 229, 229, 229, 229, 229, 229, 96, 229, 229, 229, 229, 229, 229, 96,
    96, 170, 3, 41,
];

#[test]
fn fric_stick_with_a_subnormal_stiffness_stays_on_the_cone() {
    let (case, out) = replay(&FRIC_SUBNORMAL_STIFFNESS, "PROPS", 3, f64::MIN_POSITIVE);
    succeeded(&case, &out);
    assert!(
        out["TAU"][0].abs() <= f64::MIN_POSITIVE,
        "{}",
        out["TAU"][0]
    );
}

/// Found by fuzz target `fric` (random seed, session 6) on a change that was then reverted: the
/// adhesive law's elastic start slip formed as (τ̄/τ_s)·γ_crit where γ_crit/τ_s(p₀) overflows
/// (S_a = f64::MIN_POSITIVE, μ = 0, γ_crit ≈ 2·10⁸ from `CHRLNGTH`) answered with a subnormal
/// k_s = S_a/γ_crit of eight digits, and |τ| = k_s·γ_crit came out 8·10⁻⁹ above the strength.
/// The stick stress is now formed as the Coulomb law's careful tier forms it for a subnormal
/// k_s, τ_s·(γ^pr/γ_crit) (`laws::contact::elastic_stick_stress`): the increment is answered
/// (it was refused as a numerical failure before) and the replay's property check holds.
#[test]
fn fric_adhesive_vanishing_start_strength_stays_within_the_property() {
    let (_, out) = adhesive_replay(include_bytes!(
        "../fuzz/regressions/fric-adhesive-vanishing-start-strength"
    ));
    assert_eq!(out.real("PNEWDT"), 1.0, "answered: {out:?}");
}

/// The `fric` decoder's law-3 arm (rate-and-state: `NPROPS` = 11, picked by 6 of the 64 values
/// of the third byte, 34 among them) is live and its properties hold: pseudo-random inputs (a
/// fixed Lehmer sequence) with that byte run through the fuzzer's decoder and property check,
/// and law 3 answers both in slip and in stick, not only with refusals.
#[test]
fn fric_rate_state_arm_reaches_the_law() {
    let mut state: u64 = 0x9e37_79b9;
    let mut next = || {
        state = state.wrapping_mul(48_271) % 0x7fff_ffff;
        state.to_le_bytes()[0] ^ state.to_le_bytes()[1]
    };
    let (mut slid, mut stuck, mut refused) = (0, 0, 0);
    for _ in 0..400 {
        let len = usize::from(next()) + 40;
        let mut bytes: Vec<u8> = (0..len).map(|_| next()).collect();
        bytes[2] = 34;
        let case = FricCase::decode(&bytes);
        assert_eq!(
            case.args["PROPS"].len(),
            11,
            "the decoder changed: {case:?}"
        );
        let out = checked(&case);
        if !out.message.is_empty() {
            refused += 1;
        } else if case.args.int("LM") != 2 && out["STATEV"][2] == 1.0 {
            slid += 1;
        } else if case.args.int("LM") != 2 {
            stuck += 1;
        }
    }
    eprintln!("law 3 arm: {slid} slips, {stuck} sticks, {refused} refused");
    assert!(
        slid > 0 && stuck > 0,
        "{slid} slips, {stuck} sticks, {refused} refused"
    );
}
