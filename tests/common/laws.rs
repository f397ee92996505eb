//! Law-1 `PROPS` fixtures shared by several tests (included by path), built by entry name.

use interfacial::props::CoulombBuilder;

/// Law 1 with every μ law of `fric_coef_` on: μ₁ = `mu`, μ₂ = `mu2`, the exponential decay to
/// μ_k = 0.2 at d_c = 2, p_ref = 100, b_θ = 0.01 about θ_ref = 20 (docs/props.md).
pub fn every_mu_law(mu: f64, mu2: f64) -> CoulombBuilder {
    CoulombBuilder::new()
        .mu(mu)
        .mu2(mu2)
        .mu_law(1.0)
        .mu_k(0.2)
        .decay(2.0)
        .p_ref(100.0)
        .b_theta(0.01)
        .theta_ref(20.0)
}
