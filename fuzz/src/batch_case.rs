//! One `ifl_fric_batch` call decoded from fuzzer bytes: random `npoints`, `ld`, `nfdir`,
//! `nstatv`, every structure-of-arrays input allocated with exactly `ld·(components − 1) +
//! npoints` entries (so AddressSanitizer reports any access past it), and the properties:
//! each point bit for bit what `fric_` gives it, and a whole-batch fault writes only `pnewdt`.
//!
//! Shared by the `batch` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use std::ffi::c_int;

use super::bytes::{Bytes, bits};
use super::contract::{last_error, unwritten};
use super::fric_case::{FricCase, FricOutputs};
use interfacial::abi::{IflStatus, ifl_clear_error, ifl_fric_batch};

pub use super::contract::UNWRITTEN;

/// Every `ifl_fric_batch` argument; arrays in the batch layout with exactly the needed length.
#[derive(Clone, Debug)]
pub struct BatchCase {
    pub npoints: usize,
    pub ld: usize,
    pub nfdir: i32,
    pub nstatv: i32,
    pub props: Vec<f64>,
    pub dtime: f64,
    pub pnewdt: f64,
    pub lm: Vec<c_int>,
    pub tau: Vec<f64>,
    pub statev: Vec<f64>,
    pub dgam: Vec<f64>,
    pub taulm: Vec<f64>,
    pub press: Vec<f64>,
    pub dpress: Vec<f64>,
    pub chrlngth: Vec<f64>,
    /// `dslip`, `sed`, `sfd` NULL.
    pub null_optional: bool,
    /// `taulm` NULL.
    pub null_taulm: bool,
    /// A required array NULL (index into lm, tau, ddtddg, ddtddp, statev, dgam, press,
    /// dpress, chrlngth), or none.
    pub null_required: Option<usize>,
}

/// What the batch wrote (the whole arrays, padding included), its status and message.
#[derive(Clone, Debug, PartialEq)]
pub struct BatchOutputs {
    pub lm: Vec<c_int>,
    pub tau: Vec<f64>,
    pub ddtddg: Vec<f64>,
    pub ddtddp: Vec<f64>,
    pub dslip: Vec<f64>,
    pub sed: Vec<f64>,
    pub sfd: Vec<f64>,
    pub statev: Vec<f64>,
    pub pnewdt: f64,
    pub status: i32,
    pub message: String,
}

impl BatchCase {
    /// Entries an array of `components` rows needs (0 for an empty batch).
    pub fn needed(&self, components: usize) -> usize {
        if self.npoints == 0 {
            0
        } else {
            self.ld * components.saturating_sub(1) + self.npoints
        }
    }

    fn n(&self) -> usize {
        usize::try_from(self.nfdir).unwrap_or(0).clamp(1, 2)
    }

    fn s(&self) -> usize {
        usize::try_from(self.nstatv).unwrap_or(0).max(1)
    }

