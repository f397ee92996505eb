//! One `fric_coef_` call (Abaqus FRIC_COEF) or one `ifl_forced_sliding` call decoded from fuzzer
//! bytes, every array allocated with exactly the length the call declares (so AddressSanitizer
//! reports any access past it), and the properties every call must have.
//!
//! Shared by the `fric_coef` fuzz target and `tests/fuzz_regressions_coef.rs` (included there by
//! path).

use super::args::{Args, Draw, Len, ONE, Outputs, Row, call, of, or_null, or_null_mut};
use super::bytes::Bytes;
use super::contract::{Names, unwritten};
use Draw::{Pick, Reals};
use interfacial::abi::{IflStatus, fric_coef_, ifl_forced_sliding};

/// Derivative slots per point and direction: `fCoefDeriv(nBlock,20,2)`.
const NDERIV: usize = 20;

/// The counts of a `fric_coef_` block, drawn first: mostly a valid block, but nBlock ≤ 0,
/// nProps out of range and nTemp ≤ 0 stay reachable.
const COEF_COUNTS: [Row; 4] = [
    (
        &["nBlock"],
        Pick(&[1, 1, 2, 3, 4, 5, 8, 17, 1, 2, 3, 0, -1]),
    ),
    (
        &["nProps"],
        Pick(&[13, 13, 13, 13, 10, 8, 20, 2, 3, 7, 12, 21, 1, 0, -1]),
    ),
    (&["nTemp"], Pick(&[1, 1, 1, 1, 2, 0, -1])),
    (&["nFields"], Pick(&[0, 0, 1, 2, -1])),
];

/// After `iData` (one byte, in `decode`): the block's other arrays.
const COEF_BLOCK: [Row; 3] = [
    (&["rData"], Reals(Len::Fixed(3))),
    (&["pressure", "tempAvg"], Reals(of("nBlock"))),
    (&["fieldAvg"], Reals(Len::Product("nBlock", "nFields"))),
];

/// What `fric_coef_` writes: `fCoef(nBlock,2)`, `fCoefDeriv(nBlock,20,2)`.
const COEF_OUTPUTS: [(&str, Len); 2] = [
    ("fCoef", Len::Times(2, "nBlock")),
    ("fCoefDeriv", Len::Times(2 * NDERIV, "nBlock")),
];

/// After `PROPS`: the point of an `ifl_forced_sliding` call.
const SLIDE_POINT: [Row; 2] = [
    (&["velocity"], Reals(of("nfdir"))),
    (&["pressure", "temperature"], Reals(ONE)),
];

/// What `ifl_forced_sliding` writes: τ(nfdir), the damping matrix (nfdir²), the stiffness.
const SLIDE_OUTPUTS: [(&str, Len); 3] = [
    ("tau", of("nfdir")),
    ("damping", Len::Square("nfdir")),
    ("stiffness", of("nfdir")),
];

/// A law-1 `PROPS` of `nprops` entries favouring valid μ laws (docs/props.md): `PROPS(1) = 1`,
/// μ ≥ 0, `PROPS(3)` 0 or μ, `PROPS(4..7)` 0, the decay law, p_ref and the temperature law each
/// on or off, `PROPS(14..)` 0 — and any real in any entry now and then.
pub fn decode_props(b: &mut Bytes, nprops: usize) -> Vec<f64> {
    let mut props: Vec<f64> = Vec::with_capacity(nprops);
    for i in 0..nprops {
        let sel = b.u8();
        let on = |k: usize, props: &[f64]| props.get(k).is_some_and(|x| *x != 0.0);
        let v = match (i, sel % 8) {
            (0, 0..=6) => 1.0,
            (1, 0..=6) => b.real().abs(),
            (2, 0..=3) => 0.0,
            (2, 4 | 5) => props[1],
            (2, 6) => b.real().abs(),
            (3..=6 | 13.., 0..=6) => 0.0,
            (7, 0..=3) => 1.0,
            (7, 4..=6) => 0.0,
            (8 | 9, 0..=6) if on(7, &props) => b.real().abs(),
            (8 | 9, 0..=6) => 0.0,
            (10 | 11, 0..=2) => 0.0,
            (10, 3..=6) => b.real().abs(),
            (11, 3..=6) => b.real(),
            (12, 0..=6) if on(11, &props) => b.real(),
            (12, 0..=6) => 0.0,
            _ => b.real(),
        };
        props.push(v);
    }
    props
}

