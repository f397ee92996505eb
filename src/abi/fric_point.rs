//! `ifl_fric_point`: one `fric_` point with named inputs and outputs (two `#[repr(C)]`
//! structs) instead of FRIC's 42 arguments by reference. It is `fric_` itself, called with the
//! structs' fields as its arguments: the same path, the same bits, the same messages (which
//! name FRIC).

use std::ffi::{CStr, c_char, c_int};

use super::fric::fric_;
use super::native::IflStatus;
use super::{Fault, boundary, null_pointer, take_fault};
use crate::report::Site;

/// The inputs of one `fric_` point, by FRIC's argument names (lower case). Arrays are
/// column-major as in Fortran, sized for `NFDIR = 2`; with `nfdir = 1` only the first entry of
/// each direction is read. `statev` is read and, on success, written with the end-of-increment
/// state.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct IflFricInput {
    /// `LM` on entry: 0 relative motion, 1 exact stick (then `taulm` is read), 2 frictionless
    /// (nothing is computed or written).
    pub lm: c_int,
    /// `NFDIR`: 1 (2-D) or 2 (3-D).
    pub nfdir: c_int,
    /// `TAU(NFDIR)` at the start of the increment.
    pub tau: [f64; 2],
    /// `DGAM(NFDIR)`: the slip increment.
    pub dgam: [f64; 2],
    /// `TAULM(NFDIR)`: the stick stress the host's Lagrange multiplier gives (read with `LM = 1`).
    pub taulm: [f64; 2],
    /// `PRESS`: contact pressure at the end of the increment.
    pub press: f64,
    /// `DPRESS`: its increment.
    pub dpress: f64,
    /// `DTIME`: time increment.
    pub dtime: f64,
    /// `CHRLNGTH`: characteristic length of the contact surface.
    pub chrlngth: f64,
    /// `TEMP(2)`: surface temperatures (read when μ depends on temperature).
    pub temp: [f64; 2],
    /// `DROT(2,2)`: rotation increment, column-major (read only with damping, `PROPS(17)` > 0).
    pub drot: [f64; 4],
    /// `COORDS(MCRD)`: the point's coordinates (read only by steady-state transport).
    pub coords: [f64; 3],
    /// `MCRD`: how many of `coords` are given (1 to 3).
    pub mcrd: c_int,
    /// `NOEL`, `NPT`, `NODE`: where the point is, for messages.
    pub noel: c_int,
    /// See `noel`.
    pub npt: c_int,
    /// See `noel`.
    pub node: c_int,
    /// `CINAME`: the interaction, NUL-terminated (its μ table with `PROPS(8) = 2`); NULL for a
    /// blank name.
    pub interaction: *const c_char,
    /// `PROPS(NPROPS)` (docs/props.md).
    pub props: *const f64,
    /// `NPROPS`.
    pub nprops: c_int,
    /// `STATEV(NSTATV)`: read, and written on success.
    pub statev: *mut f64,
    /// `NSTATV`.
    pub nstatv: c_int,
    /// `PNEWDT` on entry (the host's current ratio; `fric_` only ever lowers it).
    pub pnewdt: f64,
}

/// The outputs of one `fric_` point, by FRIC's argument names. `ifl_fric_point` first sets
/// `lm`, `tau` and `pnewdt` to the inputs' values and everything else to 0, then lets `fric_`
/// write what it writes (docs/fric.md): what `fric_` leaves alone (with `LM = 1` or 2, or on a
/// failure) keeps those values.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct IflFricOutput {
    /// `LM` on exit.
    pub lm: c_int,
    /// `TAU(NFDIR)` at the end of the increment.
    pub tau: [f64; 2],
    /// `DDTDDG(NFDIR,NFDIR)`: `DDTDDG(a,b)` at `[(a-1) + (b-1)*nfdir]`.
    pub ddtddg: [f64; 4],
    /// `DDTDDP(NFDIR)`.
    pub ddtddp: [f64; 2],
    /// `DSLIP(NFDIR)`.
    pub dslip: [f64; 2],
    /// `SED`: elastic energy density.
    pub sed: f64,
    /// `SFD`: frictional dissipation increment.
    pub sfd: f64,
    /// `DDTDDT(NFDIR,2)`: `DDTDDT(a,b)` at `[(a-1) + (b-1)*nfdir]`.
    pub ddtddt: [f64; 4],
    /// `PNEWDT` on exit.
    pub pnewdt: f64,
}

