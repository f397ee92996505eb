//! The calling thread's last error (docs/install.md, "Errors"): a successful call into any entry
//! point leaves it as it was (like C's `errno`), only a new failure replaces it, and only
//! `ifl_clear_error` empties it. Checked for every entry point: a failure is recorded, then a
//! successful call of each entry point in turn must leave that text untouched.

#[path = "common/config_file.rs"]
mod config_file;
#[path = "common/fric_coef.rs"]
mod fric_coef_common;
#[path = "common/refusal.rs"]
mod refusal;
use fric_coef_common::fric_coef_call;
use refusal::assert_mentions;
#[path = "common/vfric.rs"]
mod vfric_common;
use std::ffi::{CStr, c_char, c_int};
use vfric_common::{Block as VfricBlock, call as vfric_call};

use interfacial::abi::{
    IflConductance, IflStatus, ifl_clear_error, ifl_forced_sliding, ifl_fric_batch,
    ifl_gap_conductance, ifl_gap_conductance_n, ifl_last_error, ifl_last_error_copy,
};
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::{FricCall, GapconCall, UinterCall};

/// Law 1, μ = 0.3, γ_crit = 10⁻³, `PROPS(1..5)`: the good call of every law-1 entry point.
fn coulomb() -> Vec<f64> {
    CoulombBuilder::new()
        .mu(0.3)
        .gamma_crit(1e-3)
        .build_first(5)
}

fn setup() {
    config_file::config_once(
        "last-error",
        "[interactions.SI1.conductance]\nlaw = \"constant\"\nk = 2.0\n",
    );
}

fn last() -> String {
    // SAFETY: ifl_last_error returns a NUL-terminated thread-local buffer, read at once.
    unsafe { CStr::from_ptr(ifl_last_error()) }
        .to_string_lossy()
        .into_owned()
}

/// A GAPCON failure on this thread: an interaction the file does not configure.
fn fail() -> String {
    let mut g = GapconCall::new("NOT-CONFIGURED", 0.0, 1.0, 300.0, 290.0);
    assert_eq!(g.call(), 0.0);
    let m = last();
    assert_mentions(&m, &["GAPCON", "NOT-CONFIGURED"], "unconfigured GAPCON");
    m
}

fn fric_ok() {
    let mut c = FricCall::new(2, &coulomb());
    c.press = 100.0;
    c.dgam[0] = 1e-4;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "fric_ succeeded");
}

fn gapcon_ok() {
    let mut g = GapconCall::new("SI1", 0.0, 1.0, 300.0, 290.0);
    assert_eq!(g.call(), 2.0);
}

fn uinter_ok() {
    // The adhesive law with S_a = N_a = 0 (Coulomb), K_n = 1e5, closed by h = 1e-4.
    let props = AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(0.5)
        .gamma_crit(1e-3)
        .normal_stiffness(1e5)
        .build_first(10);
    let mut c = UinterCall::new(3, &props);
    c.rdisp[0] = 1e-4;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "uinter_ succeeded");
    assert!(
        (c.stress[0] - 10.0).abs() < 1e-9,
        "p = K_n h = {}",
        c.stress[0]
    );
}

fn fric_coef_ok() {
    let (mut coef, mut deriv) = ([0.0f64; 2], [0.0f64; 40]);
    let props = coulomb();
    let (slip, p, t) = ([0.0f64; 6], [100.0f64], [20.0f64]);
    fric_coef_call(&mut coef, &mut deriv, &props, &slip, &p, &t, &[b' '; 80]);
    assert_eq!(coef, [0.3, 0.3], "fric_coef_ succeeded");
}

fn forced_sliding_ok() {
    let props = coulomb();
    let v = [1.0f64, 0.0];
    let (mut tau, mut damping, mut stiffness) = ([0.0f64; 2], [0.0f64; 4], [0.0f64; 2]);
    // SAFETY: props holds nprops reals, the outputs nfdir and nfdir² reals.
    let st = unsafe {
        ifl_forced_sliding(
            props.as_ptr(),
            props.len() as c_int,
            2,
            v.as_ptr(),
            100.0,
            20.0,
            tau.as_mut_ptr(),
            damping.as_mut_ptr(),
            stiffness.as_mut_ptr(),
        )
    };
    assert_eq!(st, IflStatus::Ok);
    // Sliding along 1 at p = 100: |τ| = μp = 30.
    assert!((tau[0].abs() - 30.0).abs() < 1e-9, "{tau:?}");
}

fn native_conductance_ok() {
    let mut out = IflConductance::default();
    // SAFETY: NUL-terminated name, writable out.
    let st = unsafe { ifl_gap_conductance(c"SI1".as_ptr(), 0.0, 1.0, 300.0, 290.0, &mut out) };
    assert_eq!((st, out.k), (IflStatus::Ok, 2.0));
    // The length-carrying form: a blank-padded Fortran name, no NUL, bytes past the length
    // that would name another interaction.
    let name = b"si1     NOT-CONFIGURED";
    let mut out = IflConductance::default();
    // SAFETY: 8 readable bytes, writable out.
    let st =
        unsafe { ifl_gap_conductance_n(name.as_ptr().cast(), 8, 0.0, 1.0, 300.0, 290.0, &mut out) };
    assert_eq!((st, out.k), (IflStatus::Ok, 2.0));
}

