//! One `uinter_` call decoded from fuzzer bytes: all 47 arguments and the 3 hidden lengths,
//! every array allocated with exactly the length the call declares (so AddressSanitizer reports
//! any access past it), and the properties every call must have.
//!
//! Runs against the configuration of [`super::gapcon_case`] (its `setup` must be called first),
//! so `PROPS(11) = 1` reaches every conductance law as well as the "no thermal law" refusal.
//! Shared by the `uinter` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use std::ffi::c_int;

use super::bytes::{Bytes, bits, len};
use super::contract::{Names, input_bits, last_error, pnewdt_refusal, unwritten};
use super::gapcon_case::NAMES;
use interfacial::abi::{ifl_clear_error, uinter_};

pub use super::contract::UNWRITTEN;
/// The same, for the integer outputs.
pub const UNWRITTEN_INT: c_int = -7777;

/// Every `uinter_` argument. Arrays have exactly their declared lengths.
#[derive(Clone, Debug)]
pub struct UinterCase {
    pub ndir: i32,
    pub nstatv: i32,
    pub npred: i32,
    pub nprops: i32,
    pub mcrd: i32,
    pub node: i32,
    pub kstep: i32,
    pub kinc: i32,
    pub kit: i32,
    pub linper: i32,
    pub lprint: i32,
    /// `LOPENCLOSE`, `LSTATE`, `LSDI` on entry.
    pub lopenclose: i32,
    pub lstate: i32,
    pub lsdi: i32,
    /// `STRESS(NDIR)`, start of increment.
    pub stress: Vec<f64>,
    /// `STATEV(NSTATV)`.
    pub statev: Vec<f64>,
    pub pnewdt: f64,
    /// `RDISP(NDIR)`, `DRDISP(NDIR)`.
    pub rdisp: Vec<f64>,
    pub drdisp: Vec<f64>,
    /// `TEMP(2)`, `DTEMP(2)`.
    pub temp: Vec<f64>,
    pub dtemp: Vec<f64>,
    /// `PREDEF(2,NPRED)`, `DPRED(2,NPRED)`.
    pub predef: Vec<f64>,
    pub dpred: Vec<f64>,
    /// `TIME(2)`.
    pub time: Vec<f64>,
    pub dtime: f64,
    pub freqr: f64,
    /// `PROPS(NPROPS)`.
    pub props: Vec<f64>,
    /// `COORDS(MCRD)`, `ALOCALDIR(MCRD,MCRD)`, `DROT(2,2)`.
    pub coords: Vec<f64>,
    pub alocaldir: Vec<f64>,
    pub drot: Vec<f64>,
    pub area: f64,
    pub chrlngth: f64,
    /// `CINAME`, `SLNAME`, `MSNAME`.
    pub names: Names,
    /// Pass NULL for every optional output (`DVISCOUS`, `DSTRUCTURAL`, `FLUX`, `DDFDDT`,
    /// `DDSDDT`, `DDFDDR`, `SED` … `SCD`, `LSTATE`).
    pub null_optional: bool,
}

