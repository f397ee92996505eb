//! `fric_`: the Abaqus/Standard FRIC user subroutine.

use std::any::Any;
use std::cell::Cell;
use std::ffi::{c_char, c_int};
use std::panic::{AssertUnwindSafe, catch_unwind};

use super::{
    bad_lm, boundary_outlined, count, cut_back, fortran_name_bytes, host_number, host_site,
    null_pointer, read, read_array, short_nstatv, slice, write, write_array, write_matrix,
    write_zeros,
};
use crate::LawError;
use crate::config::friction_table_for;
use crate::laws::contact::{Conditions, Contact, EntryFlag, Increment, mean_surface_temperature};
use crate::laws::coulomb::{Coulomb, CoulombState, StickMode};
use crate::laws::point_law::{Needs, PointInput, PointLaw, PointLawTask};
use crate::props::{fast_extended_coulomb, fast_plain_coulomb, friction_law_with_table};
use crate::report::Site;

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
/// three state variables, always `LM = 0`. `PROPS(1) = 3` selects rate-and-state friction
/// (Dieterich–Ruina): the same three and the state θ in `STATEV(4)` (`NSTATV ≥ 4`), always
/// `LM = 0`.
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
// Written by the attribute from this parameter list (macros/): the view `FricArgs` (a field
// per parameter but the `unread` ones), bound to `args` in both functions, and the twin
// `fric_general`, with the same list, which `fric_` calls when its body does not return.
#[interfacial_macros::with_twin(
    view =
        /// The arguments `fric_` reads or writes: the one view of the host's call that every
        /// path works on (the plain path in `fric_`, everything else in `fric_general`), one
        /// field per parameter of `fric_` but the unread ones, same name, same type. Its
        /// address is never taken on the plain path, so it lives in registers there.
        #[derive(Clone, Copy)]
        struct FricArgs as args,
    // Not read (the laws need none of them; `DROT` is read only by the damping law in 3-D).
    unread = (ddpddh, slip, kstep, kinc, time, npatch, rcoord, predef, npred, slname, msname,
              slname_len, msname_len),
    twin =
        /// `fric_` for everything but the plain law, inside the export's boundary
        /// (`abi::boundary_outlined`: an error or a panic gets the safe outputs of
        /// `FricArgs::fail` and one report; a call, never inlined here). Out of line and `cold`
        /// (code layout and register allocation of the plain path).
        ///
        /// It has `fric_`'s parameter list on purpose: `fric_` ends in a sibling call (a jump,
        /// the arguments left where the host put them). Packing them into one view passed by
        /// reference instead cost the plain path 18–22 instructions per call (the six register
        /// arguments then stay in registers across it; measured 2026-11-26, issue 19) and three
        /// arrays of pointers 37 (docs/performance.md, fourth pass).
        ///
        /// # Safety
        /// As `fric_`.
        #[cold]
        #[inline(never)]
        unsafe extern "C" fn fric_general {
            let _ = boundary_outlined(
                // SAFETY (all three closures): the host's pointers, valid per the contract above.
                || unsafe { args.site() },
                || {
                    if let Some(payload) = HANDED_OVER.take() {
                        std::panic::resume_unwind(payload);
                    }
                    unsafe { args.general() }
                },
                || unsafe { args.fail() },
            );
        },
)]
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
    // The plain law's fast path on the view `args`; anything else goes out of line to
    // `fric_general` with `fric_`'s own arguments (the call the attribute writes after the last
    // statement, a sibling call: nothing is copied or packed on the plain path,
    // docs/performance.md, fourth pass).
    // SAFETY: the host's pointers, valid per the contract above.
    match catch_unwind(AssertUnwindSafe(|| unsafe { args.plain_fast() })) {
        Ok(true) => return,
        Ok(false) => {}
        // Not answered here: handed to the export's one boundary in `fric_general`, which
        // raises it again before anything else (no retry) and reports it.
        Err(payload) => hand_over(payload),
    }
}

