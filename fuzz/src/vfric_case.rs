//! One `vfric_` call (Abaqus/Explicit VFRIC, double-precision build) decoded from fuzzer bytes,
//! with guard values around every array the library may write (`fTangential`, `statev`) and
//! every input kept for comparison, and the properties every call must have (docs/vfric.md).
//!
//! Shared by the `vfric` fuzz target and `tests/fuzz_regressions_vfric.rs` (included there by
//! path).

use std::ffi::c_int;

use super::args::{Args, Draw, Outputs, Row, call, or_null};
use super::bytes::{Bytes, bits, len};
use super::contract::{Names, unwritten};
use Draw::Pick;
use interfacial::abi::vfric_;

/// Written into every output entry and guard before the call, to see what the call wrote.
pub use super::contract::UNWRITTEN;

/// Guard entries on each side of `fTangential` and `statev`.
pub const GUARD: usize = 4;

/// Length of the shared buffers passed for the arguments VFRIC does not read (`dSlipFric`,
/// `fTangPrev`, coordinates, …): every one of them is at most this long for the sizes drawn.
const UNREAD_LEN: usize = 3 * 3 * 18 + 8;

/// Which pointer argument is passed as NULL. VFRIC documents the ones it reads as refused when
/// NULL (a fault of the whole call), and the others as never dereferenced (`Unread`: all of
/// them NULL at once).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VfricNull {
    None,
    FTangential,
    FNormal,
    FStickForce,
    JConSlvid,
    AreaSlv,
    Props,
    NContact,
    NFricDir,
    NProps,
    NSlvNod,
    Unread,
}

/// The [`VfricNull`] that a decoder byte 0 to 9 chooses, by role: the output, the per-point
/// arrays, `PROPS`, the counts. Bytes 10 to 40 choose [`VfricNull::Unread`], any other none.
#[rustfmt::skip]
const VFRIC_NULLS: [VfricNull; 10] = [
    VfricNull::FTangential,
    VfricNull::FNormal, VfricNull::FStickForce, VfricNull::JConSlvid, VfricNull::AreaSlv,
    VfricNull::Props,
    VfricNull::NContact, VfricNull::NFricDir, VfricNull::NProps, VfricNull::NSlvNod,
];

/// The counts, drawn first: mostly a valid block, but nContact ≤ 0, nFricDir ∉ {1, 2}, nSlvNod
/// ≤ 0 and any nProps stay reachable.
const COUNTS: [Row; 4] = [
    (
        &["nContact"],
        Pick(&[1, 1, 2, 3, 4, 5, 8, 17, 1, 2, 3, 0, -1]),
    ),
    (&["nFricDir"], Pick(&[1, 2, 1, 2, 1, 2, 1, 2, 0, 3, -1])),
    (&["nSlvNod"], Pick(&[1, 2, 3, 4, 8, 17, 2, 3, 0, -1])),
    (
        &["nProps"],
        Pick(&[7, 7, 7, 7, 7, 7, 2, 3, 4, 5, 6, 8, 13, 20, 21, 1, 0, -1]),
    ),
];

/// Every argument of one VFRIC call that the library may read, by name (`nContact`,
/// `nFricDir`, `nSlvNod`, `nProps`, `jConSlvid(nContact)`; `fNormal(nContact)`,
/// `fStickForce(nContact)`, `areaSlv(nSlvNod)`, `props(nProps)`, `statev(2, nContact)`), plus
/// `unread`, the stand-in for every real array VFRIC does not read, and `unreadInts`, for the
/// integer ones. Arrays have exactly their declared lengths.
#[derive(Clone, Debug)]
pub struct VfricCase {
    pub args: Args,
    /// `surfInt` (and blank `surfSec`, `surfMain` of 8 bytes).
    pub names: Names,
    pub null: VfricNull,
}

/// What the call wrote, read by point: `fTangential` and `statev` each with `GUARD` entries
/// either side.
pub trait Tangential {
    /// `fTangential(d+1, k+1)` for `nFricDir = nf`.
    fn force(&self, nf: usize, k: usize, d: usize) -> f64;
}

impl Tangential for Outputs {
    fn force(&self, nf: usize, k: usize, d: usize) -> f64 {
        self["fTangential"][GUARD + k * nf + d]
    }
}

