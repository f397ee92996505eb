//! Every crash the fuzz targets found (docs/fuzzing.md), replayed as a plain test through the
//! real `fric_` symbol with exactly sized arrays, plus the closed-form answers the fixes give.
//!
//! The fuzz targets' decoders and property checks are compiled in from `fuzz/src` by path, so
//! a replayed input is checked for exactly the properties the fuzzer checked. The explicit
//! cases below do not depend on the byte encoding and stay meaningful if it changes.

#[allow(dead_code)]
#[path = "../fuzz/src/bytes.rs"]
mod bytes;
#[allow(dead_code)]
#[path = "../fuzz/src/fric_case.rs"]
mod fric_case;
#[allow(dead_code)]
#[path = "../fuzz/src/gapcon_case.rs"]
mod gapcon_case;

use fric_case::{FricCase, FricOutputs};

/// Runs the fuzzer's property check and returns the outputs; fails the test with the property
/// that was violated.
fn checked(case: &FricCase) -> FricOutputs {
    case.check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"))
}

fn succeeded(case: &FricCase, out: &FricOutputs) {
    assert!(out.message.is_empty(), "refused: {}", out.message);
    assert_eq!(out.pnewdt.to_bits(), case.pnewdt.to_bits());
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
    let case = FricCase::decode(&CRASH_SLIP_RATE);
    assert_eq!(
        case.dtime,
        f64::MIN_POSITIVE,
        "the decoder changed: {case:?}"
    );
    let out = checked(&case);
    succeeded(&case, &out);
    assert_eq!(out.statev[1], f64::MAX);
}

#[test]
fn slip_rate_over_a_subnormal_dtime_saturates_and_the_state_stays_usable() {
    // μ = 0.3, γ_crit = 1e-3, p = 10: slip of 1 − 1e-3 in 2-D over Δt = 5e-324.
    let mut c = FricCase::coulomb(2, &[1.0, 0.3, 0.0, 0.0, 1e-3, 0.0, 0.0]);
    c.press = 10.0;
    c.dgam = vec![0.6, 0.8];
    c.dtime = 5e-324;
    let out = checked(&c);
    succeeded(&c, &out);
    assert!(close(out.statev[0], 1.0 - 1e-3, 1e-15));
    assert_eq!(out.statev[1], f64::MAX);
    assert_eq!(out.statev[2], 1.0);
    // The next increment accepts the state it was given.
    let mut next = c.clone();
    next.statev = out.statev.clone();
    next.dtime = 1.0;
    succeeded(&next, &checked(&next));
}

#[test]
fn accumulated_slip_near_f64_max_saturates() {
    let mut c = FricCase::coulomb(1, &[1.0, 0.3, 0.0, 0.0, 1e-3]);
    c.press = 10.0;
    c.dgam = vec![1e300];
    c.statev = vec![f64::MAX, 0.0, 1.0];
    let out = checked(&c);
    succeeded(&c, &out);
    assert_eq!(out.statev[0], f64::MAX);
    // Slip rate 1e300 − 1e-3 over Δt = 1: finite, unchanged by the saturation.
    assert_eq!(out.statev[1], 1e300);
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
    assert_eq!(case.nfdir, 2, "the decoder changed: {case:?}");
    let out = checked(&case);
    succeeded(&case, &out);
    // It slips now: the predictor is far longer than γ_crit.
    assert_eq!(out.statev[2], 1.0);
}

/// 2-D slip at 45° with τ_crit = μp = p/2: the expected answer at every scale of Δγ.
fn slip_at_45_degrees(dgam: f64, gamma_crit: f64, p: f64) -> FricOutputs {
    let mut c = FricCase::coulomb(2, &[1.0, 0.5, 0.0, 0.0, gamma_crit]);
    c.press = p;
    c.dgam = vec![dgam, dgam];
    let out = checked(&c);
    succeeded(&c, &out);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert_eq!(out.lm, 0);
    assert_eq!(out.statev[2], 1.0, "slipping");
    for a in 0..2 {
        assert!(close(out.tau[a], 0.5 * p * h, 1e-15), "{out:?}");
    }
    out
}

#[test]
fn tiny_slip_whose_square_underflows_sits_on_the_cone() {
    // |Δγ| = √2·1e-170 > γ_crit = 1e-300; (1e-170)² underflows.
    let out = slip_at_45_degrees(1e-170, 1e-300, 1.0);
    assert!(close(out.dslip[0], 1e-170, 1e-15));
    assert!(close(out.statev[0], 2f64.sqrt() * 1e-170, 1e-15));
}

