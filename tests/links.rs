//! The repository documents itself: every relative link and path in README, the docs and the
//! source comments must point at a file inside this repository that exists. A clone with
//! nothing beside it has no design notes or source documents next to it, so a reference that
//! climbs out of the checkout (`../../somewhere`) or names a file that is not here is a defect.
//!
//! What is scanned: the top-level `*.md` and build files, everything under `docs/` (but
//! charts), and every file under `src/`, `examples/`, `c_tests/`, `fortran_tests/`,
//! `include/`, `tests/`, `macros/`, `bench/`, `mpi_tests/`, `scripts/`, `cmake/`, `fortran/`,
//! `.ci/` and the fuzz targets' sources (comments and strings alike; not this file, whose
//! examples of bad references are not references). What is checked, per file:
//!
//! 1. markdown links `[text](target)` in `.md` files: a target that is not a URL must name an
//!    existing file or folder, resolved from the file's folder, inside the repository; an
//!    `#anchor` into a markdown file must be one of its headings (GitHub's slugs);
//! 2. bare paths that start with `../`: resolved from the file's folder, inside the
//!    repository, existing (the few that name another project's tree on purpose are listed in
//!    `ELSEWHERE_ON_PURPOSE`, and each listed one must still occur);
//! 3. other bare paths — two or more components and a file extension of the project's
//!    (`docs/fric.md`, `abi/batch.rs`), or a folder (`src/laws/`): they must exist from the
//!    repository's root or from the file's folder, or be the tail of a path in the repository
//!    (comments shorten `src/abi/batch.rs` to `abi/batch.rs`).
//!
//! Paths under `target/` and `build/` (made by the build), under `lib/`, `share/` and
//! `include/` of an install prefix, and paths with wildcards or placeholders are not
//! references to check.

use std::collections::BTreeSet;
use std::path::{Component, Path, PathBuf};

/// Paths that name another project's files on purpose: (file, path, why).
const ELSEWHERE_ON_PURPOSE: &[(&str, &str, &str)] = &[
    (
        "docs/install.md",
        "../../../SPOOLES.2.2/spooles.a",
        "CalculiX's own Makefile line, in the user's CalculiX tree",
    ),
    (
        "docs/install.md",
        "../../../ARPACK/libarpack_INTEL.a",
        "CalculiX's own Makefile line, in the user's CalculiX tree",
    ),
];

/// Extensions a path token must end with to count as a path (prose has many slashes).
const EXTENSIONS: &[&str] = &[
    "md", "rs", "c", "h", "f", "f90", "toml", "txt", "sh", "cmake", "in", "svg", "csv", "inc",
    "json", "py", "supp", "dict",
];

/// Folders of an install prefix or of the build, named by the docs but not in the repository.
/// (`fuzz/artifacts/` and `fuzz/corpus/` are written by `cargo fuzz`.)
const NOT_IN_THE_REPOSITORY: &[&str] = &[
    "target/",
    "build/",
    "build-consumers/",
    "build-asan/",
    "lib/",
    "share/",
    "include/",
    "fuzz/artifacts/",
    "fuzz/corpus/",
];

/// Every file and folder of the repository (not `target/`, `build/`, `.git/`), by their paths
/// from the root with `/` separators, folders ending in `/`.
struct Index {
    files: BTreeSet<String>,
    dirs: BTreeSet<String>,
}

impl Index {
    fn new(root: &Path) -> Index {
        fn walk(root: &Path, dir: &Path, index: &mut Index) {
            let Ok(entries) = std::fs::read_dir(dir) else {
                return;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                let Ok(rel) = path.strip_prefix(root) else {
                    continue;
                };
                let rel = rel.to_string_lossy().replace('\\', "/");
                if path.is_dir() {
                    if matches!(rel.as_str(), "target" | "build" | ".git") {
                        continue;
                    }
                    index.dirs.insert(format!("{rel}/"));
                    walk(root, &path, index);
                } else {
                    index.files.insert(rel);
                }
            }
        }
        let mut index = Index {
            files: BTreeSet::new(),
            dirs: BTreeSet::new(),
        };
        walk(root, root, &mut index);
        index
    }

