//! `PROPS` fixtures shared by several tests (included by path): law-1 arrays built by entry
//! name, and one entry set by its index, as a bad-input test names it.
// Each test uses its own subset.
#![allow(dead_code)]

use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;

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

/// Sets `PROPS(index)` (numbered from 1, as messages and docs/props.md name it) to `v`,
/// lengthening `PROPS` (and `NPROPS`) to reach it.
pub fn set_entry(c: &mut FricCall, index: usize, v: f64) {
    if c.props.len() < index {
        c.props.resize(index, 0.0);
        c.nprops = i32::try_from(index).expect("a PROPS index fits NPROPS");
    }
    c.props[index - 1] = v;
}