/// `surfInt` as given, and blank `surfSec`, `surfMain` of 8 bytes.
fn names(surf_int: Vec<u8>) -> Names {
    Names {
        interaction: surf_int,
        secondary: vec![b' '; 8],
        main: vec![b' '; 8],
    }
}

/// What docs/vfric.md says the call does as a whole.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Expect {
    /// Refused; the block cannot or must not be written.
    RefusedUnwritten,
    /// Refused; every entry of fTangential(nFricDir, nContact) is 0.
    RefusedZeroed,
    /// nContact = 0: nothing to do, no message.
    Empty,
    /// Computed point by point.
    Points,
}

/// The plain law-1 `PROPS` VFRIC accepts (docs/vfric.md, "Parameters", and docs/props.md),
/// written from the documentation: `PROPS(1) = 1`; μ, τ_max, γ_crit, tolerance each finite and
/// ≥ 0; `PROPS(3)` 0 or μ; `PROPS(7)` 0, 1, 2, or 4 with `PROPS(5)` > 0; `PROPS(8..)` absent or 0.
pub fn plain_law(props: &[f64]) -> bool {
    let get = |i: usize| props.get(i - 1).copied().unwrap_or(0.0);
    let range = |v: f64| v.is_finite() && v >= 0.0;
    props.len() >= 2
        && get(1) == 1.0
        && [get(2), get(4), get(5), get(6)].into_iter().all(range)
        && (get(3) == 0.0 || get(3) == get(2))
        // The stick modes VFRIC takes (it ignores the stick): 0, 1, 2, and 4 (the constant stick
        // stiffness, which needs its k_s = PROPS(5) > 0).
        && match get(7) {
            0.0 | 1.0 | 2.0 => true,
            4.0 => get(5) > 0.0,
            _ => false,
        }
        && props.iter().skip(7).all(|v| *v == 0.0)
}

/// A law-1 `PROPS` of `nprops` entries, mostly a valid plain law (μ, τ_max on or off, a stick
/// mode), now and then an anisotropic, extended, viscous, adhesive or plain bad entry.
fn decode_props(b: &mut Bytes, nprops: usize) -> Vec<f64> {
    let mut props: Vec<f64> = Vec::with_capacity(nprops);
    for i in 0..nprops {
        let sel = b.u8() % 8;
        let v = match (i, sel) {
            (0, 0..=6) => 1.0,
            (1, 0..=3) => b.positive(),
            (1, 4 | 5) => b.real().abs(),
            (1, 6) => 0.0,
            (2, 0..=3) => 0.0,
            (2, 4 | 5) => props[1],
            (2, 6) => b.real().abs(),
            (3, 0..=3) => 0.0,
            (3, 4 | 5) => b.positive(),
            (3, 6) => b.real().abs(),
            (4 | 5, 0..=5) => 0.0,
            (4 | 5, 6) => b.positive(),
            (6, 0..=2) => 0.0,
            (6, 3) => 1.0,
            (6, 4 | 5) => 2.0,
            (6, 6) => 3.0,
            (7.., 0..=6) => 0.0,
            _ => b.real(),
        };
        props.push(v);
    }
    props
}

impl VfricCase {
    /// A valid block: these `props`, normal and stick forces (equal lengths), every point on
    /// slave node `slave[k]` of `area`, `nFricDir = nf`, interaction `"VF1"` (80 bytes).
    pub fn block(
        props: &[f64],
        nf: i32,
        normal: &[f64],
        stick: &[f64],
        slave: &[i32],
        area: &[f64],
    ) -> Self {
        let n = normal.len();
        let count = |len: usize| i32::try_from(len).unwrap_or(i32::MAX);
        let mut a = Args::new();
        a.set_int("nContact", count(n));
        a.set_int("nFricDir", nf);
        a.set_int("nSlvNod", count(area.len()));
        a.set_int("nProps", count(props.len()));
        a.put("props", props.to_vec());
        a.put("fNormal", normal.to_vec());
        a.put("fStickForce", stick.to_vec());
        a.put_ints("jConSlvid", slave.to_vec());
        a.put("areaSlv", area.to_vec());
        a.put("statev", vec![3.25; 2 * n]);
        a.put("unread", vec![0.5; UNREAD_LEN]);
        a.put_ints("unreadInts", vec![1; 64]);
        let mut surf_int = b"VF1".to_vec();
        surf_int.resize(80, b' ');
        VfricCase {
            args: a,
            names: names(surf_int),
            null: VfricNull::None,
        }
    }