/// Which pointer argument of `fric_coef_` is passed as NULL (a broken host).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CoefNull {
    None,
    FCoef,
    FCoefDeriv,
    NBlock,
    NProps,
    NTemp,
    Props,
    SlipData,
    Pressure,
    TempAvg,
}

/// Every `fric_coef_` argument: `args` by Abaqus name (`nBlock`, `props`, `slipData(nBlock,6)`,
/// `pressure(nBlock)`, `tempAvg(nBlock)`, `fieldAvg(nBlock,nFields)`, `iData(3)`, `rData(3)`,
/// the last two not read by the library), each array of exactly its declared length.
#[derive(Clone, Debug)]
pub struct FricCoefCase {
    pub args: Args,
    /// `surfInt`, `surfSec`, `surfMain`.
    pub names: Names,
    pub null: CoefNull,
}

/// The block `fric_coef_` wrote, read by point.
pub trait Coefficients {
    /// μ of point k (0-based) in direction d (0, 1) of a block of `n` points.
    fn mu(&self, n: usize, k: usize, d: usize) -> f64;
    /// `fCoefDeriv(k+1, j+1, d+1)`.
    fn deriv(&self, n: usize, k: usize, j: usize, d: usize) -> f64;
}

impl Coefficients for Outputs {
    fn mu(&self, n: usize, k: usize, d: usize) -> f64 {
        self["fCoef"][k + n * d]
    }
    fn deriv(&self, n: usize, k: usize, j: usize, d: usize) -> f64 {
        self["fCoefDeriv"][k + n * (j + NDERIV * d)]
    }
}

/// The [`CoefNull`] that a decoder byte 0 to 8 chooses (any other byte: none), by role: the
/// outputs, the counts, the arrays.
#[rustfmt::skip]
const COEF_NULLS: [CoefNull; 9] = [
    CoefNull::FCoef, CoefNull::FCoefDeriv,
    CoefNull::NBlock, CoefNull::NProps, CoefNull::NTemp,
    CoefNull::Props, CoefNull::SlipData, CoefNull::Pressure, CoefNull::TempAvg,
];

impl FricCoefCase {
    /// A valid block: these `props`, slip rates, pressures and temperatures (equal lengths),
    /// `nTemp = 1`, no fields, interaction `"SI1"` (80 bytes).
    pub fn block(props: &[f64], rate: &[f64], pressure: &[f64], temp: &[f64]) -> Self {
        let n = rate.len();
        let mut a = Args::new();
        a.set_int("nBlock", i32::try_from(n).unwrap_or(i32::MAX));
        a.set_int("nProps", i32::try_from(props.len()).unwrap_or(i32::MAX));
        a.set_int("nTemp", 1);
        a.set_int("nFields", 0);
        a.put_ints("iData", vec![1; 3]);
        a.put("rData", vec![0.0; 3]);
        a.put("props", props.to_vec());
        let mut slip = vec![0.0; 6 * n];
        slip[..n].copy_from_slice(rate);
        a.put("slipData", slip);
        a.put("pressure", pressure.to_vec());
        a.put("tempAvg", temp.to_vec());
        a.put("fieldAvg", Vec::new());
        FricCoefCase {
            args: a,
            names: Names::padded("SI1"),
            null: CoefNull::None,
        }
    }

