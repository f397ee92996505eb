//! A host's side of `fric_`: every FRIC argument held in Fortran layout, and a `call` that passes
//! them by reference exactly as an FE code does (80-character blank-padded names with their
//! hidden lengths). The scene driver, the Rust tests and the examples go through it, so they
//! exercise the real entry point, not the core behind it.

use std::ffi::c_char;

use interfacial::abi::fric_;

use crate::{Outputs, blank_padded, fill_guards, guards_hold, state_with_guards};

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

    /// Fills every output entry past what the call may write with [`GUARD`](crate::GUARD).
    pub fn set_guards(&mut self) {
        fill_guards(self.outputs());
    }

    /// True when every guard slot still holds [`GUARD`](crate::GUARD).
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
        crate::last_error()
    }
}
