//! The exponential-decay law's fast return map (seed 000, section 5.2.3, with
//! μ = μ_k + (μ_s − μ_k)·exp(−d_c·γ̇_eq)): the lean isotropic elastic-stick path that
//! [`super::ExtendedCoulomb::update`] takes first when it applies, and the local solve of the
//! return map in the end-of-increment slip rate (a safeguarded Halley iteration).

#![allow(clippy::needless_range_loop)] // index loops mirror the i, j of the seed's equations

use super::*;

impl ExtendedCoulomb {
    /// (r, d_c) when [`Self::update`] can take [`Self::isotropic_decay`]: the decay law with
    /// isotropic friction (or NFDIR = 1), elastic stick, no damping, no steady transport.
    #[inline(always)]
    pub(crate) fn lean_decay<const N: usize>(&self) -> Option<(f64, f64)> {
        match self.coefficient.rate() {
            RateLaw::ExponentialDecay {
                kinetic_ratio,
                decay,
            } if !self.general
                && self.damping.is_none()
                && self.transport.is_none()
                && self.base.stick() == StickMode::Elastic
                && (N == 1 || self.mu2 == self.base.mu()) =>
            {
                Some((kinetic_ratio, decay))
            }
            _ => None,
        }
    }

    /// [`Self::update`] for the decay law, isotropic, in elastic stick, without damping or
    /// steady transport ([`Self::lean_decay`]): the same arithmetic as the general path
    /// (`check_inputs`, `elastic_stick` with a = 1, μ̄ = μ₁, no unscaling), without what this
    /// case does not need: the scaled copies, the viscous stress, one evaluation of the factor
    /// (the rate-free stiffness k̄_s and the solve's A share π(p)·Θ(θ̄)), and the θ̄ derivatives
    /// when μ does not depend on temperature (∂τ/∂θ̄ = 0 then). Inlined into its callers
    /// (`fric_`'s rate fast path takes it whole), with the solve's loop out of line
    /// ([`decay_halley`]).
    #[inline(always)]
    pub(crate) fn isotropic_decay<const N: usize>(
        &self,
        inc: &Increment<N>,
        theta: f64,
        state: &ExtendedState<N>,
        (r, d): (f64, f64),
    ) -> Result<ExtendedUpdate<N>, LawError> {
        // The input test of `check_inputs` (no TAULM in elastic stick, no DROT or viscous
        // stress without damping; θ̄ is 0 when not read).
        let probe = inc.motion_probe() + theta * 0.0;
        if !(probe == 0.0 && state.coulomb.slip_rate >= 0.0) {
            let conditions = Conditions {
                temperature: theta,
                ..Conditions::default()
            };
            if let Some(refusal) = self.name_bad_input(inc, &conditions, state) {
                return Err(refusal);
            }
        }
        // The time increment for rates (`rate_increment`): a rate law needs it > 0 unless μ
        // is frozen.
        let rate_dt = match self.hht {
            Some(h) => h.rate_increment(inc.dtime),
            None => inc.dtime,
        };
        if !self.frozen && (rate_dt.is_nan() || rate_dt <= 0.0) {
            return Err(no_rate_increment(inc.dtime));
        }
        // (∞ when frozen with Δt = 0: then unused.)
        let per_dt = 1.0 / rate_dt;
        let gamma_crit = self.base.critical_slip_for(inc.characteristic_length)?;
        // (The decay law has no table: only Θ(θ̄) reads the temperature.)
        let with_theta = self.coefficient.has_temperature_factor();
        let mbar = self.base.mu();
        let tau_max = self.base.shear_limit().unwrap_or(f64::INFINITY);
        let start_rate = state.coulomb.slip_rate;
        let p = inc.pressure;
        let p0 = inc.pressure - inc.dpressure;
        // The rate-following stick stiffness (as in `elastic_stick`): k̄_s at the start rate
        // γ̇₀ = `STATEV(2)`, φ(γ̇₀) a constant factor of the strength; the earlier formulation
        // and frozen μ: the rate-free φ(0) = 1.
        let following = !self.frozen && self.formulation == RateFormulation::RateFollowingStiffness;
        let phi_k = if following && start_rate > 0.0 {
            decay_phi(r, d, start_rate).0
        } else {
            1.0
        };
        // Stick stiffness k̄_s = τ̄_crit(γ̇_k, p, θ̄)/γ_crit at the end and at the start.
        let factor = self.coefficient.rate_free(p, theta);
        let k = held_rate_critical::<true>(p, factor, mbar * phi_k, tau_max);
        let k0 = held_rate_critical::<true>(
            p0,
            self.coefficient.rate_free(p0, theta),
            mbar * phi_k,
            tau_max,
        );
        // γ^el = τ/k_s(p₀) and its θ̄-derivative (as in `elastic_stick`).
        let trial = ElasticTrial::new(&inc.tau, &inc.dgam, gamma_crit, &k0, with_theta);
        let g = trial.g;
        let stiffness = k.value / gamma_crit;
        let stiffness_p = k.d_pressure / gamma_crit;
        let stiffness_theta = k.d_temperature / gamma_crit;
        let stick_crit = if !self.frozen {
            k
        } else if with_theta {
            // `critical` multiplies (μ̄·φ·π)·Θ: with Θ on, π and Θ are needed apart.
            self.critical(mbar, start_rate, p, theta)
        } else {
            decay_critical::<true>(factor, (r, d), mbar, p, tau_max, start_rate)
        };
        let sticks = trial.sticks(following, stiffness, stick_crit.value);
        let ScaledTraction {
            traction,
            ddtdtheta,
            slip_eq,
            iterations,
        } = if sticks || stiffness <= 0.0 {
            // As the next increment reads τ: at rest (see `rest_energy`).
            let rest = || (phi_k != 1.0).then(|| (mbar * factor[0] * p).min(tau_max));
            trial.no_slip(following, &k, rest)
        } else {
            // Slip: k_s (γ_eq^pr − s) = τ_crit(s/Δt, p, θ̄).
            let (slip_eq, crit, iterations) = if following {
                // Eq. 5.2.3-2: s = γ̄_eq^pr − γ_crit, τ̄ = τ̄_crit(s/Δt)·n, explicit.
                let s_eq = g - gamma_crit;
                (
                    s_eq,
                    decay_critical::<false>(factor, (r, d), mbar, p, tau_max, s_eq * per_dt),
                    0,
                )
            } else if self.frozen {
                // μ frozen at the start rate: s = γ_eq^pr − τ_crit/k_s, explicit.
                (g - stick_crit.value / stiffness, stick_crit, 0)
            } else {
                // Start from the slip at the start-of-increment rate, else from the rate-free
                // answer; stop at the round-off level of F (as `elastic_stick`).
                let guess = if start_rate > 0.0 {
                    start_rate * rate_dt
                } else {
                    g - gamma_crit
                };
                let f_tol = 8.0 * f64::EPSILON * (stiffness * g + k.value);
                // p ≥ 0 here (k_s > 0). 1/k̄_s as γ_crit/τ̄_crit(0): one division from τ̄_crit(0)
                // to the first guess, not two.
                let compliance = gamma_crit / k.value;
                self.solve_decay(
                    factor,
                    (r, d),
                    mbar,
                    p,
                    g,
                    (stiffness, compliance),
                    per_dt,
                    guess,
                    f_tol,
                )
                .map_err(|e| local_solve_failed(e, g, rate_dt))?
            };
            // (After the solve in the code, so that its division does not queue in front of
            // those on the way to the first exp.)
            let n = unit(&trial.predictor, g);
            let t = crit.value;
            // ∂τ_crit/∂s = (∂τ_crit/∂γ̇)/Δt (0 when frozen).
            let t_s = if self.frozen {
                0.0
            } else {
                crit.d_rate * per_dt
            };
            let (ds_dg, ds_dp, per_dd) = if following {
                // s = G − γ_crit.
                (1.0, 0.0, 0.0)
            } else {
                let dd = slip_stiffness(stiffness, t_s)?;
                // Implicit derivatives of s from k_s (G − s) = τ_crit(s/Δt, p, θ̄).
                // One division for the three implicit derivatives.
                let per_dd = 1.0 / dd;
                (
                    stiffness * per_dd,
                    (stiffness_p * (g - slip_eq) - crit.d_pressure) * per_dd,
                    per_dd,
                )
            };
            let transverse = t / g;
            // Eq. 5.2.3-3: (δ − nn) τ_crit/γ_eq^pr + nn (∂τ_crit/∂s) ∂s/∂G.
            let ddtddg = super::rate_slip_tangent(&n, transverse, t_s, ds_dg);
            let dtau_dp = t_s * ds_dp + crit.d_pressure;
            let ddtdtheta = if with_theta {
                let ds_dtheta = (stiffness_theta * (g - slip_eq) - crit.d_temperature) * per_dd;
                trial.slip_temperature_tangent(
                    &n,
                    transverse,
                    t_s,
                    (ds_dg, ds_dtheta),
                    crit.d_temperature,
                )
            } else {
                [0.0; N]
            };
            let sed = slip_energy(t, following, gamma_crit, stiffness);
            ScaledTraction {
                traction: Traction::sliding(&n, t, ddtddg, dtau_dp, slip_eq, sed),
                ddtdtheta,
                slip_eq,
                iterations,
            }
        };
        // `check_outputs` in one test: x·0 is 0 for finite x, NaN otherwise.
        let mut probe = traction.sed * 0.0 + traction.sfd * 0.0;
        for i in 0..N {
            probe +=
                (traction.tau[i] + traction.ddtddp[i] + traction.dslip[i] + ddtdtheta[i]) * 0.0;
            for j in 0..N {
                probe += traction.ddtddg[i][j] * 0.0;
            }
        }
        if probe != 0.0 {
            check_outputs(&traction, &ddtdtheta)?;
        }
        Ok(ExtendedUpdate {
            contact: Contact::Motion(traction),
            ddtdtheta,
            state: ExtendedState {
                // The return map's Δγ_eq^sl (0 in stick) for the path too, not |DSLIP| again:
                // the same value without a second square root (as the plain law's state).
                coulomb: state.coulomb.after_motion(slip_eq, slip_eq, rate_dt),
                viscous: [0.0; N],
            },
            outcome: Outcome::CONVERGED,
            iterations,
        })
    }

