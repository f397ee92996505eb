//! Helpers shared by the batch tests (`batch.rs`, `batch_chunks.rs`): a reproducible generator,
//! points in the batch's structure-of-arrays layout, the same points through `fric_` one by one
//! and through `ifl_fric_batch`, and a bit-for-bit comparison.
// Each test file uses its own subset.
#![allow(dead_code)]

use interfacial::abi::{IflStatus, ifl_fric_batch};
use interfacial_test_hosts::FricCall;

/// A small deterministic generator (xorshift64*), so failures reproduce.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [a, b).
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
    /// Uniform in 0..n.
    pub fn pick(&mut self, n: usize) -> usize {
        ((self.next() * n as f64) as usize).min(n - 1)
    }
}

/// What outputs hold before a call, so that "not written" is compared too.
pub const UNSET: f64 = 12345.678;

/// `n` points (leading dimension `ld ≥ n`) in the batch layout: entry `i` of component `a` at
/// `i + a·ld`, `DDTDDG(a,b)` at `i + (a + b·nfdir)·ld`, `STATEV(r)` at `i + r·ld`.
#[derive(Clone, Debug)]
pub struct Points {
    pub n: usize,
    pub ld: usize,
    pub nfdir: usize,
    pub nstatv: usize,
    pub lm: Vec<i32>,
    pub tau: Vec<f64>,
    pub ddtddg: Vec<f64>,
    pub ddtddp: Vec<f64>,
    pub dslip: Vec<f64>,
    pub sed: Vec<f64>,
    pub sfd: Vec<f64>,
    pub statev: Vec<f64>,
    pub dgam: Vec<f64>,
    pub taulm: Vec<f64>,
    pub press: Vec<f64>,
    pub dpress: Vec<f64>,
    pub chrlngth: Vec<f64>,
}

impl Points {
    /// Every array sized for `ld` points, `LM` and `TAULM` 0, everything else [`UNSET`] (the
    /// caller draws the inputs of the first `n` points).
    pub fn new(n: usize, ld: usize, nfdir: usize, nstatv: usize) -> Points {
        Points {
            n,
            ld,
            nfdir,
            nstatv,
            lm: vec![0; ld],
            tau: vec![UNSET; ld * nfdir],
            ddtddg: vec![UNSET; ld * nfdir * nfdir],
            ddtddp: vec![UNSET; ld * nfdir],
            dslip: vec![UNSET; ld * nfdir],
            sed: vec![UNSET; ld],
            sfd: vec![UNSET; ld],
            statev: vec![UNSET; ld * nstatv],
            dgam: vec![UNSET; ld * nfdir],
            taulm: vec![0.0; ld * nfdir],
            press: vec![UNSET; ld],
            dpress: vec![UNSET; ld],
            chrlngth: vec![UNSET; ld],
        }
    }
}

/// Every point through `fric_` (`FricCall`); the outputs, the smallest PNEWDT and, per point,
/// the message `fric_` reported (empty when it succeeded).
pub fn per_point(props: &[f64], dtime: f64, input: &Points) -> (Points, f64, Vec<String>) {
    let mut out = input.clone();
    let (ld, nf) = (input.ld, input.nfdir);
    let mut pnewdt = 1e36f64;
    let mut messages = Vec::new();
    for i in 0..input.n {
        let mut c = FricCall::new(nf as i32, props);
        c.nstatv = input.nstatv as i32;
        c.statev = (0..input.nstatv)
            .map(|r| input.statev[i + r * ld])
            .collect();
        c.lm = input.lm[i];
        c.press = input.press[i];
        c.dpress = input.dpress[i];
        c.dtime = dtime;
        c.chrlngth = input.chrlngth[i];
        for a in 0..nf {
            c.tau[a] = input.tau[i + a * ld];
            c.dgam[a] = input.dgam[i + a * ld];
            c.taulm[a] = input.taulm[i + a * ld];
            c.ddtddp[a] = UNSET;
            c.dslip[a] = UNSET;
            for b in 0..nf {
                c.ddtddg[a + b * nf] = UNSET;
            }
        }
        c.sed = UNSET;
        c.sfd = UNSET;
        c.pnewdt = 1e36;
        interfacial::abi::ifl_clear_error();
        c.call();
        messages.push(FricCall::last_error());
        pnewdt = pnewdt.min(c.pnewdt);
        out.lm[i] = c.lm;
        out.sed[i] = c.sed;
        out.sfd[i] = c.sfd;
        for a in 0..nf {
            out.tau[i + a * ld] = c.tau[a];
            out.ddtddp[i + a * ld] = c.ddtddp[a];
            out.dslip[i + a * ld] = c.dslip[a];
            for b in 0..nf {
                out.ddtddg[i + (a + b * nf) * ld] = c.ddtddg[a + b * nf];
            }
        }
        for r in 0..input.nstatv {
            out.statev[i + r * ld] = c.statev[r];
        }
    }
    (out, pnewdt, messages)
}

/// The points through the C entry `ifl_fric_batch`: outputs, PNEWDT, status.
pub fn via_c(props: &[f64], dtime: f64, input: &Points) -> (Points, f64, IflStatus) {
    let mut p = input.clone();
    let mut pnewdt = 1e36;
    // SAFETY: every array holds ld × its component count, as the contract requires.
    let st = unsafe {
        ifl_fric_batch(
            p.n,
            p.ld,
            p.nfdir as i32,
            props.as_ptr(),
            props.len() as i32,
            p.nstatv as i32,
            dtime,
            p.lm.as_mut_ptr(),
            p.tau.as_mut_ptr(),
            p.ddtddg.as_mut_ptr(),
            p.ddtddp.as_mut_ptr(),
            p.dslip.as_mut_ptr(),
            p.sed.as_mut_ptr(),
            p.sfd.as_mut_ptr(),
            p.statev.as_mut_ptr(),
            input.dgam.as_ptr(),
            input.taulm.as_ptr(),
            input.press.as_ptr(),
            input.dpress.as_ptr(),
            input.chrlngth.as_ptr(),
            &mut pnewdt,
        )
    };
    (p, pnewdt, st)
}

/// The bit patterns of `v` (so that −0, +0 and NaN payloads are told apart).
pub fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// `None` when every output array of `a` and `b` is the same bit for bit, else the name of the
/// first one that differs.
pub fn first_difference(a: &Points, b: &Points) -> Option<&'static str> {
    if a.lm != b.lm {
        return Some("LM");
    }
    [
        ("TAU", &a.tau, &b.tau),
        ("DDTDDG", &a.ddtddg, &b.ddtddg),
        ("DDTDDP", &a.ddtddp, &b.ddtddp),
        ("DSLIP", &a.dslip, &b.dslip),
        ("SED", &a.sed, &b.sed),
        ("SFD", &a.sfd, &b.sfd),
        ("STATEV", &a.statev, &b.statev),
    ]
    .into_iter()
    .find(|(_, x, y)| bits(x) != bits(y))
    .map(|(name, _, _)| name)
}
