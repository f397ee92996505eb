//! The Fortran module `fortran/interfacial.f90` covers the C API: every `ifl_*` function that
//! `include/interfacial.h` declares has a `bind(C, name='ifl_…')` interface in the module, and
//! the module binds nothing the header lacks (besides libc's `strlen`). A new native function
//! without its Fortran interface fails here. The explicit interfaces of the Abaqus entry points
//! have the header's arguments: same count, same names in the same places, `character` exactly
//! where C has `const char *`, `integer(c_int)` exactly where C has `int *`.

use std::collections::BTreeSet;

fn header_functions() -> BTreeSet<String> {
    let h = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/include/interfacial.h"
    ))
    .unwrap();
    let mut out = BTreeSet::new();
    for line in h.lines() {
        // Declarations start in column 0: "<return type> ifl_name(".
        if line.starts_with(' ') || line.starts_with('*') || line.starts_with('/') {
            continue;
        }
        if let Some(open) = line.find('(') {
            let head = &line[..open];
            if let Some(name) = head.split([' ', '*']).next_back()
                && name.starts_with("ifl_")
            {
                out.insert(name.to_owned());
            }
        }
    }
    out
}

fn module_bindings() -> BTreeSet<String> {
    let f = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/fortran/interfacial.f90"
    ))
    .unwrap()
    .to_ascii_lowercase();
    let mut out = BTreeSet::new();
    for (i, _) in f.match_indices("bind(c, name='") {
        let rest = &f[i + "bind(c, name='".len()..];
        if let Some(end) = rest.find('\'') {
            out.insert(rest[..end].to_owned());
        }
    }
    out
}

#[test]
fn every_header_function_has_a_fortran_interface() {
    let header = header_functions();
    assert!(
        header.len() >= 8 && header.contains("ifl_gap_conductance_n"),
        "header parse found {header:?}"
    );
    let module = module_bindings();
    let missing: Vec<_> = header.difference(&module).collect();
    assert!(
        missing.is_empty(),
        "fortran/interfacial.f90 has no bind(C) interface for {missing:?}: add one (with \
         iso_c_binding kinds) and, for a function taking a name, a character(*) wrapper"
    );
    let extra: Vec<_> = module
        .iter()
        .filter(|m| *m != "strlen" && !header.contains(*m))
        .collect();
    assert!(
        extra.is_empty(),
        "the module binds {extra:?}, which the header lacks"
    );
}

/// The C parameters of `void <name>(...)` (the first declaration: for `gapcon_` the Abaqus one).
fn c_params(header: &str, name: &str) -> Vec<String> {
    let start = header
        .find(&format!("void {name}("))
        .unwrap_or_else(|| panic!("{name} not in the header"));
    let rest = &header[start + name.len() + 6..];
    let body = &rest[..rest.find(");").unwrap()];
    body.split(',').map(|p| p.trim().to_owned()).collect()
}

/// The dummy arguments of the module's `subroutine <name>(...)` and which are `character`.
fn fortran_dummies(module: &str, name: &str) -> (Vec<String>, Vec<String>) {
    let start = module
        .find(&format!("subroutine {name}("))
        .unwrap_or_else(|| panic!("no interface for {name} in the module"));
    let rest = &module[start + name.len() + 12..];
    let args: Vec<String> = rest[..rest.find(')').unwrap()]
        .replace('&', " ")
        .split(',')
        .map(|a| a.trim().to_owned())
        .collect();
    let end = rest.find(&format!("end subroutine {name}")).unwrap();
    let chars = rest[..end]
        .lines()
        .filter_map(|l| l.trim().strip_prefix("character(len=*) ::"))
        .flat_map(|l| l.split(',').map(|a| a.trim().to_owned()))
        .collect();
    (args, chars)
}

#[test]
fn abaqus_interfaces_match_the_exported_argument_lists() {
    let root = env!("CARGO_MANIFEST_DIR");
    let header = std::fs::read_to_string(format!("{root}/include/interfacial.h")).unwrap();
    let module = std::fs::read_to_string(format!("{root}/fortran/interfacial.f90"))
        .unwrap()
        .to_ascii_lowercase();
    for (c, f, explicit) in [
        ("fric_", "fric", 39),
        ("gapcon_", "gapcon", 15),
        ("fric_coef_", "fric_coef", 16),
        ("uinter_", "uinter", 47),
        ("vfric_", "vfric", 42),
    ] {
        let params = c_params(&header, c);
        let (args, chars) = fortran_dummies(&module, f);
        // Every CHARACTER adds one hidden size_t after the explicit arguments.
        assert_eq!(
            args.len(),
            explicit,
            "{f}: explicit arguments in the module"
        );
        assert_eq!(
            params.len(),
            explicit + chars.len(),
            "{c}: header vs module"
        );
        assert_eq!(chars.len(), 3, "{f}: three names");
        for (i, a) in args.iter().enumerate() {
            // Same name, in the same place (the C names are the Fortran ones with underscores).
            let c_name = params[i]
                .rsplit(['*', ' '])
                .next()
                .unwrap()
                .replace('_', "");
            assert_eq!(&c_name, a, "{f}: argument {} is {a} in the module", i + 1);
            let is_char = chars.contains(a);
            let c_is_char = params[i].starts_with("const char *");
            assert_eq!(
                is_char,
                c_is_char,
                "{f}: argument {} ({a}) vs {}",
                i + 1,
                params[i]
            );
            // Integers where C has int, reals where C has double/IflReal.
            let c_int = params[i].contains("int *");
            let decl = module[module.find(&format!("subroutine {f}(")).unwrap()..]
                .lines()
                .skip_while(|l| !l.contains("import ::"))
                .take_while(|l| !l.contains("end subroutine"))
                .filter(|l| !l.trim_start().starts_with('!'))
                .collect::<Vec<_>>()
                .join("\n");
            let int_decl = decl.split("integer(c_int) ::").skip(1).any(|block| {
                block
                    .split(['\n'])
                    .take_while(|l| !l.contains("::") || l.contains("integer(c_int) ::"))
                    .collect::<String>()
                    .replace('&', " ")
                    .split([',', ' '])
                    .map(|w| w.trim().trim_end_matches("(*)"))
                    .any(|w| w == a)
            });
            assert_eq!(
                int_decl, c_int,
                "{f}: {a} integer in one, not the other ({})",
                params[i]
            );
        }
    }
}