    /// The decay law's local solve of k̄_s (γ̄_eq^pr − s) = τ̄_crit(s/Δt, p, θ̄) for the slip
    /// s, with τ̄_crit = A·φ(s/Δt) below τ_max, A = μ̄·π(p)·Θ(θ̄)·p fixed during the solve (so each
    /// evaluation is one exp and a few products); the partials in p and θ̄ are formed once, at
    /// the root. `factor` = (π·Θ, ∂(π·Θ)/∂p, ∂(π·Θ)/∂θ̄), `law` = (r, d_c) of
    /// [`CoefficientLaw::split_decay`]. Returns (s, τ̄_crit and its partials at s, iterations).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn solve_decay(
        &self,
        [pt, pt_p, pt_t]: [f64; 3],
        (r, d): (f64, f64),
        mbar: f64,
        p: f64,
        g: f64,
        (stiffness, compliance): (f64, f64),
        per_dt: f64,
        guess: f64,
        f_tol: f64,
    ) -> Result<(f64, Critical, u32), RootFailure> {
        let x_tol = 4.0 * f64::EPSILON * g;
        let tau_max = self.base.shear_limit().unwrap_or(f64::INFINITY);
        let a = mbar * pt * p;
        // The smallest root (docs/props.md, "τ_max with several roots"; the earlier
        // formulation only): with A·r < τ_max < A (r < 1) the strength is capped on [0, s*],
        // A·φ(s*/Δt) = τ_max, and below the cap after s*; F is linear on the cap and concave
        // after it (φ is convex), so the smallest root is the cap's G − τ_max/k̄_s when that
        // lies in [0, s*], and otherwise the only root in [s*, G]. No case is left undecided.
        let mut floor = 0.0;
        if tau_max < a && a * r < tau_max && r < 1.0 {
            let on_cap = g - tau_max * compliance;
            let s_star = -((tau_max / a - r) / (1.0 - r)).ln() / (d * per_dt);
            if on_cap <= s_star {
                let cap = Critical::at_shear_limit(tau_max);
                return Ok((on_cap.max(0.0), cap, 0));
            }
            floor = s_star;
        }
        // φ lies between 1 (at rest) and r (fast): the root lies between the slips for the
        // largest and the smallest of τ̄_crit, so a guess outside is moved to the nearer one.
        // (Only the first guess: its rounding does not matter, so one division.)
        let guess = {
            let t_small = (a * r.min(1.0)).min(tau_max);
            let t_large = (a * r.max(1.0)).min(tau_max);
            let (low, high) = (g - t_large * compliance, g - t_small * compliance);
            // Comparisons, not `f64::max`/`min` (whose NaN rules cost a few operations on the
            // way to the first exp; a NaN bound leaves the guess alone all the same), not
            // `clamp` (no panic on a NaN bound); the solver clips into [0, γ̄_eq^pr].
            let guess = if guess < low { low } else { guess };
            let guess = if guess > high { high } else { guess };
            if guess < floor { floor } else { guess }
        };
        // F(0) = k̄_s γ̄_eq^pr − τ̄_crit(0) > 0 (slip) and F(γ̄_eq^pr) = −τ̄_crit ≤ 0: the root is
        // bracketed.
        let (x, phi, dphi, iterations) = decay_halley(
            r,
            d,
            a,
            tau_max,
            stiffness,
            (g, floor),
            per_dt,
            guess,
            x_tol,
            f_tol,
        )?;
        let root_x = x;
        let c = critical_from_phi([pt, pt_p, pt_t], mbar, p, tau_max, phi, dphi);
        Ok((root_x, c, iterations))
    }
}

