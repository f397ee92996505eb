//! Coulomb friction with elastic stick (seed 000, section 5.2.3) for `W` independent points at
//! once: the kernel of the batch entry point `ifl_fric_batch`.
//!
//! Same formulas, in the same order, as [`Coulomb::update`] with [`StickMode::Elastic`]
//! (`src/laws/coulomb.rs`), written lane by lane without branches: both the stick and the slip
//! answer are computed and one is selected per lane, so that the compiler can run the lanes in
//! SIMD registers. Every operation is an IEEE add, subtract, multiply, divide or square root
//! (correctly rounded, and Rust never contracts `a*b + c` into a fused multiply-add), so each
//! lane's result is bit for bit the scalar one.
//!
//! The kernel only answers when every lane takes the common path of the scalar law: finite
//! inputs and state, a usable γ_crit, norms whose squares are normal numbers (or exact zeros),
//! finite outputs. Otherwise it answers `None` and the caller runs the chunk through
//! [`Coulomb::update`] point by point, which gives the rare cases (the scaled norm of extreme
//! vectors, the named error messages) exactly as before.

use super::coulomb::{Coulomb, CriticalSlip, HEADROOM, StickMode};

/// Inputs of `W` points (`[..][l]` is lane `l`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChunkInput<const N: usize, const W: usize> {
    /// Frictional stress at the start of the increment, component `a` in `tau[a]`.
    pub tau: [[f64; W]; N],
    /// Relative tangential motion increment Δγ.
    pub dgam: [[f64; W]; N],
    /// Contact pressure at the end of the increment.
    pub pressure: [f64; W],
    /// Pressure increment.
    pub dpressure: [f64; W],
    /// Characteristic contact length (`CHRLNGTH`).
    pub characteristic_length: [f64; W],
    /// `STATEV(1)`: accumulated slip at the start.
    pub accumulated_slip: [f64; W],
    /// `STATEV(2)`: slip rate of the previous increment (only checked for finiteness).
    pub slip_rate: [f64; W],
}

/// Outputs of `W` points, as [`super::contact::Traction`] and the end state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChunkOutput<const N: usize, const W: usize> {
    /// Frictional stress at the end of the increment.
    pub tau: [[f64; W]; N],
    /// `ddtddg[a][b]` = ∂τ_a/∂Δγ_b.
    pub ddtddg: [[[f64; W]; N]; N],
    /// ∂τ_a/∂p.
    pub ddtddp: [[f64; W]; N],
    /// Inelastic slip increment Δγ^sl.
    pub dslip: [[f64; W]; N],
    /// Elastic energy density.
    pub sed: [f64; W],
    /// Frictional dissipation of the increment.
    pub sfd: [f64; W],
    /// `STATEV(1..3)` at the end: accumulated slip, slip rate, status (0 stick, 1 slip).
    pub statev: [[f64; W]; 3],
}

/// The parameters of a Coulomb law with elastic stick, read once for a whole batch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticStickKernel {
    mu: f64,
    /// `f64::INFINITY` without a shear limit, as in [`Coulomb`].
    tau_max: f64,
    /// γ_crit when it is absolute (`Some`), else the tolerance times `CHRLNGTH`.
    absolute: Option<f64>,
    tolerance: f64,
}

impl ElasticStickKernel {
    /// The kernel of `law`, or `None` when its stick is not elastic (exact stick and rough
    /// friction stay on the per-point path).
    #[must_use]
    pub fn new(law: &Coulomb) -> Option<Self> {
        if law.stick() != StickMode::Elastic {
            return None;
        }
        let (absolute, tolerance) = match law.critical_slip() {
            CriticalSlip::Absolute(g) => (Some(g), 0.0),
            CriticalSlip::Tolerance(t) => (None, t),
            // A constant stick stiffness stays on the per-point path.
            CriticalSlip::Stiffness(_) => return None,
        };
        Some(ElasticStickKernel {
            mu: law.mu(),
            tau_max: law.shear_limit().unwrap_or(f64::INFINITY),
            absolute,
            tolerance,
        })
    }

