//! The checked-in C header must be exactly what cbindgen generates from the sources, and the
//! exported functions must have the signatures of `docs/calling-conventions.md`.

use std::ffi::{c_char, c_int};
use std::path::Path;

#[test]
fn header_is_up_to_date() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen failed")
        .write(&mut generated);
    let generated = c89_clean(&generated);
    let path = root.join("include/interfacial.h");
    if std::env::var_os("INTERFACIAL_BLESS").is_some() {
        std::fs::write(&path, &generated).expect("write header");
        return;
    }
    let on_disk = std::fs::read(&path).unwrap_or_default();
    assert!(
        on_disk == generated,
        "include/interfacial.h is stale; regenerate it with:\n    INTERFACIAL_BLESS=1 cargo test --test header"
    );
}

/// cbindgen's C output is C99/C++11: `//` comments after `#endif` and on the closing brace of
/// `extern "C"`, and a comma after an enum's last variant. The header is also meant for C89 and
/// C++98 (`-pedantic`, c_tests/CMakeLists.txt compiles it in both), so those are rewritten.
/// Rustdoc's intra-doc links (`` [`ifl_gap_conductance_n`] ``, `` [`x`](path) ``) become plain
/// code spans: a C reader sees `` `ifl_gap_conductance_n` ``.
fn c89_clean(generated: &[u8]) -> Vec<u8> {
    strip_doc_links(&String::from_utf8_lossy(generated))
        .replace("#endif // __cplusplus", "#endif /* __cplusplus */")
        .replace("#endif  // __cplusplus", "#endif /* __cplusplus */")
        .replace("}  // extern \"C\"", "}  /* extern \"C\" */")
        .replace(",\n} ", "\n} ")
        .into_bytes()
}

/// `` [`name`] `` -> `` `name` `` and `` [`name`](target) `` -> `` `name` ``, within one line.
fn strip_doc_links(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(start) = rest.find("[`") {
        let after = &rest[start + 1..];
        match after.find("`]") {
            Some(end) if !after[..end].contains(['\n', '[']) => {
                out.push_str(&rest[..start]);
                out.push_str(&after[..=end]);
                rest = &after[end + 2..];
                if rest.starts_with('(') {
                    if let Some(close) = rest.find(')').filter(|c| !rest[..*c].contains('\n')) {
                        rest = &rest[close + 1..];
                    }
                }
            }
            _ => {
                out.push_str(&rest[..start + 2]);
                rest = &rest[start + 2..];
            }
        }
    }
    out.push_str(rest);
    out
}

#[test]
fn header_shows_no_rustdoc_link_syntax() {
    assert_eq!(
        strip_doc_links("see [`a_b`] and [`c`](d.md), [x], [`e\n`]"),
        "see `a_b` and `c`, [x], [`e\n`]"
    );
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let header = std::fs::read_to_string(root.join("include/interfacial.h")).expect("header");
    for (n, line) in header.lines().enumerate() {
        assert!(
            !line.contains("[`") && !line.contains("`]"),
            "include/interfacial.h:{}: rustdoc link syntax: {line}",
            n + 1
        );
    }
}