    /// Decodes any byte string; most inputs are valid batches of a Coulomb law.
    pub fn decode(data: &[u8]) -> Self {
        let mut b = Bytes::new(data);
        let npoints = usize::from(b.u8() % 12);
        let pad = b.pick(&[0usize, 0, 1, 2, 3, 7]);
        let ld = if b.u8() % 16 == 0 {
            npoints.saturating_sub(1)
        } else {
            npoints + pad
        };
        let nfdir = b.pick(&[1, 2, 1, 2, 1, 2, 1, 2, 0, 3, -1]);
        let nstatv = b.pick(&[3, 3, 3, 4, 5, 2, 0, -1]);
        let nprops = b.pick(&[5, 7, 7, 7, 7, 6, 4, 2, 8, 1, 0]);
        let mut props: Vec<f64> = Vec::new();
        for i in 0..nprops {
            let sel = b.u8() % 8;
            let v = match (i, sel) {
                (_, 7) => b.real(),
                (0, 6) => 2.0,
                (0, _) => 1.0,
                (1, _) => b.unit(),
                (2, 0..=4) => 0.0,
                (2, _) => props[1],
                (3, 0..=3) => 0.0,
                (3, _) => b.positive(),
                (4 | 5, 0..=2) => 0.0,
                (4 | 5, _) => b.positive(),
                (6, _) => f64::from(sel % 3),
                _ => 0.0,
            };
            props.push(v);
        }
        let flags = b.u8();
        let mut c = BatchCase {
            npoints,
            ld,
            nfdir,
            nstatv,
            props,
            dtime: b.real(),
            pnewdt: b.large(),
            lm: Vec::new(),
            tau: Vec::new(),
            statev: Vec::new(),
            dgam: Vec::new(),
            taulm: Vec::new(),
            press: Vec::new(),
            dpress: Vec::new(),
            chrlngth: Vec::new(),
            null_optional: flags & 0x80 != 0,
            null_taulm: flags & 0x60 == 0x60,
            null_required: (flags & 0x1f == 0x1f).then(|| usize::from(b.u8() % 9)),
        };
        let (n, s) = (c.n(), c.s());
        c.lm = (0..c.needed(1))
            .map(|_| b.pick(&[0, 0, 0, 0, 1, 1, 2, -1]))
            .collect();
        let mut reals = |len: usize| (0..len).map(|_| b.real()).collect::<Vec<f64>>();
        c.tau = reals(c.needed(n));
        c.dgam = reals(c.needed(n));
        c.taulm = reals(c.needed(n));
        c.press = reals(c.needed(1));
        c.dpress = reals(c.needed(1));
        c.chrlngth = reals(c.needed(1));
        c.statev = reals(c.needed(s));
        // STATEV(3) is a status code: mostly 0, 1, 2.
        if s >= 3 && npoints > 0 {
            for i in 0..npoints {
                let x = &mut c.statev[i + 2 * ld];
                if x.is_finite() {
                    *x = (x.abs() % 3.0).floor();
                }
            }
        }
        c
    }

    /// Calls `ifl_fric_batch` (status, message, what it wrote).
    pub fn call(&self) -> BatchOutputs {
        let n = self.n();
        let c = self.clone();
        let mut out = BatchOutputs {
            lm: c.lm.clone(),
            tau: c.tau.clone(),
            ddtddg: vec![UNWRITTEN; self.needed(n * n)],
            ddtddp: vec![UNWRITTEN; self.needed(n)],
            dslip: vec![UNWRITTEN; self.needed(n)],
            sed: vec![UNWRITTEN; self.needed(1)],
            sfd: vec![UNWRITTEN; self.needed(1)],
            statev: c.statev.clone(),
            pnewdt: c.pnewdt,
            status: 0,
            message: String::new(),
        };
        let req = |k: usize| self.null_required == Some(k);
        let m = |k: usize, p: *mut f64| if req(k) { std::ptr::null_mut() } else { p };
        let r = |k: usize, p: *const f64| if req(k) { std::ptr::null() } else { p };
        let opt = |p: *mut f64| {
            if self.null_optional {
                std::ptr::null_mut()
            } else {
                p
            }
        };
        let lm = if req(0) {
            std::ptr::null_mut()
        } else {
            out.lm.as_mut_ptr()
        };
        let nprops = i32::try_from(c.props.len()).unwrap_or(i32::MAX);
        ifl_clear_error();
        // SAFETY: every non-NULL array holds exactly ld·(components − 1) + npoints entries (0
        // for an empty batch), props holds nprops; outputs do not overlap.
        let status: IflStatus = unsafe {
            ifl_fric_batch(
                c.npoints,
                c.ld,
                c.nfdir,
                c.props.as_ptr(),
                nprops,
                c.nstatv,
                c.dtime,
                lm,
                m(1, out.tau.as_mut_ptr()),
                m(2, out.ddtddg.as_mut_ptr()),
                m(3, out.ddtddp.as_mut_ptr()),
                opt(out.dslip.as_mut_ptr()),
                opt(out.sed.as_mut_ptr()),
                opt(out.sfd.as_mut_ptr()),
                m(4, out.statev.as_mut_ptr()),
                r(5, c.dgam.as_ptr()),
                if c.null_taulm {
                    std::ptr::null()
                } else {
                    c.taulm.as_ptr()
                },
                r(6, c.press.as_ptr()),
                r(7, c.dpress.as_ptr()),
                r(8, c.chrlngth.as_ptr()),
                &mut out.pnewdt,
            )
        };
        out.status = status as i32;
        out.message = last_error();
        out
    }

