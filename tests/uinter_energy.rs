//! `SPD` of `uinter_`: the energy a breaking adhesive bond releases (docs/uinter.md, "Energy of
//! a breaking bond"):
//! - every transition with its closed form: a bond that breaks while apart releases
//!   ½|S̄|²/k_s + ½N̄²/K_n (the start-of-increment energy, k_s = S_a/γ_crit); a closed point whose
//!   bond breaks as it separates releases its tangential energy ½|τ̄|²γ_crit/(μ_s·p̄ + S_a) only
//!   (the penalty energy ½p̄²/K_n is given back as work); everything else releases nothing;
//! - scene A1 (pull-off under a held shear, re-contact, pull-off again): the work done on the
//!   interface, computed from `STRESS` and `RDISP` alone, equals SED + ΣSPD after every
//!   increment, and each break reports the closed form;
//! - random paths (closed, bonded, open, re-contact): SPD finite and ≥ 0, non-zero only when a
//!   bond breaks, and then equal to the SED the previous call reported minus the compressive
//!   penalty energy it contained;
//! - a refused call zeroes SPD; inputs near the f64 range saturate SPD at f64::MAX.

use interfacial::props::AdhesiveBuilder;
use interfacial_test_hosts::UinterCall;

const K_N: f64 = 1e5;
const GAMMA_CRIT: f64 = 1e-3;
const MU_S: f64 = 0.5;
const S_A: f64 = 4.0;
const N_A: f64 = 10.0;

/// μ_d = 0.3, μ_s = 0.5, strengths S_a, N_a, γ_crit = 1e-3 (absolute), K_n = 1e5.
fn props(sa: f64, na: f64) -> Vec<f64> {
    AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(MU_S)
        .sa(sa)
        .na(na)
        .gamma_crit(GAMMA_CRIT)
        .normal_stiffness(K_N)
        .build_first(10)
}

/// One increment from a given start (`STRESS`, `STATEV(3)`) to the overclosure `h` with the
/// tangential motion `dgam`; the energies are preset to −1 to see that they are written.
fn one(props: &[f64], stress: &[f64], status: f64, h: f64, dgam: &[f64]) -> UinterCall {
    let ndir = stress.len();
    let mut c = UinterCall::new(ndir as i32, props);
    c.stress[..ndir].copy_from_slice(stress);
    c.statev[2] = status;
    c.rdisp[0] = h;
    c.drdisp[1..ndir].copy_from_slice(dgam);
    c.energies = [-1.0; 5];
    c.call();
    assert_eq!(c.pnewdt, 1e36, "refused: {stress:?} {status} {h}");
    c
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-13 * b.abs()
}

/// Name, `PROPS`, start `STRESS`, start status, h, Δγ, end status, SPD.
type Case<'a> = (&'a str, &'a [f64], &'a [f64], f64, f64, &'a [f64], f64, f64);

