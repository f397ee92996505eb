//! `uinter_`: the Abaqus/Standard UINTER user subroutine, for the adhesive interface
//! (`PROPS(1) = 2`): normal contact, separation adhesion, friction and heat exchange.

use std::ffi::{c_char, c_int};

use super::{boundary, fortran_string, read, read_array, slice, write, write_zeros};
use crate::config;
use crate::laws::adhesive_interface::{InterfaceIncrement, InterfaceResponse, InterfaceState};
use crate::props::{AdhesiveProps, HeatExchange, LAW_ADHESIVE, adhesive_props};
use crate::report::Site;
use crate::{CUTBACK_RATIO, LawError};

/// Abaqus/Standard `UINTER`: the full constitutive behaviour of one interface point, callable
/// from Fortran as `CALL UINTER(...)` with no interface block (47 arguments by reference, then
/// the hidden lengths of `CINAME`, `SLNAME`, `MSNAME`). Arrays are column-major.
///
/// Law: `PROPS(1) = 2`, the adhesive friction law with a penalty normal stiffness `PROPS(10)`
/// (layout in `docs/props.md`, behaviour in `docs/uinter.md`); `NSTATV ≥ 3`; `NDIR` 2 (2-D) or
/// 3 (3-D). `STRESS(1)` is the normal stress, positive in compression, `RDISP(1)` the
/// overclosure, positive for penetration; `STRESS(2..NDIR)` the shear stresses and
/// `DRDISP(2..NDIR)` the tangential relative motion of the increment.
///
/// Reads `STRESS` (start of increment), `STATEV`, `RDISP(1)`, `DRDISP(2..NDIR)`, `DTIME`,
/// `CHRLNGTH`, `PROPS`, `NDIR`, `NSTATV`, `NPROPS`, and `TEMP(2)` (current surface
/// temperatures) when `PROPS(11) = 1`. Writes `STRESS`, `DDSDDR(NDIR,NDIR)`,
/// `DVISCOUS` and `DSTRUCTURAL` (zero), `FLUX(2)`, `DDFDDT(2,2)` (= −∂FLUX/∂TEMP),
/// `DDSDDT(NDIR,2)` (zero), `DDFDDR(2,NDIR)`, `STATEV(1..3)`, `SED`, `SFD`, `SPD` (the
/// energy released by a bond breaking in the increment, 0 otherwise), `SVD`, `SCD` (zero),
/// `LOPENCLOSE` (1 when the interface carries stress: closed or bonded; 0 when open) and
/// `LSTATE` (the status code of `STATEV(3)`). Never reads or writes the other arguments.
///
/// On failure (bad `PROPS`, `NSTATV` < 3, `NDIR` not 2 or 3, NaN or infinite input, no thermal
/// law for the interaction when `PROPS(11) = 1`, overflow, internal panic): `PNEWDT = 0.25`,
/// `STRESS`, `STATEV`, `LOPENCLOSE`, `LSTATE` unchanged, the tangents, `SFD` and `SPD` zeroed
/// (the tangents when `NDIR` is valid), one message per distinct cause.
///
/// # Safety
/// The pointers must be valid for the UINTER signature with the sizes the host passes;
/// optional outputs (`DVISCOUS`, `DSTRUCTURAL`, `DDSDDT`, `DDFDDR`, `SED` … `SCD`, `FLUX`,
/// `DDFDDT`, `LSTATE`) may be NULL.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn uinter_(
    stress: *mut f64,
    ddsddr: *mut f64,
    dviscous: *mut f64,
    dstructural: *mut f64,
    flux: *mut f64,
    ddfddt: *mut f64,
    ddsddt: *mut f64,
    ddfddr: *mut f64,
    statev: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    spd: *mut f64,
    svd: *mut f64,
    scd: *mut f64,
    pnewdt: *mut f64,
    rdisp: *const f64,
    drdisp: *const f64,
    temp: *const f64,
    dtemp: *const f64,
    predef: *const f64,
    dpred: *const f64,
    time: *const f64,
    dtime: *const f64,
    freqr: *const f64,
    ciname: *const c_char,
    slname: *const c_char,
    msname: *const c_char,
    props: *const f64,
    coords: *const f64,
    alocaldir: *const f64,
    drot: *const f64,
    area: *const f64,
    chrlngth: *const f64,
    node: *const c_int,
    ndir: *const c_int,
    nstatv: *const c_int,
    npred: *const c_int,
    nprops: *const c_int,
    mcrd: *const c_int,
    kstep: *const c_int,
    kinc: *const c_int,
    kit: *const c_int,
    linper: *const c_int,
    lopenclose: *mut c_int,
    lstate: *mut c_int,
    lsdi: *mut c_int,
    lprint: *const c_int,
    ciname_len: usize,
    slname_len: usize,
    msname_len: usize,
) {
    let _ = (
        dtemp, predef, dpred, time, freqr, slname, msname, coords, alocaldir, drot, area,
    );
    let _ = (npred, mcrd, kstep, kinc, kit, linper, lsdi, lprint);
    let _ = (slname_len, msname_len);
    let args = UinterArgs {
        stress,
        ddsddr,
        dviscous,
        dstructural,
        flux,
        ddfddt,
        ddsddt,
        ddfddr,
        statev,
        sed,
        sfd,
        spd,
        svd,
        scd,
        pnewdt,
        rdisp,
        drdisp,
        temp,
        dtime,
        ciname,
        ciname_len,
        props,
        chrlngth,
        ndir,
        nstatv,
        nprops,
        lopenclose,
        lstate,
    };
    let _ = boundary(
        // SAFETY (all three closures): the host's pointers, valid per the contract above.
        || unsafe { site(ciname, ciname_len, node) },
        || unsafe { args.run() },
        || unsafe { args.fail() },
    );
}

