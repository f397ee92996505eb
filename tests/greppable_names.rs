//! Every name the library defines can be found by searching the source for it (issue 25: a
//! macro that makes up a function's name hides it from grep, ctags and a reader).
//!
//! - Every function `include/interfacial.h` declares is written `fn NAME` in `src/`, outside
//!   comments and string literals.
//! - No `macro_rules!` body in `src/` defines an item (`fn`, `struct`, `enum`, `union`, `const`,
//!   `static`, `type`, `trait`, `mod`) under a literal name: each defined name is a `$parameter`,
//!   so the name is written at the invocation. The proc-macro attributes' expansions (the
//!   `quote!` bodies of `macros/src/lib.rs`) likewise define only names they are given
//!   (`#name`).
//! - The names the attributes are given are written at each invocation as their definitions
//!   read: `struct FricArgs as args`, `unsafe extern "C" fn fric_general { … }`.
//!
//! So every function and method of the Rust API and of the header has its name in the text
//! where it is defined or where the macro that defines it is invoked. The checker is unit-tested
//! below on small strings, including ones that must fail.

use std::path::Path;

#[path = "common/source_tree.rs"]
mod source_tree;
use source_tree::{code_only, rust_files};

/// Fails, saying `what` and listing them, when any were `found`.
fn assert_none<T: std::fmt::Debug>(found: &[T], what: &str) {
    assert!(found.is_empty(), "{what}: {found:?}");
}

/// Keywords that define a named item.
const ITEM_KEYWORDS: [&str; 9] = [
    "fn", "struct", "enum", "union", "const", "static", "type", "trait", "mod",
];

/// Rust keywords that may follow an item keyword without being the item's name (`const fn`,
/// `unsafe fn`, `const unsafe fn`, `static mut`).
const QUALIFIERS: [&str; 7] = ["fn", "unsafe", "extern", "mut", "async", "const", "crate"];

/// The tokens of code: identifiers (with a leading `$` or `#` kept: `$name`, `#name`) and
/// single punctuation characters.
fn tokens(code: &str) -> Vec<String> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        let start = i;
        if matches!(c[i], '$' | '#')
            && c.get(i + 1)
                .is_some_and(|ch| ch.is_alphabetic() || *ch == '_')
        {
            i += 1;
        }
        if c[i].is_alphabetic() || c[i] == '_' {
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push(c[start..i].iter().collect());
        } else {
            if !c[i].is_whitespace() {
                out.push(c[i].to_string());
            }
            i += 1;
        }
    }
    out
}

/// The items `body` (code only) defines under a literal name: `(keyword, name)` for each item
/// keyword followed by a plain identifier. A const generic parameter (`<const N: usize>`, after
/// `<` or `,`) is not an item.
fn literal_item_names(body: &str) -> Vec<(String, String)> {
    let t = tokens(body);
    let mut found = Vec::new();
    for (k, word) in t.iter().enumerate() {
        if !ITEM_KEYWORDS.contains(&word.as_str()) {
            continue;
        }
        if word == "const" && k > 0 && matches!(t[k - 1].as_str(), "<" | ",") {
            continue;
        }
        let Some(name) = t.get(k + 1) else { continue };
        let plain = name.starts_with(|ch: char| ch.is_alphabetic() || ch == '_');
        if plain && name != "_" && !QUALIFIERS.contains(&name.as_str()) {
            found.push((word.clone(), name.clone()));
        }
    }
    found
}

/// The text between the brace (or parenthesis) that opens at byte `open` of `code` and the one
/// that closes it.
fn delimited(code: &str, open: usize) -> &str {
    let (left, right) = match code.as_bytes()[open] {
        b'{' => (b'{', b'}'),
        b'(' => (b'(', b')'),
        b'[' => (b'[', b']'),
        other => panic!("no opening delimiter at {open}: {:?}", other as char),
    };
    let mut depth = 0;
    for (k, &b) in code.as_bytes()[open..].iter().enumerate() {
        if b == left {
            depth += 1;
        } else if b == right {
            depth -= 1;
            if depth == 0 {
                return &code[open + 1..open + k];
            }
        }
    }
    panic!("unbalanced delimiter at byte {open}")
}

