//! docs/architecture.md is the map of the code: every source file under `src/` is named there
//! (by its file name, or by its folder for the files of a law's own folder), so a new file
//! without a place on the map fails this test.

use std::path::Path;

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("read src") {
        let path = entry.expect("dir entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn every_source_file_is_on_the_map() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let map = std::fs::read_to_string(root.join("docs/architecture.md")).expect("read map");
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
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
