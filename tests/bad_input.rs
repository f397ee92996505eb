//! Rows of the bad-input catalogue (docs/bad-input.md) not covered by `fric_abi.rs` and
//! `gapcon_abi.rs`: NaN and ±Inf in every real argument of `fric_` and `gapcon_` (refused where
//! the law reads it, without effect where it does not), DTIME ≤ 0, negative pressure, names
//! that are not blank-padded, and NULL pointers in the native API.

#[path = "common/config_file.rs"]
mod config_file;
#[path = "common/refusal.rs"]
mod refusal;
use refusal::{assert_fric_refused, assert_mentions};
use std::ffi::{CString, c_char};

use interfacial::abi::{
    IflConductance, IflStatus, ifl_clear_error, ifl_gap_conductance, ifl_last_error,
    ifl_last_error_copy,
};
use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::{FricCall, GUARD, GapconCall};

const MU: f64 = 0.3;
const GAMMA_CRIT: f64 = 1e-3;

/// Law 1 with μ = [`MU`] and γ_crit = [`GAMMA_CRIT`] (elastic stick).
fn coulomb() -> CoulombBuilder {
    CoulombBuilder::new().mu(MU).gamma_crit(GAMMA_CRIT)
}

/// μ = [`MU`] alone, `NPROPS` = 2 (every other entry absent).
fn mu_only() -> Vec<f64> {
    CoulombBuilder::new().mu(MU).build_first(2)
}

/// A good call: NFDIR = 2, p = 100, sliding (|γ_pr| = 1.5·γ_crit) unless said otherwise.
fn good(props: &[f64]) -> FricCall {
    let mut c = FricCall::new(2, props);
    c.press = 100.0;
    c.dpress = 0.0;
    c.tau = [10.0, -5.0, 0.0, 0.0];
    c.dgam = [1.2e-3, 0.0, 0.0];
    c.dtime = 0.5;
    c.statev[..3].copy_from_slice(&[0.25, 0.0, 1.0]);
    c
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Every output of a call, bit for bit.
fn outputs(c: &FricCall) -> Vec<u64> {
    let mut v = bits(&c.tau);
    v.extend(bits(&c.ddtddg));
    v.extend(bits(&c.ddtddp));
    v.extend(bits(&c.dslip));
    v.extend(bits(&[c.sed, c.sfd, c.pnewdt]));
    v.extend(bits(&c.ddtddt));
    v.extend(bits(&c.statev));
    v.push(c.lm as u64);
    v
}

type Spoil = fn(&mut FricCall, f64);

/// Arguments the Coulomb law never reads: NaN or ±Inf there changes no output bit.
#[test]
fn fric_unread_real_arguments_have_no_effect() {
    let unread: [(&str, Spoil); 11] = [
        ("DDPDDH", |c, x| c.ddpddh = x),
        ("SLIP", |c, x| c.slip = [x; 3]),
        ("TIME(1)", |c, x| c.time[0] = x),
        ("TIME(2)", |c, x| c.time[1] = x),
        ("COORDS", |c, x| c.coords = [x; 3]),
        ("RCOORD", |c, x| c.rcoord = [x; 3]),
        ("DROT", |c, x| c.drot = [x; 4]),
        ("TEMP", |c, x| c.temp = [x; 2]),
        ("PREDEF", |c, x| c.predef = [x; 2]),
        ("TAULM with LM = 0", |c, x| c.taulm = [x; 3]),
        ("CHRLNGTH with PROPS(5) > 0", |c, x| c.chrlngth = x),
    ];
    for stick in [0.0, 1.0] {
        let props = coulomb().stick(stick).build_first(7);
        let mut clean = good(&props);
        clean.call();
        assert_eq!(clean.pnewdt, 1e36, "{}", FricCall::last_error());
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for (what, spoil) in unread {
                let mut c = good(&props);
                spoil(&mut c, bad);
                c.call();
                assert_eq!(
                    outputs(&c),
                    outputs(&clean),
                    "{what} = {bad}, PROPS(7) = {stick}"
                );
            }
        }
    }
}

