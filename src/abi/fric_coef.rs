//! `fric_coef_`: the Abaqus/Standard FRIC_COEF user subroutine (current form, abi.md): the
//! friction coefficient of a block of points and its derivatives, for the same μ laws as `fric_`.

use std::ffi::{c_char, c_int};

use super::{count, fortran_name_bytes, host_site, null_pointer, read, slice};
use crate::LawError;
use crate::config::friction_table_for;
use crate::laws::point_law::PointLaw;
use crate::props::friction_law_with_table;

/// Number of derivative slots per point and direction in `fCoefDeriv(nBlock,20,2)`.
pub const FRIC_COEF_NDERIV: usize = 20;

/// Abaqus/Standard `FRIC_COEF`: μ of `nBlock` points and its derivatives, callable from Fortran as
/// `CALL FRIC_COEF(...)`.
///
/// `PROPS` has the `fric_` law-1 layout (docs/props.md); only the μ entries matter here
/// (`PROPS(2)` μ₁, `PROPS(3)` μ₂, `PROPS(8..13)` the rate, pressure and temperature laws).
/// For point k: the slip-rate magnitude is `slipData(k,1)`, the pressure `pressure(k)` and the
/// temperature `tempAvg(k)` (read only with a temperature law). Writes:
/// - `fCoef(k,1)` = μ₁ and `fCoef(k,2)` = μ₂ (= μ₁ when isotropic);
/// - `fCoefDeriv(k,1,d)` = ∂μ_d/∂γ̇_eq, `fCoefDeriv(k,2,d)` = ∂μ_d/∂p,
///   `fCoefDeriv(k,3,d)` = ∂μ_d/∂θ̄, `fCoefDeriv(k,4..20,d)` = 0 (μ depends on nothing else).
///
/// A negative pressure uses the μ of p = 0 with ∂μ/∂p = 0. `iData`, `rData`, `fieldAvg`,
/// `surfSec`, `surfMain` are not read.
///
/// On failure (bad `PROPS`, NaN or infinite input, a negative slip rate, `nBlock` < 0, a
/// temperature law with `nTemp` = 0, overflow, internal panic) the whole block gets μ = 0 and
/// zero derivatives, and one message per distinct cause is reported (FRIC_COEF has no
/// `PNEWDT`; `INTERFACIAL_STRICT=1` aborts instead).
///
/// # Safety
/// Pointers valid for the FRIC_COEF signature: `fCoef(nBlock,2)`, `fCoefDeriv(nBlock,20,2)`,
/// `props(nProps)`, `slipData(nBlock,6)`, `pressure(nBlock)`, `tempAvg(nBlock)` (when read),
/// names of the given hidden lengths.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
// The view `CoefArgs` (a field per parameter but the `unread` ones, bound to `args`) is written
// by the attribute from this parameter list (macros/).
#[interfacial_macros::with_view(
    view = struct CoefArgs as args,
    unread = (nfields, idata, rdata, surf_sec, surf_main, field_avg, surf_sec_len, surf_main_len),
)]
pub unsafe extern "C" fn fric_coef_(
    fcoef: *mut f64,
    fcoef_deriv: *mut f64,
    nblock: *const c_int,
    nprops: *const c_int,
    ntemp: *const c_int,
    nfields: *const c_int,
    idata: *const c_int,
    rdata: *const f64,
    surf_int: *const c_char,
    surf_sec: *const c_char,
    surf_main: *const c_char,
    props: *const f64,
    slip_data: *const f64,
    pressure: *const f64,
    temp_avg: *const f64,
    field_avg: *const f64,
    surf_int_len: usize,
    surf_sec_len: usize,
    surf_main_len: usize,
) {
    fortran_boundary!(
        args,
        // SAFETY: the name of its hidden length, per the contract above.
        || unsafe { host_site("FRIC_COEF", surf_int, surf_int_len, "block".into()) }
    );
}

