//! `fric_`: the Abaqus/Standard FRIC user subroutine.

use std::ffi::{c_char, c_int};
use std::panic::{AssertUnwindSafe, catch_unwind};

use super::{
    boundary, fortran_string, read, read_array, slice, write, write_array, write_matrix,
    write_zeros,
};
use crate::config::friction_table_for;
use crate::laws::coulomb::{Contact, Coulomb, CoulombState, EntryFlag, Increment, StickMode};
use crate::laws::coulomb_extended::{Conditions, ExtendedCoulomb, ExtendedState};
use crate::props::coulomb_extended_with_table;
use crate::props::{FrictionLaw, extended_coulomb, friction_law, plain_coulomb_or_special_case};
use crate::report::Site;
use crate::{CUTBACK_RATIO, LawError};

mod adhesive;
mod rate;

/// Abaqus/Standard `FRIC`: frictional stress, tangents, energies and state of one closed contact
/// point, callable from Fortran as `CALL FRIC(...)` with no interface block.
///
/// Every argument is passed by reference; `INTEGER` is a 32-bit `int`, reals are `double`,
/// arrays are column-major (`DDTDDG(a,b)` is `ddtddg[(a-1) + (b-1)*nfdir]`). The last three
/// arguments are the hidden lengths of `CINAME`, `SLNAME` and `MSNAME` (blank-padded, not
/// NUL-terminated; never read past).
///
/// The law is chosen by `PROPS(1)` (1 = Coulomb; layout in `docs/props.md`). The Coulomb law
/// uses `STATEV(1..3)` (accumulated slip, slip rate, status) and needs `NSTATV ≥ 3`; with
/// tangential damping (`PROPS(17)` > 0) it also keeps the viscous stress in `STATEV(4..3+NFDIR)`
/// and needs `NSTATV ≥ 3 + NFDIR`. `PROPS(1) = 2` selects the adhesive law (seed 004): the same
/// three state variables, always `LM = 0`.
///
/// On entry `LM` is the previous iteration's answer (0 motion, 1 exact stick, 2 frictionless);
/// with `LM = 2` nothing is written. On exit:
/// - `LM = 0`: `TAU(NFDIR)` is the end-of-increment stress; `DDTDDG(NFDIR,NFDIR)`,
///   `DDTDDP(NFDIR)`, `DSLIP`, `SED`, `SFD`, `DDTDDT(NFDIR,2)` and `STATEV` are written.
///   `DDTDDT` is ∂τ/∂`TEMP(1)` and ∂τ/∂`TEMP(2)` (each half of ∂τ/∂θ̄): non-zero when μ depends
///   on temperature (`PROPS(12)`, or a friction table in temperature), zero otherwise.
/// - `LM = 1`: exact stick; `TAU`, `DDTDDG`, `DDTDDP` are not written; `DSLIP = 0`, `SED = 0`,
///   `SFD = 0` and `STATEV` are.
///
/// `PNEWDT` is only ever lowered, and only on failure: a bad argument, a bad `PROPS`, too small
/// an `NSTATV`, `NFDIR` not 1 or 2, a non-finite input or result, or an internal panic sets
/// `PNEWDT = 0.25`, leaves `LM`, `TAU` and `STATEV` unchanged, zeroes `DDTDDG`, `DDTDDP`, `DSLIP`,
/// `DDTDDT` and `SFD` (when `NFDIR` is valid), and reports one line per distinct cause (stderr
/// or `$INTERFACIAL_LOG`; `ifl_last_error` on the calling thread). Input arguments are never
/// written. `DROT` is read only with damping (`PROPS(17)` > 0): the viscous stress kept in
/// `STATEV` is rotated by it before it is taken out of `TAU`; otherwise the law keeps no vector
/// state and `DROT` is not read (the host has already rotated `TAU`).
///
/// # Safety
/// The pointers must be valid for the Abaqus FRIC signature: arrays of `NFDIR`, `NFDIR²`,
/// `NSTATV`, `NPROPS` entries as documented, names of the given hidden lengths. Optional outputs
/// (`DSLIP`, `SED`, `SFD`, `DDTDDT`) may be NULL.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fric_(
    lm: *mut c_int,
    tau: *mut f64,
    ddtddg: *mut f64,
    ddtddp: *mut f64,
    dslip: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    ddtddt: *mut f64,
    pnewdt: *mut f64,
    statev: *mut f64,
    dgam: *const f64,
    taulm: *const f64,
    press: *const f64,
    dpress: *const f64,
    ddpddh: *const f64,
    slip: *const f64,
    kstep: *const c_int,
    kinc: *const c_int,
    time: *const f64,
    dtime: *const f64,
    noel: *const c_int,
    ciname: *const c_char,
    slname: *const c_char,
    msname: *const c_char,
    npt: *const c_int,
    node: *const c_int,
    npatch: *const c_int,
    coords: *const f64,
    rcoord: *const f64,
    drot: *const f64,
    temp: *const f64,
    predef: *const f64,
    nfdir: *const c_int,
    mcrd: *const c_int,
    npred: *const c_int,
    nstatv: *const c_int,
    chrlngth: *const f64,
    props: *const f64,
    nprops: *const c_int,
    ciname_len: usize,
    slname_len: usize,
    msname_len: usize,
) {
    // The plain law (isotropic, constant μ, PROPS(1..7), or the adhesive law's Coulomb special
    // case) with valid arguments takes one pass that tests everything with a few combined
    // branches and never builds an error; anything else (the extended law, bad arguments with
    // their messages) goes out of line to the checked path, which starts afresh (the fast
    // path writes nothing unless it succeeds).
    let handled = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: the host's pointers, valid per the contract above.
        unsafe {
            plain_fast(
                lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, statev, dgam, taulm, press,
                dpress, dtime, nfdir, nstatv, chrlngth, props, nprops,
            )
        }
    }));
    if matches!(handled, Ok(true)) {
        return;
    }
    // SAFETY: the host's pointers, passed on unchanged. The same argument list as `fric_`:
    // packing the pointers into arrays here had cost the plain path above its register
    // allocation (docs/performance.md, fourth pass).
    unsafe {
        fric_general(
            lm, tau, ddtddg, ddtddp, dslip, sed, sfd, ddtddt, pnewdt, statev, dgam, taulm, press,
            dpress, ddpddh, slip, kstep, kinc, time, dtime, noel, ciname, slname, msname, npt,
            node, npatch, coords, rcoord, drot, temp, predef, nfdir, mcrd, npred, nstatv, chrlngth,
            props, nprops, ciname_len, slname_len, msname_len,
        )
    }
}

