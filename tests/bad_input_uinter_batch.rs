//! The bad-input catalogue (docs/bad-input.md, rows 52–63) for `uinter_` and `ifl_fric_batch`:
//! every class of issue 7 item 1 fed through the real symbols with exactly sized arrays. Each
//! call also passes the fuzz targets' property checks (`fuzz/src/uinter_case.rs`,
//! `fuzz/src/batch_case.rs`, compiled in by path): inputs unchanged, refused exactly when
//! `PNEWDT` is lowered with one message naming the routine, state kept on refusal, finite
//! outputs on success, a batch bit for bit `fric_` per point.

#[path = "common/fuzz_cases.rs"]
mod fuzz_cases;
use fuzz_cases::{batch_case, gapcon_case, uinter_case};

use batch_case::BatchCase;
use fuzz_cases::args::Outputs;
use interfacial::abi::IflStatus;
use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use uinter_case::UinterCase;

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// A closed, sliding 3-D point of the PTAB interaction (pressure table in the fuzz
/// configuration) with conduction, frictional heat and a rate-dependent law, γ_crit from the
/// slip tolerance × CHRLNGTH, so every argument the documentation lists as read is read.
fn uinter_law() -> AdhesiveBuilder {
    AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(0.5)
        .sa(4.0)
        .na(10.0)
        .kmu(0.01)
        .vhalf(0.1)
        .slip_tolerance(0.005)
        .normal_stiffness(1e4)
        .conductance(true)
        .heat_fraction(0.8)
        .slave_fraction(0.25)
}

/// A point of [`uinter_law`] (see there).
fn uinter_base() -> UinterCase {
    gapcon_case::setup();
    let mut c = UinterCase::decode(&[]);
    c.args.set_int("NDIR", 3);
    c.args.set_int("NSTATV", 5);
    c.args.set_int("NPROPS", 13);
    c.args["PROPS"] = uinter_law().build();
    c.args["STRESS"] = vec![20.0, 1.0, 2.0];
    c.args["STATEV"] = vec![0.1, 0.01, 1.0, 7.0, 8.0];
    c.args["RDISP"] = vec![2e-3, 0.5, 0.5];
    c.args["DRDISP"] = vec![0.0, 0.03, -0.04];
    c.args["TEMP"] = vec![300.0, 20.0];
    c.args["DTIME"][0] = 0.5;
    c.args["CHRLNGTH"][0] = 1.0;
    c.args["PNEWDT"][0] = 1e36;
    let mut name = b"PTAB".to_vec();
    name.resize(80, b' ');
    c.names.interaction = name;
    c.null_optional = false;
    c
}

fn run(c: &UinterCase) -> Outputs {
    c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"))
}

fn refused(c: &UinterCase, needle: &str) {
    let out = run(c);
    assert_eq!(out.real("PNEWDT"), 0.25, "not refused ({needle}): {c:?}");
    assert!(
        out.message.contains("UINTER")
            && out.message.contains("'PTAB'")
            && out.message.contains(needle),
        "{needle}: {}",
        out.message
    );
}

