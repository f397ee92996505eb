//! The batch entry point against `fric_` called once per point: bit-identical outputs on random
//! inputs (stick, slip, exact stick, shear limit, γ_crit from CHRLNGTH, NFDIR 1 and 2, LM 0/1/2,
//! padded leading dimensions), through both the Rust API and the C entry `ifl_fric_batch`;
//! `fric_`'s failure outputs for a bad point; nothing but PNEWDT written on a whole-batch fault.

mod common;

use common::{Points, Rng, UNSET, first_difference, per_point, via_c};
use interfacial::abi::batch::BatchError;
use interfacial::abi::{FricBatch, IflStatus, fric_batch, ifl_fric_batch};
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::FricCall;

fn random_points(rng: &mut Rng, n: usize, ld: usize, nfdir: usize, gamma_crit: f64) -> Points {
    // Inputs of the padding (between n and ld) stay UNSET: the batch must not read them.
    let mut p = Points::new(n, ld, nfdir, 4);
    for i in 0..n {
        p.lm[i] = [0, 0, 0, 1, 2][rng.pick(5)];
        let pr = rng.range(-5.0, 150.0);
        p.press[i] = pr;
        p.dpress[i] = rng.range(-20.0, 20.0);
        p.chrlngth[i] = rng.range(0.05, 2.0);
        // |γ_pr|/γ_crit spread over stick and slip.
        let scale = gamma_crit * [0.3, 1.0, 4.0][rng.pick(3)];
        for a in 0..nfdir {
            p.tau[i + a * ld] = rng.range(-30.0, 30.0);
            p.dgam[i + a * ld] = rng.range(-1.0, 1.0) * scale;
            p.taulm[i + a * ld] = rng.range(-60.0, 60.0);
        }
        p.statev[i] = rng.range(0.0, 1.0);
        p.statev[i + ld] = rng.range(0.0, 1.0);
        p.statev[i + 2 * ld] = rng.pick(3) as f64;
        p.statev[i + 3 * ld] = -1.0;
    }
    p
}

/// The points through `fric_batch`, with or without the optional outputs DSLIP, SED, SFD.
fn via_rust(
    props: &[f64],
    dtime: f64,
    input: &Points,
    optional: bool,
) -> (Points, f64, Result<(), BatchError>) {
    let mut p = input.clone();
    let mut pnewdt = 1e36;
    let result = {
        let mut b = FricBatch {
            npoints: p.n,
            ld: p.ld,
            nfdir: p.nfdir,
            nstatv: p.nstatv,
            lm: &mut p.lm,
            tau: &mut p.tau,
            ddtddg: &mut p.ddtddg,
            ddtddp: &mut p.ddtddp,
            dslip: optional.then_some(&mut p.dslip[..]),
            sed: optional.then_some(&mut p.sed[..]),
            sfd: optional.then_some(&mut p.sfd[..]),
            statev: &mut p.statev,
            dgam: &input.dgam,
            taulm: Some(&input.taulm),
            press: &input.press,
            dpress: &input.dpress,
            chrlngth: &input.chrlngth,
        };
        fric_batch(props, dtime, &mut b, &mut pnewdt)
    };
    (p, pnewdt, result)
}

fn assert_identical(what: &str, a: &Points, b: &Points) {
    assert_eq!(first_difference(a, b), None, "{what}");
}

/// PROPS variants: elastic stick (absolute γ_crit, from CHRLNGTH, with τ_max) and exact stick.
fn props_variants() -> Vec<(Vec<f64>, f64)> {
    let law = |mu: f64| CoulombBuilder::new().mu(mu);
    vec![
        (first_variant().build_first(7), 1e-3),
        (law(0.45).slip_tolerance(0.01).build_first(7), 5e-3),
        (law(0.3).tau_max(25.0).gamma_crit(2e-3).build_first(7), 2e-3),
        (first_variant().stick(1.0).build_first(7), 1e-3),
        (law(0.3).build_first(2), 5e-3),
    ]
}