/// The arguments `uinter_` reads or writes.
struct UinterArgs {
    stress: *mut f64,
    ddsddr: *mut f64,
    dviscous: *mut f64,
    dstructural: *mut f64,
    flux: *mut f64,
    ddfddt: *mut f64,
    ddsddt: *mut f64,
    ddfddr: *mut f64,
    statev: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    spd: *mut f64,
    svd: *mut f64,
    scd: *mut f64,
    pnewdt: *mut f64,
    rdisp: *const f64,
    drdisp: *const f64,
    temp: *const f64,
    dtime: *const f64,
    ciname: *const c_char,
    ciname_len: usize,
    props: *const f64,
    chrlngth: *const f64,
    ndir: *const c_int,
    nstatv: *const c_int,
    nprops: *const c_int,
    lopenclose: *mut c_int,
    lstate: *mut c_int,
}

/// The heat flux of one point: `FLUX(2)`, `DDFDDT(2,2)` (column-major), `DDFDDR(2,NDIR)` as
/// `[∂/∂h, ∂/∂Δγ…]` per row.
struct Heat {
    flux: [f64; 2],
    ddfddt: [f64; 4],
    ddfddr: [[f64; 3]; 2],
}

impl UinterArgs {
    unsafe fn run(&self) -> Result<(), LawError> {
        // SAFETY (whole body): pointers valid per the UINTER contract; sizes checked first.
        unsafe {
            let nprops = read(self.nprops, "NPROPS")?;
            let Ok(nprops) = usize::try_from(nprops) else {
                return Err(LawError::Parameter(format!(
                    "NPROPS = {nprops} is negative"
                )));
            };
            let props = slice(self.props, nprops, "PROPS")?;
            if props.first() != Some(&f64::from(LAW_ADHESIVE)) {
                return Err(not_adhesive(props.first().copied()));
            }
            let props = adhesive_props(props)?;
            let nstatv = read(self.nstatv, "NSTATV")?;
            let nstatv = match usize::try_from(nstatv) {
                Ok(n) if n >= InterfaceState::NSTATV => n,
                _ => {
                    return Err(LawError::Parameter(format!(
                        "NSTATV = {nstatv} but the adhesive interface needs {} state variables \
                         (*DEPVAR / the NSTATV of *SURFACE INTERACTION, USER)",
                        InterfaceState::NSTATV
                    )));
                }
            };
            match read(self.ndir, "NDIR")? {
                2 => self.point::<1>(&props, nstatv),
                3 => self.point::<2>(&props, nstatv),
                other => Err(bad_ndir(other)),
            }
        }
    }

