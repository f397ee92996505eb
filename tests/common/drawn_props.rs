//! `PROPS` arrays the property tests of the C API draw (tests/props_query.rs,
//! tests/fric_point.rs; included by path): a valid base of either law, one per kind of layout
//! the readers tell apart, with a few entries set to values valid in some entries and not in
//! others. The including test also includes `common/laws.rs` as `laws`.

use interfacial::props::{AdhesiveBuilder, CoulombBuilder};

/// Valid `PROPS` of both laws, one per kind of layout the readers tell apart.
pub fn bases() -> Vec<Vec<f64>> {
    vec![
        CoulombBuilder::new()
            .mu(0.3)
            .gamma_crit(1e-3)
            .build_first(5),
        CoulombBuilder::new().mu(0.3).build_first(7),
        CoulombBuilder::new().mu(0.3).stick(1.0).build_first(7),
        CoulombBuilder::new().mu(0.4).mu2(0.2).build(),
        CoulombBuilder::new()
            .mu(0.5)
            .mu_law(1.0)
            .mu_k(0.2)
            .decay(2.0)
            .build(),
        super::laws::every_mu_law(0.5, 0.0).build(),
        CoulombBuilder::new().mu(0.3).mu_law(2.0).build(),
        CoulombBuilder::new()
            .mu(0.3)
            .stick(3.0)
            .omega(2.0)
            .axis(3.0)
            .build(),
        CoulombBuilder::new()
            .mu(0.3)
            .hht_alpha(-0.1)
            .damping(5.0)
            .build(),
        AdhesiveBuilder::new().coeff(0.3).build_first(2),
        AdhesiveBuilder::new()
            .coeff(0.3)
            .coeff_static(0.5)
            .sa(1.0)
            .kmu(0.1)
            .vhalf(0.01)
            .build(),
        AdhesiveBuilder::new().coeff(0.3).coeff_static(0.3).build(),
    ]
}

/// Values each entry is set to: valid in some entry and not in others, the switches' values,
/// and the non-finite ones.
pub const VALUES: [f64; 17] = [
    0.0,
    -0.0,
    1.0,
    2.0,
    3.0,
    4.0,
    0.3,
    0.5,
    1e-3,
    -1.0,
    -0.25,
    -0.6,
    20.0,
    1.5,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
];
