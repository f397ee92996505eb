//! One `uinter_` call decoded from fuzzer bytes: all 47 arguments and the 3 hidden lengths,
//! every array allocated with exactly the length the call declares (so AddressSanitizer reports
//! any access past it), and the properties every call must have.
//!
//! Runs against the configuration of [`super::gapcon_case`] (its `setup` must be called first),
//! so `PROPS(11) = 1` reaches every conductance law as well as the "no thermal law" refusal.
//! Shared by the `uinter` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use std::ffi::c_int;

use super::args::{Args, Draw, Len, ONE, Outputs, Row, call, of, or_null_mut};
use super::bytes::{Bytes, bits, len};
use super::contract::{Names, adhesive_props, adhesive_rate, norm, pnewdt_refusal, unwritten};
use super::gapcon_case::NAMES;
use Draw::{Int, Large, Number, Pick, Reals};
use interfacial::abi::uinter_;

/// The counts, drawn first. The choices favour valid calls (NDIR 2 or 3, NSTATV ≥ 3, NPROPS
/// 9–14) so most inputs reach the law, but every bad shape stays reachable.
const COUNTS: [Row; 5] = [
    (
        &["NDIR"],
        Pick(&[2, 3, 2, 3, 2, 3, 2, 3, 2, 3, 1, 4, 0, -1]),
    ),
    (&["NSTATV"], Pick(&[3, 3, 3, 3, 4, 5, 8, 2, 0, -1])),
    (
        &["NPROPS"],
        Pick(&[10, 11, 13, 13, 13, 13, 13, 12, 9, 14, 2, 1, 0, -1]),
    ),
    (&["MCRD"], Pick(&[3, 2, 1, 0])),
    (&["NPRED"], Pick(&[1, 0, 2])),
];

/// After `PROPS`, two bytes (flags, the configured name) and `STATEV`: the rest of the point.
const POINT: [Row; 17] = [
    (&["NODE"], Number),
    (&["KSTEP", "KINC", "KIT"], Int(1)),
    (&["LINPER", "LPRINT"], Int(0)),
    (&["LOPENCLOSE"], Pick(&[-1, 0, 1, 2])),
    (&["LSTATE"], Pick(&[-1, 0, 1, 3, 4])),
    (&["LSDI"], Int(0)),
    (&["STRESS"], Reals(of("NDIR"))),
    (&["PNEWDT"], Large),
    (&["RDISP", "DRDISP"], Reals(of("NDIR"))),
    (&["TEMP", "DTEMP"], Reals(Len::Fixed(2))),
    (&["PREDEF", "DPRED"], Reals(Len::Times(2, "NPRED"))),
    (&["TIME"], Reals(Len::Fixed(2))),
    (&["DTIME", "FREQR"], Reals(ONE)),
    (&["COORDS"], Reals(of("MCRD"))),
    (&["ALOCALDIR"], Reals(Len::Square("MCRD"))),
    (&["DROT"], Reals(Len::Fixed(4))),
    (&["AREA", "CHRLNGTH"], Reals(ONE)),
];

/// The arguments `uinter_` may write and has read: kept as on entry.
const IN_OUT: [&str; 6] = ["STRESS", "STATEV", "PNEWDT", "LOPENCLOSE", "LSTATE", "LSDI"];

/// The arguments `uinter_` only writes (all but `DDSDDR` optional), with their lengths.
const OUTPUTS: [(&str, Len); 12] = [
    ("DDSDDR", Len::Square("NDIR")),
    ("DVISCOUS", Len::Square("NDIR")),
    ("DSTRUCTURAL", Len::Square("NDIR")),
    ("FLUX", Len::Fixed(2)),
    ("DDFDDT", Len::Fixed(4)),
    ("DDSDDT", Len::Times(2, "NDIR")),
    ("DDFDDR", Len::Times(2, "NDIR")),
    ("SED", ONE),
    ("SFD", ONE),
    ("SPD", ONE),
    ("SVD", ONE),
    ("SCD", ONE),
];

/// Every `uinter_` argument: `args` by Fortran name (`STRESS(NDIR)`, `PROPS(NPROPS)`, …), each
/// array of exactly its declared length.
#[derive(Clone, Debug)]
pub struct UinterCase {
    pub args: Args,
    /// `CINAME`, `SLNAME`, `MSNAME`.
    pub names: Names,
    /// Pass NULL for every optional output (`DVISCOUS`, `DSTRUCTURAL`, `FLUX`, `DDFDDT`,
    /// `DDSDDT`, `DDFDDR`, `SED` … `SCD`, `LSTATE`).
    pub null_optional: bool,
}

/// An adhesive-favouring `PROPS` of `NPROPS` entries, with a positive K_n mostly.
fn decode_props(b: &mut Bytes, nprops: i32) -> Vec<f64> {
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
    props
}

