//! `ifl_fric_point` (src/abi/fric_point.rs) is `fric_` with named inputs and outputs: over drawn
//! `PROPS` of laws 1 and 2 (valid and not) and drawn increments, every output, `STATEV`, the
//! status and the message are those of `fric_` called with the same arguments, bit for bit.

use std::ffi::CString;

use interfacial::abi::{IflFricInput, IflFricOutput, IflStatus, ifl_clear_error, ifl_fric_point};
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;

#[path = "common/drawn_props.rs"]
mod drawn_props;
#[path = "common/laws.rs"]
mod laws;
use drawn_props::{VALUES, bases};

/// One drawn point: the `fric_` call (as a host makes it) that `ifl_fric_point` must match.
#[derive(Clone, Debug)]
struct Point {
    props: Vec<f64>,
    nfdir: i32,
    lm: i32,
    tau: [f64; 2],
    dgam: [f64; 2],
    taulm: [f64; 2],
    press: f64,
    dpress: f64,
    dtime: f64,
    chrlngth: f64,
    temp: [f64; 2],
    angle: f64,
    statev: [f64; 5],
    nstatv: i32,
    pnewdt: f64,
}

/// The `fric_` answer: the outputs, `STATEV` and the message, as bits.
fn by_fric(p: &Point) -> (Vec<u64>, String) {
    let mut c = FricCall::new(p.nfdir, &p.props);
    c.lm = p.lm;
    c.tau[..2].copy_from_slice(&p.tau);
    c.dgam[..2].copy_from_slice(&p.dgam);
    c.taulm[..2].copy_from_slice(&p.taulm);
    c.press = p.press;
    c.dpress = p.dpress;
    c.dtime = p.dtime;
    c.chrlngth = p.chrlngth;
    c.temp = p.temp;
    c.drot = [p.angle.cos(), p.angle.sin(), -p.angle.sin(), p.angle.cos()];
    c.coords = [1.0, 2.0, 3.0];
    c.statev = p.statev.to_vec();
    c.nstatv = p.nstatv;
    c.pnewdt = p.pnewdt;
    c.ddtddg = [0.0; 10];
    c.ddtddt = [0.0; 7];
    c.ddtddp = [0.0; 4];
    c.dslip = [0.0; 4];
    ifl_clear_error();
    c.call();
    // fric_'s arrays have FRIC's layout (stride NFDIR), as the struct's do.
    let mut out = IflFricOutput {
        lm: c.lm,
        sed: c.sed,
        sfd: c.sfd,
        pnewdt: c.pnewdt,
        ..IflFricOutput::default()
    };
    out.tau.copy_from_slice(&c.tau[..2]);
    out.ddtddg.copy_from_slice(&c.ddtddg[..4]);
    out.ddtddp.copy_from_slice(&c.ddtddp[..2]);
    out.dslip.copy_from_slice(&c.dslip[..2]);
    out.ddtddt.copy_from_slice(&c.ddtddt[..4]);
    (bits(&out, p.nfdir, &c.statev), FricCall::last_error())
}

/// What a point's answer holds for `nfdir` directions, and `STATEV`, as bits.
fn bits(out: &IflFricOutput, nfdir: i32, statev: &[f64]) -> Vec<u64> {
    let n = nfdir.clamp(0, 2) as usize;
    let mut bits = vec![u64::from(out.lm as u32)];
    let mut put = |v: &[f64]| bits.extend(v.iter().map(|x| x.to_bits()));
    put(&out.tau[..n]);
    put(&out.ddtddg[..n * n]);
    put(&out.ddtddp[..n]);
    put(&out.dslip[..n]);
    put(&[out.sed, out.sfd]);
    put(&out.ddtddt[..2 * n]);
    put(&[out.pnewdt]);
    put(statev);
    bits
}

/// The `ifl_fric_point` answer, in the same order, with its status.
fn by_point(p: &Point) -> (Vec<u64>, String, IflStatus) {
    let name = CString::new("SI1").unwrap();
    let mut statev = p.statev;
    let input = IflFricInput {
        lm: p.lm,
        nfdir: p.nfdir,
        tau: p.tau,
        dgam: p.dgam,
        taulm: p.taulm,
        press: p.press,
        dpress: p.dpress,
        dtime: p.dtime,
        chrlngth: p.chrlngth,
        temp: p.temp,
        drot: [p.angle.cos(), p.angle.sin(), -p.angle.sin(), p.angle.cos()],
        coords: [1.0, 2.0, 3.0],
        mcrd: 3,
        noel: 0,
        npt: 1,
        node: 1,
        interaction: name.as_ptr(),
        props: p.props.as_ptr(),
        nprops: p.props.len() as i32,
        statev: statev.as_mut_ptr(),
        nstatv: p.nstatv,
        pnewdt: p.pnewdt,
    };
    let mut out = IflFricOutput::default();
    ifl_clear_error();
    // SAFETY: PROPS and STATEV hold NPROPS and NSTATV entries; the name is NUL-terminated.
    let st = unsafe { ifl_fric_point(&input, &mut out) };
    (bits(&out, p.nfdir, &statev), FricCall::last_error(), st)
}

#[track_caller]
fn assert_same(p: &Point) {
    let (want, fric_msg) = by_fric(p);
    let (got, msg, st) = by_point(p);
    assert_eq!(got, want, "{p:?}");
    assert_eq!(msg, fric_msg, "{p:?}");
    // The status says what the message says: OK exactly when fric_ reported nothing.
    assert_eq!(
        st == IflStatus::Ok,
        fric_msg.is_empty(),
        "{p:?}: {st:?} {fric_msg}"
    );
    if let Some(cause) = fric_msg.split("): ").nth(1) {
        let expected = if cause.starts_with("bad parameter") {
            IflStatus::BadParameter
        } else if cause.starts_with("bad input") {
            IflStatus::BadInput
        } else if cause.starts_with("numerical failure") {
            IflStatus::NumericalFailure
        } else {
            IflStatus::InternalError
        };
        assert_eq!(st, expected, "{fric_msg}");
    }
}

