//! `fric_` as a host sees it: what is written, what is left alone, and every documented bad
//! input (contract.md, "Errors and bad input").

use interfacial::CUTBACK_RATIO;
use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::{FricCall, GUARD};

#[path = "common/laws.rs"]
mod laws;
use laws::set_entry;
#[path = "common/refusal.rs"]
mod refusal;
use refusal::assert_fric_refused;
#[path = "common/threads.rs"]
mod threads;
use threads::map_on_threads;

const MU: f64 = 0.3;
const P: f64 = 100.0;
const GAMMA_CRIT: f64 = 1e-3;

/// μ = [`MU`], γ_crit = [`GAMMA_CRIT`], elastic stick.
fn coulomb() -> CoulombBuilder {
    CoulombBuilder::new().mu(MU).gamma_crit(GAMMA_CRIT)
}

/// `PROPS(1..5)` of [`coulomb`] (`NPROPS` = 5).
fn props() -> Vec<f64> {
    coulomb().build_first(5)
}

/// `c` with these `PROPS` (and `NPROPS`).
fn with_props(c: &mut FricCall, props: Vec<f64>) {
    c.nprops = props.len() as i32;
    c.props = props;
}

fn good(nfdir: i32) -> FricCall {
    let mut c = FricCall::new(nfdir, &props());
    c.press = P;
    c.dpress = 0.0;
    c.tau[0] = 10.0;
    c.dgam[0] = 2e-4;
    c.statev[..3].copy_from_slice(&[0.25, 0.0, 0.0]);
    c
}

#[test]
fn first_contact_is_stick_stiffness_times_slip() {
    for nfdir in [1, 2] {
        let mut c = FricCall::new(nfdir, &props());
        c.press = P;
        c.dpress = P;
        c.dgam[0] = 4e-4;
        if nfdir == 2 {
            c.dgam[1] = -3e-4;
        }
        c.call();
        let ks = MU * P / GAMMA_CRIT;
        assert_eq!(c.lm, 0);
        assert!((c.tau[0] - ks * 4e-4).abs() < 1e-12);
        if nfdir == 2 {
            assert!((c.tau[1] + ks * 3e-4).abs() < 1e-12);
        }
        assert!(c.guards_intact());
        assert_eq!(c.pnewdt, 1e36);
    }
}

#[test]
fn drot_is_not_read() {
    // The host rotates TAU itself and the law keeps no vector state, so DROT changes nothing.
    let mut a = good(2);
    a.tau[1] = -5.0;
    a.dgam[1] = 7e-4;
    let mut b = a.clone();
    let (s, c) = (0.5f64.sin(), 0.5f64.cos());
    b.drot = [c, s, -s, c];
    a.call();
    b.call();
    assert_eq!(a.tau, b.tau);
    assert_eq!(a.ddtddg, b.ddtddg);
    assert_eq!(a.statev, b.statev);
}

#[test]
fn lm_2_on_entry_writes_nothing() {
    let mut c = good(2);
    c.lm = 2;
    c.tau = [GUARD; 4];
    c.ddtddg = [GUARD; 10];
    c.sed = GUARD;
    c.sfd = GUARD;
    c.statev.fill(GUARD);
    let before = c.clone();
    c.call();
    assert_eq!(c.lm, 2);
    assert_eq!(c.tau, before.tau);
    assert_eq!(c.ddtddg, before.ddtddg);
    assert_eq!((c.sed, c.sfd), (GUARD, GUARD));
    assert_eq!(c.statev, before.statev);
    assert_eq!(c.pnewdt, 1e36);
}

#[test]
fn inputs_are_never_written() {
    let mut c = good(2);
    c.lm = 0;
    let before = c.clone();
    c.call();
    assert_eq!(c.dgam, before.dgam);
    assert_eq!(c.props, before.props);
    assert_eq!(
        (c.press, c.dpress, c.chrlngth),
        (before.press, before.dpress, before.chrlngth)
    );
    assert_eq!(c.drot, before.drot);
}

/// One bad input: what it is, NFDIR, how to break a good call, and a word the message must
/// contain.
type Case = (&'static str, i32, fn(&mut FricCall), &'static str);