/// The plain law's call when everything is valid: `true` when the call is done (outputs
/// written, or `LM = 2` on entry), `false` with nothing written when anything is off (a NULL,
/// a size, `PROPS` not the plain layout, a non-finite input or result), for the checked path
/// to handle and name.
///
/// # Safety
/// As `fric_`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
unsafe fn plain_fast(
    lm: *mut c_int,
    tau: *mut f64,
    ddtddg: *mut f64,
    ddtddp: *mut f64,
    dslip: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    ddtddt: *mut f64,
    statev: *mut f64,
    dgam: *const f64,
    taulm: *const f64,
    press: *const f64,
    dpress: *const f64,
    dtime: *const f64,
    nfdir: *const c_int,
    nstatv: *const c_int,
    chrlngth: *const f64,
    props: *const f64,
    nprops: *const c_int,
) -> bool {
    // SAFETY (whole body): every pointer is tested for NULL before it is read; arrays are read
    // with the lengths the host declared, after those were checked.
    unsafe {
        if lm.is_null() {
            return false;
        }
        let entry = match *lm {
            0 => EntryFlag::Motion,
            1 if !taulm.is_null() => EntryFlag::ExactStick,
            // Frictionless: nothing to do, whatever the rest says.
            2 => return true,
            _ => return false,
        };
        let Some(Ok(n)) = get(nprops).map(usize::try_from) else {
            return false;
        };
        if props.is_null() {
            return false;
        }
        let Some(law) = plain_coulomb_or_special_case(std::slice::from_raw_parts(props, n)) else {
            return false;
        };
        match get(nstatv) {
            Some(n) if n >= CoulombState::NSTATV as c_int => {}
            _ => return false,
        }
        let out = Outputs {
            lm,
            tau,
            ddtddg,
            ddtddp,
            dslip,
            sed,
            sfd,
            ddtddt,
            statev,
        };
        let input = Inputs {
            tau,
            dgam,
            taulm,
            press,
            dpress,
            dtime,
            chrlngth,
            statev,
        };
        // Elastic stick (Abaqus's default, and the common case) does not look at the entry
        // flag or TAULM: its own copy of the point, with neither.
        match (get(nfdir), law.stick() == StickMode::Elastic) {
            (Some(1), true) => point_fast::<1, true>(&law, entry, &input, &out),
            (Some(2), true) => point_fast::<2, true>(&law, entry, &input, &out),
            (Some(1), false) => point_fast::<1, false>(&law, entry, &input, &out),
            (Some(2), false) => point_fast::<2, false>(&law, entry, &input, &out),
            _ => false,
        }
    }
}

