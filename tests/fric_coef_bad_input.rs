//! The bad-input catalogue (docs/bad-input.md, rows 68–82) for `fric_coef_` (FRIC_COEF) and
//! `ifl_forced_sliding`, through the real symbols with exactly sized arrays. Each case also
//! passes the `fric_coef` fuzz target's property check (compiled in from `fuzz/src` by path):
//! inputs unchanged, a refusal zeroes the block / the outputs and names the routine, a success
//! writes only finite values.

#[path = "common/fuzz_cases.rs"]
mod fuzz_cases;
#[path = "common/laws.rs"]
mod laws;
use fuzz_cases::fric_coef_case;
use laws::every_mu_law;

use fric_coef_case::{CoefNull, Coefficients, ForcedSlidingCase, FricCoefCase, SlideNull};
use fuzz_cases::args::{Args, Outputs};
use interfacial::abi::IflStatus;
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// Law 1 with every μ law on: μ_s = 0.5, μ₂ = 0.25, decay to μ_k = 0.2 at d_c = 2,
/// p_ref = 100, b_θ = 0.01 about θ_ref = 20.
fn all_laws() -> Vec<f64> {
    every_mu_law(0.5, 0.25).build_first(13)
}

/// The adhesive law with adhesion (S_a = `PROPS(4)` = 1): not a μ law.
fn adhesive_with_adhesion() -> Vec<f64> {
    AdhesiveBuilder::new().coeff(0.3).sa(1.0).build_first(4)
}

/// What the message of a non-finite `PROPS(i+1)` names: the entry, except θ_ref (`PROPS(13)`),
/// which is checked with b_θ and reported under `PROPS(12)` by its symbol.
fn prop_name(i: usize) -> String {
    if i == 12 {
        "θ_ref = ".into()
    } else {
        format!("PROPS({})", i + 1)
    }
}

/// Three good points.
fn block(props: &[f64]) -> FricCoefCase {
    FricCoefCase::block(
        props,
        &[0.0, 0.5, 3.0],
        &[0.0, 100.0, 50.0],
        &[20.0, 120.0, 20.0],
    )
}

fn run(case: &FricCoefCase) -> Outputs {
    case.check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"))
}

fn refused(case: &FricCoefCase, needle: &str) -> Outputs {
    let out = run(case);
    let prefix = "interfacial: FRIC_COEF: interaction 'SI1' (block): ";
    assert_message(&out.message, prefix, needle);
    out
}

/// A refusal's message: it names the routine (and the interaction) first, then the cause.
fn assert_message(message: &str, prefix: &str, needle: &str) {
    assert!(
        message.starts_with(prefix),
        "{message:?} does not start {prefix:?}"
    );
    assert!(message.contains(needle), "{message:?} lacks {needle:?}");
}

fn accepted(case: &FricCoefCase) -> Outputs {
    let out = run(case);
    assert!(out.message.is_empty(), "refused: {}", out.message);
    out
}

fn same_bits(a: &Outputs, b: &Outputs) -> bool {
    let bits = |o: &Outputs| -> Vec<u64> {
        o["fCoef"]
            .iter()
            .chain(&o["fCoefDeriv"])
            .map(|x| x.to_bits())
            .collect()
    };
    bits(a) == bits(b)
}

/// Row 68: a slip rate NaN, ±Inf or negative, at any point.
#[test]
fn fric_coef_bad_slip_rate_is_refused() {
    for k in 0..3 {
        for x in BAD.into_iter().chain([-1e-300, -2.0]) {
            let mut c = block(&all_laws());
            c.args["slipData"][k] = x;
            refused(&c, &format!("slipData({}, 1) = ", k + 1));
        }
    }
}

/// Row 69: a pressure NaN or ±Inf.
#[test]
fn fric_coef_non_finite_pressure_is_refused() {
    for k in 0..3 {
        for x in BAD {
            let mut c = block(&all_laws());
            c.args["pressure"][k] = x;
            refused(&c, &format!("pressure({}) = ", k + 1));
        }
    }
}

