//! The `vfric` fuzz target's decoder and property checks (docs/fuzzing.md), replayed on
//! hand-made byte strings that reach each branch of `vfric_` (slip, stick, the τ_max·A cap, a
//! bad point, a refused PROPS, nFricDir out of range, rough friction with every unread pointer
//! NULL, a NULL output, an empty block, the adhesive law), plus closed-form cases that do not
//! depend on the byte encoding.
//!
//! The decoder and checks are compiled in from `fuzz/src` by path, so a replayed input is
//! checked for exactly the properties the fuzzer checks. The decoder speaks the double-precision
//! `vfric_` (the fuzz crate builds the default features), so these tests are left out of the
//! single-precision build (`--features explicit-single`, covered by `tests/vfric.rs`).
#![cfg(not(feature = "explicit-single"))]

#[path = "common/fuzz_cases.rs"]
mod fuzz_cases;
use fuzz_cases::vfric_case;

use fuzz_cases::args::Outputs;
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use vfric_case::{Tangential, VfricCase, VfricNull};

fn replay(data: &[u8]) -> (VfricCase, Outputs) {
    let case = VfricCase::decode(data);
    match case.check() {
        Ok(out) => (case, out),
        Err(e) => panic!("{e}\ninput: {case:?}"),
    }
}

/// Reals in the byte encoding of `fuzz/src/bytes.rs`: class 9 is a small integer, 16 an
/// ordinary 1.x·10^(e−12), 1 NaN.
const MU_0_55: [u8; 4] = [0, 0x00, 0x80, 5]; // selector 0, positive(): 5.5·10^-1

/// Two points, nFricDir = 2, μ = 0.55: point 1 sticks (μF_N = 2.2 > F_stick = 1), point 2
/// slips (μF_N = 1.1 < F_stick = 7).
#[test]
fn stick_and_slip() {
    let mut d = vec![2, 1, 1, 0, 255, 0];
    d.extend(MU_0_55);
    d.extend([0, 0, 0, 0, 0, 4, 9, 4, 9, 2, 9, 1, 9, 7, 0, 1, 9, 1, 9, 1]);
    let (case, out) = replay(&d);
    assert_eq!(
        (
            case.args.int("nContact"),
            case.args.int("nFricDir"),
            case.null
        ),
        (2, 2, VfricNull::None)
    );
    assert_eq!(
        (
            case.args["fNormal"].as_slice(),
            case.args["fStickForce"].as_slice()
        ),
        (&[4.0, 2.0][..], &[1.0, 7.0][..])
    );
    assert!(out.message.is_empty(), "{}", out.message);
    assert_eq!(out.force(2, 0, 0), -1.0);
    assert_eq!(out.force(2, 1, 0), -(case.args["props"][1] * 2.0));
    assert_eq!(out.force(2, 1, 1).to_bits(), 0);
}

/// τ_max = 1 with areaSlv(1) = 0.1: the cap 0.1 wins at point 1; point 2 has F_N = NaN and
/// point 3 slave node 2 of 1: both get 0, the message names point 3.
#[test]
fn shear_cap_and_bad_points() {
    let mut d = vec![3, 0, 0, 0, 255, 0];
    d.extend(MU_0_55);
    d.extend([
        0, 4, 0, 0, 6, 0, 0, 0, 4, 9, 4, 1, 9, 4, 9, 7, 9, 7, 9, 7, 0, 0, 220,
    ]);
    d.extend([16, 0, 0, 11]);
    let (case, out) = replay(&d);
    assert_eq!(
        (
            case.args.int("nContact"),
            case.args.int("nFricDir"),
            case.args.int("nSlvNod")
        ),
        (3, 1, 1)
    );
    assert_eq!(
        (
            case.args["props"][3],
            case.args["areaSlv"][0],
            case.args.ints("jConSlvid")[2]
        ),
        (1.0, 0.1, 2)
    );
    assert_eq!(out.force(1, 0, 0), -0.1);
    assert_eq!(out.force(1, 1, 0).to_bits(), 0);
    assert_eq!(out.force(1, 2, 0).to_bits(), 0);
    assert!(out.message.contains("(contact point 3)"), "{}", out.message);
}

/// μ₂ = 3 ≠ μ (anisotropy): the call is refused, the whole block +0.
#[test]
fn anisotropic_props_refused() {
    let mut d = vec![2, 1, 1, 0, 255, 0];
    d.extend(MU_0_55);
    d.extend([6, 9, 3, 0, 0, 0, 0, 4, 9, 4, 9, 4, 9, 1, 9, 1]);
    let (case, out) = replay(&d);
    assert_eq!(case.args["props"][2], 3.0);
    assert!(out.message.contains("(block)"), "{}", out.message);
    assert!(
        out["fTangential"][vfric_case::GUARD..][..4]
            .iter()
            .all(|x| x.to_bits() == 0)
    );
}

/// nFricDir = 3: refused, nothing written.
#[test]
fn nfricdir_out_of_range_writes_nothing() {
    let (case, out) = replay(&[1, 9, 0, 0, 255]);
    assert_eq!(case.args.int("nFricDir"), 3);
    assert!(out.message.contains("nFricDir = 3"), "{}", out.message);
    assert!(
        out["fTangential"]
            .iter()
            .all(|x| *x == vfric_case::UNWRITTEN)
    );
}

