//! The `PROPS` layouts through the C API a tool asks (`ifl_props_*`, src/abi/props_query.rs):
//! every row it lists is the row docs/props.md shows, read back from the committed file; and
//! `ifl_props_check` refuses exactly what `fric_` refuses, with `fric_`'s words, over drawn
//! `PROPS` arrays of both laws.

use std::ffi::{CStr, c_char};
use std::path::Path;

use interfacial::abi::{
    IflPropsEntry, IflStatus, ifl_clear_error, ifl_props_check, ifl_props_entry,
    ifl_props_entry_count, ifl_props_law_code, ifl_props_law_count,
};
use interfacial::props::AdhesiveBuilder;
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;

#[path = "common/drawn_props.rs"]
mod drawn_props;
#[path = "common/laws.rs"]
mod laws;
use drawn_props::{VALUES, bases};

fn text(p: *const c_char) -> String {
    assert!(!p.is_null());
    // SAFETY: the API's texts are NUL-terminated static strings.
    unsafe { CStr::from_ptr(p) }.to_str().unwrap().to_owned()
}

fn entry(law: i32, i: i32) -> Result<IflPropsEntry, IflStatus> {
    let mut e = std::mem::MaybeUninit::<IflPropsEntry>::uninit();
    // SAFETY: a writable entry.
    match unsafe { ifl_props_entry(law, i, e.as_mut_ptr()) } {
        // SAFETY: written on success.
        IflStatus::Ok => Ok(unsafe { e.assume_init() }),
        other => Err(other),
    }
}

/// The rows of law `law`'s table in docs/props.md, each as its seven cells.
fn docs_rows(law: i32) -> Vec<Vec<String>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/props.md");
    let doc = std::fs::read_to_string(path).unwrap();
    let begin = format!("<!-- BEGIN PROPS TABLE law {law}:");
    let start = doc.find(&begin).expect("begin marker");
    let end = start
        + doc[start..]
            .find("<!-- END PROPS TABLE")
            .expect("end marker");
    doc[start..end]
        .lines()
        .skip(3) // the marker, the header, the rule
        .map(|line| {
            let inner = line
                .strip_prefix("| ")
                .and_then(|l| l.strip_suffix(" |"))
                .unwrap_or_else(|| panic!("not a table row: {line:?}"));
            inner.split(" | ").map(str::to_owned).collect()
        })
        .collect()
}

#[test]
fn every_row_the_api_lists_is_the_row_of_docs_props_md() {
    let laws: Vec<i32> = (0..ifl_props_law_count())
        .map(|i| ifl_props_law_code(i))
        .collect();
    assert_eq!(laws, [1, 2, 3], "the laws docs/props.md documents");
    for law in laws {
        let rows = docs_rows(law);
        assert_eq!(ifl_props_entry_count(law) as usize, rows.len(), "law {law}");
        for (i, cells) in rows.iter().enumerate() {
            let e = entry(law, i as i32).unwrap();
            let context = format!("law {law}, row {i}: {cells:?}");
            assert_eq!(cells.len(), 7, "{context}");
            let when = text(e.when);
            let shown = if when.is_empty() {
                format!("PROPS({})", e.index)
            } else {
                format!("PROPS({}) ({when})", e.index)
            };
            assert_eq!(cells[0].replace('`', ""), shown, "{context}");
            let key = text(e.key);
            let seed = if e.seed_name == 1 {
                format!("`{key}`")
            } else {
                "—".to_owned()
            };
            assert_eq!(cells[1], seed, "{context}");
            let dash = |s: String| if s.is_empty() { "—".to_owned() } else { s };
            assert_eq!(cells[2], dash(text(e.symbol)), "{context}");
            assert_eq!(cells[3], text(e.meaning), "{context}");
            assert_eq!(cells[4], dash(text(e.unit)), "{context}");
            assert_eq!(cells[5], text(e.default_text), "{context}");
            assert_eq!(cells[6], text(e.valid), "{context}");
            // The number, where the docs give one number; the required entries say so.
            match cells[5].parse::<f64>() {
                Ok(v) => assert_eq!(e.default_value, v, "{context}"),
                Err(_) => assert!(e.default_value.is_nan(), "{context}"),
            }
            // Required always (not only in some mode, as d_c "required by the decay law").
            let required = cells[5] == "— (required)" || cells[6].starts_with("exactly");
            assert_eq!(e.required == 1, required, "{context}");
            // A key is a name a deck or a builder can use: no blank, not empty, unique per
            // meaning of an index.
            assert!(!key.is_empty() && !key.contains(' '), "{context}");
        }
    }
}

