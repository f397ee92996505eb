//! The batch entry point: many independent contact points of one interaction in one call, the
//! fast path for hosts that own their contact points in arrays (explicit codes, GPU-style
//! layouts, the scene driver's sweeps).
//!
//! Layout: structure of arrays with a leading dimension `ld ≥ npoints`. Component `a` (0-based)
//! of point `i` of an array with several components per point is at `x[i + a·ld]`; `DDTDDG(a,b)`
//! of point `i` is at `ddtddg[i + (a + b·NFDIR)·ld]` (the Fortran order of `DDTDDG` per point).
//! Arrays with one entry per point (`lm`, `press`, …) are indexed by `i` alone.
//!
//! Each point gets exactly what `fric_` would give it with the same `PROPS`, `NSTATV`, `DTIME`
//! and inputs, bit for bit (`tests/batch.rs`, `tests/batch_chunks.rs`). With elastic stick
//! (`PROPS(7) = 0`), chunks of 8 points (`LANES`) go through the SIMD-friendly kernel
//! [`crate::laws::coulomb_batch::ElasticStickKernel`] (the same IEEE operations in the same
//! order, lane by lane); a chunk the kernel declines (any point with non-finite input, an
//! extreme norm, `LM` ≠ 0, …), the tail of the batch and the other stick modes go point by
//! point through [`crate::laws::coulomb::Coulomb::update`], which gives the messages and safe
//! outputs. Besides the kernel, what is saved is per-call overhead: `PROPS` is read once, sizes
//! are checked once, one panic guard for the whole batch, no pointer chasing per argument.

use std::ffi::c_int;

use super::{Fault, IflStatus, bad_lm, boundary, count, cut_back, null_pointer, short_nstatv};
use crate::laws::contact::{Contact, EntryFlag, Increment};
use crate::laws::coulomb::{Coulomb, CoulombState};
use crate::laws::coulomb_batch::{ChunkInput, ElasticStickKernel};
use crate::props::friction_law;
use crate::report::{Site, report};
use crate::{CUTBACK_RATIO, LawError};

/// The arrays of a batch of friction points, structure-of-arrays with leading dimension `ld`
/// (see the module documentation). Inputs are shared borrows, outputs mutable ones; optional
/// outputs (`dslip`, `sed`, `sfd`) may be left out.
#[derive(Debug)]
pub struct FricBatch<'a> {
    /// Number of points.
    pub npoints: usize,
    /// Leading dimension: distance between components of one point, `ld ≥ npoints` (pad it a
    /// little above a multiple of 512 for speed).
    pub ld: usize,
    /// Friction directions per point, 1 or 2 (`NFDIR`).
    pub nfdir: usize,
    /// Rows of `statev` (`NSTATV`, at least 3 for the Coulomb law).
    pub nstatv: usize,
    /// `LM` per point, in/out (0 motion, 1 exact stick, 2 frictionless: point left alone).
    pub lm: &'a mut [c_int],
    /// `TAU`, NFDIR components, in/out.
    pub tau: &'a mut [f64],
    /// `DDTDDG`, NFDIR² components, out.
    pub ddtddg: &'a mut [f64],
    /// `DDTDDP`, NFDIR components, out.
    pub ddtddp: &'a mut [f64],
    /// `DSLIP`, NFDIR components, out (optional).
    pub dslip: Option<&'a mut [f64]>,
    /// `SED` per point, out (optional).
    pub sed: Option<&'a mut [f64]>,
    /// `SFD` per point, out (optional).
    pub sfd: Option<&'a mut [f64]>,
    /// `STATEV`, `nstatv` components, in/out (the law uses the first 3).
    pub statev: &'a mut [f64],
    /// `DGAM`, NFDIR components.
    pub dgam: &'a [f64],
    /// `TAULM`, NFDIR components, read only for points with `LM = 1` on entry (optional).
    pub taulm: Option<&'a [f64]>,
    /// `PRESS` per point.
    pub press: &'a [f64],
    /// `DPRESS` per point.
    pub dpress: &'a [f64],
    /// `CHRLNGTH` per point.
    pub chrlngth: &'a [f64],
}

/// Why [`fric_batch`] did not complete every point.
#[derive(Clone, Debug, PartialEq)]
pub struct BatchError {
    /// The first failing point (0-based), or `None` for a fault of the whole batch (sizes,
    /// `PROPS`, `NFDIR`, `NSTATV`), in which case no point was touched.
    pub point: Option<usize>,
    /// How many points failed.
    pub failed: usize,
    /// The cause (of the first failing point).
    pub error: LawError,
}

impl std::fmt::Display for BatchError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.point {
            Some(i) => write!(
                f,
                "{} point(s) failed; first: point {i}: {}",
                self.failed, self.error
            ),
            None => write!(f, "{}", self.error),
        }
    }
}

impl std::error::Error for BatchError {}

