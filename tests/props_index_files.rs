//! `PROPS` by name in the C and Fortran harnesses: `c_tests/props_index.h` (0-based offsets into
//! a C `props[]` array) and `fortran_tests/props_index.inc` (1-based `PROPS(i)` indices, an
//! INCLUDE file valid in fixed and free form) are rendered from the layouts' schema
//! (`interfacial::props::schema`) of law 1 (`COULOMB`, with its steady-transport variant) and
//! law 2 (`ADHESIVE`). The committed files must be exactly what the schema renders;
//! `INTERFACIAL_BLESS=1 cargo test --test props_index_files` rewrites them. Test-only: they are
//! not installed (the public header has no `PROPS` layout).

use std::collections::HashSet;
use std::path::Path;

use interfacial::props::schema::{Entry, Layout};
use interfacial::props::{ADHESIVE, COULOMB, RATE_STATE};

/// The layouts, under the word that names them in the generated identifiers.
fn layouts() -> [(&'static str, &'static Layout); 3] {
    [
        ("COULOMB", &COULOMB),
        ("ADHESIVE", &ADHESIVE),
        ("RATE_STATE", &RATE_STATE),
    ]
}

/// Every entry of a layout with its own index, then the entries its variants give another
/// meaning (law 1's steady transport reads `PROPS(14..16)` as ω, the axis, the γ̇_crit variant).
fn named_entries(layout: &'static Layout) -> Vec<&'static Entry> {
    let mut all: Vec<&Entry> = layout.entries.iter().collect();
    for variant in layout.variants {
        all.extend(variant.entries.iter());
    }
    all
}

/// `coeffStatic` → `COEFFSTATIC`, `tau_max` → `TAU_MAX`.
fn upper(key: &str) -> String {
    key.to_ascii_uppercase()
}

fn c_header() -> String {
    let mut s = String::from(
        "/* props_index.h -- PROPS entries by name for the C harnesses, generated from src/props by\n \
         * `INTERFACIAL_BLESS=1 cargo test --test props_index_files`: do not edit.\n \
         * IFLP_<LAW>_<KEY> is the 0-based offset in a C array of PROPS(i) = props[i - 1];\n \
         * IFLP_<LAW>_NPROPS the length of the whole layout; IFLP_LAW_<LAW> the law code, the\n \
         * value of PROPS(1). The twin of fortran_tests/props_index.inc. */\n\
         #ifndef INTERFACIAL_PROPS_INDEX_H\n#define INTERFACIAL_PROPS_INDEX_H\n",
    );
    render(
        &mut s,
        |law, layout| {
            format!(
                "\n/* law {}: the {} */\n#define IFLP_LAW_{law} {}\n#define IFLP_{law}_NPROPS {}\n",
                layout.code,
                layout.law,
                layout.code,
                layout.entries.len()
            )
        },
        |law, e| {
            format!(
                "#define IFLP_{law}_{} {} /* PROPS({}): {} */\n",
                upper(e.key),
                e.index - 1,
                e.index,
                e.meaning.replace("*/", "* /")
            )
        },
    );
    s.push_str("\n#endif\n");
    s
}

fn fortran_include() -> String {
    let mut s = String::from(
        "! props_index.inc -- PROPS entries by name for the Fortran harnesses,\n\
         ! generated from src/props by\n\
         !   INTERFACIAL_BLESS=1 cargo test --test props_index_files\n\
         ! Do not edit. KP<law>_<KEY> is the index i of PROPS(i) (from 1);\n\
         ! KP<law>_N the length of the whole layout; LAW_<LAW> the law code,\n\
         ! the value of PROPS(1). Valid in fixed and free form. The twin of\n\
         ! c_tests/props_index.h.\n",
    );
    render(
        &mut s,
        |law, layout| {
            format!(
                "! law {}: the {}\n      INTEGER, PARAMETER :: LAW_{law} = {}\n      \
                 INTEGER, PARAMETER :: KP{}_N = {}\n",
                layout.code,
                layout.law,
                layout.code,
                law_letter(law),
                layout.entries.len()
            )
        },
        |law, e| {
            format!(
                "      INTEGER, PARAMETER :: KP{}_{} = {}\n",
                law_letter(law),
                upper(e.key),
                e.index
            )
        },
    );
    s
}

/// Appends, for each law, the lines `law_lines` writes for the law itself (its code, the length
/// of its layout) and one line `entry_line` per named entry: the body both files share.
fn render(
    s: &mut String,
    law_lines: impl Fn(&str, &Layout) -> String,
    entry_line: impl Fn(&str, &Entry) -> String,
) {
    for (law, layout) in layouts() {
        s.push_str(&law_lines(law, layout));
        for e in named_entries(layout) {
            s.push_str(&entry_line(law, e));
        }
    }
}

/// One letter per law in the Fortran names (they must stay within 31 characters): C, A, R.
fn law_letter(law: &str) -> &'static str {
    match law {
        "COULOMB" => "C",
        "ADHESIVE" => "A",
        "RATE_STATE" => "R",
        other => panic!("no Fortran letter for {other}"),
    }
}

