//! One `fric_` call decoded from fuzzer bytes: all 39 arguments and the 3 hidden lengths, every
//! array allocated with exactly the length the call declares (so AddressSanitizer reports any
//! access past it), and the properties every call must have.
//!
//! Shared by the `fric` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use super::bytes::{Bytes, bits, len};
use super::contract::{Names, input_bits, last_error, pnewdt_refusal, unwritten};
use interfacial::abi::{fric_, ifl_clear_error};

pub use super::contract::UNWRITTEN;

/// Every `fric_` argument. Arrays have exactly their declared lengths.
#[derive(Clone, Debug)]
pub struct FricCase {
    pub lm: i32,
    pub nfdir: i32,
    pub nstatv: i32,
    pub nprops: i32,
    pub mcrd: i32,
    pub npred: i32,
    pub kstep: i32,
    pub kinc: i32,
    pub noel: i32,
    pub npt: i32,
    pub node: i32,
    pub npatch: i32,
    /// `TAU(NFDIR)`.
    pub tau: Vec<f64>,
    /// `DGAM(NFDIR)`.
    pub dgam: Vec<f64>,
    /// `TAULM(NFDIR)`.
    pub taulm: Vec<f64>,
    /// `SLIP(NFDIR)`.
    pub slip: Vec<f64>,
    /// `STATEV(NSTATV)`.
    pub statev: Vec<f64>,
    /// `PROPS(NPROPS)`.
    pub props: Vec<f64>,
    pub press: f64,
    pub dpress: f64,
    pub ddpddh: f64,
    pub dtime: f64,
    pub chrlngth: f64,
    pub pnewdt: f64,
    /// `TIME(2)`.
    pub time: Vec<f64>,
    /// `COORDS(MCRD)`.
    pub coords: Vec<f64>,
    /// `RCOORD(MCRD)`.
    pub rcoord: Vec<f64>,
    /// `DROT(2,2)`.
    pub drot: Vec<f64>,
    /// `TEMP(2)`.
    pub temp: Vec<f64>,
    /// `PREDEF(2,NPRED)`.
    pub predef: Vec<f64>,
    /// `CINAME`, `SLNAME`, `MSNAME`.
    pub names: Names,
    /// Pass NULL for the optional outputs `DSLIP`, `SED`, `SFD`, `DDTDDT`.
    pub null_optional: bool,
}

impl FricCase {
    /// A valid Coulomb call with `nfdir` directions and these `props`, `NSTATV = 3`, all reals
    /// zero except `DTIME = CHRLNGTH = 1`, `PNEWDT = 1e36`, interaction name `"SI1"` (80 bytes).
    pub fn coulomb(nfdir: i32, props: &[f64]) -> Self {
        let n = len(nfdir);
        FricCase {
            lm: 0,
            nfdir,
            nstatv: 3,
            nprops: i32::try_from(props.len()).unwrap_or(i32::MAX),
            mcrd: 3,
            npred: 1,
            kstep: 1,
            kinc: 1,
            noel: 1,
            npt: 1,
            node: 1,
            npatch: 1,
            tau: vec![0.0; n],
            dgam: vec![0.0; n],
            taulm: vec![0.0; n],
            slip: vec![0.0; n],
            statev: vec![0.0; 3],
            props: props.to_vec(),
            press: 0.0,
            dpress: 0.0,
            ddpddh: 0.0,
            dtime: 1.0,
            chrlngth: 1.0,
            pnewdt: 1e36,
            time: vec![0.0; 2],
            coords: vec![0.0; 3],
            rcoord: vec![0.0; 3],
            drot: vec![1.0, 0.0, 0.0, 1.0],
            temp: vec![20.0; 2],
            predef: vec![0.0; 2],
            names: Names::padded("SI1"),
            null_optional: false,
        }
    }