/// Rows 52, 53: NaN, +Inf and −Inf in every real argument, one at a time.
#[test]
fn uinter_non_finite_in_every_real_argument() {
    let base = uinter_base();
    let clean = run(&base);
    assert!(clean.message.is_empty(), "{}", clean.message);
    assert_eq!(clean["STATEV"][2], 1.0, "the base point slides");
    assert!(clean["FLUX"][0] != 0.0, "the base point conducts");
    type Field = fn(&mut UinterCase) -> &mut Vec<f64>;
    // Read arrays: (name, field, entries read, message needle).
    let read: [(&str, Field, &[usize], &str); 5] = [
        ("STRESS", |c| &mut c.args["STRESS"], &[0, 1, 2], "STRESS"),
        ("RDISP", |c| &mut c.args["RDISP"], &[0], "RDISP(1)"),
        ("DRDISP", |c| &mut c.args["DRDISP"], &[1, 2], "DRDISP"),
        ("STATEV", |c| &mut c.args["STATEV"], &[0, 1], "STATEV"),
        ("TEMP", |c| &mut c.args["TEMP"], &[0, 1], "TEMP"),
    ];
    for (name, field, entries, needle) in read {
        for &i in entries {
            for v in BAD {
                let mut c = base.clone();
                field(&mut c)[i] = v;
                refused(&c, needle);
                let _ = name;
            }
        }
    }
    for v in BAD {
        let mut c = base.clone();
        c.args["DTIME"][0] = v;
        refused(&c, "DTIME");
        let mut c = base.clone();
        c.args["CHRLNGTH"][0] = v;
        refused(&c, "CHRLNGTH");
        for k in 0..13 {
            let mut c = base.clone();
            c.args["PROPS"][k] = v;
            refused(&c, &format!("PROPS({})", k + 1));
        }
    }
    // Not read: no effect at all (every output bit identical to the clean call).
    let unread: [Field; 8] = [
        |c| &mut c.args["DTEMP"],
        |c| &mut c.args["PREDEF"],
        |c| &mut c.args["DPRED"],
        |c| &mut c.args["TIME"],
        |c| &mut c.args["COORDS"],
        |c| &mut c.args["ALOCALDIR"],
        |c| &mut c.args["DROT"],
        |c| &mut c.args["RDISP"],
    ];
    for (n, field) in unread.into_iter().enumerate() {
        let len = field(&mut base.clone()).len();
        for i in 0..len {
            if n == 7 && i == 0 {
                continue; // RDISP(1) is read
            }
            for v in BAD {
                let mut c = base.clone();
                field(&mut c)[i] = v;
                let out = run(&c);
                assert!(out.message.is_empty(), "{}", out.message);
                let bits = |o: &Outputs| format!("{o:?}");
                assert_eq!(bits(&out), bits(&clean), "unread argument {n}[{i}] = {v}");
            }
        }
    }
    for v in BAD {
        for set in [
            (|c: &mut UinterCase, v| c.args["FREQR"][0] = v) as fn(&mut UinterCase, f64),
            |c, v| c.args["AREA"][0] = v,
            |c, v| c.args["DRDISP"][0] = v,
        ] {
            let mut c = base.clone();
            set(&mut c, v);
            assert_eq!(format!("{:?}", run(&c)), format!("{clean:?}"));
        }
    }
    // TEMP is not read without conduction.
    let mut c = base.clone();
    c.args["PROPS"] = uinter_law().conductance(false).build();
    let plain = run(&c);
    c.args["TEMP"] = vec![f64::NAN, f64::INFINITY];
    assert_eq!(format!("{:?}", run(&c)), format!("{plain:?}"));
}

/// Row 54: sizes and codes out of range.
#[test]
fn uinter_sizes_and_codes_out_of_range() {
    let base = uinter_base();
    for ndir in [-1, 0, 1, 4] {
        let mut c = base.clone();
        c.args.set_int("NDIR", ndir);
        let n = usize::try_from(ndir).unwrap_or(0);
        c.args["STRESS"].resize(n, 0.0);
        c.args["RDISP"].resize(n, 0.0);
        c.args["DRDISP"].resize(n, 0.0);
        refused(&c, &format!("NDIR = {ndir}"));
    }
    for nstatv in [-1, 0, 2] {
        let mut c = base.clone();
        c.args.set_int("NSTATV", nstatv);
        c.args["STATEV"].truncate(usize::try_from(nstatv).unwrap_or(0));
        refused(&c, &format!("NSTATV = {nstatv}"));
    }
    for (nprops, needle) in [
        (-1, "NPROPS = -1"),
        (0, "PROPS(1)"),
        (1, "PROPS(2)"),
        (9, "PROPS(10)"),
    ] {
        let mut c = base.clone();
        c.args.set_int("NPROPS", nprops);
        c.args["PROPS"].truncate(usize::try_from(nprops).unwrap_or(0));
        refused(&c, needle);
    }
    for code in [0.0, 1.0, 3.0, 1.5, -2.0] {
        let mut c = base.clone();
        c.args["PROPS"][0] = code;
        refused(&c, "PROPS(1)");
    }
    // A non-zero entry past the law's 13.
    let mut c = base.clone();
    c.args.set_int("NPROPS", 14);
    c.args["PROPS"].push(1.0);
    refused(&c, "PROPS(14)");
    // Parameters out of range (rows 44-46 list them; one of each kind here).
    for (k, v) in [
        (1, -0.1),
        (2, 0.1),
        (3, -1.0),
        (4, -1.0),
        (9, -1.0),
        (10, 2.0),
        (11, 1.5),
        (12, 1.5),
    ] {
        let mut c = base.clone();
        c.args["PROPS"][k] = v;
        refused(&c, &format!("PROPS({})", k + 1));
    }
}

