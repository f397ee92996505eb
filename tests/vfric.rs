//! `vfric_` (Abaqus/Explicit VFRIC) in the precision of the build: `f64` by default, `f32` with
//! `--features explicit-single` (`cargo test --features explicit-single --test vfric`).
//!
//! Against the closed form computed in that precision, `−min(μ·F_N, τ_max·A, F_stick)` (0 for
//! F_N < 0, `−F_stick` for rough friction): equal bit for bit, since the library's f64
//! evaluation of f32 inputs rounds once to the same f32 (docs/vfric.md). Random blocks of
//! every kind, both nFricDir; nothing written past the block; a bad point gets 0.

use std::ffi::c_int;

#[path = "common/vfric.rs"]
mod vfric_common;
use vfric_common::{Block, SENTINEL, call};

use interfacial::abi::vfric::IflReal;
use proptest::prelude::*;

/// The closed form in the build's precision (docs/vfric.md).
fn closed_form(b: &Block, k: usize) -> IflReal {
    let (mu, tau_max, rough) = (b.props[1], b.props[3], b.props[6] == 2.0);
    if rough {
        return -b.f_stick[k];
    }
    if b.f_normal[k] < 0.0 {
        return 0.0;
    }
    let mut critical = mu * b.f_normal[k];
    if tau_max > 0.0 {
        critical = critical.min(tau_max * b.area[b.jconslvid[k] as usize - 1]);
    }
    -critical.min(b.f_stick[k])
}

fn block(
    seed: &[(u8, f64, f64)],
    nfricdir: c_int,
    mu: IflReal,
    tau_max: IflReal,
    mode: IflReal,
) -> Block {
    let n = seed.len();
    let nodes = n + 3;
    Block {
        nfricdir,
        props: vec![1.0, mu, mu, tau_max, 1e-3, 0.0, mode],
        f_normal: seed
            .iter()
            .map(|(kind, a, _)| match kind % 4 {
                0 => -(*a as IflReal),
                1 => 0.0,
                _ => (*a * 10f64.powi(i32::from(kind % 7) - 2)) as IflReal,
            })
            .collect(),
        f_stick: seed.iter().map(|(_, _, s)| *s as IflReal).collect(),
        area: (0..nodes).map(|i| 0.1 + 0.37 * i as IflReal).collect(),
        jconslvid: (0..n).map(|k| ((k * 5) % nodes + 1) as c_int).collect(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn vfric_is_the_closed_form_in_the_build_precision(
        seed in proptest::collection::vec((any::<u8>(), 0.0..1e3f64, 0.0..1e3f64), 1..20),
        nfricdir in 1..=2 as c_int,
        mu in 0.0..1.5 as IflReal,
        tau_max in prop_oneof![Just(0.0 as IflReal), 0.01..50.0 as IflReal],
        mode in prop_oneof![Just(0.0 as IflReal), Just(1.0 as IflReal), Just(2.0 as IflReal)],
    ) {
        let b = block(&seed, nfricdir, mu, tau_max, mode);
        let ftan = call(&b);
        let nf = nfricdir as usize;
        let n = seed.len();
        for k in 0..n {
            let got = ftan[k * nf];
            prop_assert_eq!(got, closed_form(&b, k), "point {}", k + 1);
            prop_assert!(got <= 0.0 && got >= -b.f_stick[k]);
            if nf == 2 {
                prop_assert_eq!(ftan[k * nf + 1], 0.0);
            }
        }
        prop_assert!(ftan[nf * n..].iter().all(|x| *x == SENTINEL));
    }
}

#[test]
fn a_bad_point_gets_no_force_and_the_others_their_closed_form() {
    let seed: Vec<(u8, f64, f64)> = (0..6)
        .map(|i| (2 + i as u8, 10.0 + i as f64, 3.0))
        .collect();
    let mut b = block(&seed, 2, 0.3, 0.0, 0.0);
    b.f_normal[3] = IflReal::NAN;
    b.f_stick[4] = -1.0;
    let ftan = call(&b);
    for k in 0..6 {
        let want = if k == 3 || k == 4 {
            0.0
        } else {
            closed_form(&b, k)
        };
        assert_eq!(ftan[2 * k], want, "point {}", k + 1);
    }
    assert!(interfacial_test_hosts::FricCall::last_error().contains("contact point 5"));
}

#[test]
fn the_build_precision_is_the_one_asked_for() {
    let expected = if cfg!(feature = "explicit-single") {
        4
    } else {
        8
    };
    assert_eq!(std::mem::size_of::<IflReal>(), expected);
}