    /// τ_crit = min(μp, τ_max) and ∂τ_crit/∂p, 0 for p < 0, lane by lane:
    /// [`Coulomb::critical_stress`] with selects instead of branches (the same product μp; the
    /// same comparisons, as `0 ≤ p` for `!(p < 0)`, equal for every p but NaN, which the probes
    /// send to the scalar path anyway).
    #[inline(always)]
    fn critical_stress<const W: usize>(&self, p: [f64; W]) -> ([f64; W], [f64; W]) {
        let mu_p = p.map(|p| self.mu * p);
        let capped = Le([self.tau_max; W], mu_p);
        let closed = Le([0.0; W], p);
        let tau_crit = select(closed, select(capped, [self.tau_max; W], mu_p), [0.0; W]);
        let slope = select(closed, select(capped, [0.0; W], [self.mu; W]), [0.0; W]);
        (tau_crit, slope)
    }

    /// One increment of `W` points with time increment `dtime` (backward Euler, elastic stick),
    /// or `None` when any lane leaves the common path (see the module documentation); then
    /// nothing has been written anywhere and the caller uses [`Coulomb::update`] per point.
    ///
    /// Every line is one operation on all `W` lanes (`[f64; W]` arrays), the shape the
    /// compiler's SLP vectoriser turns into SIMD instructions.
    ///
    /// A chunk whose lanes all stick by the test on the squares (the common case of a closed,
    /// sticking contact) skips the slip branch's square roots and divisions: the same code with
    /// the stick mask known to be all set, so its answer is the same bit for bit.
    #[inline(always)]
    #[must_use]
    pub fn update<const N: usize, const W: usize>(
        &self,
        inc: &ChunkInput<N, W>,
        dtime: f64,
    ) -> Option<ChunkOutput<N, W>> {
        let gamma_crit = self.gamma_crit(inc);
        let predictor = self.predictor(inc, &gamma_crit);
        if all_stick_on_squares(&predictor, &gamma_crit) {
            self.update_lanes::<N, W, true>(inc, dtime, &gamma_crit, &predictor)
        } else {
            self.update_lanes::<N, W, false>(inc, dtime, &gamma_crit, &predictor)
        }
    }

    /// γ_crit lane by lane: absolute, or tolerance × CHRLNGTH (a bad CHRLNGTH is refused by
    /// [`Self::update_lanes`]'s probe).
    #[inline(always)]
    fn gamma_crit<const N: usize, const W: usize>(&self, inc: &ChunkInput<N, W>) -> [f64; W] {
        match self.absolute {
            Some(g) => [g; W],
            None => inc.characteristic_length.map(|c| self.tolerance * c),
        }
    }

    /// Elastic predictor γ^pr = γ̄^el + Δγ with γ̄^el = τ̄·(γ_crit/τ_crit(p − Δp)), 0 without
    /// friction at the start.
    #[inline(always)]
    fn predictor<const N: usize, const W: usize>(
        &self,
        inc: &ChunkInput<N, W>,
        gamma_crit: &[f64; W],
    ) -> [[f64; W]; N] {
        let (tau_crit_start, _) =
            self.critical_stress(map2(inc.pressure, inc.dpressure, |p, dp| p - dp));
        let start_factor = map2(*gamma_crit, tau_crit_start, |g, t| g / t);
        per_row(|a| {
            let elastic = map3(inc.tau[a], start_factor, tau_crit_start, |t, f, c| {
                if c > 0.0 { t * f } else { 0.0 }
            });
            map2(elastic, inc.dgam[a], |e, g| e + g)
        })
    }