/// Row 70: a temperature NaN or ±Inf is refused with a temperature law and not read without.
#[test]
fn fric_coef_non_finite_temperature() {
    let mut constant = all_laws();
    constant[11] = 0.0;
    constant[12] = 0.0;
    let clean = accepted(&block(&constant));
    for k in 0..3 {
        for x in BAD {
            let mut c = block(&all_laws());
            c.args["tempAvg"][k] = x;
            refused(&c, &format!("tempAvg({}) = ", k + 1));
            let mut c = block(&constant);
            c.args["tempAvg"][k] = x;
            assert!(same_bits(&accepted(&c), &clean));
        }
    }
}

/// Row 71: NaN or ±Inf in what FRIC_COEF never reads (slipData(k,2..6), rData, fieldAvg) has
/// no effect on any output bit.
#[test]
fn fric_coef_unread_reals_have_no_effect() {
    let clean = accepted(&block(&all_laws()));
    for x in BAD {
        let mut c = block(&all_laws());
        for v in &mut c.args["slipData"][3..] {
            *v = x;
        }
        c.args["rData"] = vec![x; 3];
        c.args.set_int("nFields", 2);
        c.args["fieldAvg"] = vec![x; 6];
        assert!(same_bits(&accepted(&c), &clean));
    }
}

/// Row 72: NULL pointers. Read ones are refused and named; a NULL output array is refused
/// before anything is written (fuzz crash C1); a NULL nBlock writes nothing; nTemp and tempAvg
/// may be NULL without a temperature law.
#[test]
fn fric_coef_null_pointers() {
    use CoefNull::{FCoef, FCoefDeriv, NBlock, NProps, NTemp, Pressure, Props, SlipData, TempAvg};
    let arguments = [
        (FCoef, "fCoef"),
        (FCoefDeriv, "fCoefDeriv"),
        (NBlock, "nBlock"),
        (NProps, "nProps"),
        (NTemp, "nTemp"),
        (Props, "props"),
        (SlipData, "slipData"),
        (Pressure, "pressure"),
        (TempAvg, "tempAvg"),
    ];
    for (null, argument) in arguments {
        let mut c = block(&all_laws());
        c.null = null;
        let out = refused(&c, &format!("{argument} is a NULL pointer"));
        if null == NBlock {
            assert!(
                out["fCoef"]
                    .iter()
                    .all(|x| *x == fuzz_cases::contract::UNWRITTEN)
            );
        }
    }
    let mut constant = all_laws();
    constant[11] = 0.0;
    constant[12] = 0.0;
    for null in [CoefNull::NTemp, CoefNull::TempAvg] {
        let mut c = block(&constant);
        c.null = null;
        accepted(&c);
    }
}

/// Row 73: nBlock < 0 is refused and nothing written; nBlock = 0 is an empty block (PROPS still
/// checked).
#[test]
fn fric_coef_block_sizes() {
    let mut c = FricCoefCase::block(&all_laws(), &[], &[], &[]);
    accepted(&c);
    c.args["props"][1] = -0.5;
    refused(&c, "PROPS(2)");
    for n in [-1, -1000, i32::MIN] {
        let mut c = FricCoefCase::block(&all_laws(), &[], &[], &[]);
        c.args.set_int("nBlock", n);
        refused(&c, &format!("nBlock = {n} is negative"));
    }
}

/// Row 74: a temperature law with nTemp ≤ 0.
#[test]
fn fric_coef_temperature_law_needs_ntemp() {
    for nt in [0, -1] {
        let mut c = block(&all_laws());
        c.args.set_int("nTemp", nt);
        refused(&c, &format!("nTemp = {nt}"));
    }
}

