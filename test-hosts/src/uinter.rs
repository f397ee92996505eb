//! A host's side of `uinter_`: every UINTER argument in Fortran layout, and a `call` that
//! passes them by reference as an FE code does (80-character blank-padded names with their
//! hidden lengths). The Rust tests go through it, so they exercise the real entry point.

use std::ffi::c_char;

use interfacial::abi::uinter_;

use crate::{Outputs, blank_padded, fill_guards, guards_hold, state_with_guards};

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