fn cases() -> Vec<Case> {
    let cases: &[Case] = &[
        ("NFDIR 0", 0, |_| {}, "NFDIR = 0"),
        ("NFDIR 3", 3, |_| {}, "NFDIR = 3"),
        ("NPROPS 0", 2, |c| c.nprops = 0, "NPROPS = 0"),
        ("NPROPS 1", 2, |c| c.nprops = 1, "NPROPS = 1"),
        ("NPROPS < 0", 2, |c| c.nprops = -4, "NPROPS = -4"),
        ("unknown law", 2, |c| set_entry(c, 1, 4.0), "PROPS(1) = 4"),
        ("non-integer law", 2, |c| set_entry(c, 1, 1.5), "integer"),
        ("NaN law", 2, |c| set_entry(c, 1, f64::NAN), "PROPS(1)"),
        ("μ < 0", 2, |c| set_entry(c, 2, -0.1), "PROPS(2)"),
        ("μ NaN", 1, |c| set_entry(c, 2, f64::NAN), "PROPS(2)"),
        ("μ₂ < 0", 2, |c| set_entry(c, 3, -0.5), "PROPS(3)"),
        ("τ_max < 0", 2, |c| set_entry(c, 4, -1.0), "PROPS(4)"),
        ("γ_crit < 0", 2, |c| set_entry(c, 5, -1.0), "PROPS(5)"),
        ("stick mode 5", 2, |c| set_entry(c, 7, 5.0), "PROPS(7)"),
        (
            "PROPS(8) not a μ law",
            2,
            |c| set_entry(c, 8, 5.0),
            "PROPS(8)",
        ),
        ("NSTATV 2", 2, |c| c.nstatv = 2, "NSTATV = 2"),
        ("NSTATV < 0", 1, |c| c.nstatv = -1, "NSTATV = -1"),
        (
            "CHRLNGTH 0",
            2,
            |c| {
                set_entry(c, 5, 0.0);
                c.chrlngth = 0.0;
            },
            "CHRLNGTH",
        ),
        ("LM 7", 2, |c| c.lm = 7, "LM = 7"),
        ("STATEV NaN", 2, |c| c.statev[0] = f64::NAN, "STATEV"),
        (
            "overflow",
            2,
            |c| {
                c.press = 1e308;
                set_entry(c, 2, 10.0);
            },
            "overflow",
        ),
    ];
    cases.to_vec()
}

/// Runs a bad call and checks the documented safe outputs.
fn check_refused(mut c: FricCall, what: &str, word: &str) {
    c.set_guards();
    let c = assert_fric_refused(c, what, word);
    assert!(c.guards_intact(), "{what}: guards");
    for (i, x) in c.ddtddg.iter().enumerate() {
        assert!(!x.is_nan(), "{what}: DDTDDG[{i}] is NaN");
    }
}

#[test]
fn every_bad_input_is_refused_cleanly() {
    for (what, nfdir, spoil, word) in cases() {
        let mut c = good(nfdir);
        c.nfdir = nfdir;
        spoil(&mut c);
        check_refused(c, what, word);
    }
}

#[test]
fn non_finite_inputs_are_refused_cleanly() {
    type Spoil = fn(&mut FricCall, f64);
    let spoilers: [(i32, Spoil, &str); 4] = [
        (1, |c, x| c.press = x, "PRESS"),
        (2, |c, x| c.dpress = x, "DPRESS"),
        (2, |c, x| c.dgam[1] = x, "DGAM"),
        (1, |c, x| c.tau[0] = x, "TAU"),
    ];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for (nfdir, spoil, word) in spoilers {
            let mut c = good(nfdir);
            spoil(&mut c, bad);
            check_refused(c, &format!("{word} = {bad}"), word);
        }
    }
}

#[test]
fn taulm_is_checked_only_when_used() {
    // Exact stick, stuck on entry: a NaN Lagrange stress is refused…
    let mut c = good(2);
    with_props(&mut c, coulomb().stick(1.0).build_first(7));
    c.lm = 1;
    c.taulm = [f64::NAN, 0.0, 0.0];
    check_refused(c.clone(), "TAULM NaN", "TAULM");
    // …but with LM = 0 on entry TAULM is not read at all.
    c.lm = 0;
    c.pnewdt = 1e36;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
}

#[test]
fn a_null_taulm_is_refused_only_when_entering_stuck() {
    // Elastic stick (which never reads TAULM) and exact stick alike: LM = 1 on entry with a
    // NULL TAULM is a broken host, refused; with LM = 0 TAULM is not looked at.
    for stick in [0.0, 1.0] {
        for nfdir in [1, 2] {
            let mut c = good(nfdir);
            with_props(&mut c, coulomb().stick(stick).build_first(7));
            c.null_taulm = true;
            c.lm = 1;
            check_refused(c.clone(), &format!("PROPS(7) = {stick}, LM = 1"), "TAULM");
            c.lm = 0;
            c.pnewdt = 1e36;
            c.call();
            assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
            assert_eq!(c.lm, 0);
        }
    }
}

