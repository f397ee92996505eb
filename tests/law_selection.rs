//! Which law a `PROPS` array selects is decided by the law's own description, never by an entry
//! point reading a `PROPS` index: a value that means one thing in one law's layout (law 1's μ
//! table switch `PROPS(8) = 2`) must not change how another law's array (law 2's
//! γ_crit = `PROPS(8)`) is read.
//!
//! - the regression that found it: the adhesive law with γ_crit = 2.0 exactly through `fric_`,
//!   `fric_coef_`, `uinter_`, `vfric_` and `ifl_fric_batch` is treated as γ_crit = 2.0000001
//!   (same acceptance or the same refusal, answers continuous in γ_crit);
//! - a property: `PROPS` arrays that the layouts accept, their entries drawn often at the small
//!   integers that are switch values in the other law, are refused by no entry point that
//!   takes that law (`fric_` for laws 1, 2 and 3, `fric_coef_` for law 1, `uinter_` for law 2,
//!   `ifl_fric_batch` for the plain Coulomb law it serves).

use interfacial::abi::vfric::IflReal;
use interfacial::abi::{IflStatus, ifl_clear_error};
use interfacial::props::{
    AdhesiveBuilder, CoulombBuilder, FrictionLaw, RateStateBuilder, friction_law_checked,
};
use interfacial_test_hosts::{FricCall, UinterCall};
use proptest::prelude::*;

mod common;
use common::{Points, via_c};

#[path = "common/fric_coef.rs"]
mod fric_coef_common;
use fric_coef_common::fric_coef_call;

#[path = "common/vfric.rs"]
mod vfric_common;

/// Adhesive friction with adhesion and a static coefficient (so `fric_` takes the adhesive
/// code, not its Coulomb special case), γ_crit = `gamma_crit`, a penalty stiffness for
/// `uinter_`: the full 13-entry layout.
fn adhesive(gamma_crit: f64) -> Vec<f64> {
    AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(0.45)
        .sa(7.0)
        .na(20.0)
        .kmu(0.0)
        .vhalf(0.0)
        .gamma_crit(gamma_crit)
        .normal_stiffness(1e6)
        .build_first(13)
}

/// `fric_` once, NFDIR = `nfdir`, at pressure 50 from rest with slip increment `dgam` in each
/// direction; the call (outputs, PNEWDT) and the message it left ("" when none).
fn fric(props: &[f64], nfdir: i32, dgam: f64) -> (FricCall, String) {
    let mut c = FricCall::new(nfdir, props);
    c.statev = vec![0.0; 4];
    c.nstatv = 4;
    c.press = 50.0;
    c.dpress = 0.0;
    c.dtime = 0.1;
    c.dgam = [dgam; 3];
    ifl_clear_error();
    c.call();
    let m = FricCall::last_error();
    (c, m)
}

/// `fric_coef_` on one point; μ in the first direction and the message left.
fn fric_coef(props: &[f64]) -> (f64, String) {
    let mut coef = vec![-1.0; 2];
    let mut deriv = vec![-1.0; 40];
    let name = *b"SI1                                                                             ";
    ifl_clear_error();
    fric_coef_call(
        &mut coef,
        &mut deriv,
        props,
        &[0.01, 0.0, 0.0, 0.0, 0.0, 0.0],
        &[50.0],
        &[20.0],
        &name,
    );
    (coef[0], FricCall::last_error())
}

/// `uinter_` closed (overclosure 1e-4) with a tangential slip `dgam`, K_n = 1e6.
fn uinter(props: &[f64], dgam: f64) -> (UinterCall, String) {
    let mut c = UinterCall::new(2, props);
    c.rdisp = [-1e-4, 0.0, 0.0];
    c.drdisp = [-1e-4, dgam, 0.0];
    c.dtime = 0.1;
    ifl_clear_error();
    c.call();
    let m = FricCall::last_error();
    (c, m)
}

