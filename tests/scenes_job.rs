//! The main job (examples/scenes/, compiled in by path so that the test runs the same code) on
//! its reduced sweeps (`--quick`): it passes, and every CSV file it writes is well formed — read
//! by a real CSV reader, every row has as many fields as the header. One test in this binary on
//! purpose: the job's closed-form checks set `INTERFACIAL_CONFIG` before the first `gapcon_`
//! call, which must not race with other threads.
#![allow(dead_code)]

include!("common/scene_modules.rs");

use std::path::PathBuf;

/// Every CSV file in `dir`: (name, header width, rows), each row checked against the header.
fn read_all_csv(dir: &std::path::Path) -> Vec<(String, usize, usize)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("the output directory")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .collect();
    files.sort();
    let mut out = Vec::new();
    for path in files {
        let name = path
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into());
        // `flexible` lets the reader return rows of any width, so that the test, not the
        // reader, reports the first row that differs from the header.
        let mut reader = csv::ReaderBuilder::new()
            .flexible(true)
            .from_path(&path)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let width = reader
            .headers()
            .unwrap_or_else(|e| panic!("{name}: header: {e}"))
            .len();
        assert!(width >= 2, "{name}: header of {width} field(s)");
        let mut rows = 0;
        for (i, record) in reader.records().enumerate() {
            let record = record.unwrap_or_else(|e| panic!("{name}: row {}: {e}", i + 2));
            assert_eq!(
                record.len(),
                width,
                "{name}: line {} has {} fields under a {width}-field header: {record:?}",
                i + 2,
                record.len()
            );
            rows += 1;
        }
        assert!(rows > 0, "{name}: no rows");
        out.push((name, width, rows));
    }
    out
}

#[test]
fn the_quick_main_job_passes_and_writes_well_formed_csv() {
    let out = std::env::temp_dir().join(format!("interfacial-scenes-job-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let args = ["--quick", "--out", &out.display().to_string()].map(String::from);
    let opts = job::Options::parse(args).expect("the arguments");
    assert_eq!(
        job::run(&opts),
        0,
        "the quick main job failed (its output is above)"
    );
    let files = read_all_csv(&out);
    let names: Vec<&str> = files.iter().map(|(n, _, _)| n.as_str()).collect();
    // The files the docs list, the stability maps (classes with commas) among them.
    for expected in [
        "checks.csv",
        "findings.csv",
        "F6-map-1.csv",
        "F6-map-2.csv",
        "F6-map-3.csv",
        "F4-map-1.csv",
        "F6-work-precision.csv",
        "F7-belt.csv",
        "P1-work-precision.csv",
    ] {
        assert!(
            names.contains(&expected),
            "{expected} not written: {names:?}"
        );
    }
    // The test reads what it should: a map row with a comma inside a quoted class.
    let map = std::fs::read_to_string(out.join("F6-map-1.csv")).expect("F6-map-1.csv");
    assert!(
        map.contains("\"stable, inaccurate\""),
        "F6-map-1.csv: no quoted class"
    );
    let _ = std::fs::remove_dir_all(&out);
}