    /// Decodes any byte string. The choices favour valid calls (NFDIR 1 or 2, NSTATV ≥ 3, a
    /// Coulomb `PROPS`) so most inputs reach the law, but every bad shape stays reachable.
    pub fn decode(data: &[u8]) -> Self {
        let mut b = Bytes::new(data);
        let nfdir = b.pick(&[1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 0, 3, -1]);
        let nstatv = b.pick(&[3, 3, 3, 3, 4, 5, 8, 2, 0, -1]);
        // The first list twice (so that recorded inputs decode as before, `pick` taking the
        // byte modulo the length), with two of the second half's 7s made 20 (the extended
        // layout).
        let nprops = b.pick(&[
            2, 5, 7, 7, 7, 7, 7, 7, 6, 4, 3, 8, 9, 1, 0, -1, //
            2, 5, 7, 20, 7, 20, 7, 7, 6, 4, 3, 8, 9, 1, 0, -1,
        ]);
        let lm = b.pick(&[0, 0, 0, 0, 1, 1, 2, -1, 3]);
        let mcrd = b.pick(&[3, 2, 1, 0]);
        let npred = b.pick(&[1, 0, 2]);
        let n = len(nfdir);
        let mut props = Vec::with_capacity(len(nprops));
        for i in 0..len(nprops) {
            let sel = b.u8();
            let v = match (i, sel % 4) {
                // PROPS(1): mostly the Coulomb code.
                (0, 0..=2) => 1.0,
                // PROPS(3) μ₂: mostly 0 or μ.
                (2, 0 | 1) => 0.0,
                (2, 2) => props[1],
                // The 20-entry layout: mostly the exponential-decay μ law (PROPS(8) = 1, d_c =
                // PROPS(10) > 0), whose lean layout has a fast path of its own in `fric_`.
                (7, 0..=2) if nprops == 20 => 1.0,
                (9, 0..=2) if nprops == 20 => 0.5 * f64::from(sel % 4 + 1),
                // PROPS(4..6), PROPS(8..): mostly 0 ("off" / "default").
                (3..=5 | 7.., 0 | 1) => 0.0,
                // PROPS(7): stick mode 0, 1, 2.
                (6, 0..=2) => f64::from(sel % 4),
                _ => b.real(),
            };
            props.push(v);
        }
        let flags = b.u8();
        // Mostly a printable name, blank-padded to the hidden length.
        let name = |b: &mut Bytes| {
            b.name_padded(flags & 0x40 == 0, if flags & 0x20 == 0 { b' ' } else { 0 })
        };
        FricCase {
            lm,
            nfdir,
            nstatv,
            nprops,
            mcrd,
            npred,
            kstep: 1,
            kinc: 1,
            noel: i32::from(b.u16()),
            npt: 1,
            node: i32::from(b.u16()),
            npatch: 1,
            tau: b.reals(n),
            dgam: b.reals(n),
            taulm: b.reals(n),
            slip: b.reals(n),
            statev: {
                let mut s = b.reals(len(nstatv));
                // STATEV(3) is a status code; keep it one mostly.
                if let Some(x) = s.get_mut(2) {
                    *x = f64::from(b.u8() % 3);
                }
                s
            },
            props,
            press: b.real(),
            dpress: b.real(),
            ddpddh: b.real(),
            dtime: b.real(),
            chrlngth: b.real(),
            pnewdt: b.large(),
            time: b.reals(2),
            coords: b.reals(len(mcrd)),
            rcoord: b.reals(len(mcrd)),
            drot: b.reals(4),
            temp: b.reals(2),
            predef: b.reals(2 * len(npred)),
            names: Names {
                interaction: name(&mut b),
                secondary: name(&mut b),
                main: name(&mut b),
            },
            null_optional: flags & 0x80 != 0,
        }
    }

    /// Calls `fric_` and checks every property; `Err` names the first one violated.
    pub fn check(&self) -> Result<FricOutputs, String> {
        let before = self.clone();
        let c = self.clone();
        let n = len(self.nfdir);
        let mut out = FricOutputs {
            lm: c.lm,
            tau: c.tau.clone(),
            ddtddg: vec![UNWRITTEN; n * n],
            ddtddp: vec![UNWRITTEN; n],
            dslip: vec![UNWRITTEN; n],
            sed: UNWRITTEN,
            sfd: UNWRITTEN,
            ddtddt: vec![UNWRITTEN; 2 * n],
            pnewdt: c.pnewdt,
            statev: c.statev.clone(),
            message: String::new(),
        };
        let opt = |p: *mut f64, null: bool| if null { std::ptr::null_mut() } else { p };
        let null = c.null_optional;
        let [ci, sl, ms] = c.names.pointers();
        let [ci_len, sl_len, ms_len] = c.names.lengths();
        ifl_clear_error();
        // SAFETY: every array has exactly the length the call declares (NFDIR, NFDIR², 2·NFDIR,
        // NSTATV, NPROPS, MCRD, 2·NPRED, the hidden name lengths); scalars are locals.
        unsafe {
            fric_(
                &mut out.lm,
                out.tau.as_mut_ptr(),
                out.ddtddg.as_mut_ptr(),
                out.ddtddp.as_mut_ptr(),
                opt(out.dslip.as_mut_ptr(), null),
                opt(&mut out.sed, null),
                opt(&mut out.sfd, null),
                opt(out.ddtddt.as_mut_ptr(), null),
                &mut out.pnewdt,
                out.statev.as_mut_ptr(),
                c.dgam.as_ptr(),
                c.taulm.as_ptr(),
                &c.press,
                &c.dpress,
                &c.ddpddh,
                c.slip.as_ptr(),
                &c.kstep,
                &c.kinc,
                c.time.as_ptr(),
                &c.dtime,
                &c.noel,
                ci,
                sl,
                ms,
                &c.npt,
                &c.node,
                &c.npatch,
                c.coords.as_ptr(),
                c.rcoord.as_ptr(),
                c.drot.as_ptr(),
                c.temp.as_ptr(),
                c.predef.as_ptr(),
                &c.nfdir,
                &c.mcrd,
                &c.npred,
                &c.nstatv,
                &c.chrlngth,
                c.props.as_ptr(),
                &c.nprops,
                ci_len,
                sl_len,
                ms_len,
            );
            out.message = last_error();
        }
        // The input arguments are never written (LM, TAU, PNEWDT, STATEV are in `out`).
        if !same(&c, &before) {
            return Err("an input argument was written".into());
        }
        self.check_outputs(&out)?;
        Ok(out)
    }