/// Real arguments the law reads, not already in fric_abi.rs: refused with a message that names
/// them, state left alone, PNEWDT < 1.
#[test]
fn fric_non_finite_read_arguments_are_refused() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let mut c = good(&coulomb().build_first(5));
        c.dtime = bad;
        assert_fric_refused(c, &format!("DTIME = {bad}"), "DTIME");
        // γ_crit from the slip tolerance: CHRLNGTH is read.
        let tolerance = CoulombBuilder::new().mu(MU).slip_tolerance(0.01);
        let mut c = good(&tolerance.build_first(6));
        c.chrlngth = bad;
        assert_fric_refused(c, &format!("CHRLNGTH = {bad}"), "CHRLNGTH");
        let mut c = good(&mu_only());
        c.statev[1] = bad;
        assert_fric_refused(c, &format!("STATEV(2) = {bad}"), "STATEV");
        // Every PROPS entry of law 1.
        for k in 1..7 {
            let mut props = coulomb().build_first(7);
            props[k] = bad;
            assert_fric_refused(
                good(&props),
                &format!("PROPS({}) = {bad}", k + 1),
                &format!("PROPS({})", k + 1),
            );
        }
    }
}

/// A zero or negative time increment carries no rate: the state's slip rate is 0, the rest of
/// the answer is that of any other time increment (the Coulomb law does not depend on rate).
#[test]
fn fric_zero_or_negative_dtime_gives_zero_slip_rate() {
    let props = coulomb().build_first(5);
    let mut reference = good(&props);
    reference.call();
    assert!(reference.statev[1] > 0.0, "the reference increment slips");
    for dtime in [0.0, -0.0, -1.0, -1e300] {
        let mut c = good(&props);
        c.dtime = dtime;
        c.call();
        assert_eq!(c.pnewdt, 1e36, "DTIME = {dtime}");
        assert_eq!(c.statev[1], 0.0, "DTIME = {dtime}: slip rate");
        assert_eq!(bits(&c.tau), bits(&reference.tau), "DTIME = {dtime}");
        assert_eq!(c.statev[0], reference.statev[0], "DTIME = {dtime}");
    }
}

/// A negative contact pressure (a point about to open) carries no friction: τ = 0, no slip
/// recorded as dissipation, no cut-back.
#[test]
fn fric_negative_pressure_gives_zero_stress() {
    for stick in [0.0, 1.0] {
        for p in [-1e-12, -5.0, -1e200] {
            let mut c = good(&coulomb().stick(stick).build_first(7));
            c.press = p;
            c.dpress = p - 100.0;
            c.call();
            assert_eq!(c.pnewdt, 1e36, "p = {p}: {}", FricCall::last_error());
            assert_eq!(c.lm, 0, "p = {p}");
            assert_eq!(&c.tau[..2], &[0.0, 0.0], "p = {p}");
            assert_eq!(c.sfd, 0.0, "p = {p}");
            assert!(c.ddtddg.iter().all(|x| x.is_finite()), "p = {p}");
        }
    }
}

/// A name padded with NULs (a C caller) or followed by other bytes past its hidden length is
/// the same interaction; the message never shows bytes past the hidden length.
#[test]
fn fric_names_not_blank_padded() {
    let mut c = good(&mu_only());
    c.nstatv = 2;
    c.ciname = "SI1\0\0\0\0\0".into();
    c.name_len = 8;
    assert_fric_refused(c.clone(), "NUL-padded name", "NSTATV");
    c.ciname = "SI1ABCDEF".into();
    c.name_len = 3;
    assert_fric_refused(c.clone(), "unpadded name of hidden length 3", "NSTATV");
    assert!(!FricCall::last_error().contains("ABC"));
}

const CONFIG: &str = r#"
[interactions.SI1.conductance]
law = "pressure-table"
table = [[0.0, 1.0], [100.0, 3.0]]
"#;

fn setup() {
    config_file::config_once("badinput", CONFIG);
}

/// A `gapcon_` point of SI1 at p = 50, every argument set explicitly (`GapconCall`), so the
/// unread ones can carry NaN.
fn gapcon() -> GapconCall {
    GapconCall::new("SI1", 0.0, 50.0, 300.0, 290.0)
}

