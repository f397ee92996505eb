//! `uinter_`: the Abaqus/Standard UINTER user subroutine. A thin shell: one argument view
//! (`UinterArgs`), the law the props layer selects (`props::interface_law`; today the adhesive
//! interface: normal contact, separation adhesion, friction and heat exchange), one reader of the increment, one writer of the outputs, one panic boundary. The
//! physics, the heat exchange included, is in the laws (docs/architecture.md, "The `uinter_`
//! shell").

use std::ffi::{c_char, c_int};

use super::{
    count, cut_back, fortran_name_bytes, host_number, host_site, read, read_array, short_nstatv,
    slice, write, write_zeros,
};
use crate::LawError;
use crate::config;
use crate::laws::adhesive_interface::{InterfaceIncrement, InterfaceState};
use crate::laws::interface_heat::{FrictionalHeating, GapConduction, InterfaceHeat};
use crate::props::{AdhesiveProps, interface_law};
use crate::report::Site;

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
// The view `UinterArgs` (the arguments `uinter_` reads or writes: a field per parameter but the
// `unread` ones, bound to `args`) is written by the attribute from this parameter list (macros/).
#[interfacial_macros::with_view(
    view = struct UinterArgs as args,
    unread = (dtemp, predef, dpred, time, freqr, slname, msname, coords, alocaldir, drot, area,
              npred, mcrd, kstep, kinc, kit, linper, lsdi, lprint, slname_len, msname_len),
)]
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
    fortran_boundary!(
        args,
        // SAFETY: the name of its hidden length and NODE, per the contract above.
        || unsafe { site(args.ciname, args.ciname_len, args.node) }
    );
}

/// What every UINTER law answers for one point with N = NDIR − 1 tangential directions: the
/// one writer ([`UinterArgs::write_answer`]) puts it where the host expects it.
struct UinterAnswer<'a, const N: usize> {
    /// `STRESS(1)`, the normal stress (positive in compression).
    normal_stress: f64,
    /// `STRESS(2..NDIR)`.
    shear: [f64; N],
    /// `DDSDDR(1,1)` = ∂p/∂h.
    dp_dh: f64,
    /// `DDSDDR(1,1+b)` = ∂p/∂Δγ_b.
    dp_dgam: [f64; N],
    /// `DDSDDR(1+a,1)` = ∂τ_a/∂h.
    dtau_dh: [f64; N],
    /// `DDSDDR(1+a,1+b)` = ∂τ_a/∂Δγ_b.
    dtau_dgam: [[f64; N]; N],
    /// `FLUX`, `DDFDDT`, `DDFDDR`.
    heat: InterfaceHeat,
    /// `STATEV(1..len)` at the end, in the law's layout.
    statev: &'a [f64],
    /// `SED`, `SFD`, `SPD`.
    sed: f64,
    sfd: f64,
    spd: f64,
    /// `LOPENCLOSE`.
    closed: bool,
    /// `LSTATE`.
    lstate: c_int,
}

impl UinterArgs {
    unsafe fn run(&self) -> Result<(), LawError> {
        // SAFETY (whole body): pointers valid per the UINTER contract; sizes checked first.
        unsafe {
            let nprops = count("NPROPS", read(self.nprops, "NPROPS")?)?;
            let props = slice(self.props, nprops, "PROPS")?;
            // The law PROPS select (the props layer refuses a law UINTER does not serve).
            self.adhesive(&interface_law(props)?)
        }
    }

    /// `NSTATV`, which must be at least `needed` (the law's state variables).
    unsafe fn nstatv(&self, needed: usize, law: &str) -> Result<usize, LawError> {
        // SAFETY: NSTATV readable per the contract (NULL refused by name).
        let nstatv = unsafe { read(self.nstatv, "NSTATV")? };
        match usize::try_from(nstatv) {
            Ok(n) if n >= needed => Ok(n),
            _ => Err(short_nstatv(
                nstatv.into(),
                needed,
                law,
                "*DEPVAR / the NSTATV of *SURFACE INTERACTION, USER",
            )),
        }
    }

    /// The adhesive interface, 3 state variables.
    unsafe fn adhesive(&self, props: &AdhesiveProps) -> Result<(), LawError> {
        // SAFETY (whole body): pointers valid per the UINTER contract.
        unsafe {
            let nstatv = self.nstatv(InterfaceState::NSTATV, InterfaceState::LAW)?;
            match read(self.ndir, "NDIR")? {
                2 => self.adhesive_point::<1>(props, nstatv),
                3 => self.adhesive_point::<2>(props, nstatv),
                other => Err(bad_ndir(other)),
            }
        }
    }

