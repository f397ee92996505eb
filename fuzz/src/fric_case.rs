//! One `fric_` call decoded from fuzzer bytes: all 39 arguments and the 3 hidden lengths, every
//! array allocated with exactly the length the call declares (so AddressSanitizer reports any
//! access past it), and the properties every call must have.
//!
//! Shared by the `fric` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use super::args::{Args, Draw, Len, ONE, Outputs, Row, call, of};
use super::bytes::{Bytes, bits, len};
use super::contract::{Names, adhesive_props, adhesive_rate, norm, pnewdt_refusal};
use Draw::{Int, Large, Number, Pick, Reals};
use interfacial::abi::fric_;

pub use super::contract::UNWRITTEN;

/// The counts and `LM`, drawn first. The choices favour valid calls (NFDIR 1 or 2, NSTATV ≥ 3)
/// so most inputs reach the law, but every bad shape stays reachable.
const COUNTS: [Row; 6] = [
    (
        &["NFDIR"],
        Pick(&[1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 0, 3, -1]),
    ),
    (&["NSTATV"], Pick(&[3, 3, 3, 3, 4, 5, 8, 2, 0, -1])),
    // The first list twice (so that recorded inputs decode as before, `pick` taking the byte
    // modulo the length), with two of the second half's 7s made 20 (the extended layout).
    (
        &["NPROPS"],
        Pick(&[
            2, 5, 7, 7, 7, 7, 7, 7, 6, 4, 3, 8, 9, 1, 0, -1, //
            2, 5, 7, 20, 7, 20, 7, 7, 6, 4, 3, 8, 9, 1, 0, -1,
        ]),
    ),
    (&["LM"], Pick(&[0, 0, 0, 0, 1, 1, 2, -1, 3])),
    (&["MCRD"], Pick(&[3, 2, 1, 0])),
    (&["NPRED"], Pick(&[1, 0, 2])),
];

/// After `PROPS` and a byte of flags: the numbering and the increment's arrays, then (after a
/// byte making `STATEV(3)` a status code) the rest of the point.
const INCREMENT: [Row; 4] = [
    (&["KSTEP", "KINC", "NPT", "NPATCH"], Int(1)),
    (&["NOEL", "NODE"], Number),
    (&["TAU", "DGAM", "TAULM", "SLIP"], Reals(of("NFDIR"))),
    (&["STATEV"], Reals(of("NSTATV"))),
];
const POINT: [Row; 7] = [
    (
        &["PRESS", "DPRESS", "DDPDDH", "DTIME", "CHRLNGTH"],
        Reals(ONE),
    ),
    (&["PNEWDT"], Large),
    (&["TIME"], Reals(Len::Fixed(2))),
    (&["COORDS", "RCOORD"], Reals(of("MCRD"))),
    (&["DROT"], Reals(Len::Fixed(4))),
    (&["TEMP"], Reals(Len::Fixed(2))),
    (&["PREDEF"], Reals(Len::Times(2, "NPRED"))),
];

/// The arguments `fric_` may write and has read: kept as on entry.
const IN_OUT: [&str; 4] = ["LM", "TAU", "PNEWDT", "STATEV"];

/// The arguments `fric_` only writes (the last four optional), with their lengths.
const OUTPUTS: [(&str, Len); 6] = [
    ("DDTDDG", Len::Square("NFDIR")),
    ("DDTDDP", of("NFDIR")),
    ("DSLIP", of("NFDIR")),
    ("SED", ONE),
    ("SFD", ONE),
    ("DDTDDT", Len::Times(2, "NFDIR")),
];

/// Every `fric_` argument: `args` by Fortran name (`TAU(NFDIR)`, `PROPS(NPROPS)`, …), each
/// array of exactly its declared length.
#[derive(Clone, Debug)]
pub struct FricCase {
    pub args: Args,
    /// `CINAME`, `SLNAME`, `MSNAME`.
    pub names: Names,
    /// Pass NULL for the optional outputs `DSLIP`, `SED`, `SFD`, `DDTDDT`.
    pub null_optional: bool,
}

/// A Coulomb-favouring `PROPS` of `NPROPS` entries: `PROPS(1)` mostly the Coulomb code,
/// `PROPS(3..)` mostly off, and with 20 entries mostly the exponential-decay μ law.
fn decode_props(b: &mut Bytes, nprops: i32) -> Vec<f64> {
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
    props
}

impl FricCase {
    /// A valid Coulomb call with `nfdir` directions and these `props`, `NSTATV = 3`, all reals
    /// zero except `DTIME = CHRLNGTH = 1`, `PNEWDT = 1e36`, `DROT` the identity, `TEMP = 20`,
    /// interaction name `"SI1"` (80 bytes).
    pub fn coulomb(nfdir: i32, props: &[f64]) -> Self {
        let mut a = Args::new();
        let nprops = i32::try_from(props.len()).unwrap_or(i32::MAX);
        for (name, n) in [("NFDIR", nfdir), ("NSTATV", 3), ("NPROPS", nprops)] {
            a.set_int(name, n);
        }
        for (name, n) in [("LM", 0), ("MCRD", 3), ("NPRED", 1)] {
            a.set_int(name, n);
        }
        // The empty input draws every real 0 (and PNEWDT 1).
        let none = &mut Bytes::new(&[]);
        a.draw(none, &INCREMENT);
        a.draw(none, &POINT);
        a.put("PROPS", props.to_vec());
        for (name, v) in [("DTIME", 1.0), ("CHRLNGTH", 1.0), ("PNEWDT", 1e36)] {
            a.put(name, vec![v]);
        }
        a.put("DROT", vec![1.0, 0.0, 0.0, 1.0]);
        a.put("TEMP", vec![20.0; 2]);
        FricCase {
            args: a,
            names: Names::padded("SI1"),
            null_optional: false,
        }
    }