/// τ̄_crit(γ̇_k, p, θ̄) as `critical` forms it, from f = π·Θ and its partials, with the rate held
/// (`scaled_mu` = μ̄·φ(γ̇_k); φ(0) = 1); 0 for p < 0. `THETA = false` leaves ∂τ̄_crit/∂θ̄ = 0
/// without forming the product μ̄·φ·Θ'·p (for [`decay_critical`]'s frozen μ, where Θ = 1).
#[inline(always)]
fn held_rate_critical<const THETA: bool>(
    pressure: f64,
    f: [f64; 3],
    scaled_mu: f64,
    tau_max: f64,
) -> Critical {
    if pressure < 0.0 {
        return Critical::default();
    }
    let mu = scaled_mu * f[0];
    if mu * pressure >= tau_max {
        Critical::at_shear_limit(tau_max)
    } else {
        Critical {
            value: mu * pressure,
            d_rate: 0.0,
            d_rate2: 0.0,
            d_pressure: mu + scaled_mu * f[1] * pressure,
            d_temperature: if THETA {
                scaled_mu * f[2] * pressure
            } else {
                0.0
            },
        }
    }
}

/// τ̄_crit = min(A·φ, τ_max), A = μ̄·π·Θ·p, with its partials, from φ and φ' at the rate.
#[inline(always)]
fn critical_from_phi(
    [pt, pt_p, pt_t]: [f64; 3],
    mbar: f64,
    p: f64,
    tau_max: f64,
    phi: f64,
    dphi: f64,
) -> Critical {
    let a = mbar * pt * p;
    if a * phi >= tau_max {
        Critical::at_shear_limit(tau_max)
    } else {
        let mp = mbar * p;
        Critical {
            value: a * phi,
            d_rate: a * dphi,
            d_rate2: 0.0,
            d_pressure: mbar * phi * pt + mp * (phi * pt_p),
            d_temperature: mp * (phi * pt_t),
        }
    }
}