/// The first of [`props_variants`]: μ = 0.3, γ_crit = 10⁻³, elastic stick.
fn first_variant() -> CoulombBuilder {
    CoulombBuilder::new().mu(0.3).gamma_crit(1e-3)
}

#[test]
fn batch_is_bit_identical_to_fric_per_point() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut cases = 0;
    for (props, gc) in props_variants() {
        for nfdir in [1, 2] {
            for (n, pad) in [(1usize, 0usize), (257, 0), (300, 13)] {
                let input = random_points(&mut rng, n, n + pad, nfdir, gc);
                let dtime = rng.range(1e-3, 2.0);
                let (expected, pnewdt, _) = per_point(&props, dtime, &input);
                assert_eq!(pnewdt, 1e36, "valid inputs must not cut back");
                let (r, pr, result) = via_rust(&props, dtime, &input, true);
                assert!(result.is_ok());
                assert_eq!(pr, pnewdt);
                assert_identical("Rust API", &expected, &r);
                let (c, pc, st) = via_c(&props, dtime, &input);
                assert_eq!(st, IflStatus::Ok);
                assert_eq!(pc, pnewdt);
                assert_identical("ifl_fric_batch", &expected, &c);
                // The padding between ld and n is never written.
                assert!(c.sed[n..].iter().all(|x| *x == UNSET));
                cases += 1;
            }
        }
    }
    assert_eq!(cases, 30);
    // The random inputs cover every branch: count them in one case.
    let input = random_points(&mut rng, 2000, 2000, 2, 1e-3);
    let (out, _, _) = per_point(&props_variants()[0].0, 0.1, &input);
    let (mut stick, mut slip, mut frictionless) = (0, 0, 0);
    for i in 0..2000 {
        match (input.lm[i], out.statev[i + 2 * 2000]) {
            (2, _) => frictionless += 1,
            (_, 0.0) => stick += 1,
            (_, 1.0) => slip += 1,
            _ => {}
        }
    }
    assert!(stick > 100 && slip > 100 && frictionless > 100);
}

#[test]
fn a_bad_point_gets_fric_failure_outputs_and_the_rest_are_computed() {
    let mut rng = Rng(42);
    let props = props_variants()[0].0.clone();
    for nfdir in [1, 2] {
        let mut input = random_points(&mut rng, 50, 50, nfdir, 1e-3);
        input.lm[7] = 0;
        input.dgam[7] = f64::NAN;
        input.lm[20] = 0;
        input.press[20] = f64::INFINITY;
        let (expected, pnewdt, _) = per_point(&props, 0.5, &input);
        assert_eq!(pnewdt, 0.25);
        let (c, pc, st) = via_c(&props, 0.5, &input);
        assert_eq!(st, IflStatus::BadInput);
        assert_eq!(pc, 0.25);
        assert_identical("bad point", &expected, &c);
        let msg = FricCall::last_error();
        assert!(
            msg.contains("ifl_fric_batch") && msg.contains("point 20"),
            "{msg}"
        );
        let (_, pn, result) = via_rust(&props, 0.5, &input, false);
        let e = result.unwrap_err();
        assert_eq!((e.point, e.failed), (Some(7), 2));
        assert_eq!(pn, 0.25);
    }
}