/// Runs the friction law of `props` (the `PROPS` layout of `fric_`, `docs/props.md`) on every
/// point of `batch`, with time increment `dtime` for all of them.
///
/// Per point, the outputs are those of `fric_`. A point whose input is unusable gets `fric_`'s
/// failure outputs (`LM`, `TAU`, `STATEV` unchanged; `DDTDDG`, `DDTDDP`, `DSLIP`, `SFD` zero)
/// and the others are still computed; `pnewdt` is only ever lowered: to `CUTBACK_RATIO` (0.25)
/// when any point failed, or to a law's suggestion. Messages are reported as `fric_` reports
/// them (once per cause, routine `ifl_fric_batch`, place "batch point i").
///
/// # Errors
/// A fault of the whole batch (array too short for `ld`, `npoints` and the component count,
/// `ld < npoints`, bad `PROPS`, `NFDIR` not 1 or 2, `NSTATV < 3`): nothing is written but
/// `pnewdt`. Otherwise the first failing point and the number of failures.
pub fn fric_batch(
    props: &[f64],
    dtime: f64,
    batch: &mut FricBatch<'_>,
    pnewdt: &mut f64,
) -> Result<(), BatchError> {
    let whole = |error: LawError| BatchError {
        point: None,
        failed: batch.npoints,
        error,
    };
    let checked = check_sizes(batch)
        .and_then(|()| friction_law(props))
        .map_err(whole);
    // The batch kernel is the plain Coulomb law's; the extended law and laws 2 and 3 go
    // through fric_ (or uinter_) per point.
    let law = match checked.and_then(|law| {
        law.into_plain_coulomb(
            "the batch entry runs the plain Coulomb law (law 1) only; call fric_ per point",
        )
        .map_err(whole)
    }) {
        Ok(law) => law,
        Err(e) => {
            lower(pnewdt, CUTBACK_RATIO);
            return Err(e);
        }
    };
    let result = match batch.nfdir {
        1 => run::<1>(&law, dtime, batch, pnewdt),
        _ => run::<2>(&law, dtime, batch, pnewdt),
    };
    match result {
        None => Ok(()),
        Some(e) => Err(e),
    }
}

fn lower(pnewdt: &mut f64, ratio: f64) {
    if pnewdt.is_nan() || ratio < *pnewdt {
        *pnewdt = ratio;
    }
}

/// Length an array of `components` rows needs: `ld·(components − 1) + npoints`.
fn needed(b: &FricBatch<'_>, components: usize) -> Option<usize> {
    if b.npoints == 0 || components == 0 {
        return Some(0);
    }
    b.ld.checked_mul(components - 1)?.checked_add(b.npoints)
}

/// `NSTATV` holds the state of the law the batch runs (the plain Coulomb law), checked before
/// any array is read: the law's own count and name.
fn require_rows(nstatv: usize) -> Result<(), LawError> {
    if nstatv < CoulombState::NSTATV {
        return Err(short_nstatv(
            i64::try_from(nstatv).unwrap_or(i64::MAX),
            CoulombState::NSTATV,
            CoulombState::LAW,
            "the batch's nstatv",
        ));
    }
    Ok(())
}

fn check_sizes(b: &FricBatch<'_>) -> Result<(), LawError> {
    if b.nfdir != 1 && b.nfdir != 2 {
        return Err(LawError::Parameter(format!(
            "NFDIR = {}; expected 1 (2-D) or 2 (3-D)",
            b.nfdir
        )));
    }
    require_rows(b.nstatv)?;
    if b.ld < b.npoints {
        return Err(LawError::Parameter(format!(
            "leading dimension ld = {} is less than npoints = {}",
            b.ld, b.npoints
        )));
    }
    let n = b.nfdir;
    let arrays: [(&str, Option<usize>, usize); 11] = [
        ("lm", Some(b.lm.len()), 1),
        ("tau", Some(b.tau.len()), n),
        ("ddtddg", Some(b.ddtddg.len()), n * n),
        ("ddtddp", Some(b.ddtddp.len()), n),
        ("dslip", b.dslip.as_ref().map(|s| s.len()), n),
        ("sed", b.sed.as_ref().map(|s| s.len()), 1),
        ("sfd", b.sfd.as_ref().map(|s| s.len()), 1),
        ("statev", Some(b.statev.len()), b.nstatv),
        ("dgam", Some(b.dgam.len()), n),
        ("taulm", b.taulm.map(<[f64]>::len), n),
        ("press", Some(b.press.len()), 1),
    ];
    let tail: [(&str, Option<usize>, usize); 2] = [
        ("dpress", Some(b.dpress.len()), 1),
        ("chrlngth", Some(b.chrlngth.len()), 1),
    ];
    for (name, len, components) in arrays.into_iter().chain(tail) {
        let Some(len) = len else { continue };
        let need = needed(b, components)
            .ok_or_else(|| LawError::Parameter(format!("{name}: ld·{components} overflows")))?;
        if len < need {
            return Err(LawError::Parameter(format!(
                "{name} holds {len} values but {components} component(s) of {} points with \
                 ld = {} need {need}",
                b.npoints, b.ld
            )));
        }
    }
    Ok(())
}