    fn check_outputs(&self, out: &FricOutputs) -> Result<(), String> {
        if pnewdt_refusal(self.pnewdt, out.pnewdt, &out.message, "FRIC")? {
            if out.lm != self.lm || bits(&out.tau) != bits(&self.tau) {
                return Err("refused but LM or TAU changed".into());
            }
            if bits(&out.statev) != bits(&self.statev) {
                return Err("refused but STATEV changed".into());
            }
            return Ok(());
        }
        // Success.
        if self.lm == 2 {
            let untouched = out.lm == 2
                && bits(&out.tau) == bits(&self.tau)
                && bits(&out.statev) == bits(&self.statev)
                && out.written().is_empty();
            return if untouched {
                Ok(())
            } else {
                Err("LM = 2 on entry but an output was written".into())
            };
        }
        if out.lm != 0 && out.lm != 1 {
            return Err(format!("LM = {} on exit", out.lm));
        }
        let mut written = out.written();
        if out.lm == 0 {
            written.extend(&out.tau);
        }
        // The law's state: STATEV(1..3), and with tangential damping (law 1, PROPS(17) ≠ 0)
        // the viscous stress in STATEV(4..3+NFDIR) (docs/props.md).
        let damping =
            self.props.first() == Some(&1.0) && self.props.get(16).is_some_and(|c| *c != 0.0);
        let used = 3 + if damping { len(self.nfdir) } else { 0 };
        written.extend(&out.statev[..used]);
        if let Some(x) = written.iter().find(|x| !x.is_finite()) {
            return Err(format!("success with a non-finite output {x}: {out:?}"));
        }
        if bits(&out.statev[used..]) != bits(&self.statev[used..]) {
            return Err(format!("STATEV past the law's {used} entries was written"));
        }
        if out.statev[1] < 0.0 || ![0.0, 1.0, 2.0].contains(&out.statev[2]) {
            return Err(format!("bad state {:?}", &out.statev[..3]));
        }
        if out.statev[0] < self.statev[0] {
            return Err("accumulated slip decreased".into());
        }
        for (name, x) in [("SED", out.sed), ("SFD", out.sfd)] {
            if x != UNWRITTEN && x < 0.0 {
                return Err(format!("{name} = {x} < 0"));
            }
        }
        if out.lm == 0 {
            self.check_cone(out)?;
        }
        Ok(())
    }

    /// |τ| ≤ τ_crit = min(μp, τ_max) (0 for p < 0), and |τ| = τ_crit while slipping, for the
    /// plain law 1; the adhesive law (`PROPS(1) = 2`) against its own strength. The extended
    /// law 1 (anisotropy, μ laws, damping: `PROPS(3)` ≠ 0, μ or any of `PROPS(8..)`) has a bound
    /// that depends on the rate, the temperature and the damping state; its cone is checked in
    /// `tests/friction_extended.rs`, here only the common properties.
    fn check_cone(&self, out: &FricOutputs) -> Result<(), String> {
        let get = |i: usize| self.props.get(i).copied().unwrap_or(0.0);
        if get(0) == 2.0 {
            return self.check_adhesive_strength(out);
        }
        let anisotropic = get(2) != 0.0 && get(2) != get(1);
        if anisotropic || self.props.iter().skip(7).any(|x| *x != 0.0) {
            return Ok(());
        }
        let (mu, tau_max) = (get(1), get(3));
        let tau_max = if tau_max > 0.0 {
            tau_max
        } else {
            f64::INFINITY
        };
        let tau_crit = if self.press < 0.0 {
            0.0
        } else {
            (mu * self.press).min(tau_max)
        };
        let magnitude = out.tau.iter().fold(0.0f64, |s, x| s.hypot(*x));
        // A few ulps, and a few hundred subnormal steps where τ_crit itself is tiny.
        let tol = tau_crit * 1e-12 + 1e-321;
        if magnitude > tau_crit + tol {
            return Err(format!(
                "|TAU| = {magnitude:e} above τ_crit = {tau_crit:e}: {out:?}"
            ));
        }
        let elastic = get(6) == 0.0;
        let slipping = out.statev[2] == 1.0;
        if elastic && slipping && magnitude < tau_crit - tol && tau_crit >= f64::MIN_POSITIVE {
            return Err(format!(
                "slipping with |TAU| = {magnitude:e} below τ_crit = {tau_crit:e}: {out:?}"
            ));
        }
        Ok(())
    }