/// Facts from the seeds and the layouts' meaning, not from our output: law 2's entries carry
/// seed 004's names, law 1's steady-transport entries have two meanings each.
#[test]
fn the_api_says_what_the_layouts_mean() {
    let keys: Vec<String> = (0..ifl_props_entry_count(2))
        .map(|i| text(entry(2, i).unwrap().key))
        .collect();
    assert_eq!(
        &keys[1..7],
        ["coeff", "coeffStatic", "Sa", "Na", "kmu", "vhalf"]
    );
    let rows: Vec<IflPropsEntry> = (0..ifl_props_entry_count(1))
        .map(|i| entry(1, i).unwrap())
        .collect();
    // Every index 1..=20 once at least, in order; 14, 15, 16 twice (PROPS(7) = 3 or not), 5
    // twice (PROPS(7) = 4, the constant stick stiffness, or not).
    let indices: Vec<i32> = rows.iter().map(|e| e.index).collect();
    let mut expected: Vec<i32> = (1..=20).collect();
    expected.extend([5, 14, 15, 16]);
    expected.sort_unstable();
    assert_eq!(indices, expected);
    for pair in rows.windows(2).filter(|w| w[0].index == w[1].index) {
        let mode = if pair[0].index == 5 { 4 } else { 3 };
        assert_eq!(text(pair[0].when), format!("PROPS(7) = {mode}"));
        assert_eq!(text(pair[1].when), format!("PROPS(7) ≠ {mode}"));
    }
    // The slip tolerance's default 0.005 (docs/props.md, both laws), μ required.
    let tolerance = rows.iter().find(|e| e.index == 6).unwrap();
    assert_eq!(tolerance.default_value, 0.005);
    assert_eq!(rows[1].required, 1);
    assert_eq!(rows[2].required, 0);
}

#[test]
fn a_bad_question_is_refused_and_reported() {
    assert_eq!(ifl_props_law_code(-1), 0);
    assert_eq!(ifl_props_law_code(3), 0);
    assert_eq!(ifl_props_entry_count(4), 0);
    assert_eq!(entry(4, 0).unwrap_err(), IflStatus::BadParameter);
    let message = FricCall::last_error();
    assert!(message.contains("law 4 is not a law code"), "{message}");
    // The message lists every law the API lists (law 3 was once missing from it).
    let listed: Vec<i32> = message
        .split("law code (")
        .nth(1)
        .and_then(|l| l.strip_suffix(')'))
        .map(|l| {
            l.split(", ")
                .filter_map(|e| e.split(':').next()?.parse().ok())
        })
        .map_or_else(Vec::new, Iterator::collect);
    let codes: Vec<i32> = (0..ifl_props_law_count())
        .map(|i| ifl_props_law_code(i))
        .collect();
    assert_eq!(listed, codes, "{message}");
    let n = ifl_props_entry_count(2);
    assert_eq!(entry(2, n).unwrap_err(), IflStatus::BadParameter);
    assert!(FricCall::last_error().contains(&format!("law 2 has rows 0 to {}", n - 1)));
    assert_eq!(entry(2, -1).unwrap_err(), IflStatus::BadParameter);
    // SAFETY: NULL is refused before anything is written.
    let st = unsafe { ifl_props_entry(1, 0, std::ptr::null_mut()) };
    assert_eq!(st, IflStatus::BadInput);
    assert!(FricCall::last_error().contains("out is a NULL pointer"));
}

/// `ifl_props_check` on `props[..nprops]` (`nprops` may be negative) for interaction SI1: the
/// status and the whole message.
fn check(props: &[f64], nprops: i32) -> (IflStatus, String) {
    let mut buf = vec![0 as c_char; 1024];
    let mut len = usize::MAX;
    // SAFETY: `props` holds at least `nprops` entries; the buffer its capacity.
    let st = unsafe {
        ifl_props_check(
            props.as_ptr(),
            nprops,
            c"SI1".as_ptr(),
            buf.as_mut_ptr(),
            buf.len(),
            &mut len,
        )
    };
    assert!(len < buf.len(), "message of {len} bytes");
    let msg = text(buf.as_ptr());
    assert_eq!(msg.len(), len);
    (st, msg)
}

/// `fric_`'s verdict on `props[..nprops]` with a benign increment (closed, no slip, p = 1, the
/// state fresh, room for damping's state, coordinates off the spinning axis): `None` when it
/// answered, its message when it refused.
fn fric_verdict(props: &[f64], nprops: i32) -> Option<String> {
    let mut c = FricCall::new(2, props);
    c.nprops = nprops;
    c.nstatv = 8;
    c.statev = vec![0.0; 8];
    c.press = 1.0;
    c.coords = [1.0, 2.0, 3.0];
    ifl_clear_error();
    c.call();
    let m = FricCall::last_error();
    (!m.is_empty()).then_some(m)
}