fn point() -> impl Strategy<Value = Point> {
    let props = (
        0..bases().len(),
        proptest::collection::vec((0..22usize, 0..VALUES.len()), 0..3),
    )
        .prop_map(|(base, changes)| {
            let mut props = bases()[base].clone();
            for (i, v) in changes {
                if props.len() <= i {
                    props.resize(i + 1, 0.0);
                }
                props[i] = VALUES[v];
            }
            props
        });
    let value = prop_oneof![
        8 => -2.0..2.0f64,
        1 => Just(0.0),
        1 => prop::sample::select(vec![f64::NAN, f64::INFINITY, -1e300, 1e-300]),
    ];
    (
        props,
        prop_oneof![8 => 1..=2i32, 1 => Just(0), 1 => Just(3)],
        prop_oneof![8 => Just(0), 2 => Just(1), 1 => Just(2), 1 => Just(7)],
        [value.clone(), value.clone()],
        [value.clone(), value.clone()],
        [value.clone(), value.clone()],
        (0.0..200.0f64, -50.0..50.0f64, 1e-4..10.0f64, value.clone()),
        ([0.0..100.0f64, 0.0..100.0f64], 0.0..6.3f64),
        (
            [
                0.0..1.0f64,
                0.0..1.0f64,
                0.0..3.0f64,
                -1.0..1.0f64,
                -1.0..1.0f64,
            ],
            2..=5i32,
        ),
        prop_oneof![Just(1e36), Just(1.0), 0.01..2.0f64],
    )
        .prop_map(
            |(
                props,
                nfdir,
                lm,
                tau,
                dgam,
                taulm,
                (press, dpress, dtime, chr),
                (temp, angle),
                (s, nstatv),
                pnewdt,
            )| {
                let scale = |v: [f64; 2], k: f64| [v[0] * k, v[1] * k];
                Point {
                    props,
                    nfdir,
                    lm,
                    tau: scale(tau, press),
                    dgam: scale(dgam, 1e-3),
                    taulm: scale(taulm, press),
                    press,
                    dpress,
                    dtime,
                    chrlngth: if chr == 0.0 { 1.0 } else { chr.abs() },
                    temp,
                    angle,
                    statev: [s[0], s[1], s[2].floor(), s[3], s[4]],
                    nstatv,
                    pnewdt,
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    /// Every output of `ifl_fric_point` is `fric_`'s, bit for bit, for laws 1 and 2, valid or
    /// refused `PROPS`, stick and slip, `LM` 0, 1, 2 or wrong, `NFDIR` 1, 2 or wrong.
    #[test]
    fn ifl_fric_point_is_fric_bit_for_bit(p in point()) {
        assert_same(&p);
    }
}

/// The drawn points must reach each kind of answer: a success that slides, a refusal of each
/// status `fric_` can give, `LM = 2`; each named here rather than left to chance.
#[test]
fn the_named_cases_match() {
    let base = Point {
        props: bases()[0].clone(),
        nfdir: 2,
        lm: 0,
        tau: [0.0; 2],
        dgam: [1e-2, -2e-2],
        taulm: [0.0; 2],
        press: 10.0,
        dpress: 0.0,
        dtime: 1.0,
        chrlngth: 1.0,
        temp: [20.0; 2],
        angle: 0.0,
        statev: [0.0; 5],
        nstatv: 5,
        pnewdt: 1e36,
    };
    let mut cases = vec![base.clone()];
    let mut bad_props = base.clone();
    bad_props.props[1] = -1.0;
    cases.push(bad_props);
    let mut nan = base.clone();
    nan.press = f64::NAN;
    cases.push(nan);
    let mut frictionless = base.clone();
    frictionless.lm = 2;
    cases.push(frictionless);
    let mut adhesive = base.clone();
    adhesive.props = bases()[10].clone();
    adhesive.nfdir = 1;
    cases.push(adhesive);
    let mut damping = base.clone();
    damping.props = bases()[8].clone();
    damping.angle = 0.3;
    cases.push(damping);
    let mut exact_stick = base.clone();
    exact_stick.props = bases()[2].clone();
    exact_stick.lm = 1;
    exact_stick.taulm = [1.0, -2.0];
    cases.push(exact_stick.clone());
    let mut released = exact_stick;
    released.taulm = [10.0, 0.0];
    cases.push(released);
    for p in &cases {
        assert_same(p);
    }
    // The sliding case slid, the bad ones were refused with their statuses.
    assert_eq!(by_point(&cases[0]).2, IflStatus::Ok);
    assert_ne!(by_point(&cases[0]).0[1], 0.0f64.to_bits());
    assert_eq!(by_point(&cases[1]).2, IflStatus::BadParameter);
    assert_eq!(by_point(&cases[2]).2, IflStatus::BadInput);
}

/// A NULL input or output is refused by name; nothing is written.
#[test]
fn null_structs_are_refused() {
    let mut out = IflFricOutput {
        sed: 7.0,
        ..IflFricOutput::default()
    };
    // SAFETY: NULL is refused before anything is read or written.
    let st = unsafe { ifl_fric_point(std::ptr::null(), &mut out) };
    assert_eq!(st, IflStatus::BadInput);
    assert_eq!(out.sed, 7.0);
    assert!(FricCall::last_error().contains("ifl_fric_point"));
    assert!(FricCall::last_error().contains("input is a NULL pointer"));
}