    /// `path` (a file, or a folder ending in `/`) is in the repository, or is the tail of a
    /// path that is.
    fn has(&self, path: &str) -> bool {
        let set = if path.ends_with('/') {
            &self.dirs
        } else {
            &self.files
        };
        let tail = format!("/{path}");
        set.contains(path) || set.iter().any(|p| p.ends_with(&tail))
    }
}

/// One defect: the file, what kind of reference, the reference, why.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
struct Defect {
    file: String,
    kind: &'static str,
    target: String,
    why: String,
}

/// `path` normalised lexically (`a/./b/../c` → `a/c`); `None` when it climbs above its start.
fn normalise(path: &Path) -> Option<PathBuf> {
    let mut out: Vec<String> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop()?;
            }
            Component::Normal(s) => out.push(s.to_string_lossy().into_owned()),
            Component::RootDir | Component::Prefix(_) => return None,
        }
    }
    Some(out.iter().collect())
}

/// GitHub's anchor of a heading: lower case, punctuation other than `-` and `_` dropped,
/// spaces to `-`.
fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| {
            if c == ' ' {
                Some('-')
            } else if c.is_alphanumeric() || c == '-' || c == '_' {
                Some(c)
            } else {
                None
            }
        })
        .collect()
}

/// The anchors of a markdown text (headings outside fenced code, duplicates numbered).
fn anchors(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced || !line.starts_with('#') {
            continue;
        }
        let heading = line.trim_start_matches('#');
        if !heading.starts_with(' ') {
            continue;
        }
        let base = slug(heading);
        let mut name = base.clone();
        let mut n = 0;
        while out.contains(&name) {
            n += 1;
            name = format!("{base}-{n}");
        }
        out.insert(name);
    }
    out
}

/// The markdown link targets of a text: `](target)`, up to the first space or `)`.
fn markdown_links(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("](") {
        rest = &rest[i + 2..];
        let end = rest
            .find(|c: char| c == ')' || c.is_whitespace())
            .unwrap_or(rest.len());
        out.push(rest[..end].to_string());
    }
    out
}

/// Path-like tokens: runs of `[A-Za-z0-9_./-]` with a `/` that start with `../`, or have two or
/// more components and end in a known extension, or name a folder (`a/b/`, starting with a
/// letter); not part of a URL, an absolute path, a variable or a placeholder.
fn path_tokens(text: &str) -> Vec<String> {
    let allowed = |c: char| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '/' | '-');
    let mut out = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if !allowed(chars[i]) {
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len() && allowed(chars[i]) {
            i += 1;
        }
        let before = if start > 0 { chars[start - 1] } else { ' ' };
        let after = if i < chars.len() { chars[i] } else { ' ' };
        let mut token: String = chars[start..i].iter().collect();
        // A sentence may end right after a path.
        while token.ends_with('.') {
            token.pop();
        }
        if matches!(before, ':' | '~' | '$' | '<' | '{' | '@' | '%' | '*')
            || matches!(after, '*' | '{' | '<' | '$' | '}' | '>')
            || token.starts_with('/')
            || token.starts_with('-')
            // One component (`./name` too: a file the program writes where it runs).
            || !token
                .trim_start_matches("./")
                .trim_end_matches('/')
                .contains('/')
            || token.contains("//")
        {
            continue;
        }
        let is_path = if token.starts_with("../") {
            true
        } else if token.ends_with('/') {
            token.starts_with(|c: char| c.is_ascii_alphabetic())
        } else {
            token
                .rsplit_once('/')
                .and_then(|(_, name)| name.rsplit_once('.'))
                .is_some_and(|(_, ext)| EXTENSIONS.contains(&ext))
        };
        if is_path {
            out.push(token);
        }
    }
    out
}