#[test]
fn gapcon_unread_real_arguments_have_no_effect() {
    setup();
    // p = 50 is halfway along the table: k = 2.
    assert_eq!(gapcon().call(), 2.0);
    type GSpoil = fn(&mut GapconCall, f64);
    let unread: [(&str, GSpoil); 4] = [
        ("FLOWM", |g, x| g.flowm = [x; 2]),
        ("PREDEF", |g, x| g.predef = [x; 2]),
        ("TIME", |g, x| g.time = [x; 2]),
        ("COORDS", |g, x| g.coords = [x; 3]),
    ];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for (what, spoil) in unread {
            let mut g = gapcon();
            spoil(&mut g, bad);
            assert_eq!(g.call(), 2.0, "{what} = {bad}");
            assert_eq!(&g.ak[1..], &[GUARD; 4], "{what} = {bad}");
        }
    }
}

#[test]
fn gapcon_names_of_every_shape() {
    setup();
    let k = |name: &str| {
        let mut g = gapcon();
        g.ciname = name.into();
        g.name_len = name.len();
        let k = g.call();
        assert_eq!(&g.ak[1..], &[GUARD; 4]);
        k
    };
    // CHARACTER*8, CHARACTER*3 (not padded), NUL-padded, lower case: all SI1.
    assert_eq!(k("SI1     "), 2.0);
    assert_eq!(k("SI1"), 2.0);
    assert_eq!(k("SI1\0\0\0\0\0"), 2.0);
    assert_eq!(k("si1"), 2.0);
    // All blanks, empty, or another name: not configured (no "*" entry here), AK(1) = 0 and a
    // message that says how to fix it.
    for name in ["        ", "", "SI1X", " SI1"] {
        ifl_clear_error();
        assert_eq!(k(name), 0.0, "{name:?}");
        assert_mentions(
            &FricCall::last_error(),
            &["GAPCON", "interaction not found"],
            &format!("{name:?}"),
        );
    }
}

#[test]
fn native_api_null_pointers() {
    setup();
    let mut out = IflConductance {
        k: 7.0,
        ..IflConductance::default()
    };
    // SAFETY: NULL name is allowed by the contract (refused with a status); out is valid.
    let status =
        unsafe { ifl_gap_conductance(std::ptr::null(), 0.0, 50.0, 300.0, 290.0, &mut out) };
    assert_eq!(status, IflStatus::BadInput);
    assert_eq!(out, IflConductance::default(), "out zeroed on failure");
    assert!(FricCall::last_error().contains("NULL"));
    // ifl_last_error_copy: NULL buffer asks for the length only; a zero length writes nothing.
    // SAFETY: NULL with any length is allowed; `one` is one writable byte.
    let n = unsafe { ifl_last_error_copy(std::ptr::null_mut(), 100) };
    assert!(n > 0);
    let mut one = [b'x' as c_char; 1];
    // SAFETY: as above.
    let m = unsafe { ifl_last_error_copy(one.as_mut_ptr(), 0) };
    assert_eq!((m, one[0]), (n, b'x' as c_char));
    // A one-byte buffer gets just the NUL.
    // SAFETY: as above.
    unsafe { ifl_last_error_copy(one.as_mut_ptr(), 1) };
    assert_eq!(one[0], 0);
    // After a clear, the last error is the empty string (never NULL).
    ifl_clear_error();
    let p = ifl_last_error();
    assert!(!p.is_null());
    // SAFETY: ifl_last_error returns a valid NUL-terminated string.
    assert_eq!(unsafe { std::ffi::CStr::from_ptr(p) }.to_bytes(), b"");
    // A good native call still works after all that.
    let name = CString::new("SI1").unwrap();
    // SAFETY: valid name and out.
    let status = unsafe { ifl_gap_conductance(name.as_ptr(), 0.0, 50.0, 300.0, 290.0, &mut out) };
    assert_eq!((status, out.k), (IflStatus::Ok, 2.0));
}

#[test]
fn gapcon_overflow_is_a_failure_not_an_infinite_flux() {
    setup();
    let mut g = gapcon();
    g.temp = [1.7e308, -1.7e308];
    assert_eq!(g.call(), 0.0);
    assert_eq!(&g.ak[1..], &[GUARD; 4]);
    assert_mentions(
        &FricCall::last_error(),
        &["GAPCON", "overflow"],
        "overflowing flux",
    );
}
