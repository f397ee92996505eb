//! The Abaqus build's `gapcon_` called with CalculiX's argument list (`AREA` after `KINC`, so
//! AREA's address lands in the hidden length of `CINAME` and CINAME's length one slot later):
//! it must refuse without reading CINAME with that "length", write `AK(1) = 0` only, and name
//! the library to link instead (docs/gapcon.md, "Which library").
#![cfg(not(feature = "calculix"))]

use std::ffi::{CStr, c_char, c_int};

use interfacial::abi::{gapcon_, ifl_last_error};

const GUARD: f64 = -4242.0;

fn call_as_calculix(ciname: &[u8; 80]) -> [f64; 5] {
    let mut ak = [GUARD; 5];
    let (d, temp, zeros) = ([0.0f64, 1.0], [300.0f64, 290.0], [0.0f64; 4]);
    let (one, zero) = (1 as c_int, 0 as c_int);
    let area = 2.5f64;
    let blank = [b' '; 80];
    // SAFETY: every pointer is valid; the hidden lengths are what CalculiX's call puts in these
    // slots: &AREA, then CINAME's and SLNAME's real lengths.
    unsafe {
        gapcon_(
            ak.as_mut_ptr(),
            d.as_ptr(),
            zeros.as_ptr(),
            temp.as_ptr(),
            zeros.as_ptr(),
            zeros.as_ptr(),
            ciname.as_ptr().cast::<c_char>(),
            blank.as_ptr().cast(),
            blank.as_ptr().cast(),
            zeros.as_ptr(),
            &one,
            &one,
            &zero,
            &one,
            &one,
            std::ptr::from_ref(&area) as usize,
            80,
            80,
        );
    }
    ak
}

#[test]
fn calculix_argument_list_is_refused_with_the_library_to_link() {
    let mut name = [b' '; 80];
    name[..6].copy_from_slice(b"GAP-17");
    let ak = call_as_calculix(&name);
    assert_eq!(ak[0], 0.0, "AK(1) = 0");
    assert_eq!(&ak[1..], &[GUARD; 4], "nothing else written");
    // SAFETY: NUL-terminated thread-local text, read at once.
    let m = unsafe { CStr::from_ptr(ifl_last_error()) }.to_string_lossy();
    for word in [
        "GAPCON",
        "'GAP-17'",
        "CalculiX",
        "libinterfacial_calculix",
        "Interfacial::interfacial_calculix",
    ] {
        assert!(m.contains(word), "'{word}' missing from: {m}");
    }
}