/// The decay law's τ̄_crit(γ̇, p, θ̄) at the rate `rate`, from the rate-free factor π·Θ and its
/// partials (`factor`).
///
/// `FROZEN = false`: the rate-following slip answer, with the rate derivatives.
///
/// `FROZEN = true`: μ frozen at the start rate γ̇₀ = `rate`, without a temperature factor
/// (Θ = 1), the value `critical` gives, inline and bit for bit: `critical` forms
/// μ = ((μ̄·φ(γ̇₀))·π)·Θ and τ̄_crit = μ·p, ∂τ̄_crit/∂p = μ + ((μ̄·φ)·π')·Θ·p; with Θ = 1,
/// `factor` = (π, π', 0) and the products (μ̄·φ)·π and (μ̄·φ)·π' are the same numbers
/// ((x·π)·1 = x·π). φ is `decay_phi`'s, which is the φ of `critical` (the same terms from one
/// exponential, 1 at γ̇₀ = 0). The rate derivatives are left 0: frozen μ does not follow this
/// increment's rate (the slip answer reads ∂τ̄_crit/∂s as 0 when frozen); ∂/∂θ̄ is 0 with
/// Θ = 1. 0 for p < 0, as `critical`, tested before φ is formed (no exponential for a point in
/// tension). (`critical_from_phi` multiplies in another order, so the frozen value is formed
/// by `held_rate_critical` instead.)
#[inline(always)]
fn decay_critical<const FROZEN: bool>(
    factor: [f64; 3],
    (r, d): (f64, f64),
    mbar: f64,
    p: f64,
    tau_max: f64,
    rate: f64,
) -> Critical {
    if FROZEN {
        if p < 0.0 {
            return Critical::default();
        }
        held_rate_critical::<false>(p, factor, mbar * decay_phi(r, d, rate).0, tau_max)
    } else {
        let (phi, dphi, _) = decay_phi(r, d, rate);
        critical_from_phi(factor, mbar, p, tau_max, phi, dphi)
    }
}