thread_local! {
    /// A panic of `fric_`'s plain path on this thread, on its way to the export's boundary.
    static HANDED_OVER: Cell<Option<Box<dyn Any + Send>>> = const { Cell::new(None) };
}

/// Keeps a panic of the plain path for `fric_general`'s boundary.
#[cold]
#[inline(never)]
fn hand_over(payload: Box<dyn Any + Send>) {
    HANDED_OVER.set(Some(payload));
}

/// How a read of a host pointer refuses a NULL: quietly (`()`, the fast paths, which then
/// decline and leave the call to the checked path) or with a message naming the argument
/// (`LawError`, the checked path). One reader serves both, so both read the same arguments.
trait Refusal: Sized {
    fn null(name: &'static str) -> Self;
}

impl Refusal for () {
    #[inline(always)]
    fn null(_: &'static str) {}
}

impl Refusal for LawError {
    #[inline(always)]
    fn null(name: &'static str) -> Self {
        null_pointer(name)
    }
}

/// `*p`, or the refusal naming `name` for NULL (read unaligned: Fortran guarantees nothing
/// more than the C ABI).
///
/// # Safety
/// `p` is NULL or points to a readable `T`.
#[inline(always)]
unsafe fn arg<T: Copy, E: Refusal>(p: *const T, name: &'static str) -> Result<T, E> {
    if p.is_null() {
        Err(E::null(name))
    } else {
        // SAFETY: non-NULL, readable by contract.
        Ok(unsafe { p.read_unaligned() })
    }
}

/// `*p`, or `None` for NULL (the fast paths' reads of sizes and flags).
///
/// # Safety
/// `p` is NULL or points to a readable `T`.
#[inline(always)]
unsafe fn get<T: Copy>(p: *const T) -> Option<T> {
    // SAFETY: as `arg`.
    unsafe { arg::<T, ()>(p, "") }.ok()
}

impl FricArgs {
    /// The plain law's call when everything is valid: `true` when the call is done (outputs
    /// written, or `LM = 2` on entry), `false` with nothing written when anything is off (a
    /// NULL, a size, `PROPS` not the plain layout, a non-finite input or result).
    ///
    /// # Safety
    /// As `fric_`.
    #[inline(always)]
    unsafe fn plain_fast(&self) -> bool {
        // SAFETY (whole body): every pointer is tested for NULL before it is read; arrays are
        // read with the lengths the host declared, after those were checked.
        unsafe {
            let entry = match get(self.lm) {
                Some(0) => EntryFlag::Motion,
                Some(1) if !self.taulm.is_null() => EntryFlag::ExactStick,
                // Frictionless: nothing to do, whatever the rest says.
                Some(2) => return true,
                _ => return false,
            };
            let Some(Ok(n)) = get(self.nprops).map(usize::try_from) else {
                return false;
            };
            if self.props.is_null() {
                return false;
            }
            let Some(law) = fast_plain_coulomb(std::slice::from_raw_parts(self.props, n)) else {
                return false;
            };
            match get(self.nstatv) {
                Some(n) if n >= CoulombState::NSTATV as c_int => {}
                _ => return false,
            }
            // Elastic stick (Abaqus's default, and the common case) does not look at the
            // entry flag or TAULM: its own copy of the point, with neither.
            match (get(self.nfdir), law.stick() == StickMode::Elastic) {
                (Some(1), true) => self.plain_point::<1>(&law, EntryFlag::Motion),
                (Some(2), true) => self.plain_point::<2>(&law, EntryFlag::Motion),
                (Some(1), false) => self.plain_point::<1>(&law, entry),
                (Some(2), false) => self.plain_point::<2>(&law, entry),
                _ => false,
            }
        }
    }