    /// Decodes any byte string; most inputs are a valid block with a valid μ law, but every bad
    /// shape (nBlock ≤ 0, nProps out of range, nTemp = 0, NULL pointers) stays reachable.
    pub fn decode(b: &mut Bytes) -> Self {
        let mut a = Args::new();
        a.draw(b, &COEF_COUNTS);
        let null = b.choose(&COEF_NULLS, |_| CoefNull::None);
        a.put("props", decode_props(b, a.len_of("nProps")));
        a.draw(b, &[(&["slipData"], Reals(Len::Times(6, "nBlock")))]);
        // Slip rates: mostly finite and ≥ 0 (slipData(k,1) is a magnitude).
        let n = a.len_of("nBlock");
        if b.u8() & 1 == 0 {
            for x in &mut a["slipData"][..n] {
                *x = x.abs();
            }
        }
        a.put_ints("iData", vec![b.u8().into(); 3]);
        a.draw(b, &COEF_BLOCK);
        FricCoefCase {
            args: a,
            names: Names {
                interaction: b.name(),
                secondary: b.name(),
                main: b.name(),
            },
            null,
        }
    }

    /// Calls `fric_coef_` through its real symbol and checks every property; `Err` names the
    /// first one violated.
    pub fn check(&self) -> Result<Outputs, String> {
        let null = self.null;
        let mo = |p: *mut f64, which: CoefNull| or_null_mut(p, null == which);
        let ro = |p: *const f64, which: CoefNull| or_null(p, null == which);
        let io = |p: *const i32, which: CoefNull| or_null(p, null == which);
        let out = call(
            &self.args,
            &self.names,
            &[],
            &COEF_OUTPUTS,
            |a, names, o| {
                let [ci, sl, ms] = names.pointers();
                let [ci_len, sl_len, ms_len] = names.lengths();
                // SAFETY: every array has exactly the length the call declares (2·nBlock,
                // 40·nBlock, nProps, 6·nBlock, nBlock, nBlock, nBlock·nFields, the hidden name
                // lengths); scalars one entry; NULL where `null` says so.
                // The arguments grouped by role, several a line (rustfmt::skip keeps the groups).
                #[rustfmt::skip]
                unsafe {
                    fric_coef_(
                        // written
                        mo(o.ptr_mut("fCoef"), CoefNull::FCoef),
                        mo(o.ptr_mut("fCoefDeriv"), CoefNull::FCoefDeriv),
                        // sizes, the unread iData and rData, the names
                        io(a.int_ptr("nBlock"), CoefNull::NBlock),
                        io(a.int_ptr("nProps"), CoefNull::NProps),
                        io(a.int_ptr("nTemp"), CoefNull::NTemp),
                        a.int_ptr("nFields"), a.int_ptr("iData"), a.ptr("rData"),
                        ci, sl, ms,
                        // the block, the names' lengths
                        ro(a.ptr("props"), CoefNull::Props),
                        ro(a.ptr("slipData"), CoefNull::SlipData),
                        ro(a.ptr("pressure"), CoefNull::Pressure),
                        ro(a.ptr("tempAvg"), CoefNull::TempAvg),
                        a.ptr("fieldAvg"),
                        ci_len, sl_len, ms_len,
                    )
                };
            },
        )?;
        self.check_outputs(&out)?;
        Ok(out)
    }