    /// Decodes any byte string; most inputs are a valid block of a valid plain law, but every
    /// bad shape (nContact ≤ 0, nFricDir ∉ {1, 2}, bad PROPS, slave nodes out of range, NULL
    /// pointers) stays reachable.
    pub fn decode(data: &[u8]) -> Self {
        let b = &mut Bytes::new(data);
        let mut a = Args::new();
        a.draw(b, &COUNTS);
        let null = b.choose(&VFRIC_NULLS, |k| {
            if k <= 40 {
                VfricNull::Unread
            } else {
                VfricNull::None
            }
        });
        let (n, nodes) = (a.len_of("nContact"), a.len_of("nSlvNod"));
        let props = decode_props(b, a.len_of("nProps"));
        // Forces of every class; the flags make them mostly physical (F_N ≥ 0, F_stick ≥ 0)
        // and, now and then, put μ·F_N and F_stick close together.
        let flags = b.u8();
        let mut normal = b.reals(n);
        let mut stick = b.reals(n);
        if flags & 1 == 0 {
            normal.iter_mut().for_each(|x| *x = x.abs());
        }
        if flags & 2 == 0 {
            stick.iter_mut().for_each(|x| *x = x.abs());
        }
        if flags & 12 == 0 {
            // F_stick = μ·F_N·s, s in [0, 2]: stick and slip in equal measure.
            let mu = props.get(1).copied().unwrap_or(0.0);
            for (s, f) in stick.iter_mut().zip(&normal) {
                *s = mu * f * 2.0 * b.unit();
            }
        }
        let nslvnod = a.int("nSlvNod");
        let slave = (0..n)
            .map(|_| match b.u8() {
                x @ 0..=199 => 1 + i32::from(x) % nslvnod.max(1),
                200..=209 => 0,
                210..=219 => -1,
                220..=229 => nslvnod.saturating_add(1),
                230..=239 => i32::MAX,
                240..=249 => i32::MIN,
                _ => nslvnod,
            })
            .collect();
        let mut area = b.reals(nodes);
        if flags & 16 == 0 {
            area.iter_mut().for_each(|x| *x = x.abs());
        }
        a.put("props", props);
        a.put("fNormal", normal);
        a.put("fStickForce", stick);
        a.put_ints("jConSlvid", slave);
        a.put("areaSlv", area);
        a.put("statev", b.reals(2 * n));
        a.put("unread", b.reals(UNREAD_LEN));
        a.put_ints("unreadInts", vec![1; 64]);
        VfricCase {
            args: a,
            names: names(b.name()),
            null,
        }
    }

