//! The chunked elastic-stick kernel of the batch entry (`src/laws/coulomb_batch.rs`), property
//! tested:
//! - through `ifl_fric_batch` against `fric_` called once per point, bit for bit, with
//!   `npoints` rarely a multiple of the chunk, points of every kind mixed inside each chunk
//!   (stick, slip, slip capped by τ_max, negative and zero pressure, no motion), and sometimes
//!   one unusable input in one point: that point gets `fric_`'s message and failure outputs,
//!   every other point its normal result;
//! - directly against `Coulomb::update`, lane by lane: on ordinary inputs the kernel answers
//!   and agrees bit for bit; on inputs spread over the whole f64 range it either declines the
//!   chunk or agrees, and it always declines when the scalar law refuses a lane.

mod common;

use common::{Points, Rng, UNSET, first_difference, per_point, via_c};
use interfacial::abi::IflStatus;
use interfacial::laws::contact::{Contact, Increment};
use interfacial::laws::coulomb::{Coulomb, CoulombState, FrictionStatus};
use interfacial::laws::coulomb_batch::{ChunkInput, ElasticStickKernel};
use interfacial::props::CoulombBuilder;
use interfacial_test_hosts::FricCall;
use proptest::prelude::*;

/// Law-1 PROPS with elastic stick: μ = 0.3; γ_crit absolute (10⁻³) or 1 % of CHRLNGTH; with or
/// without τ_max = 20.
fn props(variant: usize) -> Vec<f64> {
    let tau_max = if variant & 1 == 1 { 20.0 } else { 0.0 };
    let (gc, tol) = if variant & 2 == 0 {
        (1e-3, 0.0)
    } else {
        (0.0, 0.01)
    };
    CoulombBuilder::new()
        .mu(0.3)
        .tau_max(tau_max)
        .gamma_crit(gc)
        .slip_tolerance(tol)
        .build_first(7)
}

const NSTATV: usize = 4;

/// Points of every kind, drawn independently, so that chunks mix them.
fn mixed_points(seed: u64, n: usize, ld: usize, nfdir: usize) -> Points {
    let mut rng = Rng(seed | 1);
    let mut b = Points::new(n, ld, nfdir, NSTATV);
    for i in 0..n {
        // 0 stick, 1 slip, 2 slip at high pressure (capped when τ_max is set), 3 negative
        // pressure, 4 zero pressure, 5 no motion.
        let kind = rng.pick(6);
        let p = match kind {
            2 => rng.range(100.0, 200.0),
            3 => rng.range(-5.0, -1e-3),
            4 => 0.0,
            _ => rng.range(1.0, 60.0),
        };
        b.press[i] = p;
        b.dpress[i] = if kind == 4 { 0.0 } else { rng.range(-5.0, 5.0) };
        let length = rng.range(0.05, 0.2);
        b.chrlngth[i] = length;
        // γ_crit is 10⁻³ or 0.01·CHRLNGTH (5·10⁻⁴ … 2·10⁻³): scale the motion on 10⁻³.
        let motion = match kind {
            0 => 1e-4,
            5 => 0.0,
            _ => 1e-2,
        };
        for a in 0..nfdir {
            b.tau[i + a * ld] = rng.range(-0.5, 0.5) * 0.3 * p.max(0.0);
            b.dgam[i + a * ld] = rng.range(-1.0, 1.0) * motion;
        }
        b.statev[i] = rng.range(0.0, 1.0);
        b.statev[i + ld] = rng.range(0.0, 1.0);
        b.statev[i + 2 * ld] = rng.pick(2) as f64;
        b.statev[i + 3 * ld] = -7.0;
    }
    b
}

fn identical(a: &Points, b: &Points) -> Result<(), TestCaseError> {
    prop_assert_eq!(first_difference(a, b), None);
    Ok(())
}