#[track_caller]
fn assert_agree(props: &[f64], nprops: i32) {
    let (st, msg) = check(props, nprops);
    match fric_verdict(props, nprops) {
        None => assert_eq!(
            (st, msg.as_str()),
            (IflStatus::Ok, ""),
            "fric_ took {props:?} (NPROPS {nprops})"
        ),
        Some(m) => {
            assert_ne!(st, IflStatus::Ok, "fric_ refused {props:?}: {m}");
            assert!(
                m.starts_with("interfacial: FRIC: interaction 'SI1' (") && m.ends_with(&msg),
                "fric_ said {m:?}, the check {msg:?}"
            );
            // The cause follows the place: nothing but the cause after "): ".
            assert!(m.contains(&format!("): {msg}")), "{m:?} / {msg:?}");
        }
    }
}

/// Law 2's γ_crit = 2 (`PROPS(8) = 2`, law 1's μ-table switch value) is read as γ_crit by
/// `fric_` and by the check alike (the bug tests/law_selection.rs pins).
#[test]
fn fric_takes_law_2_with_gamma_crit_2() {
    let props = AdhesiveBuilder::new()
        .coeff(0.3)
        .sa(1.0)
        .gamma_crit(2.0)
        .build();
    assert_eq!(fric_verdict(&props, props.len() as i32), None);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// One valid base, zero to three entries set to drawn values, `NPROPS` anything from −1 to
    /// 22: `ifl_props_check` takes what `fric_` takes and refuses with `fric_`'s message.
    #[test]
    fn the_check_refuses_what_fric_refuses_with_its_message(
        base in 0..bases().len(),
        changes in proptest::collection::vec((0..22usize, 0..VALUES.len()), 0..4),
        nprops in prop_oneof![3 => Just(None), 1 => (-1..23i32).prop_map(Some)],
    ) {
        let mut props = bases()[base].clone();
        for (i, v) in changes {
            if props.len() <= i {
                props.resize(i + 1, 0.0);
            }
            props[i] = VALUES[v];
        }
        let n = nprops.unwrap_or(props.len() as i32);
        if props.len() < n.max(0) as usize {
            props.resize(n as usize, 0.0);
        }
        assert_agree(&props, n);
    }
}

/// The cases the drawn ones must not miss, each named: no `PROPS`, an unknown law, a non-integer
/// code, a negative `NPROPS`, a table without a configuration file, a good array of each law.
#[test]
fn the_named_cases_agree() {
    let cases: [(&[f64], i32); 8] = [
        (&[], 0),
        (&[7.0, 0.3], 2),
        (&[1.5, 0.3], 2),
        (&[1.0, 0.3], -1),
        (&[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0], 8),
        (&[1.0, -0.3], 2),
        (&[1.0, 0.3, 0.0, 0.0, 1e-3], 5),
        (&[2.0, 0.3, -1.0], 3),
    ];
    for (props, n) in cases {
        assert_agree(props, n);
    }
    assert_eq!(check(&[1.0, 0.3], 2).0, IflStatus::Ok);
    let (st, msg) = check(&[1.0, -0.3], 2);
    assert_eq!(st, IflStatus::BadParameter);
    assert!(msg.starts_with("bad parameter: PROPS(2)"), "{msg}");
}

/// The message is cut to the caller's buffer, NUL-terminated, and nothing past it is written;
/// the whole length still comes back. A check reports nothing: the last error stays.
#[test]
fn the_message_never_runs_past_the_buffer() {
    let (_, whole) = check(&[1.0, -0.3], 2);
    let mut buf = [0x55 as c_char; 32];
    let mut len = 0usize;
    ifl_clear_error();
    // SAFETY: 16 bytes of the 32 offered; two valid doubles.
    let st = unsafe {
        ifl_props_check(
            [1.0, -0.3].as_ptr(),
            2,
            std::ptr::null(),
            buf.as_mut_ptr(),
            16,
            &mut len,
        )
    };
    assert_eq!(st, IflStatus::BadParameter);
    assert_eq!(len, whole.len());
    assert_eq!(text(buf.as_ptr()), whole[..15]);
    assert!(buf[16..].iter().all(|&b| b == 0x55));
    assert_eq!(FricCall::last_error(), "");
    // NULL buffer and length: the status alone.
    // SAFETY: NULL outputs are allowed.
    let st = unsafe {
        ifl_props_check(
            [1.0, 0.3].as_ptr(),
            2,
            std::ptr::null(),
            std::ptr::null_mut(),
            0,
            std::ptr::null_mut(),
        )
    };
    assert_eq!(st, IflStatus::Ok);
}
