//! The cheap paths of the extended law against its general path
//! (`ExtendedCoulomb::with_general_path`, a switch that exists only in this crate's unit
//! tests): moved here from tests/friction_extended.rs and tests/fric_weakening.rs when the
//! switch stopped being public.

use proptest::prelude::*;

use crate::laws::contact::Conditions;
use crate::laws::contact::{Contact, Increment};
use crate::laws::coulomb::{Coulomb, CoulombState, StickMode};
use crate::laws::coulomb_extended::{ExtendedCoulomb, ExtendedState, Hht};
use crate::laws::friction_coefficient::{CoefficientLaw, RateFormulation};

/// Elastic stick with μ, γ_crit = 10⁻³ and, when `tau_max` > 0, that shear limit.
fn base_law(mu: f64, tau_max: f64) -> Coulomb {
    let base = Coulomb::new(mu)
        .unwrap()
        .with_critical_slip_absolute(1e-3)
        .unwrap();
    if tau_max > 0.0 {
        base.with_shear_limit(tau_max).unwrap()
    } else {
        base
    }
}

/// A 2-D increment from fractions: start stress tf·μ·p₀, Δγ = gf·γ_crit (10⁻³), end pressure
/// p₀·(1 + dpf) after Δp = p₀·dpf.
fn increment(mu: f64, p0: f64, dpf: f64, tf: [f64; 2], gf: [f64; 2], dtime: f64) -> Increment<2> {
    Increment {
        tau: [tf[0] * mu * p0, tf[1] * mu * p0],
        dgam: [gf[0] * 1e-3, gf[1] * 1e-3],
        pressure: p0 * (1.0 + dpf),
        dpressure: p0 * dpf,
        dtime,
        ..Increment::default()
    }
}

/// What both agreement tests draw: μ, τ_max (0: none), and for [`increment`] p₀, Δp/p₀, the
/// start-stress fractions and the slip fractions (each within ±`slip`).
#[allow(clippy::type_complexity)]
fn law_and_increment(slip: f64) -> impl Strategy<Value = (f64, f64, f64, f64, [f64; 2], [f64; 2])> {
    (
        0.05..1.0f64,
        prop_oneof![Just(0.0), 1.0..100.0f64],
        1.0..200.0f64,
        -0.5..1.0f64,
        prop::array::uniform2(-0.6..0.6f64),
        prop::array::uniform2(-slip..slip),
    )
}

