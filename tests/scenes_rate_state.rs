//! Scenes R1 and R2 of the main job (examples/scenes/rate_state.rs: rate-and-state friction
//! through `fric_`), compiled in by path so the test runs the same code on the quick sweeps:
//! every row within its tolerance, both scenes present, and the R2 rows that resolve L present
//! (a row that went missing would leave its claim unguarded).
#![allow(dead_code)]

#[path = "../examples/scenes/checks.rs"]
mod checks;
#[path = "../examples/scenes/rate_state.rs"]
mod rate_state;

#[test]
fn rate_and_state_scenes_hold() {
    let out = std::env::temp_dir().join(format!("interfacial-r-scenes-{}", std::process::id()));
    std::fs::create_dir_all(&out).unwrap();
    let rows = rate_state::run(&out, true);
    let _ = std::fs::remove_dir_all(&out);
    let (rows, files) = rows.unwrap();
    assert_eq!(files.len(), 4);
    let failed = checks::failures(&rows);
    assert!(failed.is_empty(), "{}", failed.join("\n"));
    assert_eq!(rows.iter().filter(|r| r.scene == "R1").count(), 4);
    // --quick's R2 rows: V·Δt/L = 0.03 resolves L (1.0 does not and is not checked).
    assert_eq!(rows.iter().filter(|r| r.scene == "R2").count(), 1);
}