/// The decay law's local solve F(s) = k̄_s (γ̄_eq^pr − s) − min(A·φ(s/Δt), τ_max) = 0 on the
/// bracket F(γ̄_eq^pr) ≤ 0 ≤ F(0): the safeguarded Halley iteration of
/// [`halley_on_known_bracket`] step for step (the same tests with the same tolerances), written
/// out for this residual, so that the few values it carries stay in registers. Returns (s, φ,
/// φ' at s, steps).
///
/// For r = μ_k/μ_s ≤ 1, φ = e + r(1 − e) with e = exp(−d_c s/Δt) from `exp` alone: both
/// terms are ≥ 0 and 1 − e is exact for e ≥ ½ (Sterbenz), so φ is as accurate as e, and the
/// `exp_m1` branch of [`decay_phi`] (needed for r > 1, where r(1 − e) must not lose 1 − e to
/// cancellation) is not taken.
#[allow(clippy::too_many_arguments)]
// Out of line, with its own registers: inlined into the lean update (itself inlined into
// `fric_`'s fast path), the loop shared them with everything around it and spilled more;
// `bench_rate` cold 2.85-2.95 -> 2.70-2.77x, warm 2.75-2.86 -> 2.64-2.69x constant μ for
// +42 instructions (docs/performance.md, fourth pass).
#[inline(never)]
fn decay_halley(
    r: f64,
    d: f64,
    a: f64,
    tau_max: f64,
    stiffness: f64,
    (g, floor): (f64, f64),
    per_dt: f64,
    guess: f64,
    x_tol: f64,
    f_tol: f64,
) -> Result<(f64, f64, f64, u32), RootFailure> {
    let mut residual = DecayResidual::new(r, d, a, tau_max, stiffness, g, per_dt);
    // Bracket [low, high] = [γ̄_eq^pr, floor] with F(low) ≤ 0 ≤ F(high) (floor = 0, or s* of
    // the smallest-root rule).
    let (low, high) = (g, floor);
    if low == high {
        let (_, phi, dphi) = residual.eval::<false>(low);
        return Ok((low, phi, dphi, 0));
    }
    // Into [floor, γ̄_eq^pr] (g > floor here) with comparisons: `clamp` tests its bounds.
    let x = if guess.is_finite() {
        let x = if guess > floor { guess } else { floor };
        if x < g { x } else { g }
    } else {
        0.5 * (g + floor)
    };
    let mut it = HalleyState {
        x,
        low,
        high,
        step: g,
        step_before: g,
        f: (0.0, 0.0, 0.0),
    };
    let (f, mut phi, mut dphi) = residual.eval::<false>(x);
    it.f = f;
    if f.0.abs() <= f_tol {
        return Ok((x, phi, dphi, 0));
    }
    // The first step is peeled off: it is too long for the continued exponential (`exp` at
    // its end), the later ones are not, so the residual's radius test is not made there.
    it.step()?;
    (it.f, phi, dphi) = residual.eval::<false>(it.x);
    // Converged by the step or by the residual (the residual test of the next iteration of
    // `halley_on_known_bracket`, made here: one exit instead of two).
    if (it.step.abs() <= x_tol) | (it.f.0.abs() <= f_tol) {
        return Ok((it.x, phi, dphi, 1));
    }
    for iteration in 2..=MAX_LOCAL_ITERATIONS {
        it.step()?;
        (it.f, phi, dphi) = residual.eval::<true>(it.x);
        if (it.step.abs() <= x_tol) | (it.f.0.abs() <= f_tol) {
            return Ok((it.x, phi, dphi, iteration));
        }
    }
    Err(RootFailure::NotConverged)
}