    /// Decodes any byte string. The choices favour valid calls (NFDIR 1 or 2, NSTATV ≥ 3, a
    /// Coulomb `PROPS`) so most inputs reach the law, but every bad shape stays reachable.
    pub fn decode(data: &[u8]) -> Self {
        let b = &mut Bytes::new(data);
        let mut a = Args::new();
        a.draw(b, &COUNTS);
        a.put("PROPS", decode_props(b, a.int("NPROPS")));
        let flags = b.u8();
        a.draw(b, &INCREMENT);
        // STATEV(3) is a status code; keep it one mostly.
        if let Some(x) = a["STATEV"].get_mut(2) {
            *x = f64::from(b.u8() % 3);
        }
        a.draw(b, &POINT);
        // Mostly a printable name, blank-padded to the hidden length.
        let mut name =
            || b.name_padded(flags & 0x40 == 0, if flags & 0x20 == 0 { b' ' } else { 0 });
        FricCase {
            args: a,
            names: Names {
                interaction: name(),
                secondary: name(),
                main: name(),
            },
            null_optional: flags & 0x80 != 0,
        }
    }

    /// Calls `fric_` and checks every property; `Err` names the first one violated.
    pub fn check(&self) -> Result<Outputs, String> {
        let null = self.null_optional;
        let opt = |p: *mut f64| if null { std::ptr::null_mut() } else { p };
        let out = call(&self.args, &self.names, &IN_OUT, &OUTPUTS, |a, names, o| {
            let [ci, sl, ms] = names.pointers();
            let [ci_len, sl_len, ms_len] = names.lengths();
            // SAFETY: every array has exactly the length the call declares (NFDIR, NFDIR², 2·NFDIR,
            // NSTATV, NPROPS, MCRD, 2·NPRED, the hidden name lengths; scalars one entry).
            unsafe {
                fric_(
                    o.int_ptr_mut("LM"),
                    o.ptr_mut("TAU"),
                    o.ptr_mut("DDTDDG"),
                    o.ptr_mut("DDTDDP"),
                    opt(o.ptr_mut("DSLIP")),
                    opt(o.ptr_mut("SED")),
                    opt(o.ptr_mut("SFD")),
                    opt(o.ptr_mut("DDTDDT")),
                    o.ptr_mut("PNEWDT"),
                    o.ptr_mut("STATEV"),
                    a.ptr("DGAM"),
                    a.ptr("TAULM"),
                    a.ptr("PRESS"),
                    a.ptr("DPRESS"),
                    a.ptr("DDPDDH"),
                    a.ptr("SLIP"),
                    a.int_ptr("KSTEP"),
                    a.int_ptr("KINC"),
                    a.ptr("TIME"),
                    a.ptr("DTIME"),
                    a.int_ptr("NOEL"),
                    ci,
                    sl,
                    ms,
                    a.int_ptr("NPT"),
                    a.int_ptr("NODE"),
                    a.int_ptr("NPATCH"),
                    a.ptr("COORDS"),
                    a.ptr("RCOORD"),
                    a.ptr("DROT"),
                    a.ptr("TEMP"),
                    a.ptr("PREDEF"),
                    a.int_ptr("NFDIR"),
                    a.int_ptr("MCRD"),
                    a.int_ptr("NPRED"),
                    a.int_ptr("NSTATV"),
                    a.ptr("CHRLNGTH"),
                    a.ptr("PROPS"),
                    a.int_ptr("NPROPS"),
                    ci_len,
                    sl_len,
                    ms_len,
                )
            };
        })?;
        self.check_outputs(&out)?;
        Ok(out)
    }

