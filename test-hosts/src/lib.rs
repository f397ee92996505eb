//! The host's side of the library's Fortran entry points, for interfacial's tests and its main
//! job (`examples/scenes`): [`FricCall`] (`fric_`), [`GapconCall`] (`gapcon_`) and
//! [`UinterCall`] (`uinter_`) hold every argument in Fortran layout and pass it by reference
//! exactly as an FE code does (80-character blank-padded names with their hidden lengths),
//! through the library's public API, so what they exercise is the real entry point, not the
//! core behind it. Output arrays carry [`GUARD`] slots past what a call may write.
//!
//! A crate of its own (`publish = false`) that the library takes as a dev-dependency only: none
//! of this is compiled into the library a host links or into its package.

use std::ffi::{CStr, c_char};

use interfacial::abi::{fric_, gapcon_, uinter_};

/// Sentinel written past the end of every output array, to prove nothing is written there.
pub const GUARD: f64 = -7.77e77;

/// `STATEV` of `n` zeros followed by four [`GUARD`] slots.
pub(crate) fn state_with_guards(n: usize) -> Vec<f64> {
    let mut statev = vec![0.0; n];
    statev.extend([GUARD; 4]);
    statev
}

/// The output arrays of a host call, each with the number of entries the call may write
/// (NFDIR, NDIR², NSTATV, …): every entry past that count is a guard slot. A count past the
/// array's end (a test's deliberately bad size) leaves that array without guard slots.
pub(crate) type Outputs<'a, const K: usize> = [(&'a mut [f64], usize); K];

/// Fills every guard slot of `outputs` with [`GUARD`].
pub(crate) fn fill_guards<const K: usize>(outputs: Outputs<'_, K>) {
    for (array, written) in outputs {
        if let Some(slots) = array.get_mut(written..) {
            slots.fill(GUARD);
        }
    }
}

/// True when every guard slot of `outputs` still holds [`GUARD`].
pub(crate) fn guards_hold<const K: usize>(outputs: Outputs<'_, K>) -> bool {
    outputs.into_iter().all(|(array, written)| {
        array
            .get(written..)
            .unwrap_or(&[])
            .iter()
            .all(|x| *x == GUARD)
    })
}

/// A `CHARACTER` argument as the host passes it: `name` blank-padded to `len` bytes (longer
/// names are kept whole; the hidden length says how much is read).
pub(crate) fn blank_padded(name: &str, len: usize) -> Vec<u8> {
    let mut bytes = name.as_bytes().to_vec();
    bytes.resize(len.max(bytes.len()), b' ');
    bytes
}

/// The calling thread's last error message (empty when none), read through `ifl_last_error`.
#[must_use]
pub fn last_error() -> String {
    // SAFETY: `ifl_last_error` returns the thread's NUL-terminated message, valid until the next
    // call into the library on this thread; it is copied before any such call.
    unsafe { CStr::from_ptr(interfacial::abi::ifl_last_error()) }
        .to_string_lossy()
        .into_owned()
}

// --- FRIC: `fric_` ---