/// `*p`, or `None` for NULL (read unaligned: Fortran guarantees nothing more than the C ABI).
///
/// # Safety
/// `p` is NULL or points to a readable `T`.
#[inline(always)]
unsafe fn get<T: Copy>(p: *const T) -> Option<T> {
    if p.is_null() {
        None
    } else {
        // SAFETY: non-NULL, readable by contract.
        Some(unsafe { p.read_unaligned() })
    }
}

/// The pointers [`point_fast`] writes through.
struct Outputs {
    lm: *mut c_int,
    tau: *mut f64,
    ddtddg: *mut f64,
    ddtddp: *mut f64,
    dslip: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    ddtddt: *mut f64,
    statev: *mut f64,
}

impl Outputs {
    /// Writes a successful answer: `STATEV(1..3)`, `LM`, and with relative motion `TAU`,
    /// `DDTDDG`, `DDTDDP`, `DSLIP`, `SED`, `SFD` and both columns of `DDTDDT` (each
    /// `ddtddt_column`); in exact stick `DSLIP`, `SED` and `SFD` are zero and the rest is left
    /// alone. NULL optional outputs are skipped.
    ///
    /// # Safety
    /// The pointers as `fric_` documents them, for NFDIR = N.
    #[inline(always)]
    unsafe fn write_answer<const N: usize>(
        &self,
        contact: &Contact<N>,
        state: &CoulombState,
        ddtddt_column: &[f64; N],
    ) {
        // SAFETY: arrays of N, N·N, 2N and NSTATV ≥ 3 entries per the FRIC contract.
        unsafe {
            let mut end_state = [0.0; CoulombState::NSTATV];
            state.write_statev(&mut end_state);
            write_array(self.statev, &end_state);
            match contact {
                Contact::ExactStick => {
                    write(self.lm, 1);
                    write_array(self.dslip, &[0.0; N]);
                    write(self.sed, 0.0);
                    write(self.sfd, 0.0);
                }
                Contact::Motion(t) => {
                    write(self.lm, 0);
                    write_array(self.tau, &t.tau);
                    write_matrix(self.ddtddg, &t.ddtddg);
                    write_array(self.ddtddp, &t.ddtddp);
                    write_array(self.dslip, &t.dslip);
                    write(self.sed, t.sed);
                    write(self.sfd, t.sfd);
                    if !self.ddtddt.is_null() {
                        write_array(self.ddtddt, ddtddt_column);
                        write_array(self.ddtddt.add(N), ddtddt_column);
                    }
                }
            }
        }
    }
}