#[test]
fn short_names_are_read_only_up_to_their_hidden_length() {
    // An old CHARACTER*8 caller: the hidden length is 8; the bytes after it are not ours.
    let mut c = good(2);
    c.ciname = "SI1     GARBAGE!".into();
    c.name_len = 8;
    c.nstatv = 2;
    check_refused(c.clone(), "CHARACTER*8", "NSTATV");
    assert!(!FricCall::last_error().contains("GARBAGE"));
    // All blanks: an empty interaction name, still one clear message.
    c.ciname = String::new();
    c.name_len = 80;
    c.call();
    assert!(FricCall::last_error().contains("interaction ''"));
}

#[test]
fn a_good_call_after_a_bad_one_works() {
    let mut c = good(2);
    with_props(&mut c, coulomb().mu(-1.0).build_first(5));
    c.call();
    assert_eq!(c.pnewdt, CUTBACK_RATIO);
    with_props(&mut c, props());
    c.pnewdt = 1e36;
    c.call();
    assert_eq!(c.pnewdt, 1e36);
    assert_eq!(c.lm, 0);
    // τ̄ = 10 → γ̄_el = 10/3e4; + Δγ = 2e-4 → stick, τ = 3e4·(10/3e4 + 2e-4) = 16.
    assert!((c.tau[0] - 16.0).abs() < 1e-12);
}

#[test]
fn results_do_not_depend_on_the_number_of_threads() {
    let points: Vec<FricCall> = (0..400)
        .map(|i| {
            let mut c = good(2);
            let x = f64::from(i) / 400.0;
            c.dgam = [3e-3 * (x - 0.4), 2e-3 * (0.7 - x) * x, 0.0];
            c.dpress = 30.0 * x - 10.0;
            c
        })
        .collect();
    let run = |p: &FricCall| {
        let mut c = p.clone();
        c.call();
        c
    };
    let serial: Vec<FricCall> = points.iter().map(run).collect();
    let parallel = map_on_threads(&points, 50, run);
    for (a, b) in serial.iter().zip(&parallel) {
        assert_eq!(a.tau.map(f64::to_bits), b.tau.map(f64::to_bits));
        assert_eq!(a.ddtddg.map(f64::to_bits), b.ddtddg.map(f64::to_bits));
        assert_eq!(a.statev, b.statev);
    }
}

/// `fric_` with every pointer NULL but `pnewdt` (NULL too if so given) and zero hidden lengths.
fn fric_all_null(pnewdt: *mut f64) {
    use std::ptr::{null, null_mut};
    // SAFETY: every pointer is NULL or valid; the function must check before reading.
    unsafe {
        interfacial::abi::fric_(
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
            pnewdt,
            null_mut(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            0,
            0,
            0,
        );
    }
}

#[test]
fn null_pointers_are_refused_without_a_crash() {
    use std::ptr::{null, null_mut};
    let mut pnewdt = 1e36;
    // A host that passes nothing but PNEWDT: refused, cut-back, message names the argument.
    fric_all_null(&mut pnewdt);
    assert_eq!(pnewdt, CUTBACK_RATIO);
    assert!(FricCall::last_error().contains("LM is a NULL pointer"));
    // Everything NULL, PNEWDT too: still no crash.
    fric_all_null(null_mut());
    // A good point whose PRESS pointer is missing.
    let mut c = good(1);
    let mut lm = 0;
    let mut tau = [5.0];
    let mut pnewdt = 1e36;
    let mut statev = [0.0; 3];
    let mut scratch = [0.0; 4];
    let (nfdir, nstatv, nprops) = (1, 3, c.props.len() as i32);
    // SAFETY: all non-NULL pointers are valid for NFDIR = 1, NSTATV = 3.
    unsafe {
        interfacial::abi::fric_(
            &mut lm,
            tau.as_mut_ptr(),
            scratch.as_mut_ptr(),
            scratch.as_mut_ptr(),
            scratch.as_mut_ptr(),
            null_mut(),
            null_mut(),
            null_mut(),
            &mut pnewdt,
            statev.as_mut_ptr(),
            c.dgam.as_ptr(),
            null(),
            null(),
            &c.dpress,
            null(),
            null(),
            null(),
            null(),
            null(),
            &c.dtime,
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            null(),
            &nfdir,
            null(),
            null(),
            &nstatv,
            &c.chrlngth,
            c.props.as_mut_ptr(),
            &nprops,
            0,
            0,
            0,
        );
    }
    assert_eq!(pnewdt, CUTBACK_RATIO);
    assert_eq!(tau, [5.0]);
    assert!(FricCall::last_error().contains("PRESS is a NULL pointer"));
    assert!(FricCall::last_error().contains("element ?"));
}