#[test]
fn spd_in_every_transition() {
    let adhesive = props(S_A, N_A);
    // Bonded, S̄ = (2, −1), N̄ = 6: (S/S_a)² + (N/N_a)² = 5/16 + N²/100 holds at N = 7 and
    // fails at N = 9. Released: ½|S̄|²γ_crit/S_a + ½N̄²/K_n.
    let bonded_energy = 0.5 * 5.0 * GAMMA_CRIT / S_A + 0.5 * 36.0 / K_N;
    // Closed at p̄ = 50 with τ̄ = 3: tangential energy ½τ̄²γ_crit/(μ_s p̄ + S_a); apart with
    // S = 3·S_a/29 the bond holds at N = 1 and breaks at N = 9.99.
    let closed_shear_energy = 0.5 * 9.0 * GAMMA_CRIT / (MU_S * 50.0 + S_A);
    // After a slip (rate 0, v_½ = 0) the start shear was built with the sliding strength
    // μ_d·p̄ + S_a (the rate-following stiffness, docs/props.md).
    let closed_slip_energy = 0.5 * 9.0 * GAMMA_CRIT / (0.3 * 50.0 + S_A);
    #[rustfmt::skip]
    let cases: [Case; 15] = [
        // name, props, start STRESS, start status, h, Δγ, end status, SPD
        ("bonded -> broken (3-D)", &adhesive, &[-6.0, 2.0, -1.0], 3.0, -9.0 / K_N, &[0.0, 0.0],
         4.0, bonded_energy),
        ("bonded -> broken (2-D)", &adhesive, &[-6.0, 5f64.sqrt()], 3.0, -9.0 / K_N, &[0.0],
         4.0, bonded_energy),
        // The motion of the increment does not enter: the start energy is what breaks.
        ("bonded -> broken by shear", &adhesive, &[-6.0, 2.0, -1.0], 3.0, -6.0 / K_N,
         &[0.0, 5e-3], 4.0, bonded_energy),
        ("closed stick -> broken", &adhesive, &[50.0, 3.0, 0.0], 0.0, -9.99 / K_N, &[0.0, 0.0],
         4.0, closed_shear_energy),
        ("closed slip -> broken", &adhesive, &[50.0, 0.0, 3.0], 1.0, -9.99 / K_N, &[0.0, 0.0],
         4.0, closed_slip_energy),
        ("closed -> broken by shear", &adhesive, &[50.0, 3.0, 0.0], 0.0, -1.0 / K_N,
         &[1e-2, 0.0], 4.0, closed_shear_energy),
        // No separation adhesion: the point just opens; nothing breaks.
        ("closed -> open, N_a = 0", &props(S_A, 0.0), &[50.0, 3.0, 0.0], 0.0, -1e-6, &[0.0, 0.0],
         4.0, 0.0),
        ("closed -> open, S_a = 0", &props(0.0, N_A), &[50.0, 3.0, 0.0], 1.0, -1e-6, &[0.0, 0.0],
         4.0, 0.0),
        ("closed -> bonded", &adhesive, &[50.0, 3.0, 0.0], 0.0, -1.0 / K_N, &[0.0, 0.0], 3.0, 0.0),
        ("bonded -> bonded", &adhesive, &[-6.0, 2.0, -1.0], 3.0, -7.0 / K_N, &[0.0, 0.0], 3.0, 0.0),
        ("bonded -> closed", &adhesive, &[-6.0, 2.0, -1.0], 3.0, 1e-5, &[0.0, 0.0], 0.0, 0.0),
        ("open -> open", &adhesive, &[0.0, 0.0, 0.0], 4.0, -1e-3, &[1e-2, 0.0], 4.0, 0.0),
        // A host passing stress with an open status: no bond, nothing to break.
        ("open (stale stress) -> open", &adhesive, &[-6.0, 2.0, -1.0], 4.0, -9.0 / K_N,
         &[0.0, 0.0], 4.0, 0.0),
        ("open -> closed", &adhesive, &[0.0, 0.0, 0.0], 4.0, 1e-5, &[0.0, 0.0], 0.0, 0.0),
        // A fresh point pulled apart past N_a at once: it held nothing.
        ("fresh -> broken", &adhesive, &[0.0, 0.0, 0.0], 0.0, -20.0 / K_N, &[0.0, 0.0], 4.0, 0.0),
    ];
    for (name, props, stress, status, h, dgam, end_status, spd) in cases {
        let c = one(props, stress, status, h, dgam);
        assert_eq!(c.statev[2], end_status, "{name}: {c:?}");
        let got = c.energies[2];
        assert!(close(got, spd), "{name}: SPD = {got:e}, expected {spd:e}");
        assert_eq!(
            (c.energies[3], c.energies[4]),
            (0.0, 0.0),
            "{name}: SVD, SCD"
        );
        if end_status == 4.0 {
            assert_eq!(c.energies[0], 0.0, "{name}: SED once open");
        }
    }
}

/// Work done on the interface in one increment, from the host's view of `STRESS` and `RDISP`:
/// the trapezoid ½(σ_start + σ_end)·Δu per component, exact for the linear springs of the law
/// (normal K_n, tangential k_s = S_a/γ_crit at p = 0) while the point carries stress at both
/// ends; and σ_end·Δu = 0 in an increment that ends open (backward Euler: the break point
/// inside the increment is unknown, and the end stress is zero).
fn increment_work(start: &[f64], end: &[f64], du: &[f64], carries_stress: bool) -> f64 {
    if !carries_stress {
        return 0.0;
    }
    (0..start.len())
        .map(|i| 0.5 * (start[i] + end[i]) * du[i])
        .sum()
}