    /// One contact point of the plain law, N = NFDIR: the increment and `STATEV(1..3)` read
    /// quietly, every test folded into the few branches of [`Coulomb::try_update`]; `false`
    /// (nothing written) when a pointer is NULL or an input or result is not finite.
    ///
    /// # Safety
    /// As `fric_`, with `NSTATV ≥ 3` checked.
    #[inline(always)]
    unsafe fn plain_point<const N: usize>(&self, law: &Coulomb, entry: EntryFlag) -> bool {
        // SAFETY (whole body): arrays of N and NSTATV ≥ 3 entries per the FRIC contract.
        unsafe {
            let Ok(inc) = self.increment::<N, ()>(entry) else {
                return false;
            };
            let Some([s, rate, status]) = get(self.statev.cast::<[f64; 3]>()) else {
                return false;
            };
            // Tested for finiteness with the inputs by `try_update`.
            let state = CoulombState::from_values_unchecked(s, rate, status);
            let Some(up) = law.try_update(&inc, &state) else {
                return false;
            };
            // DDTDDT(NFDIR,2) = 0: μ does not depend on temperature. The plain law always
            // converges: PNEWDT is left alone.
            self.write_answer(&up.contact, &coulomb_statev(&up.state), &[0.0; N]);
            true
        }
    }

    /// The one reader of the increment, for every law and path: `PRESS`, `DPRESS`, `TAU`,
    /// `DGAM`, `TAULM` (only with `LM = 1` on entry), `DTIME`, `CHRLNGTH`, in that order (the
    /// checked path names the first NULL; the order is the plain path's fastest).
    ///
    /// # Safety
    /// As `fric_`, N = NFDIR.
    #[inline(always)]
    unsafe fn increment<const N: usize, E: Refusal>(
        &self,
        entry: EntryFlag,
    ) -> Result<Increment<N>, E> {
        // SAFETY (whole body): arrays of N entries per the FRIC contract.
        unsafe {
            let pressure = arg(self.press, "PRESS")?;
            let dpressure = arg(self.dpress, "DPRESS")?;
            let tau = arg(self.tau.cast::<[f64; N]>(), "TAU")?;
            let dgam = arg(self.dgam.cast::<[f64; N]>(), "DGAM")?;
            let taulm = if entry == EntryFlag::ExactStick {
                arg(self.taulm.cast::<[f64; N]>(), "TAULM")?
            } else {
                [0.0; N]
            };
            Ok(Increment {
                tau,
                dgam,
                taulm,
                pressure,
                dpressure,
                dtime: arg(self.dtime, "DTIME")?,
                characteristic_length: arg(self.chrlngth, "CHRLNGTH")?,
                entry,
            })
        }
    }