/// All FRIC arguments of one contact point. Arrays are sized for NFDIR ≤ 3 plus guard slots, so
/// even a bad `nfdir` stays inside them; `statev` and `props` are sized by their vectors.
#[derive(Clone, Debug)]
pub struct FricCall {
    /// `LM`.
    pub lm: i32,
    /// `TAU(NFDIR)`.
    pub tau: [f64; 4],
    /// `DDTDDG(NFDIR,NFDIR)`, column-major.
    pub ddtddg: [f64; 10],
    /// `DDTDDP(NFDIR)`.
    pub ddtddp: [f64; 4],
    /// `DSLIP(NFDIR)`.
    pub dslip: [f64; 4],
    /// `SED`.
    pub sed: f64,
    /// `SFD`.
    pub sfd: f64,
    /// `DDTDDT(NFDIR,2)`, column-major.
    pub ddtddt: [f64; 7],
    /// `PNEWDT` (set large before each call, as Abaqus does).
    pub pnewdt: f64,
    /// `STATEV(NSTATV)`; entries past `nstatv` are guards.
    pub statev: Vec<f64>,
    /// `DGAM(NFDIR)`.
    pub dgam: [f64; 3],
    /// `TAULM(NFDIR)`.
    pub taulm: [f64; 3],
    /// Pass a NULL `TAULM` instead of [`Self::taulm`] (a broken host; bad-input tests).
    pub null_taulm: bool,
    /// `PRESS`.
    pub press: f64,
    /// `DPRESS`.
    pub dpress: f64,
    /// `DDPDDH`.
    pub ddpddh: f64,
    /// `SLIP(NFDIR)`.
    pub slip: [f64; 3],
    /// `KSTEP`, `KINC`.
    pub kstep: i32,
    /// `KINC`.
    pub kinc: i32,
    /// `TIME(2)`.
    pub time: [f64; 2],
    /// `DTIME`.
    pub dtime: f64,
    /// `NOEL`.
    pub noel: i32,
    /// `CINAME` (blank-padded to `name_len` at the call).
    pub ciname: String,
    /// Hidden length passed for each name (80 for `CHARACTER*80`).
    pub name_len: usize,
    /// `NPT`.
    pub npt: i32,
    /// `NODE`.
    pub node: i32,
    /// `NPATCH`.
    pub npatch: i32,
    /// `COORDS(MCRD)`.
    pub coords: [f64; 3],
    /// `RCOORD(MCRD)`.
    pub rcoord: [f64; 3],
    /// `DROT(2,2)`, column-major.
    pub drot: [f64; 4],
    /// `TEMP(2)`.
    pub temp: [f64; 2],
    /// `PREDEF(2,NPRED)`.
    pub predef: [f64; 2],
    /// `NFDIR`.
    pub nfdir: i32,
    /// `MCRD`.
    pub mcrd: i32,
    /// `NPRED`.
    pub npred: i32,
    /// `NSTATV` (may be set smaller than `statev.len()` to test short state arrays).
    pub nstatv: i32,
    /// `CHRLNGTH`.
    pub chrlngth: f64,
    /// `PROPS(NPROPS)`.
    pub props: Vec<f64>,
    /// `NPROPS` (may be set smaller than `props.len()`).
    pub nprops: i32,
}

impl FricCall {
    /// A closed point with `nfdir` friction directions, the given `props`, `NSTATV = 3` (plus
    /// four guard slots), pressure 0, identity `DROT`, interaction name `"SI1"`.
    #[must_use]
    pub fn new(nfdir: i32, props: &[f64]) -> Self {
        let statev = state_with_guards(3);
        let mut call = FricCall {
            lm: 0,
            tau: [0.0; 4],
            ddtddg: [0.0; 10],
            ddtddp: [0.0; 4],
            dslip: [0.0; 4],
            sed: 0.0,
            sfd: 0.0,
            ddtddt: [0.0; 7],
            pnewdt: 1e36,
            statev,
            dgam: [0.0; 3],
            taulm: [0.0; 3],
            null_taulm: false,
            press: 0.0,
            dpress: 0.0,
            ddpddh: 1e6,
            slip: [0.0; 3],
            kstep: 1,
            kinc: 1,
            time: [0.0; 2],
            dtime: 1.0,
            noel: 0,
            ciname: "SI1".into(),
            name_len: 80,
            npt: 1,
            node: 1,
            npatch: 1,
            coords: [0.0; 3],
            rcoord: [0.0; 3],
            drot: [1.0, 0.0, 0.0, 1.0],
            temp: [20.0; 2],
            predef: [0.0; 2],
            nfdir,
            mcrd: 3,
            npred: 1,
            nstatv: 3,
            chrlngth: 1.0,
            props: props.to_vec(),
            nprops: i32::try_from(props.len()).unwrap_or(i32::MAX),
        };
        call.set_guards();
        call
    }