/// Steps the point to the overclosure `h` with the tangential motion `dgam`, adds the work of
/// the increment to `work` and its SPD to `spd_sum`, and checks W = SED + ΣSPD.
fn step(c: &mut UinterCall, h: f64, dgam: &[f64], work: &mut f64, spd_sum: &mut f64) -> f64 {
    let n = c.ndir as usize;
    let start = c.stress[..n].to_vec();
    let mut du = vec![h - c.rdisp[0]];
    du.extend_from_slice(dgam);
    c.rdisp[0] = h;
    c.drdisp[1..n].copy_from_slice(dgam);
    c.call();
    assert_eq!(c.pnewdt, 1e36);
    *work += increment_work(&start, &c.stress[..n], &du, c.lopenclose == 1);
    let [sed, _, spd, _, _] = c.energies;
    assert!(spd >= 0.0 && spd.is_finite(), "SPD = {spd}");
    *spd_sum += spd;
    assert!(
        (*work - (sed + *spd_sum)).abs() <= 1e-12 * work.abs().max(1e-30),
        "W = {work:e} but SED + ΣSPD = {sed:e} + {spd_sum:e}"
    );
    spd
}

#[test]
fn a1_pull_off_energy_balance() {
    // Scene A1: bonded at h = 0 (touching) with a shear S₀ = 3 along direction 2 (k_s =
    // S_a/γ_crit), pulled apart by steps of ΔN = 0.01: the bond breaks at the first N at or
    // past N_a·sqrt(1 − (S₀/S_a)²) = 6.614…
    let s0 = 3.0;
    let k_s = S_A / GAMMA_CRIT;
    let mut c = UinterCall::new(3, &props(S_A, N_A));
    let (mut work, mut spd_sum) = (0.0, 0.0);
    assert_eq!(
        step(&mut c, 0.0, &[0.0, s0 / k_s], &mut work, &mut spd_sum),
        0.0
    );
    assert_eq!((c.statev[2], c.stress[2]), (3.0, s0));
    let n_break = N_A * (1.0 - (s0 / S_A) * (s0 / S_A)).sqrt();
    let mut last_n = 0.0;
    let mut broke_at = None;
    for k in 1..=1000 {
        let n = 0.01 * f64::from(k);
        let spd = step(&mut c, -n / K_N, &[0.0, 0.0], &mut work, &mut spd_sum);
        if c.lopenclose == 0 {
            broke_at = Some((n, spd));
            break;
        }
        assert_eq!(spd, 0.0, "SPD while bonded at N = {n}");
        last_n = n;
    }
    let (n, spd) = broke_at.expect("the bond broke");
    assert!(
        last_n < n_break && n_break <= n,
        "{last_n} < {n_break} <= {n}"
    );
    // The energy the bond held at the last bonded increment, from K_n, k_s and the stresses
    // the host imposed.
    let held = 0.5 * s0 * s0 / k_s + 0.5 * last_n * last_n / K_N;
    assert!(close(spd, held), "SPD = {spd:e}, expected {held:e}");
    assert!(close(work, held), "W = {work:e}");
    // Apart and free, back to touching: no work, no SPD.
    for h in [-1e-6, 0.0] {
        assert_eq!(step(&mut c, h, &[0.0, 0.0], &mut work, &mut spd_sum), 0.0);
        assert_eq!(c.lopenclose, 0);
    }
    // Re-contact (p = 1), pull to 0.99·N_a (re-bonded, full strength), then past N_a.
    assert_eq!(
        step(&mut c, 1e-5, &[0.0, 0.0], &mut work, &mut spd_sum),
        0.0
    );
    assert_eq!(c.lopenclose, 1);
    assert_eq!(
        step(
            &mut c,
            -0.99 * N_A / K_N,
            &[0.0, 0.0],
            &mut work,
            &mut spd_sum
        ),
        0.0
    );
    assert_eq!(c.statev[2], 3.0);
    let spd = step(
        &mut c,
        -1.01 * N_A / K_N,
        &[0.0, 0.0],
        &mut work,
        &mut spd_sum,
    );
    assert_eq!(c.statev[2], 4.0);
    let held = 0.5 * (0.99 * N_A) * (0.99 * N_A) / K_N;
    assert!(
        close(spd, held),
        "second break: SPD = {spd:e}, expected {held:e}"
    );
    assert_eq!(c.energies[0], 0.0);
}