/// The pointers [`point_fast`] reads.
struct Inputs {
    tau: *const f64,
    dgam: *const f64,
    taulm: *const f64,
    press: *const f64,
    dpress: *const f64,
    dtime: *const f64,
    chrlngth: *const f64,
    statev: *const f64,
}

/// One contact point of the plain law, N = NFDIR: as [`FricArgs::point`], with every test
/// folded into the few branches of [`Coulomb::try_update`]; `false` (nothing written) when a
/// pointer is NULL or an input or result is not finite.
///
/// # Safety
/// As `fric_`, with `NSTATV ≥ 3` checked.
#[inline(always)]
unsafe fn point_fast<const N: usize, const ELASTIC: bool>(
    law: &Coulomb,
    entry: EntryFlag,
    input: &Inputs,
    out: &Outputs,
) -> bool {
    let exact = entry == EntryFlag::ExactStick;
    // SAFETY (whole body): each pointer is tested for NULL right before it is read (one branch
    // each, and no load moves in front of its test); arrays of N, N·N, 2N and NSTATV ≥ 3
    // entries per the FRIC contract.
    unsafe {
        let Some(pressure) = get(input.press) else {
            return false;
        };
        let Some(dpressure) = get(input.dpress) else {
            return false;
        };
        let Some(tau) = get(input.tau.cast::<[f64; N]>()) else {
            return false;
        };
        let Some(dgam) = get(input.dgam.cast::<[f64; N]>()) else {
            return false;
        };
        // Elastic stick does not read TAULM (a NULL one with LM = 1 is refused by
        // `plain_fast`, as the checked path refuses it).
        let taulm = if ELASTIC || !exact {
            [0.0; N]
        } else {
            let Some(taulm) = get(input.taulm.cast::<[f64; N]>()) else {
                return false;
            };
            taulm
        };
        let Some(dtime) = get(input.dtime) else {
            return false;
        };
        let Some(characteristic_length) = get(input.chrlngth) else {
            return false;
        };
        let inc = Increment::<N> {
            tau,
            dgam,
            taulm,
            pressure,
            dpressure,
            dtime,
            characteristic_length,
            // Elastic stick does not read the entry flag.
            entry: if ELASTIC { EntryFlag::Motion } else { entry },
        };
        let Some([s, rate, status]) = get(input.statev.cast::<[f64; 3]>()) else {
            return false;
        };
        // Tested for finiteness with the inputs by `try_update`.
        let state = CoulombState::from_values_unchecked(s, rate, status);
        let Some(up) = law.try_update(&inc, &state) else {
            return false;
        };
        // DDTDDT(NFDIR,2) = 0: μ does not depend on temperature.
        out.write_answer(&up.contact, &up.state, &[0.0; N]);
        // The plain law always converges: PNEWDT is left alone.
        true
    }
}