/// Row 75: bad PROPS — sizes, non-finite entries, values out of range, entries not read, the
/// adhesive law with its own features.
#[test]
fn fric_coef_bad_props() {
    let mut short = block(&[1.0]);
    short.args.set_int("nProps", 1);
    refused(&short, "NPROPS");
    let mut none = block(&[]);
    none.args.set_int("nProps", 0);
    refused(&none, "NPROPS");
    let mut negative = block(&[]);
    negative.args.set_int("nProps", -3);
    refused(&negative, "nProps = -3 is negative");
    for i in 0..13 {
        for x in BAD {
            let mut p = all_laws();
            p[i] = x;
            refused(&block(&p), &prop_name(i));
        }
    }
    let mut extra = all_laws();
    extra.resize(21, 0.0);
    extra[20] = 1.0;
    refused(&block(&extra), "PROPS(21)");
    for (i, x, name) in [
        (0, 4.0, "PROPS(1)"),
        (0, 1.5, "PROPS(1)"),
        (1, -0.5, "PROPS(2)"),
        (7, 2.0, "PROPS(8)"),
        (8, -0.1, "PROPS(9)"),
        (9, 0.0, "PROPS(10)"),
        (9, -1.0, "PROPS(10)"),
        (10, -5.0, "PROPS(11)"),
    ] {
        let mut p = all_laws();
        p[i] = x;
        refused(&block(&p), name);
    }
    // The decay law's entries without the decay law, θ_ref without b_θ.
    let mut p = all_laws();
    p[7] = 0.0;
    refused(&block(&p), "PROPS(9)");
    let mut p = all_laws();
    p[11] = 0.0;
    refused(&block(&p), "PROPS(13)");
    // The adhesive law with adhesion (S_a = PROPS(4)) is not a μ law FRIC_COEF can give.
    refused(&block(&adhesive_with_adhesion()), "PROPS(1) = 2");
}

/// Row 76: μ overflowing (Θ = exp(−b_θ(θ̄ − θ_ref)) past f64::MAX) is a numerical failure.
#[test]
fn fric_coef_overflow_is_refused() {
    let mut c = block(&all_laws());
    c.args["tempAvg"][1] = -1e6;
    refused(&c, "overflowed");
}

/// Row 77: a negative pressure is not an error: μ of p = 0, ∂μ/∂p = 0.
#[test]
fn fric_coef_negative_pressure_uses_zero() {
    let p = all_laws();
    let at_zero = accepted(&FricCoefCase::block(&p, &[0.5], &[0.0], &[30.0]));
    let below = accepted(&FricCoefCase::block(&p, &[0.5], &[-50.0], &[30.0]));
    // μ = (0.2 + 0.3 e^{-1})·e^{-0.1} at p = 0.
    let mu = (0.2 + 0.3 * (-1.0f64).exp()) * (-0.1f64).exp();
    assert!((below.mu(1, 0, 0) - mu).abs() < 1e-15);
    assert_eq!(below.mu(1, 0, 0).to_bits(), at_zero.mu(1, 0, 0).to_bits());
    assert_eq!(below.deriv(1, 0, 1, 0), 0.0);
    assert!(at_zero.deriv(1, 0, 1, 0) < 0.0);
}

// ---- ifl_forced_sliding ----------------------------------------------------------------------

fn slide(props: &[f64], nfdir: i32) -> ForcedSlidingCase {
    let mut args = Args::new();
    args.set_int("nfdir", nfdir);
    args.set_int("nprops", props.len() as i32);
    args.put("props", props.to_vec());
    args.put(
        "velocity",
        [0.3, -0.4][..nfdir.clamp(0, 2) as usize].to_vec(),
    );
    args.put("pressure", vec![40.0]);
    args.put("temperature", vec![30.0]);
    ForcedSlidingCase {
        args,
        null: SlideNull::None,
    }
}

fn slide_run(case: &ForcedSlidingCase) -> Outputs {
    case.check()
        .unwrap_or_else(|e| panic!("{e}\ninput: {case:?}"))
}

