//! The law interface keeps a law in few files: the map's worked example (docs/architecture.md,
//! "Checklist: add a law") says law 3 takes four files outside tests, docs and harnesses, and
//! that the shell (`src/abi/`) reads no `PROPS` entry itself. These tests fail when that stops
//! being true.

use std::fs;
use std::path::{Path, PathBuf};

#[path = "common/source_tree.rs"]
mod source_tree;
use source_tree::{code_only, rust_files};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Files under src/ whose code (comments aside) names rate-and-state friction.
fn files_naming_law_3() -> Vec<String> {
    let files = rust_files(&src());
    let mut naming: Vec<String> = files
        .iter()
        .filter(|p| {
            let code = code_only(&fs::read_to_string(p).expect("readable"));
            ["rate_state", "RateState", "RATE_STATE"]
                .iter()
                .any(|w| code.contains(w))
        })
        .map(|p| {
            p.strip_prefix(src())
                .expect("under src")
                .to_string_lossy()
                .replace('\\', "/")
        })
        .collect();
    naming.sort();
    naming
}

#[test]
fn law_3_lives_in_the_four_files_the_map_names() {
    assert_eq!(
        files_naming_law_3(),
        [
            "laws/mod.rs",
            "laws/rate_state.rs",
            "props.rs",
            "props/rate_state.rs"
        ],
        "docs/architecture.md's worked example names these four files"
    );
}

/// The shell asks the props layer for the law; it never indexes `PROPS` or compares a law
/// code. The `fric_` plain and decay-lean fast paths hand `PROPS` whole to the props layer too.
#[test]
fn the_shell_reads_no_props_entry() {
    let files = rust_files(&src().join("abi"));
    assert!(files.len() >= 10, "src/abi has its entry points");
    for p in files {
        let code = code_only(&fs::read_to_string(&p).expect("readable"));
        for (n, line) in code.lines().enumerate() {
            let compact: String = line.chars().filter(|c| !c.is_whitespace()).collect();
            for banned in [
                "props[",
                "props.first()",
                "props.get(",
                "LAW_COULOMB",
                "LAW_ADHESIVE",
                "LAW_RATE_STATE",
            ] {
                assert!(
                    !compact.contains(banned),
                    "{}:{}: `{banned}` in the shell: ask the props layer instead\n{line}",
                    p.display(),
                    n + 1
                );
            }
        }
    }
}

/// The checker itself: a comment is not code, a use in code is.
#[test]
fn the_checker_sees_code_not_comments() {
    assert!(!code_only("// RateState in a comment\n/// and rate_state").contains("RateState"));
    assert!(code_only("let x = props[7]; // PROPS(8)").contains("props[7]"));
}