/// `fric_` for everything but the plain law: the extended law, and every bad `PROPS` with its
/// message. Out of line, with the pointers passed as plain values.
///
/// # Safety
/// As `fric_`.
// `cold` only for code layout and register allocation of the plain path in `fric_`; the
// extended law is still fast once here (its own fast PROPS parser, docs/benchmarks.md).
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
unsafe extern "C" fn fric_general(
    lm: *mut c_int,
    tau: *mut f64,
    ddtddg: *mut f64,
    ddtddp: *mut f64,
    dslip: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    ddtddt: *mut f64,
    pnewdt: *mut f64,
    statev: *mut f64,
    dgam: *const f64,
    taulm: *const f64,
    press: *const f64,
    dpress: *const f64,
    ddpddh: *const f64,
    slip: *const f64,
    kstep: *const c_int,
    kinc: *const c_int,
    time: *const f64,
    dtime: *const f64,
    noel: *const c_int,
    ciname: *const c_char,
    slname: *const c_char,
    msname: *const c_char,
    npt: *const c_int,
    node: *const c_int,
    npatch: *const c_int,
    coords: *const f64,
    rcoord: *const f64,
    drot: *const f64,
    temp: *const f64,
    predef: *const f64,
    nfdir: *const c_int,
    mcrd: *const c_int,
    npred: *const c_int,
    nstatv: *const c_int,
    chrlngth: *const f64,
    props: *const f64,
    nprops: *const c_int,
    ciname_len: usize,
    slname_len: usize,
    msname_len: usize,
) {
    let _ = (ddpddh, slip, kstep, kinc, time, npatch, rcoord, predef);
    let _ = (npred, slname, msname, slname_len, msname_len);
    let args = FricArgs {
        lm,
        tau,
        ddtddg,
        ddtddp,
        dslip,
        sed,
        sfd,
        ddtddt,
        pnewdt,
        statev,
        dgam,
        taulm,
        press,
        dpress,
        dtime,
        nfdir,
        nstatv,
        chrlngth,
        props,
        nprops,
        temp,
        drot,
        coords,
        mcrd,
    };
    let _ = boundary(
        // SAFETY (all three closures): the pointers are the host's, valid per the contract above.
        || unsafe { site(ciname, ciname_len, noel, node, npt) },
        // The rate law's lean layout first (`rate.rs`), then the checked path.
        || unsafe {
            if args.decay_fast() {
                Ok(())
            } else {
                args.run(ciname, ciname_len)
            }
        },
        || unsafe { args.fail() },
    );
}

/// The arguments `fric_` reads or writes, gathered so the generic body can be written once.
struct FricArgs {
    lm: *mut c_int,
    tau: *mut f64,
    ddtddg: *mut f64,
    ddtddp: *mut f64,
    dslip: *mut f64,
    sed: *mut f64,
    sfd: *mut f64,
    ddtddt: *mut f64,
    pnewdt: *mut f64,
    statev: *mut f64,
    dgam: *const f64,
    taulm: *const f64,
    press: *const f64,
    dpress: *const f64,
    dtime: *const f64,
    nfdir: *const c_int,
    nstatv: *const c_int,
    chrlngth: *const f64,
    props: *const f64,
    nprops: *const c_int,
    temp: *const f64,
    drot: *const f64,
    coords: *const f64,
    mcrd: *const c_int,
}

impl FricArgs {
    /// The output pointers, for [`Outputs::write_answer`].
    #[inline(always)]
    fn outputs(&self) -> Outputs {
        Outputs {
            lm: self.lm,
            tau: self.tau,
            ddtddg: self.ddtddg,
            ddtddp: self.ddtddp,
            dslip: self.dslip,
            sed: self.sed,
            sfd: self.sfd,
            ddtddt: self.ddtddt,
            statev: self.statev,
        }
    }

