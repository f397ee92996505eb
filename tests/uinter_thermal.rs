//! Heat flux through `uinter_` (`PROPS(11) = 1`: conductance from the `INTERFACIAL_CONFIG`
//! file, the GAPCON laws; `PROPS(12..13)`: frictional heat): closed forms, DDFDDT = −∂FLUX/∂TEMP
//! and DDFDDR = ∂FLUX/∂RDISP against central differences, and the energy balance
//! FLUX(1) + FLUX(2) = η·SFD/Δt. One process, one configuration file (read once).

#[path = "common/config_file.rs"]
mod config_file;
use interfacial::props::AdhesiveBuilder;
use interfacial_test_hosts::{FricCall, UinterCall};

const K_N: f64 = 1e4;

fn configure() {
    // HOT: k(p, θ̄) from a table; GAP: gas conduction across the clearance.
    config_file::config_once(
        "uinter-thermal",
        "[interactions.HOT.conductance]\nlaw = \"pressure-table\"\n\
             table = [[0.0, 100.0, 0.0], [200.0, 500.0, 0.0], [0.0, 300.0, 100.0], [200.0, 900.0, 100.0]]\n\
             [interactions.GAP.conductance]\nlaw = \"gas-gap\"\nk_gas = 0.025\ng0 = 1e-4\n",
    );
}

/// μ = 0.4, S_a = 2, N_a = 5, γ_crit = 1e-3, K_n, conductance on, η, f = 0.3.
fn props(eta: f64) -> Vec<f64> {
    AdhesiveBuilder::new()
        .coeff(0.4)
        .sa(2.0)
        .na(5.0)
        .gamma_crit(1e-3)
        .normal_stiffness(K_N)
        .conductance(true)
        .heat_fraction(eta)
        .slave_fraction(0.3)
        .build()
}

fn point(name: &str, h: f64, dgam: f64, temp: [f64; 2], eta: f64) -> UinterCall {
    configure();
    let mut c = UinterCall::new(2, &props(eta));
    c.ciname = name.into();
    c.rdisp[0] = h;
    c.drdisp[1] = dgam;
    c.temp = temp;
    c.dtime = 0.5;
    c.call();
    assert_eq!(c.pnewdt, 1e36, "{}", FricCall::last_error());
    c
}

#[test]
fn conduction_closed_form_and_derivatives() {
    // Closed at p = K_n·h = 50, θ̄ = 50: k = ½(k(50, 0) + k(50, 100)) = ½(200 + 450) = 325.
    let (h, temp) = (5e-3, [60.0, 40.0]);
    let c = point("HOT", h, 0.0, temp, 0.0);
    assert!((c.flux[0] - 325.0 * (40.0 - 60.0)).abs() < 1e-9);
    assert!((c.flux[1] + c.flux[0]).abs() < 1e-12);
    // −∂FLUX/∂TEMP and ∂FLUX/∂RDISP(1) by central differences.
    for j in 0..2 {
        let dt = 1e-4;
        let (mut up, mut down) = (temp, temp);
        up[j] += dt;
        down[j] -= dt;
        let (cu, cd) = (
            point("HOT", h, 0.0, up, 0.0),
            point("HOT", h, 0.0, down, 0.0),
        );
        for i in 0..2 {
            let fd = -(cu.flux[i] - cd.flux[i]) / (2.0 * dt);
            assert!(
                (fd - c.ddfddt[i + 2 * j]).abs() < 1e-6,
                "DDFDDT({},{})",
                i + 1,
                j + 1
            );
        }
    }
    let dh = 1e-7;
    let (cu, cd) = (
        point("HOT", h + dh, 0.0, temp, 0.0),
        point("HOT", h - dh, 0.0, temp, 0.0),
    );
    for i in 0..2 {
        let fd = (cu.flux[i] - cd.flux[i]) / (2.0 * dh);
        assert!(
            (fd - c.ddfddr(i, 0)).abs() < 1e-6 * fd.abs().max(1.0),
            "DDFDDR({},1)",
            i + 1
        );
    }
}

#[test]
fn conduction_across_an_open_gap() {
    // Apart by 4e-4 (no bond: the point starts open): k = 0.025/(4e-4 + 1e-4) = 50, no stress.
    configure();
    let mut c = UinterCall::new(2, &props(0.0));
    c.ciname = "GAP".into();
    c.statev[2] = 4.0;
    c.rdisp[0] = -4e-4;
    c.temp = [100.0, 20.0];
    c.call();
    assert_eq!((c.lopenclose, c.stress[0]), (0, 0.0));
    assert!((c.flux[0] - 50.0 * (20.0 - 100.0)).abs() < 1e-9);
    // ∂FLUX(1)/∂h = −∂k/∂h·(θ₁ − θ₂), ∂k/∂h = −∂k/∂d = k_gas/(d + g0)² … against FD.
    let dh = 1e-9;
    let mut f = [0.0; 2];
    for (k, s) in [1.0, -1.0].into_iter().enumerate() {
        let mut p = UinterCall::new(2, &props(0.0));
        p.ciname = "GAP".into();
        p.statev[2] = 4.0;
        p.rdisp[0] = -4e-4 + s * dh;
        p.temp = [100.0, 20.0];
        p.call();
        f[k] = p.flux[0];
    }
    let fd = (f[0] - f[1]) / (2.0 * dh);
    assert!(
        (fd - c.ddfddr(0, 0)).abs() < 1e-5 * fd.abs(),
        "{fd} vs {}",
        c.ddfddr(0, 0)
    );
}

#[test]
fn frictional_heat_balances_the_dissipation() {
    // Sliding at p = 50 (Δγ ≫ γ_crit): FLUX(1) + FLUX(2) = η·SFD/Δt, f = 0.3 of it to the slave.
    let eta = 0.9;
    let (with, without) = (
        point("HOT", 5e-3, 0.05, [60.0, 40.0], eta),
        point("HOT", 5e-3, 0.05, [60.0, 40.0], 0.0),
    );
    let sfd = with.energies[1];
    assert!(sfd > 0.0);
    let heat = eta * sfd / 0.5;
    assert!((with.flux[0] + with.flux[1] - heat).abs() < 1e-9 * heat);
    assert!((with.flux[0] - without.flux[0] - 0.3 * heat).abs() < 1e-9 * heat);
}

#[test]
fn missing_thermal_law_cuts_back() {
    configure();
    let mut c = UinterCall::new(2, &props(0.0));
    c.ciname = "NOWHERE".into();
    c.rdisp[0] = 1e-3;
    c.call();
    assert_eq!(c.pnewdt, 0.25);
    let msg = FricCall::last_error();
    assert!(msg.contains("UINTER") && msg.contains("NOWHERE"), "{msg}");
}