/// Rough friction (PROPS(7) = 2) with τ_max set and every unread pointer (and statev) NULL:
/// F = F_stick, the slave node (i32::MIN) and the area are not read.
#[test]
fn rough_friction_with_unread_pointers_null() {
    let mut d = vec![0, 0, 0, 0, 20, 0];
    d.extend(MU_0_55);
    d.extend([0, 4, 0, 0, 6, 0, 0, 4, 4, 9, 4, 9, 7, 240]);
    let (case, out) = replay(&d);
    assert_eq!(
        (
            case.null,
            case.args["props"][6],
            case.args.ints("jConSlvid")[0]
        ),
        (VfricNull::Unread, 2.0, i32::MIN)
    );
    assert!(out.message.is_empty(), "{}", out.message);
    assert_eq!(out.force(1, 0, 0), -7.0);
}

/// fTangential NULL: refused, nothing written; nContact = 0: no message.
#[test]
fn null_output_and_empty_block() {
    let mut d = vec![0, 0, 0, 0, 0, 0];
    d.extend(MU_0_55);
    let (case, out) = replay(&d);
    assert_eq!(case.null, VfricNull::FTangential);
    assert!(
        out.message.contains("fTangential is a NULL pointer"),
        "{}",
        out.message
    );
    let mut d = vec![11, 0, 0, 0, 255, 0];
    d.extend(MU_0_55);
    let (case, out) = replay(&d);
    assert_eq!(case.args.int("nContact"), 0);
    assert!(out.message.is_empty(), "{}", out.message);
}

/// PROPS(1) = 2 (adhesive, even in the form fric_ runs as plain Coulomb): refused.
#[test]
fn adhesive_props_refused() {
    let mut d = vec![0, 0, 0, 0, 255, 7, 9, 2];
    d.extend(MU_0_55);
    let (case, out) = replay(&d);
    assert_eq!(case.args["props"][0], 2.0);
    assert!(out.message.contains("(block)"), "{}", out.message);
    assert_eq!(out.force(1, 0, 0).to_bits(), 0);
}

/// Closed forms: tension gives 0, the cap τ_max·A, a huge μ·F_N (∞) capped by F_stick.
#[test]
fn closed_forms_on_a_block() {
    // μ = 4, τ_max = 2, stick mode 1 (exact).
    let props = CoulombBuilder::new()
        .mu(4.0)
        .tau_max(2.0)
        .stick(1.0)
        .build_first(7);
    let normal = [-1.0, 10.0, f64::MAX, 1.0];
    let stick = [5.0, 50.0, 7.0, 50.0];
    let case = VfricCase::block(&props, 2, &normal, &stick, &[1, 2, 1, 2], &[3.0, 0.25]);
    let out = case.check().unwrap_or_else(|e| panic!("{e}"));
    assert!(out.message.is_empty(), "{}", out.message);
    // −min(μF_N, τ_max·A, F_stick): 0 in tension; min(40, 0.5, 50); min(∞, 6, 7); min(4, 0.5, 50).
    let want: [f64; 4] = [0.0, -0.5, -6.0, -0.5];
    for (k, w) in want.iter().enumerate() {
        assert_eq!(out.force(2, k, 0).to_bits(), w.to_bits(), "point {}", k + 1);
        assert_eq!(out.force(2, k, 1).to_bits(), 0);
    }
}

/// The extended law (PROPS(8) = 1, decay) is refused with a message saying so.
#[test]
fn extended_props_refused() {
    let props = CoulombBuilder::new()
        .mu(0.3)
        .mu_law(1.0)
        .mu_k(0.1)
        .decay(1.0)
        .build_first(10);
    let case = VfricCase::block(&props, 1, &[1.0], &[1.0], &[1], &[1.0]);
    let out = case.check().unwrap_or_else(|e| panic!("{e}"));
    assert!(out.message.contains("extended"), "{}", out.message);
    assert_eq!(out.force(1, 0, 0).to_bits(), 0);
}

/// Defect found by `adhesive_props_refused` (the first replay of the decoder): the adhesive
/// `PROPS` in its Coulomb special case (μ_s absent or equal to μ_d, no adhesion) parsed as a
/// plain Coulomb law, and `vfric_` ran it with μ = μ_d although docs/vfric.md (and bad-input
/// row V4) say law 2 is refused in VFRIC. Now refused like every other adhesive `PROPS`.
#[test]
fn adhesive_coulomb_special_case_is_refused() {
    let special = AdhesiveBuilder::new().coeff(0.4);
    for props in [
        special.build_first(2),
        special.clone().coeff_static(0.4).build_first(7),
        special.build(),
    ] {
        let case = VfricCase::block(&props, 2, &[10.0, 1.0], &[50.0, 50.0], &[1, 1], &[1.0]);
        let out = case.check().unwrap_or_else(|e| panic!("{e}"));
        assert!(
            out.message.contains("PROPS(1) = 2 (adhesive law)"),
            "{props:?}: {}",
            out.message
        );
        for k in 0..2 {
            for d in 0..2 {
                assert_eq!(out.force(2, k, d).to_bits(), 0, "{props:?}");
            }
        }
    }
}