    /// Whether the batch as a whole must be refused, by its shape alone.
    fn bad_shape(&self) -> bool {
        let required_null = self.null_required.is_some() && self.npoints > 0;
        !(1..=2).contains(&self.nfdir) || self.nstatv < 3 || self.ld < self.npoints || required_null
    }

    /// Point `i` as a `fric_` call with the batch's law, `DTIME` and entry `PNEWDT`.
    pub fn point(&self, i: usize) -> FricCase {
        let (n, s, ld) = (self.n(), self.s(), self.ld);
        let mut f = FricCase::coulomb(self.nfdir, &self.props);
        f.lm = self.lm[i];
        f.tau = (0..n).map(|a| self.tau[i + a * ld]).collect();
        f.dgam = (0..n).map(|a| self.dgam[i + a * ld]).collect();
        f.taulm = (0..n).map(|a| self.taulm[i + a * ld]).collect();
        f.statev = (0..s).map(|r| self.statev[i + r * ld]).collect();
        f.nstatv = self.nstatv;
        f.press = self.press[i];
        f.dpress = self.dpress[i];
        f.chrlngth = self.chrlngth[i];
        f.dtime = self.dtime;
        f.pnewdt = self.pnewdt;
        f.null_optional = self.null_optional;
        f
    }

    /// Calls the batch and checks every property; `Err` names the first one violated.
    pub fn check(&self) -> Result<BatchOutputs, String> {
        let before = self.clone();
        let out = self.call();
        let inputs = |c: &BatchCase| {
            let mut v = bits(&c.props);
            for a in [&c.dgam, &c.taulm, &c.press, &c.dpress, &c.chrlngth] {
                v.extend(bits(a));
            }
            v
        };
        if inputs(self) != inputs(&before) {
            return Err("an input array was written".into());
        }
        let untouched = out.lm == self.lm
            && bits(&out.tau) == bits(&self.tau)
            && bits(&out.statev) == bits(&self.statev)
            && [&out.ddtddg, &out.ddtddp, &out.dslip, &out.sed, &out.sfd]
                .iter()
                .all(|v| v.iter().all(unwritten));
        let ok = out.status == IflStatus::Ok as i32;
        if ok != out.message.is_empty() {
            return Err(format!(
                "status {} with message {:?}",
                out.status, out.message
            ));
        }
        if !ok && !out.message.starts_with("interfacial: ifl_fric_batch: ") {
            return Err(format!(
                "message does not name the routine: {:?}",
                out.message
            ));
        }
        // A batch of the adhesive law may be refused as a whole (no batch kernel), unless it
        // reduces to the Coulomb law, in which case it must run like fric_.
        // Likewise the extended law 1 (anisotropy, μ laws, damping): fric_ runs it, the batch
        // kernel is the plain law's.
        let adhesive_refusal = !ok
            && untouched
            && (out.message.contains("PROPS(1) = 2 (adhesive)")
                || out.message.contains("extended law-1 PROPS"));
        let probe_refused = !self.bad_shape() && {
            let mut probe = FricCase::coulomb(self.nfdir, &self.props);
            probe.nstatv = self.nstatv;
            probe.statev = vec![0.0; self.s()];
            // Only a PROPS fault is a fault of the whole batch; a numerical failure of the
            // probe's own zero inputs is not.
            probe.check()?.message.contains("bad parameter:")
        };
        if self.bad_shape() || probe_refused || adhesive_refusal {
            if ok || !untouched {
                return Err(format!(
                    "a batch with a bad shape or PROPS was not refused as a whole: {out:?}"
                ));
            }
            let lowered = out.pnewdt <= 0.25;
            if !lowered {
                return Err(format!("whole-batch fault with PNEWDT = {}", out.pnewdt));
            }
            return Ok(out);
        }
        // Per point: exactly fric_.
        let mut expect = BatchOutputs {
            pnewdt: self.pnewdt,
            status: IflStatus::Ok as i32,
            message: String::new(),
            ..out.clone()
        };
        expect.lm = self.lm.clone();
        expect.tau = self.tau.clone();
        expect.statev = self.statev.clone();
        for v in [
            &mut expect.ddtddg,
            &mut expect.ddtddp,
            &mut expect.dslip,
            &mut expect.sed,
            &mut expect.sfd,
        ] {
            v.iter_mut().for_each(|x| *x = UNWRITTEN);
        }
        let (n, ld) = (self.n(), self.ld);
        let mut failed = false;
        for i in 0..self.npoints {
            let f = self.point(i);
            let r = if self.null_taulm && f.lm == 1 {
                // No TAULM array: a point entering exact stick gets fric_'s failure outputs
                // (LM, TAU, STATEV kept; tangents, DSLIP, SFD zero; PNEWDT 0.25).
                let optional = |v: f64| if self.null_optional { UNWRITTEN } else { v };
                FricOutputs {
                    lm: f.lm,
                    tau: f.tau.clone(),
                    ddtddg: vec![0.0; n * n],
                    ddtddp: vec![0.0; n],
                    dslip: vec![optional(0.0); n],
                    sed: UNWRITTEN,
                    sfd: optional(0.0),
                    ddtddt: Vec::new(),
                    pnewdt: if self.pnewdt.is_nan() || self.pnewdt > 0.25 {
                        0.25
                    } else {
                        self.pnewdt
                    },
                    statev: f.statev.clone(),
                    message: "LM = 1 but no TAULM".into(),
                }
            } else {
                f.check()
                    .map_err(|e| format!("point {i} through fric_: {e}"))?
            };
            if !r.message.is_empty() {
                failed = true;
            }
            expect.lm[i] = r.lm;
            for a in 0..n {
                expect.tau[i + a * ld] = r.tau[a];
                expect.ddtddp[i + a * ld] = r.ddtddp[a];
                expect.dslip[i + a * ld] = r.dslip[a];
                for c in 0..n {
                    expect.ddtddg[i + (a + c * n) * ld] = r.ddtddg[a + c * n];
                }
            }
            expect.sed[i] = r.sed;
            expect.sfd[i] = r.sfd;
            for k in 0..self.s() {
                expect.statev[i + k * ld] = r.statev[k];
            }
            if r.pnewdt.to_bits() != self.pnewdt.to_bits()
                && (expect.pnewdt.is_nan() || r.pnewdt < expect.pnewdt)
            {
                expect.pnewdt = r.pnewdt;
            }
        }
        let same = expect.lm == out.lm
            && [
                (&expect.tau, &out.tau),
                (&expect.ddtddg, &out.ddtddg),
                (&expect.ddtddp, &out.ddtddp),
                (&expect.dslip, &out.dslip),
                (&expect.sed, &out.sed),
                (&expect.sfd, &out.sfd),
                (&expect.statev, &out.statev),
            ]
            .iter()
            .all(|(a, b)| bits(a) == bits(b))
            && expect.pnewdt.to_bits() == out.pnewdt.to_bits();
        if !same {
            return Err(format!(
                "the batch differs from fric_ per point:\n batch: {out:?}\n fric_: {expect:?}"
            ));
        }
        if failed == ok {
            return Err(format!(
                "status {} but a point failed through fric_: {failed}",
                out.status
            ));
        }
        Ok(out)
    }
}