impl UinterCase {
    /// Decodes any byte string. The choices favour valid calls (NDIR 2 or 3, NSTATV ≥ 3, an
    /// adhesive `PROPS` with a positive K_n) so most inputs reach the law, but every bad shape
    /// stays reachable.
    pub fn decode(data: &[u8]) -> Self {
        let mut b = Bytes::new(data);
        let ndir = b.pick(&[2, 3, 2, 3, 2, 3, 2, 3, 2, 3, 1, 4, 0, -1]);
        let nstatv = b.pick(&[3, 3, 3, 3, 4, 5, 8, 2, 0, -1]);
        let nprops = b.pick(&[10, 11, 13, 13, 13, 13, 13, 12, 9, 14, 2, 1, 0, -1]);
        let mcrd = b.pick(&[3, 2, 1, 0]);
        let npred = b.pick(&[1, 0, 2]);
        let n = len(ndir);
        let mut props: Vec<f64> = Vec::with_capacity(len(nprops));
        for i in 0..len(nprops) {
            let sel = b.u8() % 8;
            let v = match (i, sel) {
                (_, 7) => b.real(),
                // PROPS(1): the adhesive code, sometimes Coulomb.
                (0, 6) => 1.0,
                (0, _) => 2.0,
                // μ_d, and μ_s none / equal / above.
                (1, 0) => 0.0,
                (1, _) => b.unit(),
                (2, 0..=2) => 0.0,
                (2, 3) => -1.0,
                (2, _) => props[1] + b.unit(),
                // S_a, N_a: 0 or positive.
                (3 | 4, 0 | 1) => 0.0,
                (3 | 4, _) => b.positive(),
                // k_μ, v_½: mostly 0 (rate independent).
                (5 | 6, 0..=3) => 0.0,
                (5 | 6, _) => b.positive(),
                // γ_crit, tolerance: 0 (default) or positive.
                (7 | 8, 0..=2) => 0.0,
                (7 | 8, _) => b.positive(),
                // K_n: positive, sometimes 0 (refused).
                (9, 0) => 0.0,
                (9, _) => b.positive(),
                // Conduction: 0 or 1.
                (10, 0..=3) => 0.0,
                (10, _) => 1.0,
                // η, f: in [0, 1].
                (11 | 12, 0 | 1) => 0.0,
                (11 | 12, _) => b.unit(),
                _ => 0.0,
            };
            props.push(v);
        }
        let flags = b.u8();
        let configured = b.u8();
        let name = |b: &mut Bytes, configured: Option<&str>| {
            let l = usize::from(b.u8());
            let l = if l < 128 { 80 } else { l - 128 };
            let mut v = match configured {
                Some(s) => s.as_bytes().to_vec(),
                None => {
                    let printed = usize::from(b.u8() % 13);
                    b.bytes(printed)
                }
            };
            v.truncate(l);
            v.resize(l, if flags & 0x20 == 0 { b' ' } else { 0 });
            v
        };
        let ci = (configured < 224).then(|| NAMES[usize::from(configured) % NAMES.len()]);
        let statev = {
            let mut s = b.reals(len(nstatv));
            // STATEV(3) is a status code; keep it one of the law's mostly.
            if let Some(x) = s.get_mut(2) {
                let k = b.u8();
                if k < 224 {
                    *x = [0.0, 1.0, 3.0, 4.0][usize::from(k % 4)];
                }
            }
            if flags & 0x10 == 0 {
                // A state the law could have written: slip and rate finite, ≥ 0.
                for x in s.iter_mut().take(2) {
                    *x = if x.is_finite() { x.abs() } else { 0.0 };
                }
            }
            s
        };
        UinterCase {
            ndir,
            nstatv,
            npred,
            nprops,
            mcrd,
            node: i32::from(b.u16()),
            kstep: 1,
            kinc: 1,
            kit: 1,
            linper: 0,
            lprint: 0,
            lopenclose: b.pick(&[-1, 0, 1, 2]),
            lstate: b.pick(&[-1, 0, 1, 3, 4]),
            lsdi: 0,
            stress: b.reals(n),
            statev,
            pnewdt: b.large(),
            rdisp: b.reals(n),
            drdisp: b.reals(n),
            temp: b.reals(2),
            dtemp: b.reals(2),
            predef: b.reals(2 * len(npred)),
            dpred: b.reals(2 * len(npred)),
            time: b.reals(2),
            dtime: b.real(),
            freqr: b.real(),
            props,
            coords: b.reals(len(mcrd)),
            alocaldir: b.reals(len(mcrd) * len(mcrd)),
            drot: b.reals(4),
            area: b.real(),
            chrlngth: b.real(),
            names: Names {
                interaction: name(&mut b, ci),
                secondary: name(&mut b, None),
                main: name(&mut b, None),
            },
            null_optional: flags & 0x80 != 0,
        }
    }

