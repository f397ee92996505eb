//! One `ifl_fric_batch` call decoded from fuzzer bytes: random `npoints`, `ld`, `nfdir`,
//! `nstatv`, every structure-of-arrays input allocated with exactly `ld·(components − 1) +
//! npoints` entries (so AddressSanitizer reports any access past it), and the properties:
//! each point bit for bit what `fric_` gives it, and a whole-batch fault writes only `pnewdt`.
//!
//! Shared by the `batch` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use super::args::{Args, Outputs, call, or_null, or_null_mut};
use super::bytes::{Bytes, bits};
use super::contract::{Names, unwritten};
use super::fric_case::FricCase;
use interfacial::abi::{IflStatus, ifl_fric_batch};

pub use super::contract::UNWRITTEN;

/// The structure-of-arrays inputs after `lm`, in the order drawn, with their components (`n`:
/// one per direction, `s`: one per state variable); a line per kind of argument (rustfmt::skip).
#[rustfmt::skip]
const INPUTS: [(&str, Rows); 7] = [
    ("tau", Rows::N), ("dgam", Rows::N), ("taulm", Rows::N),
    ("press", Rows::One), ("dpress", Rows::One), ("chrlngth", Rows::One),
    ("statev", Rows::S),
];

/// The outputs only written, with their components; the tangents, then the optional outputs.
#[rustfmt::skip]
const OUTPUTS: [(&str, Rows); 5] = [
    ("ddtddg", Rows::NN), ("ddtddp", Rows::N),
    ("dslip", Rows::N), ("sed", Rows::One), ("sfd", Rows::One),
];

/// Rows (components) of a structure-of-arrays argument.
#[derive(Clone, Copy, Debug)]
enum Rows {
    One,
    /// `nfdir`.
    N,
    /// `nfdir²`.
    NN,
    /// `nstatv`.
    S,
}

