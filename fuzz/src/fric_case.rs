//! One `fric_` call decoded from fuzzer bytes: all 39 arguments and the 3 hidden lengths, every
//! array allocated with exactly the length the call declares (so AddressSanitizer reports any
//! access past it), and the properties every call must have.
//!
//! Shared by the `fric` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use super::args::{Args, Draw, Len, ONE, Outputs, Row, call, of, or_null_mut};
use super::bytes::{Bytes, bits, len};
use super::contract::{Names, adhesive_props, adhesive_rate, norm, pnewdt_refusal};
use Draw::{Int, Large, Number, Pick, Reals};
use interfacial::abi::fric_;
use interfacial::props::{LAW_RATE_STATE, RATE_STATE_NPROPS};

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
    // modulo the length), with two of the second half's 7s made 20 (the extended layout); then
    // those 32 twice, with six 7s of the second copy made 11 (law 3, rate-and-state: its whole
    // layout), away from the bytes the recorded inputs hold here (36, 38, 41 and 49 modulo 64,
    // tests/fuzz_regressions.rs and fuzz/regressions/).
    (
        &["NPROPS"],
        Pick(&[
            2, 5, 7, 7, 7, 7, 7, 7, 6, 4, 3, 8, 9, 1, 0, -1, //
            2, 5, 7, 20, 7, 20, 7, 7, 6, 4, 3, 8, 9, 1, 0, -1, //
            2, 5, 11, 11, 7, 11, 7, 11, 6, 4, 3, 8, 9, 1, 0, -1, //
            2, 5, 7, 20, 7, 20, 11, 11, 6, 4, 3, 8, 9, 1, 0, -1,
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

/// A law-3 `PROPS` (rate-and-state, docs/props.md "Law 3"), its whole layout: each entry mostly
/// a value of its own valid range (μ₀ in [0, 1], a in [0, 0.1], b in [−0.05, 0.15], V₀ and L
/// ordinary positive, the two switches 0 or 1, γ_crit, the tolerance and θ₀ off or positive),
/// one in 16 any real.
fn decode_rate_state_props(b: &mut Bytes) -> Vec<f64> {
    let mut props = Vec::with_capacity(RATE_STATE_NPROPS);
    for i in 0..RATE_STATE_NPROPS {
        let sel = b.u8();
        let v = match (i, sel % 16) {
            (_, 15) => b.real(),
            (0, _) => f64::from(LAW_RATE_STATE),
            (1, _) => b.unit(),
            (2, _) => 0.1 * b.unit(),
            (3, _) => 0.2 * b.unit() - 0.05,
            (4 | 5, _) => b.positive(),
            (6 | 7, _) => f64::from(sel % 2),
            (_, _) => {
                if sel % 2 == 0 {
                    0.0
                } else {
                    b.positive()
                }
            }
        };
        props.push(v);
    }
    props
}

/// Whether `props` selects law 3 (`PROPS(1) = 3`).
fn is_rate_state(props: &[f64]) -> bool {
    props.first() == Some(&f64::from(LAW_RATE_STATE))
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
        // Law 3's arm: its layout, and NSTATV mostly the 4 it needs.
        let rate_state = len(a.int("NPROPS")) == RATE_STATE_NPROPS;
        if rate_state {
            a.put("PROPS", decode_rate_state_props(b));
            a.set_int("NSTATV", b.pick(&[4, 4, 4, 4, 4, 4, 5, 8, 3, 0]));
        } else {
            a.put("PROPS", decode_props(b, a.int("NPROPS")));
        }
        let flags = b.u8();
        a.draw(b, &INCREMENT);
        // STATEV(3) is a status code; keep it one mostly.
        if let Some(x) = a["STATEV"].get_mut(2) {
            *x = f64::from(b.u8() % 3);
        }
        // Law 3: STATEV(4) = θ mostly 0 (not started) or positive, STATEV(1..2) mostly ≥ 0, and
        // DTIME and CHRLNGTH (drawn below) mostly ≥ 0.
        let shape = if rate_state { b.u8() } else { 0 };
        if rate_state {
            let statev = &mut a["STATEV"];
            if let Some(x) = statev.get_mut(3) {
                match shape % 4 {
                    0 => *x = 0.0,
                    1 | 2 => *x = b.positive(),
                    _ => {}
                }
            }
            if shape & 4 == 0 {
                for x in statev.iter_mut().take(2) {
                    *x = x.abs();
                }
            }
        }
        a.draw(b, &POINT);
        if rate_state && shape & 8 == 0 {
            for name in ["DTIME", "CHRLNGTH"] {
                let x = &mut a[name][0];
                *x = x.abs();
            }
        }
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
        let opt = |p: *mut f64| or_null_mut(p, null);
        let out = call(&self.args, &self.names, &IN_OUT, &OUTPUTS, |a, names, o| {
            let [ci, sl, ms] = names.pointers();
            let [ci_len, sl_len, ms_len] = names.lengths();
            // SAFETY: every array has exactly the length the call declares (NFDIR, NFDIR², 2·NFDIR,
            // NSTATV, NPROPS, MCRD, 2·NPRED, the hidden name lengths; scalars one entry).
            // The arguments grouped by role, several a line (rustfmt::skip keeps the groups).
            #[rustfmt::skip]
            unsafe {
                fric_(
                    // written
                    o.int_ptr_mut("LM"), o.ptr_mut("TAU"), o.ptr_mut("DDTDDG"), o.ptr_mut("DDTDDP"),
                    opt(o.ptr_mut("DSLIP")), opt(o.ptr_mut("SED")),
                    opt(o.ptr_mut("SFD")), opt(o.ptr_mut("DDTDDT")),
                    o.ptr_mut("PNEWDT"), o.ptr_mut("STATEV"),
                    // the increment
                    a.ptr("DGAM"), a.ptr("TAULM"), a.ptr("PRESS"),
                    a.ptr("DPRESS"), a.ptr("DDPDDH"), a.ptr("SLIP"),
                    a.int_ptr("KSTEP"), a.int_ptr("KINC"), a.ptr("TIME"), a.ptr("DTIME"),
                    // where
                    a.int_ptr("NOEL"), ci, sl, ms,
                    a.int_ptr("NPT"), a.int_ptr("NODE"), a.int_ptr("NPATCH"),
                    a.ptr("COORDS"), a.ptr("RCOORD"), a.ptr("DROT"),
                    a.ptr("TEMP"), a.ptr("PREDEF"),
                    // sizes, properties, the names' lengths
                    a.int_ptr("NFDIR"), a.int_ptr("MCRD"), a.int_ptr("NPRED"), a.int_ptr("NSTATV"),
                    a.ptr("CHRLNGTH"), a.ptr("PROPS"), a.int_ptr("NPROPS"), ci_len, sl_len, ms_len,
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
        // Law 3 keeps θ in STATEV(4), and never reports exact stick.
        let rate_state = is_rate_state(props);
        if rate_state && lm != 0 {
            return Err(format!("rate-and-state law with LM = {lm} on exit"));
        }
        if rate_state && a.len_of("NSTATV") < 4 {
            return Err("rate-and-state law answered with NSTATV < 4".into());
        }
        let used = if rate_state {
            4
        } else {
            3 + if damping { a.len_of("NFDIR") } else { 0 }
        };
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
        if is_rate_state(&self.args["PROPS"]) {
            return self.check_rate_state(out);
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

    /// Law 3 against its definition (docs/props.md "Law 3"), written out here: after a slip
    /// (`STATEV(3)` = 1 out) |τ| = μ(V, θ)·p⁺ at the rate and state the call reports
    /// (`STATEV(2)`, `STATEV(4)`); after a stick |τ| ≤ μ(V*, θₙ)·p⁺, the strength of the stick
    /// stiffness (V* the start slip rate after a slip, else V₀; θₙ the start state, θ₀ or L/V₀
    /// when `STATEV(4)` = 0), and θ healed by Δt (aging law) or kept (slip law). θ > 0 always.
    fn check_rate_state(&self, out: &Outputs) -> Result<(), String> {
        let law = RateStateLaw::from_props(&self.args["PROPS"]);
        let (statev0, statev) = (&self.args["STATEV"], &out["STATEV"]);
        let theta = statev[3];
        if theta.is_nan() || theta <= 0.0 {
            return Err(format!("rate-and-state θ = {theta} on exit: {out:?}"));
        }
        let p_plus = self.args.real("PRESS").max(0.0);
        let magnitude = norm(&out["TAU"]);
        if statev[2] == 1.0 {
            // Judged where the law's own quotients V₀θ/L and V/V₀ are normal numbers: outside,
            // the library's logarithms of under- or overflowed quotients may differ from this
            // independent μ (a NaN μ is refused: tests/rate_state.rs).
            let normal = |q: f64| (1e-300..=1e300).contains(&q);
            if !(normal(law.v0 * theta / law.l) && normal(statev[1] / law.v0)) {
                return Ok(());
            }
            let (mu, scale) = law.mu(statev[1], theta);
            let want = mu * p_plus;
            let tol = 1e-12 * scale * p_plus + 1e-321;
            if (magnitude - want).abs() > tol {
                return Err(format!(
                    "rate-and-state slip: |TAU| = {magnitude:e}, μ(V, θ)·p⁺ = {want:e}: {out:?}"
                ));
            }
            return Ok(());
        }
        let theta_start = if statev0[3] == 0.0 {
            law.theta_initial
        } else {
            statev0[3]
        };
        let v_star = if statev0[2] == 1.0 && statev0[1] > 0.0 {
            statev0[1]
        } else {
            law.v0
        };
        let (mu, scale) = law.mu(v_star, theta_start);
        let bound = (mu + 1e-12 * scale) * p_plus * (1.0 + 1e-12) + 1e-321;
        if magnitude > bound {
            return Err(format!(
                "rate-and-state stick: |TAU| = {magnitude:e} above μ(V*, θₙ)·p⁺ = {bound:e}: {out:?}"
            ));
        }
        let healed = if law.slip_law {
            theta_start
        } else {
            theta_start + self.args.real("DTIME")
        };
        if (theta - healed).abs() > 4.0 * f64::EPSILON * healed {
            return Err(format!(
                "rate-and-state stick: θ = {theta:e} on exit, {healed:e} expected: {out:?}"
            ));
        }
        Ok(())
    }
}

/// Law 3's parameters from a `PROPS` the library accepted, and μ(V, θ) written out from its
/// definition (docs/props.md "Law 3"), for the property checks.
struct RateStateLaw {
    mu0: f64,
    a: f64,
    b: f64,
    v0: f64,
    l: f64,
    slip_law: bool,
    regularised: bool,
    /// θ of a point whose `STATEV(4)` is 0: θ₀ = `PROPS(11)`, or L/V₀.
    theta_initial: f64,
}

impl RateStateLaw {
    fn from_props(props: &[f64]) -> Self {
        let get = |i: usize| props.get(i).copied().unwrap_or(0.0);
        let (v0, l, theta0) = (get(4), get(5), get(10));
        RateStateLaw {
            mu0: get(1),
            a: get(2),
            b: get(3),
            v0,
            l,
            slip_law: get(6) == 1.0,
            regularised: get(7) == 1.0,
            theta_initial: if theta0 > 0.0 { theta0 } else { l / v0 },
        }
    }

    /// μ(V, θ) (0 where the expression is below 0) and the size of the terms it sums, for a
    /// tolerance: μ₀ + a·ln(V/V₀) + b·ln(V₀θ/L), or a·asinh(V/(2V₀)·e^(ψ/a)) with
    /// ψ = μ₀ + b·ln(V₀θ/L). Each logarithm is taken apart, so no product can overflow; a term
    /// with a zero coefficient is 0 whatever its logarithm (a = 0: μ does not depend on V).
    fn mu(&self, v: f64, theta: f64) -> (f64, f64) {
        let times = |c: f64, ln: f64| if c == 0.0 { 0.0 } else { c * ln };
        let state = [self.v0.ln(), theta.ln(), -self.l.ln()];
        let psi = self.mu0 + state.iter().map(|x| times(self.b, *x)).sum::<f64>();
        let mut scale = self.mu0.abs() + state.iter().map(|x| times(self.b, *x).abs()).sum::<f64>();
        let (ln_v, ln_v0) = (v.ln(), self.v0.ln());
        let mu = if self.regularised {
            // ln z = ln(V/(2V₀)) + ψ/a; asinh z = ln 2z + O(z⁻²) far above 1.
            let ln_z = ln_v - std::f64::consts::LN_2 - ln_v0 + psi / self.a;
            let mu = if ln_z > 36.0 {
                self.a * (std::f64::consts::LN_2 + ln_z)
            } else {
                self.a * ln_z.exp().asinh()
            };
            scale += self.a * (ln_v.abs() + ln_v0.abs() + 1.0) + mu.abs() * (1.0 + ln_z.abs());
            mu
        } else {
            scale += times(self.a, ln_v).abs() + times(self.a, ln_v0).abs();
            psi + times(self.a, ln_v) - times(self.a, ln_v0)
        };
        (mu.max(0.0), scale)
    }
}
