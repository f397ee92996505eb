//! The main job's closed-form checks (examples/scenes/checks.rs: F1–F5 through `fric_`, T1 and
//! T2 through `gapcon_`, A1 through `uinter_`), compiled in by path so the test runs the same
//! code: every row within its tolerance. One test in this binary on purpose: the checks set
//! `INTERFACIAL_CONFIG` before the first `gapcon_` call, which must not race with other threads.
#![allow(dead_code)]

#[path = "../examples/scenes/checks.rs"]
mod checks;

#[test]
fn every_closed_form_check_of_the_main_job_holds() {
    let rows = checks::run().expect("the checks' configuration file");
    let failed = checks::failures(&rows);
    assert!(failed.is_empty(), "{}", failed.join("\n"));
    for scene in ["F1", "F2", "F3", "F4", "F5", "T1", "T2", "A1"] {
        assert!(rows.iter().any(|r| r.scene == scene), "no {scene} rows");
    }
}