    /// [`Self::update`] from γ_crit and the predictor; with `STICK_ONLY` every lane is known
    /// to stick.
    #[inline(always)]
    fn update_lanes<const N: usize, const W: usize, const STICK_ONLY: bool>(
        &self,
        inc: &ChunkInput<N, W>,
        dtime: f64,
        gamma_crit: &[f64; W],
        predictor: &[[f64; W]; N],
    ) -> Option<ChunkOutput<N, W>> {
        let (gamma_crit, predictor) = (*gamma_crit, *predictor);
        let p = inc.pressure;
        let dp = inc.dpressure;
        // x·0 is ±0 for finite x and NaN otherwise: the sum over every input of every lane is 0
        // exactly when the scalar path's probes (check_increment, from_statev) all pass.
        let mut probe = map2(p, dp, |p, dp| p * 0.0 + dp * 0.0);
        probe = map3(probe, inc.accumulated_slip, inc.slip_rate, |q, s, r| {
            q + (s * 0.0 + r * 0.0)
        });
        for a in 0..N {
            probe = map3(probe, inc.tau[a], inc.dgam[a], |q, t, g| {
                q + (t * 0.0 + g * 0.0)
            });
        }
        // γ_crit: absolute, or tolerance × CHRLNGTH for 0 < CHRLNGTH < ∞ (else the scalar
        // path names the bad CHRLNGTH).
        if self.absolute.is_none() {
            probe = map2(probe, inc.characteristic_length, |q, c| {
                q + if c > 0.0 && c < f64::INFINITY {
                    0.0
                } else {
                    f64::NAN
                }
            });
        }
        let (predictor_sq, predictor_eq) = norm_common(&predictor, &mut probe);
        let (tau_crit, dtau_crit_dp) = self.critical_stress(p);
        let stiffness = map2(tau_crit, gamma_crit, |t, g| t / g);
        // Stick where γ_eq^pr ≤ γ_crit, decided as the scalar law decides it
        // (`small_vec::length_beyond`): for N = 2 on the squares when γ_crit² is a normal
        // number, else or when they say no on the norm. As a mask `key ≤ 0` (the comparison is
        // repeated in each select, a SIMD mask); all set when `STICK_ONLY`, so that the
        // compiler drops the slip branch's work.
        let stick_key: [f64; W] = if STICK_ONLY {
            [0.0; W]
        } else {
            let by_norm = select(Le(predictor_eq, gamma_crit), [0.0; W], [1.0; W]);
            if N > 1 {
                let g2 = map2(gamma_crit, gamma_crit, |g, h| g * h);
                select(
                    Le(predictor_sq, g2),
                    where_normal(g2, [0.0; W], by_norm),
                    by_norm,
                )
            } else {
                by_norm
            }
        };
        let state = Lanes {
            accumulated_slip: inc.accumulated_slip,
            gamma_crit,
            predictor,
            predictor_eq,
            tau_crit,
            dtau_crit_dp,
            stiffness,
            probe,
        };
        // A chunk whose lanes all slip (key 1 everywhere) runs the same code with the stick
        // mask known to be empty, so that the compiler drops the stick branch's work and the
        // selects: the same bits, as for `STICK_ONLY`.
        if !STICK_ONLY && all_zero(stick_key.map(|k| k - 1.0)) {
            state.answer(Le([1.0; W], [0.0; W]), dtime)
        } else {
            state.answer(Le(stick_key, [0.0; W]), dtime)
        }
    }
}

/// What [`ElasticStickKernel::update`] has for `W` lanes once γ_crit, the predictor and its
/// norm, τ_crit and the input probe are formed.
struct Lanes<const N: usize, const W: usize> {
    accumulated_slip: [f64; W],
    gamma_crit: [f64; W],
    predictor: [[f64; W]; N],
    predictor_eq: [f64; W],
    tau_crit: [f64; W],
    dtau_crit_dp: [f64; W],
    stiffness: [f64; W],
    probe: [f64; W],
}