/// Spoils one input of point `i`: NaN or ∞ in PRESS, DPRESS, DGAM, TAU, STATEV(1), or a zero
/// CHRLNGTH (refused only when γ_crit is a tolerance).
fn spoil(b: &mut Points, i: usize, what: usize, a: usize) {
    let ld = b.ld;
    let a = a % b.nfdir;
    match what {
        0 => b.press[i] = f64::NAN,
        1 => b.dpress[i] = f64::INFINITY,
        2 => b.dgam[i + a * ld] = f64::NAN,
        3 => b.tau[i + a * ld] = f64::NEG_INFINITY,
        4 => b.statev[i] = f64::NAN,
        _ => b.chrlngth[i] = 0.0,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn chunks_match_fric_per_point(
        seed in any::<u64>(),
        n in 1usize..40,
        pad in 0usize..6,
        nfdir in 1usize..=2,
        variant in 0usize..4,
        dtime in prop_oneof![Just(0.0), 1e-3..2.0f64],
        bad in proptest::option::of((0usize..40, 0usize..6, 0usize..2)),
    ) {
        let props = props(variant);
        let mut input = mixed_points(seed, n, n + pad, nfdir);
        let bad = bad.map(|(i, what, a)| (i % n, what, a));
        if let Some((i, what, a)) = bad {
            spoil(&mut input, i, what, a);
        }
        let (expected, pnewdt, messages) = per_point(&props, dtime, &input);
        let failing: Vec<usize> = (0..n).filter(|i| !messages[*i].is_empty()).collect();
        let (got, got_pnewdt, status) = via_c(&props, dtime, &input);
        identical(&expected, &got)?;
        prop_assert_eq!(got_pnewdt, pnewdt);
        // The padding between npoints and ld is never written.
        prop_assert!(got.sed[n..].iter().all(|x| *x == UNSET));
        match (bad, failing.as_slice()) {
            (None, []) => prop_assert_eq!(status, IflStatus::Ok),
            // A zero CHRLNGTH is fine with an absolute γ_crit.
            (Some((_, 5, _)), []) if variant & 2 == 0 => prop_assert_eq!(status, IflStatus::Ok),
            (Some((i, _, _)), [f]) => {
                prop_assert_eq!(*f, i);
                prop_assert_eq!(status, IflStatus::BadInput);
                prop_assert_eq!(pnewdt, 0.25);
                // fric_'s cause, reported for the batch point.
                let msg = FricCall::last_error();
                let place = format!("ifl_fric_batch: interaction '' (batch point {i})");
                prop_assert!(msg.contains(&place), "{}", msg);
                let cause = messages[i].split_once("): ").map(|(_, c)| c).unwrap_or_default();
                prop_assert!(!cause.is_empty() && msg.ends_with(cause), "{} / {}", msg, cause);
            }
            (b, f) => prop_assert!(false, "unexpected failures {:?} for {:?}", f, b),
        }
    }
}

/// A value spread over the whole f64 range (both signs, subnormals, near f64::MAX) or, half
/// the time, an ordinary one.
fn wide(rng: &mut Rng) -> f64 {
    let sign = if rng.next() < 0.5 { -1.0 } else { 1.0 };
    match rng.pick(4) {
        0 => sign * 2f64.powf(rng.range(-1074.0, 1023.9)),
        1 => 0.0,
        _ => sign * rng.range(0.0, 2.0),
    }
}

const W: usize = 4;

/// Lane `l` through the scalar law.
fn scalar(
    law: &Coulomb,
    inc: &ChunkInput<2, W>,
    dtime: f64,
    l: usize,
) -> Option<(Contact<2>, CoulombState)> {
    let i = Increment::<2> {
        tau: [inc.tau[0][l], inc.tau[1][l]],
        dgam: [inc.dgam[0][l], inc.dgam[1][l]],
        pressure: inc.pressure[l],
        dpressure: inc.dpressure[l],
        dtime,
        characteristic_length: inc.characteristic_length[l],
        ..Increment::default()
    };
    let state =
        CoulombState::from_statev(&[inc.accumulated_slip[l], inc.slip_rate[l], 0.0]).ok()?;
    let up = law.update(&i, &state).ok()?;
    Some((up.contact, up.state))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn kernel_declines_or_agrees_with_the_scalar_law(
        seed in any::<u64>(),
        extreme in any::<bool>(),
        absolute in any::<bool>(),
        tau_max in prop_oneof![Just(None), (1e-3..1e3f64).prop_map(Some)],
        // Every ordinary lane sticks: the kernel's stick-only route (no slip work).
        sticking in any::<bool>(),
    ) {
        let mut rng = Rng(seed | 1);
        let mut law = Coulomb::new(0.3).unwrap();
        law = if absolute {
            law.with_critical_slip_absolute(1e-3).unwrap()
        } else {
            law.with_slip_tolerance(0.01).unwrap()
        };
        if let Some(t) = tau_max {
            law = law.with_shear_limit(t).unwrap();
        }
        let kernel = ElasticStickKernel::new(&law).unwrap();
        // With `extreme`, one lane gets a common scale 2^k (k over the whole exponent range)
        // on its stress and motion, so that its norms overflow or underflow together, and
        // wide values elsewhere; the other lanes stay ordinary.
        let odd = if extreme { rng.pick(W) } else { W };
        let scale = 2f64.powi(rng.range(-1074.0, 1023.0) as i32);
        let mut draw = |l: usize, ordinary: (f64, f64), scaled: bool| {
            let x = rng.range(ordinary.0, ordinary.1);
            match (l == odd, scaled) {
                (false, _) => x,
                (true, true) => x * scale,
                (true, false) => if rng.next() < 0.5 { x } else { wide(&mut rng) },
            }
        };
        let mut lanes_of = |ordinary: (f64, f64), scaled: bool| -> [f64; W] {
            std::array::from_fn(|l| draw(l, ordinary, scaled))
        };
        // Sticking: p − Δp ≥ 0.5, so |γ̄^el| ≤ 0.05·γ_crit/0.15 and |Δγ| ≤ γ_crit/50.
        let (tau_range, dgam_range, p_range, dp_range) = if sticking {
            ((-0.05, 0.05), (-1e-5, 1e-5), (1.0, 40.0), (-0.5, 0.5))
        } else {
            ((-3.0, 3.0), (-5e-3, 5e-3), (-2.0, 40.0), (-5.0, 5.0))
        };
        let inc = ChunkInput::<2, W> {
            tau: [lanes_of(tau_range, true), lanes_of(tau_range, true)],
            dgam: [lanes_of(dgam_range, true), lanes_of(dgam_range, true)],
            pressure: lanes_of(p_range, false),
            dpressure: lanes_of(dp_range, false),
            characteristic_length: lanes_of((0.05, 0.2), false),
            accumulated_slip: lanes_of((0.0, 1.0), false),
            slip_rate: lanes_of((0.0, 1.0), false),
        };
        let dtime = 0.1;
        let lanes: Vec<_> = (0..W).map(|l| scalar(&law, &inc, dtime, l)).collect();
        let got = kernel.update(&inc, dtime);
        if !extreme {
            prop_assert!(got.is_some(), "ordinary inputs must stay on the kernel");
        }
        let Some(out) = got else { return Ok(()) };
        for (l, lane) in lanes.iter().enumerate() {
            let Some((Contact::Motion(t), state)) = lane else {
                return Err(TestCaseError::fail(format!("lane {l}: the scalar law refused it, the kernel answered")));
            };
            for a in 0..2 {
                prop_assert_eq!(out.tau[a][l].to_bits(), t.tau[a].to_bits());
                prop_assert_eq!(out.ddtddp[a][l].to_bits(), t.ddtddp[a].to_bits());
                prop_assert_eq!(out.dslip[a][l].to_bits(), t.dslip[a].to_bits());
                for b in 0..2 {
                    prop_assert_eq!(out.ddtddg[a][b][l].to_bits(), t.ddtddg[a][b].to_bits());
                }
            }
            prop_assert_eq!(out.sed[l].to_bits(), t.sed.to_bits());
            prop_assert_eq!(out.sfd[l].to_bits(), t.sfd.to_bits());
            if sticking && !extreme {
                prop_assert_eq!(state.status, FrictionStatus::Stick, "lane {}", l);
            }
            let mut sv = [0.0; 3];
            state.write_statev(&mut sv);
            for (row, x) in out.statev.iter().zip(sv) {
                prop_assert_eq!(row[l].to_bits(), x.to_bits());
            }
        }
    }
}