    /// Calls `uinter_` and checks every property; `Err` names the first one violated.
    pub fn check(&self) -> Result<UinterOutputs, String> {
        let before = self.clone();
        let c = self.clone();
        let n = len(self.ndir);
        let mut out = UinterOutputs {
            stress: c.stress.clone(),
            ddsddr: vec![UNWRITTEN; n * n],
            dviscous: vec![UNWRITTEN; n * n],
            dstructural: vec![UNWRITTEN; n * n],
            flux: vec![UNWRITTEN; 2],
            ddfddt: vec![UNWRITTEN; 4],
            ddsddt: vec![UNWRITTEN; 2 * n],
            ddfddr: vec![UNWRITTEN; 2 * n],
            statev: c.statev.clone(),
            energies: [UNWRITTEN; 5],
            pnewdt: c.pnewdt,
            lopenclose: c.lopenclose,
            lstate: c.lstate,
            lsdi: c.lsdi,
            message: String::new(),
        };
        let null = c.null_optional;
        let opt = |p: *mut f64| if null { std::ptr::null_mut() } else { p };
        let [sed, sfd, spd, svd, scd] = out.energies.each_mut().map(|p| opt(p));
        let lstate: *mut c_int = if null {
            std::ptr::null_mut()
        } else {
            &mut out.lstate
        };
        let [ci, sl, ms] = c.names.pointers();
        let [ci_len, sl_len, ms_len] = c.names.lengths();
        ifl_clear_error();
        // SAFETY: every array has exactly the length the call declares (NDIR, NDIR², 2, 4,
        // 2·NDIR, NSTATV, 2·NPRED, NPROPS, MCRD, MCRD², the hidden name lengths); scalars are
        // locals; optional outputs are NULL or valid.
        unsafe {
            uinter_(
                out.stress.as_mut_ptr(),
                out.ddsddr.as_mut_ptr(),
                opt(out.dviscous.as_mut_ptr()),
                opt(out.dstructural.as_mut_ptr()),
                opt(out.flux.as_mut_ptr()),
                opt(out.ddfddt.as_mut_ptr()),
                opt(out.ddsddt.as_mut_ptr()),
                opt(out.ddfddr.as_mut_ptr()),
                out.statev.as_mut_ptr(),
                sed,
                sfd,
                spd,
                svd,
                scd,
                &mut out.pnewdt,
                c.rdisp.as_ptr(),
                c.drdisp.as_ptr(),
                c.temp.as_ptr(),
                c.dtemp.as_ptr(),
                c.predef.as_ptr(),
                c.dpred.as_ptr(),
                c.time.as_ptr(),
                &c.dtime,
                &c.freqr,
                ci,
                sl,
                ms,
                c.props.as_ptr(),
                c.coords.as_ptr(),
                c.alocaldir.as_ptr(),
                c.drot.as_ptr(),
                &c.area,
                &c.chrlngth,
                &c.node,
                &c.ndir,
                &c.nstatv,
                &c.npred,
                &c.nprops,
                &c.mcrd,
                &c.kstep,
                &c.kinc,
                &c.kit,
                &c.linper,
                &mut out.lopenclose,
                lstate,
                &mut out.lsdi,
                &c.lprint,
                ci_len,
                sl_len,
                ms_len,
            );
            out.message = last_error();
        }
        if !same(&c, &before) {
            return Err("an input argument was written".into());
        }
        self.check_outputs(&out)?;
        Ok(out)
    }