impl<const N: usize, const W: usize> Lanes<N, W> {
    /// The return map's answer with the lanes of `stick` sticking and the others slipping, or
    /// `None` when a lane leaves the common path.
    #[inline(always)]
    fn answer(&self, stick: Le<W>, dtime: f64) -> Option<ChunkOutput<N, W>> {
        let stick_tau: [[f64; W]; N] =
            per_row(|a| map2(self.predictor[a], self.stiffness, |x, k| x * k));

        // Slip (Eq. 5.2.3-2): n = γ^pr/γ_eq^pr, Δγ_eq^sl = γ_eq^pr − γ_crit.
        let n: [[f64; W]; N] =
            per_row(|a| map2(self.predictor[a], self.predictor_eq, |x, e| x / e));
        let slip_eq = map2(self.predictor_eq, self.gamma_crit, |e, g| e - g);
        let transverse = map2(self.tau_crit, self.predictor_eq, |t, e| t / e);
        let stick_dp = map2(self.dtau_crit_dp, self.gamma_crit, |d, g| d / g);
        let mut out = ChunkOutput {
            tau: [[0.0; W]; N],
            ddtddg: [[[0.0; W]; N]; N],
            ddtddp: [[0.0; W]; N],
            dslip: [[0.0; W]; N],
            sed: [0.0; W],
            sfd: [0.0; W],
            statev: [[0.0; W]; 3],
        };
        for a in 0..N {
            // Stick: τ = k_s γ^pr (Eq. 5.2.3-1; a subnormal k_s declined the chunk below);
            // slip: τ = n τ_crit (Eq. 5.2.3-2).
            out.tau[a] = select(stick, stick_tau[a], map2(n[a], self.tau_crit, |x, t| x * t));
            // Stick: γ^pr (∂τ_crit/∂p)/γ_crit (Eq. 5.2.3-1); slip: n ∂τ_crit/∂p (Eq. 5.2.3-3).
            out.ddtddp[a] = select(
                stick,
                map2(self.predictor[a], stick_dp, |x, d| x * d),
                map2(n[a], self.dtau_crit_dp, |x, d| x * d),
            );
            out.dslip[a] = select(stick, [0.0; W], map2(n[a], slip_eq, |x, s| x * s));
            for b in 0..N {
                let delta = if a == b { 1.0 } else { 0.0 };
                // Stick: k_s δ_ab (Eq. 5.2.3-1). Slip: (δ_ab − n_a n_b) τ_crit/γ_eq^pr
                // (Eq. 5.2.3-3), exactly 0 in 2-D (N = 1).
                let slip_tangent = if N == 1 {
                    [0.0; W]
                } else {
                    map3(transverse, n[a], n[b], |t, x, y| t * (delta - x * y))
                };
                let stick_tangent = if a == b { self.stiffness } else { [0.0; W] };
                out.ddtddg[a][b] = select(stick, stick_tangent, slip_tangent);
            }
        }
        // Stick: k_s|γ^pr|²/2 as τ·γ^pr/2 (the scalar `dot`, from 0.0 in the same order);
        // slip: |τ|²/(2k_s) with |τ| = τ_crit. Dissipation τ_crit Δγ_eq^sl.
        let mut stick_work = [0.0; W];
        for (tau, x) in stick_tau.iter().zip(&self.predictor) {
            stick_work = map3(stick_work, *tau, *x, |w, t, x| w + t * x);
        }
        out.sed = select(
            stick,
            stick_work.map(|w| 0.5 * w),
            map2(self.tau_crit, self.gamma_crit, |t, g| 0.5 * t * g),
        );
        out.sfd = select(stick, [0.0; W], map2(self.tau_crit, slip_eq, |t, s| t * s));

        // The scalar law's careful test of its results (`Coulomb::elastic_stick_checked`): the
        // few scalars that bound every result, the same values lane by lane, so the kernel
        // answers exactly when the scalar law does (its one-pass tier answers a subset, with
        // the same bits).
        // A subnormal k_s declines the chunk: the scalar law then forms the stick stress
        // differently (`Coulomb::update`).
        let subnormal = select(
            Le(self.stiffness, [0.0; W]),
            [0.0; W],
            select(
                Le([f64::MIN_POSITIVE; W], self.stiffness),
                [0.0; W],
                [f64::NAN; W],
            ),
        );
        let common: [f64; W] = lanes(|l| {
            (self.gamma_crit[l] * 0.0 + (self.tau_crit[l] * HEADROOM) * 0.0)
                + ((self.stiffness[l] * HEADROOM) * 0.0 + (self.dtau_crit_dp[l] * HEADROOM) * 0.0)
                + subnormal[l]
        });
        let branch = select(
            stick,
            map2(stick_dp, out.sed, |q, e| q * 0.0 + e * 0.0),
            map3(slip_eq, out.sed, out.sfd, |s, e, f| {
                (s * HEADROOM) * 0.0 + (e * 0.0 + f * 0.0)
            }),
        );
        let probe_out = map2(common, branch, |c, b| c + b);
        // End state from the return map's slip Δγ_eq^sl (0 in stick), as the scalar path:
        // accumulated slip and slip rate, both saturating at f64::MAX.
        let slip = select(stick, [0.0; W], slip_eq);
        out.statev[0] = map2(self.accumulated_slip, slip, |s, d| saturate(s + d));
        out.statev[1] = slip.map(|d| {
            if dtime > 0.0 {
                saturate(d / dtime)
            } else {
                0.0
            }
        });
        out.statev[2] = slip.map(|d| if d > 0.0 { 1.0 } else { 0.0 });

        // Every probe term is ±0 or NaN, so their sum is 0 exactly when no term is NaN, in any
        // order: lane by lane (a SIMD compare and one mask test) rather than one running sum.
        let terms = map2(self.probe, probe_out, |q, r| q + r);
        (dtime * 0.0 == 0.0 && all_zero(terms)).then_some(out)
    }
}