    /// Seed 004: |τ| ≤ (max(μ_s, μ_d) + k_μ·Δv)·p⁺ + S_a, Δv the slip rate the call reports in
    /// `STATEV(2)` (the sliding stress at any rate, and the static strength in stick). S_a is
    /// carried at any pressure, negative included.
    fn check_adhesive_strength(&self, out: &FricOutputs) -> Result<(), String> {
        let get = |i: usize| self.props.get(i).copied().unwrap_or(0.0);
        let (mu_d, mu_s, s_a, k_mu) = (get(1), get(2), get(3), get(5));
        let p_plus = self.press.max(0.0);
        // The rate term from STATEV(2), and again from |DSLIP|·(p/Δt): STATEV(2) can be
        // subnormal (few significant bits) while the law's own k_μ/Δt is not.
        // After a slip (start status 1) a stick increment keeps the stiffness of the start rate
        // (docs/props.md, the rate-dependent formulation): its strength is g(start rate).
        let start_rate = if self.statev.get(2) == Some(&1.0) {
            self.statev.get(1).copied().unwrap_or(0.0).max(0.0)
        } else {
            0.0
        };
        let via_state = k_mu * out.statev[1].max(start_rate) * p_plus;
        let slip = out.dslip.iter().fold(0.0f64, |s, x| s.hypot(*x));
        let via_slip = if self.dtime > 0.0 && !out.dslip.contains(&UNWRITTEN) {
            k_mu * slip * (p_plus / self.dtime)
        } else {
            0.0
        };
        // A rate saturated at f64::MAX with k_μ > 0: no finite bound to check.
        if out.statev[1].max(start_rate) == f64::MAX && k_mu > 0.0 {
            return Ok(());
        }
        let rate_term = if via_slip.is_finite() {
            via_state.max(via_slip)
        } else {
            via_state
        };
        let strength = mu_d.max(mu_s) * p_plus + rate_term + s_a;
        let magnitude = out.tau.iter().fold(0.0f64, |s, x| s.hypot(*x));
        if magnitude > strength * (1.0 + 1e-12) + 1e-321 {
            return Err(format!(
                "adhesive law: |TAU| = {magnitude:e} above its strength {strength:e}: {out:?}"
            ));
        }
        Ok(())
    }
}

/// What `fric_` wrote, and its message (empty on success).
#[derive(Clone, Debug)]
pub struct FricOutputs {
    pub lm: i32,
    pub tau: Vec<f64>,
    pub ddtddg: Vec<f64>,
    pub ddtddp: Vec<f64>,
    pub dslip: Vec<f64>,
    pub sed: f64,
    pub sfd: f64,
    pub ddtddt: Vec<f64>,
    pub pnewdt: f64,
    pub statev: Vec<f64>,
    pub message: String,
}

impl FricOutputs {
    /// The entries of DDTDDG, DDTDDP, DSLIP, SED, SFD, DDTDDT that the call wrote.
    pub fn written(&self) -> Vec<f64> {
        let all = self.ddtddg.iter().chain(&self.ddtddp).chain(&self.dslip);
        all.chain([&self.sed, &self.sfd])
            .chain(&self.ddtddt)
            .copied()
            .filter(|x| !unwritten(x))
            .collect()
    }
}

/// Bitwise equality of every input.
fn same(a: &FricCase, b: &FricCase) -> bool {
    let reals = |c: &FricCase| {
        input_bits(
            &[c.press, c.dpress, c.ddpddh, c.dtime, c.chrlngth],
            &[
                &c.dgam, &c.taulm, &c.slip, &c.props, &c.time, &c.coords, &c.rcoord, &c.drot,
                &c.temp, &c.predef,
            ],
        )
    };
    let ints = |c: &FricCase| {
        [
            c.nfdir, c.nstatv, c.nprops, c.mcrd, c.npred, c.kstep, c.kinc, c.noel, c.npt, c.node,
            c.npatch,
        ]
    };
    reals(a) == reals(b) && ints(a) == ints(b) && a.names == b.names
}