    fn check_outputs(&self, out: &UinterOutputs) -> Result<(), String> {
        if out.lsdi != self.lsdi {
            return Err("LSDI was written".into());
        }
        let refused = pnewdt_refusal(self.pnewdt, out.pnewdt, &out.message, "UINTER")?;
        let state_kept = bits(&out.stress) == bits(&self.stress)
            && bits(&out.statev) == bits(&self.statev)
            && out.lopenclose == self.lopenclose
            && out.lstate == self.lstate;
        if refused {
            if !state_kept {
                return Err("refused but STRESS, STATEV, LOPENCLOSE or LSTATE changed".into());
            }
            if let Some(x) = out.written().iter().find(|x| **x != 0.0) {
                return Err(format!("refused but an output was set to {x}, not zeroed"));
            }
            return Ok(());
        }
        // Success: only a valid shape gets here.
        let n = len(self.ndir);
        if !(2..=3).contains(&n) || self.nstatv < 3 {
            return Err(format!(
                "accepted NDIR = {}, NSTATV = {}",
                self.ndir, self.nstatv
            ));
        }
        let mut all = out.written();
        all.extend(&out.stress);
        all.extend(&out.statev[..3]);
        if let Some(x) = all.iter().find(|x| !x.is_finite()) {
            return Err(format!("success with a non-finite output {x}: {out:?}"));
        }
        if out.ddsddr.iter().any(unwritten) {
            return Err("DDSDDR not fully written".into());
        }
        if !self.null_optional {
            let everything = [
                &out.dviscous,
                &out.dstructural,
                &out.flux,
                &out.ddfddt,
                &out.ddsddt,
                &out.ddfddr,
            ];
            let unwritten = everything.iter().any(|v| v.iter().any(unwritten))
                || out.energies.iter().any(unwritten);
            if unwritten {
                return Err("an output was left unwritten".into());
            }
        }
        if bits(&out.statev[3..]) != bits(&self.statev[3..]) {
            return Err("STATEV past the law's 3 entries was written".into());
        }
        let [slip0, _, _] = [self.statev[0], self.statev[1], self.statev[2]];
        let [slip, rate, status] = [out.statev[0], out.statev[1], out.statev[2]];
        if rate < 0.0 || slip < slip0 {
            return Err(format!("bad slip state {:?}", &out.statev[..3]));
        }
        let code = match status {
            0.0 => 0,
            1.0 => 1,
            3.0 => 3,
            4.0 => 4,
            _ => return Err(format!("status STATEV(3) = {status}")),
        };
        if !self.null_optional && out.lstate != code {
            return Err(format!("LSTATE = {} but STATEV(3) = {status}", out.lstate));
        }
        if out.lopenclose != c_int::from(code != 4) {
            return Err(format!(
                "LOPENCLOSE = {} with status {code}",
                out.lopenclose
            ));
        }
        let p = out.stress[0];
        let tau = out.stress[1..].iter().fold(0.0f64, |s, x| s.hypot(*x));
        match code {
            4 if p != 0.0 || tau != 0.0 => {
                return Err(format!("open but STRESS = {:?}", out.stress));
            }
            3 if p > 0.0 => return Err(format!("bonded in compression: {:?}", out.stress)),
            0 | 1 if p < 0.0 => return Err(format!("closed in tension: {:?}", out.stress)),
            _ => {}
        }
        self.check_strength(out, tau)?;
        if !self.null_optional {
            let [sed, sfd, spd, svd, scd] = out.energies;
            if sed < 0.0 || sfd < 0.0 || spd < 0.0 || [svd, scd] != [0.0; 2] {
                return Err(format!("energies {:?}", out.energies));
            }
            // SPD is the energy of a bond breaking in this increment: a point not open at the
            // start (STATEV(3) ≠ 4), apart at the end (RDISP(1) ≤ 0), open after the call, with
            // separation adhesion (S_a, N_a > 0). Zero in every other increment.
            let get = |i: usize| self.props.get(i).copied().unwrap_or(0.0);
            let broke = self.statev[2] != 4.0
                && code == 4
                && self.rdisp[0] <= 0.0
                && get(3) > 0.0
                && get(4) > 0.0;
            if spd != 0.0 && !broke {
                return Err(format!("SPD = {spd:e} without a bond breaking: {out:?}"));
            }
            if bits(&out.dviscous) != bits(&vec![0.0; n * n])
                || bits(&out.dstructural) != bits(&vec![0.0; n * n])
                || bits(&out.ddsddt) != bits(&vec![0.0; 2 * n])
            {
                return Err("DVISCOUS, DSTRUCTURAL or DDSDDT not zero".into());
            }
        }
        Ok(())
    }