    /// One point with N = NDIR − 1 tangential directions; everything is computed before the
    /// first output is written.
    unsafe fn point<const N: usize>(
        &self,
        props: &AdhesiveProps,
        nstatv: usize,
    ) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of NDIR, NDIR², 2, 4, 2·NDIR and NSTATV entries.
        unsafe {
            let interface = props.interface()?;
            let ndir = N + 1;
            let stress_in = slice(self.stress, ndir, "STRESS")?;
            let rdisp = slice(self.rdisp, ndir, "RDISP")?;
            let drdisp = slice(self.drdisp, ndir, "DRDISP")?;
            let mut shear_start = [0.0; N];
            let mut dgam = [0.0; N];
            shear_start.copy_from_slice(&stress_in[1..]);
            dgam.copy_from_slice(&drdisp[1..]);
            let inc = InterfaceIncrement::<N> {
                normal_stress_start: stress_in[0],
                shear_start,
                overclosure: rdisp[0],
                dgam,
                dtime: read(self.dtime, "DTIME")?,
                characteristic_length: read(self.chrlngth, "CHRLNGTH")?,
            };
            let state = InterfaceState::from_statev(slice(self.statev, nstatv, "STATEV")?)?;
            let r = interface.update(&inc, &state)?;
            let heat = self.heat(&props.heat, &inc, &r)?;

            let mut end_state = [0.0; InterfaceState::NSTATV];
            r.state.write_statev(&mut end_state);
            for (i, v) in end_state.iter().enumerate() {
                self.statev.add(i).write(*v);
            }
            self.stress.write(r.normal_stress);
            for a in 0..N {
                self.stress.add(1 + a).write(r.shear.tau[a]);
            }
            if !self.ddsddr.is_null() {
                let at = |i: usize, j: usize| self.ddsddr.add(i + j * ndir);
                at(0, 0).write(r.dp_dh);
                for a in 0..N {
                    at(0, 1 + a).write(0.0);
                    at(1 + a, 0).write(r.shear.ddtddp[a] * r.dp_dh);
                    for b in 0..N {
                        at(1 + a, 1 + b).write(r.shear.ddtddg[a][b]);
                    }
                }
            }
            write_zeros(self.dviscous, ndir * ndir);
            write_zeros(self.dstructural, ndir * ndir);
            write_zeros(self.ddsddt, 2 * ndir);
            if !self.flux.is_null() {
                self.flux.write(heat.flux[0]);
                self.flux.add(1).write(heat.flux[1]);
            }
            if !self.ddfddt.is_null() {
                for (k, v) in heat.ddfddt.iter().enumerate() {
                    self.ddfddt.add(k).write(*v);
                }
            }
            if !self.ddfddr.is_null() {
                for i in 0..2 {
                    for j in 0..ndir {
                        self.ddfddr.add(i + 2 * j).write(heat.ddfddr[i][j]);
                    }
                }
            }
            write(self.sed, r.sed);
            write(self.sfd, r.shear.sfd);
            write(self.spd, r.spd);
            write(self.svd, 0.0);
            write(self.scd, 0.0);
            write(self.lopenclose, c_int::from(r.closed));
            write(self.lstate, r.state.status as c_int);
            Ok(())
        }
    }

    /// Conduction k(θ_slave − θ_master) from the interaction's thermal law (the GAPCON laws of
    /// `INTERFACIAL_CONFIG`, clearance max(−h, 0) and pressure max(p, 0)), plus the frictional
    /// heat η·SFD/Δt, a part f into the slave and 1 − f into the master.
    unsafe fn heat<const N: usize>(
        &self,
        h: &HeatExchange,
        inc: &InterfaceIncrement<N>,
        r: &InterfaceResponse<N>,
    ) -> Result<Heat, LawError> {
        let mut out = Heat {
            flux: [0.0; 2],
            ddfddt: [0.0; 4],
            ddfddr: [[0.0; 3]; 2],
        };
        if h.conductance {
            // SAFETY: CINAME of its hidden length, TEMP(2) readable per the contract.
            let (law, [theta_s, theta_m]) = unsafe {
                let name = if self.ciname.is_null() || self.ciname_len == 0 {
                    &[][..]
                } else {
                    std::slice::from_raw_parts(self.ciname.cast::<u8>(), self.ciname_len)
                };
                (
                    config::gap_law_for(name)?,
                    read_array::<2>(self.temp, "TEMP")?,
                )
            };
            let clearance = (-inc.overclosure).max(0.0);
            let pressure = r.normal_stress.max(0.0);
            let c = law.evaluate(clearance, pressure, theta_s, theta_m)?;
            // q = k(θ_s − θ_m) leaves the slave and enters the master.
            let q = c.k * (theta_s - theta_m);
            out.flux = [-q, q];
            // DDFDDT(i,j) = −∂FLUX(i)/∂θ_j, column-major.
            out.ddfddt = [c.dq_dtheta_a, -c.dq_dtheta_a, c.dq_dtheta_b, -c.dq_dtheta_b];
            let dk_dh = if inc.overclosure < 0.0 {
                -c.dk_dd
            } else if r.normal_stress > 0.0 {
                c.dk_dp * r.dp_dh
            } else {
                0.0
            };
            out.ddfddr[0][0] = -dk_dh * (theta_s - theta_m);
            out.ddfddr[1][0] = dk_dh * (theta_s - theta_m);
        }
        if h.heat_fraction > 0.0 && inc.dtime > 0.0 {
            let eta = h.heat_fraction / inc.dtime;
            let f = h.slave_fraction;
            out.flux[0] += f * eta * r.shear.sfd;
            out.flux[1] += (1.0 - f) * eta * r.shear.sfd;
            for (i, part) in [f, 1.0 - f].into_iter().enumerate() {
                out.ddfddr[i][0] += part * eta * r.dsfd_dh;
                for b in 0..N {
                    out.ddfddr[i][1 + b] += part * eta * r.dsfd_dgam[b];
                }
            }
        }
        let finite = out.flux.iter().all(|v| v.is_finite())
            && out.ddfddt.iter().all(|v| v.is_finite())
            && out.ddfddr.iter().flatten().all(|v| v.is_finite());
        if finite {
            Ok(out)
        } else {
            Err(LawError::Numerical(
                "the heat flux overflowed (inputs too large for f64)".into(),
            ))
        }
    }

    /// The documented safe outputs of a failed call.
    unsafe fn fail(&self) {
        // SAFETY: as in `run`; arrays are written only when NDIR is known to be 2 or 3.
        unsafe {
            if !self.pnewdt.is_null() {
                let current = self.pnewdt.read();
                if current.is_nan() || current > CUTBACK_RATIO {
                    self.pnewdt.write(CUTBACK_RATIO);
                }
            }
            write(self.sfd, 0.0);
            write(self.spd, 0.0);
            if let Ok(ndir @ (2 | 3)) = read(self.ndir, "NDIR") {
                let ndir = ndir as usize;
                write_zeros(self.ddsddr, ndir * ndir);
                write_zeros(self.dviscous, ndir * ndir);
                write_zeros(self.dstructural, ndir * ndir);
                write_zeros(self.ddsddt, 2 * ndir);
                write_zeros(self.ddfddr, 2 * ndir);
                write_zeros(self.ddfddt, 4);
            }
        }
    }
}

#[cold]
#[inline(never)]
fn not_adhesive(code: Option<f64>) -> LawError {
    let code = code.map_or("absent (NPROPS = 0)".to_string(), |c| c.to_string());
    LawError::Parameter(format!(
        "PROPS(1) = {code}: UINTER needs PROPS(1) = 2 (the adhesive interface law); the other \
         laws are tangential only (FRIC)"
    ))
}

#[cold]
#[inline(never)]
fn bad_ndir(ndir: c_int) -> LawError {
    LawError::Parameter(format!(
        "NDIR = {ndir}; expected 2 (2-D: normal + 1 shear) or 3 (3-D: normal + 2 shear)"
    ))
}

/// Where a UINTER message comes from, read only on the error path.
unsafe fn site(ciname: *const c_char, ciname_len: usize, node: *const c_int) -> Site {
    // SAFETY: the host's pointers; NULL reads as "?".
    let num = |p: *const c_int| unsafe { read(p, "") }.map_or("?".to_string(), |v| v.to_string());
    Site {
        routine: "UINTER",
        // SAFETY: CINAME has the hidden length the host passed.
        interaction: unsafe { fortran_string(ciname, ciname_len) },
        place: format!("node {}", num(node)),
    }
}
