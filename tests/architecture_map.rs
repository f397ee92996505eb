//! docs/architecture.md is the map of the code: every source file under `src/` is named there
//! (by its file name, or by its folder for the files of a law's own folder), every other crate
//! of the workspace by its folder and every script under `scripts/` by its file name, so a new
//! file without a place on the map fails this test.

use std::path::Path;

#[path = "common/source_tree.rs"]
mod source_tree;
use source_tree::rust_files;

#[test]
fn every_source_file_is_on_the_map() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let map = std::fs::read_to_string(root.join("docs/architecture.md")).expect("read map");
    let files = rust_files(&root.join("src"));
    assert!(files.len() > 30, "found only {} files", files.len());
    let mut missing = Vec::new();
    for path in files {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let folder = path
            .parent()
            .unwrap()
            .file_name()
            .unwrap()
            .to_string_lossy();
        // `mod.rs` and `lib.rs` are the modules' own roots, named by their folder.
        let named = name == "mod.rs"
            || name == "lib.rs"
            || map.contains(&format!("`{name}`"))
            || map.contains(&format!("src/{name}`"))
            || map.contains(&format!("/{name}`"))
            || map.contains(&format!("`{folder}/`"));
        if !named {
            missing.push(path.strip_prefix(root).unwrap().display().to_string());
        }
    }
    assert!(
        missing.is_empty(),
        "not named in docs/architecture.md: {missing:?}"
    );
}

#[test]
fn every_workspace_crate_and_script_is_on_the_map() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let map = std::fs::read_to_string(root.join("docs/architecture.md")).expect("read map");
    let manifest = std::fs::read_to_string(root.join("Cargo.toml")).expect("read Cargo.toml");
    let members = manifest
        .lines()
        .find_map(|l| l.trim().strip_prefix("members = "))
        .expect("Cargo.toml names the workspace members");
    let mut missing = Vec::new();
    let mut crates = 0;
    for member in members
        .trim_matches(|c| c == '[' || c == ']')
        .split(',')
        .map(|m| m.trim().trim_matches('"'))
        .filter(|m| !m.is_empty() && *m != ".")
    {
        crates += 1;
        if !map.contains(&format!("`{member}/`")) {
            missing.push(format!("{member}/"));
        }
    }
    assert!(
        crates > 0,
        "no workspace member besides the library in {members}"
    );
    let mut scripts = 0;
    for entry in std::fs::read_dir(root.join("scripts")).expect("read scripts") {
        let name = entry
            .expect("dir entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        scripts += 1;
        if !map.contains(&format!("scripts/{name}`")) {
            missing.push(format!("scripts/{name}"));
        }
    }
    assert!(scripts > 5, "found only {scripts} scripts");
    assert!(
        missing.is_empty(),
        "not named in docs/architecture.md: {missing:?}"
    );
}