    fn check_outputs(&self, out: &Outputs) -> Result<(), String> {
        let n = self.args.len_of("nBlock");
        let written = |v: &[f64]| !v.iter().all(unwritten);
        let all = out["fCoef"].iter().chain(&out["fCoefDeriv"]);
        if !out.message.is_empty() {
            // Refused: one message naming the routine; the block zeroed when nBlock is
            // readable and ≥ 0 (and the array not NULL), nothing written otherwise.
            if !out
                .message
                .starts_with("interfacial: FRIC_COEF: interaction '")
            {
                return Err(format!(
                    "message does not name FRIC_COEF: {:?}",
                    out.message
                ));
            }
            if self.null == CoefNull::NBlock {
                if written(&out["fCoef"]) || written(&out["fCoefDeriv"]) {
                    return Err("nBlock NULL but an output was written".into());
                }
                return Ok(());
            }
            let zeroed = |v: &[f64], which| self.null == which || v.iter().all(|x| *x == 0.0);
            if !zeroed(&out["fCoef"], CoefNull::FCoef)
                || !zeroed(&out["fCoefDeriv"], CoefNull::FCoefDeriv)
            {
                return Err(format!(
                    "refused ({}) but the block is not zeroed",
                    out.message
                ));
            }
            return Ok(());
        }
        // Success.
        // nTemp and tempAvg are read only with a temperature law (docs/props.md).
        let unread =
            matches!(self.null, CoefNull::NTemp | CoefNull::TempAvg) && !self.reads_temperature();
        if self.null != CoefNull::None && n > 0 && !unread {
            return Err(format!("a NULL {:?} was accepted", self.null));
        }
        if let Some(x) = all.clone().find(|x| !x.is_finite()) {
            return Err(format!("success with a non-finite output {x}"));
        }
        if n > 0 && !(written(&out["fCoef"]) && written(&out["fCoefDeriv"])) {
            return Err("success but the block was not written".into());
        }
        // PROPS(1) = 2 is accepted only where the adhesive law is the plain Coulomb law
        // (docs/props.md, law 2): μ = PROPS(2) in both directions, constant.
        let adhesive = self.prop(0) == 2.0;
        let isotropic = adhesive || self.prop(2) == 0.0;
        for k in 0..n {
            let (rate, p) = (self.args["slipData"][k], self.args["pressure"][k]);
            if !(rate.is_finite() && rate >= 0.0 && p.is_finite()) {
                return Err(format!(
                    "point {k}: bad rate {rate} or pressure {p} accepted"
                ));
            }
            for d in 0..2 {
                let mu = out.mu(n, k, d);
                if mu < 0.0 {
                    return Err(format!("μ({k},{d}) = {mu} < 0"));
                }
                for j in 3..NDERIV {
                    if out.deriv(n, k, j, d) != 0.0 {
                        return Err(format!("fCoefDeriv({},{},{}) ≠ 0", k + 1, j + 1, d + 1));
                    }
                }
                if p < 0.0 && out.deriv(n, k, 1, d) != 0.0 {
                    return Err(format!("∂μ/∂p ≠ 0 at negative pressure, point {k}"));
                }
                if !self.reads_temperature() && out.deriv(n, k, 2, d) != 0.0 {
                    return Err(format!("∂μ/∂θ ≠ 0 without a temperature law, point {k}"));
                }
            }
            if isotropic && out.mu(n, k, 0).to_bits() != out.mu(n, k, 1).to_bits() {
                return Err(format!("isotropic but μ₁ ≠ μ₂ at point {k}"));
            }
            if adhesive {
                let still = (0..3).all(|j| out.deriv(n, k, j, 0) == 0.0);
                if out.mu(n, k, 0) != self.prop(1) || !still {
                    return Err(format!("PROPS(1) = 2 but μ ≠ PROPS(2) at point {k}"));
                }
            } else if let Some(direct) = self.direct(k) {
                for (d, m) in direct.iter().enumerate() {
                    let got = out.mu(n, k, d);
                    if (got - m).abs() > 1e-12 * m.abs() {
                        return Err(format!(
                            "μ({k},{d}) = {got:e}, direct evaluation {m:e} (rate {rate:e}, p {p:e})"
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// `PROPS(i+1)`, 0 when absent.
    fn prop(&self, i: usize) -> f64 {
        self.args["props"].get(i).copied().unwrap_or(0.0)
    }

    /// A law-1 temperature law (`PROPS(12)` of law 2 is a heat fraction, not read here).
    fn reads_temperature(&self) -> bool {
        self.prop(0) == 1.0 && self.prop(11) != 0.0
    }

    /// μ₁, μ₂ of point k straight from docs/props.md, written independently of the library:
    /// μ_i = (μ_s,i·e + μ_k,i·(1 − e))·π·Θ with e = exp(−d_c·γ̇), 1 − e = −expm1(−d_c·γ̇),
    /// μ_k,2 = μ_k·μ₂/μ₁, π = 1/(1 + p⁺/p_ref), Θ = exp(−b_θ(θ̄ − θ_ref)). `None` when an
    /// intermediate leaves the normal range (the library multiplies in another order there).
    fn direct(&self, k: usize) -> Option<[f64; 2]> {
        let normal = |x: f64| x == 0.0 || (x.abs() > 1e-280 && x.abs() < 1e280);
        let mu1 = self.prop(1);
        let mu2 = if self.prop(2) != 0.0 {
            self.prop(2)
        } else {
            mu1
        };
        let (rate, p) = (self.args["slipData"][k], self.args["pressure"][k].max(0.0));
        let (e, one_minus_e, mu_k1) = if self.prop(7) == 1.0 {
            let x = self.prop(9) * rate;
            ((-x).exp(), -(-x).exp_m1(), self.prop(8))
        } else {
            (1.0, 0.0, 0.0)
        };
        let ratio = mu2 / mu1;
        // The library keeps r = μ_k/μ_s; an r out of the normal range (underflowing to 0,
        // an absolute difference of at most μ_k) is not compared here.
        let r = mu_k1 / mu1;
        if mu_k1 != 0.0 && !(ratio.is_normal() && normal(ratio) && r.is_normal() && normal(r)) {
            return None;
        }
        let mu_k2 = mu_k1 * ratio;
        let pi = if self.prop(10) > 0.0 {
            1.0 / (1.0 + p / self.prop(10))
        } else {
            1.0
        };
        let theta = if self.reads_temperature() {
            (-self.prop(11) * (self.args["tempAvg"][k] - self.prop(12))).exp()
        } else {
            1.0
        };
        let m1 = (mu1 * e + mu_k1 * one_minus_e) * pi * theta;
        let m2 = (mu2 * e + mu_k2 * one_minus_e) * pi * theta;
        let parts = [mu1, mu2, e, one_minus_e, mu_k1, mu_k2, pi, theta, m1, m2];
        let parts_ok = parts.iter().all(|x| normal(*x));
        let products = [mu1 * e, mu_k1 * one_minus_e, mu2 * e, mu_k2 * one_minus_e];
        (parts_ok && products.iter().all(|x| normal(*x))).then_some([m1, m2])
    }
}

/// Which pointer argument of `ifl_forced_sliding` is passed as NULL.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SlideNull {
    None,
    Props,
    Velocity,
    Tau,
    Damping,
    Stiffness,
}

/// Every `ifl_forced_sliding` argument: `args` by name (`nfdir`, `nprops`, `props`,
/// `velocity(nfdir)`, `pressure`, `temperature`).
#[derive(Clone, Debug)]
pub struct ForcedSlidingCase {
    pub args: Args,
    pub null: SlideNull,
}

/// The [`SlideNull`] that a decoder byte 0 to 4 chooses (any other byte: none): the inputs,
/// the outputs.
#[rustfmt::skip]
const SLIDE_NULLS: [SlideNull; 5] = [
    SlideNull::Props, SlideNull::Velocity,
    SlideNull::Tau, SlideNull::Damping, SlideNull::Stiffness,
];

impl ForcedSlidingCase {
    /// Decodes any byte string (mostly nfdir 1 or 2 and a valid law-1 `PROPS`).
    pub fn decode(b: &mut Bytes) -> Self {
        let mut a = Args::new();
        a.set_int("nfdir", b.pick(&[1, 2, 1, 2, 1, 2, 0, 3, -1]));
        a.set_int("nprops", b.pick(&[13, 13, 10, 8, 4, 2, 20, 21, 1, 0, -1]));
        let null = b.choose(&SLIDE_NULLS, |_| SlideNull::None);
        a.put("props", decode_props(b, a.len_of("nprops")));
        a.draw(b, &SLIDE_POINT);
        ForcedSlidingCase { args: a, null }
    }

    /// Calls `ifl_forced_sliding` and checks every property: what it wrote, and its status as
    /// the integer `status`.
    pub fn check(&self) -> Result<Outputs, String> {
        let null = self.null;
        let mo = |p: *mut f64, which: SlideNull| or_null_mut(p, null == which);
        let ro = |p: *const f64, which: SlideNull| or_null(p, null == which);
        let out = call(
            &self.args,
            &Names::none(),
            &[],
            &SLIDE_OUTPUTS,
            |a, _, o| {
                // SAFETY: arrays of exactly nprops, nfdir, nfdir² entries; NULL where `null` says
                // so.
                let status = unsafe {
                    ifl_forced_sliding(
                        ro(a.ptr("props"), SlideNull::Props),
                        a.int("nprops"),
                        a.int("nfdir"),
                        ro(a.ptr("velocity"), SlideNull::Velocity),
                        a.real("pressure"),
                        a.real("temperature"),
                        mo(o.ptr_mut("tau"), SlideNull::Tau),
                        mo(o.ptr_mut("damping"), SlideNull::Damping),
                        mo(o.ptr_mut("stiffness"), SlideNull::Stiffness),
                    )
                };
                o.set_int("status", status as i32);
            },
        )?;
        self.check_outputs(&out)?;
        Ok(out)
    }

    fn check_outputs(&self, out: &Outputs) -> Result<(), String> {
        let a = &self.args;
        let n = a.len_of("nfdir");
        let status = out.int("status");
        let ok = status == IflStatus::Ok as i32;
        if ok != out.message.is_empty() {
            return Err(format!("status {status} with message {:?}", out.message));
        }
        let outputs = [
            ("tau", SlideNull::Tau),
            ("damping", SlideNull::Damping),
            ("stiffness", SlideNull::Stiffness),
        ];
        if !ok {
            if !out.message.starts_with("interfacial: ifl_forced_sliding: ") {
                return Err(format!(
                    "message does not name the routine: {:?}",
                    out.message
                ));
            }
            // Outputs zeroed when nfdir is 1 or 2 (and the pointer not NULL).
            let valid = matches!(a.int("nfdir"), 1 | 2);
            for (name, which) in outputs {
                if valid && self.null != which && out[name].iter().any(|x| *x != 0.0) {
                    return Err(format!(
                        "refused ({}) but {which:?} not zeroed",
                        out.message
                    ));
                }
            }
            return Ok(());
        }
        if self.null != SlideNull::None {
            return Err(format!("a NULL {:?} was accepted", self.null));
        }
        for (name, which) in outputs {
            if let Some(x) = out[name].iter().find(|x| !x.is_finite() || unwritten(x)) {
                return Err(format!("success but {which:?} holds {x}"));
            }
        }
        // τ is parallel to the (scaled) velocity component by component: τ_a·v_a ≥ 0, and
        // zero with no pressure or no velocity.
        let (tau, velocity, pressure) = (&out["tau"], &a["velocity"], a.real("pressure"));
        for k in 0..n {
            if tau[k] * velocity[k] < 0.0 {
                return Err(format!("τ({k}) = {} against v = {}", tau[k], velocity[k]));
            }
        }
        let still = velocity.iter().all(|v| *v == 0.0);
        if (pressure <= 0.0 || still) && tau.iter().any(|t| *t != 0.0) {
            return Err(format!(
                "τ = {tau:?} with p = {pressure} and v = {velocity:?}"
            ));
        }
        Ok(())
    }
}

/// One fuzz input: the first byte picks the entry point (three in four `fric_coef_`).
pub enum CoefCall {
    Coef(FricCoefCase),
    Slide(ForcedSlidingCase),
}

impl CoefCall {
    pub fn decode(data: &[u8]) -> Self {
        let mut b = Bytes::new(data);
        if b.u8() % 4 == 3 {
            CoefCall::Slide(ForcedSlidingCase::decode(&mut b))
        } else {
            CoefCall::Coef(FricCoefCase::decode(&mut b))
        }
    }

    pub fn check(&self) -> Result<(), String> {
        match self {
            CoefCall::Coef(c) => c.check().map(|_| ()),
            CoefCall::Slide(c) => c.check().map(|_| ()),
        }
    }
}

impl std::fmt::Debug for CoefCall {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CoefCall::Coef(c) => c.fmt(f),
            CoefCall::Slide(c) => c.fmt(f),
        }
    }
}
