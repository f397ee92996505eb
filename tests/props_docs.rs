//! The `PROPS` tables of docs/props.md are rendered from the layouts' schema
//! (`interfacial::props::schema`): the committed text between the markers must be exactly what
//! the schema renders. `INTERFACIAL_BLESS=1 cargo test --test props_docs` rewrites it.

use std::path::Path;

use interfacial::props::schema::Layout;
use interfacial::props::{ADHESIVE, COULOMB, RATE_STATE};

/// The marker pair around the table of `law` in docs/props.md.
fn markers(law: &str) -> (String, String) {
    (
        format!(
            "<!-- BEGIN PROPS TABLE {law}: generated from src/props by `INTERFACIAL_BLESS=1 cargo test --test props_docs`, do not edit -->\n"
        ),
        format!("<!-- END PROPS TABLE {law} -->\n"),
    )
}

/// `text` with the region between the markers of `law` replaced by `table`, or an error when
/// the markers are missing.
fn with_table(text: &str, law: &str, table: &str) -> Result<String, String> {
    let (begin, end) = markers(law);
    let start = text
        .find(&begin)
        .ok_or_else(|| format!("docs/props.md has no line {begin:?}"))?
        + begin.len();
    let stop = start
        + text[start..]
            .find(&end)
            .ok_or_else(|| format!("docs/props.md has no line {end:?} after the begin marker"))?;
    Ok(format!("{}{table}{}", &text[..start], &text[stop..]))
}

fn check(layouts: &[(&str, &Layout)]) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/props.md");
    let on_disk = std::fs::read_to_string(&path).expect("read docs/props.md");
    let mut rendered = on_disk.clone();
    for (law, layout) in layouts {
        rendered = with_table(&rendered, law, &layout.markdown_table()).unwrap();
    }
    if std::env::var_os("INTERFACIAL_BLESS").is_some() {
        std::fs::write(&path, &rendered).expect("write docs/props.md");
        return;
    }
    assert!(
        on_disk == rendered,
        "a PROPS table in docs/props.md differs from the schema; regenerate with:\n    \
         INTERFACIAL_BLESS=1 cargo test --test props_docs"
    );
}

#[test]
fn props_tables_are_up_to_date() {
    check(&[
        ("law 1", &COULOMB),
        ("law 2", &ADHESIVE),
        ("law 3", &RATE_STATE),
    ]);
}

/// The check itself can fail: a table that differs from the schema by one character is caught,
/// and missing markers are an error.
#[test]
fn a_stale_table_is_caught() {
    let (begin, end) = markers("law 2");
    let table = ADHESIVE.markdown_table();
    let fresh = format!("intro\n{begin}{table}{end}outro\n");
    assert_eq!(with_table(&fresh, "law 2", &table).unwrap(), fresh);
    let stale = fresh.replacen("finite and ≥ 0", "finite and > 0", 1);
    assert_ne!(with_table(&stale, "law 2", &table).unwrap(), stale);
    assert!(with_table("no markers\n", "law 2", &table).is_err());
}

/// Spot checks of the rendering against the layout's meaning (not against its own output):
/// the law code's row, μ_s's default and rule, f's default ½ and range.
#[test]
fn the_table_says_what_the_schema_means() {
    let table = ADHESIVE.markdown_table();
    let row = |i: usize| {
        table
            .lines()
            .find(|l| l.starts_with(&format!("| `PROPS({i})` |")))
            .unwrap_or_else(|| panic!("no row for PROPS({i})"))
            .to_string()
    };
    assert_eq!(table.lines().count(), 2 + 13);
    assert!(row(1).ends_with("| exactly 2 |"), "{}", row(1));
    assert!(row(3).contains("none: μ_s = μ_d"), "{}", row(3));
    assert!(
        row(3).ends_with("| finite (≤ 0 for none); when > 0, ≥ `coeff` |"),
        "{}",
        row(3)
    );
    assert!(row(9).contains("| 0.005 |"), "{}", row(9));
    assert!(row(13).contains("| 0.5 | in (0, 1] |"), "{}", row(13));
}

/// Law 1's table against the layout's meaning: one row per entry plus one per entry that
/// steady transport (`PROPS(7) = 3`) or the constant stick stiffness (`PROPS(7) = 4`)
/// redefines, each saying when it holds; the switches' codes
/// and the rules between entries are in the "valid" column.
#[test]
fn the_law_1_table_says_what_the_schema_means() {
    let table = COULOMB.markdown_table();
    let row = |start: &str| {
        table
            .lines()
            .find(|l| l.starts_with(start))
            .unwrap_or_else(|| panic!("no row starting {start}"))
            .to_string()
    };
    assert_eq!(table.lines().count(), 2 + 20 + 3 + 1);
    assert!(row("| `PROPS(1)` |").ends_with("| exactly 1 |"));
    assert!(row("| `PROPS(6)` |").contains("| 0.005 |"));
    assert!(row("| `PROPS(7)` |").ends_with("| 0, 1, 2, 3 or 4 |"));
    assert!(row("| `PROPS(5)` (`PROPS(7) = 4`) |").contains("| k_s |"));
    assert!(row("| `PROPS(5)` (`PROPS(7)` ≠ 4) |").contains("| γ_crit |"));
    assert!(row("| `PROPS(14)` (`PROPS(7) = 3`) |").contains("| ω |"));
    assert!(row("| `PROPS(14)` (`PROPS(7)` ≠ 3) |").ends_with("| in [−1/2, 0] |"));
    assert!(row("| `PROPS(19)` |").contains("in [0, 1); 0 when `PROPS(17) = 0`"));
    assert!(row("| `PROPS(9)` |").contains("0 when `PROPS(8) = 0`"));
}