/// SplitMix64.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        lo + (hi - lo) * ((z >> 11) as f64 / (1u64 << 53) as f64)
    }
}

#[test]
fn spd_along_random_paths() {
    let mut rng = Rng(0x5bd1_e995);
    let (mut breaks, mut calls) = (0u32, 0u32);
    for path in 0..120 {
        let ndir = 2 + path % 2;
        let adhesion = path % 4 != 0;
        let mu_d = rng.uniform(0.1, 0.5);
        let p = vec![
            2.0,
            mu_d,
            if path % 3 == 0 { 0.0 } else { mu_d + 0.2 },
            if adhesion {
                rng.uniform(1.0, 20.0)
            } else {
                0.0
            },
            if adhesion {
                rng.uniform(5.0, 50.0)
            } else {
                0.0
            },
            if path % 5 == 0 { 0.3 } else { 0.0 },
            if path % 5 == 0 { 0.05 } else { 0.0 },
            rng.uniform(1e-4, 1e-3),
            0.0,
            K_N,
        ];
        let mut c = UinterCall::new(ndir, &p);
        c.dtime = 0.1;
        let (amp, offset) = (rng.uniform(1e-4, 1e-3), rng.uniform(-0.6, 0.5));
        let (omega, slide) = (rng.uniform(0.05, 0.4), rng.uniform(0.1, 2.0) * p[7]);
        for inc in 0..300 {
            let (p_prev, sed_prev) = (c.stress[0], c.energies[0]);
            let status_prev = c.statev[2];
            c.rdisp[0] = amp * (offset + (omega * f64::from(inc)).sin());
            for a in 1..ndir as usize {
                c.drdisp[a] = rng.uniform(-slide, slide);
            }
            c.energies[2] = -1.0;
            c.call();
            calls += 1;
            assert_eq!(c.pnewdt, 1e36, "path {path} increment {inc}");
            let spd = c.energies[2];
            assert!(spd.is_finite() && spd >= 0.0, "SPD = {spd}");
            let broke = status_prev != 4.0 && c.statev[2] == 4.0 && c.rdisp[0] <= 0.0 && adhesion;
            if broke {
                // What the previous call reported as stored, less the compressive penalty
                // energy, which the separation gives back.
                let held = sed_prev - 0.5 * p_prev.max(0.0).powi(2) / K_N;
                assert!(
                    (spd - held).abs() <= 1e-12 * sed_prev + 1e-300,
                    "path {path} increment {inc}: SPD = {spd:e}, held {held:e}"
                );
                breaks += u32::from(spd > 0.0);
            } else {
                assert_eq!(spd, 0.0, "path {path} increment {inc}: no bond broke");
            }
        }
    }
    // The paths do break bonds that held energy (the test has teeth).
    assert!(breaks > 100, "{breaks} breaks in {calls} calls");
}

#[test]
fn refused_call_zeroes_spd_and_extreme_inputs_saturate() {
    let mut c = UinterCall::new(2, &props(S_A, N_A));
    c.rdisp[0] = f64::NAN;
    c.energies = [7.0; 5];
    c.call();
    assert_eq!(c.pnewdt, 0.25);
    assert_eq!(
        (c.energies[1], c.energies[2]),
        (0.0, 0.0),
        "SFD, SPD zeroed"
    );
    // A bond holding stresses near the f64 range: ½|S̄|²/k_s overflows; SPD saturates.
    let c = one(&props(S_A, N_A), &[-1e300, 1e300], 3.0, -1.0, &[0.0]);
    assert_eq!((c.statev[2], c.energies[2]), (4.0, f64::MAX));
}