/// The iterate of [`decay_halley`]: x, the bracket, the last two steps, (F, F', F'') at x.
struct HalleyState {
    x: f64,
    low: f64,
    high: f64,
    step: f64,
    step_before: f64,
    f: (f64, f64, f64),
}

impl HalleyState {
    /// One safeguarded Halley step from x (the bracket updated with F(x) first).
    #[inline(always)]
    fn step(&mut self) -> Result<(), RootFailure> {
        let (fx, dfx, ddfx) = self.f;
        if !(fx.is_finite() && dfx.is_finite()) {
            return Err(RootFailure::NotConverged);
        }
        // Selects on the bits, not branches: the side is as likely one as the other.
        let below = fx < 0.0;
        self.low = select(below, self.x, self.low);
        self.high = select(below, self.high, self.x);
        let (low, high) = (self.low, self.high);
        // Halley's step δ = 2ff'/(2f'² − ff''), Newton's f/f' where the curvature term would
        // flip it; accepted when inside the bracket and at least halving the step before last.
        let denominator = 2.0 * dfx * dfx - fx * ddfx;
        let candidate = if denominator > 0.0 {
            2.0 * fx * dfx / denominator
        } else {
            fx / dfx
        };
        let target = self.x - candidate;
        let inside = target >= low.min(high) && target <= low.max(high);
        let fast_enough = 2.0 * candidate.abs() <= self.step_before.abs();
        self.step_before = self.step;
        if inside && fast_enough {
            self.step = candidate;
            self.x = target;
        } else {
            self.step = 0.5 * (high - low);
            self.x = low + self.step;
        }
        Ok(())
    }
}

/// `if c { a } else { b }` as bit operations, so that the compiler makes no branch of it.
#[inline(always)]
fn select(c: bool, a: f64, b: f64) -> f64 {
    let mask = u64::from(c).wrapping_neg();
    f64::from_bits((a.to_bits() & mask) | (b.to_bits() & !mask))
}

/// F(s) of [`decay_halley`] with what it needs, and the last point where `exp` was called.
struct DecayResidual {
    r: f64,
    d: f64,
    a: f64,
    tau_max: f64,
    stiffness: f64,
    g: f64,
    per_dt: f64,
    /// r ≤ 1: φ from e alone (see [`decay_halley`]).
    lean: bool,
    /// c = d_c/Δt (e = exp(−c s)), A·r, B = A(1 − r), B·c and B·c², for the lean case:
    /// τ̄_crit = A·r + B·e, F' = −k̄_s + B·c·e, F'' = −B·c²·e.
    c: f64,
    ar: f64,
    b: f64,
    bc: f64,
    bcc: f64,
    /// The last x where `exp` was called (NaN before the first) and its e.
    anchor_x: f64,
    anchor_e: f64,
}

impl DecayResidual {
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn new(r: f64, d: f64, a: f64, tau_max: f64, stiffness: f64, g: f64, per_dt: f64) -> Self {
        let c = d * per_dt;
        let b = a * (1.0 - r);
        DecayResidual {
            r,
            d,
            a,
            tau_max,
            stiffness,
            g,
            per_dt,
            lean: r <= 1.0,
            c,
            ar: a * r,
            b,
            bc: b * c,
            bcc: b * c * c,
            anchor_x: f64::NAN,
            anchor_e: f64::NAN,
        }
    }

