//! `gapcon_` through the ABI with a configuration file: name matching, outputs, bad input,
//! threads, and the native `ifl_gap_conductance`. The file is read once per process, so this
//! binary sets `INTERFACIAL_CONFIG` before its first call; bad files are tried in child
//! processes (see `config_errors`).

#[path = "common/config_file.rs"]
mod config_file;
#[path = "common/threads.rs"]
mod threads;
use std::ffi::CString;
use std::process::Command;
use threads::map_on_threads;

use interfacial::abi::{IflConductance, IflStatus, ifl_gap_conductance};
use interfacial_test_hosts::{FricCall, GUARD, GapconCall};

const CONFIG: &str = r#"
[interactions.SI1.conductance]
law = "constant"
k = 2.0

[interactions.Spots.conductance]
law = "cmy"
k_s = 20.0
m = 0.1
sigma = 2e-6
H_c = 2e9

[interactions.Hot.conductance]
law = "pressure-table"
table = [[0.0, 100.0, 300.0], [50.0, 600.0, 300.0], [0.0, 200.0, 500.0], [50.0, 900.0, 500.0]]

[interactions.Hot.radiation]
view_factor = 0.5
stefan_boltzmann = 5.670374419e-8
absolute_zero = 0.0

[interactions."*".conductance]
law = "pressure-table"
table = [[0.0, 1.0], [100.0, 3.0]]
"#;

fn setup() {
    config_file::config_once("gapcon", CONFIG);
}

#[test]
fn names_match_exactly_ignoring_case_and_trailing_blanks() {
    setup();
    for name in ["SI1", "si1", "Si1      "] {
        let mut c = GapconCall::new(name, 0.0, 70.0, 300.0, 290.0);
        assert_eq!(c.call(), 2.0, "{name}");
        assert_eq!(&c.ak[1..], &[GUARD; 4], "AK(2..5) untouched");
    }
    // SI1A is not SI1: it falls back to "*" (k linear in p: 1 + 2·70/100 = 2.4).
    let mut c = GapconCall::new("SI1A", 0.0, 70.0, 300.0, 290.0);
    assert!((c.call() - 2.4).abs() < 1e-15);
    // CHARACTER*8 caller: the bytes after the hidden length are not part of the name.
    let mut c = GapconCall::new("SI1     SI1A", 0.0, 70.0, 300.0, 290.0);
    c.name_len = 8;
    assert_eq!(c.call(), 2.0);
}

#[test]
fn table_plus_radiation() {
    setup();
    // θ̄ = 400: halfway between the tables; p = 25: halfway along each → (350 + 550)/2 = 450.
    let (ta, tb) = (410.0, 390.0);
    let mut c = GapconCall::new("HOT", 0.0, 25.0, ta, tb);
    let k_rad = 0.5 * 5.670374419e-8 * (ta + tb) * (ta * ta + tb * tb);
    assert!((c.call() - (450.0 + k_rad)).abs() < 1e-9);
}

#[test]
fn non_finite_inputs_give_zero_and_a_message() {
    setup();
    for (d, p, ta, tb, word) in [
        (f64::NAN, 1.0, 300.0, 300.0, "D(1)"),
        (0.0, f64::INFINITY, 300.0, 300.0, "D(2)"),
        (0.0, 1.0, f64::NAN, 300.0, "TEMP(1)"),
        (0.0, 1.0, 300.0, f64::NEG_INFINITY, "TEMP(2)"),
    ] {
        let mut c = GapconCall::new("SI1", d, p, ta, tb);
        c.noel = 42;
        assert_eq!(c.call(), 0.0);
        assert_eq!(&c.ak[1..], &[GUARD; 4]);
        let msg = FricCall::last_error();
        assert!(
            msg.contains("GAPCON")
                && msg.contains("'SI1'")
                && msg.contains("element 42")
                && msg.contains(word),
            "{msg}"
        );
    }
    // Radiation below absolute zero.
    let mut c = GapconCall::new("HOT", 0.0, 1.0, -5.0, 300.0);
    assert_eq!(c.call(), 0.0);
    assert!(FricCall::last_error().contains("absolute zero"));
}