/// Every lane sticks by the first test of `small_vec::length_beyond`: v·v ≤ γ_crit² with
/// γ_crit² normal (N = 2), |v| ≤ γ_crit (N = 1). v·v summed as [`norm_common`] sums it.
#[inline(always)]
fn all_stick_on_squares<const N: usize, const W: usize>(
    predictor: &[[f64; W]; N],
    gamma_crit: &[f64; W],
) -> bool {
    // 0 where the lane sticks, 1 elsewhere.
    let key = if N == 1 {
        select(
            Le(predictor[0].map(f64::abs), *gamma_crit),
            [0.0; W],
            [1.0; W],
        )
    } else {
        let mut s = predictor[0].map(|x| x * x);
        for row in &predictor[1..] {
            s = map2(s, *row, |s, x| s + x * x);
        }
        let g2 = map2(*gamma_crit, *gamma_crit, |g, h| g * h);
        select(Le(s, g2), where_normal(g2, [0.0; W], [1.0; W]), [1.0; W])
    };
    all_zero(key)
}

/// `a` where γ_crit² = `g2` is a normal number (`MIN_POSITIVE ≤ g2 < ∞`, where the test on the
/// squares stands), `b` elsewhere; as selects, so that the lanes compare as SIMD masks.
#[inline(always)]
fn where_normal<const W: usize>(g2: [f64; W], a: [f64; W], b: [f64; W]) -> [f64; W] {
    select(
        Le([f64::MIN_POSITIVE; W], g2),
        select(Le([f64::INFINITY; W], g2), b, a),
        b,
    )
}

/// Every lane is ±0 (no NaN, no other number): the bits but the sign bit, OR-ed over the lanes
/// (an integer reduction, which the compiler vectorises; a sum or an `&&` of comparisons it
/// runs lane by lane).
#[inline(always)]
fn all_zero<const W: usize>(x: [f64; W]) -> bool {
    let mut bits = 0u64;
    for v in x {
        bits |= v.to_bits() << 1;
    }
    bits == 0
}

/// `[f(0), …, f(W − 1)]`, as a plain loop over a zeroed array: unlike `std::array::from_fn`
/// (not always inlined into the AVX2 build of the chunk loop, where its call ran SSE2 code),
/// always inlined, so the SLP vectoriser sees every lane.
#[inline(always)]
fn lanes<const W: usize>(f: impl Fn(usize) -> f64) -> [f64; W] {
    let mut out = [0.0; W];
    for (l, x) in out.iter_mut().enumerate() {
        *x = f(l);
    }
    out
}

/// `[f(0), …, f(N − 1)]` for rows of `W` lanes, as [`lanes`].
#[inline(always)]
fn per_row<const N: usize, const W: usize>(f: impl Fn(usize) -> [f64; W]) -> [[f64; W]; N] {
    let mut out = [[0.0; W]; N];
    for (a, x) in out.iter_mut().enumerate() {
        *x = f(a);
    }
    out
}

/// Lane by lane `f(a, b)`.
#[inline(always)]
fn map2<const W: usize>(a: [f64; W], b: [f64; W], f: impl Fn(f64, f64) -> f64) -> [f64; W] {
    lanes(|l| f(a[l], b[l]))
}

/// Lane by lane `f(a, b, c)`.
#[inline(always)]
fn map3<const W: usize>(
    a: [f64; W],
    b: [f64; W],
    c: [f64; W],
    f: impl Fn(f64, f64, f64) -> f64,
) -> [f64; W] {
    lanes(|l| f(a[l], b[l], c[l]))
}

/// The lanes where `x ≤ y`.
#[derive(Clone, Copy)]
struct Le<const W: usize>([f64; W], [f64; W]);

/// Lane by lane `if x ≤ y { a } else { b }`.
#[inline(always)]
fn select<const W: usize>(m: Le<W>, a: [f64; W], b: [f64; W]) -> [f64; W] {
    lanes(|l| if m.0[l] <= m.1[l] { a[l] } else { b[l] })
}