/// Every `ifl_fric_batch` argument: `args` by name (`nfdir`, `nstatv`, `lm`; `props`,
/// `dtime`, `pnewdt`, and the structure-of-arrays inputs of [`INPUTS`]), arrays in the batch
/// layout with exactly the needed length.
#[derive(Clone, Debug)]
pub struct BatchCase {
    pub npoints: usize,
    pub ld: usize,
    pub args: Args,
    /// `dslip`, `sed`, `sfd` NULL.
    pub null_optional: bool,
    /// `taulm` NULL.
    pub null_taulm: bool,
    /// A required array NULL (index into lm, tau, ddtddg, ddtddp, statev, dgam, press,
    /// dpress, chrlngth), or none.
    pub null_required: Option<usize>,
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
        usize::try_from(self.args.int("nfdir"))
            .unwrap_or(0)
            .clamp(1, 2)
    }

    fn s(&self) -> usize {
        usize::try_from(self.args.int("nstatv")).unwrap_or(0).max(1)
    }

    /// Entries of an array of `rows`.
    fn entries(&self, rows: Rows) -> usize {
        let n = self.n();
        self.needed(match rows {
            Rows::One => 1,
            Rows::N => n,
            Rows::NN => n * n,
            Rows::S => self.s(),
        })
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
        let mut a = Args::new();
        a.set_int("nfdir", b.pick(&[1, 2, 1, 2, 1, 2, 1, 2, 0, 3, -1]));
        a.set_int("nstatv", b.pick(&[3, 3, 3, 4, 5, 2, 0, -1]));
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
        a.put("props", props);
        let flags = b.u8();
        a.put("dtime", vec![b.real()]);
        a.put("pnewdt", vec![b.large()]);
        let mut c = BatchCase {
            npoints,
            ld,
            args: a,
            null_optional: flags & 0x80 != 0,
            null_taulm: flags & 0x60 == 0x60,
            null_required: (flags & 0x1f == 0x1f).then(|| usize::from(b.u8() % 9)),
        };
        let lm = (0..c.needed(1))
            .map(|_| b.pick(&[0, 0, 0, 0, 1, 1, 2, -1]))
            .collect();
        c.args.put_ints("lm", lm);
        for (name, rows) in INPUTS {
            let values = b.reals(c.entries(rows));
            c.args.put(name, values);
        }
        // STATEV(3) is a status code: mostly 0, 1, 2.
        if c.s() >= 3 && npoints > 0 {
            for i in 0..npoints {
                let x = &mut c.args["statev"][i + 2 * ld];
                if x.is_finite() {
                    *x = (x.abs() % 3.0).floor();
                }
            }
        }
        c
    }

    /// Calls `ifl_fric_batch`: what it wrote (the whole arrays, padding included; `lm`, `tau`,
    /// `statev`, `pnewdt` and the outputs of [`OUTPUTS`]), its status (the integer `status`)
    /// and its message; `Err` when an input was written.
    pub fn call(&self) -> Result<Outputs, String> {
        let req = |k: usize| self.null_required == Some(k);
        let m = |k: usize, p: *mut f64| or_null_mut(p, req(k));
        let r = |k: usize, p: *const f64| or_null(p, req(k));
        let opt = |p: *mut f64| or_null_mut(p, self.null_optional);
        let kept = ["lm", "tau", "statev", "pnewdt"];
        call(&self.args, &Names::none(), &kept, &[], |a, _, o| {
            for (name, rows) in OUTPUTS {
                o.put(name, vec![UNWRITTEN; self.entries(rows)]);
            }
            let lm = or_null_mut(o.int_ptr_mut("lm"), req(0));
            let nprops = i32::try_from(a["props"].len()).unwrap_or(i32::MAX);
            // SAFETY: every non-NULL array holds exactly ld·(components − 1) + npoints entries
            // (0 for an empty batch), props holds nprops; outputs do not overlap.
            let status: IflStatus = unsafe {
                ifl_fric_batch(
                    self.npoints,
                    self.ld,
                    a.int("nfdir"),
                    a.ptr("props"),
                    nprops,
                    a.int("nstatv"),
                    a.real("dtime"),
                    lm,
                    m(1, o.ptr_mut("tau")),
                    m(2, o.ptr_mut("ddtddg")),
                    m(3, o.ptr_mut("ddtddp")),
                    opt(o.ptr_mut("dslip")),
                    opt(o.ptr_mut("sed")),
                    opt(o.ptr_mut("sfd")),
                    m(4, o.ptr_mut("statev")),
                    r(5, a.ptr("dgam")),
                    or_null(a.ptr("taulm"), self.null_taulm),
                    r(6, a.ptr("press")),
                    r(7, a.ptr("dpress")),
                    r(8, a.ptr("chrlngth")),
                    o.ptr_mut("pnewdt"),
                )
            };
            o.set_int("status", status as i32);
        })
    }

    /// Whether the batch as a whole must be refused, by its shape alone.
    fn bad_shape(&self) -> bool {
        let required_null = self.null_required.is_some() && self.npoints > 0;
        let (nfdir, nstatv) = (self.args.int("nfdir"), self.args.int("nstatv"));
        !(1..=2).contains(&nfdir) || nstatv < 3 || self.ld < self.npoints || required_null
    }

    /// Point `i` as a `fric_` call with the batch's law, `DTIME` and entry `PNEWDT`.
    pub fn point(&self, i: usize) -> FricCase {
        let (a, ld) = (&self.args, self.ld);
        let mut f = FricCase::coulomb(a.int("nfdir"), &a["props"]);
        let column = |name: &str, rows: usize| (0..rows).map(|r| a[name][i + r * ld]).collect();
        let p = &mut f.args;
        p.set_int("LM", a.ints("lm")[i]);
        p.set_int("NSTATV", a.int("nstatv"));
        for (name, batch) in [("TAU", "tau"), ("DGAM", "dgam"), ("TAULM", "taulm")] {
            p.put(name, column(batch, self.n()));
        }
        p.put("STATEV", column("statev", self.s()));
        for (name, batch) in [("PRESS", "press"), ("DPRESS", "dpress")] {
            p.put(name, column(batch, 1));
        }
        p.put("CHRLNGTH", column("chrlngth", 1));
        p.put("DTIME", a["dtime"].clone());
        p.put("PNEWDT", a["pnewdt"].clone());
        f.null_optional = self.null_optional;
        f
    }

    /// What `fric_` gives a point entering exact stick (`LM = 1`) with no `TAULM` array: `LM`,
    /// `TAU`, `STATEV` kept; tangents, `DSLIP`, `SFD` zero; `PNEWDT` 0.25.
    fn without_taulm(&self, f: &FricCase) -> Outputs {
        let n = self.n();
        let optional = |v: f64| if self.null_optional { UNWRITTEN } else { v };
        let mut r = f.args.clone();
        r.put("DDTDDG", vec![0.0; n * n]);
        r.put("DDTDDP", vec![0.0; n]);
        r.put("DSLIP", vec![optional(0.0); n]);
        r.put("SED", vec![UNWRITTEN]);
        r.put("SFD", vec![optional(0.0)]);
        let pnewdt = self.args.real("pnewdt");
        r.put(
            "PNEWDT",
            vec![if pnewdt.is_nan() || pnewdt > 0.25 {
                0.25
            } else {
                pnewdt
            }],
        );
        Outputs {
            args: r,
            message: "LM = 1 but no TAULM".into(),
        }
    }

    /// Calls the batch and checks every property; `Err` names the first one violated.
    pub fn check(&self) -> Result<Outputs, String> {
        let out = self.call()?;
        let a = &self.args;
        let kept = |name: &str| bits(&out[name]) == bits(&a[name]);
        let untouched = out.args.ints("lm") == a.ints("lm")
            && kept("tau")
            && kept("statev")
            && OUTPUTS
                .iter()
                .all(|(name, _)| out[*name].iter().all(unwritten));
        let status = out.int("status");
        let ok = status == IflStatus::Ok as i32;
        if ok != out.message.is_empty() {
            return Err(format!("status {status} with message {:?}", out.message));
        }
        if !ok && !out.message.starts_with("interfacial: ifl_fric_batch: ") {
            return Err(format!(
                "message does not name the routine: {:?}",
                out.message
            ));
        }
        // A batch of another law than 1 (adhesive, rate-and-state) may be refused as a whole
        // (no batch kernel), unless it reduces to the Coulomb law, in which case it must run
        // like fric_. Likewise the extended law 1 (anisotropy, μ laws, damping): fric_ runs
        // it, the batch kernel is the plain law's.
        let adhesive_refusal = !ok
            && untouched
            && (out
                .message
                .contains("the batch entry runs the plain Coulomb law (law 1) only")
                || out.message.contains("extended law-1 PROPS"));
        let probe_refused = !self.bad_shape() && {
            let mut probe = FricCase::coulomb(a.int("nfdir"), &a["props"]);
            probe.args.set_int("NSTATV", a.int("nstatv"));
            probe.args.put("STATEV", vec![0.0; self.s()]);
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
            let pnewdt = out.real("pnewdt");
            if pnewdt > 0.25 || pnewdt.is_nan() {
                return Err(format!("whole-batch fault with PNEWDT = {pnewdt}"));
            }
            return Ok(out);
        }
        // Per point: exactly fric_, into the batch layout.
        let mut expect = a.outputs(&["lm", "tau", "statev", "pnewdt"], &[]);
        for (name, rows) in OUTPUTS {
            expect.put(name, vec![UNWRITTEN; self.entries(rows)]);
        }
        let (n, ld) = (self.n(), self.ld);
        let mut failed = false;
        for i in 0..self.npoints {
            let f = self.point(i);
            let r = if self.null_taulm && f.args.int("LM") == 1 {
                self.without_taulm(&f)
            } else {
                f.check()
                    .map_err(|e| format!("point {i} through fric_: {e}"))?
            };
            if !r.message.is_empty() {
                failed = true;
            }
            expect.ints_mut("lm")[i] = r.int("LM");
            for k in 0..n {
                for (name, fric) in [("tau", "TAU"), ("ddtddp", "DDTDDP"), ("dslip", "DSLIP")] {
                    expect[name][i + k * ld] = r[fric][k];
                }
                for j in 0..n {
                    expect["ddtddg"][i + (k + j * n) * ld] = r["DDTDDG"][k + j * n];
                }
            }
            for (name, fric) in [("sed", "SED"), ("sfd", "SFD")] {
                expect[name][i] = r.real(fric);
            }
            for k in 0..self.s() {
                expect["statev"][i + k * ld] = r["STATEV"][k];
            }
            let (entry, point, lowest) =
                (a.real("pnewdt"), r.real("PNEWDT"), expect.real("pnewdt"));
            if point.to_bits() != entry.to_bits() && (lowest.is_nan() || point < lowest) {
                expect["pnewdt"][0] = point;
            }
        }
        // The status is checked below, against the points.
        expect.set_int("status", status);
        if !expect.same(&out.args) {
            return Err(format!(
                "the batch differs from fric_ per point:\n batch: {out:?}\n fric_: {expect:?}"
            ));
        }
        if failed == ok {
            return Err(format!(
                "status {status} but a point failed through fric_: {failed}"
            ));
        }
        Ok(out)
    }
}