#[test]
fn native_api_agrees_with_gapcon() {
    setup();
    let name = CString::new("hot").unwrap();
    let mut out = IflConductance::default();
    // SAFETY: valid NUL-terminated name and output struct.
    let status = unsafe { ifl_gap_conductance(name.as_ptr(), 0.0, 30.0, 420.0, 380.0, &mut out) };
    assert_eq!(status, IflStatus::Ok);
    let mut c = GapconCall::new("HOT", 0.0, 30.0, 420.0, 380.0);
    assert_eq!(out.k, c.call());
    // Flux derivatives: conduction part by the seed's formula, radiation exact; together they
    // are the derivatives of q = k·(θ_A − θ_B), checked here by central differences.
    let q = |ta: f64, tb: f64| GapconCall::new("HOT", 0.0, 30.0, ta, tb).call() * (ta - tb);
    let h = 1e-4;
    let fd_a = (q(420.0 + h, 380.0) - q(420.0 - h, 380.0)) / (2.0 * h);
    let fd_b = (q(420.0, 380.0 + h) - q(420.0, 380.0 - h)) / (2.0 * h);
    assert!(
        (out.dq_dtheta_a - fd_a).abs() < 1e-6 * fd_a.abs(),
        "{} {fd_a}",
        out.dq_dtheta_a
    );
    assert!(
        (out.dq_dtheta_b - fd_b).abs() < 1e-6 * fd_b.abs(),
        "{} {fd_b}",
        out.dq_dtheta_b
    );
    // Unknown name with no match falls back to "*"; NULL out is refused.
    // SAFETY: NULL out is allowed by the contract (refused with a status).
    let status = unsafe {
        ifl_gap_conductance(name.as_ptr(), 0.0, 30.0, 420.0, 380.0, std::ptr::null_mut())
    };
    assert_eq!(status, IflStatus::BadInput);
    // SAFETY: as above.
    let status =
        unsafe { ifl_gap_conductance(name.as_ptr(), f64::NAN, 30.0, 420.0, 380.0, &mut out) };
    assert_eq!(status, IflStatus::BadInput);
    assert_eq!(out, IflConductance::default());
}

#[test]
fn results_do_not_depend_on_the_number_of_threads() {
    setup();
    let points: Vec<GapconCall> = (0..2000)
        .map(|i| {
            let x = f64::from(i);
            let name = ["SI1", "HOT", "OTHER"][i as usize % 3];
            GapconCall::new(
                name,
                0.0,
                (x * 0.37) % 120.0 - 10.0,
                280.0 + (x * 0.71) % 250.0,
                300.0,
            )
        })
        .collect();
    let serial: Vec<u64> = points.iter().map(|p| p.clone().call().to_bits()).collect();
    let parallel = map_on_threads(&points, 250, |p| p.clone().call().to_bits());
    assert_eq!(serial, parallel);
}

/// Child side of `config_errors`: one call with whatever INTERFACIAL_CONFIG the parent set.
#[test]
fn child_one_call() {
    if std::env::var_os("IFL_GAPCON_CHILD").is_none() {
        return;
    }
    let mut c = GapconCall::new("SI1", 0.0, 1.0, 300.0, 290.0);
    let ak = c.call();
    println!("AK1={ak}");
    println!("MSG={}", FricCall::last_error());
}