/// One friction point: `fric_` with the arguments named in `*input`, its answer in `*output`.
/// Bit for bit what `fric_` gives for the same arguments (it is the same call), refusals,
/// `PNEWDT` and messages included; the messages name FRIC. Returns `IFL_STATUS_OK`, or the cause
/// of `fric_`'s failure (reported as `fric_` reports it; `ifl_last_error`). A NULL `input` or
/// `output` is `IFL_STATUS_BAD_INPUT` (nothing is written).
///
/// # Safety
/// `input` and `output` are NULL or valid; `input->props` holds `nprops` doubles and
/// `input->statev` `nstatv` (writable); `input->interaction` is NULL or NUL-terminated.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ifl_fric_point(
    input: *const IflFricInput,
    output: *mut IflFricOutput,
) -> IflStatus {
    if input.is_null() || output.is_null() {
        let name = if input.is_null() { "input" } else { "output" };
        return boundary(
            || Site {
                routine: "ifl_fric_point",
                interaction: String::new(),
                place: String::new(),
            },
            || Err(null_pointer(name)),
            || {},
        )
        .into();
    }
    // SAFETY: non-NULL and valid per the contract.
    let i = unsafe { input.read() };
    let mut o = IflFricOutput {
        lm: i.lm,
        tau: i.tau,
        pnewdt: i.pnewdt,
        ..IflFricOutput::default()
    };
    let name: &[u8] = if i.interaction.is_null() {
        b""
    } else {
        // SAFETY: NUL-terminated per the contract.
        unsafe { CStr::from_ptr(i.interaction) }.to_bytes()
    };
    // FRIC's arguments that no path reads (`FricArgs`'s `unread`), given valid values anyway.
    let (ddpddh, slip, kstep, kinc, time, npatch) = (0.0, [0.0; 3], 1, 1, [0.0; 2], 1);
    let (rcoord, predef, npred, blank) = ([0.0; 3], [0.0; 2], 1, [b' '; 1]);
    let _ = take_fault();
    // SAFETY: every pointer is a field of `i` or `o` or a local sized as FRIC's contract asks
    // for NFDIR ≤ 2 (the structs' arrays), MCRD ≤ 3, and the host's PROPS and STATEV per this
    // function's contract; the names with their lengths.
    unsafe {
        fric_(
            &mut o.lm,
            o.tau.as_mut_ptr(),
            o.ddtddg.as_mut_ptr(),
            o.ddtddp.as_mut_ptr(),
            o.dslip.as_mut_ptr(),
            &mut o.sed,
            &mut o.sfd,
            o.ddtddt.as_mut_ptr(),
            &mut o.pnewdt,
            i.statev,
            i.dgam.as_ptr(),
            i.taulm.as_ptr(),
            &i.press,
            &i.dpress,
            &ddpddh,
            slip.as_ptr(),
            &kstep,
            &kinc,
            time.as_ptr(),
            &i.dtime,
            &i.noel,
            name.as_ptr().cast::<c_char>(),
            blank.as_ptr().cast::<c_char>(),
            blank.as_ptr().cast::<c_char>(),
            &i.npt,
            &i.node,
            &npatch,
            i.coords.as_ptr(),
            rcoord.as_ptr(),
            i.drot.as_ptr(),
            i.temp.as_ptr(),
            predef.as_ptr(),
            &i.nfdir,
            &i.mcrd,
            &npred,
            &i.nstatv,
            &i.chrlngth,
            i.props,
            &i.nprops,
            name.len(),
            1,
            1,
        );
        output.write(o);
    }
    let fault: Option<Fault> = take_fault();
    IflStatus::from(fault.map_or(Ok(()), Err))
}