    /// The one writer of a successful answer: `STATEV(1..)` (`statev`, the law's layout),
    /// `LM`, and with relative motion `TAU`, `DDTDDG`, `DDTDDP`, `DSLIP`, `SED`, `SFD` and both
    /// columns of `DDTDDT` (each `ddtddt_column`); in exact stick `DSLIP`, `SED` and `SFD` are
    /// zero and the rest is left alone. NULL optional outputs are skipped.
    ///
    /// # Safety
    /// As `fric_`, N = NFDIR, `NSTATV ≥ statev.len()` checked.
    #[inline(always)]
    unsafe fn write_answer<const N: usize>(
        &self,
        contact: &Contact<N>,
        statev: &[f64],
        ddtddt_column: &[f64; N],
    ) {
        // SAFETY: arrays of N, N·N, 2N and NSTATV ≥ statev.len() entries per the FRIC contract.
        unsafe {
            for (i, x) in statev.iter().enumerate() {
                self.statev.add(i).write(*x);
            }
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

    /// Lowers `PNEWDT` to the law's step ratio (never raises it).
    ///
    /// # Safety
    /// As `fric_`.
    unsafe fn lower_pnewdt(&self, ratio: f64) {
        // SAFETY: PNEWDT is NULL or a valid double per the FRIC contract.
        unsafe {
            if ratio.is_finite() && !self.pnewdt.is_null() && ratio < self.pnewdt.read() {
                self.pnewdt.write(ratio);
            }
        }
    }

    /// Everything but the plain law: the rate law's lean layout (`rate.rs`), then the checked
    /// path with its messages.
    ///
    /// # Safety
    /// As `fric_`.
    unsafe fn general(&self) -> Result<(), LawError> {
        // SAFETY: as `fric_`.
        unsafe {
            if self.decay_fast() {
                Ok(())
            } else {
                self.run()
            }
        }
    }

    /// The checked path: reads every argument with named checks, the law through the `PROPS`
    /// layer (its fast layouts first, then the checked parsers, which name the entry), then
    /// `NSTATV` and `NFDIR` once, and runs [`Self::point`].
    ///
    /// # Safety
    /// As `fric_`.
    unsafe fn run(&self) -> Result<(), LawError> {
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
            let nprops = count("NPROPS", read(self.nprops, "NPROPS")?)?;
            let props = slice(self.props, nprops, "PROPS")?;
            // The extended law's own fast reader (no FrictionLaw built and moved).
            if let Some(law) = fast_extended_coulomb(props) {
                return self.on_nfdir(&law, entry);
            }
            self.any_law(props, entry)
        }
    }

    /// Every other law and layout: the law from the `PROPS` layer (its other fast layouts,
    /// then the checked parsers, which name the entry), then one point with that law's own
    /// type. Out of line, so that `fric_general` keeps the decay law's lean path compact (in
    /// line it cost that path 20 instructions per call, bench_rate).
    ///
    /// # Safety
    /// As `fric_`.
    #[inline(never)]
    unsafe fn any_law(&self, props: &[f64], entry: EntryFlag) -> Result<(), LawError> {
        // The μ table (law 1's, when its PROPS ask for one) is the interaction's, from the
        // configuration file. A NULL name or an implausible hidden length (an address) reads
        // as no name.
        // SAFETY: CINAME of its hidden length or NULL, per the FRIC contract.
        let law = friction_law_with_table(props, || unsafe {
            friction_table_for(fortran_name_bytes(self.ciname, self.ciname_len))
        })?;
        law.run_with(OnePoint { args: self, entry })
    }

    /// Reads `NFDIR` (1 or 2) and runs the point with N = NFDIR.
    ///
    /// # Safety
    /// As `fric_`.
    unsafe fn on_nfdir<L: PointLaw>(&self, law: &L, entry: EntryFlag) -> Result<(), LawError> {
        // SAFETY: NFDIR is a valid pointer or NULL per the FRIC contract.
        unsafe {
            match read(self.nfdir, "NFDIR")? {
                1 => self.point::<1, L>(law, entry),
                2 => self.point::<2, L>(law, entry),
                other => Err(bad_nfdir(other)),
            }
        }
    }

    /// One point through the law interface ([`PointLaw`]), N = NFDIR: `NSTATV` as the law
    /// needs it, the increment (an `LM = 1` on entry read as 0 by a law without exact stick)
    /// and the conditions the law asks for, the update, the answer written. Everything is
    /// computed before the first output is written, so a failure leaves the caller's arrays as
    /// they were.
    ///
    /// # Safety
    /// As `fric_`, N = NFDIR.
    unsafe fn point<const N: usize, L: PointLaw>(
        &self,
        law: &L,
        entry: EntryFlag,
    ) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of N, N·N, 2N and NSTATV entries per the FRIC contract;
        // STATEV is read and written only up to the checked NSTATV.
        unsafe {
            let given = read(self.nstatv, "NSTATV")?;
            let needed = law.nstatv(N);
            let nstatv = match usize::try_from(given) {
                Ok(n) if n >= needed => n,
                _ => {
                    return Err(short_nstatv(
                        given.into(),
                        needed,
                        law.name(),
                        "*DEPVAR / the DEPVAR of *FRICTION, USER",
                    ));
                }
            };
            let entry = if law.exact_stick() {
                entry
            } else {
                EntryFlag::Motion
            };
            let inc = self.increment::<N, LawError>(entry)?;
            let conditions = self.conditions::<N>(law.needs(N))?;
            let statev = slice(self.statev, nstatv, "STATEV")?;
            let up = law.update_point(&PointInput {
                increment: &inc,
                conditions: &conditions,
                statev,
            })?;
            let half = up.dtau_dtheta.map(|d| 0.5 * d);
            self.write_answer(&up.contact, &up.statev[..up.statev_len], &half);
            self.lower_pnewdt(up.step_ratio);
            Ok(())
        }
    }