fn slide_refused(case: &ForcedSlidingCase, status: IflStatus, needle: &str) {
    let out = slide_run(case);
    assert_eq!(out.int("status"), status as i32, "{}", out.message);
    assert_message(&out.message, "interfacial: ifl_forced_sliding: ", needle);
}

/// Row 78: velocity, pressure or temperature NaN or ±Inf.
#[test]
fn forced_sliding_non_finite_inputs() {
    for nfdir in [1, 2] {
        for x in BAD {
            for which in 0..(nfdir as usize + 2) {
                let mut c = slide(&all_laws(), nfdir);
                match which {
                    0 => c.args["pressure"][0] = x,
                    1 => c.args["temperature"][0] = x,
                    a => c.args["velocity"][a - 2] = x,
                }
                slide_refused(&c, IflStatus::BadInput, "NaN or infinite");
            }
        }
    }
}

/// Row 79: NULL pointers.
#[test]
fn forced_sliding_null_pointers() {
    for (null, needle) in [
        (SlideNull::Props, "props is a NULL pointer"),
        (SlideNull::Velocity, "velocity is a NULL pointer"),
        (SlideNull::Tau, "output pointer is NULL"),
        (SlideNull::Damping, "output pointer is NULL"),
        (SlideNull::Stiffness, "output pointer is NULL"),
    ] {
        for nfdir in [1, 2] {
            let mut c = slide(&all_laws(), nfdir);
            c.null = null;
            slide_refused(&c, IflStatus::BadInput, needle);
        }
    }
}

/// Row 80: nfdir other than 1 or 2, nprops < 0.
#[test]
fn forced_sliding_bad_sizes() {
    for nfdir in [0, 3, -1] {
        slide_refused(&slide(&all_laws(), nfdir), IflStatus::BadParameter, "nfdir");
    }
    let mut c = slide(&all_laws(), 2);
    c.args.set_int("nprops", -1);
    slide_refused(&c, IflStatus::BadParameter, "nprops = -1 is negative");
}

/// Row 81: bad PROPS, as for FRIC_COEF.
#[test]
fn forced_sliding_bad_props() {
    for i in 0..13 {
        let mut p = all_laws();
        p[i] = f64::NAN;
        slide_refused(&slide(&p, 2), IflStatus::BadParameter, &prop_name(i));
    }
    let mut p = all_laws();
    p[1] = -0.5;
    slide_refused(&slide(&p, 2), IflStatus::BadParameter, "PROPS(2)");
    slide_refused(&slide(&[1.0], 2), IflStatus::BadParameter, "NPROPS");
    slide_refused(
        &slide(&adhesive_with_adhesion(), 2),
        IflStatus::BadParameter,
        "PROPS(1) = 2",
    );
}

/// Row 82: zero velocity and negative pressure are not errors (zeros); overflow is a numerical
/// failure with zeroed outputs.
#[test]
fn forced_sliding_edge_values() {
    let mut c = slide(&all_laws(), 2);
    c.args["velocity"] = vec![0.0, -0.0];
    let out = slide_run(&c);
    assert_eq!(out.int("status"), IflStatus::Ok as i32);
    assert!(
        out["tau"]
            .iter()
            .chain(&out["damping"])
            .chain(&out["stiffness"])
            .all(|x| *x == 0.0)
    );
    let mut c = slide(&all_laws(), 2);
    c.args["pressure"][0] = -10.0;
    let out = slide_run(&c);
    assert_eq!(out.int("status"), IflStatus::Ok as i32);
    assert!(out["tau"].iter().all(|x| *x == 0.0));
    // μ = 10 at p = 1e308 overflows τ = μp.
    let mut c = slide(&CoulombBuilder::new().mu(10.0).build_first(2), 2);
    c.args["pressure"][0] = 1e308;
    slide_refused(&c, IflStatus::NumericalFailure, "overflowed");
}