    /// Calls `vfric_` through its real symbol and checks every property; `Err` names the first
    /// one violated. What it wrote: `fTangential` and `statev`, each with `GUARD` entries either
    /// side.
    pub fn check(&self) -> Result<Outputs, String> {
        let n = self.args.len_of("nContact");
        let nf = self.args.len_of("nFricDir");
        let null = self.null;
        let unread = null == VfricNull::Unread;
        let ro = |p: *const f64, which: VfricNull| or_null(p, null == which);
        let io = |p: *const c_int, which: VfricNull| or_null(p, null == which);
        let out = call(&self.args, &self.names, &[], &[], |a, names, o| {
            let guard = vec![UNWRITTEN; GUARD];
            o.put("fTangential", vec![UNWRITTEN; nf * n + 2 * GUARD]);
            o.put("statev", [&guard[..], &a["statev"], &guard].concat());
            let ftan = if null == VfricNull::FTangential {
                std::ptr::null_mut()
            } else {
                // SAFETY: GUARD < the array's length.
                unsafe { o.ptr_mut("fTangential").add(GUARD) }
            };
            let statev = if unread {
                std::ptr::null_mut()
            } else {
                // SAFETY: as above.
                unsafe { o.ptr_mut("statev").add(GUARD) }
            };
            // The arguments VFRIC does not read, each NULL with `VfricNull::Unread`: the sizes
            // it does not use (1, 2, 4, nFricDir + 1), and shared buffers for the arrays.
            let sizes: [c_int; 4] = [1, 2, 4, a.int("nFricDir").saturating_add(1)];
            let [one, two, four, ndir] = sizes.each_ref().map(|n| io(n, VfricNull::Unread));
            let ip = io(a.int_ptr("unreadInts"), VfricNull::Unread);
            let u = ro(a.ptr("unread"), VfricNull::Unread);
            let [surf_int, surf_sec, surf_main] = names.pointers();
            let [int_len, sec_len, main_len] = names.lengths();
            // SAFETY: every array the call reads has exactly the length it declares (nContact,
            // nSlvNod, nProps, the name's hidden length), fTangential(nFricDir, nContact) and
            // statev(2, nContact) lie inside their guards; the arrays VFRIC does not read point
            // to buffers longer than any of them; NULL where `null` says so.
            // The arguments grouped by role, several a line (rustfmt::skip keeps the groups).
            #[rustfmt::skip]
            unsafe {
                vfric_(
                    // written
                    ftan, statev,
                    // kStep, kInc, the sizes
                    one, one,
                    io(a.int_ptr("nContact"), VfricNull::NContact), four,
                    io(a.int_ptr("nSlvNod"), VfricNull::NSlvNod), four,
                    io(a.int_ptr("nFricDir"), VfricNull::NFricDir), ndir, two,
                    io(a.int_ptr("nProps"), VfricNull::NProps), one, one, one,
                    // the node and contact ids, the times, the names, lContType
                    ip, ip, io(a.int_ptr("jConSlvid"), VfricNull::JConSlvid), ip,
                    u, u, u,
                    surf_int, surf_sec, surf_main, ip,
                    // the forces and the geometry
                    u, ro(a.ptr("fStickForce"), VfricNull::FStickForce),
                    u, ro(a.ptr("fNormal"), VfricNull::FNormal),
                    u, u, u, u, u, u,
                    // props, areaSlv, the temperatures and fields, the names' lengths
                    ro(a.ptr("props"), VfricNull::Props), ro(a.ptr("areaSlv"), VfricNull::AreaSlv),
                    u, u, u, u,
                    int_len, sec_len, main_len,
                )
            };
        })?;
        let statev = &out["statev"];
        if bits(&statev[GUARD..GUARD + 2 * n]) != bits(&self.args["statev"])
            || statev[..GUARD]
                .iter()
                .chain(&statev[GUARD + 2 * n..])
                .any(|x| !unwritten(x))
        {
            return Err("statev (or around it) was written".into());
        }
        let t = &out["fTangential"];
        if t[..GUARD]
            .iter()
            .chain(&t[t.len() - GUARD..])
            .any(|x| !unwritten(x))
        {
            return Err("written outside fTangential(nFricDir, nContact)".into());
        }
        self.check_outputs(&out)?;
        Ok(out)
    }

    /// `PROPS(i)`, 0 when absent.
    fn prop(&self, i: usize) -> f64 {
        self.args["props"].get(i - 1).copied().unwrap_or(0.0)
    }

    fn rough(&self) -> bool {
        self.prop(7) == 2.0
    }

    /// The force cap τ_max·A applies (docs/vfric.md: areaSlv is read only then).
    fn needs_area(&self) -> bool {
        self.prop(4) > 0.0 && !self.rough()
    }

    /// The whole-call outcome docs/vfric.md gives.
    fn expect(&self) -> Expect {
        use VfricNull as N;
        let null = self.null;
        if matches!(null, N::NContact | N::NFricDir)
            || self.args.int("nContact") < 0
            || !(self.args.int("nFricDir") == 1 || self.args.int("nFricDir") == 2)
        {
            return Expect::RefusedUnwritten;
        }
        let refused = if null == N::FTangential {
            Expect::RefusedUnwritten
        } else {
            Expect::RefusedZeroed
        };
        let props_ok = null != N::NProps
            && self.args.int("nProps") >= 0
            && (null != N::Props || self.args.int("nProps") == 0)
            && plain_law(&self.args["props"]);
        if !props_ok {
            return refused;
        }
        if self.args.int("nContact") == 0 {
            return Expect::Empty;
        }
        if matches!(null, N::FTangential | N::FNormal | N::FStickForce) {
            return refused;
        }
        if self.needs_area()
            && (matches!(null, N::NSlvNod | N::JConSlvid)
                || self.args.int("nSlvNod") < 0
                || (null == N::AreaSlv && self.args.int("nSlvNod") > 0))
        {
            return refused;
        }
        Expect::Points
    }