/// The start pressure of the three-roots case.
const P: f64 = 100.0;
/// μ_s of the three-roots case.
const MU_S: f64 = 0.5;

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    /// The cheap paths (isotropic without scaling, rate-free μ without the local solve, the
    /// plain Coulomb law when nothing is switched on) agree with the general path to round-off.
    #[test]
    fn cheap_and_general_paths_agree(
        (mu, tau_max, p0, dpf, tf, gf) in law_and_increment(4.0),
        exact in prop::bool::ANY,
        p_ref in prop_oneof![Just(0.0), 10.0..500.0f64],
    ) {
        let mut base = base_law(mu, tau_max);
        if exact {
            base = base.with_stick(StickMode::Exact);
        }
        let mut coefficient = CoefficientLaw::default();
        if p_ref > 0.0 {
            coefficient = coefficient.with_pressure_reference(p_ref).unwrap();
        }
        let cheap = ExtendedCoulomb::new(base).with_coefficient_law(coefficient);
        let general = cheap.with_general_path();
        let inc = increment(mu, p0, dpf, tf, gf, 0.1);
        let st = ExtendedState::default();
        let c = cheap.update(&inc, &Conditions::default(), &st).unwrap();
        let g = general.update(&inc, &Conditions::default(), &st).unwrap();
        prop_assert_eq!(c.state.coulomb.status, g.state.coulomb.status);
        if let (Contact::Motion(a), Contact::Motion(b)) = (c.contact, g.contact) {
            let close = |x: f64, y: f64, scale: f64| (x - y).abs() <= 1e-12 * scale.max(1e-300);
            let ks = mu * p0 * 2.0 / 1e-3;
            for i in 0..2 {
                prop_assert!(close(a.tau[i], b.tau[i], mu * p0 * 2.0), "{a:?} {b:?}");
                prop_assert!(close(a.ddtddp[i], b.ddtddp[i], mu), "{a:?} {b:?}");
                prop_assert!(close(a.dslip[i], b.dslip[i], 1e-2), "{a:?} {b:?}");
                for j in 0..2 {
                    prop_assert!(close(a.ddtddg[i][j], b.ddtddg[i][j], ks), "{a:?} {b:?}");
                }
            }
            prop_assert!(close(a.sfd, b.sfd, mu * p0 * 1e-2));
        } else {
            prop_assert_eq!(c.contact, g.contact);
        }
        // With nothing switched on, the extended law is the plain law bit for bit.
        if p_ref == 0.0 {
            let plain = base.update(&inc, &CoulombState::default()).unwrap();
            prop_assert_eq!(plain.contact, c.contact);
        }
        // NFDIR = 1 through the 2-D code with a zero second component gives the scalar answer.
        let inc1 = Increment::<1> {
            tau: [inc.tau[0]],
            dgam: [inc.dgam[0]],
            pressure: inc.pressure,
            dpressure: inc.dpressure,
            dtime: 0.1,
            ..Increment::default()
        };
        let inc2 = Increment::<2> { tau: [inc.tau[0], 0.0], dgam: [inc.dgam[0], 0.0], ..inc };
        let one = general.update(&inc1, &Conditions::default(), &ExtendedState::default()).unwrap();
        let two = general.update(&inc2, &Conditions::default(), &ExtendedState::default()).unwrap();
        if let (Contact::Motion(a), Contact::Motion(b)) = (one.contact, two.contact) {
            prop_assert!((a.tau[0] - b.tau[0]).abs() <= 1e-12 * mu * p0 * 2.0);
            prop_assert!((a.ddtddg[0][0] - b.ddtddg[0][0]).abs() <= 1e-9 * mu * p0 / 1e-3);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, failure_persistence: None, ..ProptestConfig::default() })]

    /// The decay law's lean path (isotropic, elastic stick, no damping: no scaled copies, one
    /// factor evaluation, θ̄ work only with a temperature law, the solve's first guess moved
    /// into the root's interval) against the general path (scaling with a = μ_i/μ̄, the
    /// general return map) for the same law: stress, tangents, slip, energies, ∂τ/∂θ̄ and the
    /// state agree to round-off, in stick and slip, with and without p/θ̄ dependence, HHT,
    /// τ_max, a frozen μ, μ_k above or below μ_s, and any start rate.
    #[test]
    fn lean_decay_path_agrees_with_the_general_path(
        (mu, tau_max, p0, dpf, tf, gf) in law_and_increment(6.0),
        ratio in prop_oneof![0.0..1.0f64, 1.0..5.0f64],
        dc in 0.1..50.0f64,
        p_ref in prop_oneof![Just(0.0), 10.0..500.0f64],
        temperature in prop_oneof![Just(None), (-0.02..0.02f64, 0.0..100.0f64).prop_map(Some)],
        theta in 0.0..200.0f64,
        hht in prop::bool::ANY,
        frozen in prop::bool::ANY,
        start_rate in prop_oneof![Just(0.0), 0.0..2.0f64],
        dtime in 1e-3..1.0f64,
    ) {
        let base = base_law(mu, tau_max);
        let mut coefficient = CoefficientLaw::default().with_exponential_decay(ratio, dc).unwrap();
        if p_ref > 0.0 {
            coefficient = coefficient.with_pressure_reference(p_ref).unwrap();
        }
        if let Some((b, t0)) = temperature {
            coefficient = coefficient.with_temperature(b, t0).unwrap();
        }
        let lean = ExtendedCoulomb::new(base)
            .with_coefficient_law(coefficient)
            .with_frozen_coefficient(frozen)
            .with_hht(hht.then(|| Hht::new(-0.05, 0.0, 0.0).unwrap()));
        let general = lean.with_general_path();
        let inc = increment(mu, p0, dpf, tf, gf, dtime);
        let conditions = Conditions { temperature: theta, ..Conditions::default() };
        let st = ExtendedState::<2> {
            coulomb: CoulombState { slip_rate: start_rate, ..CoulombState::default() },
            ..ExtendedState::default()
        };
        let a = lean.update(&inc, &conditions, &st).unwrap();
        let b = general.update(&inc, &conditions, &st).unwrap();
        prop_assert_eq!(a.state.coulomb.status, b.state.coulomb.status);
        let (Contact::Motion(x), Contact::Motion(y)) = (a.contact, b.contact) else {
            return Err(TestCaseError::fail("elastic stick answers LM = 0"));
        };
        // Scales: the stress μ_s p (up to r·μ_s p), the stiffness μ_s p/γ_crit.
        let stress = mu * p0 * 2.0 * ratio.max(1.0);
        let close = |u: f64, v: f64, scale: f64| (u - v).abs() <= 1e-10 * scale;
        for i in 0..2 {
            prop_assert!(close(x.tau[i], y.tau[i], stress), "{x:?} {y:?}");
            prop_assert!(close(x.ddtddp[i], y.ddtddp[i], stress / p0), "{x:?} {y:?}");
            prop_assert!(close(x.dslip[i], y.dslip[i], 1e-2), "{x:?} {y:?}");
            prop_assert!(close(a.ddtdtheta[i], b.ddtdtheta[i], stress), "{a:?} {b:?}");
            for j in 0..2 {
                prop_assert!(close(x.ddtddg[i][j], y.ddtddg[i][j], stress / 1e-3), "{x:?} {y:?}");
            }
        }
        prop_assert!(close(x.sfd, y.sfd, stress * 1e-2));
        prop_assert!(close(x.sed, y.sed, stress * 1e-3));
        let rate_scale = 1e-2 / dtime;
        prop_assert!(close(a.state.coulomb.slip_rate, b.state.coulomb.slip_rate, rate_scale));
    }
}