/// Checks one file's text; `rel` is its path from the repository root.
fn check_text(root: &Path, index: &Index, rel: &Path, text: &str, defects: &mut Vec<Defect>) {
    let dir = rel.parent().unwrap_or(Path::new(""));
    let file = rel.to_string_lossy().into_owned();
    let mut report = |kind: &'static str, target: &str, why: &str| {
        defects.push(Defect {
            file: file.clone(),
            kind,
            target: target.to_string(),
            why: why.to_string(),
        });
    };
    let is_markdown = rel.extension().is_some_and(|e| e == "md");

    // The targets of markdown links, checked as links (not again as bare paths).
    let mut linked = BTreeSet::new();
    if is_markdown {
        for target in markdown_links(text) {
            linked.insert(target.split('#').next().unwrap_or("").to_string());
            if target.is_empty()
                || target.contains("://")
                || target.starts_with("mailto:")
                || target.starts_with('<')
            {
                continue;
            }
            let (path_part, anchor) = match target.split_once('#') {
                Some((p, a)) => (p, Some(a)),
                None => (target.as_str(), None),
            };
            let resolved = if path_part.is_empty() {
                Some(rel.to_path_buf())
            } else {
                normalise(&dir.join(path_part))
            };
            let Some(resolved) = resolved else {
                report("link", &target, "leaves the repository");
                continue;
            };
            let full = root.join(&resolved);
            if !full.exists() {
                report("link", &target, "no such file in the repository");
                continue;
            }
            if let Some(anchor) = anchor
                && resolved.extension().is_some_and(|e| e == "md")
            {
                let target_text = std::fs::read_to_string(&full).unwrap_or_default();
                if !anchors(&target_text).contains(anchor) {
                    report("anchor", &target, "no heading with this anchor");
                }
            }
        }
    }

    for token in path_tokens(text) {
        if linked.contains(&token) {
            continue;
        }
        if token.starts_with("../") {
            if ELSEWHERE_ON_PURPOSE
                .iter()
                .any(|(f, p, _)| *f == file && *p == token)
            {
                continue;
            }
            match normalise(&dir.join(&token)) {
                None => report("path", &token, "leaves the repository"),
                Some(r) if !root.join(&r).exists() => {
                    report("path", &token, "no such file in the repository");
                }
                Some(_) => {}
            }
            continue;
        }
        if NOT_IN_THE_REPOSITORY.iter().any(|f| token.starts_with(f)) {
            continue;
        }
        let from_dir = normalise(&dir.join(&token)).is_some_and(|r| root.join(r).exists());
        if !(from_dir || index.has(&token)) {
            report("path", &token, "no such file in the repository");
        }
    }
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            // Made by the build, not part of the repository.
            if path
                .file_name()
                .is_some_and(|n| n == "target" || n == "build")
            {
                continue;
            }
            collect(&path, out);
        } else {
            out.push(path);
        }
    }
}

/// The files the test reads, relative to the root.
fn scanned_files(root: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(root)
        .expect("read the repository root")
        .flatten()
    {
        let path = entry.path();
        if path.is_file() && path.extension().is_some_and(|e| e == "md") {
            files.push(path);
        }
    }
    for file in ["CMakeLists.txt", "Cargo.toml", "build.rs", "cbindgen.toml"] {
        files.push(root.join(file));
    }
    for dir in [
        "docs",
        "src",
        "examples",
        "c_tests",
        "fortran_tests",
        "include",
        "tests",
        "macros",
        "bench",
        "mpi_tests",
        "scripts",
        "cmake",
        "fortran",
        ".ci",
        "fuzz/src",
        "fuzz/fuzz_targets",
    ] {
        collect(&root.join(dir), &mut files);
    }
    let mut rel: Vec<PathBuf> = files
        .into_iter()
        .filter(|p| {
            !p.extension()
                .is_some_and(|e| e == "svg" || e == "csv" || e == "png")
        })
        .filter_map(|p| p.strip_prefix(root).ok().map(Path::to_path_buf))
        // This file's own examples of bad references are not references.
        .filter(|p| p != Path::new("tests/links.rs"))
        .collect();
    rel.sort();
    rel
}