/// `ifl_fric_batch` on `n` points from rest at pressure 50 with slip increments spread over
/// ±`dgam`; the outputs, PNEWDT and status.
fn batch(props: &[f64], nfdir: usize, dgam: f64) -> (Points, f64, IflStatus) {
    let n = 5;
    let mut p = Points::new(n, n, nfdir, 3);
    for i in 0..n {
        p.lm[i] = 0;
        p.press[i] = 50.0;
        p.dpress[i] = 0.0;
        p.chrlngth[i] = 1.0;
        p.sed[i] = 0.0;
        p.sfd[i] = 0.0;
        for r in 0..3 {
            p.statev[i + r * n] = 0.0;
        }
        for a in 0..nfdir {
            p.tau[i + a * n] = 0.0;
            p.dgam[i + a * n] = dgam * (i as f64 - 2.0) / 2.0;
        }
    }
    ifl_clear_error();
    via_c(props, 0.1, &p)
}

/// The relative difference of two answers (0 when both are 0).
fn rel(a: f64, b: f64) -> f64 {
    let s = a.abs().max(b.abs());
    if s == 0.0 { 0.0 } else { (a - b).abs() / s }
}

#[test]
fn adhesive_gamma_crit_two_is_read_as_gamma_crit() {
    let (exact, near) = (adhesive(2.0), adhesive(2.000_000_1));
    assert_eq!(exact[7], 2.0, "PROPS(8) is the adhesive law's γ_crit");
    // fric_: stick and slip, NFDIR 1 and 2. With γ_crit = 2 a slip of 0.5 sticks
    // (τ = k_s·Δγ, k_s = (μ_s p + S_a)/γ_crit), a slip of 5 slides.
    for nfdir in [1, 2] {
        for dgam in [0.5, 5.0] {
            let (a, ma) = fric(&exact, nfdir, dgam);
            let (b, mb) = fric(&near, nfdir, dgam);
            assert_eq!(
                ma, "",
                "fric_ refused γ_crit = 2.0 (NFDIR {nfdir}, Δγ {dgam})"
            );
            assert_eq!(mb, "", "fric_ refused γ_crit = 2.0000001");
            assert!(a.pnewdt >= 1.0 && b.pnewdt >= 1.0);
            for i in 0..nfdir as usize {
                assert!(
                    rel(a.tau[i], b.tau[i]) < 1e-6,
                    "{} vs {}",
                    a.tau[i],
                    b.tau[i]
                );
                assert!(a.tau[i] != 0.0, "a stress was carried");
            }
            if dgam == 0.5 {
                // Stick: τ = (μ_s p + S_a)/γ_crit · Δγ, closed form.
                let expect = (0.45 * 50.0 + 7.0) / 2.0 * 0.5;
                assert!(rel(a.tau[0], expect) < 1e-12, "{} vs {expect}", a.tau[0]);
            }
        }
    }
    // fric_coef_ serves law 1 only: both refused, with the same message.
    let (_, ma) = fric_coef(&exact);
    let (_, mb) = fric_coef(&near);
    assert!(
        ma.contains("adhesive"),
        "fric_coef_ refusal names the law: {ma}"
    );
    assert_eq!(ma, mb, "fric_coef_ refuses both the same way");
    // uinter_: both run, same answer to first order in γ_crit.
    let (a, ma) = uinter(&exact, 0.5);
    let (b, mb) = uinter(&near, 0.5);
    assert_eq!((ma.as_str(), mb.as_str()), ("", ""));
    assert!(a.pnewdt >= 1.0 && b.pnewdt >= 1.0);
    for i in 0..2 {
        assert!(rel(a.stress[i], b.stress[i]) < 1e-6);
    }
    // vfric_ refuses law 2 in every form: the same message for both.
    let block = |props: &[f64]| vfric_common::Block {
        nfricdir: 1,
        props: props.iter().map(|&x| x as IflReal).collect(),
        f_normal: vec![10.0],
        f_stick: vec![1.0],
        area: vec![1.0, 1.0],
        jconslvid: vec![1],
    };
    ifl_clear_error();
    vfric_common::call(&block(&exact));
    let ma = FricCall::last_error();
    ifl_clear_error();
    vfric_common::call(&block(&near));
    let mb = FricCall::last_error();
    assert!(ma.contains("VFRIC") || ma.contains("adhesive"), "{ma}");
    assert_eq!(ma, mb);
    // ifl_fric_batch runs the plain Coulomb kernel, which serves the adhesive law's Coulomb
    // special case (no adhesion, μ_s = μ_d): both γ_crit run it with answers continuous in
    // γ_crit; the general adhesive law is refused the same way for both.
    let special = |g: f64| {
        AdhesiveBuilder::new()
            .coeff(0.3)
            .coeff_static(-1.0)
            .gamma_crit(g)
            .build_first(8)
    };
    for nfdir in [1, 2] {
        let (a, pa, sa) = batch(&special(2.0), nfdir, 5.0);
        let (b, pb, sb) = batch(&special(2.000_000_1), nfdir, 5.0);
        assert_eq!((sa, sb), (IflStatus::Ok, IflStatus::Ok));
        assert!(pa >= 1.0 && pb >= 1.0);
        for (x, y) in a.tau.iter().zip(&b.tau) {
            assert!(rel(*x, *y) < 1e-6);
        }
        let (_, _, sa) = batch(&exact, nfdir, 5.0);
        let ma = FricCall::last_error();
        let (_, _, sb) = batch(&near, nfdir, 5.0);
        let mb = FricCall::last_error();
        assert_eq!(sa, sb);
        assert_eq!(ma, mb);
    }
}

