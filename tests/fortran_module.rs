//! The Fortran module `fortran/interfacial.f90` covers the C API: every `ifl_*` function that
//! `include/interfacial.h` declares has a `bind(C, name='ifl_…')` interface in the module, and
//! the module binds nothing the header lacks (besides libc's `strlen`). A new native function
//! without its Fortran interface fails here.

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