    /// |τ| ≤ (max(μ_s, μ_d) + k_μ·Δv)·p⁺ + S_a (seed 004: the static strength in stick, the
    /// rate-dependent strength while sliding, below S_a while bonded, 0 when open).
    fn check_strength(&self, out: &UinterOutputs, tau: f64) -> Result<(), String> {
        let get = |i: usize| self.props.get(i).copied().unwrap_or(0.0);
        let (mu_d, mu_s, s_a, k_mu) = (get(1), get(2), get(3), get(5));
        let mu = if mu_s > 0.0 { mu_s.max(mu_d) } else { mu_d };
        let p_plus = out.stress[0].max(0.0);
        // A slip rate saturated at f64::MAX (a slip over a subnormal DTIME) no longer tells
        // the rate the law used: no bound then for a rate-dependent law.
        // After a slip (start status 1) a stick increment keeps the stiffness of the start rate
        // (docs/props.md, the rate-dependent formulation): its strength is g(start rate).
        let start_rate = if self.statev.get(2) == Some(&1.0) {
            self.statev.get(1).copied().unwrap_or(0.0).max(0.0)
        } else {
            0.0
        };
        let rate = out.statev[1].max(start_rate);
        let bound = if rate == f64::MAX && k_mu > 0.0 {
            f64::INFINITY
        } else {
            (mu + k_mu * rate) * p_plus + s_a
        };
        let tol = bound * 1e-12 + 1e-321;
        if tau > bound + tol {
            return Err(format!(
                "|TAU| = {tau:e} above the strength {bound:e}: {out:?}"
            ));
        }
        Ok(())
    }
}

/// What `uinter_` wrote, and its message (empty on success).
#[derive(Clone, Debug)]
pub struct UinterOutputs {
    pub stress: Vec<f64>,
    pub ddsddr: Vec<f64>,
    pub dviscous: Vec<f64>,
    pub dstructural: Vec<f64>,
    pub flux: Vec<f64>,
    pub ddfddt: Vec<f64>,
    pub ddsddt: Vec<f64>,
    pub ddfddr: Vec<f64>,
    pub statev: Vec<f64>,
    /// `SED`, `SFD`, `SPD`, `SVD`, `SCD`.
    pub energies: [f64; 5],
    pub pnewdt: f64,
    pub lopenclose: i32,
    pub lstate: i32,
    pub lsdi: i32,
    pub message: String,
}

impl UinterOutputs {
    /// The entries of the tangents, fluxes and energies that the call wrote.
    pub fn written(&self) -> Vec<f64> {
        let arrays = [
            &self.ddsddr,
            &self.dviscous,
            &self.dstructural,
            &self.flux,
            &self.ddfddt,
            &self.ddsddt,
            &self.ddfddr,
        ];
        arrays
            .into_iter()
            .flatten()
            .chain(&self.energies)
            .copied()
            .filter(|x| !unwritten(x))
            .collect()
    }
}

/// Bitwise equality of every input.
fn same(a: &UinterCase, b: &UinterCase) -> bool {
    let reals = |c: &UinterCase| {
        input_bits(
            &[c.pnewdt, c.dtime, c.freqr, c.area, c.chrlngth],
            &[
                &c.stress,
                &c.statev,
                &c.rdisp,
                &c.drdisp,
                &c.temp,
                &c.dtemp,
                &c.predef,
                &c.dpred,
                &c.time,
                &c.props,
                &c.coords,
                &c.alocaldir,
                &c.drot,
            ],
        )
    };
    let ints = |c: &UinterCase| {
        [
            c.ndir,
            c.nstatv,
            c.npred,
            c.nprops,
            c.mcrd,
            c.node,
            c.kstep,
            c.kinc,
            c.kit,
            c.linper,
            c.lprint,
            c.lopenclose,
            c.lstate,
            c.lsdi,
        ]
    };
    reals(a) == reals(b) && ints(a) == ints(b) && a.names == b.names
}