#[test]
fn whole_batch_faults_write_only_pnewdt() {
    let mut rng = Rng(7);
    let input = random_points(&mut rng, 10, 10, 2, 1e-3);
    let good = first_variant().build_first(7);
    // Bad PROPS (μ < 0), bad NFDIR, ld < npoints, short NSTATV, NULL arrays.
    let bad_mu = first_variant().mu(-1.0).build_first(7);
    let (c, pc, st) = via_c(&bad_mu, 0.5, &input);
    assert_eq!((st, pc), (IflStatus::BadParameter, 0.25));
    assert_identical("bad PROPS", &input, &c);
    assert!(FricCall::last_error().contains("ifl_fric_batch"));
    // The adhesive law (PROPS(1) = 2, here with S_a > 0 so it is not the Coulomb special case)
    // has no batch kernel: refused as a whole, naming the law.
    let adhesive = AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(-1.0)
        .sa(1.0)
        .gamma_crit(1e-3)
        .build_first(8);
    let (c, pc, st) = via_c(&adhesive, 0.5, &input);
    assert_eq!((st, pc), (IflStatus::BadParameter, 0.25));
    assert_identical("adhesive PROPS", &input, &c);
    assert!(FricCall::last_error().contains("runs the plain Coulomb law (law 1) only"));
    // Anisotropy (PROPS(3) != PROPS(2)) is the extended law 1: refused as a whole too.
    let anisotropic = first_variant().mu2(0.5 * 0.3).build_first(7);
    let (c, pc, st) = via_c(&anisotropic, 0.5, &input);
    assert_eq!((st, pc), (IflStatus::BadParameter, 0.25));
    assert_identical("anisotropic PROPS", &input, &c);
    assert!(FricCall::last_error().contains("extended law-1 PROPS"));
    let mut p = input.clone();
    for (nfdir, ld, nstatv, expect) in [
        (3, 10, 4, IflStatus::BadParameter),
        (2, 9, 4, IflStatus::BadParameter),
        (2, 10, 2, IflStatus::BadParameter),
    ] {
        let (st, pnewdt) = refused_ten_points(&good, &input, &mut p, (ld, nfdir, nstatv), false);
        assert_eq!((st, pnewdt), (expect, 0.25));
        assert_identical("refused batch", &input, &p);
    }
    // A required array NULL: refused with BadInput, naming it.
    let (st, pnewdt) = refused_ten_points(&good, &input, &mut p, (10, 2, 4), true);
    assert_eq!((st, pnewdt), (IflStatus::BadInput, 0.25));
    assert!(FricCall::last_error().contains("chrlngth"));
    assert_identical("NULL chrlngth", &input, &p);
    // An empty batch is fine with NULL everywhere.
    // SAFETY: npoints = 0: nothing is read or written.
    let st = unsafe {
        ifl_fric_batch(
            0,
            0,
            1,
            good.as_ptr(),
            7,
            3,
            0.5,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null_mut(),
        )
    };
    assert_eq!(st, IflStatus::Ok);
}

/// A batch of the 10 points of `input` (outputs into `p`; `NPROPS` 7, Δt 0.5; DSLIP, SED, SFD
/// and CHRLNGTH NULL, TAULM too unless `taulm`) that must be refused before any array is read:
/// `shape` = (ld, NFDIR, NSTATV). The status and PNEWDT.
fn refused_ten_points(
    props: &[f64],
    input: &Points,
    p: &mut Points,
    shape: (usize, i32, i32),
    taulm: bool,
) -> (IflStatus, f64) {
    let (ld, nfdir, nstatv) = shape;
    let mut pnewdt = 1e36;
    // SAFETY: the arrays are sized for 10 points with ld = 10, NFDIR 2 and NSTATV 4; the call
    // must refuse (a bad shape, or the NULL CHRLNGTH) before it reads or writes any of them.
    let st = unsafe {
        ifl_fric_batch(
            10,
            ld,
            nfdir,
            props.as_ptr(),
            7,
            nstatv,
            0.5,
            p.lm.as_mut_ptr(),
            p.tau.as_mut_ptr(),
            p.ddtddg.as_mut_ptr(),
            p.ddtddp.as_mut_ptr(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            p.statev.as_mut_ptr(),
            input.dgam.as_ptr(),
            if taulm {
                input.taulm.as_ptr()
            } else {
                std::ptr::null()
            },
            input.press.as_ptr(),
            input.dpress.as_ptr(),
            std::ptr::null(),
            &mut pnewdt,
        )
    };
    (st, pnewdt)
}