#[test]
fn config_errors() {
    let dir = std::env::temp_dir();
    let write = |tag: &str, text: &str| {
        let p = dir.join(format!("interfacial-bad-{tag}-{}.toml", std::process::id()));
        std::fs::write(&p, text).unwrap();
        p.to_string_lossy().into_owned()
    };
    let write_bytes = |tag: &str, bytes: &[u8]| {
        let p = dir.join(format!("interfacial-bad-{tag}-{}.toml", std::process::id()));
        std::fs::write(&p, bytes).unwrap();
        p.to_string_lossy().into_owned()
    };
    let cases: Vec<(Option<String>, &str)> = vec![
        (None, "INTERFACIAL_CONFIG is not set"),
        (Some("/nonexistent/interfacial.toml".into()), "cannot read"),
        (
            Some(write("syntax", "[interactions.SI1.conductance\n")),
            ":1:",
        ),
        (
            Some(write(
                "law",
                "[interactions.SI1.conductance]\nlaw = \"magic\"\n",
            )),
            ":2: interactions.SI1.conductance.law: unknown law",
        ),
        (
            Some(write(
                "order",
                "[interactions.SI1.conductance]\nlaw = \"pressure-table\"\ntable = [[5.0, 1.0], [1.0, 2.0]]\n",
            )),
            ":3: interactions.SI1.conductance.table",
        ),
        (
            Some(write(
                "empty",
                "[interactions.SI1.conductance]\nlaw = \"clearance-table\"\ntable = []\n",
            )),
            "empty",
        ),
        (
            Some(write(
                "negative",
                "[interactions.SI1.conductance]\nlaw = \"constant\"\nk = -3.0\n",
            )),
            ":3: interactions.SI1.conductance.k",
        ),
        // Unreadable: a directory, and a file that is not UTF-8 text.
        (Some(dir.to_string_lossy().into_owned()), "cannot read"),
        (
            Some(write_bytes("binary", b"k = \xff\xfe\n")),
            "cannot read",
        ),
        // Inconsistent: a value of the wrong type, rows of different widths, an unknown key at
        // the top, radiation without its units, two names that differ only in case.
        (
            Some(write(
                "type",
                "[interactions.SI1.conductance]\nlaw = \"constant\"\nk = \"two\"\n",
            )),
            ":3:",
        ),
        (
            Some(write(
                "widths",
                "[interactions.SI1.conductance]\nlaw = \"pressure-table\"\ntable = [[0.0, 1.0], [1.0, 2.0, 300.0]]\n",
            )),
            ":3: interactions.SI1.conductance.table",
        ),
        (Some(write("toplevel", "interaction = 1\n")), ":1:"),
        (
            Some(write(
                "units",
                "[interactions.SI1.radiation]\nview_factor = 0.5\n",
            )),
            "interactions.SI1.radiation",
        ),
        (
            Some(write(
                "case",
                "[interactions.SI1.conductance]\nlaw = \"constant\"\nk = 1.0\n[interactions.si1.conductance]\nlaw = \"constant\"\nk = 2.0\n",
            )),
            "ignoring case",
        ),
        (
            Some(write(
                "missing",
                "[interactions.OTHER.conductance]\nlaw = \"constant\"\nk = 1.0\n",
            )),
            "interaction not found",
        ),
    ];
    let exe = std::env::current_exe().unwrap();
    for (config, needle) in cases {
        let mut cmd = Command::new(&exe);
        cmd.args([
            "--exact",
            "child_one_call",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("IFL_GAPCON_CHILD", "1")
        .env_remove("INTERFACIAL_CONFIG");
        if let Some(c) = &config {
            cmd.env("INTERFACIAL_CONFIG", c);
        }
        let out = cmd.output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{text}");
        assert!(text.contains("AK1=0\n"), "{config:?}: {text}");
        let msg = text.lines().find(|l| l.starts_with("MSG=")).unwrap_or("");
        assert!(
            msg.contains("GAPCON") && msg.contains(needle),
            "{config:?}: {msg}"
        );
        if let Some(c) = &config {
            if c.starts_with(&*dir.to_string_lossy()) {
                assert!(msg.contains(c.as_str()), "message names the file: {msg}");
                let _ = std::fs::remove_file(c);
            }
        }
    }
}

/// Child side of `a_bad_file_is_reported_once`: calls for three interactions.
#[test]
fn child_three_names() {
    if std::env::var_os("IFL_GAPCON_CHILD3").is_none() {
        return;
    }
    for name in ["A", "B", "C", "A"] {
        assert_eq!(GapconCall::new(name, 0.0, 1.0, 300.0, 290.0).call(), 0.0);
    }
}

#[test]
fn a_bad_file_is_reported_once_for_all_interactions() {
    let dir = std::env::temp_dir();
    let cfg = dir.join(format!("interfacial-bad-once-{}.toml", std::process::id()));
    let log = dir.join(format!("interfacial-bad-once-{}.log", std::process::id()));
    std::fs::write(
        &cfg,
        "[interactions.A.conductance]\nlaw = \"constant\"\nk = -1.0\n",
    )
    .unwrap();
    let _ = std::fs::remove_file(&log);
    let out = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "child_three_names",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("IFL_GAPCON_CHILD3", "1")
        .env("INTERFACIAL_CONFIG", &cfg)
        .env("INTERFACIAL_LOG", &log)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let text = std::fs::read_to_string(&log).unwrap_or_default();
    let _ = std::fs::remove_file(&cfg);
    let _ = std::fs::remove_file(&log);
    assert_eq!(text.lines().count(), 1, "{text}");
    assert!(text.contains(":3: interactions.A.conductance.k"), "{text}");
}

/// docs/config.md and bad-input row 27a through `gapcon_`: the CMY correlation answers up to
/// P/H_c = 1 (closed form 1.25·(k_s·m/σ)·(P/H_c)^0.95) and refuses beyond it with AK(1) = 0,
/// nothing else written, and a message naming the routine, the interaction and H_c.
#[test]
fn cmy_answers_up_to_the_microhardness_and_refuses_beyond_it() {
    setup();
    let scale = 1.25 * (20.0 * 0.1 / 2e-6);
    for p in [2e6, 2e8, 2e9] {
        let mut c = GapconCall::new("Spots", 0.0, p, 320.0, 300.0);
        let k = c.call();
        let expected = scale * (p / 2e9f64).powf(0.95);
        assert!(
            (k - expected).abs() <= 1e-12 * expected,
            "p = {p}: {k} vs {expected}"
        );
    }
    let mut c = GapconCall::new("Spots", 0.0, 2.2e9, 320.0, 300.0);
    assert_eq!(c.call(), 0.0, "AK(1) = 0 on refusal");
    assert_eq!(&c.ak[1..], &[GUARD; 4], "AK(2..5) untouched");
    let m = FricCall::last_error();
    for word in ["GAPCON", "Spots", "H_c", "P/H_c"] {
        assert!(m.contains(word), "'{word}' missing from: {m}");
    }
}