fn fric_batch_ok() {
    // One point, NFDIR = 1, the stick increment of fric_ok: tau = k_s dgam = 3e4 * 1e-4 = 3.
    let props = coulomb();
    let mut lm = [0 as c_int];
    let (mut tau, mut ddtddg, mut ddtddp) = ([0.0f64], [0.0f64], [0.0f64]);
    let (mut dslip, mut sed, mut sfd, mut statev) = ([0.0f64], [0.0f64], [0.0f64], [0.0f64; 3]);
    let (dgam, taulm, press, dpress, chrlngth) = ([1e-4f64], [0.0f64], [100.0f64], [0.0], [1.0]);
    let mut pnewdt = 1e36;
    // SAFETY: every array holds one point's components, props holds nprops reals.
    let st = unsafe {
        ifl_fric_batch(
            1,
            1,
            1,
            props.as_ptr(),
            props.len() as c_int,
            3,
            1.0,
            lm.as_mut_ptr(),
            tau.as_mut_ptr(),
            ddtddg.as_mut_ptr(),
            ddtddp.as_mut_ptr(),
            dslip.as_mut_ptr(),
            sed.as_mut_ptr(),
            sfd.as_mut_ptr(),
            statev.as_mut_ptr(),
            dgam.as_ptr(),
            taulm.as_ptr(),
            press.as_ptr(),
            dpress.as_ptr(),
            chrlngth.as_ptr(),
            &mut pnewdt,
        )
    };
    assert_eq!((st, pnewdt), (IflStatus::Ok, 1e36));
    assert!((tau[0] - 3.0).abs() < 1e-12, "{tau:?}");
}

fn vfric_ok() {
    // One sliding contact point: fTangential = -min(mu F_N, F_stick) = -min(0.3 * 10, 5) = -3.
    let ftan = vfric_call(&VfricBlock {
        nfricdir: 1,
        // VFRIC's PROPS are in the build's precision (IflReal), the builders' in f64.
        props: vec![1.0, 0.3],
        f_normal: vec![10.0],
        f_stick: vec![5.0],
        area: vec![1.0],
        jconslvid: vec![1],
    });
    assert!((ftan[0] + 3.0).abs() < 1e-6, "vfric_ succeeded: {ftan:?}");
}

#[test]
fn a_successful_call_of_any_entry_point_keeps_the_last_error() {
    setup();
    let entry_points: [(&str, fn()); 8] = [
        ("fric_", fric_ok),
        ("gapcon_", gapcon_ok),
        ("uinter_", uinter_ok),
        ("fric_coef_", fric_coef_ok),
        ("ifl_forced_sliding", forced_sliding_ok),
        ("ifl_gap_conductance(_n)", native_conductance_ok),
        ("ifl_fric_batch", fric_batch_ok),
        ("vfric_", vfric_ok),
    ];
    for (name, ok) in entry_points {
        let m = fail();
        ok();
        assert_eq!(last(), m, "{name}: a success changed the last error");
    }
}

#[test]
fn only_ifl_clear_error_empties_it_and_copy_agrees() {
    setup();
    let m = fail();
    let mut buf = [1 as c_char; 8];
    // SAFETY: 8 writable bytes.
    let n = unsafe { ifl_last_error_copy(buf.as_mut_ptr(), buf.len()) };
    assert_eq!(n, m.len(), "the full length, not the truncated one");
    assert_eq!(buf[7], 0, "always NUL-terminated");
    ifl_clear_error();
    assert_eq!(last(), "");
    // SAFETY: NULL asks for the length only.
    assert_eq!(unsafe { ifl_last_error_copy(std::ptr::null_mut(), 0) }, 0);
    // A failure after the clear is recorded again; a second failure replaces the first.
    fail();
    let mut out = IflConductance::default();
    // SAFETY: writable out; the NULL name is the failure asked for.
    let st = unsafe { ifl_gap_conductance_n(std::ptr::null(), 3, 0.0, 1.0, 1.0, 1.0, &mut out) };
    assert_eq!(st, IflStatus::BadInput);
    assert_mentions(&last(), &["ifl_gap_conductance_n", "NULL"], "NULL name");
    // A Fortran caller called the module's ifl_gap_conductance, which is this call: named too.
    assert_mentions(
        &last(),
        &["ifl_gap_conductance_n (or the Fortran module's ifl_gap_conductance): "],
        "NULL name",
    );
}

#[test]
fn each_thread_has_its_own_last_error() {
    setup();
    let m = fail();
    std::thread::spawn(|| assert_eq!(last(), "", "a new thread starts empty"))
        .join()
        .unwrap();
    assert_eq!(last(), m);
}