    /// Checks the sizes and the law once, then runs the NFDIR-specific code.
    #[inline(always)]
    /// `ciname` (of `ciname_len` bytes) is read only when `PROPS(8) = 2` asks for the
    /// interaction's μ table.
    unsafe fn run(&self, ciname: *const c_char, ciname_len: usize) -> Result<(), LawError> {
        // SAFETY (whole body): pointers valid per the FRIC contract; every array is read with
        // the length the host declared, after that length was checked.
        unsafe {
            let lm_in = read(self.lm, "LM")?;
            if lm_in == 2 {
                return Ok(());
            }
            let entry = match lm_in {
                0 => EntryFlag::Motion,
                1 => EntryFlag::ExactStick,
                other => return Err(bad_lm(other)),
            };
            let nprops = read(self.nprops, "NPROPS")?;
            let Ok(nprops) = usize::try_from(nprops) else {
                return Err(negative_nprops(nprops));
            };
            let props = slice(self.props, nprops, "PROPS")?;
            // The extended law's own fast path (no FrictionLaw built and moved).
            if let Some(law) = extended_coulomb(props) {
                let nstatv = self.nstatv()?;
                return match read(self.nfdir, "NFDIR")? {
                    1 => self.point_extended::<1>(&law, entry, nstatv),
                    2 => self.point_extended::<2>(&law, entry, nstatv),
                    other => Err(bad_nfdir(other)),
                };
            }
            let law = if props.get(7) == Some(&2.0) {
                // μ table (PROPS(8) = 2): the interaction's, from the configuration file.
                let name = if ciname.is_null() {
                    &[][..]
                } else {
                    std::slice::from_raw_parts(ciname.cast::<u8>(), ciname_len)
                };
                coulomb_extended_with_table(props, Some(friction_table_for(name)?))?
            } else {
                friction_law(props)?
            };
            match law {
                FrictionLaw::Coulomb(law) => {
                    let nstatv = self.nstatv()?;
                    match read(self.nfdir, "NFDIR")? {
                        1 => self.point::<1>(&law, entry, nstatv),
                        2 => self.point::<2>(&law, entry, nstatv),
                        other => Err(bad_nfdir(other)),
                    }
                }
                FrictionLaw::CoulombExtended(law) => {
                    let nstatv = self.nstatv()?;
                    match read(self.nfdir, "NFDIR")? {
                        1 => self.point_extended::<1>(&law, entry, nstatv),
                        2 => self.point_extended::<2>(&law, entry, nstatv),
                        other => Err(bad_nfdir(other)),
                    }
                }
                // (S_a = k_μ = v_½ = 0, μ_s = μ_d comes as the Coulomb law.)
                FrictionLaw::Adhesive(a) => self.adhesive(&a.law),
            }
        }
    }

    /// `NSTATV`, at least the Coulomb law's 3.
    #[inline(always)]
    unsafe fn nstatv(&self) -> Result<usize, LawError> {
        // SAFETY: NSTATV is a valid pointer or NULL per the FRIC contract.
        let nstatv = unsafe { read(self.nstatv, "NSTATV") }?;
        match usize::try_from(nstatv) {
            Ok(n) if n >= CoulombState::NSTATV => Ok(n),
            _ => Err(short_nstatv(nstatv)),
        }
    }