/// Whether `ifl_fric_batch` takes the law of `props`: its kernel is the plain Coulomb law's
/// (law 1 without extensions, or law 2's Coulomb special case); the others go through `fric_`.
fn takes_batch(props: &[f64]) -> bool {
    matches!(friction_law_checked(props), Ok(FrictionLaw::Coulomb(_)))
}

/// A small integer often (0 to 3, the switch values of the layouts), else a value in `range`.
fn entry(range: std::ops::Range<f64>) -> impl Strategy<Value = f64> {
    prop_oneof![
        2 => (0u8..4).prop_map(f64::from),
        1 => range,
    ]
}

prop_compose! {
    /// Law-2 `PROPS` of 8 to 13 entries that the layout accepts: μ_d, μ_s (≤ 0 for none, else
    /// ≥ μ_d), S_a, N_a, k_μ, v_½, γ_crit, the slip tolerance, K_n, no GAPCON (`PROPS(11)` = 0),
    /// η ∈ [0, 1], f ∈ (0, 1].
    fn adhesive_props()(
        mu in entry(0.0..2.0),
        static_extra in prop_oneof![Just(-1.0), entry(0.0..1.0)],
        sa in entry(0.0..10.0), na in entry(0.0..10.0),
        kmu in entry(0.0..1.0), vhalf in entry(0.0..1.0),
        gamma_crit in entry(1e-3..3.0), tol in entry(1e-3..3.0),
        kn in entry(1.0..1e6), eta in prop_oneof![Just(0.0), Just(1.0), 0.0..1.0],
        f in prop_oneof![Just(1.0), Just(0.5), 0.01..1.0],
        len in 8usize..=13,
    ) -> Vec<f64> {
        let coeff_static = if static_extra < 0.0 { -1.0 } else { mu + static_extra };
        let mut v = vec![2.0, mu, coeff_static, sa, na, kmu, vhalf, gamma_crit.max(1e-3),
                         tol.max(1e-3), kn.max(1.0), 0.0, eta, f];
        v.truncate(len);
        v
    }
}

prop_compose! {
    /// Law-1 `PROPS` the layout accepts (kept by the checked parser), entries at the other
    /// law's switch values often: μ (isotropic or not), τ_max, γ_crit or the tolerance, stick
    /// mode 0 (elastic) or 2 (rough), constant μ or the decay law, p_ref.
    fn coulomb_props()(
        mu in entry(0.05..2.0), mu2 in prop_oneof![Just(None), entry(0.05..2.0).prop_map(Some)],
        tau_max in entry(0.0..100.0), gamma_crit in entry(0.0..3.0), tol in entry(0.0..3.0),
        mode in prop_oneof![Just(0.0), Just(2.0)],
        decay in prop_oneof![Just(None), (entry(0.0..1.0), entry(0.1..3.0)).prop_map(Some)],
        p_ref in entry(0.0..100.0),
    ) -> Vec<f64> {
        let mut b = CoulombBuilder::new().mu(mu).tau_max(tau_max).gamma_crit(gamma_crit)
            .slip_tolerance(tol).stick(mode).p_ref(p_ref);
        if let Some(mu2) = mu2 {
            b = b.mu2(mu2);
        }
        if let Some((fraction, d_c)) = decay {
            b = b.mu_law(1.0).mu_k(mu * fraction).decay(d_c);
        }
        b.build_first(20)
    }
}