/// Up to four rows of `n` entries, `ld` apart, borrowed from a structure-of-arrays slice whose
/// length `check_sizes` has verified; rows past `rows` are empty. Inlined, so that the loop
/// over points sees every row's length as `n` and needs no bounds check per access.
#[inline(always)]
fn rows_mut(s: &mut [f64], ld: usize, n: usize, rows: usize) -> [&mut [f64]; 4] {
    let mut out: [&mut [f64]; 4] = [&mut [], &mut [], &mut [], &mut []];
    let mut rest = s;
    for (r, slot) in out.iter_mut().enumerate().take(rows) {
        let taken = std::mem::take(&mut rest);
        let (row, tail) = if r + 1 < rows {
            taken.split_at_mut(ld)
        } else {
            (taken, &mut [][..])
        };
        *slot = &mut row[..n];
        rest = tail;
    }
    out
}

/// As [`rows_mut`], shared.
#[inline(always)]
fn rows(s: &[f64], ld: usize, n: usize, rows: usize) -> [&[f64]; 4] {
    let mut out: [&[f64]; 4] = [&[]; 4];
    for (r, slot) in out.iter_mut().enumerate().take(rows) {
        *slot = &s[r * ld..r * ld + n];
    }
    out
}

/// Views of one batch, each row exactly `npoints` long: the loop works on locals, not through
/// the `FricBatch` borrow, so the compiler keeps the row pointers in registers.
struct Views<'b> {
    lm: &'b mut [c_int],
    tau: [&'b mut [f64]; 4],
    ddtddg: [&'b mut [f64]; 4],
    ddtddp: [&'b mut [f64]; 4],
    dslip: Option<[&'b mut [f64]; 4]>,
    sed: Option<&'b mut [f64]>,
    sfd: Option<&'b mut [f64]>,
    statev: [&'b mut [f64]; 4],
    dgam: [&'b [f64]; 4],
    taulm: Option<[&'b [f64]; 4]>,
    press: &'b [f64],
    dpress: &'b [f64],
    chrlngth: &'b [f64],
}

/// The loop over points, one NFDIR. Returns the first point failure, if any.
#[inline(always)]
fn run<const N: usize>(
    law: &Coulomb,
    dtime: f64,
    b: &mut FricBatch<'_>,
    pnewdt: &mut f64,
) -> Option<BatchError> {
    let (n, ld) = (b.npoints, b.ld);
    if n == 0 {
        return None;
    }
    let mut v = Views {
        lm: &mut b.lm[..n],
        tau: rows_mut(b.tau, ld, n, N),
        ddtddg: rows_mut(b.ddtddg, ld, n, N * N),
        ddtddp: rows_mut(b.ddtddp, ld, n, N),
        dslip: b.dslip.as_deref_mut().map(|d| rows_mut(d, ld, n, N)),
        sed: b.sed.as_deref_mut().map(|s| &mut s[..n]),
        sfd: b.sfd.as_deref_mut().map(|s| &mut s[..n]),
        statev: rows_mut(b.statev, ld, n, CoulombState::NSTATV),
        dgam: rows(b.dgam, ld, n, N),
        taulm: b.taulm.map(|t| rows(t, ld, n, N)),
        press: &b.press[..n],
        dpress: &b.dpress[..n],
        chrlngth: &b.chrlngth[..n],
    };
    let mut tally = Tally {
        first: None,
        failed: 0,
        ratio: f64::INFINITY,
    };
    let mut i = 0;
    // Elastic stick: whole chunks through the SIMD-friendly kernel; a chunk it declines (a
    // point not on the common path, LM ≠ 0) and the tail go point by point.
    if let Some(kernel) = ElasticStickKernel::new(law) {
        i = chunks_dispatch::<N>(&kernel, law, dtime, &mut v, &mut tally);
    }
    for j in i..n {
        tally.one::<N>(law, dtime, &mut v, j);
    }
    let Tally {
        first,
        failed,
        mut ratio,
    } = tally;
    if failed > 0 {
        ratio = ratio.min(CUTBACK_RATIO);
    }
    if ratio.is_finite() {
        lower(pnewdt, ratio);
    }
    first.map(|(i, error)| BatchError {
        point: Some(i),
        failed,
        error,
    })
}

/// A function with one parameter list and body, compiled twice (multiversioning): `$baseline`
/// (`#[inline(always)]`) for the baseline target and `$avx2` with AVX2 enabled (the same IEEE
/// operations, so the same bits; wider registers and three-operand instructions), and `$name`,
/// which calls the AVX2 one when the processor has it (and no unit test forces the baseline,
/// `crate::switch`), else the baseline one. The list and the body are written once, in the
/// invocation, which names the three functions it defines (`fn chunks_dispatch, unsafe fn
/// chunks_avx2, fn chunks;`), so that each is found by its name. A macro because the
/// `#[target_feature]` copy must be a function of its own with the same parameter list: written
/// out, the list would be written three times and the call twice; one argument struct shared by
/// the three instead cost 0.3–1.1 % per point (docs/architecture.md).
macro_rules! multiversioned {
    (
        $(#[$doc:meta])*
        fn $name:ident, unsafe fn $avx2:ident, fn $baseline:ident;
        <const N: usize>($($p:ident: $t:ty),* $(,)?) -> $ret:ty $body:block
    ) => {
        $(#[$doc])*
        fn $name<const N: usize>($($p: $t),*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            if !crate::switch::forced(crate::switch::Path::Baseline)
                && std::arch::is_x86_feature_detected!("avx2")
            {
                // SAFETY: the processor supports AVX2 (checked just above).
                return unsafe { $avx2::<N>($($p),*) };
            }
            $baseline::<N>($($p),*)
        }

        // `unsafe fn`: a safe `#[target_feature]` function needs Rust 1.86, above the MSRV.
        /// # Safety
        /// The processor supports AVX2.
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2")]
        unsafe fn $avx2<const N: usize>($($p: $t),*) -> $ret {
            $baseline::<N>($($p),*)
        }

        #[inline(always)]
        fn $baseline<const N: usize>($($p: $t),*) -> $ret $body
    };
}

multiversioned! {
    /// The whole chunks of the batch through the kernel; returns where the tail starts. Chunks
    /// the kernel declines go point by point after the others (each point is independent, and
    /// they keep their order, so the first failure and the reports are those of a loop in
    /// order). Compiled for the baseline (`chunks`) and for AVX2 (`chunks_avx2`).
    fn chunks_dispatch, unsafe fn chunks_avx2, fn chunks;
    <const N: usize>(
        kernel: &ElasticStickKernel,
        law: &Coulomb,
        dtime: f64,
        v: &mut Views<'_>,
        tally: &mut Tally,
    ) -> usize {
        let m = v.lm.len() / LANES;
        let has_taulm = v.taulm.is_some();
        let mut declined = Vec::new();
        match ChunkRows::new::<N>(v, m) {
            Some(mut rows) => {
                for k in 0..m {
                    if !rows.chunk::<N>(kernel, dtime, k, has_taulm) {
                        declined.push(k);
                    }
                }
            }
            // Every row is `npoints` long (`Views`): not taken.
            None => declined.extend(0..m),
        }
        for k in declined {
            for j in k * LANES..(k + 1) * LANES {
                tally.one::<N>(law, dtime, v, j);
            }
        }
        m * LANES
    }
}

/// Points per chunk of the elastic-stick kernel: 8 (two AVX2 registers per quantity) rather
/// than 4, so that the divisions and square roots of one half overlap with the other half's
/// work (NFDIR = 2: 2.0–2.1× → 2.3–2.5× the throughput of `fric_` per point).
const LANES: usize = 8;

/// The running result of a batch: first failure, failure count, smallest step ratio.
struct Tally {
    first: Option<(usize, LawError)>,
    failed: usize,
    ratio: f64,
}

impl Tally {
    /// Point `i` through the per-point path.
    #[inline(always)]
    fn one<const N: usize>(&mut self, law: &Coulomb, dtime: f64, v: &mut Views<'_>, i: usize) {
        match point::<N>(law, dtime, v, i) {
            Ok(r) => self.ratio = self.ratio.min(r),
            Err(e) => {
                self.failed += 1;
                fail_point::<N>(v, i, &e);
                if self.first.is_none() {
                    self.first = Some((i, e));
                }
            }
        }
    }
}

/// The first `m` chunks of `LANES` points of every row of a batch, each row exactly `m` chunks
/// long (so that the loop over chunks needs no bounds check per row); rows past NFDIR empty.
struct ChunkRows<'r> {
    lm: &'r mut [[c_int; LANES]],
    tau: [&'r mut [[f64; LANES]]; 2],
    ddtddg: [&'r mut [[f64; LANES]]; 4],
    ddtddp: [&'r mut [[f64; LANES]]; 2],
    dslip: Option<[&'r mut [[f64; LANES]]; 2]>,
    sed: Option<&'r mut [[f64; LANES]]>,
    sfd: Option<&'r mut [[f64; LANES]]>,
    statev: [&'r mut [[f64; LANES]]; 3],
    dgam: [&'r [[f64; LANES]]; 2],
    press: &'r [[f64; LANES]],
    dpress: &'r [[f64; LANES]],
    chrlngth: &'r [[f64; LANES]],
}

/// The first `m` chunks of `row` as arrays, or `None` when it is shorter: `<[T]>::as_chunks_mut`
/// (Rust 1.88, after this crate's MSRV 1.85). Indexing the arrays by chunk is what lets the
/// compiler drop the per-row bounds checks of the chunk loop (with `row[k·LANES..]` it kept
/// them: 84 against 62 instructions per point, NFDIR 2 stick, bench_batch callgrind).
#[inline(always)]
fn chunked_mut<T>(row: &mut [T], m: usize) -> Option<&mut [[T; LANES]]> {
    let head = row.get_mut(..m.checked_mul(LANES)?)?;
    // SAFETY: `[T; LANES]` is `LANES` consecutive `T` with the alignment of `T` (arrays have no
    // padding), `head` holds exactly `m·LANES` of them, and the result reborrows `head`
    // mutably for its whole life, as `as_chunks_mut` does.
    Some(unsafe { std::slice::from_raw_parts_mut(head.as_mut_ptr().cast::<[T; LANES]>(), m) })
}

/// As [`chunked_mut`], shared (`<[T]>::as_chunks`).
#[inline(always)]
fn chunked<T>(row: &[T], m: usize) -> Option<&[[T; LANES]]> {
    let head = row.get(..m.checked_mul(LANES)?)?;
    // SAFETY: as in `chunked_mut`, shared.
    Some(unsafe { std::slice::from_raw_parts(head.as_ptr().cast::<[T; LANES]>(), m) })
}

/// The first `rows` rows of `from`, chunked; the others empty.
#[inline(always)]
fn chunked_rows<'r, const R: usize>(
    from: &'r mut [&mut [f64]],
    rows: usize,
    m: usize,
) -> Option<[&'r mut [[f64; LANES]]; R]> {
    let mut out: [&mut [[f64; LANES]]; R] = std::array::from_fn(|_| <&mut [_]>::default());
    for (slot, row) in out.iter_mut().zip(from.iter_mut()).take(rows) {
        *slot = chunked_mut(row, m)?;
    }
    Some(out)
}

impl<'r> ChunkRows<'r> {
    #[inline(always)]
    fn new<const N: usize>(v: &'r mut Views<'_>, m: usize) -> Option<Self> {
        let mut dgam: [&[[f64; LANES]]; 2] = [&[], &[]];
        for (slot, row) in dgam.iter_mut().zip(v.dgam).take(N) {
            *slot = chunked(row, m)?;
        }
        Some(ChunkRows {
            lm: chunked_mut(v.lm, m)?,
            tau: chunked_rows(&mut v.tau, N, m)?,
            ddtddg: chunked_rows(&mut v.ddtddg, N * N, m)?,
            ddtddp: chunked_rows(&mut v.ddtddp, N, m)?,
            dslip: match &mut v.dslip {
                Some(d) => Some(chunked_rows(d, N, m)?),
                None => None,
            },
            sed: match &mut v.sed {
                Some(s) => Some(chunked_mut(s, m)?),
                None => None,
            },
            sfd: match &mut v.sfd {
                Some(s) => Some(chunked_mut(s, m)?),
                None => None,
            },
            statev: chunked_rows(&mut v.statev, CoulombState::NSTATV, m)?,
            dgam,
            press: chunked(v.press, m)?,
            dpress: chunked(v.dpress, m)?,
            chrlngth: chunked(v.chrlngth, m)?,
        })
    }

    /// Chunk `k` (points `k·LANES ..`) through the elastic-stick kernel. Returns false, having
    /// written nothing, when a point enters with `LM` other than 0 (or 1 with `TAULM` given,
    /// which elastic stick treats alike) or the kernel declines the chunk.
    #[inline(always)]
    fn chunk<const N: usize>(
        &mut self,
        kernel: &ElasticStickKernel,
        dtime: f64,
        k: usize,
        has_taulm: bool,
    ) -> bool {
        let Some(lm) = self.lm.get_mut(k) else {
            return false;
        };
        let mut motion = true;
        for x in lm.iter() {
            // `|`, `&`: no branch per point.
            motion &= (*x == 0) | ((*x == 1) & has_taulm);
        }
        if !motion {
            return false;
        }
        // Every row is `m` chunks long and k < m: the fallback is never taken.
        let at = |row: &[[f64; LANES]]| row.get(k).copied().unwrap_or([f64::NAN; LANES]);
        let input = ChunkInput::<N, LANES> {
            tau: rows_of(|a| at(self.tau[a])),
            dgam: rows_of(|a| at(self.dgam[a])),
            pressure: at(self.press),
            dpressure: at(self.dpress),
            characteristic_length: at(self.chrlngth),
            accumulated_slip: at(self.statev[0]),
            slip_rate: at(self.statev[1]),
        };
        let Some(out) = kernel.update(&input, dtime) else {
            return false;
        };
        let store = |row: &mut [[f64; LANES]], x: &[f64; LANES]| {
            if let Some(slot) = row.get_mut(k) {
                *slot = *x;
            }
        };
        *lm = [0; LANES];
        for a in 0..N {
            store(self.tau[a], &out.tau[a]);
            store(self.ddtddp[a], &out.ddtddp[a]);
            for c in 0..N {
                // DDTDDG(a,c) in Fortran order per point.
                store(self.ddtddg[a + c * N], &out.ddtddg[a][c]);
            }
        }
        if let Some(d) = &mut self.dslip {
            for (row, x) in d.iter_mut().zip(&out.dslip) {
                store(row, x);
            }
        }
        if let Some(s) = &mut self.sed {
            store(s, &out.sed);
        }
        if let Some(s) = &mut self.sfd {
            store(s, &out.sfd);
        }
        for (r, x) in out.statev.iter().enumerate() {
            store(self.statev[r], x);
        }
        true
    }
}

/// `[f(0), …, f(N − 1)]` as a plain loop (always inlined, unlike `std::array::from_fn`).
#[inline(always)]
fn rows_of<const N: usize>(f: impl Fn(usize) -> [f64; LANES]) -> [[f64; LANES]; N] {
    let mut out = [[0.0; LANES]; N];
    for (a, x) in out.iter_mut().enumerate() {
        *x = f(a);
    }
    out
}

/// One point: reads its inputs, updates it and writes its outputs, as `fric_` does (everything
/// computed before the first write). Returns the law's suggested step ratio.
#[inline(always)]
fn point<const N: usize>(
    law: &Coulomb,
    dtime: f64,
    v: &mut Views<'_>,
    i: usize,
) -> Result<f64, LawError> {
    let entry = match v.lm[i] {
        0 => EntryFlag::Motion,
        1 => EntryFlag::ExactStick,
        2 => return Ok(f64::INFINITY),
        other => return Err(bad_lm(other)),
    };
    let mut inc = Increment::<N> {
        pressure: v.press[i],
        dpressure: v.dpress[i],
        dtime,
        characteristic_length: v.chrlngth[i],
        entry,
        ..Increment::default()
    };
    for a in 0..N {
        inc.tau[a] = v.tau[a][i];
        inc.dgam[a] = v.dgam[a][i];
    }
    if entry == EntryFlag::ExactStick {
        let Some(taulm) = &v.taulm else {
            // Said with its cause: TAULM may be NULL in a batch where no point enters with LM = 1.
            return Err(null_pointer("LM = 1 on entry but TAULM"));
        };
        for (x, row) in inc.taulm.iter_mut().zip(taulm) {
            *x = row[i];
        }
    }
    let sv = [v.statev[0][i], v.statev[1][i], v.statev[2][i]];
    let state = CoulombState::from_statev(&sv)?;
    let up = law.update(&inc, &state)?;
    let mut end_state = [0.0; CoulombState::NSTATV];
    up.state.write_statev(&mut end_state);
    for (r, x) in end_state.iter().enumerate() {
        v.statev[r][i] = *x;
    }
    match up.contact {
        Contact::ExactStick => {
            v.lm[i] = 1;
            if let Some(d) = &mut v.dslip {
                for row in d.iter_mut().take(N) {
                    row[i] = 0.0;
                }
            }
            if let Some(s) = &mut v.sed {
                s[i] = 0.0;
            }
            if let Some(s) = &mut v.sfd {
                s[i] = 0.0;
            }
        }
        Contact::Motion(t) => {
            v.lm[i] = 0;
            for a in 0..N {
                v.tau[a][i] = t.tau[a];
                v.ddtddp[a][i] = t.ddtddp[a];
                for c in 0..N {
                    // DDTDDG(a,c) in Fortran order per point.
                    v.ddtddg[a + c * N][i] = t.ddtddg[a][c];
                }
            }
            if let Some(d) = &mut v.dslip {
                for (row, x) in d.iter_mut().zip(t.dslip) {
                    row[i] = x;
                }
            }
            if let Some(s) = &mut v.sed {
                s[i] = t.sed;
            }
            if let Some(s) = &mut v.sfd {
                s[i] = t.sfd;
            }
        }
    }
    Ok(up.outcome.step_ratio)
}

/// `fric_`'s failure outputs for one point, and the report.
#[cold]
#[inline(never)]
fn fail_point<const N: usize>(v: &mut Views<'_>, i: usize, e: &LawError) {
    for a in 0..N {
        v.ddtddp[a][i] = 0.0;
        for c in 0..N {
            v.ddtddg[a + c * N][i] = 0.0;
        }
    }
    if let Some(d) = &mut v.dslip {
        for row in d.iter_mut().take(N) {
            row[i] = 0.0;
        }
    }
    if let Some(s) = &mut v.sfd {
        s[i] = 0.0;
    }
    let site = Site {
        routine: "ifl_fric_batch",
        interaction: String::new(),
        place: format!("batch point {i}"),
    };
    report(&site, &e.to_string(), true);
}

/// Borrows `len` entries of a C array; NULL is allowed only when `len` is 0 or `optional`.
///
/// # Safety
/// `p` is NULL or points to `len` valid entries, not aliased by another argument.
unsafe fn c_slice<'a, T>(p: *const T, len: usize, name: &str) -> Result<Option<&'a [T]>, LawError> {
    if p.is_null() {
        return if len == 0 {
            Ok(Some(&[]))
        } else {
            Err(LawError::Input(format!("{name} is a NULL pointer")))
        };
    }
    // SAFETY: as documented.
    Ok(Some(unsafe { std::slice::from_raw_parts(p, len) }))
}

/// As [`c_slice`], mutable.
///
/// # Safety
/// As [`c_slice`], and writable.
unsafe fn c_slice_mut<'a, T>(p: *mut T, len: usize, name: &str) -> Result<&'a mut [T], LawError> {
    if p.is_null() {
        return if len == 0 {
            Ok(&mut [])
        } else {
            Err(LawError::Input(format!("{name} is a NULL pointer")))
        };
    }
    // SAFETY: as documented.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, len) })
}

/// Many independent `fric_` points in one call (structure of arrays, leading dimension `ld`).
///
/// Component `a` (0-based) of point `i` is at `x[i + a*ld]`; `DDTDDG(a,b)` of point `i` at
/// `ddtddg[i + (a + b*nfdir)*ld]`; `lm`, `sed`, `sfd`, `press`, `dpress`, `chrlngth` have one
/// entry per point. For speed, pad `ld` a little above a multiple of 512 (rows a power of two
/// bytes apart share cache sets; `docs/benchmarks-batch.md`). `props`/`nprops`, `nstatv` and `dtime` are shared by all points and mean
/// what they mean for `fric_` (`docs/props.md`); `statev` has `nstatv` rows.
///
/// Every point gets bit for bit what `fric_` gives it. A point with unusable input gets
/// `fric_`'s failure outputs, the others are still computed, and the call returns the first
/// failure's status. A fault of the whole batch (`ld < npoints`, `nfdir` not 1 or 2, bad
/// `PROPS`, `nstatv < 3`, a NULL required array) writes nothing but `*pnewdt`. `*pnewdt` is only
/// ever lowered (to 0.25 on any failure). `dslip`, `sed`, `sfd` may be NULL (not written);
/// `taulm` may be NULL when no point enters with `LM = 1`.
///
/// # Safety
/// Every non-NULL array holds at least `ld*(components-1) + npoints` entries (`components` as
/// above: `nfdir`, `nfdir*nfdir`, `nstatv` or 1; none when `npoints` is 0); `props` holds
/// `nprops`; `pnewdt` is NULL or writable; output arrays do not overlap each other or the inputs.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
// Parameters a line per role (sizes; shared by all points; per point, written or updated; per
// point, read; the step ratio), written out for cbindgen; `fric_` has FRIC's own list.
#[rustfmt::skip]
pub unsafe extern "C" fn ifl_fric_batch(
    npoints: usize, ld: usize, nfdir: c_int,
    props: *const f64, nprops: c_int, nstatv: c_int, dtime: f64,
    lm: *mut c_int, tau: *mut f64, ddtddg: *mut f64, ddtddp: *mut f64, dslip: *mut f64,
    sed: *mut f64, sfd: *mut f64, statev: *mut f64,
    dgam: *const f64, taulm: *const f64, press: *const f64, dpress: *const f64,
    chrlngth: *const f64,
    pnewdt: *mut f64,
) -> IflStatus {
    let mut point_fault: Result<(), Fault> = Ok(());
    let whole = boundary(
        || Site {
            routine: "ifl_fric_batch",
            interaction: String::new(),
            place: format!("batch of {npoints} points"),
        },
        || {
            let n = usize::try_from(nfdir)
                .ok()
                .filter(|n| *n == 1 || *n == 2)
                .ok_or_else(|| {
                    LawError::Parameter(format!("NFDIR = {nfdir}; expected 1 (2-D) or 2 (3-D)"))
                })?;
            let nstatv = count("NSTATV", nstatv)?;
            require_rows(nstatv)?;
            if ld < npoints {
                return Err(LawError::Parameter(format!(
                    "leading dimension ld = {ld} is less than npoints = {npoints}"
                )));
            }
            let nprops = count("NPROPS", nprops)?;
            let len = |components: usize| -> Result<usize, LawError> {
                if npoints == 0 {
                    return Ok(0);
                }
                ld.checked_mul(components - 1)
                    .and_then(|x| x.checked_add(npoints))
                    .ok_or_else(|| LawError::Parameter("ld × components overflows".into()))
            };
            let (l1, ln, lnn, ls) = (len(1)?, len(n)?, len(n * n)?, len(nstatv)?);
            // SAFETY: sizes per the contract above; NULL handled by the helpers.
            let mut batch = unsafe {
                FricBatch {
                    npoints,
                    ld,
                    nfdir: n,
                    nstatv,
                    lm: c_slice_mut(lm, l1, "lm")?,
                    tau: c_slice_mut(tau, ln, "tau")?,
                    ddtddg: c_slice_mut(ddtddg, lnn, "ddtddg")?,
                    ddtddp: c_slice_mut(ddtddp, ln, "ddtddp")?,
                    dslip: optional_mut(dslip, ln),
                    sed: optional_mut(sed, l1),
                    sfd: optional_mut(sfd, l1),
                    statev: c_slice_mut(statev, ls, "statev")?,
                    dgam: c_slice(dgam, ln, "dgam")?.unwrap_or(&[]),
                    taulm: if taulm.is_null() {
                        None
                    } else {
                        c_slice(taulm, ln, "taulm")?
                    },
                    press: c_slice(press, l1, "press")?.unwrap_or(&[]),
                    dpress: c_slice(dpress, l1, "dpress")?.unwrap_or(&[]),
                    chrlngth: c_slice(chrlngth, l1, "chrlngth")?.unwrap_or(&[]),
                }
            };
            // SAFETY: props holds nprops entries per the contract.
            let props = unsafe { c_slice(props, nprops, "props")? }.unwrap_or(&[]);
            let mut ratio = f64::INFINITY;
            let r = fric_batch(props, dtime, &mut batch, &mut ratio);
            if ratio < f64::INFINITY && !pnewdt.is_null() {
                // SAFETY: writable per the contract.
                unsafe {
                    let current = pnewdt.read();
                    if current.is_nan() || ratio < current {
                        pnewdt.write(ratio);
                    }
                }
            }
            match r {
                Ok(()) => Ok(()),
                // A whole-batch fault: let the boundary report it once.
                Err(BatchError {
                    point: None, error, ..
                }) => Err(error),
                // Point faults were reported point by point.
                Err(BatchError { error, .. }) => {
                    point_fault = Err(match error {
                        LawError::Parameter(_) => Fault::Parameter,
                        LawError::Config(_) => Fault::Config,
                        LawError::Input(_) => Fault::Input,
                        LawError::Numerical(_) => Fault::Numerical,
                    });
                    Ok(())
                }
            }
        },
        // SAFETY: NULL or writable per the contract.
        || unsafe { cut_back(pnewdt) },
    );
    whole.and(point_fault).into()
}

/// An optional output: NULL → `None`.
///
/// # Safety
/// `p` is NULL or points to `len` writable entries.
unsafe fn optional_mut<'a>(p: *mut f64, len: usize) -> Option<&'a mut [f64]> {
    if p.is_null() {
        None
    } else {
        // SAFETY: as documented.
        Some(unsafe { std::slice::from_raw_parts_mut(p, len) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::switch::{Path, force};
    use crate::testing::XorShift;

    /// The baseline (SSE2) and AVX2 builds of the chunk loop give the same bits; the
    /// integration tests compare the build the processor selects with `fric_` per point.
    #[test]
    fn baseline_and_avx2_chunks_agree() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
        let mut next = move || rng.unit() * 2.0 - 1.0;
        for nfdir in [1usize, 2] {
            let n = 103;
            let random = |k: usize, s: f64, next: &mut dyn FnMut() -> f64| -> Vec<f64> {
                (0..k * n).map(|_| s * next()).collect()
            };
            let dgam = random(nfdir, 4e-3, &mut next);
            let press = random(1, 60.0, &mut next);
            let dpress = random(1, 5.0, &mut next);
            let chrlngth: Vec<f64> = random(1, 1.0, &mut next).iter().map(|x| 1.5 + x).collect();
            let tau0 = random(nfdir, 5.0, &mut next);
            let statev0: Vec<f64> = random(3, 1.0, &mut next).iter().map(|x| x.abs()).collect();
            let props = [1.0, 0.3, 0.0, 12.0, 0.0, 0.002, 0.0];
            let mut results = Vec::new();
            for baseline in [true, false] {
                force(Path::Baseline, baseline);
                let mut lm = vec![0; n];
                let mut tau = tau0.clone();
                let mut statev = statev0.clone();
                let mut ddtddg = vec![0.0; nfdir * nfdir * n];
                let mut ddtddp = vec![0.0; nfdir * n];
                let mut dslip = vec![0.0; nfdir * n];
                let mut sed = vec![0.0; n];
                let mut sfd = vec![0.0; n];
                let mut pnewdt = 1.0;
                let mut b = FricBatch {
                    npoints: n,
                    ld: n,
                    nfdir,
                    nstatv: 3,
                    lm: &mut lm,
                    tau: &mut tau,
                    ddtddg: &mut ddtddg,
                    ddtddp: &mut ddtddp,
                    dslip: Some(&mut dslip),
                    sed: Some(&mut sed),
                    sfd: Some(&mut sfd),
                    statev: &mut statev,
                    dgam: &dgam,
                    taulm: None,
                    press: &press,
                    dpress: &dpress,
                    chrlngth: &chrlngth,
                };
                assert!(fric_batch(&props, 0.1, &mut b, &mut pnewdt).is_ok());
                let all: Vec<u64> = [tau, statev, ddtddg, ddtddp, dslip, sed, sfd]
                    .iter()
                    .flatten()
                    .map(|x| x.to_bits())
                    .collect();
                results.push(all);
            }
            force(Path::Baseline, false);
            assert_eq!(results[0], results[1], "NFDIR {nfdir}");
        }
    }
}