impl UinterCase {
    /// Decodes any byte string. The choices favour valid calls (NDIR 2 or 3, NSTATV ≥ 3, an
    /// adhesive `PROPS` with a positive K_n) so most inputs reach the law, but every bad shape
    /// stays reachable.
    pub fn decode(data: &[u8]) -> Self {
        let b = &mut Bytes::new(data);
        let mut a = Args::new();
        a.draw(b, &COUNTS);
        a.put("PROPS", decode_props(b, a.int("NPROPS")));
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
        a.draw(b, &[(&["STATEV"], Reals(of("NSTATV")))]);
        let statev = &mut a["STATEV"];
        // STATEV(3) is a status code; keep it one of the law's mostly.
        if let Some(x) = statev.get_mut(2) {
            let k = b.u8();
            if k < 224 {
                *x = [0.0, 1.0, 3.0, 4.0][usize::from(k % 4)];
            }
        }
        if flags & 0x10 == 0 {
            // A state the law could have written: slip and rate finite, ≥ 0.
            for x in statev.iter_mut().take(2) {
                *x = if x.is_finite() { x.abs() } else { 0.0 };
            }
        }
        a.draw(b, &POINT);
        UinterCase {
            args: a,
            names: Names {
                interaction: name(b, ci),
                secondary: name(b, None),
                main: name(b, None),
            },
            null_optional: flags & 0x80 != 0,
        }
    }

    /// Calls `uinter_` and checks every property; `Err` names the first one violated.
    pub fn check(&self) -> Result<Outputs, String> {
        let null = self.null_optional;
        let opt = |p: *mut f64| or_null_mut(p, null);
        let out = call(&self.args, &self.names, &IN_OUT, &OUTPUTS, |a, names, o| {
            let lstate = or_null_mut(o.int_ptr_mut("LSTATE"), null);
            let [ci, sl, ms] = names.pointers();
            let [ci_len, sl_len, ms_len] = names.lengths();
            // SAFETY: every array has exactly the length the call declares (NDIR, NDIR², 2, 4,
            // 2·NDIR, NSTATV, 2·NPRED, NPROPS, MCRD, MCRD², the hidden name lengths; scalars one
            // entry); optional outputs are NULL or valid.
            // The arguments grouped by role, several a line (rustfmt::skip keeps the groups).
            #[rustfmt::skip]
            unsafe {
                uinter_(
                    // written
                    o.ptr_mut("STRESS"), o.ptr_mut("DDSDDR"),
                    opt(o.ptr_mut("DVISCOUS")), opt(o.ptr_mut("DSTRUCTURAL")),
                    opt(o.ptr_mut("FLUX")), opt(o.ptr_mut("DDFDDT")),
                    opt(o.ptr_mut("DDSDDT")), opt(o.ptr_mut("DDFDDR")),
                    o.ptr_mut("STATEV"), opt(o.ptr_mut("SED")), opt(o.ptr_mut("SFD")),
                    opt(o.ptr_mut("SPD")), opt(o.ptr_mut("SVD")), opt(o.ptr_mut("SCD")),
                    o.ptr_mut("PNEWDT"),
                    // the increment
                    a.ptr("RDISP"), a.ptr("DRDISP"), a.ptr("TEMP"), a.ptr("DTEMP"),
                    a.ptr("PREDEF"), a.ptr("DPRED"), a.ptr("TIME"), a.ptr("DTIME"), a.ptr("FREQR"),
                    // the names, PROPS, the geometry
                    ci, sl, ms, a.ptr("PROPS"),
                    a.ptr("COORDS"), a.ptr("ALOCALDIR"), a.ptr("DROT"),
                    a.ptr("AREA"), a.ptr("CHRLNGTH"),
                    // sizes, counters, the flags (LOPENCLOSE, LSTATE, LSDI written)
                    a.int_ptr("NODE"), a.int_ptr("NDIR"), a.int_ptr("NSTATV"),
                    a.int_ptr("NPRED"), a.int_ptr("NPROPS"), a.int_ptr("MCRD"),
                    a.int_ptr("KSTEP"), a.int_ptr("KINC"), a.int_ptr("KIT"), a.int_ptr("LINPER"),
                    o.int_ptr_mut("LOPENCLOSE"), lstate, o.int_ptr_mut("LSDI"),
                    a.int_ptr("LPRINT"), ci_len, sl_len, ms_len,
                )
            };
        })?;
        self.check_outputs(&out)?;
        Ok(out)
    }