/// Row 55: zero or negative DTIME with the rate-dependent law; the rate-independent law takes
/// it (slip rate 0).
#[test]
fn uinter_zero_or_negative_dtime() {
    for dt in [0.0, -1.0] {
        let mut c = uinter_base();
        c.args["DTIME"][0] = dt;
        refused(&c, "DTIME");
        // No rate law and no frictional heat: nothing reads DTIME.
        c.args["PROPS"] = uinter_law().kmu(0.0).vhalf(0.0).heat_fraction(0.0).build();
        let out = run(&c);
        assert!(out.message.is_empty(), "{}", out.message);
        assert_eq!(out["STATEV"][1], 0.0);
    }
}

/// Row 56: interaction names of every shape: CHARACTER*8, not padded, NUL-padded, lower case
/// find the same thermal law; all blanks finds none and is refused.
#[test]
fn uinter_names_of_every_shape() {
    let base = uinter_base();
    let clean = run(&base);
    for name in [
        b"PTAB    ".to_vec(),
        b"PTAB".to_vec(),
        b"PTAB\0\0\0\0".to_vec(),
        b"ptab".to_vec(),
    ] {
        let mut c = base.clone();
        c.names.interaction = name.clone();
        let out = run(&c);
        assert!(out.message.is_empty(), "{name:?}: {}", out.message);
        assert_eq!(format!("{out:?}"), format!("{clean:?}"), "{name:?}");
    }
    for name in [vec![b' '; 80], vec![b' '; 8], Vec::new()] {
        let mut c = base.clone();
        c.names.interaction = name;
        let out = run(&c);
        assert_eq!(out.real("PNEWDT"), 0.25);
        assert!(
            out.message.contains("UINTER: interaction ''")
                && out.message.contains("[interactions."),
            "{}",
            out.message
        );
    }
}

/// Row 57: a point apart (negative overclosure) is not an error: open, zero stress, or bonded
/// under a small tension.
#[test]
fn uinter_apart_is_not_an_error() {
    let mut c = uinter_base();
    c.args["RDISP"][0] = -1.0;
    let out = run(&c);
    assert!(out.message.is_empty());
    assert_eq!(out["STATEV"][2], 4.0);
    assert_eq!(out["STRESS"], vec![0.0; 3]);
    assert_eq!(out.int("LOPENCLOSE"), 0);
}

// ---- ifl_fric_batch --------------------------------------------------------------------

/// Four points, NFDIR 2, ld = 6, Coulomb μ = 0.3 with γ_crit from the tolerance × CHRLNGTH;
/// point 3 enters exact stick (LM = 1) so TAULM is read.
fn batch_law() -> CoulombBuilder {
    CoulombBuilder::new().mu(0.3).slip_tolerance(0.005)
}

/// Points of [`batch_law`] (see there).
fn batch_base() -> BatchCase {
    let mut c = BatchCase::decode(&[]);
    c.npoints = 4;
    c.ld = 6;
    c.args.set_int("nfdir", 2);
    c.args.set_int("nstatv", 4);
    c.args["props"] = batch_law().build_first(7);
    c.args["dtime"][0] = 0.5;
    c.args["pnewdt"][0] = 1e36;
    c.null_optional = false;
    c.null_taulm = false;
    c.null_required = None;
    c.args.put_ints("lm", vec![0, 0, 0, 1, 0, 0]);
    let ld = c.ld;
    let fill = |rows: usize, f: &dyn Fn(usize, usize) -> f64| {
        let mut v = vec![-1.0; ld * (rows - 1) + 4];
        for r in 0..rows {
            for i in 0..4 {
                v[i + r * ld] = f(r, i);
            }
        }
        v
    };
    c.args["tau"] = fill(2, &|r, i| 0.1 * (r + i) as f64);
    c.args["dgam"] = fill(2, &|r, i| {
        1e-3 * (1.0 + i as f64) * if r == 0 { 1.0 } else { -0.5 }
    });
    c.args["taulm"] = fill(2, &|r, _| 0.5 + r as f64);
    c.args["statev"] = fill(4, &|r, _| [0.1, 0.0, 0.0, 9.0][r]);
    c.args["press"] = fill(1, &|_, i| 10.0 + i as f64);
    c.args["dpress"] = fill(1, &|_, _| 0.1);
    c.args["chrlngth"] = fill(1, &|_, _| 1.0);
    c
}

fn run_batch(c: &BatchCase) -> Outputs {
    c.check().unwrap_or_else(|e| panic!("{e}\ninput: {c:?}"))
}