    /// The output arrays, each with what the call may write: NFDIR (or NFDIR², 2·NFDIR,
    /// NSTATV) entries.
    fn outputs(&mut self) -> Outputs<'_, 6> {
        let n = self.nfdir.clamp(0, 3) as usize;
        let ns = self.nstatv.max(0) as usize;
        [
            (&mut self.statev, ns),
            (&mut self.tau, n),
            (&mut self.ddtddg, n * n),
            (&mut self.ddtddp, n),
            (&mut self.dslip, n),
            (&mut self.ddtddt, 2 * n),
        ]
    }

    /// Fills every output entry past what the call may write with [`GUARD`].
    pub fn set_guards(&mut self) {
        fill_guards(self.outputs());
    }

    /// True when every guard slot still holds [`GUARD`].
    #[must_use]
    pub fn guards_intact(&self) -> bool {
        // On a copy: `outputs` lends the arrays mutably (one list serves both).
        guards_hold(self.clone().outputs())
    }

    /// `∂τ_a/∂Δγ_b` = `DDTDDG(a,b)`, 0-based.
    #[must_use]
    pub fn ddtddg(&self, a: usize, b: usize) -> f64 {
        self.ddtddg[a + b * self.nfdir.max(0) as usize]
    }

    /// Calls `fric_` with this point's arguments.
    ///
    /// # Panics
    /// When `statev`, `props` or the name are shorter than `nstatv`, `nprops` or `name_len`
    /// claim (a test-harness mistake; the library itself is never given such arrays).
    pub fn call(&mut self) {
        assert!(self.statev.len() >= self.nstatv.max(0) as usize);
        assert!(self.props.len() >= self.nprops.max(0) as usize);
        assert!((-1..=3).contains(&self.nfdir));
        let len = self.name_len;
        let name = blank_padded(&self.ciname, len);
        let sl = [b' '; 80];
        let ms = [b' '; 80];
        // SAFETY: every pointer refers to a field of `self` or a local that outlives the call,
        // sized as FRIC's contract requires for nfdir ≤ 3, nstatv and nprops (asserted above).
        unsafe {
            fric_(
                &mut self.lm,
                self.tau.as_mut_ptr(),
                self.ddtddg.as_mut_ptr(),
                self.ddtddp.as_mut_ptr(),
                self.dslip.as_mut_ptr(),
                &mut self.sed,
                &mut self.sfd,
                self.ddtddt.as_mut_ptr(),
                &mut self.pnewdt,
                self.statev.as_mut_ptr(),
                self.dgam.as_ptr(),
                if self.null_taulm {
                    std::ptr::null()
                } else {
                    self.taulm.as_ptr()
                },
                &self.press,
                &self.dpress,
                &self.ddpddh,
                self.slip.as_ptr(),
                &self.kstep,
                &self.kinc,
                self.time.as_ptr(),
                &self.dtime,
                &self.noel,
                name.as_ptr().cast::<c_char>(),
                sl.as_ptr().cast::<c_char>(),
                ms.as_ptr().cast::<c_char>(),
                &self.npt,
                &self.node,
                &self.npatch,
                self.coords.as_ptr(),
                self.rcoord.as_ptr(),
                self.drot.as_ptr(),
                self.temp.as_ptr(),
                self.predef.as_ptr(),
                &self.nfdir,
                &self.mcrd,
                &self.npred,
                &self.nstatv,
                &self.chrlngth,
                self.props.as_ptr(),
                &self.nprops,
                len,
                80,
                80,
            );
        }
    }

    /// The calling thread's last error message (empty when none): [`crate::last_error`].
    #[must_use]
    pub fn last_error() -> String {
        last_error()
    }
}

// --- GAPCON: `gapcon_` ---

/// All GAPCON arguments of one point, passed to `gapcon_` as a Fortran host does. `FLOWM`,
/// `PREDEF`, `TIME` and `COORDS` are never read by the library (a test may fill them with NaN to
/// show it); `SLNAME` and `MSNAME` are blank, `NPRED` = 0, `KSTEP` = `KINC` = 1, and CalculiX's
/// `AREA` (never read either) is NaN.
#[derive(Clone, Debug)]
pub struct GapconCall {
    /// `AK(5)`; `AK(2..5)` hold [`GUARD`] to prove they are not written.
    pub ak: [f64; 5],
    /// `D(2)`: clearance, contact pressure.
    pub d: [f64; 2],
    /// `FLOWM(2)`.
    pub flowm: [f64; 2],
    /// `TEMP(2)`: surface temperatures θ_A, θ_B.
    pub temp: [f64; 2],
    /// `PREDEF(2)`.
    pub predef: [f64; 2],
    /// `TIME(2)`.
    pub time: [f64; 2],
    /// `COORDS(3)`.
    pub coords: [f64; 3],
    /// `CINAME` (blank-padded to `name_len` at the call).
    pub ciname: String,
    /// Hidden length of `CINAME`.
    pub name_len: usize,
    /// `NOEL`.
    pub noel: i32,
    /// `NODE`.
    pub node: i32,
}