prop_compose! {
    /// Law-3 `PROPS` the layout accepts, entries at the other laws' switch values often: μ₀, a
    /// (> 0 with the regularised form), b, V₀, L, either state evolution, either form of μ,
    /// γ_crit or the tolerance, θ₀ (0: L/V₀).
    fn rate_state_props()(
        mu0 in entry(0.0..1.0), a in entry(1e-3..0.05), b in entry(-0.05..0.05),
        v0 in entry(1e-6..1.0), l in entry(1e-5..1.0),
        evolution in 1u8..=2, form in 0u8..=1,
        gamma_crit in entry(0.0..1e-2), tol in entry(0.0..1.0), theta0 in entry(0.0..10.0),
    ) -> Vec<f64> {
        RateStateBuilder::new().mu0(mu0).a(a).b(b).v0(v0.max(1e-6)).l(l.max(1e-5))
            .evolution(f64::from(evolution)).form(f64::from(form)).gamma_crit(gamma_crit)
            .slip_tolerance(tol).theta0(theta0).build_first(11)
    }
}

/// `fric_` (NFDIR 1 and 2) and, for the law it serves, `ifl_fric_batch` take `props`: no
/// message, PNEWDT not lowered. `NSTATV` = 4, what every friction law needs at most without
/// damping.
fn fric_and_batch_take(props: &[f64]) -> Result<(), TestCaseError> {
    for nfdir in [1, 2] {
        let (c, m) = fric(props, nfdir, 0.01);
        prop_assert_eq!(m, "", "fric_ NFDIR {} refused {:?}", nfdir, props);
        prop_assert!(c.pnewdt >= 1.0);
        if takes_batch(props) {
            let (_, pn, st) = batch(props, nfdir as usize, 0.01);
            prop_assert_eq!(st, IflStatus::Ok, "ifl_fric_batch refused {:?}", props);
            prop_assert!(pn >= 1.0);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, failure_persistence: None, ..ProptestConfig::default() })]

    /// No entry point that takes law 2 refuses accepted law-2 `PROPS` for their `PROPS`.
    #[test]
    fn accepted_adhesive_props_are_refused_by_no_entry_point(props in adhesive_props()) {
        prop_assume!(friction_law_checked(&props).is_ok());
        fric_and_batch_take(&props)?;
        if props.len() >= 10 {
            let (c, m) = uinter(&props, 0.01);
            prop_assert_eq!(m, "", "uinter_ refused {:?}", props);
            prop_assert!(c.pnewdt >= 1.0);
        }
    }

    /// No entry point that takes law 3 (`fric_`) refuses accepted law-3 `PROPS` for their
    /// `PROPS`; `fric_coef_`, `vfric_` and the batch refuse law 3 by name.
    #[test]
    fn accepted_rate_state_props_are_refused_by_no_entry_point(props in rate_state_props()) {
        prop_assume!(friction_law_checked(&props).is_ok());
        fric_and_batch_take(&props)?;
        let (_, m) = fric_coef(&props);
        prop_assert!(m.contains("PROPS(1) = 3"), "fric_coef_ names law 3: {}", m);
    }

    /// No entry point that takes law 1 refuses accepted law-1 `PROPS` for their `PROPS`.
    #[test]
    fn accepted_coulomb_props_are_refused_by_no_entry_point(props in coulomb_props()) {
        prop_assume!(friction_law_checked(&props).is_ok());
        fric_and_batch_take(&props)?;
        let (mu, m) = fric_coef(&props);
        prop_assert_eq!(m, "", "fric_coef_ refused {:?}", props);
        prop_assert!(mu.is_finite() && mu >= 0.0);
    }
}
