//! The documented contract of `fric_` against its behaviour: each test reads the sentence the
//! documentation states (the `fric_` doc comment, which cbindgen copies into
//! `include/interfacial.h`, and `docs/fric.md`) and then checks the behaviour it describes, so
//! the test fails when either side changes without the other.

use interfacial::props::{AdhesiveBuilder, CoulombBuilder};
use interfacial_test_hosts::FricCall;

/// The text with comment markers removed and whitespace collapsed, so sentences that wrap
/// across lines compare as one.
fn normalised(text: &str) -> String {
    text.lines()
        .map(|l| {
            let t = l.trim_start();
            t.strip_prefix("///")
                .or_else(|| t.strip_prefix("//!"))
                .or_else(|| t.strip_prefix("* ").filter(|_| !t.starts_with("*/")))
                .unwrap_or(t)
        })
        .collect::<Vec<_>>()
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

fn read(path: &str) -> String {
    let full = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    normalised(&std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}")))
}

/// The doc comment of `fric_` (source and generated header) states `comment`, and docs/fric.md
/// states `page`.
fn documented(comment: &str, page: &str) {
    for (paths, phrase) in [
        (&["src/abi/fric.rs", "include/interfacial.h"][..], comment),
        (&["docs/fric.md"][..], page),
    ] {
        let phrase = normalised(phrase);
        for path in paths {
            let text = read(path);
            assert!(text.contains(&phrase), "{path} no longer states: {phrase}");
        }
    }
}

/// Law 1 with μ = 0.4, γ_crit = 10⁻³: add the extended entries, then `build()` all 20.
fn extended() -> CoulombBuilder {
    CoulombBuilder::new().mu(0.4).gamma_crit(1e-3)
}

/// A slipping NFDIR = 2 call at pressure 50, temperature `temp`, with the given DROT.
fn slipping(props: &[f64], nstatv: i32, temp: [f64; 2], drot: [f64; 4]) -> FricCall {
    let mut c = FricCall::new(2, props);
    c.statev = vec![0.0; nstatv as usize + 2];
    c.nstatv = nstatv;
    c.set_guards();
    if nstatv >= 5 {
        // A viscous stress from the last increment, as damping keeps it.
        c.statev[3] = 0.7;
        c.statev[4] = -0.2;
    }
    c.press = 50.0;
    c.dpress = 0.0;
    c.dtime = 0.1;
    c.tau = [3.0, 1.0, c.tau[2], c.tau[3]];
    c.dgam = [4e-3, 1e-3, 0.0];
    c.temp = temp;
    c.drot = drot;
    c.call();
    c
}

const IDENTITY: [f64; 4] = [1.0, 0.0, 0.0, 1.0];
/// 30° rotation, column-major.
fn rotation() -> [f64; 4] {
    let (s, c) = 30f64.to_radians().sin_cos();
    [c, s, -s, c]
}

#[test]
fn ddtddt_is_the_temperature_derivative_and_non_zero_exactly_when_mu_depends_on_temperature() {
    documented(
        "`DDTDDT` is ∂τ/∂`TEMP(1)` and ∂τ/∂`TEMP(2)` (each half of ∂τ/∂θ̄): non-zero when μ \
         depends on temperature (`PROPS(12)`, or a friction table in temperature), zero otherwise.",
        "each half of ∂τ/∂θ̄: non-zero when μ depends on temperature, `PROPS(12)` or a friction \
         table in θ̄; zeros otherwise",
    );
    // μ·exp(−b_θ(θ̄ − θ_ref)), b_θ = 2e-3, θ_ref = 20: DDTDDT against central differences.
    let props = extended().b_theta(2e-3).theta_ref(20.0).build();
    let base = [150.0, 90.0];
    let c = slipping(&props, 3, base, IDENTITY);
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(c.statev[2], 1.0, "the point must slip");
    let h = 1e-3;
    for s in 0..2 {
        let mut up = base;
        let mut down = base;
        up[s] += h;
        down[s] -= h;
        let (cu, cd) = (
            slipping(&props, 3, up, IDENTITY),
            slipping(&props, 3, down, IDENTITY),
        );
        for a in 0..2 {
            let fd = (cu.tau[a] - cd.tau[a]) / (2.0 * h);
            let got = c.ddtddt[a + 2 * s];
            assert!(got != 0.0, "DDTDDT({}, {}) is zero", a + 1, s + 1);
            assert!(
                (got - fd).abs() <= 1e-6 * fd.abs().max(1e-9),
                "DDTDDT({}, {}) = {got}, central difference {fd}",
                a + 1,
                s + 1
            );
        }
    }
    // Without a temperature law: exactly zero, and TEMP changes nothing.
    let plain = extended().mu2(0.3).build();
    let (c1, c2) = (
        slipping(&plain, 3, base, IDENTITY),
        slipping(&plain, 3, [400.0, -30.0], IDENTITY),
    );
    assert_eq!(c1.pnewdt, 1e36, "{}", FricCall::last_error());
    assert!(c1.ddtddt[..4].iter().all(|d| *d == 0.0), "{:?}", c1.ddtddt);
    assert_eq!(c1.tau[..2], c2.tau[..2]);
}

#[test]
fn drot_is_read_with_damping_only() {
    documented(
        "`DROT` is read only with damping (`PROPS(17)` > 0): the viscous stress kept in `STATEV` \
         is rotated by it before it is taken out of `TAU`",
        "`DROT` is read only with damping: the kept viscous stress is rotated by `DROT` before it \
         is taken out of `TAU`",
    );
    // Damping c₀ = 2: the kept viscous stress (0.7, −0.2) is rotated, so DROT changes TAU.
    let damped = extended().damping(2.0).build();
    let (a, b) = (
        slipping(&damped, 5, [0.0; 2], IDENTITY),
        slipping(&damped, 5, [0.0; 2], rotation()),
    );
    assert_eq!(a.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(b.pnewdt, 1e36, "{}", FricCall::last_error());
    assert!(
        (a.tau[0] - b.tau[0]).abs() + (a.tau[1] - b.tau[1]).abs() > 1e-6,
        "DROT had no effect with damping: {:?} {:?}",
        &a.tau[..2],
        &b.tau[..2]
    );
    // Without damping (anisotropic extended law and the plain law): bit for bit the same.
    for props in [extended().mu2(0.3).build(), extended().build_first(7)] {
        let (a, b) = (
            slipping(&props, 3, [0.0; 2], IDENTITY),
            slipping(&props, 3, [0.0; 2], rotation()),
        );
        assert_eq!(a.pnewdt, 1e36, "{}", FricCall::last_error());
        assert_eq!(a.tau, b.tau);
        assert_eq!(a.ddtddg, b.ddtddg);
        assert_eq!(a.statev, b.statev);
    }
}

#[test]
fn damping_needs_nstatv_of_three_plus_nfdir() {
    documented(
        "with tangential damping (`PROPS(17)` > 0) it also keeps the viscous stress in \
         `STATEV(4..3+NFDIR)` and needs `NSTATV ≥ 3 + NFDIR`",
        "with damping (`PROPS(17)` > 0) `NSTATV ≥ 3 + NFDIR`",
    );
    let damped = extended().damping(2.0).build();
    let short = slipping(&damped, 3, [0.0; 2], IDENTITY);
    assert!(short.pnewdt < 1.0, "NSTATV = 3 with damping was accepted");
    assert!(FricCall::last_error().contains("NSTATV"));
    let enough = slipping(&damped, 5, [0.0; 2], IDENTITY);
    assert_eq!(enough.pnewdt, 1e36, "{}", FricCall::last_error());
}

/// Law 2 (adhesive) at a negative pressure carries its shear adhesion S_a; law 1 carries nothing.
#[test]
fn negative_pressure_carries_the_shear_adhesion_under_law_2_only() {
    let text = read("docs/fric.md");
    assert!(text.contains(&normalised(
        "Law 2 (adhesive, `PROPS(1) = 2`) uses p⁺ = max(p, 0) and still carries its shear \
         adhesion: stick with k_s = S_a/γ_crit up to |τ| = S_a, then sliding at τ = S_a"
    )));
    let (s_a, gamma_crit) = (5.0, 1e-3);
    let run = |props: &[f64], dgam: f64| {
        let mut c = FricCall::new(1, props);
        c.press = -20.0;
        c.dpress = 0.0;
        c.dtime = 0.1;
        c.dgam[0] = dgam;
        c.call();
        assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
        c
    };
    let law2 = AdhesiveBuilder::new()
        .coeff(0.3)
        .sa(s_a)
        .gamma_crit(gamma_crit)
        .build_first(8);
    // Stick: τ = (S_a/γ_crit)·Δγ; far beyond γ_crit: τ = S_a.
    let stick = run(&law2, 0.4 * gamma_crit);
    assert!(
        (stick.tau[0] - 0.4 * s_a).abs() < 1e-12 * s_a,
        "{}",
        stick.tau[0]
    );
    let slide = run(&law2, 10.0 * gamma_crit);
    assert!((slide.tau[0] - s_a).abs() < 1e-12 * s_a, "{}", slide.tau[0]);
    let law1 = CoulombBuilder::new()
        .mu(0.3)
        .gamma_crit(gamma_crit)
        .build_first(7);
    let none = run(&law1, 10.0 * gamma_crit);
    assert_eq!(none.tau[0], 0.0);
}

/// PROPS(18..19), the damping ramp over the clearance, never act through FRIC.
#[test]
fn the_damping_ramp_entries_do_not_act_through_fric() {
    let text = read("docs/fric.md");
    assert!(text.contains(&normalised(
        "are range-checked but never act through `fric_`"
    )));
    let without = extended().damping(2.0).build();
    let with = extended()
        .damping(2.0)
        .damping_clearance(0.05)
        .damping_fraction(0.5)
        .build();
    let (a, b) = (
        slipping(&without, 5, [0.0; 2], rotation()),
        slipping(&with, 5, [0.0; 2], rotation()),
    );
    assert_eq!(b.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(a.tau, b.tau);
    assert_eq!(a.ddtddg, b.ddtddg);
    assert_eq!(a.ddtddp, b.ddtddp);
    assert_eq!((a.sed, a.sfd), (b.sed, b.sfd));
    assert_eq!(a.statev, b.statev);
}

/// Under HHT, STATEV(2) is the slip over Δt_rate = β·Δt/γ (docs/props.md, docs/fric.md).
#[test]
fn hht_slip_rate_in_statev_uses_the_scaled_increment() {
    let text = read("docs/props.md");
    assert!(text.contains(&normalised(
        "\\|Δγ^sl\\|/Δt_rate with Δt_rate = β·Δt/γ under HHT"
    )));
    let alpha = -0.2;
    // HHT α only: β = (1 − α)²/4, γ = 1/2 − α.
    let props = extended().hht_alpha(alpha).build();
    let c = slipping(&props, 3, [0.0; 2], IDENTITY);
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(c.statev[2], 1.0);
    let (beta, gamma) = (0.25 * (1.0 - alpha) * (1.0 - alpha), 0.5 - alpha);
    let slip = c.dslip[0].hypot(c.dslip[1]);
    let expected = slip / (beta * 0.1 / gamma);
    assert!(
        (c.statev[1] - expected).abs() <= 1e-12 * expected,
        "STATEV(2) = {}, slip/Δt_rate = {expected}",
        c.statev[1]
    );
}

/// docs/fric.md: with anisotropy SED = Σ τ_i²/(2k_i), k_i = (μ_i/μ̄)²·k̄_s, and STATEV(1) adds the
/// length of the actual (unscaled) slip increment |DSLIP|.
#[test]
fn anisotropic_sed_and_accumulated_slip_are_as_documented() {
    let text = read("docs/fric.md");
    assert!(text.contains(&normalised(
        "|τ̄|²/(2k̄_s) = Σ τ_i²/(2k_i) with k_i = (μ_i/μ̄)²·k̄_s. `STATEV(1)` adds the length of \
         the actual slip increment |Δγ^sl| (not the scaled one)"
    )));
    let (mu1, mu2, p, gamma_crit) = (0.4, 0.2, 50.0, 1e-3);
    let props = extended().mu2(mu2).build();
    let mbar = ((mu1 * mu1 + mu2 * mu2) / 2.0f64).sqrt();
    let kbar = mbar * p / gamma_crit;
    let k = [(mu1 / mbar).powi(2) * kbar, (mu2 / mbar).powi(2) * kbar];
    // Stick from rest: τ_i = k_i·Δγ_i.
    let mut c = FricCall::new(2, &props);
    c.press = p;
    c.dpress = 0.0;
    c.dtime = 0.1;
    c.dgam = [2e-4, -1e-4, 0.0];
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(c.statev[2], 0.0, "the point must stick");
    for (i, k_i) in k.iter().enumerate() {
        assert!((c.tau[i] - k_i * c.dgam[i]).abs() < 1e-12 * kbar * 1e-4);
    }
    let sed = c.tau[0] * c.tau[0] / (2.0 * k[0]) + c.tau[1] * c.tau[1] / (2.0 * k[1]);
    assert!(
        (c.sed - sed).abs() < 1e-12 * sed,
        "SED {} against {sed}",
        c.sed
    );
    // Slip: STATEV(1) grows by |DSLIP|.
    let before = c.statev[0];
    c.dgam = [4e-3, 3e-3, 0.0];
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    assert_eq!(c.statev[2], 1.0, "the point must slip");
    let slip = c.dslip[0].hypot(c.dslip[1]);
    assert!(slip > 0.0);
    assert!((c.statev[0] - before - slip).abs() < 1e-15 * slip.max(1.0));
}