impl GapconCall {
    /// A point of interaction `name` at clearance `d`, pressure `p`, temperatures θ_A, θ_B.
    #[must_use]
    pub fn new(name: &str, d: f64, p: f64, theta_a: f64, theta_b: f64) -> Self {
        GapconCall {
            ak: [GUARD; 5],
            d: [d, p],
            flowm: [0.0; 2],
            temp: [theta_a, theta_b],
            predef: [0.0; 2],
            time: [0.0; 2],
            coords: [0.0; 3],
            ciname: name.into(),
            name_len: 80,
            noel: 1,
            node: 1,
        }
    }

    /// Calls `gapcon_` (the variant this crate was built with) and returns `AK(1)`.
    pub fn call(&mut self) -> f64 {
        let len = self.name_len;
        let name = blank_padded(&self.ciname, len);
        let blank = [b' '; 80];
        let (one, zero) = (1i32, 0i32);
        // SAFETY: every pointer refers to a field of `self` or a local that outlives the call,
        // sized as GAPCON's contract requires.
        unsafe {
            gapcon_(
                self.ak.as_mut_ptr(),
                self.d.as_ptr(),
                self.flowm.as_ptr(),
                self.temp.as_ptr(),
                self.predef.as_ptr(),
                self.time.as_ptr(),
                name.as_ptr().cast::<c_char>(),
                blank.as_ptr().cast::<c_char>(),
                blank.as_ptr().cast::<c_char>(),
                self.coords.as_ptr(),
                &self.noel,
                &self.node,
                &zero,
                &one,
                &one,
                #[cfg(feature = "calculix")]
                &f64::NAN,
                len,
                80,
                80,
            );
        }
        self.ak[0]
    }
}

// --- UINTER: `uinter_` ---

/// All UINTER arguments of one interface point. Arrays are sized for NDIR ≤ 3 plus guard slots.
#[derive(Clone, Debug)]
pub struct UinterCall {
    /// `STRESS(NDIR)`: start of increment in, end out.
    pub stress: [f64; 4],
    /// `DDSDDR(NDIR,NDIR)`, column-major.
    pub ddsddr: [f64; 10],
    /// `DVISCOUS(NDIR,NDIR)`.
    pub dviscous: [f64; 10],
    /// `DSTRUCTURAL(NDIR,NDIR)`.
    pub dstructural: [f64; 10],
    /// `FLUX(2)`.
    pub flux: [f64; 3],
    /// `DDFDDT(2,2)`.
    pub ddfddt: [f64; 5],
    /// `DDSDDT(NDIR,2)`.
    pub ddsddt: [f64; 7],
    /// `DDFDDR(2,NDIR)`.
    pub ddfddr: [f64; 7],
    /// `STATEV(NSTATV)`; entries past `nstatv` are guards.
    pub statev: Vec<f64>,
    /// `SED`, `SFD`, `SPD`, `SVD`, `SCD`.
    pub energies: [f64; 5],
    /// `PNEWDT`.
    pub pnewdt: f64,
    /// `RDISP(NDIR)`.
    pub rdisp: [f64; 3],
    /// `DRDISP(NDIR)`.
    pub drdisp: [f64; 3],
    /// `TEMP(2)`.
    pub temp: [f64; 2],
    /// `DTEMP(2)`.
    pub dtemp: [f64; 2],
    /// `DTIME`.
    pub dtime: f64,
    /// `CINAME`.
    pub ciname: String,
    /// `PROPS(NPROPS)`.
    pub props: Vec<f64>,
    /// `CHRLNGTH`.
    pub chrlngth: f64,
    /// `NDIR`.
    pub ndir: i32,
    /// `NSTATV`.
    pub nstatv: i32,
    /// `NPROPS`.
    pub nprops: i32,
    /// `LOPENCLOSE`.
    pub lopenclose: i32,
    /// `LSTATE`.
    pub lstate: i32,
}

impl UinterCall {
    /// A point with `ndir` stress components, the given `props`, `NSTATV = 3` (+ guards),
    /// `LOPENCLOSE = LSTATE = −1` as at the start of an analysis, interaction `"SI1"`.
    #[must_use]
    pub fn new(ndir: i32, props: &[f64]) -> Self {
        let statev = state_with_guards(3);
        let mut c = UinterCall {
            stress: [0.0; 4],
            ddsddr: [0.0; 10],
            dviscous: [0.0; 10],
            dstructural: [0.0; 10],
            flux: [0.0; 3],
            ddfddt: [0.0; 5],
            ddsddt: [0.0; 7],
            ddfddr: [0.0; 7],
            statev,
            energies: [0.0; 5],
            pnewdt: 1e36,
            rdisp: [0.0; 3],
            drdisp: [0.0; 3],
            temp: [20.0; 2],
            dtemp: [0.0; 2],
            dtime: 1.0,
            ciname: "SI1".into(),
            props: props.to_vec(),
            chrlngth: 1.0,
            ndir,
            nstatv: 3,
            nprops: i32::try_from(props.len()).unwrap_or(i32::MAX),
            lopenclose: -1,
            lstate: -1,
        };
        c.set_guards();
        c
    }