    /// (F, F', F'') and φ, φ' at x. With `CONTINUE`, e within the radius of the last `exp`
    /// is continued from it.
    #[inline(always)]
    fn eval<const CONTINUE: bool>(&mut self, x: f64) -> ((f64, f64, f64), f64, f64) {
        let Self {
            r,
            d,
            a,
            tau_max,
            stiffness,
            g,
            per_dt,
            c,
            ..
        } = *self;
        if self.lean {
            // e(x) = e(x_a)·exp(u), u = c (x_a − x): within |u| ≤ 2⁻⁸ of the last exact e,
            // exp(u) from its Taylor series to u⁵ (the rest, u⁶/720 < 5·10⁻¹⁸, is below the
            // rounding of e), grouped for a short chain of dependent operations; NaN (so
            // `exp`) before the first call.
            let u = c * (self.anchor_x - x);
            let e = if CONTINUE && u.abs() <= 1.0 / 256.0 {
                let u2 = u * u;
                let p = (u + 0.5 * u2)
                    + (u2 * u) * ((1.0 / 6.0 + u * (1.0 / 24.0)) + u2 * (1.0 / 120.0));
                self.anchor_e + self.anchor_e * p
            } else {
                let e = if x > 0.0 { (-c * x).exp() } else { 1.0 };
                (self.anchor_x, self.anchor_e) = (x, e);
                e
            };
            let tc = self.ar + self.b * e;
            let f = if tc >= tau_max {
                (stiffness * (g - x) - tau_max, -stiffness, 0.0)
            } else {
                (
                    stiffness * (g - x) - tc,
                    -stiffness + self.bc * e,
                    -self.bcc * e,
                )
            };
            // φ = e + r(1 − e), φ' = −d_c (1 − r) e (in the rate), as `decay_phi`.
            (f, e + r * (1.0 - e), -d * ((1.0 - r) * e))
        } else {
            let (phi, dphi, ddphi) = decay_phi(r, d, x * per_dt);
            let tc = a * phi;
            let f = if tc >= tau_max {
                (stiffness * (g - x) - tau_max, -stiffness, 0.0)
            } else {
                (
                    stiffness * (g - x) - tc,
                    -stiffness - a * dphi * per_dt,
                    -a * ddphi * per_dt * per_dt,
                )
            };
            (f, phi, dphi)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn tau_max_or_infinity(tau_max: f64) -> f64 {
        if tau_max > 0.0 {
            tau_max
        } else {
            f64::INFINITY
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 4000, failure_persistence: None, ..ProptestConfig::default() })]

        /// The residual's e = exp(−c·s) continued from the last exact evaluation (Taylor series
        /// within |u| ≤ 2⁻⁸) against `exp` at the point itself: a few ulps, at any distance
        /// inside the radius, either side, and the first call (no anchor) is `exp` itself.
        #[test]
        fn continued_exponential_matches_exp(
            c in prop_oneof![1e-3..1.0f64, 1.0..1e4f64],
            anchor in 0.0..2.0f64,
            fraction in -1.0..1.0f64,
        ) {
            let mut res = DecayResidual::new(0.5, c, 1.0, f64::INFINITY, 1.0, 1.0, 1.0);
            let x0 = anchor / c;
            let ((..), phi0, _) = res.eval::<false>(x0);
            let e0 = (-c * x0).exp();
            prop_assert_eq!(phi0, e0 + 0.5 * (1.0 - e0));
            // A point within the Taylor radius of x0 (u = c·(x0 − x)).
            let x = x0 - fraction / 256.0 / c;
            prop_assume!(x > 0.0);
            let ((..), phi, dphi) = res.eval::<true>(x);
            let exact = (-c * x).exp();
            // φ = e + r(1 − e) and φ' = −d(1 − r)e with r = 1/2, d = c (per_dt = 1).
            let e = -2.0 * dphi / c;
            prop_assert!((e - exact).abs() <= 4.0 * f64::EPSILON * exact, "{e:e} vs {exact:e}");
            prop_assert!((phi - (exact + 0.5 * (1.0 - exact))).abs() <= 4.0 * f64::EPSILON);
        }

        /// Frozen μ's inline strength (`decay_critical::<true>`, no temperature factor) against the
        /// general `critical` at the same start rate: value and ∂/∂p equal bit for bit (the
        /// lean path's stresses and tangents must not move), with and without π(p) and
        /// τ_max, at rest, on both sides of `decay_terms`' switch from `exp_m1` to `exp`, for
        /// μ_k below and above μ_s and p < 0.
        #[test]
        fn frozen_strength_is_critical_bit_for_bit(
            mu in prop_oneof![1e-3..1.0f64, 1.0..1e3f64],
            r in prop_oneof![0.0..1.0f64, 1.0..50.0f64],
            d in prop_oneof![1e-3..1.0f64, 1.0..1e3f64],
            rate in prop_oneof![Just(0.0), 0.0..0.5f64, 0.0..1e3f64],
            p in prop_oneof![-10.0..0.0f64, 0.0..1e4f64],
            p_ref in prop_oneof![Just(0.0), 1e-2..1e4f64],
            tau_max in prop_oneof![Just(0.0), 1e-2..1e4f64],
        ) {
            let mut base = Coulomb::new(mu).unwrap();
            if tau_max > 0.0 {
                base = base.with_shear_limit(tau_max).unwrap();
            }
            let mut coefficient = CoefficientLaw::default().with_exponential_decay(r, d).unwrap();
            if p_ref > 0.0 {
                coefficient = coefficient.with_pressure_reference(p_ref).unwrap();
            }
            let law = ExtendedCoulomb::new(base)
                .with_coefficient_law(coefficient)
                .with_frozen_coefficient(true);
            // The rate argument of `decay_terms`, −d·γ̇₀, on both sides of −0.5.
            let rate = if rate < 0.5 { rate / d } else { rate };
            let lean = law.lean_decay::<2>().unwrap();
            let cap = tau_max_or_infinity(tau_max);
            let general = law.critical(mu, rate, p, 0.0);
            let inline = decay_critical::<true>(law.coefficient.rate_free(p, 0.0), lean, mu, p, cap, rate);
            prop_assert_eq!(inline.value.to_bits(), general.value.to_bits(), "{:?} {:?}", inline, general);
            prop_assert_eq!(
                inline.d_pressure.to_bits(),
                general.d_pressure.to_bits(),
                "{:?} {:?}", inline, general
            );
            prop_assert_eq!(inline.d_temperature, 0.0);
            prop_assert_eq!(general.d_temperature, 0.0);
        }

        /// The solve's root against an independent evaluation of the residual with `exp` at the
        /// root: F within a few times the stopping tolerance, φ and φ' those of the root, for
        /// μ_k below and above μ_s (the continued and the `exp_m1` evaluations), with and
        /// without τ_max, from any first guess.
        #[test]
        fn decay_root_has_round_off_residual(
            r in prop_oneof![0.0..1.0f64, 1.0..4.0f64],
            d in 0.1..50.0f64,
            a in 1.0..100.0f64,
            cap in prop_oneof![Just(f64::INFINITY), 0.5..150.0f64],
            gamma_crit in 1e-4..1e-2f64,
            over in 1.05..10.0f64,
            dt in 1e-3..1.0f64,
            guess_fraction in -0.5..1.5f64,
        ) {
            let stiffness = a / gamma_crit;
            // Slipping: k·g above τ_crit at rest (φ = 1), capped by τ_max.
            let g = over * a.min(cap) / stiffness;
            let per_dt = 1.0 / dt;
            let f_tol = 8.0 * f64::EPSILON * (stiffness * g + a);
            let x_tol = 4.0 * f64::EPSILON * g;
            let Ok((x, phi, dphi, _)) =
                decay_halley(r, d, a, cap, stiffness, (g, 0.0), per_dt, guess_fraction * g, x_tol, f_tol)
            else {
                return Err(TestCaseError::fail("no convergence"));
            };
            let e = (-d * (x * per_dt)).exp();
            let phi_exact = e + r * (1.0 - e);
            let f = stiffness * (g - x) - (a * phi_exact).min(cap);
            // Stopped by the step (the residual then is the slope times that step) or by F.
            let slope = stiffness + a * d * (1.0 - r).abs() * per_dt;
            prop_assert!(f.abs() <= 4.0 * f_tol + 4.0 * slope * x_tol, "F = {f:e}, tol {f_tol:e}");
            prop_assert!((phi - phi_exact).abs() <= 8.0 * f64::EPSILON * phi_exact.max(1.0));
            prop_assert!((dphi + d * (1.0 - r) * e).abs() <= 8.0 * f64::EPSILON * d * (1.0 - r).abs().max(1.0));
        }
    }
}