/// The committed file at `rel` against `rendered`: rewritten under INTERFACIAL_BLESS, else an
/// error naming the file and the command when they differ.
fn check(rel: &str, rendered: &str) -> Result<(), String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    if std::env::var_os("INTERFACIAL_BLESS").is_some() {
        std::fs::write(&path, rendered).map_err(|e| format!("write {rel}: {e}"))?;
        return Ok(());
    }
    let on_disk = std::fs::read_to_string(&path).map_err(|e| format!("read {rel}: {e}"))?;
    if on_disk == rendered {
        Ok(())
    } else {
        Err(format!(
            "{rel} differs from the PROPS schema; regenerate with:\n    \
             INTERFACIAL_BLESS=1 cargo test --test props_index_files"
        ))
    }
}

#[test]
fn props_index_files_are_up_to_date() {
    check("c_tests/props_index.h", &c_header()).unwrap();
    check("fortran_tests/props_index.inc", &fortran_include()).unwrap();
}

/// The check can fail: a committed file one character away from the schema is caught.
#[test]
fn a_stale_index_file_is_caught() {
    if std::env::var_os("INTERFACIAL_BLESS").is_some() {
        return;
    }
    let rendered = c_header().replacen("IFLP_COULOMB_MU 1", "IFLP_COULOMB_MU 2", 1);
    assert_ne!(rendered, c_header(), "the mutation must change the text");
    let err = check("c_tests/props_index.h", &rendered).unwrap_err();
    assert!(
        err.contains("INTERFACIAL_BLESS=1 cargo test --test props_index_files"),
        "{err}"
    );
}

/// The names are unique per language, valid identifiers, and the Fortran lines fit fixed form
/// (72 columns, statements from column 7, names within 31 characters).
#[test]
fn generated_names_are_unique_and_fit_both_languages() {
    let c = c_header();
    let mut seen = HashSet::new();
    for line in c.lines().filter(|l| l.starts_with("#define IFLP")) {
        let name = line.split_whitespace().nth(1).unwrap();
        assert!(seen.insert(name.to_string()), "C name {name} twice");
        assert!(
            name.chars()
                .all(|ch| ch.is_ascii_uppercase() || ch.is_ascii_digit() || ch == '_')
        );
    }
    let f = fortran_include();
    let mut seen = HashSet::new();
    for line in f.lines() {
        assert!(line.len() <= 72, "past column 72: {line}");
        if line.starts_with('!') {
            continue;
        }
        assert!(line.starts_with("      INTEGER, PARAMETER :: "), "{line}");
        let name = line.split_whitespace().nth(3).unwrap();
        assert!(name.len() <= 31, "Fortran name over 31 characters: {name}");
        assert!(seen.insert(name.to_string()), "Fortran name {name} twice");
    }
    // The indices agree with the layout itself (PROPS(2) of law 1 is μ, of law 2 coeff).
    assert_eq!(COULOMB.entries[1].key, "mu");
    assert!(c.contains("#define IFLP_COULOMB_MU 1 "));
    assert!(f.contains("KPC_MU = 2\n"));
    assert_eq!(ADHESIVE.entries[1].key, "coeff");
    assert!(f.contains("KPA_COEFF = 2\n"));
}