    /// What the law reads besides the increment, as it asked ([`Needs`]): the mean surface
    /// temperature `TEMP`, the rotation `DROT` (2 × 2), the coordinates `COORDS(1..MCRD)`.
    ///
    /// # Safety
    /// As `fric_`, N = NFDIR.
    unsafe fn conditions<const N: usize>(&self, needs: Needs) -> Result<Conditions, LawError> {
        // SAFETY (whole body): TEMP(2), DROT(2,2) and COORDS(MCRD) per the FRIC contract.
        unsafe {
            let mut conditions = Conditions::default();
            if needs.temperature {
                conditions.temperature = mean_surface_temperature(read_array(self.temp, "TEMP")?);
            }
            if needs.rotation {
                // DROT(2,2), column-major: DROT(a,b) at (a-1) + 2(b-1).
                let r = read_array::<4>(self.drot, "DROT")?;
                conditions.drot = [[r[0], r[2]], [r[1], r[3]]];
            }
            if needs.coordinates {
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
            Ok(conditions)
        }
    }

    /// The documented safe outputs of a failed call.
    ///
    /// # Safety
    /// As `fric_`.
    unsafe fn fail(&self) {
        // SAFETY: as in `run`; arrays are written only when NFDIR is known to be 1 or 2.
        unsafe {
            cut_back(self.pnewdt);
            write(self.sfd, 0.0);
            let n = match read(self.nfdir, "NFDIR") {
                Ok(1) => 1,
                Ok(2) => 2,
                _ => return,
            };
            // N = NFDIR entries per array, N·N for DDTDDG, 2N for DDTDDT.
            write_zeros(self.ddtddg, n * n);
            write_zeros(self.ddtddp, n);
            write_zeros(self.dslip, n);
            write_zeros(self.ddtddt, 2 * n);
        }
    }

    /// Where a FRIC message comes from, read only on the error path.
    ///
    /// # Safety
    /// As `fric_`.
    unsafe fn site(&self) -> Site {
        // SAFETY: the host's pointers: CINAME of its hidden length, NOEL, NODE, NPT or NULL.
        unsafe {
            let place = format!(
                "element {}, node {}, point {}",
                host_number(self.noel),
                host_number(self.node),
                host_number(self.npt)
            );
            host_site("FRIC", self.ciname, self.ciname_len, place)
        }
    }
}

/// `fric_`'s checked path for whichever law `PROPS` select, compiled once per law
/// ([`PointLawTask`]: one match on the law enum, then the law's own type, as a direct call
/// would be; through the enum's own `PointLaw` methods the adhesive law cost 1519 instructions
/// per call against 1366, bench_adhesive law 4, callgrind, 2026-11-28).
struct OnePoint<'a> {
    /// The host's arguments, valid per `fric_`'s contract (a `OnePoint` is made only inside
    /// `fric_`'s call).
    args: &'a FricArgs,
    entry: EntryFlag,
}

impl PointLawTask for OnePoint<'_> {
    type Output = Result<(), LawError>;

    #[inline(always)]
    fn run<L: PointLaw>(self, law: &L) -> Self::Output {
        // SAFETY: the pointers of `fric_`'s call, valid per its contract (see the field).
        unsafe { self.args.on_nfdir(law, self.entry) }
    }
}

/// `STATEV(1..3)` of the Coulomb state.
#[inline(always)]
fn coulomb_statev(state: &CoulombState) -> [f64; CoulombState::NSTATV] {
    let mut out = [0.0; CoulombState::NSTATV];
    state.write_statev(&mut out);
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
fn bad_nfdir(nfdir: c_int) -> LawError {
    LawError::Parameter(format!("NFDIR = {nfdir}; expected 1 (2-D) or 2 (3-D)"))
}