    /// The output arrays, each with what the call may write: NDIR (or NDIR², 2·NDIR, 2, 4,
    /// NSTATV) entries.
    fn outputs(&mut self) -> Outputs<'_, 9> {
        let n = self.ndir.clamp(0, 3) as usize;
        let ns = self.nstatv.max(0) as usize;
        [
            (&mut self.statev, ns),
            (&mut self.stress, n),
            (&mut self.ddsddr, n * n),
            (&mut self.dviscous, n * n),
            (&mut self.dstructural, n * n),
            (&mut self.flux, 2),
            (&mut self.ddfddt, 4),
            (&mut self.ddsddt, 2 * n),
            (&mut self.ddfddr, 2 * n),
        ]
    }

    /// `DDSDDR(i,j)`, 0-based.
    #[must_use]
    pub fn ddsddr(&self, i: usize, j: usize) -> f64 {
        self.ddsddr[i + j * self.ndir.max(0) as usize]
    }

    /// `DDFDDR(i,j)`, 0-based.
    #[must_use]
    pub fn ddfddr(&self, i: usize, j: usize) -> f64 {
        self.ddfddr[i + 2 * j]
    }

    /// Fills every output entry past what the call may write with [`GUARD`].
    pub fn set_guards(&mut self) {
        fill_guards(self.outputs());
    }

    /// True when every guard slot still holds [`GUARD`].
    #[must_use]
    pub fn guards_intact(&self) -> bool {
        // On a copy: `outputs` lends the arrays mutably (one list serves both).
        guards_hold(self.clone().outputs())
    }

    /// Calls `uinter_` with this point's arguments.
    ///
    /// # Panics
    /// When `statev` or `props` are shorter than `nstatv` or `nprops` claim (a harness mistake).
    pub fn call(&mut self) {
        assert!(self.statev.len() >= self.nstatv.max(0) as usize);
        assert!(self.props.len() >= self.nprops.max(0) as usize);
        assert!((-1..=3).contains(&self.ndir));
        let name = blank_padded(&self.ciname, 80);
        let blank = [b' '; 80];
        let zeros = [0.0f64; 9];
        let (one, zero) = (1i32, 0i32);
        let (mut lsdi, time) = (0i32, [0.0f64; 2]);
        let [sed, sfd, spd, svd, scd] = &mut self.energies;
        // SAFETY: every pointer refers to a field of `self` or a local that outlives the call,
        // sized as UINTER's contract requires for ndir ≤ 3, nstatv and nprops (asserted above).
        unsafe {
            uinter_(
                self.stress.as_mut_ptr(),
                self.ddsddr.as_mut_ptr(),
                self.dviscous.as_mut_ptr(),
                self.dstructural.as_mut_ptr(),
                self.flux.as_mut_ptr(),
                self.ddfddt.as_mut_ptr(),
                self.ddsddt.as_mut_ptr(),
                self.ddfddr.as_mut_ptr(),
                self.statev.as_mut_ptr(),
                sed,
                sfd,
                spd,
                svd,
                scd,
                &mut self.pnewdt,
                self.rdisp.as_ptr(),
                self.drdisp.as_ptr(),
                self.temp.as_ptr(),
                self.dtemp.as_ptr(),
                zeros.as_ptr(),
                zeros.as_ptr(),
                time.as_ptr(),
                &self.dtime,
                &0.0,
                name.as_ptr().cast::<c_char>(),
                blank.as_ptr().cast::<c_char>(),
                blank.as_ptr().cast::<c_char>(),
                self.props.as_ptr(),
                zeros.as_ptr(),
                zeros.as_ptr(),
                zeros.as_ptr(),
                &1.0,
                &self.chrlngth,
                &one,
                &self.ndir,
                &self.nstatv,
                &one,
                &self.nprops,
                &3,
                &one,
                &one,
                &one,
                &zero,
                &mut self.lopenclose,
                &mut self.lstate,
                &mut lsdi,
                &zero,
                80,
                80,
                80,
            );
        }
    }
}