    /// One contact point with N = NFDIR friction directions. Everything is computed before the
    /// first output is written, so a failure leaves the caller's arrays as they were.
    #[inline(always)]
    unsafe fn point<const N: usize>(
        &self,
        law: &Coulomb,
        entry: EntryFlag,
        nstatv: usize,
    ) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of N, N·N and NSTATV entries per the FRIC contract.
        unsafe {
            let inc = Increment::<N> {
                tau: read_array(self.tau, "TAU")?,
                dgam: read_array(self.dgam, "DGAM")?,
                taulm: if entry == EntryFlag::ExactStick {
                    read_array(self.taulm, "TAULM")?
                } else {
                    [0.0; N]
                },
                pressure: read(self.press, "PRESS")?,
                dpressure: read(self.dpress, "DPRESS")?,
                dtime: read(self.dtime, "DTIME")?,
                characteristic_length: read(self.chrlngth, "CHRLNGTH")?,
                entry,
            };
            let state = CoulombState::from_statev(slice(self.statev, nstatv, "STATEV")?)?;
            let up = law.update(&inc, &state)?;
            // DDTDDT(NFDIR,2) = 0: μ does not depend on temperature.
            self.outputs()
                .write_answer(&up.contact, &up.state, &[0.0; N]);
            let ratio = up.outcome.step_ratio;
            if ratio.is_finite() && !self.pnewdt.is_null() && ratio < self.pnewdt.read() {
                self.pnewdt.write(ratio);
            }
            Ok(())
        }
    }

    /// One contact point with the extended Coulomb law (anisotropy, μ law, HHT, damping).
    /// Computes everything before writing, like [`Self::point`].
    unsafe fn point_extended<const N: usize>(
        &self,
        law: &ExtendedCoulomb,
        entry: EntryFlag,
        nstatv: usize,
    ) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of N, N·N, 2N, NSTATV, 2 and 4 entries per the FRIC
        // contract; STATEV is read only up to the checked NSTATV.
        unsafe {
            let needed = law.nstatv(N);
            if nstatv < needed {
                return Err(short_nstatv_extended(nstatv, needed));
            }
            let inc = Increment::<N> {
                tau: read_array(self.tau, "TAU")?,
                dgam: read_array(self.dgam, "DGAM")?,
                taulm: if entry == EntryFlag::ExactStick {
                    read_array(self.taulm, "TAULM")?
                } else {
                    [0.0; N]
                },
                pressure: read(self.press, "PRESS")?,
                dpressure: read(self.dpress, "DPRESS")?,
                dtime: read(self.dtime, "DTIME")?,
                characteristic_length: read(self.chrlngth, "CHRLNGTH")?,
                entry,
            };
            let mut conditions = Conditions::default();
            if law.reads_temperature() {
                let [t1, t2] = read_array::<2>(self.temp, "TEMP")?;
                conditions.temperature = 0.5 * (t1 + t2);
            }
            if law.damping().is_some() && N == 2 {
                // DROT(2,2), column-major: DROT(a,b) at (a-1) + 2(b-1).
                let r = read_array::<4>(self.drot, "DROT")?;
                conditions.drot = [[r[0], r[2]], [r[1], r[3]]];
            }
            if law.steady_transport().is_some() {
                // The radius R of γ̇_crit = 2 F_f ω R (or F_f ω R) comes from COORDS(1..MCRD).
                let mcrd = read(self.mcrd, "MCRD")?;
                let n = match usize::try_from(mcrd) {
                    Ok(n) if (1..=3).contains(&n) => n,
                    _ => return Err(bad_mcrd(mcrd)),
                };
                let c = slice(self.coords, n, "COORDS")?;
                if !c.iter().all(|x| x.is_finite()) {
                    return Err(LawError::Input("COORDS is NaN or infinite".into()));
                }
                conditions.coords[..n].copy_from_slice(c);
                conditions.ncoords = n;
            }
            let statev = slice(self.statev, nstatv, "STATEV")?;
            let mut state = ExtendedState::<N> {
                coulomb: CoulombState::from_statev(statev)?,
                viscous: [0.0; N],
            };
            if law.damping().is_some() {
                state.viscous.copy_from_slice(&statev[3..3 + N]);
            }
            let up = law.update(&inc, &conditions, &state)?;
            let mut end_state = [0.0; CoulombState::NSTATV];
            up.state.coulomb.write_statev(&mut end_state);
            write_array(self.statev, &end_state);
            if law.damping().is_some() {
                write_array(self.statev.add(3), &up.state.viscous);
            }
            match up.contact {
                Contact::ExactStick => {
                    write(self.lm, 1);
                    write_array(self.dslip, &[0.0; N]);
                    write(self.sed, 0.0);
                    write(self.sfd, 0.0);
                }
                Contact::Motion(t) => {
                    write(self.lm, 0);
                    write_array(self.tau, &t.tau);
                    write_matrix(self.ddtddg, &t.ddtddg);
                    write_array(self.ddtddp, &t.ddtddp);
                    write_array(self.dslip, &t.dslip);
                    write(self.sed, t.sed);
                    write(self.sfd, t.sfd);
                    // DDTDDT(a,1) and DDTDDT(a,2): θ̄ = (θ_slave + θ_master)/2, so each
                    // surface temperature carries half of ∂τ/∂θ̄.
                    if !self.ddtddt.is_null() {
                        let half = scale_half(&up.ddtdtheta);
                        write_array(self.ddtddt, &half);
                        write_array(self.ddtddt.add(N), &half);
                    }
                }
            }
            let ratio = up.outcome.step_ratio;
            if ratio.is_finite() && !self.pnewdt.is_null() && ratio < self.pnewdt.read() {
                self.pnewdt.write(ratio);
            }
            Ok(())
        }
    }

    /// The documented safe outputs of a failed call. Inlined, so that no call takes the
    /// arguments' address (which would keep them in memory on every call).
    #[inline(always)]
    unsafe fn fail(&self) {
        // SAFETY: as in `run`; arrays are written only when NFDIR is known to be 1 or 2.
        unsafe {
            if !self.pnewdt.is_null() {
                let current = self.pnewdt.read();
                if current.is_nan() || current > CUTBACK_RATIO {
                    self.pnewdt.write(CUTBACK_RATIO);
                }
            }
            write(self.sfd, 0.0);
            match read(self.nfdir, "NFDIR") {
                Ok(1) => self.zero_tangents::<1>(),
                Ok(2) => self.zero_tangents::<2>(),
                _ => {}
            }
        }
    }

    #[inline(always)]
    unsafe fn zero_tangents<const N: usize>(&self) {
        // SAFETY: N = NFDIR entries per array, N·N for the matrices, 2N for DDTDDT.
        unsafe {
            write_matrix::<N>(self.ddtddg, &[[0.0; N]; N]);
            write_array::<N>(self.ddtddp, &[0.0; N]);
            write_array::<N>(self.dslip, &[0.0; N]);
            write_zeros(self.ddtddt, 2 * N);
        }
    }
}