/// Row 58: NaN, +Inf and −Inf in every real argument of one point: that point gets the
/// failure outputs and a message naming the argument and the point; the others are computed.
#[test]
fn batch_non_finite_in_every_real_argument() {
    let base = batch_base();
    let clean = run_batch(&base);
    assert_eq!(
        clean.int("status"),
        IflStatus::Ok as i32,
        "{}",
        clean.message
    );
    type Field = fn(&mut BatchCase) -> &mut Vec<f64>;
    let fields: [(Field, usize, usize, &str); 7] = [
        (|c| &mut c.args["tau"], 2, 1, "TAU"),
        (|c| &mut c.args["dgam"], 2, 1, "DGAM"),
        (|c| &mut c.args["taulm"], 2, 3, "TAULM"),
        (|c| &mut c.args["statev"], 2, 1, "STATEV"),
        (|c| &mut c.args["press"], 1, 1, "PRESS"),
        (|c| &mut c.args["dpress"], 1, 1, "DPRESS"),
        (|c| &mut c.args["chrlngth"], 1, 1, "CHRLNGTH"),
    ];
    for (field, rows, point, needle) in fields {
        for r in 0..rows {
            for v in BAD {
                let mut c = base.clone();
                let clean = if needle == "TAULM" {
                    // TAULM is read only by exact stick (PROPS(7) = 1) with LM = 1 on entry.
                    c.args["props"] = batch_law().stick(1.0).build_first(7);
                    run_batch(&c)
                } else {
                    clean.clone()
                };
                let ld = c.ld;
                field(&mut c)[point + r * ld] = v;
                let out = run_batch(&c);
                assert_eq!(
                    out.int("status"),
                    IflStatus::BadInput as i32,
                    "{needle}: {}",
                    out.message
                );
                assert_eq!(out.real("pnewdt"), 0.25);
                assert!(
                    out.message.contains(&format!("batch point {point}"))
                        && out.message.contains(needle),
                    "{needle}: {}",
                    out.message
                );
                for i in (0..4).filter(|i| *i != point) {
                    assert_eq!(out.args.ints("lm")[i], clean.args.ints("lm")[i]);
                    assert_eq!(out["tau"][i].to_bits(), clean["tau"][i].to_bits());
                    assert_eq!(out["statev"][i].to_bits(), clean["statev"][i].to_bits());
                }
            }
        }
    }
    // DTIME is shared: every point fails. PROPS entries: the whole batch is refused.
    for v in BAD {
        let mut c = base.clone();
        c.args["dtime"][0] = v;
        let out = run_batch(&c);
        assert_eq!(out.int("status"), IflStatus::BadInput as i32);
        assert!(out.message.contains("DTIME"), "{}", out.message);
        for k in 0..7 {
            let mut c = base.clone();
            c.args["props"][k] = v;
            let out = run_batch(&c);
            assert_eq!(
                out.int("status"),
                IflStatus::BadParameter as i32,
                "PROPS({}) = {v}",
                k + 1
            );
            assert!(
                out.message.contains(&format!("PROPS({})", k + 1)),
                "{}",
                out.message
            );
        }
    }
}

/// Row 59: sizes out of range refuse the whole batch and write only PNEWDT; LM out of range
/// fails its point; an empty batch is fine.
#[test]
fn batch_sizes_out_of_range() {
    let base = batch_base();
    for (nfdir, nstatv, ld, needle) in [
        (0, 4, 6, "NFDIR = 0"),
        (3, 4, 6, "NFDIR = 3"),
        (-1, 4, 6, "NFDIR = -1"),
        (2, 2, 6, "NSTATV = 2"),
        (2, -1, 6, "NSTATV = -1"),
        (2, 4, 3, "ld = 3 is less than npoints = 4"),
    ] {
        let mut c = base.clone();
        c.args.set_int("nfdir", nfdir);
        c.args.set_int("nstatv", nstatv);
        c.ld = ld;
        let out = run_batch(&c);
        assert_eq!(out.int("status"), IflStatus::BadParameter as i32);
        assert!(out.message.contains(needle), "{needle}: {}", out.message);
    }
    for nprops in [0usize, 1] {
        let mut c = base.clone();
        c.args["props"].truncate(nprops);
        let out = run_batch(&c);
        assert_eq!(
            out.int("status"),
            IflStatus::BadParameter as i32,
            "NPROPS = {nprops}"
        );
    }
    // The adhesive law has no batch kernel.
    let mut c = base.clone();
    c.args["props"] = AdhesiveBuilder::new().coeff(0.3).sa(1.0).build_first(4);
    let out = run_batch(&c);
    assert_eq!(out.int("status"), IflStatus::BadParameter as i32);
    // LM out of range: that point fails.
    for lm in [-1, 3] {
        let mut c = base.clone();
        c.args.ints_mut("lm")[2] = lm;
        let out = run_batch(&c);
        assert_eq!(out.int("status"), IflStatus::BadInput as i32);
        assert!(out.message.contains("batch point 2") && out.message.contains("LM"));
    }
    // Empty batch.
    let mut c = base.clone();
    c.npoints = 0;
    c.ld = 0;
    for name in [
        "tau", "dgam", "taulm", "statev", "press", "dpress", "chrlngth",
    ] {
        c.args[name].clear();
    }
    c.args.ints_mut("lm").clear();
    let out = run_batch(&c);
    assert_eq!(out.int("status"), IflStatus::Ok as i32);
    assert_eq!(out.real("pnewdt"), 1e36);
}