#[test]
fn every_relative_link_and_path_stays_in_the_repository_and_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = scanned_files(root);
    let index = Index::new(root);
    assert!(files.len() > 100, "scanned only {} files", files.len());
    let mut defects = Vec::new();
    let mut texts = Vec::new();
    for rel in &files {
        // Binary files (none expected) are skipped rather than misread.
        let Ok(text) = std::fs::read_to_string(root.join(rel)) else {
            continue;
        };
        check_text(root, &index, rel, &text, &mut defects);
        texts.push((rel.to_string_lossy().into_owned(), text));
    }
    let listing: Vec<String> = defects
        .iter()
        .map(|d| format!("{}: {} `{}`: {}", d.file, d.kind, d.target, d.why))
        .collect();
    assert!(
        defects.is_empty(),
        "{} reference(s) leave the repository or name a missing file:\n{}",
        defects.len(),
        listing.join("\n")
    );
    // A path kept on the list after its text went away would hide the next one.
    for (file, path, why) in ELSEWHERE_ON_PURPOSE {
        let found = texts.iter().any(|(f, t)| f == file && t.contains(path));
        assert!(
            found,
            "ELSEWHERE_ON_PURPOSE lists `{path}` in {file} ({why}), which no longer has it"
        );
    }
}

/// The checker itself: each kind of bad reference is reported, and good ones are not.
#[test]
fn the_checker_reports_every_kind_of_bad_reference() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let index = Index::new(root);
    let cases: &[(&str, &str, &[&str])] = &[
        // A markdown link out of the checkout, and one to a missing file.
        (
            "docs/x.md",
            "See [the notes](../../notes/scenes.md) and [this](missing-page.md).",
            &["../../notes/scenes.md", "missing-page.md"],
        ),
        // A link to an existing page but a heading it does not have.
        (
            "docs/x.md",
            "[props](props.md#no-such-heading)",
            &["props.md#no-such-heading"],
        ),
        // A bare `../` path in a C comment that climbs out.
        (
            "c_tests/x.c",
            "/* closed forms of ../../notes/design/scenes.md */",
            &["../../notes/design/scenes.md"],
        ),
        // A root-relative path in a Rust comment to a file that is not there.
        (
            "src/x.rs",
            "//! follows `docs/no-such-page.md`, section 2",
            &["docs/no-such-page.md"],
        ),
        // A markdown file named through a folder that is not in the repository.
        (
            "fortran_tests/x.f",
            "C     closed forms (notes/design/scenes.md, F1)",
            &["notes/design/scenes.md"],
        ),
        // A folder and a text file that are not in the repository, named in a Rust comment.
        (
            "src/x.rs",
            "//! follows the documents in `notes/sources/` (`notes/sources/000.txt`)",
            &["notes/sources/", "notes/sources/000.txt"],
        ),
        // Good references: none reported.
        (
            "docs/x.md",
            "[props](props.md#law-1-coulomb-friction-props1--1), [code](../src/lib.rs), \
             `docs/fric.md`, ../README.md, https://example.org/a/b.md, target/scenes/x.csv, \
             abi/batch.rs (the tail of src/abi/batch.rs), src/laws/, lib/pkgconfig/interfacial.pc",
            &[],
        ),
    ];
    for (file, text, expected) in cases {
        let mut defects = Vec::new();
        check_text(root, &index, Path::new(file), text, &mut defects);
        let got: Vec<&str> = defects.iter().map(|d| d.target.as_str()).collect();
        assert_eq!(&got, expected, "{file}: {text}");
    }
}