    fn check_outputs(&self, out: &Outputs) -> Result<(), String> {
        let a = &self.args;
        let kept = |name: &str| bits(&out[name]) == bits(&a[name]);
        if pnewdt_refusal(a.real("PNEWDT"), out.real("PNEWDT"), &out.message, "FRIC")? {
            if out.int("LM") != a.int("LM") || !kept("TAU") {
                return Err("refused but LM or TAU changed".into());
            }
            if !kept("STATEV") {
                return Err("refused but STATEV changed".into());
            }
            return Ok(());
        }
        // Success.
        let mut written = out.args.written(&OUTPUTS.map(|(name, _)| name));
        if a.int("LM") == 2 {
            let untouched =
                out.int("LM") == 2 && kept("TAU") && kept("STATEV") && written.is_empty();
            return if untouched {
                Ok(())
            } else {
                Err("LM = 2 on entry but an output was written".into())
            };
        }
        let lm = out.int("LM");
        if lm != 0 && lm != 1 {
            return Err(format!("LM = {lm} on exit"));
        }
        if lm == 0 {
            written.extend(&out["TAU"]);
        }
        // The law's state: STATEV(1..3), and with tangential damping (law 1, PROPS(17) ≠ 0)
        // the viscous stress in STATEV(4..3+NFDIR) (docs/props.md).
        let props = &a["PROPS"];
        let damping = props.first() == Some(&1.0) && props.get(16).is_some_and(|c| *c != 0.0);
        let used = 3 + if damping { a.len_of("NFDIR") } else { 0 };
        let (statev, statev0) = (&out["STATEV"], &a["STATEV"]);
        written.extend(&statev[..used]);
        if let Some(x) = written.iter().find(|x| !x.is_finite()) {
            return Err(format!("success with a non-finite output {x}: {out:?}"));
        }
        if bits(&statev[used..]) != bits(&statev0[used..]) {
            return Err(format!("STATEV past the law's {used} entries was written"));
        }
        if statev[1] < 0.0 || ![0.0, 1.0, 2.0].contains(&statev[2]) {
            return Err(format!("bad state {:?}", &statev[..3]));
        }
        if statev[0] < statev0[0] {
            return Err("accumulated slip decreased".into());
        }
        for name in ["SED", "SFD"] {
            let x = out.real(name);
            if x != UNWRITTEN && x < 0.0 {
                return Err(format!("{name} = {x} < 0"));
            }
        }
        if lm == 0 {
            self.check_cone(out)?;
        }
        Ok(())
    }

    /// `PROPS(i+1)`, 0 when absent.
    fn prop(&self, i: usize) -> f64 {
        self.args["PROPS"].get(i).copied().unwrap_or(0.0)
    }

    /// |τ| ≤ τ_crit = min(μp, τ_max) (0 for p < 0), and |τ| = τ_crit while slipping, for the
    /// plain law 1; the adhesive law (`PROPS(1) = 2`) against its own strength. The extended
    /// law 1 (anisotropy, μ laws, damping: `PROPS(3)` ≠ 0, μ or any of `PROPS(8..)`) has a bound
    /// that depends on the rate, the temperature and the damping state; its cone is checked in
    /// `tests/friction_extended.rs`, here only the common properties.
    fn check_cone(&self, out: &Outputs) -> Result<(), String> {
        let get = |i: usize| self.prop(i);
        if get(0) == 2.0 {
            return self.check_adhesive_strength(out);
        }
        let anisotropic = get(2) != 0.0 && get(2) != get(1);
        if anisotropic || self.args["PROPS"].iter().skip(7).any(|x| *x != 0.0) {
            return Ok(());
        }
        let (mu, tau_max) = (get(1), get(3));
        let tau_max = if tau_max > 0.0 {
            tau_max
        } else {
            f64::INFINITY
        };
        let press = self.args.real("PRESS");
        let tau_crit = if press < 0.0 {
            0.0
        } else {
            (mu * press).min(tau_max)
        };
        let magnitude = norm(&out["TAU"]);
        // A few ulps, and a few hundred subnormal steps where τ_crit itself is tiny.
        let tol = tau_crit * 1e-12 + 1e-321;
        if magnitude > tau_crit + tol {
            return Err(format!(
                "|TAU| = {magnitude:e} above τ_crit = {tau_crit:e}: {out:?}"
            ));
        }
        let elastic = get(6) == 0.0;
        let slipping = out["STATEV"][2] == 1.0;
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
    fn check_adhesive_strength(&self, out: &Outputs) -> Result<(), String> {
        let [mu_d, mu_s, s_a, k_mu] = adhesive_props(&self.args["PROPS"]);
        let dtime = self.args.real("DTIME");
        let p_plus = self.args.real("PRESS").max(0.0);
        // The rate term from STATEV(2), and again from |DSLIP|·(p/Δt): STATEV(2) can be
        // subnormal (few significant bits) while the law's own k_μ/Δt is not.
        let rate = adhesive_rate(&self.args["STATEV"], &out["STATEV"]);
        let via_state = k_mu * rate * p_plus;
        let dslip = &out["DSLIP"];
        let via_slip = if dtime > 0.0 && !dslip.contains(&UNWRITTEN) {
            k_mu * norm(dslip) * (p_plus / dtime)
        } else {
            0.0
        };
        // A rate saturated at f64::MAX with k_μ > 0: no finite bound to check.
        if rate == f64::MAX && k_mu > 0.0 {
            return Ok(());
        }
        let rate_term = if via_slip.is_finite() {
            via_state.max(via_slip)
        } else {
            via_state
        };
        let strength = mu_d.max(mu_s) * p_plus + rate_term + s_a;
        let magnitude = norm(&out["TAU"]);
        if magnitude > strength * (1.0 + 1e-12) + 1e-321 {
            return Err(format!(
                "adhesive law: |TAU| = {magnitude:e} above its strength {strength:e}: {out:?}"
            ));
        }
        Ok(())
    }
}