/// One point through `ifl_fric_batch` on scratch arrays of 4 entries (`NPROPS` 5, `NSTATV` 3,
/// Δt 0.5, the optional outputs and TAULM NULL): leading dimension `ld`, `nfdir`, these `props`
/// and `pnewdt` (either may be NULL).
fn one_point_batch(ld: usize, nfdir: i32, props: *const f64, pnewdt: *mut f64) -> IflStatus {
    let mut lm = [0i32; 1];
    let mut x = [0.0f64; 4];
    let chrlngth = [1.0f64; 4];
    // SAFETY: every array holds 4 entries, enough for one point with ld = 1 and NFDIR ≤ 2; with
    // a larger ld the call must refuse on the sizes before it forms any slice. NULLs as
    // documented.
    unsafe {
        interfacial::abi::ifl_fric_batch(
            1,
            ld,
            nfdir,
            props,
            5,
            3,
            0.5,
            lm.as_mut_ptr(),
            x.as_mut_ptr(),
            x.as_mut_ptr(),
            x.as_mut_ptr(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            x.as_mut_ptr(),
            x.as_ptr(),
            std::ptr::null(),
            x.as_ptr(),
            x.as_ptr(),
            chrlngth.as_ptr(),
            pnewdt,
        )
    }
}

/// Row 60: ld × components overflowing usize is refused before any array is touched.
#[test]
fn batch_leading_dimension_overflow() {
    let good = CoulombBuilder::new()
        .mu(0.3)
        .gamma_crit(1e-3)
        .build_first(5);
    let mut pnewdt = 1e36;
    let st = one_point_batch(usize::MAX / 2, 2, good.as_ptr(), &mut pnewdt);
    assert_eq!((st, pnewdt), (IflStatus::BadParameter, 0.25));
}

/// Row 61: NULL pointers: each required array NULL refuses the whole batch naming it; PNEWDT
/// NULL still returns the status; optional outputs NULL are not written; TAULM NULL fails
/// only the point that enters exact stick.
#[test]
fn batch_null_pointers() {
    let base = batch_base();
    let names = [
        "lm", "tau", "ddtddg", "ddtddp", "statev", "dgam", "press", "dpress", "chrlngth",
    ];
    for (k, name) in names.iter().enumerate() {
        let mut c = base.clone();
        c.null_required = Some(k);
        let out = run_batch(&c);
        assert_eq!(out.int("status"), IflStatus::BadInput as i32, "{name}");
        assert!(
            out.message.contains(&format!("{name} is a NULL pointer")),
            "{}",
            out.message
        );
    }
    let mut c = base.clone();
    c.null_optional = true;
    run_batch(&c);
    let mut c = base.clone();
    c.null_taulm = true;
    let out = run_batch(&c);
    assert_eq!(out.int("status"), IflStatus::BadInput as i32);
    assert!(
        out.message.contains("batch point 3") && out.message.contains("LM = 1 on entry but TAULM")
    );
    // PNEWDT NULL and PROPS NULL with NPROPS > 0.
    let good = CoulombBuilder::new()
        .mu(0.3)
        .gamma_crit(1e-3)
        .build_first(5);
    for (props, pnewdt_null, expect) in [
        (good.as_ptr(), true, IflStatus::Ok),
        (std::ptr::null(), false, IflStatus::BadInput),
    ] {
        let mut pnewdt = 1e36;
        let p: *mut f64 = if pnewdt_null {
            std::ptr::null_mut()
        } else {
            &mut pnewdt
        };
        let st = one_point_batch(1, 1, props, p);
        assert_eq!(st, expect);
    }
}