/// The earlier formulation (comparison only) with τ_max between μ_k·p and μ_s·p under strong
/// weakening: its slip equation k̄_s(G − s) = min(A·φ(s/Δt), τ_max) has three roots here
/// (counted below on a fine grid, independently of the solver); the documented rule takes the
/// smallest, on the cap (s = G − τ_max/k̄_s, τ = τ_max), wherever the solve starts from.
#[test]
fn the_earlier_formulation_takes_the_smallest_of_three_roots() {
    // γ_crit = 10⁻³ is `base_law`'s.
    let (tau_max, d_c, dt, gamma_crit) = (35.0, 2000.0, 0.05, 1e-3);
    let mu_k = 0.2; // r = 0.4, A = μ_s·p = 50, A·r = 20 < τ_max < A
    let decay = CoefficientLaw::default().with_exponential_decay(mu_k / MU_S, d_c);
    let law = ExtendedCoulomb::new(base_law(MU_S, tau_max))
        .with_coefficient_law(decay.unwrap())
        .with_rate_formulation(RateFormulation::RateFreeStiffness);
    let g = 1.01e-3;
    let k = tau_max / gamma_crit;
    let f = |s: f64| {
        let phi = mu_k / MU_S + (1.0 - mu_k / MU_S) * (-d_c * s / dt).exp();
        k * (g - s) - (MU_S * P * phi).min(tau_max)
    };
    let grid: Vec<f64> = (0..=100_000).map(|i| g * f64::from(i) / 1e5).collect();
    let sign_changes = grid.windows(2).filter(|w| f(w[0]) * f(w[1]) < 0.0).count();
    assert_eq!(sign_changes, 3, "the case must have three roots");
    for start_rate in [0.0, 1e-4, 5e-3, 1.0] {
        for general in [false, true] {
            let law = if general {
                law.with_general_path()
            } else {
                law
            };
            let inc = Increment::<1> {
                tau: [0.0],
                dgam: [g],
                pressure: P,
                dpressure: 0.0,
                dtime: dt,
                characteristic_length: 1.0,
                ..Increment::default()
            };
            let mut state = ExtendedState::<1>::default();
            state.coulomb.slip_rate = start_rate;
            let up = law.update(&inc, &Conditions::default(), &state).unwrap();
            let Contact::Motion(t) = up.contact else {
                panic!("no exact stick here")
            };
            let smallest = g - tau_max / k;
            assert!((t.dslip[0] - smallest).abs() <= 1e-12 * g, "{t:?}");
            assert!((t.tau[0] - tau_max).abs() <= 1e-12 * tau_max, "{t:?}");
            assert!(f(smallest).abs() <= 1e-9 * tau_max);
        }
    }
}