    fn check_outputs(&self, out: &Outputs) -> Result<(), String> {
        let a = &self.args;
        if out.int("LSDI") != a.int("LSDI") {
            return Err("LSDI was written".into());
        }
        let refused = pnewdt_refusal(a.real("PNEWDT"), out.real("PNEWDT"), &out.message, "UINTER")?;
        let kept = |name: &str| bits(&out[name]) == bits(&a[name]);
        let state_kept = kept("STRESS")
            && kept("STATEV")
            && out.int("LOPENCLOSE") == a.int("LOPENCLOSE")
            && out.int("LSTATE") == a.int("LSTATE");
        let written = out.args.written(&OUTPUTS.map(|(name, _)| name));
        if refused {
            if !state_kept {
                return Err("refused but STRESS, STATEV, LOPENCLOSE or LSTATE changed".into());
            }
            if let Some(x) = written.iter().find(|x| **x != 0.0) {
                return Err(format!("refused but an output was set to {x}, not zeroed"));
            }
            return Ok(());
        }
        // Success: only a valid shape gets here.
        let n = a.len_of("NDIR");
        if !(2..=3).contains(&n) || a.int("NSTATV") < 3 {
            return Err(format!(
                "accepted NDIR = {}, NSTATV = {}",
                a.int("NDIR"),
                a.int("NSTATV")
            ));
        }
        let (stress, statev, statev0) = (&out["STRESS"], &out["STATEV"], &a["STATEV"]);
        let mut all = written;
        all.extend(stress);
        all.extend(&statev[..3]);
        if let Some(x) = all.iter().find(|x| !x.is_finite()) {
            return Err(format!("success with a non-finite output {x}: {out:?}"));
        }
        if out["DDSDDR"].iter().any(unwritten) {
            return Err("DDSDDR not fully written".into());
        }
        let optional = &OUTPUTS[1..];
        if !self.null_optional
            && optional
                .iter()
                .any(|(name, _)| out[*name].iter().any(unwritten))
        {
            return Err("an output was left unwritten".into());
        }
        if bits(&statev[3..]) != bits(&statev0[3..]) {
            return Err("STATEV past the law's 3 entries was written".into());
        }
        let [slip0, _, _] = [statev0[0], statev0[1], statev0[2]];
        let [slip, rate, status] = [statev[0], statev[1], statev[2]];
        if rate < 0.0 || slip < slip0 {
            return Err(format!("bad slip state {:?}", &statev[..3]));
        }
        let code = match status {
            0.0 => 0,
            1.0 => 1,
            3.0 => 3,
            4.0 => 4,
            _ => return Err(format!("status STATEV(3) = {status}")),
        };
        if !self.null_optional && out.int("LSTATE") != code {
            return Err(format!(
                "LSTATE = {} but STATEV(3) = {status}",
                out.int("LSTATE")
            ));
        }
        if out.int("LOPENCLOSE") != c_int::from(code != 4) {
            return Err(format!(
                "LOPENCLOSE = {} with status {code}",
                out.int("LOPENCLOSE")
            ));
        }
        let p = stress[0];
        let tau = norm(&stress[1..]);
        match code {
            4 if p != 0.0 || tau != 0.0 => {
                return Err(format!("open but STRESS = {stress:?}"));
            }
            3 if p > 0.0 => return Err(format!("bonded in compression: {stress:?}")),
            0 | 1 if p < 0.0 => return Err(format!("closed in tension: {stress:?}")),
            _ => {}
        }
        self.check_strength(out, tau)?;
        if !self.null_optional {
            let [sed, sfd, spd, svd, scd] =
                ["SED", "SFD", "SPD", "SVD", "SCD"].map(|e| out.real(e));
            if sed < 0.0 || sfd < 0.0 || spd < 0.0 || [svd, scd] != [0.0; 2] {
                return Err(format!("energies {:?}", [sed, sfd, spd, svd, scd]));
            }
            // SPD is the energy of a bond breaking in this increment: a point not open at the
            // start (STATEV(3) ≠ 4), apart at the end (RDISP(1) ≤ 0), open after the call, with
            // separation adhesion (S_a, N_a > 0). Zero in every other increment.
            let broke = statev0[2] != 4.0
                && code == 4
                && a["RDISP"][0] <= 0.0
                && self.prop(3) > 0.0
                && self.prop(4) > 0.0;
            if spd != 0.0 && !broke {
                return Err(format!("SPD = {spd:e} without a bond breaking: {out:?}"));
            }
            let zero = |name: &str| out[name].iter().all(|x| x.to_bits() == 0);
            if !(zero("DVISCOUS") && zero("DSTRUCTURAL") && zero("DDSDDT")) {
                return Err("DVISCOUS, DSTRUCTURAL or DDSDDT not zero".into());
            }
        }
        Ok(())
    }

    /// `PROPS(i+1)`, 0 when absent.
    fn prop(&self, i: usize) -> f64 {
        self.args["PROPS"].get(i).copied().unwrap_or(0.0)
    }

    /// |τ| ≤ (max(μ_s, μ_d) + k_μ·Δv)·p⁺ + S_a (seed 004: the static strength in stick, the
    /// rate-dependent strength while sliding, below S_a while bonded, 0 when open).
    fn check_strength(&self, out: &Outputs, tau: f64) -> Result<(), String> {
        let [mu_d, mu_s, s_a, k_mu] = adhesive_props(&self.args["PROPS"]);
        let mu = if mu_s > 0.0 { mu_s.max(mu_d) } else { mu_d };
        let p_plus = out["STRESS"][0].max(0.0);
        // A slip rate saturated at f64::MAX (a slip over a subnormal DTIME) no longer tells
        // the rate the law used: no bound then for a rate-dependent law.
        let rate = adhesive_rate(&self.args["STATEV"], &out["STATEV"]);
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
