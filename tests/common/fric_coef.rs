//! One `fric_coef_` (Abaqus FRIC_COEF) call on a block of points, the host arguments no law reads
//! filled as a host would (nTemp = 1, no field variables, IDATA all 1, RDATA 0, one name for the
//! three surfaces): shared by the tests that call the export directly (fric_coef_abi.rs,
//! friction_table.rs, last_error.rs; included there by path).

use interfacial::abi::fric_coef_;
use std::ffi::c_int;

/// FRIC_COEF for nBlock = `p.len()` points: fCoef(nBlock,2) into `coef`, fCoefDeriv(nBlock,20,2)
/// into `deriv` (either may be longer, e.g. for guard slots after the contract's length),
/// slipData(nBlock,6) from `slip`, tempAvg(nBlock) from `temp`; `name` (any length, passed as
/// the hidden length) names the interaction and both surfaces.
pub fn fric_coef_call(
    coef: &mut [f64],
    deriv: &mut [f64],
    props: &[f64],
    slip: &[f64],
    p: &[f64],
    temp: &[f64],
    name: &[u8],
) {
    let n = p.len();
    assert!(
        coef.len() >= 2 * n && deriv.len() >= 40 * n && slip.len() >= 6 * n && temp.len() >= n,
        "arrays shorter than the FRIC_COEF contract for nBlock = {n}"
    );
    let (nb, np, nt, nf) = (n as c_int, props.len() as c_int, 1 as c_int, 0 as c_int);
    let idata = [1 as c_int; 6];
    let rdata = [0.0f64; 8];
    let field = [0.0f64; 1];
    // SAFETY: every array is at least as long as the FRIC_COEF contract asks for nBlock = n
    // (checked above; fieldAvg is not read with nFields = 0); the names' hidden lengths are
    // their true lengths.
    unsafe {
        fric_coef_(
            coef.as_mut_ptr(),
            deriv.as_mut_ptr(),
            &nb,
            &np,
            &nt,
            &nf,
            idata.as_ptr(),
            rdata.as_ptr(),
            name.as_ptr().cast(),
            name.as_ptr().cast(),
            name.as_ptr().cast(),
            props.as_ptr(),
            slip.as_ptr(),
            p.as_ptr(),
            temp.as_ptr(),
            field.as_ptr(),
            name.len(),
            name.len(),
            name.len(),
        );
    }
}