impl CoefArgs {
    #[allow(clippy::needless_range_loop)] // d, j are the Fortran indices of fCoefDeriv(k,j,d)
    unsafe fn run(&self) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of the sizes the FRIC_COEF contract gives, read after
        // their sizes were checked; outputs written only after every point was computed.
        unsafe {
            let n = count("nBlock", read(self.nblock, "nBlock")?)?;
            let nprops = count("nProps", read(self.nprops, "nProps")?)?;
            let props = slice(self.props, nprops, "props")?;
            // The μ table (law 1's, when its PROPS ask for one) is the interaction's, from the
            // configuration file. A NULL name or an implausible hidden length (an address) reads
            // as no name.
            let law = friction_law_with_table(props, || {
                friction_table_for(fortran_name_bytes(self.surf_int, self.surf_int_len))
            })?;
            // A law whose μ is not a function of rate, pressure and temperature alone (law 2
            // carries adhesion, law 3 the state θ, which FRIC_COEF has no STATEV for) has no
            // `coefficients`; fric_ serves it (docs/props.md). Asked once before the block, so
            // such a law is refused even with nBlock = 0.
            if law.coefficients(0.0, 0.0, 0.0).is_none() {
                return Err(LawError::Parameter(format!(
                    "{}: μ is not a function of slip rate, pressure and temperature alone \
                     (FRIC_COEF has no STATEV); FRIC serves it",
                    law.name_with_code()
                )));
            }
            if n == 0 {
                return Ok(());
            }
            // The outputs are written through raw pointers below: refuse NULL ones first
            // (fric_coef fuzz crash C1, docs/fuzzing.md).
            if self.fcoef.is_null() {
                return Err(null_pointer("fCoef"));
            }
            if self.fcoef_deriv.is_null() {
                return Err(null_pointer("fCoefDeriv"));
            }
            let slip = slice(self.slip_data, 6 * n, "slipData")?;
            let pressure = slice(self.pressure, n, "pressure")?;
            let temperature = if law.needs(2).temperature {
                let ntemp = read(self.ntemp, "nTemp")?;
                if ntemp < 1 {
                    return Err(LawError::Input(format!(
                        "μ of {} depends on temperature but nTemp = {ntemp}",
                        law.name()
                    )));
                }
                Some(slice(self.temp_avg, n, "tempAvg")?)
            } else {
                None
            };
            // Compute the whole block first: a failure at any point leaves it unwritten.
            let mut values = vec![[[0.0; 2]; 4]; n];
            for (k, out) in values.iter_mut().enumerate() {
                let rate = slip[k];
                let p = pressure[k];
                let theta = temperature.map_or(0.0, |t| t[k]);
                if !(rate.is_finite() && rate >= 0.0) {
                    return Err(LawError::Input(format!(
                        "slipData({}, 1) = {rate}: the slip-rate magnitude must be finite and ≥ 0",
                        k + 1
                    )));
                }
                if !p.is_finite() {
                    return Err(LawError::Input(format!("pressure({}) = {p}", k + 1)));
                }
                if !theta.is_finite() {
                    return Err(LawError::Input(format!("tempAvg({}) = {theta}", k + 1)));
                }
                // Some: the law was asked before the block.
                *out = law
                    .coefficients(rate, p.max(0.0), theta)
                    .unwrap_or_default();
                if p < 0.0 {
                    out[2] = [0.0; 2];
                }
                if !out.iter().flatten().all(|x| x.is_finite()) {
                    return Err(LawError::Numerical(format!(
                        "μ overflowed at point {} (rate {rate}, pressure {p}, temperature {theta})",
                        k + 1
                    )));
                }
            }
            for (k, v) in values.iter().enumerate() {
                for d in 0..2 {
                    // fCoef(k,d) at (k-1) + nBlock(d-1).
                    self.fcoef.add(k + n * d).write(v[0][d]);
                    for j in 0..FRIC_COEF_NDERIV {
                        // fCoefDeriv(k,j,d) at (k-1) + nBlock((j-1) + 20(d-1)).
                        let x = if (1..=3).contains(&(j + 1)) {
                            v[j + 1][d]
                        } else {
                            0.0
                        };
                        self.fcoef_deriv
                            .add(k + n * (j + FRIC_COEF_NDERIV * d))
                            .write(x);
                    }
                }
            }
            Ok(())
        }
    }

    /// μ = 0 and zero derivatives for the whole block (when nBlock is readable and ≥ 0).
    unsafe fn fail(&self) {
        // SAFETY: the output arrays hold nBlock·2 and nBlock·40 entries per the contract.
        unsafe {
            let Ok(Ok(n)) = read(self.nblock, "nBlock").map(usize::try_from) else {
                return;
            };
            if !self.fcoef.is_null() {
                for i in 0..2 * n {
                    self.fcoef.add(i).write(0.0);
                }
            }
            if !self.fcoef_deriv.is_null() {
                for i in 0..2 * FRIC_COEF_NDERIV * n {
                    self.fcoef_deriv.add(i).write(0.0);
                }
            }
        }
    }
}