/// The sum of squares v·v (for N = 2 the scalar `dot(v, v)`, which the stick test uses) and the
/// Euclidean norm of each lane when the scalar `norm` (`small_vec.rs`) takes its direct path:
/// |v₁| for N = 1; for N = 2 √(v·v) when v·v is a normal number, which √ of the same sum
/// reproduces, or 0 for the zero vector (√0 = 0). Otherwise (v·v overflowed, underflowed or is
/// NaN) the scalar path scales the vector: such a lane adds NaN to `probe`.
#[inline(always)]
fn norm_common<const N: usize, const W: usize>(
    v: &[[f64; W]; N],
    probe: &mut [f64; W],
) -> ([f64; W], [f64; W]) {
    if N == 1 {
        return (v[0].map(|x| x * x), v[0].map(f64::abs));
    }
    // The scalar dot product starts from 0.0; 0.0 + x = x bit for bit here since x = v₀² is
    // never −0.
    let mut s = v[0].map(|x| x * x);
    // Σ|v_a| is 0 exactly for the zero vector (a sum of non-negative numbers rounds to 0 only
    // when they all are 0).
    let mut length1 = v[0].map(f64::abs);
    for row in &v[1..] {
        s = map2(s, *row, |s, x| s + x * x);
        length1 = map2(length1, *row, |m, x| m + x.abs());
    }
    // NaN unless MIN_POSITIVE ≤ v·v < ∞ or v = 0; written as selects (SIMD masks).
    // s·0 is NaN for s = ∞ or NaN.
    let in_range = select(
        Le([f64::MIN_POSITIVE; W], s),
        s.map(|s| s * 0.0),
        [f64::NAN; W],
    );
    let flag = select(Le(length1, [0.0; W]), [0.0; W], in_range);
    *probe = map2(*probe, flag, |q, f| q + f);
    (s, s.map(f64::sqrt))
}