/// The Rust side of the prototype check: each export coerces to the function-pointer type
/// written by hand from abi.md (Fortran: everything by reference, int = INTEGER, hidden
/// `size_t` lengths last). The C side (`c_tests/abi_prototypes.c`) redeclares the same
/// prototypes after including the header, which fails to compile on any mismatch.
#[test]
fn exports_have_the_abaqus_signatures() {
    type I = *const c_int;
    type R = *const f64;
    type S = *const c_char;
    type Fric = unsafe extern "C" fn(
        *mut c_int, // LM
        *mut f64,   // TAU
        *mut f64,   // DDTDDG
        *mut f64,   // DDTDDP
        *mut f64,   // DSLIP
        *mut f64,   // SED
        *mut f64,   // SFD
        *mut f64,   // DDTDDT
        *mut f64,   // PNEWDT
        *mut f64,   // STATEV
        R,          // DGAM
        R,          // TAULM
        R,          // PRESS
        R,          // DPRESS
        R,          // DDPDDH
        R,          // SLIP
        I,          // KSTEP
        I,          // KINC
        R,          // TIME
        R,          // DTIME
        I,          // NOEL
        S,          // CINAME
        S,          // SLNAME
        S,          // MSNAME
        I,          // NPT
        I,          // NODE
        I,          // NPATCH
        R,          // COORDS
        R,          // RCOORD
        R,          // DROT
        R,          // TEMP
        R,          // PREDEF
        I,          // NFDIR
        I,          // MCRD
        I,          // NPRED
        I,          // NSTATV
        R,          // CHRLNGTH
        R,          // PROPS
        I,          // NPROPS
        usize,      // len(CINAME)
        usize,      // len(SLNAME)
        usize,      // len(MSNAME)
    );
    let _: Fric = interfacial::abi::fric_;
    // FRIC_COEF: 16 explicit arguments, 3 hidden lengths.
    let _: unsafe extern "C" fn(
        *mut f64, // fCoef(nBlock,2)
        *mut f64, // fCoefDeriv(nBlock,20,2)
        I,        // nBlock
        I,        // nProps
        I,        // nTemp
        I,        // nFields
        I,        // iData
        R,        // rData
        S,        // surfInt
        S,        // surfSec
        S,        // surfMain
        R,        // props
        R,        // slipData(nBlock,6)
        R,        // pressure(nBlock)
        R,        // tempAvg(nBlock)
        R,        // fieldAvg(nBlock,nFields)
        usize,    // len(surfInt)
        usize,    // len(surfSec)
        usize,    // len(surfMain)
    ) = interfacial::abi::fric_coef_;
    // CalculiX's GAPCON has one more argument, AREA, before the hidden lengths.
    macro_rules! gapcon {
        ($($area:ty)?) => {
            unsafe extern "C" fn(
                *mut f64, // AK
                R,        // D
                R,        // FLOWM
                R,        // TEMP
                R,        // PREDEF
                R,        // TIME
                S,        // CINAME
                S,        // SLNAME
                S,        // MSNAME
                R,        // COORDS
                I,        // NOEL
                I,        // NODE
                I,        // NPRED
                I,        // KSTEP
                I,        // KINC
                $($area,)?
                usize,    // len(CINAME)
                usize,    // len(SLNAME)
                usize,    // len(MSNAME)
            )
        };
    }
    #[cfg(not(feature = "calculix"))]
    type Gapcon = gapcon!();
    #[cfg(feature = "calculix")]
    type Gapcon = gapcon!(R);
    let _: Gapcon = interfacial::abi::gapcon_;
    let _: unsafe extern "C" fn(
        *const c_char,
        f64,
        f64,
        f64,
        f64,
        *mut interfacial::abi::IflConductance,
    ) -> interfacial::abi::IflStatus = interfacial::abi::ifl_gap_conductance;
    let _: extern "C" fn() -> *const c_char = interfacial::abi::ifl_version;
    let _: extern "C" fn() -> *const c_char = interfacial::abi::ifl_last_error;
    let _: unsafe extern "C" fn(*mut c_char, usize) -> usize =
        interfacial::abi::ifl_last_error_copy;
    let _: extern "C" fn() = interfacial::abi::ifl_clear_error;
    let _: unsafe extern "C" fn(
        usize,      // npoints
        usize,      // ld
        c_int,      // nfdir
        R,          // props
        c_int,      // nprops
        c_int,      // nstatv
        f64,        // dtime
        *mut c_int, // lm
        *mut f64,   // tau
        *mut f64,   // ddtddg
        *mut f64,   // ddtddp
        *mut f64,   // dslip
        *mut f64,   // sed
        *mut f64,   // sfd
        *mut f64,   // statev
        R,          // dgam
        R,          // taulm
        R,          // press
        R,          // dpress
        R,          // chrlngth
        *mut f64,   // pnewdt
    ) -> interfacial::abi::IflStatus = interfacial::abi::ifl_fric_batch;
}