/// The bodies of the invocations of `opener` (`"macro_rules!"`, `"quote!"`) in `code` (code
/// only): for `macro_rules! name { … }`, the text inside the braces, with the macro's name.
fn bodies<'a>(code: &'a str, opener: &str) -> Vec<(String, &'a str)> {
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(at) = code[from..].find(opener) {
        let start = from + at;
        from = start + opener.len();
        let before = code[..start].chars().next_back();
        if before.is_some_and(|ch| ch.is_alphanumeric() || ch == '_') {
            continue;
        }
        let rest = &code[from..];
        let Some(open) = rest.find(['{', '(', '[']) else {
            continue;
        };
        let name = rest[..open].trim().to_string();
        out.push((name, delimited(code, from + open)));
    }
    out
}

/// Every item a `macro_rules!` in `code` defines under a literal name, as
/// `macro NAME: KEYWORD ITEM`.
fn macro_rules_violations(code: &str) -> Vec<String> {
    bodies(code, "macro_rules!")
        .into_iter()
        .flat_map(|(name, body)| {
            literal_item_names(body)
                .into_iter()
                .map(move |(kw, item)| format!("macro {name}: {kw} {item}"))
        })
        .collect()
}

/// The functions a C header declares: each identifier directly followed by `(` outside
/// comments and preprocessor lines (a function pointer's `(*Name)(` is a type, not one).
fn header_functions(header: &str) -> Vec<String> {
    let code: String = code_only(header)
        .lines()
        .filter(|l| !l.trim_start().starts_with('#'))
        .collect::<Vec<_>>()
        .join("\n");
    let c: Vec<char> = code.chars().collect();
    let mut names = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if c[i].is_alphabetic() || c[i] == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            if c.get(i) == Some(&'(') {
                let name: String = c[start..i].iter().collect();
                if !names.contains(&name) {
                    names.push(name);
                }
            }
        } else {
            i += 1;
        }
    }
    names
}

/// Whether `code` (code only) has `fn NAME` (any whitespace between).
fn defines_fn(code: &str, name: &str) -> bool {
    tokens(code)
        .windows(2)
        .any(|w| w[0] == "fn" && w[1] == name)
}

/// Every `.rs` file under `src/`, code only, with its path.
fn src_code() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = rust_files(&root.join("src"));
    assert!(
        files.len() > 30,
        "found only {} files under src/",
        files.len()
    );
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("read a source file");
            (
                p.strip_prefix(root).unwrap().display().to_string(),
                code_only(&text),
            )
        })
        .collect()
}

fn read(path: &str) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(root.join(path)).unwrap_or_else(|e| panic!("read {path}: {e}"))
}

#[test]
fn every_header_function_is_written_fn_name_in_src() {
    let names = header_functions(&read("include/interfacial.h"));
    // The header's entry points are all there (the parse found them, not nothing).
    for expected in [
        "fric_",
        "uinter_",
        "vfric_",
        "ifl_fric_batch",
        "ifl_props_check",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "{expected} not found in {names:?}"
        );
    }
    let code = src_code();
    let missing: Vec<&String> = names
        .iter()
        .filter(|n| !code.iter().any(|(_, c)| defines_fn(c, n)))
        .collect();
    assert_none(
        &missing,
        "declared in include/interfacial.h, never written `fn NAME` in src/",
    );
}

#[test]
fn no_macro_rules_in_src_defines_a_literal_name() {
    let code = src_code();
    let count: usize = code
        .iter()
        .map(|(_, c)| bodies(c, "macro_rules!").len())
        .sum();
    assert!(
        count > 0,
        "no macro_rules! found under src/: the scan reads nothing"
    );
    let violations: Vec<String> = code
        .iter()
        .flat_map(|(path, c)| {
            macro_rules_violations(c)
                .into_iter()
                .map(move |v| format!("{path}: {v}"))
        })
        .collect();
    assert_none(
        &violations,
        "a macro_rules! defines an item whose name is not a $parameter (write the name at the \
         invocation)",
    );
}

#[test]
fn the_attribute_macros_define_only_names_they_are_given() {
    let lib = code_only(&read("macros/src/lib.rs"));
    let lib = &lib[..lib
        .find("mod tests")
        .expect("macros/src/lib.rs has its tests module")];
    let quoted = bodies(lib, "quote!");
    assert!(quoted.len() >= 3, "found {} quote! bodies", quoted.len());
    let literal: Vec<(String, String)> = quoted
        .iter()
        .flat_map(|(_, body)| literal_item_names(body))
        .collect();
    assert_none(
        &literal,
        "the proc-macro expansion defines an item under a literal name",
    );
}