#[test]
fn huge_slip_whose_square_overflows_is_accepted_and_exact() {
    // |Δγ| = √2·1e200: the squares overflow, the norm does not. Was refused as an overflow.
    let out = slip_at_45_degrees(1e200, 1e-3, 1.0);
    assert!(close(out.dslip[1], 1e200, 1e-15));
    let slip = 2f64.sqrt() * 1e200;
    assert!(close(out.statev[0], slip, 1e-15));
    assert!(close(out.sfd, 0.5 * slip, 1e-15));
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
        case.d = [1e-4, 50.0];
        case.temp = [300.0, 290.0];
        let k = case.check().unwrap_or_else(|e| panic!("{name}: {e}"));
        if *name == "NONE" {
            assert_eq!(k, 0.0);
        } else {
            assert!(k > 0.0, "{name}: k = {k}");
        }
    }
}

/// Crash 3 (fuzz target `fric`, found on the merged adhesive law): PROPS(1) = 2 with
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
fn crash_3_replays_clean() {
    let case = FricCase::decode(&CRASH_ADHESIVE_CANCELLATION);
    assert_eq!(case.props[0], 2.0, "the decoder changed: {case:?}");
    let out = checked(&case);
    succeeded(&case, &out);
    // Seed 004 with μ_s = μ_d = μ, S_a = k_μ = 0: sliding stress μp whatever the rate.
    let mu_p = case.props[1] * case.press;
    assert_eq!(out.lm, 0);
    assert!(
        close(out.tau[0].abs(), mu_p, 1e-13),
        "{} vs {mu_p}",
        out.tau[0]
    );
}

/// Crash 4 (fuzz target `fric`, on the merged extended law): anisotropic law 1 (μ₂ ≠ μ in
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
fn crash_4_replays_clean() {
    let case = FricCase::decode(&CRASH_EXTENDED_SLIP_RATE);
    assert_eq!(
        (case.nfdir, case.dtime),
        (2, f64::MIN_POSITIVE),
        "the decoder changed: {case:?}"
    );
    assert!(case.props[2] != 0.0 && case.props[2] != case.props[1]);
    let out = checked(&case);
    succeeded(&case, &out);
    assert_eq!(out.statev[1], f64::MAX);
}

/// Crash 5 (fuzz target `fric`): the adhesive law (PROPS(1) = 2) slipping over
/// DTIME = 5·10⁻³²⁴ from an accumulated slip of f64::MAX stored ∞ in STATEV(1..2); it now
/// saturates at f64::MAX like the Coulomb laws.
const CRASH_ADHESIVE_SLIP_RATE: [u8; 65] = [
    17, 100, 100, 226, 30, 215, 59, 10, 10, 10, 0, 30, 30, 30, 30, 50, 30, 100, 104, 100, 100, 100,
    100, 100, 255, 100, 255, 5, 5, 5, 5, 5, 5, 5, 5, 5, 100, 255, 255, 100, 0, 43, 90, 90, 90, 3,
    0, 0, 0, 0, 0, 0, 0, 90, 6, 0, 90, 90, 90, 90, 90, 42, 255, 100, 10,
];

#[test]
fn crash_5_replays_clean() {
    let case = FricCase::decode(&CRASH_ADHESIVE_SLIP_RATE);
    assert_eq!(case.props[0], 2.0, "the decoder changed: {case:?}");
    let out = checked(&case);
    succeeded(&case, &out);
    assert_eq!((out.statev[0], out.statev[1]), (f64::MAX, f64::MAX));
}

/// Crash 6 (fuzz target `fric`): the adhesive law with μ_d = 0, k_μ = 2, p = Δt = f64::MAX.
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
fn crash_6_replays_clean() {
    let case = FricCase::decode(&CRASH_ADHESIVE_SUBNORMAL_RATE);
    assert_eq!(case.props[0], 2.0, "the decoder changed: {case:?}");
    let out = checked(&case);
    succeeded(&case, &out);
    // Seed 004 with μ_s = μ_d = 0: τ = k_μ·(Δs/Δt)·p + S_a.
    let (s_a, k_mu) = (case.props[3], case.props[5]);
    let expected = k_mu * out.dslip[0].abs() * (case.press / case.dtime) + s_a;
    assert!(
        close(out.tau[0].abs(), expected, 1e-13),
        "{} vs {expected}",
        out.tau[0]
    );
}