#[cold]
#[inline(never)]
fn bad_lm(lm: c_int) -> LawError {
    LawError::Input(format!("LM = {lm} on entry; expected 0, 1 or 2"))
}

#[cold]
#[inline(never)]
fn negative_nprops(nprops: c_int) -> LawError {
    LawError::Parameter(format!("NPROPS = {nprops} is negative"))
}

#[cold]
#[inline(never)]
fn short_nstatv(nstatv: c_int) -> LawError {
    LawError::Parameter(format!(
        "NSTATV = {nstatv} but the Coulomb law needs {} state variables (*DEPVAR / the NSTATV \
         of *FRICTION, USER)",
        CoulombState::NSTATV
    ))
}

fn scale_half<const N: usize>(v: &[f64; N]) -> [f64; N] {
    let mut out = *v;
    for x in &mut out {
        *x *= 0.5;
    }
    out
}

#[cold]
#[inline(never)]
fn bad_mcrd(mcrd: c_int) -> LawError {
    LawError::Input(format!(
        "MCRD = {mcrd}; steady-state transport needs the point's coordinates (MCRD 1 to 3)"
    ))
}

#[cold]
#[inline(never)]
fn short_nstatv_extended(nstatv: usize, needed: usize) -> LawError {
    LawError::Parameter(format!(
        "NSTATV = {nstatv} but the Coulomb law with tangential damping needs {needed} (3 + NFDIR: \
         STATEV(4..) keep the viscous stress)"
    ))
}

#[cold]
#[inline(never)]
fn bad_nfdir(nfdir: c_int) -> LawError {
    LawError::Parameter(format!("NFDIR = {nfdir}; expected 1 (2-D) or 2 (3-D)"))
}

/// Where a FRIC message comes from, read only on the error path.
unsafe fn site(
    ciname: *const c_char,
    ciname_len: usize,
    noel: *const c_int,
    node: *const c_int,
    npt: *const c_int,
) -> Site {
    // SAFETY: the host's pointers; NULL reads as "?".
    let num = |p: *const c_int| unsafe { read(p, "") }.map_or("?".to_string(), |v| v.to_string());
    Site {
        routine: "FRIC",
        // SAFETY: CINAME has the hidden length the host passed.
        interaction: unsafe { fortran_string(ciname, ciname_len) },
        place: format!(
            "element {}, node {}, point {}",
            num(noel),
            num(node),
            num(npt)
        ),
    }
}