/// `x` capped at f64::MAX, as the scalar path stores the state.
#[inline(always)]
fn saturate(x: f64) -> f64 {
    if x > f64::MAX { f64::MAX } else { x }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laws::contact::{Contact, Increment};
    use crate::laws::coulomb::{CoulombState, FrictionStatus};
    use crate::testing::XorShift;

    const W: usize = 8;

    /// A chunk of `W` lanes whose predictor |γ^pr| is `ratio(l)` × γ_crit (γ_crit = 10⁻³
    /// absolute, or 1 % of CHRLNGTH = 0.1), at pressures 1 … 100 (every lane's τ_crit > 0;
    /// μp above `tau_max` is capped).
    fn chunk<const N: usize>(
        rng: &mut XorShift,
        tau_max: f64,
        ratio: impl Fn(usize, f64) -> f64,
    ) -> ChunkInput<N, W> {
        let mut inc = ChunkInput::<N, W> {
            tau: [[0.0; W]; N],
            dgam: [[0.0; W]; N],
            pressure: [0.0; W],
            dpressure: [0.0; W],
            characteristic_length: [0.1; W],
            accumulated_slip: [0.0; W],
            slip_rate: [0.0; W],
        };
        // γ_crit: 10⁻³ absolute, or 1 % of CHRLNGTH = 0.1, the same number.
        let gc = 1e-3;
        for l in 0..W {
            let (p, dp) = (1.0 + 99.0 * rng.unit(), 0.5 * rng.unit() - 0.25);
            inc.pressure[l] = p;
            inc.dpressure[l] = dp;
            inc.accumulated_slip[l] = rng.unit();
            inc.slip_rate[l] = rng.unit();
            // γ^pr = γ̄^el + Δγ with |γ^pr| = ratio·γ_crit: Δγ from a chosen start stress.
            let k_start = (0.3 * (p - dp)).min(tau_max) / gc;
            let angle = std::f64::consts::TAU * rng.unit();
            let r = ratio(l, rng.unit());
            for a in 0..N {
                let dir = match (N, a) {
                    (1, _) => angle.cos().signum(),
                    (_, 0) => angle.cos(),
                    _ => angle.sin(),
                };
                let elastic = (0.6 * rng.unit() - 0.3) * gc;
                inc.tau[a][l] = k_start * elastic;
                inc.dgam[a][l] = r * gc * dir - elastic;
            }
        }
        inc
    }

    /// Every lane of the kernel's answer against `Coulomb::update`, bit for bit; returns how
    /// many lanes slipped.
    fn agree<const N: usize>(law: &Coulomb, inc: &ChunkInput<N, W>) -> usize {
        let dtime = 0.1;
        let kernel = ElasticStickKernel::new(law).expect("elastic stick");
        let out = kernel
            .update(inc, dtime)
            .expect("ordinary lanes stay on the kernel");
        let mut slipped = 0;
        for l in 0..W {
            let mut one = Increment::<N> {
                pressure: inc.pressure[l],
                dpressure: inc.dpressure[l],
                dtime,
                characteristic_length: inc.characteristic_length[l],
                ..Increment::default()
            };
            for a in 0..N {
                one.tau[a] = inc.tau[a][l];
                one.dgam[a] = inc.dgam[a][l];
            }
            let state =
                CoulombState::from_statev(&[inc.accumulated_slip[l], inc.slip_rate[l], 0.0])
                    .expect("state");
            let up = law.update(&one, &state).expect("scalar law");
            let Contact::Motion(t) = up.contact else {
                panic!("lane {l}: exact stick from elastic stick");
            };
            let bits = |x: f64| x.to_bits();
            for a in 0..N {
                assert_eq!(bits(out.tau[a][l]), bits(t.tau[a]), "tau lane {l}");
                assert_eq!(bits(out.ddtddp[a][l]), bits(t.ddtddp[a]), "ddtddp lane {l}");
                assert_eq!(bits(out.dslip[a][l]), bits(t.dslip[a]), "dslip lane {l}");
                for b in 0..N {
                    assert_eq!(bits(out.ddtddg[a][b][l]), bits(t.ddtddg[a][b]), "lane {l}");
                }
            }
            assert_eq!(bits(out.sed[l]), bits(t.sed), "sed lane {l}");
            assert_eq!(bits(out.sfd[l]), bits(t.sfd), "sfd lane {l}");
            let mut sv = [0.0; 3];
            up.state.write_statev(&mut sv);
            for (r, x) in sv.iter().enumerate() {
                assert_eq!(bits(out.statev[r][l]), bits(*x), "statev {r} lane {l}");
            }
            slipped += usize::from(up.state.status == FrictionStatus::Slip);
        }
        slipped
    }

    /// Chunks whose lanes all stick, all slip (the routes that drop one branch) or mix (the
    /// selects) give `Coulomb::update`'s bits, NFDIR 1 and 2, γ_crit absolute or relative,
    /// with and without τ_max.
    #[test]
    fn whole_stick_whole_slip_and_mixed_chunks_agree_with_the_scalar_law() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
        for absolute in [true, false] {
            for tau_max in [None, Some(15.0)] {
                let mut law = Coulomb::new(0.3).expect("mu");
                law = if absolute {
                    law.with_critical_slip_absolute(1e-3).expect("gamma_crit")
                } else {
                    law.with_slip_tolerance(0.01).expect("tolerance")
                };
                if let Some(t) = tau_max {
                    law = law.with_shear_limit(t).expect("tau_max");
                }
                let cap = tau_max.unwrap_or(f64::INFINITY);
                for _ in 0..50 {
                    let stick = |_: usize, u: f64| 0.05 + 0.85 * u;
                    let slip = |_: usize, u: f64| 1.1 + 3.9 * u;
                    let mixed = |l: usize, u: f64| if l % 3 == 0 { 0.5 * u } else { 1.1 + u };
                    assert_eq!(agree::<1>(&law, &chunk(&mut rng, cap, stick)), 0);
                    assert_eq!(agree::<2>(&law, &chunk(&mut rng, cap, stick)), 0);
                    assert_eq!(agree::<1>(&law, &chunk(&mut rng, cap, slip)), W);
                    assert_eq!(agree::<2>(&law, &chunk(&mut rng, cap, slip)), W);
                    assert_eq!(agree::<1>(&law, &chunk(&mut rng, cap, mixed)), 5);
                    assert_eq!(agree::<2>(&law, &chunk(&mut rng, cap, mixed)), 5);
                }
            }
        }
    }
}