    /// One point of the adhesive interface; everything is computed before the first output
    /// is written.
    unsafe fn adhesive_point<const N: usize>(
        &self,
        props: &AdhesiveProps,
        nstatv: usize,
    ) -> Result<(), LawError> {
        let interface = props.interface()?;
        // SAFETY (whole body): pointers valid per the UINTER contract, NDIR = N + 1.
        unsafe {
            let (inc, statev) = self.increment::<N>(nstatv)?;
            let state = InterfaceState::from_statev(statev)?;
            let r = interface.update(&inc, &state)?;
            let conduction = if props.heat.conductance {
                Some(self.conduction()?)
            } else {
                None
            };
            let heating = FrictionalHeating {
                heat_fraction: props.heat.heat_fraction,
                slave_fraction: props.heat.slave_fraction,
            };
            let heat = InterfaceHeat::exchange(conduction, heating, &r.mechanical_answer(&inc))?;
            let mut end_state = [0.0; InterfaceState::NSTATV];
            r.state.write_statev(&mut end_state);
            // ∂τ_a/∂h = ∂τ_a/∂p · ∂p/∂h.
            let dtau_dh = r.shear.ddtddp.map(|d| d * r.dp_dh);
            self.write_answer(&UinterAnswer::<N> {
                normal_stress: r.normal_stress,
                shear: r.shear.tau,
                dp_dh: r.dp_dh,
                dp_dgam: [0.0; N],
                dtau_dh,
                dtau_dgam: r.shear.ddtddg,
                heat,
                statev: &end_state,
                sed: r.sed,
                sfd: r.shear.sfd,
                spd: r.spd,
                closed: r.closed,
                lstate: r.state.status as c_int,
            });
            Ok(())
        }
    }

    /// The one reader of the increment, for every UINTER law: `STRESS`, `RDISP`, `DRDISP`
    /// (NDIR = N + 1 entries each), `DTIME`, `CHRLNGTH`, then `STATEV(NSTATV)`, in this
    /// order (the first bad one is the message).
    unsafe fn increment<'a, const N: usize>(
        &self,
        nstatv: usize,
    ) -> Result<(InterfaceIncrement<N>, &'a [f64]), LawError> {
        // SAFETY (whole body): arrays of NDIR and NSTATV entries per the contract.
        unsafe {
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
            Ok((inc, slice(self.statev, nstatv, "STATEV")?))
        }
    }

    /// The thermal inputs of gap conduction: the interaction's GAPCON law from
    /// `INTERFACIAL_CONFIG` (keyed by `CINAME`), then `TEMP(2)`.
    unsafe fn conduction(&self) -> Result<GapConduction<'static>, LawError> {
        // SAFETY: CINAME of its hidden length, TEMP(2) readable per the contract.
        unsafe {
            // A NULL name or an implausible hidden length (an address) reads as no name.
            let name = fortran_name_bytes(self.ciname, self.ciname_len);
            let law = config::gap_law_for(name)?;
            let [theta_slave, theta_master] = read_array::<2>(self.temp, "TEMP")?;
            Ok(GapConduction {
                law,
                theta_slave,
                theta_master,
            })
        }
    }

    /// The one writer of a successful answer: every output UINTER defines (optional ones
    /// only when not NULL); `DVISCOUS`, `DSTRUCTURAL`, `DDSDDT`, `SVD`, `SCD` zero.
    unsafe fn write_answer<const N: usize>(&self, a: &UinterAnswer<'_, N>) {
        // SAFETY (whole body): arrays of NDIR, NDIR², 2, 4, 2·NDIR and NSTATV entries.
        unsafe {
            let ndir = N + 1;
            for (i, v) in a.statev.iter().enumerate() {
                self.statev.add(i).write(*v);
            }
            self.stress.write(a.normal_stress);
            for i in 0..N {
                self.stress.add(1 + i).write(a.shear[i]);
            }
            if !self.ddsddr.is_null() {
                let at = |i: usize, j: usize| self.ddsddr.add(i + j * ndir);
                at(0, 0).write(a.dp_dh);
                for i in 0..N {
                    at(0, 1 + i).write(a.dp_dgam[i]);
                    at(1 + i, 0).write(a.dtau_dh[i]);
                    for j in 0..N {
                        at(1 + i, 1 + j).write(a.dtau_dgam[i][j]);
                    }
                }
            }
            write_zeros(self.dviscous, ndir * ndir);
            write_zeros(self.dstructural, ndir * ndir);
            write_zeros(self.ddsddt, 2 * ndir);
            if !self.flux.is_null() {
                self.flux.write(a.heat.flux[0]);
                self.flux.add(1).write(a.heat.flux[1]);
            }
            if !self.ddfddt.is_null() {
                for (k, v) in a.heat.ddfddt.iter().enumerate() {
                    self.ddfddt.add(k).write(*v);
                }
            }
            if !self.ddfddr.is_null() {
                for i in 0..2 {
                    for j in 0..ndir {
                        self.ddfddr.add(i + 2 * j).write(a.heat.ddfddr[i][j]);
                    }
                }
            }
            write(self.sed, a.sed);
            write(self.sfd, a.sfd);
            write(self.spd, a.spd);
            write(self.svd, 0.0);
            write(self.scd, 0.0);
            write(self.lopenclose, c_int::from(a.closed));
            write(self.lstate, a.lstate);
        }
    }

    /// The documented safe outputs of a failed call.
    unsafe fn fail(&self) {
        // SAFETY: as in `run`; arrays are written only when NDIR is known to be 2 or 3.
        unsafe {
            cut_back(self.pnewdt);
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
fn bad_ndir(ndir: c_int) -> LawError {
    LawError::Parameter(format!(
        "NDIR = {ndir}; expected 2 (2-D: normal + 1 shear) or 3 (3-D: normal + 2 shear)"
    ))
}

/// Where a UINTER message comes from, read only on the error path.
unsafe fn site(ciname: *const c_char, ciname_len: usize, node: *const c_int) -> Site {
    // SAFETY: the host's pointers: CINAME of its hidden length, NODE or NULL.
    unsafe {
        host_site(
            "UINTER",
            ciname,
            ciname_len,
            format!("node {}", host_number(node)),
        )
    }
}