#[test]
fn the_attribute_macros_generated_names_are_written_at_their_invocations() {
    let code = src_code();
    let text = |file: &str| {
        &code
            .iter()
            .find(|(p, _)| p == file)
            .unwrap_or_else(|| panic!("{file} not found"))
            .1
    };
    // (file, attribute, view, twin): each written as its definition reads.
    let cases = [
        (
            "src/abi/fric.rs",
            "with_twin",
            "FricArgs",
            Some("fric_general"),
        ),
        ("src/abi/uinter.rs", "with_view", "UinterArgs", None),
        ("src/abi/fric_coef.rs", "with_view", "CoefArgs", None),
        ("src/abi/vfric.rs", "with_view", "VfricArgs", None),
    ];
    for (file, attribute, view, twin) in cases {
        let invocations = bodies(text(file), &format!("interfacial_macros::{attribute}"));
        assert_eq!(invocations.len(), 1, "{file}: one #[{attribute}]");
        let attr = invocations[0].1;
        let t = tokens(attr);
        assert!(
            t.windows(2).any(|w| w[0] == "struct" && w[1] == view),
            "{file}: `struct {view}` is not written in #[{attribute}(…)]"
        );
        if let Some(twin) = twin {
            assert!(
                defines_fn(attr, twin),
                "{file}: `fn {twin}` is not written in #[{attribute}(…)]"
            );
        }
    }
    // And no other file uses the attributes without a line above.
    let uses = code
        .iter()
        .map(|(_, c)| {
            bodies(c, "interfacial_macros::with_twin").len()
                + bodies(c, "interfacial_macros::with_view").len()
        })
        .sum::<usize>();
    assert_eq!(
        uses,
        cases.len(),
        "an attribute invocation this test does not check"
    );
}

#[cfg(test)]
mod checker {
    use super::*;

    #[test]
    fn comments_and_strings_are_not_code() {
        let code = code_only(
            "// fn a\n/* fn b /* nested */ fn c */ let s = \"fn d\"; let r = r#\"fn \"e\"\"#;\n\
             let q = '\"'; fn f<'a>() {}",
        );
        assert!(!defines_fn(&code, "a") && !defines_fn(&code, "b") && !defines_fn(&code, "c"));
        assert!(!defines_fn(&code, "d") && !defines_fn(&code, "e"));
        assert!(defines_fn(&code, "f"), "{code}");
        assert_eq!(code.lines().count(), 3, "line breaks kept");
    }

    #[test]
    fn a_macro_that_makes_up_a_name_fails_and_one_given_it_passes() {
        let made_up = "macro_rules! setters {\n  ($f:ident) => { pub fn with_hht(mut self) -> Self \
                       { self.$f = 1; self } };\n}";
        assert_eq!(
            macro_rules_violations(made_up),
            ["macro setters: fn with_hht"]
        );
        let inner = "macro_rules! m { () => { impl X { const INDEX: usize = 1; } struct S; } }";
        assert_eq!(
            macro_rules_violations(inner),
            ["macro m: const INDEX", "macro m: struct S"]
        );
        let given = "macro_rules! m { (fn $name:ident, unsafe fn $avx2:ident;) => {\n\
                     fn $name<const N: usize>() {} unsafe fn $avx2() {} const $i: usize = 0;\n\
                     pub const fn $x() {} self.set(const { Self::L.index_of(\"k\") }, v) } }";
        assert_eq!(macro_rules_violations(given), Vec::<String>::new());
        // A proc-macro's quote! body: `#name` is given, a literal is made up.
        assert_eq!(literal_item_names("#sig { } fn #name() {}"), []);
        assert_eq!(
            literal_item_names("struct #view { } fn helper() {}"),
            [("fn".to_string(), "helper".to_string())]
        );
    }

    #[test]
    fn header_functions_are_the_declarations() {
        let header = "/* f(x) */\n#if defined(A)\ntypedef void (*Handler)(const char *m);\n\
                      enum IflStatus ifl_a(const double *p,\n int n);\nvoid fric_(int *lm);\n#endif\n";
        assert_eq!(header_functions(header), ["ifl_a", "fric_"]);
        let src = code_only("pub unsafe extern \"C\" fn fric_(lm: *mut i32) {}\n// fn ifl_a\n");
        assert!(defines_fn(&src, "fric_"));
        assert!(
            !defines_fn(&src, "ifl_a"),
            "a name in a comment is not a definition"
        );
    }
}