    /// Point k (0-based) by the closed form of docs/vfric.md: `Ok(F)` for a valid point,
    /// `Err(true)` for a bad point, `Err(false)` for a point whose output is 0 either way and
    /// whose message is optional (a bad area at a point in tension, where the area is not
    /// needed).
    pub fn expected_force(&self, k: usize) -> Result<f64, bool> {
        let (fnormal, fstick) = (self.args["fNormal"][k], self.args["fStickForce"][k]);
        if !(fnormal.is_finite() && fstick.is_finite() && fstick >= 0.0) {
            return Err(true);
        }
        if self.rough() {
            return Ok(fstick);
        }
        let cap = if self.needs_area() {
            let node = usize::try_from(self.args.ints("jConSlvid")[k])
                .ok()
                .filter(|i| (1..=len(self.args.int("nSlvNod"))).contains(i));
            let Some(node) = node else {
                return Err(true);
            };
            let a = self.args["areaSlv"][node - 1];
            if !(a.is_finite() && a >= 0.0) {
                return Err(fnormal >= 0.0);
            }
            self.prop(4) * a
        } else {
            f64::INFINITY
        };
        if fnormal < 0.0 {
            return Ok(0.0);
        }
        Ok((self.prop(2) * fnormal).min(cap).min(fstick))
    }

    fn check_outputs(&self, out: &Outputs) -> Result<(), String> {
        let n = len(self.args.int("nContact"));
        let nf = len(self.args.int("nFricDir"));
        let block = &out["fTangential"][GUARD..GUARD + nf * n];
        let names = out.message.starts_with("interfacial: VFRIC: interaction '");
        match self.expect() {
            Expect::RefusedUnwritten | Expect::RefusedZeroed => {
                if !names {
                    return Err(format!(
                        "refused without a VFRIC message: {:?}",
                        out.message
                    ));
                }
                let zeroed = self.expect() == Expect::RefusedZeroed;
                if zeroed && block.iter().any(|x| x.to_bits() != 0) {
                    return Err(format!("refused ({}) but the block is not +0", out.message));
                }
                if !zeroed && !block.iter().all(unwritten) {
                    return Err(format!("refused ({}) and wrote the block", out.message));
                }
                if !out.message.contains("(block)") {
                    return Err(format!("a call fault not named as such: {}", out.message));
                }
                Ok(())
            }
            Expect::Empty => {
                if out.message.is_empty() {
                    Ok(())
                } else {
                    Err(format!("nContact = 0 with a message: {}", out.message))
                }
            }
            Expect::Points => {
                let mut last_bad = None;
                for k in 0..n {
                    let f1 = out.force(nf, k, 0);
                    if nf == 2 && out.force(nf, k, 1).to_bits() != 0 {
                        return Err(format!(
                            "fTangential(2,{}) = {} ≠ +0",
                            k + 1,
                            out.force(nf, k, 1)
                        ));
                    }
                    let want = match self.expected_force(k) {
                        Ok(f) => {
                            if !(f1 >= -self.args["fStickForce"][k] && f1 <= 0.0) {
                                return Err(format!(
                                    "fTangential(1,{}) = {f1} outside [-fStickForce, 0]",
                                    k + 1
                                ));
                            }
                            0.0 - f
                        }
                        Err(bad) => {
                            if bad {
                                last_bad = Some(k);
                            }
                            0.0
                        }
                    };
                    if f1.to_bits() != want.to_bits() {
                        return Err(format!(
                            "fTangential(1,{}) = {f1:e}, closed form {want:e} (F_N {:e}, \
                             F_stick {:e})",
                            k + 1,
                            self.args["fNormal"][k],
                            self.args["fStickForce"][k]
                        ));
                    }
                }
                if out.message.is_empty() {
                    return match last_bad {
                        None => Ok(()),
                        Some(k) => Err(format!("bad point {} without a message", k + 1)),
                    };
                }
                if !names {
                    return Err(format!("a message not naming VFRIC: {:?}", out.message));
                }
                // The last message names the last point reported.
                let named = out
                    .message
                    .split("(contact point ")
                    .nth(1)
                    .and_then(|s| s.split(')').next())
                    .and_then(|s| s.parse::<usize>().ok())
                    .and_then(|k| k.checked_sub(1));
                match named {
                    Some(k)
                        if k < n
                            && self.expected_force(k).is_err()
                            && last_bad.is_none_or(|b| b <= k) =>
                    {
                        Ok(())
                    }
                    _ => Err(format!(
                        "message {:?} does not name the last bad point ({last_bad:?})",
                        out.message
                    )),
                }
            }
        }
    }
}
